//! `gam interpolate [--json] SPEC.json`: a motion through key poses by a named method, exactly as
//! in the Wave 2 contract (shared/cli.md). Every method goes through ONE build path,
//! `motion::method::Method::build`, which returns a `motion::method::BuiltMotion` (the motion,
//! its segments, its sampler); this file reads the spec into a `MethodInput` and writes the
//! segments and samples, the same way for every method. Names of the contract that are not
//! implemented yet are recognised and refused with "not implemented yet".
//!
//! The spec, its pose objects, its checks and their messages are `motion::schema` (the
//! library owns the format: `motion::schema::InterpolateSpec`); this module reads the file and
//! prints the result. [`interpolate_json`] is the command on an already read spec.
//! Velocities, when left out, are estimated by the method (docs/cli.md).
//!
//! A spec of this command is also accepted by `gam sample` and `gam plot` ([`spec_sampler`]).

use crate::budget::Tableau;
use crate::error::CliError;
use crate::hermite::strip_comments;
use crate::output::{Streamed, mv_human, mv_json};
use crate::precision::{self, MotionScalar, OutScalar, json_list};
use crate::sample::{Sample, Sampler, checked, norm};
use crate::scalar::format_f64;
use algebra_core::rational::Q;
use algebra_core::{MpFloat, Real, Ring};
use motion::method::{BuiltMotion, Method, MethodSegment};
use motion::schema::{InterpolateSpec, SchemaError};
use motion::trajectory::TrajectorySample;
use serde_json::{Value, json};

/// A built spec: the motion of its method, the body points and the number of samples.
pub(crate) struct Built {
    pub(crate) motion: BuiltMotion<f64>,
    pub(crate) body_points: Vec<[f64; 3]>,
    samples: usize,
}

pub(crate) fn usage(path: &str, what: impl std::fmt::Display) -> CliError {
    CliError::usage(format!("`{path}`: {what}"))
}

/// A refused spec as a CLI error: bad input is exit 2, prefixed by `label` (the file), a
/// mathematical failure exit 1.
pub(crate) fn schema_error(label: &str, e: SchemaError) -> CliError {
    if e.is_input() { usage(label, e) } else { CliError::math(e.to_string()) }
}

/// Reads the file; `Ok(None)` when it is not a `gam interpolate` spec (no top-level `method`).
pub(crate) fn read(path: &str) -> Result<Option<InterpolateSpec>, CliError> {
    let text = std::fs::read_to_string(path).map_err(|e| CliError::usage(format!("cannot read `{path}`: {e}")))?;
    read_text(path, &text)
}

/// [`read`] of the spec's text (named `label` in messages; also the Python door's reader, so
/// both doors give the same messages).
pub(crate) fn read_text(label: &str, text: &str) -> Result<Option<InterpolateSpec>, CliError> {
    let text = strip_comments(text);
    let value = motion::schema::parse_json(&text).map_err(|e| usage(label, e))?;
    if value.get("method").is_none() {
        return Ok(None);
    }
    InterpolateSpec::from_json(&text).map(Some).map_err(|e| schema_error(label, e))
}

/// Builds a checked spec (`label` names it in messages).
pub(crate) fn build(label: &str, spec: &InterpolateSpec) -> Result<Built, CliError> {
    let m = spec.poses.len();
    if let Some(work) = crate::budget::global_build_work(spec.method, m) {
        crate::budget::check(&format!("building {} through {m} key poses", spec.method.name()), work)?;
    }
    let motion = spec.build().map_err(|e| schema_error(label, e))?;
    Ok(Built { motion, body_points: spec.body_points(), samples: spec.samples })
}

/// Reads a `gam interpolate` spec (also for `gam trajectory`).
pub(crate) fn read_spec(path: &str) -> Result<InterpolateSpec, CliError> {
    read(path)?.ok_or_else(|| usage(path, "invalid spec: missing field `method`"))
}

/// Reads and builds a `gam interpolate` spec (for `gam plot`).
pub(crate) fn built(path: &str) -> Result<Built, CliError> {
    build(path, &read_spec(path)?)
}

fn finite3(v: &[f64; 3]) -> bool {
    v.iter().all(|x| x.is_finite())
}

/// The work of `passes` passes over `n` samples ([`crate::budget::sampling_work`], with the
/// largest segment degree and the motion's [`Tableau`]) per body point, checked against the
/// budget.
pub(crate) fn check_work(b: &Built, n: usize, passes: usize) -> Result<(), CliError> {
    check_sampling(&b.motion, b.body_points.len(), n, passes)
}

/// [`check_work`] for `points` body points (at least one counted) of `motion` (also the Python
/// package's sampler).
pub(crate) fn check_sampling(
    motion: &BuiltMotion<f64>,
    points: usize,
    n: usize,
    passes: usize,
) -> Result<(), CliError> {
    check_segments(motion.method(), motion.segments(), points, n, passes, 1.0)
}

/// [`check_sampling`] of a method's segments in any scalar, the f64 estimate times `factor`
/// ([`MotionScalar::cost_factor`]).
pub(crate) fn check_segments<T: Ring>(
    method: Method,
    segments: &[MethodSegment<T>],
    points: usize,
    n: usize,
    passes: usize,
    factor: f64,
) -> Result<(), CliError> {
    let points = points.max(1);
    let degree = segments.iter().map(|s| s.degree).max().unwrap_or(0);
    crate::budget::check(
        &format!("sampling {points} body points of degree-{degree} segments at {n} values"),
        crate::budget::sampling_work(Tableau::of_method(method), degree, n, passes) * points as f64 * factor,
    )
}

/// Sample `i` of `n` evenly spaced times over `[t_0, t_m]` (as `Trajectory::sample_evenly`),
/// checked finite.
fn sample_at(b: &Built, n: usize, i: usize) -> Result<TrajectorySample<f64>, CliError> {
    let times = b.motion.times();
    let (t0, t1) = (times[0], times[times.len() - 1]);
    let t = if i + 1 == n { t1 } else { t0 + (t1 - t0) * (i as f64 / (n - 1) as f64) };
    sample_t(b, &b.body_points, t)
}

/// The sample at `t` of `body_points`, checked finite (also the Python package's sampler).
pub(crate) fn sample_t(b: &Built, body_points: &[[f64; 3]], t: f64) -> Result<TrajectorySample<f64>, CliError> {
    let s = b.motion.sample(&t, body_points).map_err(|e| CliError::math(e.to_string()))?;
    let ok = s.points.iter().all(|p| finite3(&p.position) && finite3(&p.velocity))
        && finite3(&s.space_twist.angular.to_array());
    if !ok {
        return Err(CliError::math(format!("the result at t = {} is not finite (overflow)", format_f64(s.t))));
    }
    Ok(s)
}

/// One sample of `gam interpolate` in any scalar: the parameter, the rigid matrix, the body
/// points, their velocities and the angular velocity.
struct Row<T> {
    t: T,
    matrix: [[T; 4]; 4],
    points: Vec<[T; 3]>,
    velocities: Vec<[T; 3]>,
    angular_velocity: [T; 3],
}

impl<T: Real> Row<T> {
    /// The row of a sample of a floating-point motion.
    fn of(s: &TrajectorySample<T>) -> Result<Self, CliError> {
        let matrix = s.pose.unitize().and_then(|u| u.to_matrix()).map_err(|e| CliError::math(e.to_string()))?;
        Ok(Row {
            t: s.t.clone(),
            matrix,
            points: s.points.iter().map(|p| p.position.clone()).collect(),
            velocities: s.points.iter().map(|p| p.velocity.clone()).collect(),
            angular_velocity: s.space_twist.angular.to_array(),
        })
    }
}

impl Row<Q> {
    /// The row of an exact sample.
    fn exact(s: motion::method::ExactSample) -> Self {
        Row {
            t: s.t,
            matrix: s.matrix,
            points: s.points,
            velocities: s.velocities,
            angular_velocity: s.angular_velocity,
        }
    }
}

impl<T: OutScalar> Row<T> {
    /// The JSON object of `gam interpolate --json`'s `samples[]`.
    fn json(&self) -> Value {
        let list3 = |v: &[[T; 3]]| v.iter().map(|p| json_list(p)).collect::<Vec<_>>();
        json!({"t": self.t.json(), "matrix": self.matrix.iter().map(|r| json_list(r)).collect::<Vec<_>>(),
            "points": list3(&self.points), "velocities": list3(&self.velocities),
            "angular_velocity": json_list(&self.angular_velocity)})
    }

    /// The human line.
    fn text(&self) -> String {
        let pts: Vec<String> = self
            .points
            .iter()
            .map(|p| format!("[{}]", p.iter().map(OutScalar::text).collect::<Vec<_>>().join(", ")))
            .collect();
        format!("t = {}: points {}", self.t.text(), pts.join(" "))
    }
}

/// One sample as a JSON object of `gam interpolate --json`.
fn sample_json(s: &TrajectorySample<f64>) -> Result<Value, CliError> {
    Ok(Row::of(s)?.json())
}

/// The rigid (normalised) pose of a sample as a 4x4 matrix.
pub(crate) fn sample_matrix(s: &TrajectorySample<f64>) -> Result<[[f64; 4]; 4], CliError> {
    s.pose.unitize().and_then(|u| u.to_matrix()).map_err(|e| CliError::math(e.to_string()))
}

/// The contract's `segments` array.
fn segments_json<T: OutScalar>(segments: &[MethodSegment<T>]) -> Vec<Value> {
    segments
        .iter()
        .map(|seg| {
            let mut v = json!({"t0": seg.t0.json(), "t1": seg.t1.json(), "representation": seg.representation, "degree": seg.degree,
                "control_poses": seg.control_poses.iter().map(|s| mv_json(&s.to_multivector())).collect::<Vec<_>>()});
            if let Some(d) = &seg.dual_quaternions {
                v["dual_quaternions"] = json!(d.iter().map(|d| json_list(&d.coeffs())).collect::<Vec<_>>());
            }
            if let Some(h) = &seg.hexanions {
                let hex = |x: &motion::repr::hexanion::Hexanion<T>| json!({"omega": json_list(&x.omega), "m": json_list(&x.m)});
                v["hexanions"] = json!([hex(&h[0]), hex(&h[1])]);
            }
            v
        })
        .collect()
}

/// The header lines of the human output: the method, its parameters and each segment's
/// control poses (the key poses once, for the methods whose segments are key poses).
fn header_text<T: OutScalar>(
    method: Method,
    times: &[T],
    segments: &[MethodSegment<T>],
    key_poses: &[motion::Pose<T>],
) -> Vec<String> {
    let t = times.iter().map(OutScalar::text).collect::<Vec<_>>().join(", ");
    let mut lines = vec![format!("{method}: {} segments through {} poses at t = [{t}]", segments.len(), times.len())];
    if matches!(method, Method::WlLinear | Method::WlQuadratic | Method::HexanionLinear) {
        // their segments' control poses are key poses: each once
        for (i, s) in key_poses.iter().enumerate() {
            lines.push(format!("  P{i} = {}", mv_human(&s.to_multivector())));
        }
    } else {
        for (k, seg) in segments.iter().enumerate() {
            lines.push(format!("segment {k} (t = {} .. {}):", seg.t0.text(), seg.t1.text()));
            for (i, s) in seg.control_poses.iter().enumerate() {
                lines.push(format!("  S{i} = {}", mv_human(&s.to_multivector())));
            }
        }
    }
    lines
}

/// Parameter `i` of `n` evenly spaced over `[t0, t1]` (the last exactly `t1`).
pub(crate) fn even<T: Ring>(t0: &T, t1: &T, n: usize, i: usize) -> T {
    if i + 1 == n { t1.clone() } else { t0.add_ref(&t1.sub_ref(t0).mul_ref(&T::from_ratio(i as i64, n as i64 - 1))) }
}

/// `gam interpolate --json` of a spec (`label` names it in messages): the header (method,
/// parameters, segments) and the samples, streamed by the CLI in bounded memory like
/// `gam sample --json`, or taken as one value ([`Streamed::into_value`]) by another front door.
pub fn interpolate_json<'a>(label: &str, spec: &InterpolateSpec) -> Result<Streamed<'a>, CliError> {
    let b = build(label, spec)?;
    let n = if b.samples >= 2 { b.samples } else { 0 };
    if n > 0 {
        check_work(&b, n, 2)?;
    }
    let head = json!({"method": b.motion.method().name(), "parameters": json_list(b.motion.times()),
        "segments": segments_json(b.motion.segments())});
    Ok(Streamed { head, n, sample: Box::new(move |i| sample_json(&sample_at(&b, n, i)?)) })
}

/// What the header of a motion's output shows: its method, parameters, segments and key poses.
type Header<'h, T> = (Method, &'h [T], &'h [MethodSegment<T>], &'h [motion::Pose<T>]);

/// The output of a motion in an exact or MPFR scalar, ready to print either way: the JSON
/// head and the human header lines, and sample `i` as JSON or as a human line.
pub(crate) struct Precise {
    head: Value,
    header: Vec<String>,
    n: usize,
    json_row: Box<dyn Fn(usize) -> Result<Value, CliError>>,
    text_row: Box<dyn Fn(usize) -> Result<String, CliError>>,
}

impl Precise {
    /// The JSON head and the human header lines of a motion (written before its rows take the
    /// motion over).
    fn describe<T: OutScalar>((method, times, segments, key_poses): Header<'_, T>) -> (Value, Vec<String>) {
        let head =
            json!({"method": method.name(), "parameters": json_list(times), "segments": segments_json(segments)});
        (head, header_text(method, times, segments, key_poses))
    }

    /// The output of a described motion and its `n` rows (`row(i)`).
    fn new<T: OutScalar + 'static>(
        (head, header): (Value, Vec<String>),
        n: usize,
        row: impl Fn(usize) -> Result<Row<T>, CliError> + 'static,
    ) -> Self {
        let row = std::rc::Rc::new(row);
        let (r1, r2) = (row.clone(), row);
        Precise {
            head,
            header,
            n,
            json_row: Box::new(move |i| Ok(r1(i)?.json())),
            text_row: Box::new(move |i| Ok(r2(i)?.text())),
        }
    }

    /// The JSON result, streamed by the CLI or taken as one value.
    pub(crate) fn streamed(self) -> Streamed<'static> {
        Streamed { head: self.head, n: self.n, sample: self.json_row }
    }

    /// The human output.
    fn text(self) -> Result<String, CliError> {
        let mut lines = self.header;
        for i in 0..self.n {
            lines.push((self.text_row)(i)?);
        }
        Ok(lines.join("\n"))
    }
}

/// `gam interpolate` of the spec text `text` (named `label` in messages) over exact rationals
/// or MPFR (inside [`MotionScalar::run`]).
pub(crate) fn precise(label: &str, text: &str, scalar: MotionScalar) -> Result<Precise, CliError> {
    let spec = precision::exact_spec(label, text)?;
    let n = if spec.samples >= 2 { spec.samples } else { 0 };
    let bodies = precision::body_points(&spec);
    if scalar == MotionScalar::Rational {
        let m = precision::build_exact(label, &spec)?;
        if n > 0 {
            check_segments(m.method(), m.segments(), bodies.len(), n, 1, scalar.cost_factor(m.key_poses().len()))?;
        }
        let described = Precise::describe((m.method(), m.times(), m.segments(), m.key_poses()));
        let row = move |i: usize| {
            let times = m.times();
            let t = even(&times[0], &times[times.len() - 1], n, i);
            let s = m.sample(&t, &bodies).map_err(|e| CliError::math(format!("{}: {e}", m.method())))?;
            Ok(Row::exact(s))
        };
        return Ok(Precise::new(described, n, row));
    }
    let b = precision::build_mpfr(label, &spec)?;
    let bodies: Vec<[MpFloat; 3]> = bodies.iter().map(|p| p.each_ref().map(MpFloat::from_rational)).collect();
    if n > 0 {
        check_segments(b.method(), b.segments(), bodies.len(), n, 1, scalar.cost_factor(b.key_poses().len()))?;
    }
    let described = Precise::describe((b.method(), b.times(), b.segments(), b.key_poses()));
    let row = move |i: usize| {
        let times = b.times();
        let t = even(&times[0], &times[times.len() - 1], n, i);
        Row::of(&b.sample(&t, &bodies).map_err(|e| CliError::math(e.to_string()))?)
    };
    Ok(Precise::new(described, n, row))
}

/// Runs `gam interpolate` on the spec file at `path`, in the scalar of `--scalar`.
pub fn interpolate(path: &str, json: bool, scalar: MotionScalar) -> Result<String, CliError> {
    if scalar == MotionScalar::F64 {
        return interpolate_f64(path, json);
    }
    let text = precision::read_file(path)?;
    scalar.run(|| {
        let out = precise(path, &text, scalar)?;
        if json { out.streamed().stream() } else { out.text() }
    })
}

/// `gam interpolate` in f64.
fn interpolate_f64(path: &str, json: bool) -> Result<String, CliError> {
    let spec = read_spec(path)?;
    if json {
        return interpolate_json(path, &spec)?.stream();
    }
    let b = build(path, &spec)?;
    let n = if b.samples >= 2 { b.samples } else { 0 };
    if n > 0 {
        check_work(&b, n, 1)?;
    }
    let m = &b.motion;
    let mut lines = header_text(m.method(), m.times(), m.segments(), m.key_poses());
    for i in 0..n {
        lines.push(Row::of(&sample_at(&b, n, i)?)?.text());
    }
    Ok(lines.join("\n"))
}

/// `gam sample` / `gam plot` on a `gam interpolate` spec (`label` names it in messages). The
/// body point is the first of `body_points`; sample `i` is at `t_0 + (t_m - t_0) i/(n-1)`.
pub(crate) fn spec_sampler(label: &str, spec: &InterpolateSpec, n: usize, passes: usize) -> Result<Sampler, CliError> {
    let b = build(label, spec)?;
    motion_sampler(b.motion, b.body_points.first().copied(), (n, passes, 1.0))
}

/// The sampler of a built motion over a real scalar and one body point (default the origin);
/// its work is checked as f64's times `factor` ([`MotionScalar::cost_factor`]).
pub(crate) fn motion_sampler<T: Real + OutScalar>(
    motion: BuiltMotion<T>,
    body_point: Option<[T; 3]>,
    (n, passes, factor): (usize, usize, f64),
) -> Result<Sampler<T>, CliError> {
    let body_point = body_point.unwrap_or_else(|| [T::zero(), T::zero(), T::zero()]);
    check_segments(motion.method(), motion.segments(), 1, n, passes, factor)?;
    let (kind, degree, segments) = (motion.method().kind(), motion.max_degree(), motion.segments().len());
    let point = [body_point.clone()];
    let at = move |i: usize| {
        let times = motion.times();
        let t = even(&times[0], &times[times.len() - 1], n, i);
        let s = motion.sample(&t, &point).map_err(|e| CliError::math(e.to_string()))?;
        let p = &s.points[0];
        checked(Sample {
            t: s.t.clone(),
            linear_speed: Some(norm(&p.velocity)),
            angular_speed: Some(norm(&s.space_twist.angular.to_array())),
            position: p.position.clone(),
            pose: s.pose,
        })
    };
    Ok(Sampler { kind, degree, segments, body_point, n, at: Box::new(at) })
}

#[cfg(test)]
mod tests {
    use super::interpolate_json;
    use crate::sample::{SampleSpec, sample_json};
    use motion::schema::InterpolateSpec;
    use serde_json::json;

    /// The entry points of a second front door on a spec already read: the whole result as one
    /// value, with the keys and samples the CLI streams.
    #[test]
    fn entry_points_on_a_parsed_value() {
        let v = json!({"method": "ccm-additive", "samples": 3, "body_points": [[0, 1, 0]],
            "poses": [{"position": [0, 0, 0]}, {"position": [2, 0, 0], "axis": [0, 0, 1], "angle": std::f64::consts::FRAC_PI_2}]});
        let spec = InterpolateSpec::from_value(&v).unwrap();
        let out = interpolate_json("spec", &spec).unwrap().into_value().unwrap();
        assert_eq!(out["method"], "ccm-additive");
        assert_eq!(out["parameters"], json!([0.0, 1.0]));
        let samples = out["samples"].as_array().unwrap();
        assert_eq!(samples.iter().map(|s| s["t"].as_f64().unwrap()).collect::<Vec<_>>(), [0.0, 0.5, 1.0]);
        // the body point (0, 1, 0) under the last key pose: a quarter turn about z, then (2, 0, 0)
        let p: Vec<f64> = samples[2]["points"][0].as_array().unwrap().iter().map(|x| x.as_f64().unwrap()).collect();
        assert!((p[0] - 1.0).abs() < 1e-15 && p[1].abs() < 1e-15 && p[2] == 0.0, "{p:?}");
        // `gam sample` on the same value: the first body point, with speeds
        let s = SampleSpec::from_value("spec", &v).unwrap();
        let out = sample_json("spec", &s, 2).unwrap().into_value().unwrap();
        assert_eq!(out["samples"].as_array().unwrap().len(), 2);
        assert_eq!(out["samples"][1]["position"], samples[2]["points"][0]);
        // a refusal carries the label and the library's message
        let bad = json!({"method": "ccm-additive", "poses": [{"position": [0, 0, 0]}, {"quaternion": [0, 0, 0, 0]}]});
        let e = SampleSpec::from_value("spec", &bad).err().unwrap();
        assert_eq!((e.code, e.message.as_str()), (2, "`spec`: `poses[1].quaternion` must be non-zero and finite"));
    }
}
