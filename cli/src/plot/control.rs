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
use crate::budget::Tableau;
use crate::error::CliError;
use crate::interpolate::usage;
use motion::schema::ControlSpec;
use motion::{AdditiveBezier, MultiplicativeBezier, Piecewise};
use serde_json::Value;

/// The series of a control-data spec (see the module doc; the format and its checks are
/// `motion::schema::ControlSpec`).
pub(crate) fn series(path: &str, spec: &Value, name: &str, n: usize, k: usize) -> Result<Series, CliError> {
    let ControlSpec { segments, body_points } = ControlSpec::from_value(spec).map_err(|e| usage(path, e))?;
    let kind = segments[0].representation.clone();
    let mut breaks: Vec<f64> = segments.iter().map(|s| s.t0).collect();
    breaks.push(segments[segments.len() - 1].t1);
    let shape = Shape {
        label: format!("{name}: {kind}"),
        method: kind.clone(),
        segments: segments.len(),
        degree: segments.iter().map(|s| s.control_poses.len() - 1).max().unwrap_or(0),
        tableau: if kind == "multiplicative-bezier" { Tableau::Slerp } else { Tableau::Linear },
        key_times: breaks.clone(),
        joins: breaks[1..breaks.len() - 1].to_vec(),
    };
    let bad = |e: motion::CurveError| usage(path, format!("segments: {e}"));
    let controls = segments.into_iter().map(|s| s.control_poses);
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
