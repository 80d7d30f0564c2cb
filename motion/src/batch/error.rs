//! [`BatchError`]: why a batch operation refused its input, with the index of the element.

use crate::{CurveError, MotionError};

/// Why a batch operation failed. Every variant names the element (row) it is about, so a bad
/// point in a cloud of a million is found without searching.
///
/// ```
/// use motion::batch::{BatchError, Points};
/// let err = Points::from_columns(vec![1.0, 2.0], vec![0.0], vec![0.0, 0.0]).unwrap_err();
/// assert_eq!(err, BatchError::LengthMismatch { what: "y column", expected: 2, got: 1 });
/// let err = Points::from_columns(vec![1.0, f64::NAN], vec![0.0; 2], vec![0.0; 2]).unwrap_err();
/// assert!(matches!(err, BatchError::NotFinite { what: "point", index: 1, .. }));
/// ```
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum BatchError {
    /// Two inputs that must have one entry per element differ in length.
    #[error("{what} has {got} entries, expected {expected}")]
    LengthMismatch {
        /// Which input.
        what: &'static str,
        /// The length it must have.
        expected: usize,
        /// The length it has.
        got: usize,
    },
    /// An element with a NaN or infinite component.
    #[error("{what} {index} is not finite: {value}")]
    NotFinite {
        /// "point", "pose", "parameter", ...
        what: &'static str,
        /// The element's index.
        index: usize,
        /// The element, printed.
        value: String,
    },
    /// A pose operation failed on one element (a singular pose has no action or inverse).
    #[error("element {index}: {source}")]
    Pose {
        /// The element's index.
        index: usize,
        /// What failed.
        source: MotionError,
    },
    /// Evaluating motion `motion` at its parameter number `parameter` failed.
    #[error("motion {motion} at parameter {parameter}: {source}")]
    Curve {
        /// The motion's index.
        motion: usize,
        /// The parameter's index.
        parameter: usize,
        /// What failed.
        source: CurveError,
    },
}
