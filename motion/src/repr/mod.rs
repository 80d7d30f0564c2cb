//! Every pose representation of the four papers, and conversions between them (issue 10):
//!
//! | module | representation | paper |
//! |---|---|---|
//! | [`quaternion`] | unit quaternion + position | — |
//! | [`dual_quaternion`] | dual quaternions in Jüttler's conventions, the pose map | Jüttler Sec. 1, main paper App. 2 |
//! | [`hexanion`] | Angelidis' hexanions `<ω, m>` | Angelidis Secs. 2-7 |
//! | [`screw`] | the screw (Chasles) decomposition; Jüttler's dist, dist*, angle | Jüttler Sec. 2 |
//! | [`sign`] | unique signs, short-way slerp (alignment (24): `trajectory::align_signs`) | Jüttler (24) |
//!
//! The 4x4 matrix is [`Pose::to_matrix`](crate::Pose::to_matrix) /
//! [`Pose::from_matrix`](crate::Pose::from_matrix).
//!
//! ```
//! use motion::{Pose, repr::{hexanion::Hexanion, screw::Screw}};
//! let s = Pose::<f64>::from_axis_angle_translation(&[1.0, 0.0, 0.0], &0.5, &[0.0, 1.0, 0.0]).unwrap();
//! let h = Hexanion::from_pose(&s).unwrap();
//! assert!((Screw::of_hexanion(&h).angle - 0.5).abs() < 1e-15);
//! ```

pub mod dual_quaternion;
pub mod hexanion;
pub mod quaternion;
pub mod screw;
pub mod sign;
pub(crate) mod vec3;

use crate::{CurveError, MotionError};
use algebra_core::Real;

/// Why a conversion or a motion of this module failed.
///
/// ```
/// let e = motion::repr::ReprError::OffStudyQuadric { cosine: 0.5 };
/// assert!(e.to_string().contains("Study quadric"));
/// ```
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ReprError {
    /// A pose operation failed.
    #[error(transparent)]
    Motion(#[from] MotionError),
    /// A motion could not be built or evaluated.
    #[error(transparent)]
    Curve(#[from] CurveError),
    /// A dual quaternion whose real part is zero (no rigid motion).
    #[error("the dual quaternion has a zero real part (no rigid motion)")]
    ZeroRealPart,
    /// A dual quaternion off the Study quadric (Jüttler's Plücker relation (8)).
    #[error(
        "the dual quaternion is off the Study quadric: Plücker's relation (8) fails, cosine between real and dual part {cosine:e}"
    )]
    OffStudyQuadric {
        /// `Q⁰·Q^ε/(|Q⁰| |Q^ε|)`.
        cosine: f64,
    },
    /// A NaN or infinite input.
    #[error("a coefficient is not finite")]
    NotFinite,
    /// Weights that sum to zero.
    #[error("the weights sum to zero")]
    ZeroWeight,
    /// Key times that are not finite and strictly increasing, or not one per pose.
    #[error("times: {why}")]
    Times {
        /// What is wrong.
        why: String,
    },
}

/// `times` has `n` finite, strictly increasing values.
pub(crate) fn check_times<T: Real>(times: &[T], n: usize) -> Result<(), ReprError> {
    if times.len() != n {
        return Err(ReprError::Times { why: format!("{} times for {n} poses", times.len()) });
    }
    if let Some(i) = times.iter().position(|t| !t.is_finite()) {
        return Err(ReprError::Times { why: format!("time {i} is not finite") });
    }
    if let Some(i) = (1..n).find(|&i| times[i] <= times[i - 1]) {
        return Err(ReprError::Times { why: format!("time {i} is not larger than time {}", i - 1) });
    }
    Ok(())
}
