//! The spec of one Hermite segment (the input of `gam hermite`, shared/cli.md), its checks and
//! the segment it describes: the library owns the format, the CLI only reads the file.
//!
//! A [`HermiteSpec`] gives, at each end, the position of the reference point, the rotation
//! (axis, normalised, and angle), the velocity of the reference point and the angular velocity,
//! and optionally the shape factor `shape` (λ, default 1, positive) and `gamma` (`[α, β]` for
//! `α + βω`, default `[0, 0]`). The end poses are `S = R T`; `ν = Ω e123 + u einf` with
//! `u = v - Ω × r`; `Ψ = λ(ν + γ)`; the control poses next to the ends follow eq. (22)
//! (additive) or eq. (23) (multiplicative), read as in Sec. 5.2 ([`crate::joins`]). Degrees
//! above 3 spread the inner control poses evenly ([`crate::hermite::hermite_segment`]).
//!
//! [`HermiteSpec::check`] applies every rule of the format and returns a typed [`SpecError`];
//! [`HermiteSpec::segment`] checks and builds. With the feature `serde` the types derive
//! `Serialize`/`Deserialize` with exactly the field names of the JSON format (unknown fields
//! rejected).
//!
//! ```
//! use motion::spec::{EndSpec, HermiteSpec, SpecKind};
//! let start = EndSpec::new([0.0; 3], [0.0, 0.0, 1.0], 0.0, [3.0, 0.0, 0.0], [0.0; 3]);
//! let end = EndSpec::new([3.0, 0.0, 0.0], [0.0, 0.0, 1.0], 0.0, [3.0, 0.0, 0.0], [0.0; 3]);
//! let spec = HermiteSpec::new(SpecKind::Additive, 3, start, end);
//! let seg = spec.segment()?;
//! assert_eq!(seg.control_poses()[1], motion::Pose::translation(&[1.0, 0.0, 0.0]));
//! # Ok::<(), motion::spec::SpecError>(())
//! ```

use crate::hermite::{AnyHermiteSegment, hermite_segment};
use crate::joins::{EndCondition, JoinError, SegmentKind, Shape};
use crate::{MotionError, Pose, Pseudoscalar};
use algebra_core::Real;

/// The largest degree accepted (a segment of degree `n` has `n + 1` control poses).
pub const MAX_DEGREE: i64 = 10_000;

/// The segment kind, as spelled in a spec (`"additive"` or `"multiplicative"`).
///
/// ```
/// use motion::{SegmentKind, spec::SpecKind};
/// assert_eq!(SegmentKind::from(SpecKind::Multiplicative), SegmentKind::Multiplicative);
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize), serde(rename_all = "lowercase"))]
pub enum SpecKind {
    /// An additive Bezier segment (eq. 18, joins by eq. 22).
    Additive,
    /// A multiplicative Bezier segment (Fig. 2, joins by eq. 23).
    Multiplicative,
}

impl From<SpecKind> for SegmentKind {
    fn from(k: SpecKind) -> Self {
        match k {
            SpecKind::Additive => SegmentKind::Additive,
            SpecKind::Multiplicative => SegmentKind::Multiplicative,
        }
    }
}

impl From<SegmentKind> for SpecKind {
    fn from(k: SegmentKind) -> Self {
        match k {
            SegmentKind::Additive => SpecKind::Additive,
            SegmentKind::Multiplicative => SpecKind::Multiplicative,
        }
    }
}

/// One end condition of a [`HermiteSpec`].
///
/// ```
/// let e = motion::spec::EndSpec::new([0.0; 3], [1.0, 0.0, 0.0], 0.5, [1.0, 0.0, 0.0], [0.0; 3]);
/// assert_eq!((e.shape, e.gamma), (1.0, [0.0, 0.0]));
/// ```
///
/// The numbers are `f64` by default; a spec read with exact numbers
/// (`EndSpec<motion::schema::Exact>`) is mapped to any real scalar with [`EndSpec::map`].
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize),
    serde(deny_unknown_fields, bound = "N: crate::schema::SpecNumber")
)]
pub struct EndSpec<N = f64> {
    /// The position `r` of the reference point (the translation of `S = R T`).
    pub position: [N; 3],
    /// The rotation axis (normalised; not zero).
    pub axis: [N; 3],
    /// The rotation angle (radians, right-handed).
    pub angle: N,
    /// The velocity `v` of the reference point.
    pub velocity: [N; 3],
    /// The angular velocity `Ω` (fixed frame).
    pub angular_velocity: [N; 3],
    /// The shape factor λ (positive; default 1).
    #[cfg_attr(feature = "serde", serde(default = "crate::schema::SpecNumber::one"))]
    pub shape: N,
    /// `[α, β]` of the pseudoscalar `γ = α + βω` (default `[0, 0]`).
    #[cfg_attr(feature = "serde", serde(default = "zero_pair"))]
    pub gamma: [N; 2],
}

#[cfg(feature = "serde")]
fn zero_pair<N: crate::schema::SpecNumber>() -> [N; 2] {
    [N::zero(), N::zero()]
}

impl<N> EndSpec<N> {
    /// The same end with every number mapped by `f` (e.g. exact numbers rounded once to a
    /// precision).
    ///
    /// ```
    /// let e = motion::spec::EndSpec::new([1.0, 2.0, 3.0], [0.0, 0.0, 1.0], 0.5, [0.0; 3], [0.0; 3]);
    /// assert_eq!(e.map(&|x: &f64| 2.0 * x).position, [2.0, 4.0, 6.0]);
    /// ```
    pub fn map<M>(&self, f: &dyn Fn(&N) -> M) -> EndSpec<M> {
        let a3 = |v: &[N; 3]| v.each_ref().map(f);
        EndSpec {
            position: a3(&self.position),
            axis: a3(&self.axis),
            angle: f(&self.angle),
            velocity: a3(&self.velocity),
            angular_velocity: a3(&self.angular_velocity),
            shape: f(&self.shape),
            gamma: self.gamma.each_ref().map(f),
        }
    }
}

impl EndSpec {
    /// An end condition with `shape = 1` and `gamma = [0, 0]`.
    ///
    /// ```
    /// let e = motion::spec::EndSpec::new([1.0, 2.0, 3.0], [0.0, 0.0, 1.0], 0.0, [0.0; 3], [0.0; 3]);
    /// assert_eq!(e.position, [1.0, 2.0, 3.0]);
    /// ```
    pub fn new(position: [f64; 3], axis: [f64; 3], angle: f64, velocity: [f64; 3], angular_velocity: [f64; 3]) -> Self {
        EndSpec { position, axis, angle, velocity, angular_velocity, shape: 1.0, gamma: [0.0, 0.0] }
    }

    /// The same end with shape factor `shape` and pseudoscalar `gamma`.
    ///
    /// ```
    /// let e = motion::spec::EndSpec::new([0.0; 3], [0.0, 0.0, 1.0], 0.0, [0.0; 3], [0.0; 3]).shaped(4.0, [0.5, 0.5]);
    /// assert_eq!((e.shape, e.gamma), (4.0, [0.5, 0.5]));
    /// ```
    pub fn shaped(mut self, shape: f64, gamma: [f64; 2]) -> Self {
        self.shape = shape;
        self.gamma = gamma;
        self
    }
}

impl<T: Real> EndSpec<T> {
    /// The end condition and shape it describes (after [`HermiteSpec::check`]).
    ///
    /// ```
    /// let e = motion::spec::EndSpec::new([0.0; 3], [0.0, 0.0, 1.0], 0.0, [1.0, 0.0, 0.0], [0.0; 3]);
    /// let (cond, shape) = e.end_condition("start")?;
    /// assert_eq!(cond.velocity_bivector().e1inf, 1.0);
    /// assert_eq!(shape.lambda, 1.0);
    /// # Ok::<(), motion::spec::SpecError>(())
    /// ```
    pub fn end_condition(&self, name: &'static str) -> Result<(EndCondition<T>, Shape<T>), SpecError> {
        let cond = EndCondition::from_axis_angle(
            &self.position,
            &self.axis,
            &self.angle,
            &self.velocity,
            &self.angular_velocity,
        )
        .map_err(|e| match e {
            MotionError::ZeroAxis => SpecError::ZeroAxis { end: name },
            other => SpecError::Motion { end: Some(name), source: other },
        })?;
        let [a, b] = self.gamma.clone();
        Ok((cond, Shape::new(self.shape.clone(), Pseudoscalar::new(a, b))))
    }

    fn check(&self, name: &'static str) -> Result<(), SpecError> {
        if self.axis.iter().all(|x| x.is_exact_zero()) {
            return Err(SpecError::ZeroAxis { end: name });
        }
        // not (shape > 0) also catches NaN
        if self.shape.partial_cmp(&T::zero()) != Some(std::cmp::Ordering::Greater) {
            return Err(SpecError::Shape { end: name, got: self.shape.to_f64() });
        }
        let all = self.position.iter().chain(&self.axis).chain([&self.angle]).chain(&self.velocity);
        if let Some(x) =
            all.chain(&self.angular_velocity).chain([&self.shape]).chain(&self.gamma).find(|x| !Real::is_finite(*x))
        {
            return Err(SpecError::NotFinite { end: name, value: x.to_f64() });
        }
        Ok(())
    }
}

/// A Hermite segment of degree `n` from its two end conditions (the `gam hermite` format).
///
/// ```
/// use motion::spec::{EndSpec, HermiteSpec, SpecKind};
/// let a = EndSpec::new([0.0; 3], [0.0, 0.0, 1.0], 0.0, [0.0; 3], [0.0; 3]);
/// let spec = HermiteSpec::new(SpecKind::Multiplicative, 5, a.clone(), a);
/// assert_eq!(spec.segment()?.degree(), 5);
/// # Ok::<(), motion::spec::SpecError>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize),
    serde(deny_unknown_fields, bound = "N: crate::schema::SpecNumber")
)]
pub struct HermiteSpec<N = f64> {
    /// Additive or multiplicative.
    pub kind: SpecKind,
    /// The degree `n`, from 3 to [`MAX_DEGREE`].
    pub degree: i64,
    /// The condition at `t = 0`.
    pub start: EndSpec<N>,
    /// The condition at `t = 1`.
    pub end: EndSpec<N>,
    /// A body point (body coordinates) for sampling (`gam sample` / `gam plot`); not part of the
    /// segment.
    #[cfg_attr(feature = "serde", serde(default, skip_serializing_if = "Option::is_none"))]
    pub body_point: Option<[N; 3]>,
}

impl<N> HermiteSpec<N> {
    /// The same spec with every number mapped by `f`.
    ///
    /// ```
    /// use motion::spec::{EndSpec, HermiteSpec, SpecKind};
    /// let a = EndSpec::new([0.0; 3], [0.0, 0.0, 1.0], 0.0, [0.0; 3], [0.0; 3]);
    /// let spec = HermiteSpec::new(SpecKind::Additive, 3, a.clone(), a);
    /// assert_eq!(spec.map(&|x: &f64| *x as f32).degree, 3);
    /// ```
    pub fn map<M>(&self, f: &dyn Fn(&N) -> M) -> HermiteSpec<M> {
        HermiteSpec {
            kind: self.kind,
            degree: self.degree,
            start: self.start.map(f),
            end: self.end.map(f),
            body_point: self.body_point.as_ref().map(|p| p.each_ref().map(f)),
        }
    }
}

impl HermiteSpec {
    /// A spec without a body point.
    ///
    /// ```
    /// use motion::spec::{EndSpec, HermiteSpec, SpecKind};
    /// let a = EndSpec::new([0.0; 3], [0.0, 0.0, 1.0], 0.0, [0.0; 3], [0.0; 3]);
    /// assert_eq!(HermiteSpec::new(SpecKind::Additive, 3, a.clone(), a).body_point, None);
    /// ```
    pub fn new(kind: SpecKind, degree: i64, start: EndSpec, end: EndSpec) -> Self {
        HermiteSpec { kind, degree, start, end, body_point: None }
    }
}

impl<T: Real> HermiteSpec<T> {
    /// Every rule of the format: degree in `3..=MAX_DEGREE`, non-zero axes, positive shape
    /// factors, finite numbers (the body point too).
    ///
    /// ```
    /// use motion::spec::{EndSpec, HermiteSpec, SpecError, SpecKind};
    /// let a = EndSpec::new([0.0; 3], [0.0, 0.0, 1.0], 0.0, [0.0; 3], [0.0; 3]);
    /// let bad = HermiteSpec::new(SpecKind::Additive, 3, a.clone(), a.clone().shaped(0.0, [0.0, 0.0]));
    /// assert!(matches!(bad.check(), Err(SpecError::Shape { end: "end", .. })));
    /// assert!(matches!(HermiteSpec::new(SpecKind::Additive, 2, a.clone(), a).check(), Err(SpecError::Degree { got: 2 })));
    /// ```
    pub fn check(&self) -> Result<(), SpecError> {
        if !(3..=MAX_DEGREE).contains(&self.degree) {
            return Err(SpecError::Degree { got: self.degree });
        }
        self.start.check("start")?;
        self.end.check("end")?;
        if let Some(p) = &self.body_point
            && let Some(x) = p.iter().find(|x| !Real::is_finite(*x))
        {
            return Err(SpecError::NotFinite { end: "body_point", value: x.to_f64() });
        }
        Ok(())
    }

    /// Checks the spec and builds its segment ([`hermite_segment`]); a non-finite result (an
    /// overflow) is [`SpecError::NotFinite`] with `end = "result"`.
    ///
    /// ```
    /// use motion::spec::{EndSpec, HermiteSpec, SpecKind};
    /// let a = EndSpec::new([0.0; 3], [0.0, 0.0, 1.0], 0.0, [1.0, 0.0, 0.0], [0.0; 3]);
    /// let seg = HermiteSpec::new(SpecKind::Additive, 3, a.clone(), a).segment()?;
    /// assert_eq!(seg.velocity_bivectors()[0].e1inf, 1.0);
    /// # Ok::<(), motion::spec::SpecError>(())
    /// ```
    pub fn segment(&self) -> Result<AnyHermiteSegment<T>, SpecError> {
        self.check()?;
        let degree = self.degree as usize; // 3..=MAX_DEGREE
        let (start, start_shape) = self.start.end_condition("start")?;
        let (end, end_shape) = self.end.end_condition("end")?;
        let seg =
            hermite_segment(self.kind.into(), degree, &start, &end, &start_shape, &end_shape).map_err(|e| match e {
                JoinError::Motion(m) => SpecError::Motion { end: None, source: m },
                other => SpecError::Join(other),
            })?;
        let nus = seg.velocity_bivectors().iter().map(Pose::from);
        let mut all = seg.control_poses().iter().cloned().chain(nus).chain(seg.velocity_indicatrices().iter().cloned());
        if !all.all(|m| m.is_finite()) {
            return Err(SpecError::NotFinite { end: "result", value: f64::INFINITY });
        }
        Ok(seg)
    }
}

#[cfg(feature = "serde")]
impl HermiteSpec {
    /// Reads a spec from JSON text and checks it ([`HermiteSpec::check`]).
    ///
    /// ```
    /// use motion::spec::{HermiteSpec, SpecError};
    /// let e = HermiteSpec::from_json(r#"{"kind": "additive", "degree": 3, "start": {}}"#).unwrap_err();
    /// assert!(matches!(&e, SpecError::Invalid(m) if m.starts_with("missing field `start.position`")));
    /// let e = HermiteSpec::from_json(r#"{"kind": "additive", "kind": "additive"}"#).unwrap_err();
    /// assert!(e.to_string().contains("duplicate field `kind`"));
    /// ```
    pub fn from_json(text: &str) -> Result<Self, SpecError> {
        let spec = HermiteSpec::read_json(text)?;
        spec.check()?;
        Ok(spec)
    }

    /// Reads a spec from a parsed JSON value and checks it.
    ///
    /// ```
    /// use motion::spec::HermiteSpec;
    /// let end = serde_json::json!({"position": [0, 0, 0], "axis": [0, 0, 1], "angle": 0,
    ///     "velocity": [1, 0, 0], "angular_velocity": [0, 0, 0]});
    /// let spec = HermiteSpec::from_value(&serde_json::json!({"kind": "additive", "degree": 3, "start": end, "end": end}))?;
    /// assert_eq!(spec.degree, 3);
    /// # Ok::<(), motion::spec::SpecError>(())
    /// ```
    pub fn from_value(v: &serde_json::Value) -> Result<Self, SpecError> {
        use serde::Deserialize;
        let spec = HermiteSpec::deserialize(v).map_err(|e| SpecError::Invalid(e.to_string()))?;
        spec.check()?;
        Ok(spec)
    }
}

#[cfg(feature = "serde")]
impl<N: crate::schema::SpecNumber> HermiteSpec<N> {
    /// Reads a spec from JSON text in any number type, without the checks of
    /// [`HermiteSpec::check`] (which need a real scalar: map the spec first).
    /// [`crate::schema::Exact`] reads every literal as written.
    ///
    /// ```
    /// use algebra_core::rational::ratio;
    /// use motion::{schema::Exact, spec::HermiteSpec};
    /// let end = r#"{"position": [0.1, 0, 0], "axis": [0, 0, 1], "angle": 0, "velocity": [1, 0, 0], "angular_velocity": [0, 0, 0]}"#;
    /// let spec = HermiteSpec::<Exact>::read_json(&format!(r#"{{"kind": "additive", "degree": 3, "start": {end}, "end": {end}}}"#))?;
    /// assert_eq!(spec.start.position[0], Exact(ratio(1, 10)));
    /// # Ok::<(), motion::spec::SpecError>(())
    /// ```
    pub fn read_json(text: &str) -> Result<Self, SpecError> {
        let prepared = N::prepare_text(text);
        serde_json::from_str(&prepared).map_err(|e| {
            use serde_json::error::Category;
            match e.classify() {
                Category::Syntax | Category::Eof | Category::Io => SpecError::Json(e.to_string()),
                Category::Data => SpecError::Invalid(qualify_missing_field(&e.to_string(), &prepared)),
            }
        })
    }
}

/// serde reports a missing field by its name only; name the end it is missing from
/// (`missing field `start.velocity``) when that can be told.
#[cfg(feature = "serde")]
fn qualify_missing_field(message: &str, text: &str) -> String {
    let Some(rest) = message.strip_prefix("missing field `") else { return message.to_string() };
    let Some((field, tail)) = rest.split_once('`') else { return message.to_string() };
    let Ok(value) = serde_json::from_str::<serde_json::Value>(text) else { return message.to_string() };
    if value.get(field).is_some() || ["kind", "degree", "start", "end"].contains(&field) {
        return message.to_string();
    }
    for end in ["start", "end"] {
        if value.get(end).is_some_and(|v| v.is_object() && v.get(field).is_none()) {
            return format!("missing field `{end}.{field}`{tail}");
        }
    }
    message.to_string()
}

/// Why a [`HermiteSpec`] was rejected or could not be built.
///
/// [`SpecError::is_input`] tells bad input (the CLI's exit 2) from a mathematical failure
/// (exit 1).
///
/// ```
/// use motion::spec::SpecError;
/// let e = SpecError::ZeroAxis { end: "end" };
/// assert_eq!(e.to_string(), "`end.axis` has length zero");
/// assert!(e.is_input());
/// ```
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SpecError {
    /// The text is not JSON (serde_json's message, with line and column; `HermiteSpec::from_json`, feature `serde`).
    #[error("invalid JSON: {0}")]
    Json(String),
    /// The JSON is not a spec: a wrong type, an unknown, missing or repeated field (serde's
    /// message; a missing field of an end is named `start.velocity`).
    #[error("invalid spec: {0}")]
    Invalid(String),
    /// The degree is outside `3..=MAX_DEGREE`.
    #[error(
        "`degree` must be an integer from 3 to {MAX_DEGREE} (got {got}): the end conditions fix the four control \
         poses S0, S1, S_(n-1) and Sn"
    )]
    Degree {
        /// The degree given.
        got: i64,
    },
    /// A rotation axis of length zero.
    #[error("`{end}.axis` has length zero")]
    ZeroAxis {
        /// `start` or `end`.
        end: &'static str,
    },
    /// A shape factor that is not positive.
    #[error("`{end}.shape` must be positive (got {got})")]
    Shape {
        /// `start` or `end`.
        end: &'static str,
        /// The value given.
        got: f64,
    },
    /// A NaN or infinite input (or, with `end = "result"`, an overflow in the result).
    #[error("{}", not_finite_message(end, *value))]
    NotFinite {
        /// `start`, `end`, `body_point` or `result`.
        end: &'static str,
        /// The value.
        value: f64,
    },
    /// The construction failed (bad input the checks could not see).
    #[error(transparent)]
    Join(JoinError),
    /// A pose operation failed (e.g. exp overflowed).
    #[error("{}{source}", end.map(|e| format!("`{e}`: ")).unwrap_or_default())]
    Motion {
        /// The end whose pose failed, if it was one end.
        end: Option<&'static str>,
        /// The failure.
        source: MotionError,
    },
}

fn not_finite_message(end: &str, value: f64) -> String {
    if end == "result" {
        "the result is not finite (overflow)".to_string()
    } else {
        format!("`{end}` has a value that is not finite ({value})")
    }
}

impl SpecError {
    /// `true` for bad input (exit 2 in the CLI), `false` for a mathematical failure (exit 1).
    ///
    /// ```
    /// use motion::spec::SpecError;
    /// assert!(SpecError::Degree { got: 1 }.is_input());
    /// assert!(!SpecError::NotFinite { end: "result", value: f64::INFINITY }.is_input());
    /// ```
    pub fn is_input(&self) -> bool {
        match self {
            SpecError::NotFinite { end, .. } => *end != "result",
            SpecError::Motion { .. } => false,
            _ => true,
        }
    }
}
