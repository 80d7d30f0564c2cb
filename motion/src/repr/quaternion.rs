//! A pose as a unit rotation quaternion (Hamilton, `[w, x, y, z]`) and a position: the rigid
//! motion `p ↦ q p q* + t`. With `a e123 = a1 e23 - a2 e13 + a3 e12`, the unit pose `R T` has
//! `q = (S∅, S23, -S13, S12)`; `t` is the image of the origin.
//!
//! ```
//! use motion::{Pose, repr::quaternion::{from_quaternion_position, to_quaternion_position}};
//! let s = Pose::from_axis_angle_translation(&[0.0, 0.0, 1.0], &std::f64::consts::PI, &[1.0, 2.0, 3.0]).unwrap();
//! let (q, t) = to_quaternion_position(&s).unwrap();
//! assert!((q[3] - 1.0).abs() < 1e-15 && q[0].abs() < 1e-15 && t == [1.0, 2.0, 3.0]);
//! assert!(from_quaternion_position(&q, &t).unwrap().is_equivalent(&s, &1e-15).unwrap());
//! ```

use crate::repr::sign::canonical_quaternion;
use crate::{MotionError, Pose};
use algebra_core::Real;

/// The unit quaternion (sign of `gam pose`: `w ≥ 0`, at `w = 0` the first non-zero of
/// `x, y, z` positive) and the position of a pose. Fails for singular poses.
///
/// ```
/// use motion::{Pose, repr::quaternion::to_quaternion_position};
/// let (q, t) = to_quaternion_position(&Pose::translation(&[1.0, 0.0, 0.0])).unwrap();
/// assert_eq!((q, t), ([1.0, 0.0, 0.0, 0.0], [1.0, 0.0, 0.0]));
/// ```
pub fn to_quaternion_position<T: Real>(s: &Pose<T>) -> Result<([T; 4], [T; 3]), MotionError> {
    let u = s.unitize()?;
    let [w, b12, b13, b23, ..] = u.to_array();
    let q = canonical_quaternion([w, b23, b13.neg_ref(), b12]);
    Ok((q, u.transform_point(&crate::repr::vec3::zero())?))
}

/// The pose `R T` of a non-zero quaternion (normalised here) and a position.
///
/// ```
/// use motion::{Pose, repr::quaternion::from_quaternion_position};
/// let s = from_quaternion_position(&[2.0, 0.0, 0.0, 0.0], &[1.0, 0.0, 0.0]).unwrap();
/// assert_eq!(s, Pose::translation(&[1.0, 0.0, 0.0]));
/// assert!(from_quaternion_position(&[0.0; 4], &[0.0; 3]).is_err());
/// ```
pub fn from_quaternion_position<T: Real>(q: &[T; 4], t: &[T; 3]) -> Result<Pose<T>, MotionError> {
    for x in q.iter().chain(t) {
        crate::pose::check_finite_scalar("from_quaternion_position", x)?;
    }
    let n = crate::scaled::length(q).ok_or(MotionError::ZeroAxis)?;
    let inv = T::one().div_ref(&n);
    let [w, x, y, z] = q.clone().map(|c| c.mul_ref(&inv));
    Ok(Pose::rotor_from_parts(&w, &T::one(), &[x, y, z]) * Pose::translation(t))
}
