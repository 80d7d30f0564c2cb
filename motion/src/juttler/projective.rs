//! The projective method for the rotational parts (Jüttler Sec. 3.3, eqs. 27-28, Proposition 3):
//! no normalisation at all. `Q_rot(t_i) = λ_i Rot(P_i)` for some real `λ_i ≠ 0` says that
//! `Q_rot(t_i)` lies on the line through `0` and `R_i = Rot(P_i)` in the 4-space `H`: three
//! homogeneous linear equations per position, `3(m + 1)` in all, for the `4(k + 1)` unknown
//! coordinates of `C_0, …, C_k`. With `k = 3m/4` the system (28) has `4(k + 1) - 3(m + 1) = 1`
//! more unknown than equations, so a non-trivial solution exists, and in general it is unique
//! up to a real factor: the null space of (28), computed exactly over rationals.
//!
//! **The equations.** Jüttler's (27) is `r_{i,0} Vec Q_rot(t_i) - Scal Q_rot(t_i) r_i = 0`:
//! the three `2×2` minors of `(Q_rot(t_i), R_i)` that pair the scalar coordinate with a vector
//! coordinate. They state `Q_rot(t_i) ∥ R_i` only when `r_{i,0} ≠ 0` (for a half turn they
//! leave the vector part free). We take the three minors that pair the first non-zero
//! coordinate `p` of `R_i` with the other three, `R_{i,p} q_j - R_{i,j} q_p = 0`: exactly (27)
//! when `r_{i,0} ≠ 0`, and still equivalent to `Q_rot(t_i) ∈ span(R_i)` for half turns, so the
//! method stays invariant under every linear map of `H` (Proposition 3).
//!
//! **Errors.** `m` not divisible by 4 ([`JuttlerError::ProjectiveCount`], use
//! [`projective_with_degree`] for another `k`), a null space of dimension `> 1`
//! ([`JuttlerError::NotUnique`]) or `0` ([`JuttlerError::OnlyTrivial`]), and Jüttler's
//! *inaccessible* positions, `Q_rot(t_i) = 0` ([`JuttlerError::Inaccessible`]).
//!
//! ```
//! use algebra_core::rational::{q, ratio};
//! use gam_algebras::dual_quaternion::Quaternion;
//! use motion::juttler::projective::projective;
//! // five rotations (m = 4): a rotational Q-motion of degree k = 3
//! let r = [[1, 0, 0, 0], [1, 1, 0, 0], [0, 1, 1, 0], [1, 0, 2, 1], [2, -1, 0, 3]]
//!     .map(|[w, x, y, z]| Quaternion::new(q(w), q(x), q(y), q(z)));
//! let t = [q(0), ratio(1, 4), ratio(1, 2), ratio(3, 4), q(1)];
//! let rot = projective(&r, &t).unwrap();
//! assert_eq!(rot.degree(), 3);
//! assert_eq!(rot.eval(&q(0)).real, r[0]); // scaled so that λ_0 = 1
//! ```

use super::rotational::{check_count, rotational};
use super::{JuttlerError, QMotion, bernstein_values};
use crate::repr::dual_quaternion::Quaternion;
use algebra_core::Field;

/// A basis of the null space `{x : A x = 0}` of a matrix given by its rows (all of the same
/// length), by reduction to row echelon form with partial pivoting. Exact for exact fields;
/// for floats a pivot below `64 · ε · n · max|entry|` counts as zero (as in
/// [`algebra_core::linalg::solve`]). The rank is the number of columns minus the basis size.
///
/// ```
/// use algebra_core::rational::q;
/// use motion::juttler::projective::null_space;
/// let a = vec![vec![q(1), q(2), q(3)], vec![q(2), q(4), q(6)]];
/// let n = null_space(&a, 3);
/// assert_eq!(n.len(), 2); // rank 1
/// assert!(n.iter().all(|x| x[0].clone() + q(2) * x[1].clone() + q(3) * x[2].clone() == q(0)));
/// ```
#[allow(clippy::needless_range_loop)] // row operations read clearest with indices
pub fn null_space<T: Field>(a: &[Vec<T>], cols: usize) -> Vec<Vec<T>> {
    let mut m: Vec<Vec<T>> = a.to_vec();
    let rows = m.len();
    let one = T::one();
    let scale =
        m.iter().flatten().reduce(|x, y| if y.cmp_magnitude(x).is_gt() { y } else { x }).unwrap_or(&one).clone();
    let ulps = u32::try_from(rows.max(cols)).unwrap_or(u32::MAX).saturating_mul(64);
    let mut pivots: Vec<usize> = Vec::new();
    for c in 0..cols {
        let r = pivots.len();
        if r == rows {
            break;
        }
        let Some(p) = (r..rows).filter(|&i| !m[i][c].is_exact_zero()).max_by(|&x, &y| m[x][c].cmp_magnitude(&m[y][c]))
        else {
            continue;
        };
        if m[p][c].is_negligible(&scale, ulps) {
            continue;
        }
        m.swap(p, r);
        let Some(inv) = m[r][c].try_recip() else { continue };
        for x in m[r].iter_mut() {
            *x = x.mul_ref(&inv);
        }
        for i in 0..rows {
            if i == r || m[i][c].is_exact_zero() {
                continue;
            }
            let f = m[i][c].clone();
            for j in c..cols {
                let d = f.mul_ref(&m[r][j]);
                m[i][j].sub_assign_ref(&d);
            }
        }
        pivots.push(c);
    }
    (0..cols)
        .filter(|c| !pivots.contains(c))
        .map(|free| {
            let mut x = vec![T::zero(); cols];
            x[free] = T::one();
            for (row, &pc) in pivots.iter().enumerate() {
                x[pc] = m[row][free].neg_ref();
            }
            x
        })
        .collect()
}

/// The rows of the homogeneous system (28) for degree `k`: three per position, unknowns
/// ordered `C_0.w, C_0.x, C_0.y, C_0.z, C_1.w, …` (`4(k + 1)` columns). Fails for a zero
/// rotation ([`JuttlerError::ZeroQuaternion`]).
///
/// ```
/// use algebra_core::rational::q;
/// use gam_algebras::dual_quaternion::Quaternion;
/// let r = [Quaternion::new(q(1), q(0), q(0), q(0))];
/// let a = motion::juttler::projective::system(&r, &[q(0)], 0).unwrap();
/// // (27) with r_0 = 1: Vec C_0 = 0
/// assert_eq!(a[0], [q(0), q(1), q(0), q(0)]);
/// ```
pub fn system<T: Field>(rotations: &[Quaternion<T>], params: &[T], k: usize) -> Result<Vec<Vec<T>>, JuttlerError> {
    let mut rows = Vec::with_capacity(3 * rotations.len());
    for (index, (r, t)) in rotations.iter().zip(params).enumerate() {
        let c = [&r.w, &r.x, &r.y, &r.z];
        let p = c.iter().position(|x| !x.is_exact_zero()).ok_or(JuttlerError::ZeroQuaternion { index })?;
        let b = bernstein_values(k, t);
        for j in (0..4).filter(|&j| j != p) {
            let mut row = vec![T::zero(); 4 * (k + 1)];
            for (l, bl) in b.iter().enumerate() {
                row[4 * l + j] = bl.mul_ref(c[p]);
                row[4 * l + p] = bl.mul_ref(c[j]).neg_ref();
            }
            rows.push(row);
        }
    }
    Ok(rows)
}

/// The projective method (Proposition 3) with `k = 3m/4` for `m + 1` rotations (`m` divisible
/// by 4): the rotational Q-motion of degree `k` with `Q_rot(t_i) = λ_i R_i` (18), the unique (up
/// to a real factor) solution of (28), scaled so that `λ_0 = 1`; exact over rationals. Errors:
/// see the module documentation.
///
/// ```
/// use algebra_core::rational::q;
/// use gam_algebras::dual_quaternion::Quaternion;
/// use motion::juttler::{JuttlerError, projective::projective};
/// let r = [Quaternion::new(q(1), q(0), q(0), q(0)), Quaternion::new(q(0), q(1), q(0), q(0))];
/// assert!(matches!(projective(&r, &[q(0), q(1)]), Err(JuttlerError::ProjectiveCount { positions: 2 })));
/// ```
pub fn projective<T: Field>(rotations: &[Quaternion<T>], params: &[T]) -> Result<QMotion<T>, JuttlerError> {
    check_count(rotations.len(), params)?;
    let m = rotations.len() - 1;
    if !m.is_multiple_of(4) {
        return Err(JuttlerError::ProjectiveCount { positions: m + 1 });
    }
    projective_with_degree(rotations, params, 3 * m / 4)
}

/// The projective method (28) with a chosen degree `k`: succeeds when the null space of (28)
/// is one-dimensional and no position is inaccessible; the result is scaled so that
/// `Q_rot(t_0) = R_0`. Exact over rationals.
///
/// ```
/// use algebra_core::rational::q;
/// use gam_algebras::dual_quaternion::Quaternion;
/// use motion::juttler::{JuttlerError, projective::projective_with_degree};
/// let r = [Quaternion::new(q(1), q(0), q(0), q(0)), Quaternion::new(q(1), q(1), q(0), q(0))];
/// // degree 1 through two rotations: 8 unknowns, 6 equations, two free factors
/// assert_eq!(projective_with_degree(&r, &[q(0), q(1)], 1), Err(JuttlerError::NotUnique { dimension: 2 }));
/// ```
pub fn projective_with_degree<T: Field>(
    rotations: &[Quaternion<T>],
    params: &[T],
    k: usize,
) -> Result<QMotion<T>, JuttlerError> {
    check_count(rotations.len(), params)?;
    let a = system(rotations, params, k)?;
    let mut basis = null_space(&a, 4 * (k + 1));
    let x = match basis.len() {
        0 => return Err(JuttlerError::OnlyTrivial),
        1 => basis.swap_remove(0),
        dimension => return Err(JuttlerError::NotUnique { dimension }),
    };
    let coeffs: Vec<[T; 4]> = x.chunks(4).map(|c| std::array::from_fn(|j| c[j].clone())).collect();
    let scale = x.iter().reduce(|u, v| if v.cmp_magnitude(u).is_gt() { v } else { u }).cloned().unwrap_or(T::one());
    let ulps = 64 * (k as u32 + 1);
    let mut lambda0 = None;
    for (index, (r, t)) in rotations.iter().zip(params).enumerate() {
        let b = bernstein_values(k, t);
        let v: [T; 4] = std::array::from_fn(|j| {
            b.iter().zip(&coeffs).fold(T::zero(), |acc, (bl, c)| acc.add_ref(&bl.mul_ref(&c[j])))
        });
        let rc = [&r.w, &r.x, &r.y, &r.z];
        // the coordinate of largest |R_i| gives λ_i = v_p / R_p
        let p = (0..4).max_by(|&u, &w| rc[u].cmp_magnitude(rc[w])).unwrap_or(0);
        if v.iter().all(|x| x.is_negligible(&scale, ulps)) {
            return Err(JuttlerError::Inaccessible { index });
        }
        if index == 0 {
            lambda0 = v[p].div_ref(rc[p]).try_recip();
        }
    }
    let inv = lambda0.ok_or(JuttlerError::Inaccessible { index: 0 })?;
    rotational(coeffs.into_iter().map(|c| c.map(|x| x.mul_ref(&inv))).collect())
}
