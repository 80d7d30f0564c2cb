//! Interpolation of the rotational parts `Rot(P_i) = r_{i,0} + r_i` of the given positions
//! by a quaternion Bézier curve `Q_rot(t) = Σ b_j^m(t) C_j` of degree `m` (Jüttler eq. 17,
//! Sec. 3): the affine method (19)-(21) and the elliptic method (22)-(25) with the sign rule
//! (24). Both solve one linear system with the Bernstein collocation matrix `b_j^m(t_i)`.
//!
//! ```
//! use algebra_core::rational::{q, ratio};
//! use gam_algebras::dual_quaternion::Quaternion;
//! use motion::juttler::rotational::affine;
//! let r = [Quaternion::new(q(1), q(0), q(0), q(0)), Quaternion::new(q(2), q(0), q(0), q(2))];
//! let rot = affine(&r, &[q(0), q(1)]).unwrap();
//! assert_eq!(rot.eval(&ratio(1, 2)).real, Quaternion::new(q(1), q(0), q(0), ratio(1, 2)));
//! ```

use super::{JuttlerError, QMotion};
use crate::repr::dual_quaternion::{DualQuaternion, Quaternion};
use algebra_core::linalg::solve;
use algebra_core::{Field, Real, Ring};

/// The Bernstein collocation matrix `A[i][j] = b_j^m(t_i)` (`m + 1` parameters, degree `m`).
fn collocation<T: Ring>(params: &[T]) -> Vec<Vec<T>> {
    params.iter().map(|t| super::bernstein_values(params.len() - 1, t)).collect()
}

/// Solves `Σ_j b_j^m(t_i) c_j = rhs_i` for `N` components at once (exact over rationals).
/// Equal or non-finite parameters are refused ([`JuttlerError::Parameters`]); distinct ones
/// can still make it singular in the scalar's precision ([`JuttlerError::NumericallySingular`]).
pub(crate) fn solve_bernstein<T: Field, const N: usize>(
    params: &[T],
    rhs: &[[T; N]],
) -> Result<Vec<[T; N]>, JuttlerError> {
    super::check_finite_distinct(params, std::iter::empty())?;
    solve_columns(&collocation(params), rhs)
        .ok_or(JuttlerError::NumericallySingular { system: "Σ_j b_j^m(t_i) C_j = R_i", unknowns: params.len() })
}

/// Solves `A c = rhs` for each of the `N` components of the right-hand sides (one solve per
/// component); `None` when `A` is singular.
pub(crate) fn solve_columns<T: Field, const N: usize>(a: &[Vec<T>], rhs: &[[T; N]]) -> Option<Vec<[T; N]>> {
    let mut cols: Vec<Vec<T>> = Vec::with_capacity(N);
    for k in 0..N {
        let b = rhs.iter().map(|r| r[k].clone()).collect();
        cols.push(solve(a.to_vec(), b)?);
    }
    Some((0..rhs.len()).map(|j| std::array::from_fn(|k| cols[k][j].clone())).collect())
}

/// `m + 1 ≥ 1` parameters for `m + 1` positions.
pub(crate) fn check_count<T>(positions: usize, params: &[T]) -> Result<(), JuttlerError> {
    if positions == 0 {
        return Err(JuttlerError::TooFewPositions { need: 1, got: 0 });
    }
    if params.len() != positions {
        return Err(JuttlerError::Parameters { why: format!("{} parameters for {positions} positions", params.len()) });
    }
    Ok(())
}

pub(crate) fn rotational<T: Ring>(c: Vec<[T; 4]>) -> Result<QMotion<T>, JuttlerError> {
    let [w, x, y, z] = [0, 1, 2, 3];
    QMotion::new_exact(
        c.into_iter()
            .map(|c| DualQuaternion::from_real(Quaternion::new(c[w].clone(), c[x].clone(), c[y].clone(), c[z].clone())))
            .collect(),
    )
}

/// The affine method (Proposition 1): the unique `Q_rot` of degree `m` with `Scal Q_rot ≡ 1`
/// (19) and `Q_rot(t_i) = Rot(P_i)/r_{i,0}` (20)-(21); exact over rationals. Fails for a
/// rotation with `r_{i,0} = 0` (a half turn: at infinity, [`JuttlerError::AtInfinity`]) and for
/// parameters that are not one per position and distinct.
///
/// ```
/// use algebra_core::rational::q;
/// use gam_algebras::dual_quaternion::Quaternion;
/// use motion::juttler::{JuttlerError, rotational::affine};
/// let half_turn = [Quaternion::new(q(1), q(0), q(0), q(0)), Quaternion::new(q(0), q(1), q(0), q(0))];
/// assert!(matches!(affine(&half_turn, &[q(0), q(1)]), Err(JuttlerError::AtInfinity { index: 1 })));
/// ```
pub fn affine<T: Field>(rotations: &[Quaternion<T>], params: &[T]) -> Result<QMotion<T>, JuttlerError> {
    check_count(rotations.len(), params)?;
    let rhs = rotations
        .iter()
        .enumerate()
        .map(|(index, r)| {
            let inv = r.w.try_recip().ok_or(JuttlerError::AtInfinity { index })?;
            Ok(r.vector().map(|v| v.mul_ref(&inv)))
        })
        .collect::<Result<Vec<[T; 3]>, JuttlerError>>()?;
    let v = solve_bernstein(params, &rhs)?;
    rotational(v.into_iter().map(|[x, y, z]| [T::one(), x, y, z]).collect())
}

/// The elliptic method (Proposition 2) on rotations already normalised (23) (`|R_i| = 1`, e.g.
/// rational unit quaternions): signs by (24) (each `R_{i+1}` flipped when `R_i·R_{i+1} < 0`),
/// then the unique `Q_rot` of degree `m` with `Q_rot(t_i) = ±R_i` (25); exact over rationals.
///
/// ```
/// use algebra_core::rational::{q, ratio};
/// use gam_algebras::dual_quaternion::Quaternion;
/// use motion::juttler::rotational::elliptic_normalised;
/// let r = [Quaternion::new(q(1), q(0), q(0), q(0)), Quaternion::new(ratio(-3, 5), q(0), q(0), ratio(-4, 5))];
/// let rot = elliptic_normalised(&r, &[q(0), q(1)]).unwrap();
/// assert_eq!(rot.eval(&q(1)).real, Quaternion::new(ratio(3, 5), q(0), q(0), ratio(4, 5))); // sign (24)
/// ```
pub fn elliptic_normalised<T: Field + PartialOrd>(
    rotations: &[Quaternion<T>],
    params: &[T],
) -> Result<QMotion<T>, JuttlerError> {
    check_count(rotations.len(), params)?;
    let mut rhs: Vec<[T; 4]> = Vec::with_capacity(rotations.len());
    for r in rotations {
        let mut c = [r.w.clone(), r.x.clone(), r.y.clone(), r.z.clone()];
        if let Some(prev) = rhs.last() {
            let dot = (0..4).fold(T::zero(), |acc, k| acc.add_ref(&prev[k].mul_ref(&c[k])));
            if dot < T::zero() {
                c = c.map(|x| x.neg_ref());
            }
        }
        rhs.push(c);
    }
    rotational(solve_bernstein(params, &rhs)?)
}

/// The elliptic method (Proposition 2): normalise each `Rot(P_i)` (23), then
/// [`elliptic_normalised`]. Fails for a zero quaternion ([`JuttlerError::ZeroQuaternion`]).
///
/// ```
/// use gam_algebras::dual_quaternion::Quaternion;
/// let r = [Quaternion::new(1.0, 0.0, 0.0, 0.0), Quaternion::new(2.0, 0.0, 0.0, 2.0)];
/// let rot = motion::juttler::rotational::elliptic(&r, &[0.0, 1.0]).unwrap();
/// assert!((rot.eval(&1.0).real.z - 0.5f64.sqrt()).abs() < 1e-15);
/// ```
pub fn elliptic<T: Real>(rotations: &[Quaternion<T>], params: &[T]) -> Result<QMotion<T>, JuttlerError> {
    let unit = rotations
        .iter()
        .enumerate()
        .map(|(index, r)| {
            let n = Real::sqrt(&r.norm_squared());
            let inv = n.try_recip().filter(|_| !n.is_exact_zero()).ok_or(JuttlerError::ZeroQuaternion { index })?;
            Ok(r.scale(&inv))
        })
        .collect::<Result<Vec<_>, JuttlerError>>()?;
    elliptic_normalised(&unit, params)
}
