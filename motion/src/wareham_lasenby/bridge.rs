//! The one place where Wareham–Lasenby code touches the layout of [`Pose`]: its eight
//! coefficients in the main paper's order `[S∅, S12, S13, S23, S1∞, S2∞, S3∞, Sω]`.
//! Everything else in [`crate::wareham_lasenby`] uses public pose methods only.
//!
//! ```
//! use motion::Pose;
//! use motion::wareham_lasenby::bridge::{pose_from_array, pose_to_array};
//! let s = Pose::<f64>::translation(&[2.0, 0.0, 0.0]);
//! assert_eq!(pose_to_array(&s), [1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0]);
//! assert_eq!(pose_from_array(pose_to_array(&s)), s);
//! ```

use crate::{Motor, Pose};
use algebra_core::Ring;

/// The coefficients `[S∅, S12, S13, S23, S1∞, S2∞, S3∞, Sω]` of a pose.
///
/// ```
/// let a = motion::wareham_lasenby::bridge::pose_to_array(&motion::Pose::<f64>::identity());
/// assert_eq!(a, [1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0]);
/// ```
pub fn pose_to_array<T: Ring>(s: &Pose<T>) -> [T; 8] {
    s.components().map(Clone::clone)
}

/// The pose with coefficients `[S∅, S12, S13, S23, S1∞, S2∞, S3∞, Sω]`.
///
/// ```
/// let s = motion::wareham_lasenby::bridge::pose_from_array([1.0, 0.0, 0.0, 0.0, 0.5, 0.0, 0.0, 0.0]);
/// assert_eq!(s, motion::Pose::translation(&[1.0, 0.0, 0.0]));
/// ```
pub fn pose_from_array<T: Ring>(c: [T; 8]) -> Pose<T> {
    Pose::from_motor(Motor::from_array(c))
}
