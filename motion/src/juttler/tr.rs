//! The TR method (Jüttler Sec. 4.1, eqs. 30-31, Proposition 4) and Algorithm 1: a rotational
//! Q-motion `Q_rot` of degree `k` through the rotational parts, composed with the translational
//! motion `Q_trans(t) = 2 + ε Σ b_j^m(t) p_j` through the positions' translations `s_i`
//! (`P_i = (2 + ε s_i) * Rot(P_i)`, (14)): `Q = Q_trans * Q_rot` of degree `k + m` by the
//! product formula (29).
//!
//! ```
//! use motion::{Motion, Pose, juttler::tr::algorithm1};
//! let poses = [
//!     Pose::<f64>::identity(),
//!     Pose::from_axis_angle_translation(&[0.0, 0.0, 1.0], &1.0, &[1.0, 2.0, 0.0]).unwrap(),
//!     Pose::from_axis_angle_translation(&[1.0, 0.0, 0.0], &0.5, &[3.0, 0.0, 1.0]).unwrap(),
//! ];
//! let m = algorithm1(&poses, &[0.0, 0.4, 1.0]).unwrap();
//! assert_eq!(m.degree(), 4);
//! assert!(m.pose(&0.4).unwrap().is_equivalent(&poses[1], &1e-12).unwrap());
//! ```

use super::rotational::{check_count, elliptic, solve_bernstein};
use super::{JuttlerError, QMotion};
use crate::Pose;
use crate::repr::ReprError;
use crate::repr::dual_quaternion::{DualQuaternion, Quaternion, to_dual_quaternion_exact};
use algebra_core::{Field, Real};

/// The rotational part `Rot(P) = Q⁰` and the translation `s` of a position `P = (2 + ε s) * Rot(P)`
/// (14), from its dual quaternion (repr's pose map): `s = 2 Vec(Q^ε Q̃⁰)/|Q⁰|²`; exact.
///
/// ```
/// use algebra_core::rational::q;
/// use motion::Pose;
/// let (r, s) = motion::juttler::tr::rotation_translation(&Pose::translation(&[q(1), q(2), q(3)])).unwrap();
/// assert_eq!((r.w, s), (q(1), [q(1), q(2), q(3)]));
/// ```
pub fn rotation_translation<T: Field>(p: &Pose<T>) -> Result<(Quaternion<T>, [T; 3]), JuttlerError> {
    let q = to_dual_quaternion_exact(p);
    let inv = q.real.norm_squared().try_recip().ok_or(ReprError::ZeroRealPart)?;
    let two = T::from_i64(2).mul_ref(&inv);
    let s = (&q.dual * &q.real.conjugate()).vector().map(|v| v.mul_ref(&two));
    Ok((q.real, s))
}

/// The rotational parts `Rot(P_i)` of `poses` ([`rotation_translation`]), as the rotational
/// methods take them.
///
/// ```
/// use algebra_core::rational::q;
/// use motion::{Pose, juttler::tr::rotations};
/// let r = rotations(&[Pose::translation(&[q(1), q(0), q(0)])]).unwrap();
/// assert_eq!((r[0].w.clone(), r[0].x.clone()), (q(1), q(0)));
/// ```
pub fn rotations<T: Field>(poses: &[Pose<T>]) -> Result<Vec<Quaternion<T>>, JuttlerError> {
    poses.iter().map(|p| Ok(rotation_translation(p)?.0)).collect()
}

/// The TR method (30)-(31): `Q_trans * rot` with `Q_trans` of degree `m` through the
/// translations `s_i` at `params` (one per position, distinct); exact over rationals. `rot`
/// must interpolate the rotational parts at `params` (e.g. [`super::rotational::affine`]); then
/// `Q(t_i) = λ_i P_i`.
///
/// ```
/// use algebra_core::rational::q;
/// use motion::{Pose, juttler::{rotational::affine, tr::{rotation_translation, tr_method}}};
/// let poses = [Pose::translation(&[q(0), q(0), q(0)]), Pose::translation(&[q(2), q(0), q(0)])];
/// let rots: Vec<_> = poses.iter().map(|p| rotation_translation(p).unwrap().0).collect();
/// let m = tr_method(&affine(&rots, &[q(0), q(1)]).unwrap(), &poses, &[q(0), q(1)]).unwrap();
/// assert!(m.pose_exact(&q(1)).unwrap().is_equivalent_exact(&poses[1]));
/// ```
pub fn tr_method<T: Field>(rot: &QMotion<T>, poses: &[Pose<T>], params: &[T]) -> Result<QMotion<T>, JuttlerError> {
    check_count(poses.len(), params)?;
    let s = poses.iter().map(|p| Ok(rotation_translation(p)?.1)).collect::<Result<Vec<_>, JuttlerError>>()?;
    let p = solve_bernstein(params, &s)?;
    let two = Quaternion::new(T::from_i64(2), T::zero(), T::zero(), T::zero());
    let trans = QMotion::new_exact(p.iter().map(|p| DualQuaternion::new(two.clone(), Quaternion::pure(p))).collect())?;
    Ok(trans.product(rot))
}

/// Algorithm 1: the elliptic method (23)-(25) for the rotational parts, the TR method for the
/// translations; a Q-motion of degree `2m` with `Q(t_i) = λ_i P_i` (`params` one per position,
/// distinct, e.g. from [`super::parameters`]).
///
/// ```
/// use motion::{Pose, juttler::{JuttlerError, tr::algorithm1}};
/// let p = [Pose::<f64>::identity(), Pose::translation(&[1.0, 0.0, 0.0])];
/// assert!(matches!(algorithm1(&p, &[0.0, 0.0]), Err(JuttlerError::Parameters { .. })));
/// ```
pub fn algorithm1<T: Real>(poses: &[Pose<T>], params: &[T]) -> Result<QMotion<T>, JuttlerError> {
    check_count(poses.len(), params)?;
    tr_method(&elliptic(&rotations(poses)?, params)?, poses, params)
}
