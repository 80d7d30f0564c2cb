//! The one place where `repr` touches the inside of [`Pose`]: its eight coefficients in the
//! paper's order `[S∅, S12, S13, S23, S1∞, S2∞, S3∞, Sω]` (eq. 4), both ways.
//!
//! ```
//! use motion::Pose;
//! use motion::repr::bridge::{pose_from_array, pose_to_array};
//! let t = Pose::translation(&[2.0, 0.0, 0.0]);
//! assert_eq!(pose_to_array(&t), [1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0]);
//! assert_eq!(pose_from_array(pose_to_array(&t)), t);
//! ```

use crate::{Motor, Pose};
use algebra_core::Ring;

/// The coefficients `[S∅, S12, S13, S23, S1∞, S2∞, S3∞, Sω]` of a pose.
///
/// ```
/// let c = motion::repr::bridge::pose_to_array(&motion::Pose::<f64>::identity());
/// assert_eq!(c[0], 1.0);
/// ```
pub fn pose_to_array<T: Ring>(s: &Pose<T>) -> [T; 8] {
    s.components().map(Clone::clone)
}

/// The pose with coefficients `[S∅, S12, S13, S23, S1∞, S2∞, S3∞, Sω]`.
///
/// ```
/// let s = motion::repr::bridge::pose_from_array([1.0, 0.0, 0.0, 0.0, 0.5, 0.0, 0.0, 0.0]);
/// assert_eq!(s, motion::Pose::translation(&[1.0, 0.0, 0.0]));
/// ```
pub fn pose_from_array<T: Ring>(c: [T; 8]) -> Pose<T> {
    let [s, b12, b13, b23, c1, c2, c3, w] = c;
    Pose::from_motor(Motor::new(s, b12, b13, b23, c1, c2, c3, w))
}
