//! Conversions between [`Pose<f32>`]/[`Pose<f64>`] and glam's rotation and transform types
//! (feature `glam`): `Quat`/`DQuat` with a `Vec3`/`DVec3` translation, `Affine3A`/`DAffine3`
//! and `Mat4`/`DMat4`. They take glam's types, never arrays: glam's `Quat::to_array` is
//! `[x, y, z, w]` while [`Pose::from_quaternion_wxyz`] is scalar first.
//!
//! # Conventions
//!
//! The pose and the glam value move every point identically: `Pose::transform_point(p)` equals
//! `Affine3A::transform_point3(p)`, `Mat4::transform_point3(p)` and `q * p + t`. A matrix or
//! affine map must be a rigid-body transform (orthonormal rotation part with determinant +1,
//! bottom row `[0, 0, 0, 1]`) within a tolerance ([`Pose::from_matrix`]), or the conversion
//! fails with [`MotionError::NotRigid`]: `try_from_glam_mat4(m, tol)` takes the tolerance,
//! `TryFrom` uses [`GLAM_TOL_F32`] or [`GLAM_TOL_F64`]. A non-unit pose is unitized before
//! it is converted to glam; singular or non-finite poses and non-finite glam values are
//! refused with a [`MotionError`].
//!
//! ```
//! use glam::{Affine3A, Quat, Vec3};
//! use motion::Pose;
//! let affine = Affine3A::from_rotation_translation(Quat::from_rotation_z(0.5), Vec3::new(1.0, 2.0, 3.0));
//! let s = Pose::<f32>::try_from(&affine)?;
//! let p = s.transform_point(&[1.0, 0.0, 0.0])?;
//! let want = affine.transform_point3(Vec3::X);
//! assert!((Vec3::from(p) - want).length() < 1e-6);
//! # Ok::<(), motion::MotionError>(())
//! ```

use crate::{MotionError, Pose};
use glam::{Affine3A, DAffine3, DMat4, DQuat, DVec3, Mat4, Quat, Vec3};

/// The tolerance of the `TryFrom` conversions of `f32` glam matrices
/// ([`Pose::try_from_glam_mat4`] with this `tol`): the entries of `RᵀR - I` and of the bottom
/// row's difference from `[0, 0, 0, 1]` may be this large.
pub const GLAM_TOL_F32: f32 = 1e-5;

/// The tolerance of the `TryFrom` conversions of `f64` glam matrices (see [`GLAM_TOL_F32`]).
pub const GLAM_TOL_F64: f64 = 1e-12;

macro_rules! glam_conversions {
    ($t:ty, $quat:ident, $vec3:ident, $affine:ident, $mat4:ident, $tol:ident) => {
        impl Pose<$t> {
            #[doc = concat!("The pose `S = R T` of the rotation `q` (a glam `", stringify!($quat), "`, normalised")]
            /// here) followed by the translation `t`: `F_S(p) = q p q* + t`. Fails for a zero or
            /// non-finite quaternion or translation.
            ///
            /// ```
            #[doc = concat!("use glam::{", stringify!($quat), ", ", stringify!($vec3), "};")]
            #[doc = concat!("let q = ", stringify!($quat), "::from_rotation_x(1.0);")]
            #[doc = concat!("let t = ", stringify!($vec3), "::new(1.0, 2.0, 3.0);")]
            #[doc = concat!("let s = motion::Pose::<", stringify!($t), ">::from_glam_quat_translation(&q, &t)?;")]
            #[doc = concat!("let p = ", stringify!($vec3), "::from(s.transform_point(&[0.0, 1.0, 0.0])?);")]
            #[doc = concat!("assert!((p - (q * ", stringify!($vec3), "::Y + t)).length() < 1e-6);")]
            /// # Ok::<(), motion::MotionError>(())
            /// ```
            pub fn from_glam_quat_translation(q: &$quat, t: &$vec3) -> Result<Self, MotionError> {
                Self::from_quaternion_wxyz(&[q.w, q.x, q.y, q.z], &t.to_array())
            }

            /// The unit rotation quaternion and the translation of the pose (a non-unit pose is
            /// unitized first; the sign of the quaternion is kept). Fails for singular or
            /// non-finite poses.
            ///
            /// ```
            #[doc = concat!("use glam::{", stringify!($quat), ", ", stringify!($vec3), "};")]
            #[doc = concat!("let q = ", stringify!($quat), "::from_rotation_y(-0.25);")]
            #[doc = concat!("let s = motion::Pose::<", stringify!($t), ">::from_glam_quat_translation(&q, &", stringify!($vec3), "::Z)?;")]
            /// let (back, t) = s.to_glam_quat_translation()?;
            #[doc = concat!("assert!(back.abs_diff_eq(q, 1e-6) && t.abs_diff_eq(", stringify!($vec3), "::Z, 1e-6));")]
            /// # Ok::<(), motion::MotionError>(())
            /// ```
            pub fn to_glam_quat_translation(&self) -> Result<($quat, $vec3), MotionError> {
                let (q, t) = self.to_quaternion_translation()?;
                Ok(($quat::from_xyzw(q.x, q.y, q.z, q.w), $vec3::from_array(t)))
            }

            #[doc = concat!("The unit pose of a rigid glam `", stringify!($mat4), "` (acting on column vectors),")]
            /// checked within `tol` as by [`Pose::from_matrix`]: [`MotionError::NotRigid`] for a
            /// scale, shear, reflection or projective bottom row.
            ///
            /// ```
            #[doc = concat!("use glam::{", stringify!($mat4), ", ", stringify!($quat), ", ", stringify!($vec3), "};")]
            #[doc = concat!("let m = ", stringify!($mat4), "::from_rotation_translation(", stringify!($quat), "::from_rotation_z(2.0), ", stringify!($vec3), "::X);")]
            #[doc = concat!("let s = motion::Pose::<", stringify!($t), ">::try_from_glam_mat4(&m, &1e-5)?;")]
            #[doc = concat!("let p = ", stringify!($vec3), "::from(s.transform_point(&[0.0, 1.0, 0.0])?);")]
            #[doc = concat!("assert!((p - m.transform_point3(", stringify!($vec3), "::Y)).length() < 1e-6);")]
            #[doc = concat!("let scaled = ", stringify!($mat4), "::from_scale(", stringify!($vec3), "::splat(2.0));")]
            #[doc = concat!("assert!(motion::Pose::<", stringify!($t), ">::try_from_glam_mat4(&scaled, &1e-5).is_err());")]
            /// # Ok::<(), motion::MotionError>(())
            /// ```
            pub fn try_from_glam_mat4(m: &$mat4, tol: &$t) -> Result<Self, MotionError> {
                let c = m.to_cols_array_2d();
                let rows: [[$t; 4]; 4] = ::core::array::from_fn(|i| ::core::array::from_fn(|j| c[j][i]));
                Self::from_matrix(&rows, tol)
            }

            #[doc = concat!("The rigid glam `", stringify!($mat4), "` of the pose ([`Pose::to_matrix`], column-major).")]
            /// Fails for singular or non-finite poses.
            ///
            /// ```
            #[doc = concat!("let s = motion::Pose::<", stringify!($t), ">::translation(&[1.0, 2.0, 3.0]);")]
            #[doc = concat!("assert_eq!(s.to_glam_mat4()?, glam::", stringify!($mat4), "::from_translation(glam::", stringify!($vec3), "::new(1.0, 2.0, 3.0)));")]
            /// # Ok::<(), motion::MotionError>(())
            /// ```
            pub fn to_glam_mat4(&self) -> Result<$mat4, MotionError> {
                let r = self.to_matrix()?;
                Ok($mat4::from_cols_array_2d(&::core::array::from_fn(|j| ::core::array::from_fn(|i| r[i][j]))))
            }

            #[doc = concat!("The unit pose of a rigid glam `", stringify!($affine), "`, checked within `tol`")]
            /// ([`Pose::try_from_glam_mat4`]).
            ///
            /// ```
            #[doc = concat!("use glam::{", stringify!($affine), ", ", stringify!($vec3), "};")]
            #[doc = concat!("let a = ", stringify!($affine), "::from_translation(", stringify!($vec3), "::new(0.0, 0.0, 4.0));")]
            #[doc = concat!("let s = motion::Pose::<", stringify!($t), ">::try_from_glam_affine(&a, &1e-5)?;")]
            /// assert_eq!(s, motion::Pose::translation(&[0.0, 0.0, 4.0]));
            /// # Ok::<(), motion::MotionError>(())
            /// ```
            pub fn try_from_glam_affine(a: &$affine, tol: &$t) -> Result<Self, MotionError> {
                Self::try_from_glam_mat4(&$mat4::from(*a), tol)
            }

            #[doc = concat!("The rigid glam `", stringify!($affine), "` of the pose. Fails for singular or non-finite poses.")]
            ///
            /// ```
            #[doc = concat!("let s = motion::Pose::<", stringify!($t), ">::rotation(&[0.0, 0.0, 1.0], &1.0)?;")]
            #[doc = concat!("let v = s.to_glam_affine()?.transform_vector3(glam::", stringify!($vec3), "::X);")]
            #[doc = concat!("let (sin, cos) = (1.0 as ", stringify!($t), ").sin_cos();")]
            /// assert!((v.x - cos).abs() < 1e-6 && (v.y - sin).abs() < 1e-6);
            /// # Ok::<(), motion::MotionError>(())
            /// ```
            pub fn to_glam_affine(&self) -> Result<$affine, MotionError> {
                Ok($affine::from_mat4(self.to_glam_mat4()?))
            }
        }

        impl TryFrom<&$mat4> for Pose<$t> {
            type Error = MotionError;

            #[doc = concat!("[`Pose::try_from_glam_mat4`] with the tolerance [`", stringify!($tol), "`].")]
            ///
            /// ```
            #[doc = concat!("let m = glam::", stringify!($mat4), "::from_translation(glam::", stringify!($vec3), "::ONE);")]
            #[doc = concat!("assert_eq!(motion::Pose::<", stringify!($t), ">::try_from(&m)?, motion::Pose::translation(&[1.0; 3]));")]
            /// # Ok::<(), motion::MotionError>(())
            /// ```
            fn try_from(m: &$mat4) -> Result<Self, MotionError> {
                Self::try_from_glam_mat4(m, &$tol)
            }
        }

        impl TryFrom<&$affine> for Pose<$t> {
            type Error = MotionError;

            #[doc = concat!("[`Pose::try_from_glam_affine`] with the tolerance [`", stringify!($tol), "`].")]
            ///
            /// ```
            #[doc = concat!("let a = glam::", stringify!($affine), "::IDENTITY;")]
            #[doc = concat!("assert_eq!(motion::Pose::<", stringify!($t), ">::try_from(&a)?, motion::Pose::identity());")]
            /// # Ok::<(), motion::MotionError>(())
            /// ```
            fn try_from(a: &$affine) -> Result<Self, MotionError> {
                Self::try_from_glam_affine(a, &$tol)
            }
        }

        impl TryFrom<&$quat> for Pose<$t> {
            type Error = MotionError;

            /// [`Pose::from_glam_quat_translation`] with no translation.
            ///
            /// ```
            #[doc = concat!("let s = motion::Pose::<", stringify!($t), ">::try_from(&glam::", stringify!($quat), "::IDENTITY)?;")]
            /// assert_eq!(s, motion::Pose::identity());
            /// # Ok::<(), motion::MotionError>(())
            /// ```
            fn try_from(q: &$quat) -> Result<Self, MotionError> {
                Self::from_glam_quat_translation(q, &$vec3::ZERO)
            }
        }
    };
}

glam_conversions!(f32, Quat, Vec3, Affine3A, Mat4, GLAM_TOL_F32);
glam_conversions!(f64, DQuat, DVec3, DAffine3, DMat4, GLAM_TOL_F64);
