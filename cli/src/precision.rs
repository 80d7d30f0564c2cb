//! `--scalar f64|rational|mpfr:BITS` of the motion commands (shared/cli.md, "Precision of the
//! motion commands"): which scalar a command computes in, how a spec is read for it, and how
//! its numbers are printed.
//!
//! - `f64` (the default): the spec is read as always, every output unchanged.
//! - `rational`: the spec is read with every literal exact (`motion::schema::Exact`), the
//!   motion built by `motion::method::Method::build_exact`, every number printed as a `"p/q"`
//!   coefficient string; a method or pose form that needs a square root or a transcendental
//!   function exits 2 naming it.
//! - `mpfr:BITS`: the spec is read exactly and each number rounded once to `BITS` bits; every
//!   method runs at that precision ([`motion::method::Method::build`] over `MpFloat`) and prints
//!   its digits as strings.

use crate::error::CliError;
use crate::hermite::strip_comments;
use crate::interpolate::{schema_error, usage};
use crate::scalar::{CliScalar, ScalarKind};
use algebra_core::rational::{Q, parse_rational};
use algebra_core::{Field, MpFloat, PrecisionGuard, Ring};
use motion::Pose;
use motion::method::{BuildError, BuiltMotion, ExactMotion, MethodInput};
use motion::schema::{Exact, InterpolateSpec, PoseObject, SchemaError};
use serde_json::Value;

/// The scalar of a motion command.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum MotionScalar {
    /// IEEE doubles (the default).
    F64,
    /// Exact rationals.
    Rational,
    /// MPFR floats with this many bits.
    Mpfr(u32),
}

impl std::str::FromStr for MotionScalar {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, String> {
        match s.parse::<ScalarKind>()? {
            ScalarKind::F64 => Ok(MotionScalar::F64),
            ScalarKind::Rational => Ok(MotionScalar::Rational),
            ScalarKind::Mpfr(bits) => Ok(MotionScalar::Mpfr(bits)),
            ScalarKind::Poly => {
                Err("`poly` is not a scalar of the motion commands (f64, rational or mpfr:BITS)".into())
            }
        }
    }
}

impl MotionScalar {
    /// The `--scalar` spelling.
    ///
    /// ```
    /// assert_eq!(gam::precision::MotionScalar::Mpfr(256).name(), "mpfr:256");
    /// ```
    pub fn name(self) -> String {
        match self {
            MotionScalar::F64 => "f64".into(),
            MotionScalar::Rational => "rational".into(),
            MotionScalar::Mpfr(bits) => format!("mpfr:{bits}"),
        }
    }

    /// How much dearer an arithmetic operation is than in f64, for a motion through `m` key
    /// poses, as a factor of the f64 work estimates ([`crate::budget`]): exact rationals carry
    /// coefficients whose size grows about linearly with `m` in the global constructions (the
    /// collocation's denominators: about `16 m` bits, so `(1 + 16m/64)²`-ish per operation,
    /// taken as `1 + m²/16`); MPFR at `BITS` bits costs about `(1 + BITS/64)^1.5`. Measured on
    /// `juttler-q-motion` and `juttler-bspline` with random rational key poses (debug build): 16
    /// poses 3.7 s, 20 poses 17 s, 40 poses past two minutes before the budget refused them.
    ///
    /// ```
    /// use gam::precision::MotionScalar;
    /// assert_eq!(MotionScalar::F64.cost_factor(40), 1.0);
    /// assert_eq!(MotionScalar::Rational.cost_factor(8), 5.0);
    /// ```
    pub fn cost_factor(self, m: usize) -> f64 {
        match self {
            MotionScalar::F64 => 1.0,
            MotionScalar::Rational => 1.0 + (m * m) as f64 / 16.0,
            MotionScalar::Mpfr(bits) => (1.0 + f64::from(bits) / 64.0).powf(1.5),
        }
    }

    /// Runs `f` with MPFR's default precision set to the command's (for `mpfr:BITS`).
    pub(crate) fn run<R>(self, f: impl FnOnce() -> R) -> R {
        let _guard = match self {
            MotionScalar::Mpfr(bits) => Some(PrecisionGuard::new(bits)),
            _ => None,
        };
        f()
    }
}

/// A scalar the motion commands print: `f64` as JSON numbers (as always), the others as
/// coefficient strings.
pub(crate) trait OutScalar: CliScalar + Field {
    /// The value in `--json` output.
    fn json(&self) -> Value;
    /// The value in human output.
    fn text(&self) -> String {
        self.format()
    }
}

impl OutScalar for f64 {
    fn json(&self) -> Value {
        // `x + 0.0` prints -0.0 as 0.0
        Value::from(self + 0.0)
    }
    fn text(&self) -> String {
        (self + 0.0).format()
    }
}

impl OutScalar for Q {
    fn json(&self) -> Value {
        Value::String(self.format())
    }
}

impl OutScalar for MpFloat {
    fn json(&self) -> Value {
        Value::String(self.format())
    }
}

/// The values as a JSON list.
pub(crate) fn json_list<T: OutScalar>(v: &[T]) -> Value {
    Value::Array(v.iter().map(OutScalar::json).collect())
}

/// `x,y,z` of `--point`, exactly: three numbers (`p`, `p/q` or decimals).
pub(crate) fn point_exact(text: &str) -> Result<[Q; 3], CliError> {
    let bad = || CliError::usage(format!("`--point {text}`: expected three numbers `x,y,z`"));
    let v: Vec<Q> = text.split(',').map(|s| parse_rational(s).map_err(|_| bad())).collect::<Result<_, _>>()?;
    <[Q; 3]>::try_from(v).map_err(|_| bad())
}

/// The text of the file at `path`.
pub(crate) fn read_file(path: &str) -> Result<String, CliError> {
    std::fs::read_to_string(path).map_err(|e| CliError::usage(format!("cannot read `{path}`: {e}")))
}

/// A `gam interpolate` spec read with every literal exact from its text (`label` names it in
/// messages; `//` comments allowed).
pub(crate) fn exact_spec(label: &str, text: &str) -> Result<InterpolateSpec<Exact>, CliError> {
    exact_spec_if_any(label, text)?.ok_or_else(|| usage(label, "invalid spec: missing field `method`"))
}

/// [`exact_spec`], or `None` when the text is no `gam interpolate` spec (no top-level
/// `method`: a `gam hermite` spec, for `gam sample`), as `interpolate::read_text` in f64.
pub(crate) fn exact_spec_if_any(label: &str, text: &str) -> Result<Option<InterpolateSpec<Exact>>, CliError> {
    // every literal quoted first: `1e400` is a rational, not an f64 out of range
    let text = motion::schema::quote_numbers(&strip_comments(text));
    let value = motion::schema::parse_json(&text).map_err(|e| usage(label, e))?;
    if value.get("method").is_none() {
        return Ok(None);
    }
    InterpolateSpec::<Exact>::read_json(&text).map(Some).map_err(|e| schema_error(label, e))
}

/// The method input over exact rationals (pose forms that are not rational are refused).
fn exact_input(label: &str, spec: &InterpolateSpec<Exact>) -> Result<MethodInput<Q>, CliError> {
    let poses = spec.poses_with(&PoseObject::to_pose_exact).map_err(|e| schema_error(label, e))?;
    spec.method_input_with(poses, &|x| x.0.clone()).map_err(|e| schema_error(label, e))
}

/// The method input at the current MPFR precision (each exact literal rounded once).
fn mpfr_input(label: &str, spec: &InterpolateSpec<Exact>) -> Result<MethodInput<MpFloat>, CliError> {
    let f = |x: &Exact| MpFloat::from_rational(&x.0);
    let poses: Vec<Pose<MpFloat>> = spec.poses_with(&|p| p.map(&f).to_pose()).map_err(|e| schema_error(label, e))?;
    spec.method_input_with(poses, &f).map_err(|e| schema_error(label, e))
}

/// A refusal of the method as the CLI's error (bad input exit 2, a numerical failure exit 1).
fn build_error(label: &str, spec: &InterpolateSpec<Exact>, source: BuildError) -> CliError {
    schema_error(label, SchemaError::Build { method: spec.method, source })
}

/// The budget of building a spec's motion in `scalar`: the global interpolants as in f64
/// ([`crate::budget::global_build_work`]), and `juttler-bspline`'s dense collocation (`50 m³`
/// units), times [`MotionScalar::cost_factor`].
fn check_budget(spec: &InterpolateSpec<Exact>, scalar: MotionScalar) -> Result<(), CliError> {
    let m = spec.poses.len();
    let work = match spec.method {
        motion::method::Method::JuttlerBSpline => Some(50.0 * (m as f64).powi(3)),
        method => crate::budget::global_build_work(method, m),
    };
    if let Some(work) = work {
        let what = format!("building {} through {m} key poses ({})", spec.method.name(), scalar.name());
        crate::budget::check(&what, work * scalar.cost_factor(m))?;
    }
    Ok(())
}

/// Builds a spec exactly (`label` names it in messages).
pub(crate) fn build_exact(label: &str, spec: &InterpolateSpec<Exact>) -> Result<ExactMotion, CliError> {
    check_budget(spec, MotionScalar::Rational)?;
    let input = exact_input(label, spec)?;
    spec.method.build_exact(&input).map_err(|e| build_error(label, spec, e))
}

/// Builds a spec at the current MPFR precision (inside [`MotionScalar::run`]).
pub(crate) fn build_mpfr(label: &str, spec: &InterpolateSpec<Exact>) -> Result<BuiltMotion<MpFloat>, CliError> {
    check_budget(spec, MotionScalar::Mpfr(algebra_core::default_precision()))?;
    let input = mpfr_input(label, spec)?;
    spec.method.build(&input).map_err(|e| build_error(label, spec, e))
}

/// The exact body points of a spec (`[[0, 0, 0]]` when left out).
pub(crate) fn body_points(spec: &InterpolateSpec<Exact>) -> Vec<[Q; 3]> {
    match &spec.body_points {
        Some(v) => v.iter().map(|p| p.each_ref().map(|x| x.0.clone())).collect(),
        None => vec![[Q::zero(), Q::zero(), Q::zero()]],
    }
}
