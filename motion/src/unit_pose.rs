//! [`UnitPose`]: a pose known to be unit (`rev(S) S = 1` up to rounding), for callers that
//! normalise once and then act or interpolate many times.
//!
//! [`Pose`] is deliberately any element of G_{123inf}^+ (docs/conventions.md, "Non-unit
//! poses"), so its action divides by `α = S∅² + S12² + S13² + S23²` and its slerp normalises
//! `rev(A) B`. A `UnitPose` is made only by a checked normalisation ([`Pose::to_unit`],
//! `TryFrom<Pose>`), so its own [`UnitPose::transform_point`] and [`UnitPose::slerp`] skip that
//! work: no `1/α`, no test of `α`, no `√α`, `ln α` or `e^σ`. Every other [`Pose`] method is
//! reached through `Deref` (or [`UnitPose::as_pose`]) and behaves as on the pose itself.
//!
//! ```
//! use motion::{Pose, UnitPose};
//! let s = Pose::from_axis_angle_translation(&[0.0, 0.0, 1.0], &1.0, &[1.0, 2.0, 3.0])?.scale(&3.0);
//! let u: UnitPose<f64> = s.to_unit()?; // normalised once
//! let (fast, general) = (u.transform_point(&[1.0, 0.0, 0.0]), s.transform_point(&[1.0, 0.0, 0.0])?);
//! assert!(fast.iter().zip(&general).all(|(x, y)| (x - y).abs() < 1e-15));
//! assert!(u.is_unitary(&1e-15)); // a `Pose` method, through `Deref`
//! # Ok::<(), motion::MotionError>(())
//! ```

use crate::{MotionError, Pose};
use algebra_core::{Real, Ring};
use std::ops::Deref;

/// A [`Pose`] with `rev(S) S = 1` up to the rounding of the normalisation that made it (and of
/// the operations that produced it from unit poses). Only [`Pose::to_unit`] and `TryFrom`
/// (and [`UnitPose::identity`], [`UnitPose::slerp`]) make one, so its coefficients are finite
/// and it is never singular.
///
/// Use it when one pose acts on many points, or when unit poses are interpolated many times
/// (nalgebra's `UnitDualQuaternion` makes the same promise); use [`Pose`] for additive and
/// Bezier motions, whose poses leave the unit poses, and wherever a pose's scale is data.
///
/// ```
/// use motion::{Pose, UnitPose};
/// let u = UnitPose::try_from(Pose::translation(&[1.0, 0.0, 0.0]).scale(&2.0))?;
/// assert_eq!(u.transform_point(&[0.0, 0.0, 0.0]), [1.0, 0.0, 0.0]);
/// assert_eq!(*u.as_pose(), Pose::translation(&[1.0, 0.0, 0.0]));
/// # Ok::<(), motion::MotionError>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct UnitPose<T: Ring>(Pose<T>);

impl<T: Real> Pose<T> {
    /// The unit pose `S/|S|` ([`Pose::unitize`]) as a [`UnitPose`]: the same transform, whose
    /// action and slerp then skip the normalisation. Fails with [`MotionError::NotFinite`]
    /// for a non-finite pose and [`MotionError::Singular`] for a singular one.
    ///
    /// ```
    /// use motion::{MotionError, Pose};
    /// let u = Pose::rotation(&[1.0, 0.0, 0.0], &0.5)?.scale(&1e-200).to_unit()?;
    /// assert!(u.is_unitary(&1e-15));
    /// assert!(matches!(Pose::new(0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0).to_unit(), Err(MotionError::Singular { .. })));
    /// assert!(matches!(Pose::translation(&[f64::NAN, 0.0, 0.0]).to_unit(), Err(MotionError::NotFinite { .. })));
    /// # Ok::<(), MotionError>(())
    /// ```
    pub fn to_unit(&self) -> Result<UnitPose<T>, MotionError> {
        self.unitize().map(UnitPose)
    }
}

impl<T: Real> TryFrom<Pose<T>> for UnitPose<T> {
    type Error = MotionError;

    /// [`Pose::to_unit`].
    ///
    /// ```
    /// use motion::{Pose, UnitPose};
    /// assert!(UnitPose::try_from(Pose::<f64>::identity().scale(&0.0)).is_err());
    /// ```
    fn try_from(s: Pose<T>) -> Result<Self, MotionError> {
        s.to_unit()
    }
}

impl<T: Real> TryFrom<&Pose<T>> for UnitPose<T> {
    type Error = MotionError;

    /// [`Pose::to_unit`].
    ///
    /// ```
    /// use motion::{Pose, UnitPose};
    /// let u = UnitPose::try_from(&Pose::<f64>::identity().scale(&-2.0)).unwrap();
    /// assert_eq!(u.scalar, -1.0); // the sign is kept: -1 is the identity transform
    /// ```
    fn try_from(s: &Pose<T>) -> Result<Self, MotionError> {
        s.to_unit()
    }
}

impl<T: Ring> UnitPose<T> {
    /// The identity pose `1`.
    ///
    /// ```
    /// assert_eq!(motion::UnitPose::<f64>::identity().transform_point(&[1.0, 2.0, 3.0]), [1.0, 2.0, 3.0]);
    /// ```
    pub fn identity() -> Self {
        UnitPose(Pose::identity())
    }

    /// The pose itself (also reached through `Deref`: every [`Pose`] method works on a
    /// `UnitPose`).
    ///
    /// ```
    /// let u = motion::UnitPose::<f64>::identity();
    /// assert_eq!(u.as_pose(), &motion::Pose::identity());
    /// ```
    pub fn as_pose(&self) -> &Pose<T> {
        &self.0
    }

    /// The pose itself, by value.
    ///
    /// ```
    /// assert_eq!(motion::UnitPose::<f64>::identity().into_pose(), motion::Pose::identity());
    /// ```
    pub fn into_pose(self) -> Pose<T> {
        self.0
    }

    /// `F_S(p)` for a unit `S`: `p + 2(S∅ m + v × m + Sω v)` with `v = (S23, -S13, S12)`,
    /// `c = (S1∞, S2∞, S3∞)`, `m = v × p + c` ([`Pose::transform_point`] without its `1/α`,
    /// 18 products). No check and no error: the pose is finite and non-singular by
    /// construction, and a non-finite point gives a non-finite image (as nalgebra's
    /// `UnitDualQuaternion::transform_point`). The result differs from
    /// [`Pose::transform_point`] by the pose's departure from unit, a few rounding errors.
    ///
    /// ```
    /// use motion::Pose;
    /// let u = Pose::from_axis_angle_translation(&[0.0, 0.0, 1.0], &std::f64::consts::FRAC_PI_2, &[0.0, 0.0, 1.0])?.to_unit()?;
    /// let p = u.transform_point(&[1.0, 0.0, 0.0]);
    /// assert!(p[0].abs() < 1e-15 && (p[1] - 1.0).abs() < 1e-15 && (p[2] - 1.0).abs() < 1e-15);
    /// # Ok::<(), motion::MotionError>(())
    /// ```
    pub fn transform_point(&self, p: &[T; 3]) -> [T; 3] {
        self.0.image_unit(p)
    }
}

impl<T: Real> UnitPose<T> {
    /// The slerp `A (rev(A) B)^t` (eq. 15, [`Pose::slerp`]) between unit poses: `rev(A) B` is
    /// unit, so its power needs no `√α`, `1/√α`, `ln α` or `e^σ`, and the result is unit (up
    /// to rounding). The same path as [`Pose::slerp`]: the element's logarithm, so pass `-B`
    /// (the same transform) when `rev(A) B` has negative scalar part to turn the short way.
    /// Fails only for a non-finite `t` ([`MotionError::NotFinite`]).
    ///
    /// ```
    /// use motion::{Pose, UnitPose};
    /// let a = Pose::rotation(&[1.0, 0.0, 0.0], &0.3)?.to_unit()?;
    /// let b = Pose::from_axis_angle_translation(&[0.0, 1.0, 0.0], &2.0, &[1.0, 2.0, 3.0])?.to_unit()?;
    /// let mid = UnitPose::slerp(&a, &b, &0.5)?;
    /// let general = Pose::slerp(&a, &b, &0.5)?;
    /// assert!((mid.as_pose() - &general).components().iter().all(|x: &&f64| x.abs() < 1e-14));
    /// assert!(UnitPose::slerp(&a, &b, &f64::NAN).is_err());
    /// # Ok::<(), motion::MotionError>(())
    /// ```
    pub fn slerp(a: &Self, b: &Self, t: &T) -> Result<Self, MotionError> {
        if let Some(out) = Pose::slerp_unit_direct(&a.0, &b.0, t) {
            return Ok(UnitPose(out));
        }
        Pose::slerp(&a.0, &b.0, t).map(UnitPose)
    }
}

impl<T: Ring> Deref for UnitPose<T> {
    type Target = Pose<T>;

    fn deref(&self) -> &Pose<T> {
        &self.0
    }
}

impl<T: Ring> AsRef<Pose<T>> for UnitPose<T> {
    fn as_ref(&self) -> &Pose<T> {
        &self.0
    }
}

impl<T: Ring> From<UnitPose<T>> for Pose<T> {
    /// [`UnitPose::into_pose`].
    ///
    /// ```
    /// let p: motion::Pose<f64> = motion::UnitPose::identity().into();
    /// assert_eq!(p, motion::Pose::identity());
    /// ```
    fn from(u: UnitPose<T>) -> Self {
        u.0
    }
}
