//! Jüttler's rational motions ("Visualization of moving objects using dual quaternion
//! curves", Secs. 2-5; issue 11), on the dual quaternions of [`crate::repr::dual_quaternion`]
//! (his conventions, the pose map stated there).
//!
//! | module | contents | paper |
//! |---|---|---|
//! | [`parametrisation`] | parameters `t_i` of the given positions: chordal, `*`-chordal, equidistant, centripetal, angular, angle + distance, explicit | eq. (15) |
//!
//! The parametrisations that take square roots or angles need [`algebra_core::Real`]; the
//! rest is exact over [`algebra_core::rational::Q`].

pub mod parametrisation;

pub use parametrisation::{Parametrisation, parameters};

use crate::MotionError;
use crate::repr::ReprError;

/// Why a construction of this module failed.
///
/// ```
/// let e = motion::juttler::JuttlerError::TooFewPositions { need: 2, got: 1 };
/// assert_eq!(e.to_string(), "needs at least 2 positions, got 1");
/// ```
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum JuttlerError {
    /// Fewer positions (or control points) than the construction needs.
    #[error("needs at least {need} positions, got {got}")]
    TooFewPositions {
        /// The minimum.
        need: usize,
        /// What was given.
        got: usize,
    },
    /// Parameters that are not `m + 1` finite, strictly increasing values.
    #[error("parameters: {why}")]
    Parameters {
        /// What is wrong.
        why: String,
    },
    /// A parametrisation step `Δt_i` of (15) that is zero or negative (e.g. two positions
    /// with the same origin under the chordal parametrisation).
    #[error("the parameter step between positions {index} and {} is {value}, not positive", index + 1)]
    ZeroStep {
        /// The index `i` of `Δt_i`.
        index: usize,
        /// The step, printed.
        value: String,
    },
    /// A dual-quaternion Bézier curve off the Study quadric: the Bernstein coefficient
    /// `index` of the Study polynomial `Scal(Q⁰ Q̃^ε)` is not (close to) zero.
    #[error("not a Q-motion: Plücker's relation (8) fails, Study polynomial coefficient {index} is {value}")]
    NotQMotion {
        /// The Bernstein index of the offending coefficient.
        index: usize,
        /// Its value, printed.
        value: String,
    },
    /// A trajectory control point (or point of the curve) with weight zero (at infinity).
    #[error("the rational Bézier curve has weight zero at {what}")]
    ZeroWeight {
        /// Where: "control point i" or "t = ...".
        what: String,
    },
    /// A pose operation failed.
    #[error(transparent)]
    Motion(#[from] MotionError),
    /// A dual quaternion <-> pose conversion failed.
    #[error(transparent)]
    Repr(#[from] ReprError),
}
