//! The `gam` commands for other front ends (the Python package, python/): each function takes
//! already-parsed inputs (a spec or pose as a [`serde_json::Value`], option values as the
//! command line spells them) and returns the JSON value that the command prints with
//! `--json`, or the [`CliError`] whose message is the command's `error:` line (without the
//! `error: ` prefix). They run the same code as the binary, so the answers are the same.
//!
//! Differences from the command line, all on the input side:
//! - a spec or pose is a value, not a file: messages name it by the label given (where the
//!   command names the file);
//! - an expression is the text itself (no `@FILE`, no `-` for stdin);
//! - where a command prints its JSON and *then* exits 1 (a claim that does not hold, an
//!   undecided claim, a relation of `gam eval` that is false, a statement of `gam verify`
//!   that fails), the value is returned: its `holds` / `value` says so.
//!
//! ```
//! let v = gam::api::eval("e1*e2*e3*einf*e0", "cga-null", "product", "rational")?;
//! assert_eq!(v, serde_json::json!({"e123": "-2", "e0123inf": "1"}));
//! # Ok::<(), gam::api::CliError>(())
//! ```

pub use crate::error::CliError;
use crate::interpolate::{self, Built};
use crate::precision::MotionScalar;
use algebra_core::{Basis, Product};
use motion::Pose;
use serde_json::Value;
use std::str::FromStr;

/// An option value as clap reads it: the value or clap's message for it.
fn option<T: FromStr>(value: &str, flag: &str) -> Result<T, CliError>
where
    T::Err: std::fmt::Display,
{
    value.parse().map_err(|e| CliError::usage(format!("invalid value '{value}' for '{flag}': {e}")))
}

/// `v` unless it holds a non-finite number: the binary's last guard before printing
/// ([`crate::finite_guard`]), so both doors refuse the same results.
fn finite(command: &str, v: Value) -> Result<Value, CliError> {
    crate::finite_guard::finite_value(command, &v).map(|()| v)
}

/// Command output (JSON text) as a value.
fn value(out: &str) -> Result<Value, CliError> {
    serde_json::from_str(out).map_err(|e| CliError::math(format!("internal: the command's JSON does not parse: {e}")))
}

/// `gam eval --json --algebra ALGEBRA --basis BASIS --scalar SCALAR EXPR` (also the relations
/// `==` / `!=`, whose `{"value": false}` is returned rather than an error).
///
/// ```
/// let v = gam::api::eval("(a + b)*e1", "g3", "blade", "poly")?;
/// assert_eq!(v["e1"], "a + b");
/// # Ok::<(), gam::api::CliError>(())
/// ```
pub fn eval(expr: &str, algebra: &str, basis: &str, scalar: &str) -> Result<Value, CliError> {
    let basis: Basis = option(basis, "--basis <B>")?;
    let scalar: crate::scalar::ScalarKind = option(scalar, "--scalar <S>")?;
    if let Some(result) = crate::prove::eval_relation(algebra, basis, &scalar, true, expr) {
        return value(&result?.0);
    }
    let args = crate::commands::EvalArgs { algebra: algebra.into(), basis, scalar, json: true, expr: String::new() };
    finite("eval", value(&crate::commands::eval_text(&args, expr)?)?)
}

/// `gam table --json --algebra ALGEBRA --basis BASIS --product PRODUCT`.
///
/// ```
/// let v = gam::api::table("g3", "blade", "gp")?;
/// assert_eq!(v.as_array().map(Vec::len), Some(64));
/// # Ok::<(), gam::api::CliError>(())
/// ```
pub fn table(algebra: &str, basis: &str, product: &str) -> Result<Value, CliError> {
    let basis: Basis = option(basis, "--basis <B>")?;
    let product: Product = option(product, "--product <P>")?;
    value(&crate::commands::table(algebra, basis, product, true)?)
}

/// `gam prove --json --algebra ALGEBRA --basis BASIS [--assume A]... --timeout SECONDS CLAIM`;
/// a claim that does not hold (or is undecided) is a value with `"holds": false`.
///
/// ```
/// let v = gam::api::prove("let X = vector(\"x\"); X*X = sp(X, X)", "g3", "blade", &[], 10.0)?;
/// assert_eq!(v["holds"], true);
/// # Ok::<(), gam::api::CliError>(())
/// ```
pub fn prove(claim: &str, algebra: &str, basis: &str, assume: &[String], timeout: f64) -> Result<Value, CliError> {
    let basis: Basis = option(basis, "--basis <B>")?;
    let args = crate::prove::ProveArgs {
        algebra: algebra.into(),
        basis,
        assume: assume.to_vec(),
        timeout,
        max_basis: algebra_core::ideal::Budget::default().max_basis,
        max_terms: algebra_core::ideal::Budget::default().max_terms,
        json: true,
        claim: claim.into(),
    };
    value(&crate::prove::prove(&args)?.0)
}

/// `gam verify --json [--filter TEXT]`: the report, also when some statement fails (its
/// `holds` is false).
///
/// ```no_run
/// let v = gam::api::verify(Some("lemma-2.2"))?;
/// assert!(v.as_array().is_some_and(|l| !l.is_empty()));
/// # Ok::<(), gam::api::CliError>(())
/// ```
pub fn verify(filter: Option<&str>) -> Result<Value, CliError> {
    value(&crate::verify::verify(filter, true)?.output)
}

/// `gam verify --json --list [--filter TEXT]`: the selected statements (id, paper, label,
/// statement, method, hypotheses) without running them.
///
/// ```
/// let v = gam::api::verify_list(Some("lemma-2.2"))?;
/// assert_eq!(v.as_array().map(Vec::len), Some(5));
/// # Ok::<(), gam::api::CliError>(())
/// ```
pub fn verify_list(filter: Option<&str>) -> Result<Value, CliError> {
    value(&crate::verify::list(filter, true)?)
}

/// `gam pose --json POSE_JSON`, with the pose object as a value (named `POSE_JSON` in
/// messages, as the command names an inline pose).
///
/// ```
/// let v = gam::api::pose(&serde_json::json!({"position": [1, 2, 3]}))?;
/// assert_eq!(v["position"], serde_json::json!([1.0, 2.0, 3.0]));
/// # Ok::<(), gam::api::CliError>(())
/// ```
pub fn pose(pose: &Value) -> Result<Value, CliError> {
    finite("pose", crate::pose::pose_json("POSE_JSON", &pose_object(pose, "POSE_JSON")?)?)
}

// The values are read through their JSON text, by the readers the command uses on a file, so
// every message (with its line and column) is the command's.

/// A pose object of the contract read from a value (`label` names it in messages).
fn pose_object(pose: &Value, label: &str) -> Result<motion::schema::PoseObject, CliError> {
    motion::schema::PoseObject::from_json(&pose.to_string(), "pose").map_err(|e| interpolate::usage(label, e))
}

/// An interpolate spec read from a value (`label` names it in messages).
fn interpolate_spec(spec: &Value, label: &str) -> Result<motion::schema::InterpolateSpec, CliError> {
    interpolate::read_text(label, &spec.to_string())?
        .ok_or_else(|| interpolate::usage(label, "invalid spec: missing field `method`"))
}

/// `gam hermite --json SPEC.json` of the spec `spec`, named `label` in messages.
///
/// ```
/// use serde_json::json;
/// let end = |p: [f64; 3]| json!({"position": p, "axis": [0, 0, 1], "angle": 0,
///     "velocity": [1, 0, 0], "angular_velocity": [0, 0, 0]});
/// let spec = json!({"kind": "additive", "degree": 3, "start": end([0.0; 3]), "end": end([1.0, 0.0, 0.0])});
/// let v = gam::api::hermite(&spec, "spec")?;
/// assert_eq!(v["control_poses"].as_array().map(Vec::len), Some(4));
/// # Ok::<(), gam::api::CliError>(())
/// ```
pub fn hermite(spec: &Value, label: &str) -> Result<Value, CliError> {
    let spec =
        motion::spec::HermiteSpec::from_json(&spec.to_string()).map_err(|e| crate::hermite::spec_error(label, e))?;
    finite("hermite", crate::hermite::hermite_json(label, &spec)?)
}

/// `gam interpolate --json SPEC.json` of the spec `spec`, named `label` in messages.
///
/// ```
/// use serde_json::json;
/// let spec = json!({"method": "wl-linear", "poses": [{"position": [0, 0, 0]}, {"position": [2, 0, 0]}],
///     "samples": 3});
/// let v = gam::api::interpolate(&spec, "spec")?;
/// assert_eq!(v["samples"][1]["points"], json!([[1.0, 0.0, 0.0]]));
/// # Ok::<(), gam::api::CliError>(())
/// ```
pub fn interpolate(spec: &Value, label: &str) -> Result<Value, CliError> {
    finite("interpolate", interpolate::interpolate_json(label, &interpolate_spec(spec, label)?)?.into_value()?)
}

/// `gam trajectory --json SPEC.json --point POINT` of the spec `spec`, named `label` in
/// messages; `point` is the text `x,y,z` of `--point`.
///
/// ```
/// use serde_json::json;
/// let spec = json!({"method": "juttler-q-motion", "poses": [{"position": [0, 0, 0]}, {"position": [2, 0, 0]}]});
/// let v = gam::api::trajectory(&spec, "spec", "0,0,0")?;
/// assert_eq!(v["segments"][0]["degree"], 4);
/// # Ok::<(), gam::api::CliError>(())
/// ```
pub fn trajectory(spec: &Value, label: &str, point: &str) -> Result<Value, CliError> {
    let x = crate::trajectory::point(point)?;
    finite("trajectory", crate::trajectory::trajectory_json(label, &interpolate_spec(spec, label)?, &x)?)
}

/// The scalar of `--scalar` of the motion commands (`f64`, `rational` or `mpfr:BITS`).
fn motion_scalar(scalar: &str) -> Result<MotionScalar, CliError> {
    option(scalar, "--scalar <S>")
}

/// [`pose`] with `--scalar SCALAR` (`f64`, `rational` or `mpfr:BITS`; docs/cli.md, "Precision
/// of the motion commands").
///
/// ```
/// let v = gam::api::pose_with(&serde_json::json!({"quaternion": [0.6, 0, 0, 0.8]}), "rational")?;
/// assert_eq!(v["matrix"][0], serde_json::json!(["-7/25", "-24/25", "0", "0"]));
/// # Ok::<(), gam::api::CliError>(())
/// ```
pub fn pose_with(pose: &Value, scalar: &str) -> Result<Value, CliError> {
    match motion_scalar(scalar)? {
        MotionScalar::F64 => self::pose(pose),
        s => finite("pose", crate::pose::pose_in("POSE_JSON", &pose.to_string(), s)?.0),
    }
}

/// [`hermite`] with `--scalar SCALAR`.
///
/// ```
/// use serde_json::json;
/// let end = |p: [f64; 3]| json!({"position": p, "axis": [0, 0, 1], "angle": 0,
///     "velocity": [1, 0, 0], "angular_velocity": [0, 0, 0]});
/// let spec = json!({"kind": "additive", "degree": 3, "start": end([0.0; 3]), "end": end([1.0, 0.0, 0.0])});
/// assert_eq!(gam::api::hermite_with(&spec, "spec", "mpfr:100")?["control_poses"].as_array().map(Vec::len), Some(4));
/// assert_eq!(gam::api::hermite_with(&spec, "spec", "rational").unwrap_err().code, 2);
/// # Ok::<(), gam::api::CliError>(())
/// ```
pub fn hermite_with(spec: &Value, label: &str, scalar: &str) -> Result<Value, CliError> {
    match motion_scalar(scalar)? {
        MotionScalar::F64 => hermite(spec, label),
        s => finite("hermite", value(&crate::hermite::hermite_in(label, &spec.to_string(), true, s)?)?),
    }
}

/// [`interpolate`] with `--scalar SCALAR`.
///
/// ```
/// use serde_json::json;
/// let spec = json!({"method": "juttler-affine", "poses": [{"position": [0, 0, 0]}, {"position": [0.3, 0, 0]}], "samples": 3});
/// let v = gam::api::interpolate_with(&spec, "spec", "rational")?;
/// assert_eq!(v["samples"][1]["points"], json!([["3/20", "0", "0"]]));
/// # Ok::<(), gam::api::CliError>(())
/// ```
pub fn interpolate_with(spec: &Value, label: &str, scalar: &str) -> Result<Value, CliError> {
    match motion_scalar(scalar)? {
        MotionScalar::F64 => interpolate(spec, label),
        s => {
            s.run(|| finite("interpolate", interpolate::precise(label, &spec.to_string(), s)?.streamed().into_value()?))
        }
    }
}

/// [`trajectory`] with `--scalar SCALAR`.
///
/// ```
/// use serde_json::json;
/// let spec = json!({"method": "juttler-q-motion", "poses": [{"position": [0, 0, 0]}, {"position": [2, 0, 0]}]});
/// let v = gam::api::trajectory_with(&spec, "spec", "1/2,0,0", "rational")?;
/// assert_eq!(v["segments"][0]["points"][2], json!(["3/2", "0", "0"]));
/// # Ok::<(), gam::api::CliError>(())
/// ```
pub fn trajectory_with(spec: &Value, label: &str, point: &str, scalar: &str) -> Result<Value, CliError> {
    match motion_scalar(scalar)? {
        MotionScalar::F64 => trajectory(spec, label, point),
        s => finite("trajectory", value(&crate::trajectory::trajectory_in(label, &spec.to_string(), point, true, s)?)?),
    }
}

/// `gam surface --json --scalar SCALAR SPEC.json --curve CURVE.json` of the spec `spec` and the
/// curve `curve` (`{"points": [...], "weights": [...]}`), named `label` and `curve` in messages.
///
/// ```
/// use serde_json::json;
/// let spec = json!({"method": "juttler-affine", "poses": [{"position": [0, 0, 0]}, {"position": [0, 0, 2]}]});
/// let v = gam::api::surface(&spec, "spec", &json!({"points": [[1, 0, 0], [1, 1, 0]]}), "rational")?;
/// assert_eq!(v["segments"][0]["degrees"], json!([4, 1]));
/// assert_eq!(v["segments"][0]["points"][0][1], json!(["1", "1", "0"]));
/// # Ok::<(), gam::api::CliError>(())
/// ```
pub fn surface(spec: &Value, label: &str, curve: &Value, scalar: &str) -> Result<Value, CliError> {
    let (spec, curve) = (spec.to_string(), curve.to_string());
    let out = crate::surface::surface_in((label, &spec), ("curve", &curve), true, motion_scalar(scalar)?)?;
    finite("surface", value(&out)?)
}

/// A pose object of the contract (any form) as a [`Pose`], checked as `gam pose` checks it
/// (`label` names it in messages).
///
/// ```
/// let s = gam::api::pose_of(&serde_json::json!({"position": [1, 0, 0]}), "pose")?;
/// assert_eq!(s.transform_point(&[0.0; 3]).unwrap(), [1.0, 0.0, 0.0]);
/// # Ok::<(), gam::api::CliError>(())
/// ```
pub fn pose_of(pose: &Value, label: &str) -> Result<Pose<f64>, CliError> {
    pose_object(pose, label)?.to_pose().map_err(|e| interpolate::usage(label, e.at("pose")))
}

/// Every representation of a pose: the object `gam pose --json` prints for it.
///
/// ```
/// let v = gam::api::representations(&motion::Pose::translation(&[0.0, 0.0, 2.0]))?;
/// assert_eq!(v["quaternion"], serde_json::json!([1.0, 0.0, 0.0, 0.0]));
/// # Ok::<(), gam::api::CliError>(())
/// ```
pub fn representations(pose: &Pose<f64>) -> Result<Value, CliError> {
    crate::pose::representations(pose)
}

/// The motion of a `gam interpolate` spec, built once and sampled at any parameters.
///
/// ```
/// use serde_json::json;
/// let spec = json!({"method": "wl-linear", "poses": [{"position": [0, 0, 0]}, {"position": [2, 0, 0]}]});
/// let m = gam::api::Motion::build(&spec, "spec")?;
/// let s = m.sample(0.25, m.body_points())?;
/// assert_eq!(s.points[0], [0.5, 0.0, 0.0]);
/// assert_eq!(s.matrix[0][3], 0.5);
/// # Ok::<(), gam::api::CliError>(())
/// ```
pub struct Motion(Built);

/// One sample of a [`Motion`]: the numbers of one entry of `gam interpolate`'s `samples`.
#[derive(Debug, Clone, PartialEq)]
pub struct Sample {
    /// The rigid (normalised) pose at `t`.
    pub matrix: [[f64; 4]; 4],
    /// The images of the body points.
    pub points: Vec<[f64; 3]>,
    /// Their velocities d/dt.
    pub velocities: Vec<[f64; 3]>,
    /// The angular velocity in the fixed frame.
    pub angular_velocity: [f64; 3],
}

impl Motion {
    /// Reads and builds an interpolate spec (named `label` in messages), as `gam interpolate`.
    pub fn build(spec: &Value, label: &str) -> Result<Self, CliError> {
        interpolate::build(label, &interpolate_spec(spec, label)?).map(Motion)
    }

    /// The spec's `body_points` (default the origin).
    pub fn body_points(&self) -> &[[f64; 3]] {
        &self.0.body_points
    }

    /// The parameters `t_0 < ... < t_m` of the key poses.
    pub fn times(&self) -> &[f64] {
        self.0.motion.times()
    }

    /// Refuses sampling `n` parameters at `points` body points beyond the work budget (the
    /// check of `gam interpolate`).
    pub fn check_work(&self, n: usize, points: usize) -> Result<(), CliError> {
        interpolate::check_sampling(&self.0.motion, points, n, 1)
    }

    /// The sample at `t` (within `[t_0, t_m]`) of `body_points`: the same numbers as the sample
    /// of `gam interpolate` at that `t`.
    pub fn sample(&self, t: f64, body_points: &[[f64; 3]]) -> Result<Sample, CliError> {
        let times = self.times();
        let (t0, t1) = (times[0], times[times.len() - 1]);
        if !(t >= t0 && t <= t1) {
            return Err(CliError::usage(format!(
                "t = {} is outside the motion's parameter range [{}, {}]",
                crate::scalar::format_f64(t),
                crate::scalar::format_f64(t0),
                crate::scalar::format_f64(t1)
            )));
        }
        let s = interpolate::sample_t(&self.0, body_points, t)?;
        Ok(Sample {
            matrix: interpolate::sample_matrix(&s)?,
            points: s.points.iter().map(|p| p.position).collect(),
            velocities: s.points.iter().map(|p| p.velocity).collect(),
            angular_velocity: s.space_twist.angular.to_array(),
        })
    }
}

/// The budget check of the command line for `what` of `estimate` work units (the default
/// budget is about a minute of work; `GAM_WORK_BUDGET` changes it).
///
/// ```
/// assert!(gam::api::check_budget("a little", 1.0).is_ok());
/// assert!(gam::api::check_budget("too much", 1e30).is_err());
/// ```
pub fn check_budget(what: &str, estimate: f64) -> Result<(), CliError> {
    crate::budget::check(what, estimate)
}
