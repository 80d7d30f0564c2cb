//! Explicit control data (what `gam plot` draws without a method): a `segments` list in the form
//! `gam interpolate --json` prints it, so that output (or hand-written control poses) can be
//! read back as [`ControlSpec`].
//!
//! ```json
//! {"segments": [{"t0": 0, "t1": 1, "representation": "additive-bezier",
//!                "control_poses": [{"1": 1}, {"1": 1, "e1inf": -0.5}]}],
//!  "body_points": [[0, 0, 0]]}
//! ```
//!
//! Keys other than these are ignored (the output of `gam interpolate --json` has `method`,
//! `samples`, `degree`, `dual_quaternions`, ...). Every segment has the same representation and
//! each starts where the previous one ends.
//!
//! ```
//! let spec = motion::schema::ControlSpec::from_value(&serde_json::json!({"segments": [
//!     {"t0": 0, "t1": 1, "representation": "additive-bezier", "control_poses": [{"1": 1}, {"1": 1, "e1inf": -0.5}]}]}))?;
//! assert_eq!(spec.segments[0].control_poses[1].transform_point(&[0.0; 3])?, [-1.0, 0.0, 0.0]);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use super::{PoseObject, SchemaError};
use crate::Pose;
use serde::Deserialize;
use serde_json::{Value, json};

/// One segment of control data.
#[derive(Debug, Clone, PartialEq)]
pub struct ControlSegment {
    /// Where the segment starts.
    pub t0: f64,
    /// Where it ends.
    pub t1: f64,
    /// What the control poses mean (`additive-bezier`, `multiplicative-bezier`, ...).
    pub representation: String,
    /// The control poses (motors; at least one, none singular).
    pub control_poses: Vec<Pose<f64>>,
}

/// Control data read and checked (see the module doc).
///
/// ```
/// use motion::schema::{ControlSpec, SchemaError};
/// let seg = |t0: f64, t1: f64| serde_json::json!({"t0": t0, "t1": t1, "representation": "additive-bezier", "control_poses": [{"1": 1}]});
/// let e = ControlSpec::from_value(&serde_json::json!({"segments": [seg(0.0, 1.0), seg(1.5, 2.0)]})).unwrap_err();
/// assert_eq!(e, SchemaError::Gap { segment: 1 });
/// assert_eq!(e.to_string(), "`segments[1].t0` must equal `segments[0].t1` (no gaps)");
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct ControlSpec {
    /// The segments (at least one).
    pub segments: Vec<ControlSegment>,
    /// The body points (`[[0, 0, 0]]` when left out).
    pub body_points: Vec<[f64; 3]>,
}

impl ControlSpec {
    /// Reads control data from a JSON value, with every check of the format.
    pub fn from_value(v: &Value) -> Result<Self, SchemaError> {
        let list = v
            .get("segments")
            .and_then(Value::as_array)
            .filter(|a| !a.is_empty())
            .ok_or(SchemaError::Field { at: "segments".into(), expected: "a non-empty list" })?;
        let segments = list.iter().enumerate().map(|(i, v)| segment(i, v)).collect::<Result<Vec<_>, _>>()?;
        let kind = &segments[0].representation;
        if let Some((i, s)) = segments.iter().enumerate().find(|(_, s)| s.representation != *kind) {
            return Err(SchemaError::MixedRepresentation {
                segment: i,
                got: s.representation.clone(),
                first: kind.clone(),
            });
        }
        if let Some(i) = segments.windows(2).position(|pair| pair[0].t1 != pair[1].t0) {
            return Err(SchemaError::Gap { segment: i + 1 });
        }
        let body_points = match v.get("body_points") {
            Some(b) => Vec::<[f64; 3]>::deserialize(b)
                .map_err(|_| SchemaError::Field { at: "body_points".into(), expected: "a list of [x, y, z]" })?,
            None => vec![[0.0; 3]],
        };
        Ok(ControlSpec { segments, body_points })
    }
}

/// Segment `i` of the `segments` list.
fn segment(i: usize, v: &Value) -> Result<ControlSegment, SchemaError> {
    let field = |key: &str, expected| SchemaError::Field { at: format!("segments[{i}].{key}"), expected };
    let representation =
        v.get("representation").and_then(Value::as_str).ok_or(field("representation", "a string"))?.to_string();
    let poses = v
        .get("control_poses")
        .and_then(Value::as_array)
        .filter(|a| !a.is_empty())
        .ok_or(field("control_poses", "a non-empty list of motors"))?;
    let control_poses = poses
        .iter()
        .enumerate()
        .map(|(j, mv)| {
            PoseObject::from_value(&json!({ "motor": mv }))
                .and_then(|p| p.to_pose())
                .map_err(|e| e.at(&format!("segments[{i}].control_poses[{j}]")))
        })
        .collect::<Result<Vec<_>, _>>()?;
    let number =
        |key: &str| v.get(key).and_then(Value::as_f64).filter(|x| x.is_finite()).ok_or(field(key, "a finite number"));
    Ok(ControlSegment { t0: number("t0")?, t1: number("t1")?, representation, control_poses })
}
