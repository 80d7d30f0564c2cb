//! `gam pose [--json] POSE_JSON`: one pose in every representation of the Wave 2 contract
//! (shared/cli.md): matrix, position + quaternion, axis + angle, motor, dual quaternion
//! (Jüttler's eq. (12) action), hexanion (Angelidis, principal logarithm), screw and the
//! Wareham–Lasenby `cga_rotor` (`motion::wareham_lasenby::from_pose`, signed by
//! `motion::wareham_lasenby::convert::canonical_sign`).
//!
//! Also the two pose input forms of issue 10, `dual_quaternion` and `hexanion`, for the shared
//! pose parser of `gam interpolate` ([`extra_form`]).

use crate::error::CliError;
use crate::output::{mv_human, mv_json};
use crate::scalar::format_f64;
use motion::repr::dual_quaternion::{DualQuaternion, from_dual_quaternion, to_dual_quaternion};
use motion::repr::hexanion::Hexanion;
use motion::repr::quaternion::to_quaternion_position;
use motion::repr::screw::Screw;
use motion::repr::sign::canonical_pose;
use motion::wareham_lasenby::{convert::canonical_sign, from_pose as cga_rotor};
use motion::{Motor, Pose};
use serde_json::{Map, Value, json};

/// Plücker's relation (8) must hold to this, relative (the cosine between real and dual part).
const STUDY_TOL: f64 = 1e-9;

/// The `dual_quaternion` or `hexanion` form of a pose object at `at` (e.g. `poses[2]`);
/// `None` when the object has neither key. Errors are messages for an exit-2 `error:` line.
pub(crate) fn extra_form(obj: &Map<String, Value>, at: &str) -> Option<Result<Pose<f64>, String>> {
    let key = ["dual_quaternion", "hexanion"].into_iter().find(|k| obj.contains_key(*k))?;
    if let Some(other) = obj.keys().find(|k| *k != key) {
        return Some(Err(format!("`{at}`: unexpected key `{other}` (this pose form has [\"{key}\"])")));
    }
    let v = &obj[key];
    Some(if key == "dual_quaternion" { dual_quaternion(v, at) } else { hexanion(v, at) })
}

fn dual_quaternion(v: &Value, at: &str) -> Result<Pose<f64>, String> {
    let c: [f64; 8] = serde_json::from_value(v.clone())
        .map_err(|_| format!("`{at}.dual_quaternion` must be [w, x, y, z, dw, dx, dy, dz]"))?;
    from_dual_quaternion(&DualQuaternion::from_coeffs(c), &STUDY_TOL)
        .map_err(|e| format!("`{at}.dual_quaternion`: {e}"))
}

fn hexanion(v: &Value, at: &str) -> Result<Pose<f64>, String> {
    #[derive(serde::Deserialize)]
    #[serde(deny_unknown_fields)]
    struct H {
        omega: [f64; 3],
        m: [f64; 3],
    }
    let h: H = serde_json::from_value(v.clone())
        .map_err(|_| format!("`{at}.hexanion` must be {{\"omega\": [x, y, z], \"m\": [x, y, z]}}"))?;
    Hexanion::new(h.omega, h.m).to_pose().map_err(|e| format!("`{at}.hexanion`: {e}"))
}

/// `x + 0.0` prints -0.0 as 0.0.
fn z<const N: usize>(v: [f64; N]) -> [f64; N] {
    v.map(|x| x + 0.0)
}

fn motor_of(s: &Pose<f64>) -> Motor<f64> {
    let [a, b, c, d, e, f, g, h] = s.to_array();
    Motor::new(a, b, c, d, e, f, g, h)
}

/// Every representation of a (non-singular) pose, as the contract's JSON object.
fn representations(s: &Pose<f64>) -> Result<Value, CliError> {
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
    let value: Value = serde_json::from_str(&crate::hermite::strip_comments(&text))
        .map_err(|e| CliError::usage(format!("`{label}`: invalid JSON: {e}")))?;
    let s = crate::interpolate::pose_in(&label, "pose", &value)?;
    let out = representations(&s)?;
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
