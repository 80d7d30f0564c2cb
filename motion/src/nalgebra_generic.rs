//! nalgebra's `Isometry3<T>` to and from [`Pose<T>`] for any scalar that is both a GAM
//! [`Real`] and a nalgebra `RealField` (`f64`, `f32`, num-dual's `Dual64`, `Dual2_64`, ...), so
//! dual numbers can enter from nalgebra poses (feature `nalgebra`). The `f64` conversions of
//! [`crate::nalgebra_conv`] (through dual quaternions) are the same map; these go through the
//! rotation quaternion and the translation.
//!
//! The isometry `x ↦ R x + t` is the pose `S = R T` ([`Pose::from_axis_angle_translation`]):
//! the unit quaternion `w + x i + y j + z k` is the rotor `w + (x, y, z) e123`
//! ([`Pose::rotor_from_parts`]). Composition: nalgebra's `b * a` applies `a` first, the paper's
//! `A * B` applies `A` first.
//!
//! ```
//! use motion::Pose;
//! use nalgebra::{Isometry3, Vector3};
//! use num_dual::Dual64;
//! let iso = Isometry3::new(Vector3::new(Dual64::new(1.0, 1.0), Dual64::from(2.0), Dual64::from(0.0)),
//!     Vector3::new(Dual64::from(0.0), Dual64::from(0.0), Dual64::from(0.5)));
//! let s = Pose::from_na_isometry(&iso);
//! let p = s.transform_point(&[Dual64::from(0.0); 3]).unwrap();
//! assert_eq!((p[0].re, p[0].eps), (1.0, 1.0)); // the derivative came through
//! ```

use crate::{MotionError, Pose};
use algebra_core::{Real, Ring};
use nalgebra::{Isometry3, Quaternion, RealField, Translation3, UnitQuaternion, Vector3};

impl<T: Real + RealField> Pose<T> {
    /// The pose `S = R T` of the isometry `x ↦ R x + t`. Unchecked: a NaN or infinite
    /// isometry gives a non-finite pose (which every fallible pose operation then refuses with
    /// [`MotionError::NotFinite`]); [`Pose::try_from_na_isometry`] refuses it here.
    ///
    /// ```
    /// use nalgebra::{Isometry3, Vector3};
    /// let iso = Isometry3::new(Vector3::new(1.0f64, 2.0, 3.0), Vector3::new(0.0, 0.0, 1.0));
    /// let s = motion::Pose::from_na_isometry(&iso);
    /// let q = s.transform_point(&[1.0, 0.0, 0.0]).unwrap();
    /// let r = iso.transform_point(&nalgebra::Point3::new(1.0, 0.0, 0.0));
    /// assert!((q[0] - r.x).abs() < 1e-15 && (q[1] - r.y).abs() < 1e-15 && (q[2] - r.z).abs() < 1e-15);
    /// ```
    pub fn from_na_isometry(iso: &Isometry3<T>) -> Self {
        Pose::from_na_rotation_translation(&iso.rotation, &iso.translation.vector)
    }

    /// The pose `S = R T` of nalgebra's unit quaternion `q` (read by its named parts
    /// `w, i, j, k`: nalgebra's `coords` array is `[i, j, k, w]`) followed by the translation
    /// `t`, so `F_S(p) = q p q* + t`. Unchecked like [`Pose::from_na_isometry`].
    ///
    /// ```
    /// use nalgebra::{UnitQuaternion, Vector3};
    /// let q = UnitQuaternion::from_axis_angle(&Vector3::z_axis(), 0.5f64);
    /// let t = Vector3::new(1.0, 2.0, 3.0);
    /// let s = motion::Pose::from_na_rotation_translation(&q, &t);
    /// let p = s.transform_point(&[1.0, 0.0, 0.0]).unwrap();
    /// let want = q * Vector3::x() + t;
    /// assert!((p[0] - want.x).abs() < 1e-15 && (p[1] - want.y).abs() < 1e-15 && (p[2] - want.z).abs() < 1e-15);
    /// ```
    pub fn from_na_rotation_translation(q: &UnitQuaternion<T>, t: &Vector3<T>) -> Self {
        let q = q.quaternion();
        let r = Pose::rotor_from_parts(&q.w, &<T as Ring>::one(), &[q.i.clone(), q.j.clone(), q.k.clone()]);
        &r * &Pose::translation(&[t[0].clone(), t[1].clone(), t[2].clone()])
    }

    /// [`Pose::from_na_isometry`] of a finite isometry: [`MotionError::NotFinite`] when a
    /// rotation or translation component is NaN or infinite.
    ///
    /// ```
    /// use nalgebra::{Isometry3, Vector3};
    /// use motion::{MotionError, Pose};
    /// let ok = Isometry3::new(Vector3::new(1.0f64, 2.0, 3.0), Vector3::new(0.0, 0.0, 1.0));
    /// assert_eq!(Pose::try_from_na_isometry(&ok)?, Pose::from_na_isometry(&ok));
    /// let bad = Isometry3::new(Vector3::new(f64::NAN, 0.0, 0.0), Vector3::zeros());
    /// assert!(matches!(Pose::try_from_na_isometry(&bad), Err(MotionError::NotFinite { .. })));
    /// # Ok::<(), MotionError>(())
    /// ```
    pub fn try_from_na_isometry(iso: &Isometry3<T>) -> Result<Self, MotionError> {
        let q = iso.rotation.quaternion();
        let v = &iso.translation.vector;
        for x in [&q.w, &q.i, &q.j, &q.k, &v[0], &v[1], &v[2]] {
            crate::pose::check_finite_scalar("isometry", x)?;
        }
        Ok(Self::from_na_isometry(iso))
    }

    /// The isometry of the same rigid motion (a non-unit pose is unitized first). Fails for
    /// singular or non-finite poses.
    ///
    /// ```
    /// use motion::Pose;
    /// let s = Pose::from_axis_angle_translation(&[0.0, 1.0, 0.0], &0.7, &[1.0, -1.0, 2.0])?;
    /// let back = Pose::from_na_isometry(&s.to_na_isometry()?);
    /// assert!(back.is_equivalent(&s, &1e-15)?);
    /// # Ok::<(), motion::MotionError>(())
    /// ```
    pub fn to_na_isometry(&self) -> Result<Isometry3<T>, MotionError> {
        let u = self.unitize()?;
        let c = u.components();
        let q = Quaternion::new(c[0].clone(), c[3].clone(), c[2].neg_ref(), c[1].clone());
        let t = u.transform_point(&[<T as Ring>::zero(), <T as Ring>::zero(), <T as Ring>::zero()])?;
        let [x, y, z] = t;
        Ok(Isometry3::from_parts(Translation3::new(x, y, z), UnitQuaternion::new_unchecked(q)))
    }
}

impl<T: Real + RealField> From<&UnitQuaternion<T>> for Pose<T> {
    /// The rotation [`Pose::from_na_rotation_translation`] with no translation.
    ///
    /// ```
    /// use nalgebra::{UnitQuaternion, Vector3};
    /// let q = UnitQuaternion::from_axis_angle(&Vector3::y_axis(), 0.3f64);
    /// let s = motion::Pose::from(&q);
    /// assert!(s.is_equivalent(&motion::Pose::rotation(&[0.0, 1.0, 0.0], &0.3)?, &1e-15)?);
    /// # Ok::<(), motion::MotionError>(())
    /// ```
    fn from(q: &UnitQuaternion<T>) -> Self {
        let z = <T as Ring>::zero;
        Pose::from_na_rotation_translation(q, &Vector3::new(z(), z(), z()))
    }
}
