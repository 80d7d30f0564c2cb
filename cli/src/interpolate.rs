//! `gam interpolate [--json] SPEC.json`: a motion through key poses by a named method, exactly as
//! in the Wave 2 contract (shared/cli.md). Every method goes through ONE build path,
//! `motion::method::Method::build`, which returns a `motion::method::BuiltMotion` (the motion,
//! its segments, its sampler); this file reads the spec into a `MethodInput` and writes the
//! segments and samples, the same way for every method. Names of the contract that are not
//! implemented yet are recognised and refused with "not implemented yet".
//!
//! Pose objects: position + axis + angle, position + quaternion, matrix, motor, and the
//! `dual_quaternion` and `hexanion` forms (`crate::pose::extra_form`).
//! Parameters: `uniform` (default), a rule of Jüttler's eq. (15) (`chordal`, `star-chordal`,
//! `centripetal`, `angular`, `angular-chordal`, normalised to [0, 1]) or an explicit
//! increasing list (used as given). Velocities, when left out, are estimated by the method
//! (docs/cli.md).
//!
//! A spec of this command is also accepted by `gam sample` and `gam plot` ([`sampler`]).

use crate::error::CliError;
use crate::hermite::strip_comments;
use crate::output::{mv_human, mv_json};
use crate::sample::{MAX_SAMPLES, Sample, Sampler, checked};
use crate::scalar::format_f64;
use motion::juttler::Parametrisation;
use motion::method::{BuildError, BuiltMotion, Method, MethodInput, Parameters};
use motion::trajectory::TrajectorySample;
use motion::velocity::Twist;
use motion::{HermiteShapes, Pose, Pseudoscalar, Shape, Vec3};
use serde::Deserialize;
use serde_json::{Value, json};

/// The spec of `gam interpolate`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct Spec {
    method: String,
    poses: Vec<Value>,
    #[serde(default)]
    parameters: Option<Value>,
    #[serde(default)]
    velocities: Option<Vec<VelocitySpec>>,
    #[serde(default)]
    shape: Option<Value>,
    #[serde(default)]
    gamma: Option<Value>,
    #[serde(default)]
    samples: usize,
    #[serde(default)]
    body_points: Option<Vec<[f64; 3]>>,
    #[serde(default)]
    l1: Option<i64>,
}

/// The velocity of the body origin and the angular velocity at one key pose (per unit of t).
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct VelocitySpec {
    velocity: [f64; 3],
    angular_velocity: [f64; 3],
}

/// A built spec: the motion of its method, the body points and the number of samples.
pub(crate) struct Built {
    pub(crate) motion: BuiltMotion<f64>,
    pub(crate) body_points: Vec<[f64; 3]>,
    samples: usize,
}

pub(crate) fn usage(path: &str, what: impl std::fmt::Display) -> CliError {
    CliError::usage(format!("`{path}`: {what}"))
}

/// Reads the file; `Ok(None)` when it is not a `gam interpolate` spec (no top-level `method`).
fn read(path: &str) -> Result<Option<Spec>, CliError> {
    let text = std::fs::read_to_string(path).map_err(|e| CliError::usage(format!("cannot read `{path}`: {e}")))?;
    let text = strip_comments(&text);
    let value: Value = serde_json::from_str(&text).map_err(|e| usage(path, format!("invalid JSON: {e}")))?;
    if value.get("method").is_none() {
        return Ok(None);
    }
    let spec = serde_json::from_str(&text).map_err(|e| usage(path, format!("invalid spec: {e}")))?;
    Ok(Some(spec))
}

fn array3(path: &str, where_: &str, v: &Value) -> Result<[f64; 3], CliError> {
    serde_json::from_value(v.clone()).map_err(|_| usage(path, format!("`{where_}` must be a list of 3 numbers")))
}

/// One pose object of the spec.
fn pose(path: &str, i: usize, v: &Value) -> Result<Pose<f64>, CliError> {
    pose_in(path, &format!("poses[{i}]"), v)
}

/// One pose object (every form of the contract), named `name` in messages (also `gam pose`).
pub(crate) fn pose_in(path: &str, name: &str, v: &Value) -> Result<Pose<f64>, CliError> {
    let i = name;
    let at = |key: &str| format!("{i}.{key}");
    let obj = v.as_object().ok_or_else(|| usage(path, format!("`{i}` must be a pose object")))?;
    if let Some(parsed) = crate::pose::extra_form(obj, name) {
        return parsed.map_err(|e| usage(path, e));
    }
    let allowed: &[&str] = if obj.contains_key("motor") {
        &["motor"]
    } else if obj.contains_key("matrix") {
        &["matrix"]
    } else if obj.contains_key("quaternion") {
        &["position", "quaternion"]
    } else {
        &["position", "axis", "angle"]
    };
    if let Some(k) = obj.keys().find(|k| !allowed.contains(&k.as_str())) {
        return Err(usage(path, format!("`{i}`: unexpected key `{k}` (this pose form has {allowed:?})")));
    }
    let math = |e: motion::MotionError| usage(path, format!("`{i}`: {e}"));
    if let Some(m) = obj.get("motor") {
        let mv = m.as_object().ok_or_else(|| usage(path, format!("`{}` must be a multivector object", at("motor"))))?;
        let mut c = [0.0; 8];
        for (key, x) in mv {
            let k = motion::paper::BLADES
                .iter()
                .position(|b| b == key)
                .ok_or_else(|| usage(path, format!("`{}`: `{key}` is not a blade of g123inf^+", at("motor"))))?;
            c[k] = match x {
                Value::Number(n) => n.as_f64(),
                Value::String(s) => s.trim().parse::<f64>().ok(),
                _ => None,
            }
            .filter(|x| x.is_finite())
            .ok_or_else(|| usage(path, format!("`{}.{key}` must be a finite number", at("motor"))))?;
        }
        let s = Pose::new(c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7]);
        if s.is_singular() {
            return Err(usage(path, format!("`{}` is singular (rev(S) S has zero scalar part)", at("motor"))));
        }
        return Ok(s);
    }
    if let Some(m) = obj.get("matrix") {
        let m: [[f64; 4]; 4] = serde_json::from_value(m.clone())
            .map_err(|_| usage(path, format!("`{}` must be 4 rows of 4 numbers", at("matrix"))))?;
        return Pose::from_matrix(&m, &1e-9).map_err(math);
    }
    let position = match obj.get("position") {
        Some(p) => array3(path, &at("position"), p)?,
        None => [0.0; 3],
    };
    if let Some(q) = obj.get("quaternion") {
        let q: [f64; 4] = serde_json::from_value(q.clone())
            .map_err(|_| usage(path, format!("`{}` must be [w, x, y, z]", at("quaternion"))))?;
        return Pose::from_quaternion_wxyz(&q, &position)
            .map_err(|_| usage(path, format!("`{}` must be non-zero and finite", at("quaternion"))));
    }
    match (obj.get("axis"), obj.get("angle")) {
        (None, None) => Ok(Pose::translation(&position)),
        (Some(a), Some(phi)) => {
            let axis = array3(path, &at("axis"), a)?;
            let angle = phi.as_f64().ok_or_else(|| usage(path, format!("`{}` must be a number", at("angle"))))?;
            Pose::from_axis_angle_translation(&axis, &angle, &position)
                .map_err(|e| usage(path, format!("`{}`: {e}", at("axis"))))
        }
        _ => Err(usage(path, format!("`{i}`: `axis` and `angle` go together"))),
    }
}

/// `parameters` of the spec.
fn parameters(path: &str, spec: &Spec) -> Result<Parameters<f64>, CliError> {
    let rule = |r| Ok(Parameters::Rule(r));
    match &spec.parameters {
        None => Ok(Parameters::Uniform),
        Some(Value::String(s)) => match s.as_str() {
            "uniform" => Ok(Parameters::Uniform),
            "chordal" => rule(Parametrisation::Chordal),
            "star-chordal" => rule(Parametrisation::StarChordal),
            "centripetal" => rule(Parametrisation::Centripetal),
            "angular" => rule(Parametrisation::Angular),
            "angular-chordal" => rule(Parametrisation::AngleDistance),
            _ => Err(usage(
                path,
                format!(
                    "`parameters`: unknown rule `{s}` (uniform, chordal, star-chordal, centripetal, angular, angular-chordal, or a list)"
                ),
            )),
        },
        Some(Value::Array(list)) => serde_json::from_value(Value::Array(list.clone()))
            .map(Parameters::Given)
            .map_err(|_| usage(path, "`parameters` must be a list of numbers")),
        Some(other) => Err(usage(path, format!("`parameters` must be a rule name or a list (got {other})"))),
    }
}

/// `shape`/`gamma`: one common value or one per key pose.
fn shapes(path: &str, spec: &Spec, m: usize) -> Result<HermiteShapes<f64>, CliError> {
    let lambda: Vec<f64> = match &spec.shape {
        None => vec![1.0],
        Some(Value::Array(v)) if v.len() == m => serde_json::from_value(Value::Array(v.clone()))
            .map_err(|_| usage(path, "`shape` must be a number or one number per pose"))?,
        Some(v) => vec![v.as_f64().ok_or_else(|| usage(path, "`shape` must be a number or one number per pose"))?],
    };
    if let Some(x) = lambda.iter().find(|x| !(**x > 0.0 && x.is_finite())) {
        return Err(usage(path, format!("`shape` must be positive (got {})", format_f64(*x))));
    }
    let gamma: Vec<[f64; 2]> = match &spec.gamma {
        None => vec![[0.0, 0.0]],
        Some(v) => match serde_json::from_value::<[f64; 2]>(v.clone()) {
            Ok(g) => vec![g],
            Err(_) => serde_json::from_value::<Vec<[f64; 2]>>(v.clone())
                .ok()
                .filter(|g| g.len() == m)
                .ok_or_else(|| usage(path, "`gamma` must be [alpha, beta] or one such pair per pose"))?,
        },
    };
    let shape = |k: usize| {
        let (l, g) = (lambda[k.min(lambda.len() - 1)], gamma[k.min(gamma.len() - 1)]);
        Shape::new(l, Pseudoscalar::new(g[0], g[1]))
    };
    Ok(if lambda.len() == 1 && gamma.len() == 1 {
        HermiteShapes::Common(shape(0))
    } else {
        HermiteShapes::PerPose((0..m).map(shape).collect())
    })
}

/// A failure of [`Method::build`]: exit 2 for bad input, 1 for a numerical failure (singular
/// system, pose or join), naming the method where the failure is the method's own.
fn build_error(path: &str, method: Method, e: BuildError) -> CliError {
    let own = matches!(
        e,
        BuildError::Trajectory(_)
            | BuildError::Wl(_)
            | BuildError::Repr(_)
            | BuildError::Juttler(_)
            | BuildError::Unstable { .. }
    );
    let message = if own { format!("{}: {e}", method.name()) } else { e.to_string() };
    if e.is_input() { usage(path, message) } else { CliError::math(message) }
}

/// The optional spec keys that are given.
fn given_keys(spec: &Spec) -> [(&'static str, bool); 4] {
    [
        ("velocities", spec.velocities.is_some()),
        ("shape", spec.shape.is_some()),
        ("gamma", spec.gamma.is_some()),
        ("l1", spec.l1.is_some()),
    ]
}

/// Checks and builds a spec.
fn build(path: &str, spec: &Spec) -> Result<Built, CliError> {
    let method: Method = spec.method.parse().map_err(|e| usage(path, e))?;
    if let Some((key, _)) = given_keys(spec).into_iter().find(|(k, given)| *given && !method.inputs().contains(k)) {
        return Err(usage(path, BuildError::Unused { key, method }));
    }
    let m = spec.poses.len();
    if m < 2 {
        return Err(usage(path, BuildError::TooFewPoses { got: m }));
    }
    let poses = spec.poses.iter().enumerate().map(|(i, v)| pose(path, i, v)).collect::<Result<Vec<_>, _>>()?;
    let velocities = match &spec.velocities {
        None => None,
        Some(v) if v.len() != m => {
            return Err(usage(path, format!("`velocities` has {} entries for {m} poses", v.len())));
        }
        Some(v) => Some(
            v.iter()
                .zip(&poses)
                .map(|(w, s)| {
                    // u = v - Ω × p: the velocity of the body point at the global origin.
                    let p = s.transform_point(&[0.0; 3]).map_err(|e| CliError::math(e.to_string()))?;
                    let o = w.angular_velocity;
                    let c = [o[1] * p[2] - o[2] * p[1], o[2] * p[0] - o[0] * p[2], o[0] * p[1] - o[1] * p[0]];
                    Ok(Twist { angular: o.into(), linear: Vec3::from(std::array::from_fn(|k| w.velocity[k] - c[k])) })
                })
                .collect::<Result<Vec<_>, CliError>>()?,
        ),
    };
    let shapes = if spec.shape.is_some() || spec.gamma.is_some() { Some(shapes(path, spec, m)?) } else { None };
    let l1 = match spec.l1 {
        None => None,
        Some(k) => Some(usize::try_from(k).map_err(|_| usage(path, format!("`l1` must be 0 or more (got {k})")))?),
    };
    let input = MethodInput { parameters: parameters(path, spec)?, velocities, shapes, l1, ..MethodInput::new(poses) };
    if spec.samples == 1 || spec.samples > MAX_SAMPLES {
        return Err(usage(path, format!("`samples` must be 0 or from 2 to {MAX_SAMPLES} (got {})", spec.samples)));
    }
    let body_points = spec.body_points.clone().unwrap_or_else(|| vec![[0.0; 3]]);
    let motion = method.build(&input).map_err(|e| build_error(path, method, e))?;
    Ok(Built { motion, body_points, samples: spec.samples })
}

/// Reads and builds a `gam interpolate` spec (also for `gam trajectory`).
pub(crate) fn built(path: &str) -> Result<Built, CliError> {
    let spec = read(path)?.ok_or_else(|| usage(path, "invalid spec: missing field `method`"))?;
    build(path, &spec)
}

fn finite3(v: &[f64; 3]) -> bool {
    v.iter().all(|x| x.is_finite())
}

/// The work of sampling `n` values: `n × (degree + 1)²` per body point (as for `gam sample`),
/// with the largest segment degree, checked against the budget.
fn check_work(b: &Built, n: usize) -> Result<(), CliError> {
    let (points, degree) = (b.body_points.len().max(1), b.motion.max_degree());
    crate::budget::check(
        &format!("sampling {points} body points of degree-{degree} segments at {n} values"),
        crate::budget::sampling_work(degree, n) * points as f64,
    )
}

/// Sample `i` of `n` evenly spaced times over `[t_0, t_m]` (as `Trajectory::sample_evenly`),
/// checked finite.
fn sample_at(b: &Built, n: usize, i: usize) -> Result<TrajectorySample<f64>, CliError> {
    let times = b.motion.times();
    let (t0, t1) = (times[0], times[times.len() - 1]);
    let t = if i + 1 == n { t1 } else { t0 + (t1 - t0) * (i as f64 / (n - 1) as f64) };
    let s = b.motion.sample(&t, &b.body_points).map_err(|e| CliError::math(e.to_string()))?;
    let ok = s.points.iter().all(|p| finite3(&p.position) && finite3(&p.velocity))
        && finite3(&s.space_twist.angular.to_array());
    if !ok {
        return Err(CliError::math(format!("the result at t = {} is not finite (overflow)", format_f64(s.t))));
    }
    Ok(s)
}

/// One sample as a JSON object of `gam interpolate --json`.
fn sample_json(s: &TrajectorySample<f64>) -> Result<Value, CliError> {
    let matrix = s.pose.unitize().and_then(|u| u.to_matrix()).map_err(|e| CliError::math(e.to_string()))?;
    // `x + 0.0` prints -0.0 as 0.0.
    let v3 = |v: &[f64; 3]| v.map(|x| x + 0.0);
    Ok(json!({"t": s.t, "matrix": matrix.map(|r| r.map(|x| x + 0.0)),
        "points": s.points.iter().map(|p| v3(&p.position)).collect::<Vec<_>>(),
        "velocities": s.points.iter().map(|p| v3(&p.velocity)).collect::<Vec<_>>(),
        "angular_velocity": v3(&s.space_twist.angular.to_array())}))
}

/// The contract's `segments` array.
fn segments_json(b: &Built) -> Vec<Value> {
    let z = |x: &f64| x + 0.0;
    b.motion
        .segments()
        .iter()
        .map(|seg| {
            let mut v = json!({"t0": seg.t0, "t1": seg.t1, "representation": seg.representation, "degree": seg.degree,
                "control_poses": seg.control_poses.iter().map(|s| mv_json(&s.to_multivector())).collect::<Vec<_>>()});
            if let Some(d) = &seg.dual_quaternions {
                v["dual_quaternions"] = json!(d.iter().map(|d| d.coeffs().map(|x| z(&x))).collect::<Vec<_>>());
            }
            if let Some(h) = &seg.hexanions {
                let hex = |x: &motion::repr::hexanion::Hexanion<f64>| json!({"omega": x.omega.map(|c| z(&c)), "m": x.m.map(|c| z(&c))});
                v["hexanions"] = json!([hex(&h[0]), hex(&h[1])]);
            }
            v
        })
        .collect()
}

/// `gam interpolate --json`, streamed in bounded memory like `gam sample --json`: the header
/// (method, parameters, segments), then a first pass that computes every sample and discards
/// it (a failure leaves stdout empty), then a second that writes them one by one.
fn stream_json(b: &Built) -> Result<String, CliError> {
    let n = if b.samples >= 2 { b.samples } else { 0 };
    if n > 0 {
        check_work(b, n)?;
    }
    let head =
        json!({"method": b.motion.method().name(), "parameters": b.motion.times(), "segments": segments_json(b)});
    write_streamed(&head, n, &|i| sample_json(&sample_at(b, n, i)?))
}

/// Writes `head` with a `samples` array of `n` objects appended, sample by sample in bounded
/// memory, after a first pass that computes every sample and discards it (so a failure
/// leaves stdout empty, as the error contract requires). Returns the empty string: the
/// caller's final newline ends the JSON.
fn write_streamed(
    head: &Value,
    n: usize,
    sample: &dyn Fn(usize) -> Result<Value, CliError>,
) -> Result<String, CliError> {
    use crate::sample::write_error;
    use std::io::Write;
    for i in 0..n {
        sample(i)?;
    }
    let head = head.to_string();
    let mut out = std::io::BufWriter::new(std::io::stdout().lock());
    out.write_all(head.strip_suffix('}').unwrap_or(&head).as_bytes()).map_err(write_error)?;
    out.write_all(b",\"samples\":[").map_err(write_error)?;
    for i in 0..n {
        if i > 0 {
            out.write_all(b",").map_err(write_error)?;
        }
        serde_json::to_writer(&mut out, &sample(i)?).map_err(|e| write_error(e.into()))?;
    }
    out.write_all(b"]}").map_err(write_error)?;
    out.flush().map_err(write_error)?;
    Ok(String::new())
}

/// Runs `gam interpolate`.
pub fn interpolate(path: &str, json: bool) -> Result<String, CliError> {
    let b = built(path)?;
    if json {
        return stream_json(&b);
    }
    let n = if b.samples >= 2 { b.samples } else { 0 };
    if n > 0 {
        check_work(&b, n)?;
    }
    let method = b.motion.method();
    let times = b.motion.times();
    let t = times.iter().map(|x| format_f64(*x)).collect::<Vec<_>>().join(", ");
    let segments = b.motion.segments();
    let mut lines = vec![format!("{method}: {} segments through {} poses at t = [{t}]", segments.len(), times.len())];
    if matches!(method, Method::WlLinear | Method::WlQuadratic | Method::HexanionLinear) {
        // their segments' control poses are key poses: each once
        for (i, s) in b.motion.key_poses().iter().enumerate() {
            lines.push(format!("  P{i} = {}", mv_human(&s.to_multivector())));
        }
    } else {
        for (k, seg) in segments.iter().enumerate() {
            lines.push(format!("segment {k} (t = {} .. {}):", format_f64(seg.t0), format_f64(seg.t1)));
            for (i, s) in seg.control_poses.iter().enumerate() {
                lines.push(format!("  S{i} = {}", mv_human(&s.to_multivector())));
            }
        }
    }
    for i in 0..n {
        let s = sample_at(&b, n, i)?;
        let pts: Vec<String> =
            s.points.iter().map(|p| format!("[{}]", p.position.map(format_f64).join(", "))).collect();
        lines.push(format!("t = {}: points {}", format_f64(s.t), pts.join(" ")));
    }
    Ok(lines.join("\n"))
}

/// `gam sample` / `gam plot` on a `gam interpolate` spec: `Ok(None)` when the file is not one.
/// The body point is the first of `body_points`; sample `i` is at `t_0 + (t_m - t_0) i/(n-1)`.
pub(crate) fn sampler(path: &str, n: usize) -> Result<Option<Sampler>, CliError> {
    let Some(spec) = read(path)? else { return Ok(None) };
    let b = build(path, &spec)?;
    let body_point = b.body_points.first().copied().unwrap_or([0.0; 3]);
    let one = Built { body_points: vec![body_point], ..b };
    check_work(&one, n)?;
    let norm = |v: &[f64; 3]| v.iter().map(|x| x * x).sum::<f64>().sqrt();
    let (kind, degree, segments) = (one.motion.method().kind(), one.motion.max_degree(), one.motion.segments().len());
    let at = move |i: usize| {
        let s = sample_at(&one, n, i)?;
        checked(Sample {
            t: s.t,
            linear_speed: norm(&s.points[0].velocity),
            angular_speed: norm(&s.space_twist.angular.to_array()),
            position: s.points[0].position,
            pose: s.pose,
        })
    };
    Ok(Some(Sampler { kind, degree, segments, body_point, n, at: Box::new(at) }))
}
