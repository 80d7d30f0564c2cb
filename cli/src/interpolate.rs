//! `gam interpolate [--json] SPEC.json`: a motion through key poses by a named method, exactly as
//! in the Wave 2 contract (shared/cli.md). The methods are `motion::method::Method` (today
//! `ccm-additive` and `ccm-multiplicative`, main paper Sec. 5.3: `motion::trajectory`; and
//! `wl-linear`, `wl-quadratic`, Wareham–Lasenby Sec. 3: `motion::wareham_lasenby`, and
//! `hexanion-linear`, Angelidis (56): `motion::repr::hexanion::blend::HexanionLinear`, the
//! methods through the key poses only, built by `wl_build`); the other names of the contract are recognised and refused with "not
//! implemented yet".
//!
//! Pose objects: position + axis + angle, position + quaternion, matrix, motor, and the
//! `dual_quaternion` and `hexanion` forms (`crate::pose::extra_form`).
//! Parameters: `uniform` (default) or an explicit increasing list; the Jüttler rules of eq. (15)
//! come with issue 11 and are refused (exit 2). Velocities, when left out, are estimated
//! (docs/cli.md): zero at the ends, the weighted mean of the neighbouring screw twists inside.
//!
//! A spec of this command is also accepted by `gam sample` and `gam plot` ([`sampled`]).

use crate::error::CliError;
use crate::hermite::strip_comments;
use crate::output::{mv_human, mv_json};
use crate::sample::{MAX_SAMPLES, Sample, Sampler, checked};
use crate::scalar::format_f64;
use motion::method::Method;
use motion::trajectory::{Trajectory, TrajectoryError, TrajectorySample, Velocities};
use motion::velocity::Twist;
use motion::{HermiteShapes, JoinError, Pose, Pseudoscalar, Shape, Vec3};
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

/// A built spec.
pub(crate) struct Built {
    method: Method,
    times: Vec<f64>,
    trajectory: Trajectory<f64>,
    body_points: Vec<[f64; 3]>,
    samples: usize,
}

fn usage(path: &str, what: impl std::fmt::Display) -> CliError {
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
        return Pose::from_quaternion_translation(&q, &position)
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

/// `t_i` from `parameters`.
fn times(path: &str, spec: &Spec, m: usize) -> Result<Vec<f64>, CliError> {
    match &spec.parameters {
        None => Ok((0..m).map(|i| i as f64 / (m - 1) as f64).collect()),
        Some(Value::String(s)) if s == "uniform" => Ok((0..m).map(|i| i as f64 / (m - 1) as f64).collect()),
        Some(Value::String(s))
            if ["chordal", "star-chordal", "centripetal", "angular", "angular-chordal"].contains(&s.as_str()) =>
        {
            Err(usage(
                path,
                format!(
                    "`parameters`: `{s}` (Jüttler's eq. (15)) is not implemented yet (it comes with issue 11); use `uniform` or a list"
                ),
            ))
        }
        Some(Value::Array(list)) => {
            let t: Vec<f64> = serde_json::from_value(Value::Array(list.clone()))
                .map_err(|_| usage(path, "`parameters` must be a list of numbers"))?;
            if t.len() != m {
                return Err(usage(path, format!("`parameters` has {} values for {m} poses", t.len())));
            }
            Ok(t)
        }
        Some(other) => Err(usage(path, format!("`parameters` must be `uniform` or a list (got {other})"))),
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

fn trajectory_error(path: &str, method: Method, e: TrajectoryError) -> CliError {
    match e {
        TrajectoryError::Input(m) | TrajectoryError::Join(JoinError::Input(m)) => usage(path, m),
        other => CliError::math(format!("{}: {other}", method.name())),
    }
}

/// Checks and builds a spec.
fn build(path: &str, spec: &Spec) -> Result<Built, CliError> {
    let method: Method = spec.method.parse().map_err(|e| usage(path, e))?;
    if spec.l1.is_some() {
        return Err(usage(path, format!("`l1` is only used by `juttler-trt`, not `{}`", method.name())));
    }
    let m = spec.poses.len();
    if m < 2 {
        return Err(usage(path, format!("at least two poses are needed (got {m})")));
    }
    let poses = spec.poses.iter().enumerate().map(|(i, v)| pose(path, i, v)).collect::<Result<Vec<_>, _>>()?;
    let times = times(path, spec, m)?;
    let velocities = match &spec.velocities {
        None => Velocities::CatmullRom,
        Some(v) if v.len() != m => {
            return Err(usage(path, format!("`velocities` has {} entries for {m} poses", v.len())));
        }
        Some(v) => Velocities::Given(
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
    let shapes = shapes(path, spec, m)?;
    if spec.samples == 1 || spec.samples > MAX_SAMPLES {
        return Err(usage(path, format!("`samples` must be 0 or from 2 to {MAX_SAMPLES} (got {})", spec.samples)));
    }
    let body_points = spec.body_points.clone().unwrap_or_else(|| vec![[0.0; 3]]);
    let trajectory =
        method.interpolate(&poses, &times, &velocities, &shapes).map_err(|e| trajectory_error(path, method, e))?;
    Ok(Built { method, times, trajectory, body_points, samples: spec.samples })
}

fn finite3(v: &[f64; 3]) -> bool {
    v.iter().all(|x| x.is_finite())
}

/// The work of sampling `n` values: `n × (degree + 1)²` per body point (as for `gam sample`),
/// with the largest segment degree, checked against the budget.
fn check_work(b: &Built, n: usize) -> Result<(), CliError> {
    let degree = b.trajectory.segments().iter().map(|s| s.degree()).max().unwrap_or(0);
    check_sampling_work(b.body_points.len(), degree, n)
}

/// The budget check of sampling `points` body points (at least one: the pose itself is
/// sampled) on segments of degree at most `degree` at `n` values, for every method.
fn check_sampling_work(points: usize, degree: usize, n: usize) -> Result<(), CliError> {
    let points = points.max(1);
    crate::budget::check(
        &format!("sampling {points} body points of degree-{degree} segments at {n} values"),
        crate::budget::sampling_work(degree, n) * points as f64,
    )
}

/// Sample `i` of `n` evenly spaced times over `[t_0, t_m]` (as `Trajectory::sample_evenly`),
/// checked finite.
fn sample_at(b: &Built, n: usize, i: usize) -> Result<TrajectorySample<f64>, CliError> {
    let (t0, t1) = (b.times[0], b.times[b.times.len() - 1]);
    let t = if i + 1 == n { t1 } else { t0 + (t1 - t0) * (i as f64 / (n - 1) as f64) };
    let s = b.trajectory.sample(&t, &b.body_points).map_err(|e| CliError::math(e.to_string()))?;
    let ok = s.points.iter().all(|p| finite3(&p.position) && finite3(&p.velocity))
        && finite3(&s.space_twist.angular.to_array());
    if !ok {
        return Err(CliError::math(format!("the result at t = {} is not finite (overflow)", format_f64(s.t))));
    }
    Ok(s)
}

/// The samples of a built spec at `n` evenly spaced times over `[t_0, t_m]`, after
/// [`check_work`].
fn samples(b: &Built, n: usize) -> Result<Vec<TrajectorySample<f64>>, CliError> {
    check_work(b, n)?;
    (0..n).map(|i| sample_at(b, n, i)).collect()
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

/// `gam interpolate --json`, streamed in bounded memory like `gam sample --json`: the header
/// (method, parameters, segments), then a first pass that computes every sample and discards
/// it (a failure leaves stdout empty), then a second that writes them one by one.
fn stream_json(b: &Built) -> Result<String, CliError> {
    let n = if b.samples >= 2 { b.samples } else { 0 };
    if n > 0 {
        check_work(b, n)?;
    }
    let segs: Vec<Value> = b
        .trajectory
        .segments()
        .iter()
        .enumerate()
        .map(|(k, seg)| {
            let mut seg_json = json!({"t0": b.times[k], "t1": b.times[k + 1], "representation": b.method.representation(),
                   "degree": seg.degree(),
                   "control_poses": seg.control_poses().iter().map(|s| mv_json(&s.to_multivector())).collect::<Vec<_>>()});
            if b.method == Method::CcmAdditive {
                seg_json["dual_quaternions"] = json!(crate::pose::dual_quaternions(seg.control_poses()));
            }
            seg_json
        })
        .collect();
    let head = json!({"method": b.method.name(), "parameters": b.times, "segments": segs});
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
    let spec = read(path)?.ok_or_else(|| usage(path, "invalid spec: missing field `method`"))?;
    if let Some(w) = wl_build(path, &spec)? {
        return wl_output(&w, json);
    }
    let b = build(path, &spec)?;
    if json {
        return stream_json(&b);
    }
    let sampled = if b.samples >= 2 { samples(&b, b.samples)? } else { Vec::new() };
    let name = b.method.name();
    let segments = b.trajectory.segments();
    let t = b.times.iter().map(|x| format_f64(*x)).collect::<Vec<_>>().join(", ");
    let mut lines = vec![format!("{name}: {} segments through {} poses at t = [{t}]", segments.len(), b.times.len())];
    for (k, seg) in segments.iter().enumerate() {
        lines.push(format!("segment {k} (t = {} .. {}):", format_f64(b.times[k]), format_f64(b.times[k + 1])));
        for (i, s) in seg.control_poses().iter().enumerate() {
            lines.push(format!("  S{i} = {}", mv_human(&s.to_multivector())));
        }
    }
    for s in &sampled {
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
    if let Some(w) = wl_build(path, &spec)? {
        return wl_sampled(w, n).map(Some);
    }
    let b = build(path, &spec)?;
    let body_point = b.body_points.first().copied().unwrap_or([0.0; 3]);
    let one = Built { body_points: vec![body_point], ..b };
    check_work(&one, n)?;
    let norm = |v: &[f64; 3]| v.iter().map(|x| x * x).sum::<f64>().sqrt();
    let (kind, segments) = (one.method.kind(), one.trajectory.segments().len());
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
    Ok(Some(Sampler { kind, degree: 3, segments, body_point, n, at: Box::new(at) }))
}

/// A built spec of a method through the key poses only (`wl-linear`, `wl-quadratic`,
/// `hexanion-linear`): a [`motion::method::KeyMotion`], not a Hermite trajectory.
struct WlBuilt {
    method: Method,
    times: Vec<f64>,
    poses: Vec<Pose<f64>>,
    motion: motion::method::KeyMotion<f64>,
    body_points: Vec<[f64; 3]>,
    samples: usize,
}

/// `Ok(None)` unless the spec names a W-L or hexanion method; the Hermite-only keys are refused.
fn wl_build(path: &str, spec: &Spec) -> Result<Option<WlBuilt>, CliError> {
    let Ok(method) = spec.method.parse::<Method>() else { return Ok(None) };
    if !method.through_keys() {
        return Ok(None);
    }
    let name = method.name();
    for (key, given) in [
        ("velocities", spec.velocities.is_some()),
        ("shape", spec.shape.is_some()),
        ("gamma", spec.gamma.is_some()),
        ("l1", spec.l1.is_some()),
    ] {
        if given {
            return Err(usage(path, format!("`{key}` is not used by `{name}` (it interpolates the key poses only)")));
        }
    }
    let m = spec.poses.len();
    if m < 2 {
        return Err(usage(path, format!("at least two poses are needed (got {m})")));
    }
    let mut poses = spec.poses.iter().enumerate().map(|(i, v)| pose(path, i, v)).collect::<Result<Vec<_>, _>>()?;
    motion::trajectory::align_signs(&mut poses);
    let times = times(path, spec, m)?;
    if spec.samples == 1 || spec.samples > MAX_SAMPLES {
        return Err(usage(path, format!("`samples` must be 0 or from 2 to {MAX_SAMPLES} (got {})", spec.samples)));
    }
    let motion = match method.key_motion(&poses, &times) {
        Some(Ok(m)) => m,
        Some(Err(e)) if e.is_input() => return Err(usage(path, format!("{name}: {e}"))),
        Some(Err(e)) => return Err(CliError::math(format!("{name}: {e}"))),
        None => return Ok(None),
    };
    let body_points = spec.body_points.clone().unwrap_or_else(|| vec![[0.0; 3]]);
    Ok(Some(WlBuilt { method, times, poses, motion, body_points, samples: spec.samples }))
}

/// The key poses segment `k` depends on and its degree in `t` (of the generator before exp).
fn wl_segment(w: &WlBuilt, k: usize) -> (std::ops::RangeInclusive<usize>, usize) {
    let last = w.poses.len() - 1;
    match w.method {
        Method::WlQuadratic if last == 2 => (0..=2, 2),
        Method::WlQuadratic => {
            let (lo, hi) = (k.saturating_sub(1), (k + 2).min(last));
            (lo..=hi, if hi - lo == 3 { 3 } else { 2 })
        }
        _ => (k..=k + 1, 1),
    }
}

/// A sample of a W-L motion: the pose, the images and velocities of the body points, `Ω`.
type WlSample = (Pose<f64>, Vec<[f64; 3]>, Vec<[f64; 3]>, [f64; 3]);

/// One sample of a W-L motion ([`WlSample`]).
fn wl_sample(w: &WlBuilt, t: f64, points: &[[f64; 3]]) -> Result<WlSample, CliError> {
    let math = |e: &dyn std::fmt::Display| CliError::math(format!("{} at t = {}: {e}", w.method.name(), format_f64(t)));
    let v = motion::velocity::velocity(&w.motion, &t).map_err(|e| math(&e))?;
    let twist = v.twist();
    let mut pos = Vec::with_capacity(points.len());
    let mut vel = Vec::with_capacity(points.len());
    for p in points {
        let q = v.pose.transform_point(p).map_err(|e| math(&e))?;
        vel.push(twist.point_velocity(&q).to_array());
        pos.push(q);
    }
    let angular = twist.angular.to_array();
    if !(pos.iter().chain(&vel).all(finite3) && finite3(&angular)) {
        return Err(CliError::math(format!("the result at t = {} is not finite (overflow)", format_f64(t))));
    }
    Ok((v.pose, pos, vel, angular))
}

fn wl_times(w: &WlBuilt, n: usize) -> Vec<f64> {
    let (t0, t1) = (w.times[0], w.times[w.times.len() - 1]);
    (0..n).map(|i| if i + 1 == n { t1 } else { t0 + (t1 - t0) * i as f64 / (n - 1) as f64 }).collect()
}

/// `gam interpolate` output for a W-L method (the contract's keys; `control_poses` are the
/// sign-aligned key poses each segment depends on).
fn wl_output(w: &WlBuilt, json: bool) -> Result<String, CliError> {
    let name = w.method.name();
    let segs = w.times.len() - 1;
    if json {
        let segments: Vec<Value> = (0..segs)
            .map(|k| {
                let (range, degree) = wl_segment(w, k);
                let mut seg = json!({"t0": w.times[k], "t1": w.times[k + 1], "representation": w.method.representation(),
                       "degree": degree,
                       "control_poses": w.poses[range].iter().map(|s| mv_json(&s.to_multivector())).collect::<Vec<_>>()});
                if let motion::method::KeyMotion::Hexanion(h) = &w.motion {
                    let hex = |x: &motion::repr::hexanion::Hexanion<f64>| json!({"omega": x.omega.map(|c| c + 0.0), "m": x.m.map(|c| c + 0.0)});
                    seg["hexanions"] = json!([hex(&h.hexanions()[k]), hex(&h.hexanions()[k + 1])]);
                }
                seg
            })
            .collect();
        let n = if w.samples >= 2 { w.samples } else { 0 };
        let times = if n > 0 {
            wl_check_work(w, n, w.body_points.len())?;
            wl_times(w, n)
        } else {
            Vec::new()
        };
        let sample = |i: usize| -> Result<Value, CliError> {
            let t = times[i];
            let (pose, pos, vel, omega) = wl_sample(w, t, &w.body_points)?;
            let matrix = pose.unitize().and_then(|u| u.to_matrix()).map_err(|e| CliError::math(e.to_string()))?;
            let v3 = |v: &[f64; 3]| v.map(|x| x + 0.0);
            Ok(json!({"t": t, "matrix": matrix.map(|r| r.map(|x| x + 0.0)),
                "points": pos.iter().map(v3).collect::<Vec<_>>(),
                "velocities": vel.iter().map(v3).collect::<Vec<_>>(),
                "angular_velocity": v3(&omega)}))
        };
        let head = json!({"method": name, "parameters": w.times, "segments": segments});
        return write_streamed(&head, n, &sample);
    }
    let t = w.times.iter().map(|x| format_f64(*x)).collect::<Vec<_>>().join(", ");
    let mut lines = vec![format!("{name}: {segs} segments through {} poses at t = [{t}]", w.times.len())];
    for (i, s) in w.poses.iter().enumerate() {
        lines.push(format!("  P{i} = {}", mv_human(&s.to_multivector())));
    }
    if w.samples >= 2 {
        wl_check_work(w, w.samples, w.body_points.len())?;
        for t in wl_times(w, w.samples) {
            let (_, pos, _, _) = wl_sample(w, t, &w.body_points)?;
            let pts: Vec<String> = pos.iter().map(|p| format!("[{}]", p.map(format_f64).join(", "))).collect();
            lines.push(format!("t = {}: points {}", format_f64(t), pts.join(" ")));
        }
    }
    Ok(lines.join("\n"))
}

/// The largest segment degree of a W-L / hexanion spec and the budget check of sampling
/// `points` body points at `n` values.
fn wl_check_work(w: &WlBuilt, n: usize, points: usize) -> Result<usize, CliError> {
    let degree = (0..w.times.len() - 1).map(|k| wl_segment(w, k).1).max().unwrap_or(1);
    check_sampling_work(points, degree, n)?;
    Ok(degree)
}

/// `gam sample` / `gam plot` on a W-L or hexanion spec.
fn wl_sampled(w: WlBuilt, n: usize) -> Result<Sampler, CliError> {
    let body_point = w.body_points.first().copied().unwrap_or([0.0; 3]);
    let degree = wl_check_work(&w, n, 1)?;
    let norm = |v: &[f64; 3]| v.iter().map(|x| x * x).sum::<f64>().sqrt();
    let (kind, segments) = (w.method.kind(), w.times.len() - 1);
    let times = wl_times(&w, n);
    let at = move |i: usize| {
        let t = times[i];
        let (pose, pos, vel, omega) = wl_sample(&w, t, &[body_point])?;
        checked(Sample { t, linear_speed: norm(&vel[0]), angular_speed: norm(&omega), position: pos[0], pose })
    };
    Ok(Sampler { kind, degree, segments, body_point, n, at: Box::new(at) })
}
