//! `gam plot` from explicit control data: a JSON object with a `segments` list in the form
//! `gam interpolate --json` prints (`t0`, `t1`, `representation`, `control_poses`), so the
//! output of `gam interpolate --json` (or hand-written control poses) can be drawn directly:
//!
//! ```json
//! {"segments": [{"t0": 0, "t1": 1, "representation": "additive-bezier",
//!                "control_poses": [{"1": 1}, {"1": 1, "e1inf": -0.5}]}],
//!  "body_points": [[0, 0, 0]]}
//! ```
//!
//! Every segment must have the same representation: `additive-bezier` or
//! `dual-quaternion-bezier` (a Q-motion is the additive Bézier motion of its control motors)
//! or `multiplicative-bezier`. Segments whose control data are key poses (Wareham–Lasenby,
//! hexanion) cannot be redrawn from them: plot their `gam interpolate` spec instead.

use super::data::{Series, Shape, of_motion};
use crate::error::CliError;
use crate::interpolate::usage;
use motion::schema::PoseObject;
use motion::{AdditiveBezier, MultiplicativeBezier, Piecewise, Pose};
use serde_json::{Value, json};

/// One segment of the control-data form.
struct Segment {
    t0: f64,
    t1: f64,
    representation: String,
    control: Vec<Pose<f64>>,
}

fn segment(path: &str, i: usize, v: &Value) -> Result<Segment, CliError> {
    let at = |key: &str| format!("segments[{i}].{key}");
    let number = |key: &str| {
        v.get(key)
            .and_then(Value::as_f64)
            .filter(|x| x.is_finite())
            .ok_or_else(|| usage(path, format!("`{}` must be a finite number", at(key))))
    };
    let representation = v
        .get("representation")
        .and_then(Value::as_str)
        .ok_or_else(|| usage(path, format!("`{}` must be a string", at("representation"))))?
        .to_string();
    let poses = v
        .get("control_poses")
        .and_then(Value::as_array)
        .filter(|a| !a.is_empty())
        .ok_or_else(|| usage(path, format!("`{}` must be a non-empty list of motors", at("control_poses"))))?;
    let control = poses
        .iter()
        .enumerate()
        .map(|(j, mv)| {
            let at = format!("segments[{i}].control_poses[{j}]");
            PoseObject::from_value(&json!({ "motor": mv }))
                .and_then(|p| p.to_pose())
                .map_err(|e| usage(path, e.at(&at)))
        })
        .collect::<Result<Vec<_>, _>>()?;
    Ok(Segment { t0: number("t0")?, t1: number("t1")?, representation, control })
}

/// The series of a control-data spec (see the module doc).
pub(crate) fn series(path: &str, spec: &Value, name: &str, n: usize, k: usize) -> Result<Series, CliError> {
    let list = spec
        .get("segments")
        .and_then(Value::as_array)
        .filter(|a| !a.is_empty())
        .ok_or_else(|| usage(path, "`segments` must be a non-empty list"))?;
    let segments = list.iter().enumerate().map(|(i, v)| segment(path, i, v)).collect::<Result<Vec<_>, _>>()?;
    let kind = segments[0].representation.clone();
    if let Some((i, s)) = segments.iter().enumerate().find(|(_, s)| s.representation != kind) {
        return Err(usage(
            path,
            format!(
                "`segments[{i}].representation` is `{}`, but segment 0's is `{kind}`: one kind per plot",
                s.representation
            ),
        ));
    }
    for (i, pair) in segments.windows(2).enumerate() {
        if pair[0].t1 != pair[1].t0 {
            return Err(usage(path, format!("`segments[{}].t0` must equal `segments[{i}].t1` (no gaps)", i + 1)));
        }
    }
    let body_points: Vec<[f64; 3]> = match spec.get("body_points") {
        Some(v) => {
            serde_json::from_value(v.clone()).map_err(|_| usage(path, "`body_points` must be a list of [x, y, z]"))?
        }
        None => vec![[0.0; 3]],
    };
    let mut breaks: Vec<f64> = segments.iter().map(|s| s.t0).collect();
    breaks.push(segments[segments.len() - 1].t1);
    let shape = Shape {
        label: format!("{name}: {kind}"),
        method: kind.clone(),
        segments: segments.len(),
        degree: segments.iter().map(|s| s.control.len() - 1).max().unwrap_or(0),
        key_times: breaks.clone(),
        joins: breaks[1..breaks.len() - 1].to_vec(),
    };
    let bad = |e: motion::CurveError| usage(path, format!("segments: {e}"));
    let controls = segments.into_iter().map(|s| s.control);
    match kind.as_str() {
        "additive-bezier" | "dual-quaternion-bezier" => {
            let parts = controls.map(|c| AdditiveBezier::new(c).map_err(bad)).collect::<Result<Vec<_>, _>>()?;
            of_motion(shape, &Piecewise::new(breaks, parts).map_err(bad)?, body_points, n, k)
        }
        "multiplicative-bezier" => {
            let parts = controls.map(|c| MultiplicativeBezier::new(c).map_err(bad)).collect::<Result<Vec<_>, _>>()?;
            of_motion(shape, &Piecewise::new(breaks, parts).map_err(bad)?, body_points, n, k)
        }
        other => Err(usage(
            path,
            format!(
                "representation `{other}` cannot be drawn from control data (additive-bezier, dual-quaternion-bezier or multiplicative-bezier); plot its `gam interpolate` spec instead"
            ),
        )),
    }
}
