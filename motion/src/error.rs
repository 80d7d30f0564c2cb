//! [`MotionError`]: every way a pose operation can fail, and [`CurveError`]: every way building
//! or evaluating a motion curve can fail. Operations return a typed error
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
    /// A tolerance that is NaN, negative or infinite (an infinite one would accept any
    /// matrix, a shear among them).
    #[error("{op}: the tolerance {value} must be a finite number >= 0")]
    BadTolerance {
        /// The operation.
        op: &'static str,
        /// The tolerance, printed.
        value: String,
    },
}

/// Why building or evaluating a motion curve failed.
///
/// Values are carried as their printed form, so the error type does not depend on the scalar.
/// Pose-level failures (a singular pose in a slerp, an inverse, ...) are wrapped unchanged.
///
/// ```
/// use motion::{AdditiveBezier, CurveError, Motion, Pose};
/// let m = AdditiveBezier::new(vec![Pose::<f64>::identity(), Pose::translation(&[1.0, 0.0, 0.0])]).unwrap();
/// assert!(matches!(m.pose(&1.5), Err(CurveError::OutOfDomain { .. })));
/// assert!(matches!(AdditiveBezier::<f64>::new(vec![]), Err(CurveError::TooFewPoses { need: 1, got: 0 })));
/// ```
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum CurveError {
    /// A pose operation failed (singular pose, non-finite value, ...).
    #[error(transparent)]
    Pose(#[from] MotionError),
    /// The parameter is outside the motion's domain (or is NaN).
    #[error("the parameter {t} is outside the domain [{start}, {end}]")]
    OutOfDomain {
        /// The parameter, printed.
        t: String,
        /// The start of the domain, printed.
        start: String,
        /// The end of the domain, printed.
        end: String,
    },
    /// Not enough control poses for the requested degree.
    #[error("needs at least {need} control poses, got {got}")]
    TooFewPoses {
        /// The minimum.
        need: usize,
        /// What was given.
        got: usize,
    },
    /// A knot vector of the wrong length: `poses + degree + 1` knots are needed.
    #[error("a B-spline of degree {degree} with {poses} control poses needs {expected} knots, got {got}")]
    KnotCount {
        /// The degree.
        degree: usize,
        /// The number of control poses.
        poses: usize,
        /// `poses + degree + 1`.
        expected: usize,
        /// What was given.
        got: usize,
    },
    /// A knot (or breakpoint) that is NaN or infinite.
    #[error("{what} {index} is {value}, not finite")]
    NotFiniteParameter {
        /// "knot" or "breakpoint".
        what: &'static str,
        /// Its index.
        index: usize,
        /// The value, printed.
        value: String,
    },
    /// Knots must be non-decreasing.
    #[error("knot {index} ({value}) is smaller than knot {} ({previous}): knots must be non-decreasing", index - 1)]
    KnotsDecreasing {
        /// The index of the offending knot.
        index: usize,
        /// Its value, printed.
        value: String,
        /// The previous knot, printed.
        previous: String,
    },
    /// A knot value repeated more than `degree + 1` times.
    #[error("the knot {value} is repeated {multiplicity} times; degree {degree} allows at most {}", degree + 1)]
    KnotMultiplicity {
        /// The knot value, printed.
        value: String,
        /// How often it occurs.
        multiplicity: usize,
        /// The degree.
        degree: usize,
    },
    /// The parameter domain `[u_p, u_{n+1}]` of a B-spline has zero length.
    #[error("the B-spline domain [{start}, {end}] is empty")]
    EmptyDomain {
        /// `u_p`, printed.
        start: String,
        /// `u_{n+1}`, printed.
        end: String,
    },
    /// A piecewise motion without segments.
    #[error("a piecewise motion needs at least one segment")]
    NoSegments,
    /// A piecewise motion needs one more breakpoint than segments.
    #[error("{segments} segments need {} breakpoints, got {got}", segments + 1)]
    BreakCount {
        /// The number of segments.
        segments: usize,
        /// The number of breakpoints given.
        got: usize,
    },
    /// Breakpoints must be strictly increasing.
    #[error("breakpoint {index} ({value}) is not greater than breakpoint {} ({previous})", index - 1)]
    BreaksNotIncreasing {
        /// The index of the offending breakpoint.
        index: usize,
        /// Its value, printed.
        value: String,
        /// The previous breakpoint, printed.
        previous: String,
    },
}
