//! `gam pose [--json] POSE_JSON`: one pose in every representation of the Wave 2 contract
//! (shared/cli.md): matrix, position + quaternion, axis + angle, motor, dual quaternion
//! (Jüttler's eq. (12) action), hexanion (Angelidis, principal logarithm), screw and the
//! Wareham–Lasenby `cga_rotor` (`motion::wareham_lasenby::from_pose`, signed by
//! `motion::wareham_lasenby::convert::canonical_sign`).
//!
//! The pose object, every form of it and its checks are `motion::schema::PoseObject` (the
//! library owns the format); [`pose_json`] is the command on an already read pose object.

use crate::error::CliError;
use crate::output::{mv_human, mv_json};
use crate::scalar::format_f64;
use motion::repr::dual_quaternion::to_dual_quaternion;
use motion::repr::hexanion::Hexanion;
use motion::repr::quaternion::to_quaternion_position;
use motion::repr::screw::Screw;
use motion::repr::sign::canonical_pose;
use motion::schema::PoseObject;
use motion::wareham_lasenby::{convert::canonical_sign, from_pose as cga_rotor};
use motion::{Motor, Pose};
use serde_json::{Value, json};

/// `x + 0.0` prints -0.0 as 0.0.
fn z<const N: usize>(v: [f64; N]) -> [f64; N] {
    v.map(|x| x + 0.0)
}

fn motor_of(s: &Pose<f64>) -> Motor<f64> {
    let [a, b, c, d, e, f, g, h] = s.to_array();
    Motor::new(a, b, c, d, e, f, g, h)
}

/// Every representation of a (non-singular) pose, as the contract's JSON object.
pub(crate) fn representations(s: &Pose<f64>) -> Result<Value, CliError> {
    let math = |e: &dyn std::fmt::Display| CliError::math(e.to_string());
    let u = canonical_pose(&s.unitize().map_err(|e| math(&e))?);
    let matrix = u.to_matrix().map_err(|e| math(&e))?;
    let (q, position) = to_quaternion_position(&u).map_err(|e| math(&e))?;
    let v = [q[1], q[2], q[3]];
    // hypot: the squares of a tiny half-angle (1e-200) underflow
    let sin_half = v[0].hypot(v[1]).hypot(v[2]);
    let angle = 2.0 * sin_half.atan2(q[0]);
    let axis = if sin_half > 0.0 { v.map(|x| x / sin_half) } else { [0.0; 3] };
    let mut d = to_dual_quaternion(&u).map_err(|e| math(&e))?;
    let r = &d.real;
    if r.w * q[0] + r.x * q[1] + r.y * q[2] + r.z * q[3] < 0.0 {
        d = -d;
    }
    let h = Hexanion::from_pose(&u).map_err(|e| math(&e))?;
    let sc = Screw::of_hexanion(&h);
    let rotor = canonical_sign(cga_rotor(&u).map_err(|e| math(&e))?);
    let all = [matrix.iter().flatten().copied().collect(), position.to_vec(), d.coeffs().to_vec(), h.omega.to_vec()]
        .into_iter()
        .chain([h.m.to_vec(), sc.point.to_vec(), vec![sc.translation, sc.pitch.unwrap_or(0.0), angle]])
        .chain([rotor.iter().copied().collect()])
        .collect::<Vec<Vec<f64>>>();
    if !all.iter().flatten().all(|x| x.is_finite()) {
        return Err(CliError::math("the pose's representations overflow (a translation near the largest f64)"));
    }
    Ok(json!({
        "matrix": matrix.map(z),
        "position": z(position),
        "quaternion": z(q),
        "axis": z(axis),
        "angle": angle,
        "motor": mv_json(&motor_of(&u).to_multivector()),
        "dual_quaternion": z(d.coeffs()),
        "hexanion": {"omega": z(h.omega), "m": z(h.m)},
        "screw": {"axis": z(sc.axis), "angle": sc.angle, "translation": sc.translation + 0.0,
                  "point": z(sc.point), "pitch": sc.pitch.map(|p| p + 0.0)},
        "cga_rotor": mv_json(&rotor.to_multivector()),
    }))
}

/// The pose of a pose object (`label` names the document in messages).
fn the_pose(label: &str, object: &PoseObject) -> Result<Pose<f64>, CliError> {
    object.to_pose().map_err(|e| crate::interpolate::usage(label, e.at("pose")))
}

/// `gam pose --json` of a pose object (`label` names the document in messages): the pose in
/// every representation of the contract.
pub fn pose_json(label: &str, object: &PoseObject) -> Result<Value, CliError> {
    representations(&the_pose(label, object)?)
}

fn list(v: &[f64]) -> String {
    format!("[{}]", v.iter().map(|x| format_f64(*x)).collect::<Vec<_>>().join(", "))
}

/// Runs `gam pose`: `arg` is a pose object, or `@FILE` holding one.
pub fn pose(arg: &str, json: bool) -> Result<String, CliError> {
    let (label, text) = match arg.strip_prefix('@') {
        Some(file) => (
            file.to_string(),
            std::fs::read_to_string(file).map_err(|e| CliError::usage(format!("cannot read `{file}`: {e}")))?,
        ),
        None => ("POSE_JSON".to_string(), arg.to_string()),
    };
    let object = PoseObject::from_json(&crate::hermite::strip_comments(&text), "pose")
        .map_err(|e| crate::interpolate::usage(&label, e))?;
    let out = pose_json(&label, &object)?;
    let s = the_pose(&label, &object)?;
    if json {
        return Ok(out.to_string());
    }
    let nums =
        |k: &str| out[k].as_array().map(|a| a.iter().filter_map(Value::as_f64).collect::<Vec<_>>()).unwrap_or_default();
    let m = out["matrix"].as_array().cloned().unwrap_or_default();
    let rows: Vec<String> = m
        .iter()
        .map(|r| {
            list(&r.as_array().map(|a| a.iter().filter_map(Value::as_f64).collect::<Vec<_>>()).unwrap_or_default())
        })
        .collect();
    let sc = &out["screw"];
    let f = |v: &Value| v.as_f64().map(format_f64).unwrap_or_else(|| "none".into());
    let sub = |v: &Value| {
        list(&v.as_array().map(|a| a.iter().filter_map(Value::as_f64).collect::<Vec<_>>()).unwrap_or_default())
    };
    Ok([
        format!("matrix: [{}]", rows.join(", ")),
        format!("position: {}", list(&nums("position"))),
        format!("quaternion: {}", list(&nums("quaternion"))),
        format!("axis: {}, angle: {}", list(&nums("axis")), f(&out["angle"])),
        format!(
            "motor: {}",
            mv_human(
                &motor_of(&canonical_pose(&s.unitize().map_err(|e| CliError::math(e.to_string()))?)).to_multivector()
            )
        ),
        format!("dual_quaternion: {}", list(&nums("dual_quaternion"))),
        format!("hexanion: omega {}, m {}", sub(&out["hexanion"]["omega"]), sub(&out["hexanion"]["m"])),
        format!(
            "screw: axis {}, angle {}, translation {}, point {}, pitch {}",
            sub(&sc["axis"]),
            f(&sc["angle"]),
            f(&sc["translation"]),
            sub(&sc["point"]),
            f(&sc["pitch"])
        ),
        format!(
            "cga_rotor: {}",
            mv_human(
                &canonical_sign(
                    cga_rotor(&s.unitize().map_err(|e| CliError::math(e.to_string()))?)
                        .map_err(|e| CliError::math(e.to_string()))?
                )
                .to_multivector()
            )
        ),
    ]
    .join("\n"))
}
