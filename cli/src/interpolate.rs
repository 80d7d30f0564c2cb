//! `gam interpolate [--json] SPEC.json`: a motion through key poses by a named method, exactly as
//! in the Wave 2 contract (shared/cli.md). The methods are `motion::method::Method` (today
//! `ccm-additive` and `ccm-multiplicative`, main paper Sec. 5.3: `motion::trajectory`); the
//! other names of the contract are recognised and refused with "not implemented yet".
//!
//! Pose objects: position + axis + angle, position + quaternion, matrix, motor. The
//! `dual_quaternion` and `hexanion` forms come with issue 10 and are refused (exit 2).
//! Parameters: `uniform` (default) or an explicit increasing list; the Jüttler rules of eq. (15)
//! come with issue 11 and are refused (exit 2). Velocities, when left out, are estimated
//! (docs/cli.md): zero at the ends, the weighted mean of the neighbouring screw twists inside.
//!
//! A spec of this command is also accepted by `gam sample` and `gam plot` ([`sampled`]).

use crate::error::CliError;
use crate::hermite::strip_comments;
use crate::output::{mv_human, mv_json};
use crate::sample::{MAX_SAMPLES, Sample, Sampled};
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

/// One pose object (the contract's forms that exist today).
fn pose(path: &str, i: usize, v: &Value) -> Result<Pose<f64>, CliError> {
    let at = |key: &str| format!("poses[{i}].{key}");
    let obj = v.as_object().ok_or_else(|| usage(path, format!("`poses[{i}]` must be a pose object")))?;
    for later in ["dual_quaternion", "hexanion"] {
        if obj.contains_key(later) {
            return Err(usage(
                path,
                format!("`poses[{i}]`: the `{later}` pose form is not implemented yet (it comes with issue 10)"),
            ));
        }
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
        return Err(usage(path, format!("`poses[{i}]`: unexpected key `{k}` (this pose form has {allowed:?})")));
    }
    let math = |e: motion::MotionError| usage(path, format!("`poses[{i}]`: {e}"));
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
        _ => Err(usage(path, format!("`poses[{i}]`: `axis` and `angle` go together"))),
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

/// The samples of a built spec at `n` evenly spaced times over `[t_0, t_m]`.
fn samples(b: &Built, n: usize) -> Result<Vec<TrajectorySample<f64>>, CliError> {
    let out = b.trajectory.sample_evenly(n, &b.body_points).map_err(|e| CliError::math(e.to_string()))?;
    for s in &out {
        let ok = s.points.iter().all(|p| finite3(&p.position) && finite3(&p.velocity))
            && finite3(&s.space_twist.angular.to_array());
        if !ok {
            return Err(CliError::math(format!("the result at t = {} is not finite (overflow)", format_f64(s.t))));
        }
    }
    Ok(out)
}

/// Runs `gam interpolate`.
pub fn interpolate(path: &str, json: bool) -> Result<String, CliError> {
    let spec = read(path)?.ok_or_else(|| usage(path, "invalid spec: missing field `method`"))?;
    let b = build(path, &spec)?;
    let sampled = if b.samples >= 2 { samples(&b, b.samples)? } else { Vec::new() };
    let name = b.method.name();
    let segments = b.trajectory.segments();
    if json {
        let segs: Vec<Value> = segments
            .iter()
            .enumerate()
            .map(|(k, seg)| {
                json!({"t0": b.times[k], "t1": b.times[k + 1], "representation": b.method.representation(),
                       "degree": seg.degree(),
                       "control_poses": seg.control_poses().iter().map(|s| mv_json(&s.to_multivector())).collect::<Vec<_>>()})
            })
            .collect();
        let mut out = Vec::with_capacity(sampled.len());
        for s in &sampled {
            let matrix = s.pose.unitize().and_then(|u| u.to_matrix()).map_err(|e| CliError::math(e.to_string()))?;
            // `x + 0.0` prints -0.0 as 0.0.
            let v3 = |v: &[f64; 3]| v.map(|x| x + 0.0);
            out.push(json!({"t": s.t, "matrix": matrix.map(|r| r.map(|x| x + 0.0)),
                "points": s.points.iter().map(|p| v3(&p.position)).collect::<Vec<_>>(),
                "velocities": s.points.iter().map(|p| v3(&p.velocity)).collect::<Vec<_>>(),
                "angular_velocity": v3(&s.space_twist.angular.to_array())}));
        }
        return Ok(json!({"method": name, "parameters": b.times, "segments": segs, "samples": out}).to_string());
    }
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
/// The body point is the first of `body_points`.
pub(crate) fn sampled(path: &str, n: usize) -> Result<Option<Sampled>, CliError> {
    let Some(spec) = read(path)? else { return Ok(None) };
    let b = build(path, &spec)?;
    let body_point = b.body_points.first().copied().unwrap_or([0.0; 3]);
    let one = Built { body_points: vec![body_point], ..b };
    let norm = |v: &[f64; 3]| v.iter().map(|x| x * x).sum::<f64>().sqrt();
    let samples = samples(&one, n)?
        .into_iter()
        .map(|s| Sample {
            t: s.t,
            linear_speed: norm(&s.points[0].velocity),
            angular_speed: norm(&s.space_twist.angular.to_array()),
            position: s.points[0].position,
            pose: s.pose,
        })
        .collect();
    Ok(Some(Sampled {
        kind: one.method.kind(),
        degree: 3,
        segments: one.trajectory.segments().len(),
        body_point,
        samples,
    }))
}
