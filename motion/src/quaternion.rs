//! Rotation quaternions at the pose boundary, with the component order always in the name or
//! the type: [`Quaternion`] (named fields `w, x, y, z`, Hamilton `w + x i + y j + z k`),
//! [`Pose::from_quaternion`], [`Pose::from_quaternion_wxyz`] (a scalar-first array) and
//! [`Pose::to_quaternion_translation`]. The libraries disagree on array order: nalgebra's
//! `Quaternion::coords` and glam's `Quat::to_array` are `[x, y, z, w]`; their conversions
//! (modules `nalgebra_conv`, `nalgebra_generic` and `glam_conv`, features `nalgebra` and `glam`)
//! take their own types, never arrays.
//!
//! The unit quaternion `q` is the rotor `w + (x, y, z) e123` ([`Pose::rotor_from_parts`]): the
//! pose rotates a point `p` to `q p q*` (the rotation matrix of `q`, right-handed).
//!
//! ```
//! use motion::{Pose, Quaternion};
//! let h = std::f64::consts::FRAC_1_SQRT_2;
//! let q = Quaternion::new(h, 0.0, 0.0, h); // w = cos 45°, z = sin 45°: a quarter turn about z
//! let s = Pose::from_quaternion(&q, &[0.0, 0.0, 1.0])?;
//! let p = s.transform_point(&[1.0, 0.0, 0.0])?;
//! assert!(p[0].abs() < 1e-15 && (p[1] - 1.0).abs() < 1e-15 && (p[2] - 1.0).abs() < 1e-15);
//! # Ok::<(), motion::MotionError>(())
//! ```

use crate::pose::check_finite_scalar;
use crate::{MotionError, Pose};
use algebra_core::{Real, Ring};
pub use gam_algebras::dual_quaternion::Quaternion;

impl<T: Real> Pose<T> {
    /// `S = R T` from a rotation quaternion with named fields (normalised here, without
    /// overflow) and a translation: `F_S(p) = q p q* + translation` for the unit `q`. Fails
    /// with [`MotionError::ZeroQuaternion`] for a zero quaternion and
    /// [`MotionError::NotFinite`] for a NaN or infinite component.
    ///
    /// ```
    /// use motion::{MotionError, Pose, Quaternion};
    /// // q = 1 + i (not normalised): a quarter turn about x
    /// let s = Pose::from_quaternion(&Quaternion::new(1.0f64, 1.0, 0.0, 0.0), &[0.0; 3])?;
    /// let p = s.transform_point(&[0.0, 1.0, 0.0])?; // y goes to z
    /// assert!(p[0].abs() < 1e-15 && p[1].abs() < 1e-15 && (p[2] - 1.0).abs() < 1e-15);
    /// assert_eq!(Pose::from_quaternion(&Quaternion::zero(), &[0.0; 3]), Err(MotionError::ZeroQuaternion));
    /// # Ok::<(), MotionError>(())
    /// ```
    pub fn from_quaternion(q: &Quaternion<T>, translation: &[T; 3]) -> Result<Self, MotionError> {
        let wxyz = [q.w.clone(), q.x.clone(), q.y.clone(), q.z.clone()];
        Pose::from_quaternion_wxyz(&wxyz, translation)
    }

    /// `S = R T` from a rotation quaternion given scalar first, `[w, x, y, z]` (Hamilton,
    /// `w + x i + y j + z k`; normalised here without overflow: components of size 1e200 or
    /// 1e-300 are fine), and the translation: the rotor is `w + (x, y, z) e123`
    /// ([`Pose::rotor_from_parts`]), so `F_S(p) = q p q* + translation`. Fails for a zero or
    /// non-finite quaternion. nalgebra's `coords` and glam's `to_array` are `[x, y, z, w]`:
    /// do not pass them here (use their conversions).
    ///
    /// ```
    /// use motion::{MotionError, Pose};
    /// let h = std::f64::consts::FRAC_1_SQRT_2;
    /// let s = Pose::from_quaternion_wxyz(&[1e200, 0.0, 0.0, 1e200], &[1.0, 0.0, 0.0])?; // quarter turn about e3
    /// let want = Pose::from_axis_angle_translation(&[0.0, 0.0, 1.0], &std::f64::consts::FRAC_PI_2, &[1.0, 0.0, 0.0])?;
    /// assert!(s.is_equivalent(&want, &1e-15)? && (s.scalar - h).abs() < 1e-15);
    /// assert_eq!(Pose::from_quaternion_wxyz(&[0.0; 4], &[0.0; 3]), Err(MotionError::ZeroQuaternion));
    /// # Ok::<(), MotionError>(())
    /// ```
    pub fn from_quaternion_wxyz(q: &[T; 4], translation: &[T; 3]) -> Result<Self, MotionError> {
        for x in q.iter().chain(translation) {
            check_finite_scalar("from_quaternion_wxyz", x)?;
        }
        let [w, x, y, z] = crate::scaled::direction(q).ok_or(MotionError::ZeroQuaternion)?;
        Ok(Pose::rotor_from_parts(&w, &T::one(), &[x, y, z]) * Pose::translation(translation))
    }

    /// The unit rotation quaternion and the translation of the pose (a non-unit pose is
    /// unitized first): the inverse of [`Pose::from_quaternion`] up to the sign of `q`, which
    /// is kept (`±q` are the same rotation). Fails for singular or non-finite poses.
    ///
    /// ```
    /// use motion::{Pose, Quaternion};
    /// let q = Quaternion::new(0.5f64, 0.5, -0.5, 0.5);
    /// let (back, t) = Pose::from_quaternion(&q, &[1.0, 2.0, 3.0])?.to_quaternion_translation()?;
    /// assert_eq!(back, q);
    /// assert!((t[0] - 1.0).abs() < 1e-15 && (t[1] - 2.0).abs() < 1e-15 && (t[2] - 3.0).abs() < 1e-15);
    /// # Ok::<(), motion::MotionError>(())
    /// ```
    pub fn to_quaternion_translation(&self) -> Result<(Quaternion<T>, [T; 3]), MotionError> {
        let u = self.unitize()?;
        let z = <T as Ring>::zero;
        let t = u.transform_point(&[z(), z(), z()])?;
        // w + (x, y, z) e123 = w + x e23 - y e13 + z e12
        Ok((Quaternion::new(u.scalar.clone(), u.e23.clone(), u.e13.neg_ref(), u.e12.clone()), t))
    }
}
