//! The JSON input format of the motion commands, owned by the library (feature `serde`): pose
//! objects ([`pose::PoseObject`], every form of the CLI contract's "Pose objects"), the spec
//! of `gam interpolate` / `gam trajectory` ([`interpolate::InterpolateSpec`]) and explicit
//! control data for `gam plot` ([`control::ControlSpec`]); the spec of
//! `gam hermite` / `gam sample` is [`crate::spec::HermiteSpec`]. The `gam` CLI, and any other
//! front door (a Python binding), deserializes through these types, so every rule and every
//! message of the format lives here once.
//!
//! Reading happens in two steps, each with its own errors:
//! 1. serde: the JSON text (or an already parsed [`serde_json::Value`]) into the shape of the
//!    format: wrong types, unknown fields, and **duplicate keys** (refused everywhere: a key
//!    given twice in a pose object or spec is an error naming the key, never last-wins) give
//!    [`SchemaError::Json`] or [`SchemaError::Invalid`] with serde's message (and the line and
//!    column, when read from text);
//! 2. the typed checks of the format: each refusal is one [`SchemaError`] variant whose message
//!    names the place in the document (`poses[1].quaternion`, `shape`, ...).
//!
//! [`SchemaError::is_input`] tells bad input (the CLI's exit status 2) from a mathematical
//! failure (exit 1), and the messages are the CLI's (`gam` prints `error: `FILE`: MESSAGE`).
//!
//! ```
//! use motion::schema::{SchemaError, pose::PoseObject};
//! let p = PoseObject::from_json(r#"{"position": [1, 2, 3], "quaternion": [1, 0, 0, 0]}"#, "pose")?;
//! assert_eq!(p.to_pose()?.transform_point(&[0.0; 3])?, [1.0, 2.0, 3.0]);
//! let dup = PoseObject::from_json(r#"{"angle": 1, "axis": [0, 0, 1], "angle": 2}"#, "pose").unwrap_err();
//! assert!(dup.to_string().contains("duplicate key `angle`"));
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

pub mod control;
pub mod interpolate;
mod number;
pub mod pose;
mod strict;

pub use control::ControlSpec;
pub use interpolate::{InterpolateSpec, MAX_SAMPLES};
pub use number::{Exact, SpecNumber, quote_numbers};
pub use pose::{PoseError, PoseObject};
pub use strict::StrictValue;

use crate::MotionError;
use crate::method::{BuildError, Method, MethodError};

/// Why a document of the format was refused (or, for [`SchemaError::Velocity`] and some
/// [`SchemaError::Build`]s, could not be turned into a motion).
///
/// The messages are those of the `gam` CLI, naming the place in the document.
///
/// ```
/// use motion::schema::SchemaError;
/// let e = SchemaError::Samples { got: 1 };
/// assert_eq!(e.to_string(), "`samples` must be 0 or from 2 to 1000000 (got 1)");
/// assert!(e.is_input());
/// ```
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum SchemaError {
    /// The text is not JSON (serde_json's message, with line and column).
    #[error("invalid JSON: {0}")]
    Json(String),
    /// The JSON does not have the shape of the format: a wrong type, an unknown or missing
    /// field, a duplicate key (serde's message).
    #[error("invalid spec: {0}")]
    Invalid(String),
    /// A pose object given as text is not JSON-shaped right (a key given twice; serde's
    /// message).
    #[error("invalid pose object: {0}")]
    InvalidPose(String),
    /// A pose object of the wrong form or shape, or one that is not a pose.
    #[error("{}", source.message_at(at))]
    Pose {
        /// Where the pose object is (`pose`, `poses[2]`, ...).
        at: String,
        /// What is wrong with it.
        source: PoseError,
    },
    /// `method` names no method.
    #[error(transparent)]
    Method(#[from] MethodError),
    /// A refusal of [`Method::build`] (or a spec rule stated by it: an unused key, too few
    /// poses); the method is named where the failure is the method's own.
    #[error("{}", build_message(*method, source))]
    Build {
        /// The method.
        method: Method,
        /// The failure.
        source: BuildError,
    },
    /// `parameters` names no rule.
    #[error(
        "`parameters`: unknown rule `{got}` (uniform, chordal, star-chordal, centripetal, angular, angular-chordal, or a list)"
    )]
    UnknownRule {
        /// The name given.
        got: String,
    },
    /// `parameters` is a list with something else than numbers.
    #[error("`parameters` must be a list of numbers")]
    ParameterList,
    /// `parameters` is neither a rule name nor a list.
    #[error("`parameters` must be a rule name or a list (got {got})")]
    ParameterType {
        /// The value given, as JSON.
        got: String,
    },
    /// `shape` is neither a number nor one number per pose.
    #[error("`shape` must be a number or one number per pose")]
    ShapeForm,
    /// A shape factor that is not positive and finite.
    #[error("`shape` must be positive (got {})", format_f64(*got))]
    ShapeValue {
        /// The value given.
        got: f64,
    },
    /// `gamma` is neither a pair nor one pair per pose.
    #[error("`gamma` must be [alpha, beta] or one such pair per pose")]
    GammaForm,
    /// `velocities` does not have one entry per pose.
    #[error("`velocities` has {got} entries for {poses} poses")]
    VelocityCount {
        /// Entries given.
        got: usize,
        /// Poses given.
        poses: usize,
    },
    /// The velocity of the body origin could not be computed from a key pose (a
    /// mathematical failure).
    #[error(transparent)]
    Velocity(MotionError),
    /// `weights` names no weight functions of `hexanion-blend`.
    #[error("`weights`: {0}")]
    Weights(String),
    /// `degree` is negative.
    #[error("`degree` must be 1 or more (got {got})")]
    Degree {
        /// The value given.
        got: i64,
    },
    /// `l1` is negative.
    #[error("`l1` must be 0 or more (got {got})")]
    L1 {
        /// The value given.
        got: i64,
    },
    /// A field of control data that is missing or of the wrong shape.
    #[error("`{at}` must be {expected}")]
    Field {
        /// Where (`segments`, `segments[2].t0`, `body_points`).
        at: String,
        /// What it must be.
        expected: &'static str,
    },
    /// Control data whose segments have different representations.
    #[error("`segments[{segment}].representation` is `{got}`, but segment 0's is `{first}`: one kind per plot")]
    MixedRepresentation {
        /// The first segment that differs.
        segment: usize,
        /// Its representation.
        got: String,
        /// Segment 0's.
        first: String,
    },
    /// Control data with a gap: segment `segment` does not start where the one before ends.
    #[error("`segments[{segment}].t0` must equal `segments[{}].t1` (no gaps)", segment - 1)]
    Gap {
        /// The segment after the gap (at least 1).
        segment: usize,
    },
    /// `samples` is 1 or more than [`MAX_SAMPLES`].
    #[error("`samples` must be 0 or from 2 to {MAX_SAMPLES} (got {got})")]
    Samples {
        /// The value given.
        got: usize,
    },
}

impl SchemaError {
    /// `true` for bad input (the CLI's exit status 2), `false` for a mathematical failure
    /// (exit 1: a velocity that cannot be computed, a method whose system is singular, ...).
    ///
    /// ```
    /// use motion::schema::SchemaError;
    /// assert!(SchemaError::ShapeForm.is_input());
    /// assert!(!SchemaError::Velocity(motion::MotionError::ZeroAxis).is_input());
    /// ```
    pub fn is_input(&self) -> bool {
        match self {
            SchemaError::Velocity(_) => false,
            SchemaError::Build { source, .. } => source.is_input(),
            _ => true,
        }
    }

    /// A serde_json error while reading `what`: a syntax error is [`SchemaError::Json`],
    /// anything else (type, field, duplicate key) [`SchemaError::Invalid`].
    fn of_json(e: &serde_json::Error) -> Self {
        use serde_json::error::Category;
        match e.classify() {
            Category::Syntax | Category::Eof | Category::Io => SchemaError::Json(e.to_string()),
            Category::Data => SchemaError::Invalid(e.to_string()),
        }
    }
}

/// Parses JSON text into a value, refusing keys given twice anywhere ([`StrictValue`]): a syntax
/// error is [`SchemaError::Json`], a repeated key [`SchemaError::Invalid`] naming it.
///
/// ```
/// let v = motion::schema::parse_json(r#"{"poses": [{"position": [1, 2, 3]}]}"#)?;
/// assert_eq!(v["poses"][0]["position"][2], 3);
/// let e = motion::schema::parse_json(r#"{"a": {"b": 1, "b": 1}}"#).unwrap_err();
/// assert!(e.to_string().starts_with("invalid spec: duplicate key `b` at line 1"));
/// # Ok::<(), motion::schema::SchemaError>(())
/// ```
pub fn parse_json(text: &str) -> Result<serde_json::Value, SchemaError> {
    serde_json::from_str::<StrictValue>(text).map(|v| v.0).map_err(|e| SchemaError::of_json(&e))
}

/// The message of [`SchemaError::Build`]: prefixed by the method where the failure is its own.
fn build_message(method: Method, e: &BuildError) -> String {
    let own = matches!(
        e,
        BuildError::Trajectory(_)
            | BuildError::Wl(_)
            | BuildError::Repr(_)
            | BuildError::Juttler(_)
            | BuildError::Unstable { .. }
    );
    if own { format!("{}: {e}", method.name()) } else { e.to_string() }
}

/// How the messages of the format (and the `gam` CLI) print a number: the shortest round-trip
/// decimal, plain for moderate magnitudes and in exponent form (`1.2246467991473532e-16`)
/// outside `1e-7 <= |x| < 1e16`, like JavaScript.
///
/// ```
/// use motion::schema::format_f64;
/// assert_eq!((format_f64(0.5), format_f64(-1e-300), format_f64(1e16)), ("0.5".into(), "-1e-300".into(), "1e16".into()));
/// ```
pub fn format_f64(x: f64) -> String {
    let a = x.abs();
    if a == 0.0 || !x.is_finite() || (1e-7..1e16).contains(&a) { format!("{x}") } else { format!("{x:e}") }
}
