//! [`MotionError`]: every way a pose operation can fail. Operations return a typed error
//! instead of a NaN or an infinity.

/// Why a pose operation failed.
///
/// Values are carried as their printed form, so the error type does not depend on the scalar.
///
/// ```
/// use motion::{MotionError, Pose};
/// // Only the translation part: rev(S) S = 0 + 0 ω is singular, F_S is the zero transform.
/// let s = Pose::new(0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0);
/// assert!(matches!(s.try_inverse(), Err(MotionError::Singular { .. })));
/// ```
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum MotionError {
    /// The pose is singular: `rev(S) S = α + βω` has `α = 0`, so `F_S` is the zero transform
    /// (Lemma 2.6) and `S` has no inverse, norm or logarithm.
    #[error("{op}: the pose {value} is singular (rev(S) S has zero scalar part; F_S is the zero transform)")]
    Singular {
        /// The operation.
        op: &'static str,
        /// The pose, printed.
        value: String,
    },
    /// A pseudoscalar `a + bω` with `a = 0` (no inverse, Lemma 2.4(i)), or with `a ≤ 0` where a
    /// square root or logarithm was asked for (Lemma 2.4(ii)).
    #[error("{op}: the pseudoscalar {value} needs a {need} scalar part")]
    Pseudoscalar {
        /// The operation.
        op: &'static str,
        /// The pseudoscalar, printed.
        value: String,
        /// "non-zero" or "positive".
        need: &'static str,
    },
    /// A rotation axis of length zero.
    #[error("the rotation axis has length zero")]
    ZeroAxis,
    /// An input or a result with a NaN or infinite component.
    #[error("{op}: {value} is not finite")]
    NotFinite {
        /// The operation.
        op: &'static str,
        /// The offending value, printed.
        value: String,
    },
    /// A 4x4 matrix that is not a rigid-body transform within the tolerance.
    #[error("the matrix is not a rigid-body transform: {why}")]
    NotRigid {
        /// What failed (bottom row, orthonormality or orientation).
        why: String,
    },
    /// A rotation quaternion `[w, x, y, z]` that is zero (no rotation to normalise to).
    #[error("the rotation quaternion is zero")]
    ZeroQuaternion,
}
