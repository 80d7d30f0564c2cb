//! Conversions between [`Pose<f64>`] and nalgebra's [`Isometry3<f64>`] and
//! [`UnitDualQuaternion<f64>`], both ways (feature `nalgebra`).
//!
//! # Conventions
//!
//! The pose `S` acts on points by the paper's `F_S = P f_S E` ([`Pose::transform_point`]); the
//! nalgebra value produced from it moves every point **identically**
//! (`Isometry3::transform_point`, `UnitDualQuaternion::transform_point`). Composition follows:
//! the paper's `U * V` applies `U` first (`F_{UV} = F_V F_U`, Lemma 2.3), nalgebra's
//! `v * u` applies `u` first, so `to_isometry(U * V) = to_isometry(V) * to_isometry(U)`.
//!
//! The isometry conversions are the generic ones of [`crate::nalgebra_generic`] at `f64`
//! ([`Pose::to_na_isometry`], [`Pose::from_na_isometry`]). The dual-quaternion conversions go
//! through GAM's hand-written [`DualQuaternion`]:
//! [`DualQuaternion::from_pose`] is the anti-isomorphism onto the standard dual quaternion of the
//! same rigid motion, `q = r + ε ½ t r`, which is exactly nalgebra's `UnitDualQuaternion`
//! (`real` = the rotation, `dual` = `½ t r`, Hamilton quaternions `w + x i + y j + z k`).
//!
//! # Non-unit poses
//!
//! A non-unit (but non-singular) pose `S = |S| U` is **unitized first** ([`Pose::unitize`], the
//! pseudoscalar norm of Lemma 2.4, so the `ω` part is handled exactly); `U` generates the same
//! transform. Singular or non-finite poses are rejected with a [`MotionError`]. Going from
//! nalgebra back, the result is always a unit pose. No sign is chosen: the unit poses `±U` are
//! the same motion, and the conversions keep the sign they are given (so the round trip
//! `UnitDualQuaternion → Pose → UnitDualQuaternion` returns the same coefficients).
//!
//! ```
//! use motion::Pose;
//! use nalgebra::{Isometry3, Point3};
//! let s = Pose::from_axis_angle_translation(&[0.0, 0.0, 1.0], &std::f64::consts::FRAC_PI_2, &[1.0, 0.0, 0.0]).unwrap();
//! let iso: Isometry3<f64> = s.to_isometry().unwrap();
//! let p = iso.transform_point(&Point3::new(1.0, 0.0, 0.0));
//! let q = s.transform_point(&[1.0, 0.0, 0.0]).unwrap();
//! assert!((p.x - q[0]).abs() < 1e-15 && (p.y - q[1]).abs() < 1e-15 && (p.z - q[2]).abs() < 1e-15);
//! assert!(Pose::from_isometry(&iso).is_equivalent(&s, &1e-15).unwrap());
//! ```

use crate::{MotionError, Pose};
use gam_algebras::DualQuaternion;
use gam_algebras::dual_quaternion::Quaternion;
use nalgebra::{Isometry3, UnitDualQuaternion};

fn to_na(q: &Quaternion<f64>) -> nalgebra::Quaternion<f64> {
    nalgebra::Quaternion::new(q.w, q.x, q.y, q.z)
}

fn from_na(q: &nalgebra::Quaternion<f64>) -> Quaternion<f64> {
    Quaternion::new(q.w, q.i, q.j, q.k)
}

impl Pose<f64> {
    /// The standard unit dual quaternion (GAM's [`DualQuaternion`]) of the same rigid motion,
    /// after unitizing. Fails for singular or non-finite poses.
    fn unit_dual_quaternion(&self) -> Result<DualQuaternion<f64>, MotionError> {
        let u = self.unitize()?;
        Ok(DualQuaternion::from_pose(&u.to_motor()))
    }

    /// The nalgebra unit dual quaternion of the same rigid motion (`q = r + ε ½ t r`), after
    /// unitizing a non-unit pose. Fails for singular or non-finite poses.
    ///
    /// ```
    /// use motion::Pose;
    /// let s = Pose::translation(&[2.0, 0.0, 0.0]).scale(&3.0); // non-unit: unitized first
    /// let q = s.to_unit_dual_quaternion().unwrap();
    /// assert_eq!(q.translation().vector.x, 2.0);
    /// ```
    pub fn to_unit_dual_quaternion(&self) -> Result<UnitDualQuaternion<f64>, MotionError> {
        let q = self.unit_dual_quaternion()?;
        Ok(UnitDualQuaternion::new_unchecked(nalgebra::DualQuaternion::from_real_and_dual(
            to_na(&q.real),
            to_na(&q.dual),
        )))
    }

    /// The unit pose of a nalgebra unit dual quaternion (the inverse of
    /// [`Pose::to_unit_dual_quaternion`] on unit poses; the sign is kept).
    ///
    /// ```
    /// use motion::Pose;
    /// use nalgebra::{Translation3, UnitDualQuaternion, UnitQuaternion};
    /// let q = UnitDualQuaternion::from_parts(Translation3::new(1.0, 2.0, 3.0), UnitQuaternion::identity());
    /// assert!(Pose::from_unit_dual_quaternion(&q).is_equivalent(&Pose::translation(&[1.0, 2.0, 3.0]), &1e-15).unwrap());
    /// ```
    ///
    /// Unchecked: a NaN or infinite dual quaternion gives a non-finite pose;
    /// [`Pose::try_from_unit_dual_quaternion`] refuses it.
    pub fn from_unit_dual_quaternion(q: &UnitDualQuaternion<f64>) -> Self {
        let q = q.as_ref();
        Pose::from_motor(DualQuaternion::new(from_na(&q.real), from_na(&q.dual)).to_pose())
    }

    /// The nalgebra isometry of the same rigid motion, `p ↦ R p + t`, after unitizing a
    /// non-unit pose ([`Pose::to_na_isometry`] at `f64`). Fails for singular or non-finite poses.
    ///
    /// ```
    /// use motion::Pose;
    /// let iso = Pose::translation(&[1.0, 2.0, 3.0]).to_isometry().unwrap();
    /// assert_eq!(iso.translation.vector.z, 3.0);
    /// ```
    pub fn to_isometry(&self) -> Result<Isometry3<f64>, MotionError> {
        self.to_na_isometry()
    }

    /// The unit pose `S = R T` of a nalgebra isometry (rotation, then translation;
    /// [`Pose::from_na_isometry`] at `f64`).
    ///
    /// ```
    /// use motion::Pose;
    /// use nalgebra::{Isometry3, Vector3};
    /// let iso = Isometry3::new(Vector3::new(1.0, 2.0, 3.0), Vector3::new(0.0, 0.0, 0.5));
    /// let s = Pose::from_isometry(&iso);
    /// let expected = Pose::from_axis_angle_translation(&[0.0, 0.0, 1.0], &0.5, &[1.0, 2.0, 3.0]).unwrap();
    /// assert!(s.is_equivalent(&expected, &1e-15).unwrap());
    /// ```
    pub fn from_isometry(iso: &Isometry3<f64>) -> Self {
        Pose::from_na_isometry(iso)
    }

    /// [`Pose::from_unit_dual_quaternion`] of a finite dual quaternion:
    /// [`MotionError::NotFinite`] when a component is NaN or infinite.
    ///
    /// ```
    /// use motion::{MotionError, Pose};
    /// use nalgebra::{DualQuaternion, Quaternion, UnitDualQuaternion};
    /// let ok = UnitDualQuaternion::<f64>::identity();
    /// assert_eq!(Pose::try_from_unit_dual_quaternion(&ok)?, Pose::identity());
    /// let nan = Quaternion::new(f64::NAN, 0.0, 0.0, 0.0);
    /// let bad = UnitDualQuaternion::new_unchecked(DualQuaternion::from_real_and_dual(nan, Quaternion::identity()));
    /// assert!(matches!(Pose::try_from_unit_dual_quaternion(&bad), Err(MotionError::NotFinite { .. })));
    /// # Ok::<(), MotionError>(())
    /// ```
    pub fn try_from_unit_dual_quaternion(q: &UnitDualQuaternion<f64>) -> Result<Self, MotionError> {
        let d = q.as_ref();
        if d.real.coords.iter().chain(d.dual.coords.iter()).all(|x| x.is_finite()) {
            Ok(Pose::from_unit_dual_quaternion(q))
        } else {
            Err(MotionError::NotFinite {
                op: "unit dual quaternion",
                value: format!("{:?} + ε {:?}", d.real.coords.as_slice(), d.dual.coords.as_slice()),
            })
        }
    }

    /// [`Pose::try_from_na_isometry`] at `f64`: [`MotionError::NotFinite`] for a NaN or
    /// infinite isometry.
    ///
    /// ```
    /// use motion::Pose;
    /// use nalgebra::{Isometry3, Vector3};
    /// assert!(Pose::try_from_isometry(&Isometry3::new(Vector3::new(f64::INFINITY, 0.0, 0.0), Vector3::zeros())).is_err());
    /// ```
    pub fn try_from_isometry(iso: &Isometry3<f64>) -> Result<Self, MotionError> {
        Pose::try_from_na_isometry(iso)
    }
}

impl TryFrom<&Pose<f64>> for Isometry3<f64> {
    type Error = MotionError;

    /// [`Pose::to_isometry`].
    ///
    /// ```
    /// use nalgebra::Isometry3;
    /// let iso = Isometry3::try_from(&motion::Pose::<f64>::identity()).unwrap();
    /// assert_eq!(iso, Isometry3::identity());
    /// ```
    fn try_from(s: &Pose<f64>) -> Result<Self, MotionError> {
        s.to_isometry()
    }
}

impl TryFrom<&Pose<f64>> for UnitDualQuaternion<f64> {
    type Error = MotionError;

    /// [`Pose::to_unit_dual_quaternion`].
    ///
    /// ```
    /// use nalgebra::UnitDualQuaternion;
    /// let q = UnitDualQuaternion::try_from(&motion::Pose::<f64>::identity()).unwrap();
    /// assert_eq!(q, UnitDualQuaternion::identity());
    /// ```
    fn try_from(s: &Pose<f64>) -> Result<Self, MotionError> {
        s.to_unit_dual_quaternion()
    }
}

impl From<&Isometry3<f64>> for Pose<f64> {
    /// [`Pose::from_isometry`].
    ///
    /// ```
    /// use nalgebra::Isometry3;
    /// assert_eq!(motion::Pose::from(&Isometry3::<f64>::identity()), motion::Pose::identity());
    /// ```
    fn from(iso: &Isometry3<f64>) -> Self {
        Pose::from_isometry(iso)
    }
}

impl From<&UnitDualQuaternion<f64>> for Pose<f64> {
    /// [`Pose::from_unit_dual_quaternion`].
    ///
    /// ```
    /// use nalgebra::UnitDualQuaternion;
    /// assert_eq!(motion::Pose::from(&UnitDualQuaternion::<f64>::identity()), motion::Pose::identity());
    /// ```
    fn from(q: &UnitDualQuaternion<f64>) -> Self {
        Pose::from_unit_dual_quaternion(q)
    }
}
