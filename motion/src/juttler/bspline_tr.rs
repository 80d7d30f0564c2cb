//! The TR method (Jüttler Sec. 4.1, (30)-(31)) generalised to B-spline Q-motions, as his
//! Sec. 6 says it can be: the rotational parts and the translations of the positions are each
//! interpolated by a B-spline of degree `p` at the parameters (collocation with the B-spline
//! basis in place of the Bernstein one), and the motion is their product
//! ([`BSplineQMotion::product`], in place of (29)): a B-spline Q-motion of degree `2p` with
//! `Q(t_i) = λ_i P_i`.
//!
//! Knots: clamped, interior knots by averaging `p` consecutive parameters (de Boor's choice,
//! Hoschek–Lasser; it satisfies the Schoenberg–Whitney condition, so the collocation systems
//! have unique solutions for strictly increasing parameters). With `p = m` the knots are those
//! of a Bézier curve and the result is the TR method on the elliptic rotational interpolant.
//!
//! ```
//! use algebra_core::rational::{q, ratio};
//! use motion::{Pose, juttler::bspline_tr::bspline_tr};
//! let poses: Vec<Pose<_>> = (0..5).map(|i| Pose::translation(&[q(i), q(i * i), q(0)])).collect();
//! let params = [q(0), ratio(1, 4), ratio(1, 2), ratio(3, 4), q(1)];
//! let m = bspline_tr(&poses, &params, 2).unwrap();
//! assert_eq!(m.degree(), 4);
//! assert!(m.pieces().pose_exact(&ratio(1, 4)).unwrap().is_equivalent_exact(&poses[1]));
//! ```

use super::JuttlerError;
use super::bspline::{BSplineQMotion, span};
use super::rotational::solve_columns;
use super::spline::aligned_parts;
use super::velocity::check_spline_parameters;
use crate::Pose;
use crate::repr::dual_quaternion::{DualQuaternion, Quaternion};
use algebra_core::Field;

/// The clamped knot vector of degree `p` for `m + 1` parameters: `t_0` and `t_m` `p + 1` times,
/// interior knots `(t_j + … + t_{j+p-1})/p` for `j = 1, …, m - p`.
fn averaged_knots<T: Field>(params: &[T], p: usize) -> Vec<T> {
    let m = params.len() - 1;
    let inv = T::from_ratio(1, p.max(1) as i64);
    let mut knots = vec![params[0].clone(); p + 1];
    for j in 1..=m - p {
        let sum = params[j..j + p].iter().fold(T::zero(), |acc, t| acc.add_ref(t));
        knots.push(sum.mul_ref(&inv));
    }
    knots.extend(std::iter::repeat_n(params[m].clone(), p + 1));
    knots
}

/// The values `N_0^p(t), …, N_n^p(t)` of the B-spline basis (Cox–de Boor triangle on the span
/// of `t`).
fn basis_row<T: Field + PartialOrd>(u: &[T], p: usize, n1: usize, t: &T) -> Vec<T> {
    let k = span(u, p, n1, t);
    // n[r] = N_{k-j+r}^j(t) for the current j
    let mut n = vec![T::one()];
    for j in 1..=p {
        let mut next = vec![T::zero(); j + 1];
        for (r, v) in n.iter().enumerate() {
            // N_i^j = (t - u_i)/(u_{i+j} - u_i) N_i^{j-1} + (u_{i+j+1} - t)/(u_{i+j+1} - u_{i+1}) N_{i+1}^{j-1}
            let i = k + r - (j - 1);
            let (lo, hi) = (&u[i], &u[i + j]);
            let w = hi.sub_ref(lo).try_recip().unwrap_or_else(T::zero);
            // N_i^{j-1} feeds N_{i-1}^j (falling part) and N_i^j (rising part)
            next[r] = next[r].add_ref(&hi.sub_ref(t).mul_ref(&w).mul_ref(v));
            next[r + 1] = next[r + 1].add_ref(&t.sub_ref(lo).mul_ref(&w).mul_ref(v));
        }
        n = next;
    }
    let mut row = vec![T::zero(); n1];
    for (r, v) in n.into_iter().enumerate() {
        row[k - p + r] = v;
    }
    row
}

/// Solves `Σ_j N_j^p(t_i) c_j = rhs_i` for `N` components at once.
fn collocate<T: Field + PartialOrd, const N: usize>(
    knots: &[T],
    p: usize,
    params: &[T],
    rhs: &[[T; N]],
) -> Result<Vec<[T; N]>, JuttlerError> {
    let a: Vec<Vec<T>> = params.iter().map(|t| basis_row(knots, p, params.len(), t)).collect();
    solve_columns(&a, rhs)
        .ok_or_else(|| JuttlerError::Parameters { why: "the B-spline collocation matrix is singular".into() })
}

/// The TR method with B-spline Q-motions of degree `p` (module docs): `m + 1 ≥ 2` positions
/// at strictly increasing `params`, `1 ≤ p ≤ m`; rotational parts at the poses' own scale with
/// the signs of (24) (unit ones for the paper's normalisation (23)); exact over rationals.
/// Fails for too few positions, bad parameters, `p` out of range, a singular collocation
/// system, or a pose with a zero rotational part.
///
/// ```
/// use algebra_core::rational::q;
/// use motion::{Pose, juttler::{JuttlerError, bspline_tr::bspline_tr}};
/// let p = [Pose::translation(&[q(0), q(0), q(0)]), Pose::translation(&[q(1), q(0), q(0)])];
/// assert!(matches!(bspline_tr(&p, &[q(0), q(1)], 2), Err(JuttlerError::Parameters { .. })));
/// ```
pub fn bspline_tr<T: Field + PartialOrd>(
    poses: &[Pose<T>],
    params: &[T],
    p: usize,
) -> Result<BSplineQMotion<T>, JuttlerError> {
    check_spline_parameters(poses.len(), params)?;
    let m = poses.len() - 1;
    if p == 0 || p > m {
        return Err(JuttlerError::Parameters {
            why: format!("degree {p} for {} positions (need 1 ≤ p ≤ {m})", m + 1)
        });
    }
    let (rots, trans): (Vec<[T; 4]>, Vec<[T; 3]>) =
        aligned_parts(poses)?.into_iter().map(|(r, s)| ([r.w, r.x, r.y, r.z], s)).unzip();
    let knots = averaged_knots(params, p);
    let rot = collocate(&knots, p, params, &rots)?
        .into_iter()
        .map(|[w, x, y, z]| DualQuaternion::from_real(Quaternion::new(w, x, y, z)))
        .collect();
    let two = Quaternion::new(T::from_i64(2), T::zero(), T::zero(), T::zero());
    let tr = collocate(&knots, p, params, &trans)?
        .iter()
        .map(|s| DualQuaternion::new(two.clone(), Quaternion::pure(s)))
        .collect();
    let rot = BSplineQMotion::new_exact(p, knots.clone(), rot)?;
    BSplineQMotion::new_exact(p, knots, tr)?.product(&rot)
}
