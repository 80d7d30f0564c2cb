//! `gam pose [--json] POSE_JSON`: one pose in every representation of the Wave 2 contract
//! (shared/cli.md): matrix, position + quaternion, axis + angle, motor, dual quaternion
//! (Jüttler's eq. (12) action), hexanion (Angelidis, principal logarithm), screw and the
//! Wareham–Lasenby `cga_rotor` (`motion::wareham_lasenby::from_pose`, signed by
//! `motion::wareham_lasenby::convert::canonical_sign`).
//!
//! The pose object, every form of it and its checks are `motion::schema::PoseObject` (the
//! library owns the format); [`pose_json`] is the command on an already read pose object.
//!
//! `--scalar mpfr:BITS` computes every representation at that precision (the object's numbers
//! read exactly, rounded once); `--scalar rational` reads them exactly and prints the
//! representations that are rational for every rational pose: `matrix` and `position` (the
//! others need square roots or transcendental functions: docs/cli.md).

use crate::error::CliError;
use crate::output::{mv_human, mv_json};
use crate::precision::{MotionScalar, OutScalar, json_list};
use crate::scalar::CliScalar;
use algebra_core::{MpFloat, Multivector, Real, Ring};
use motion::repr::dual_quaternion::to_dual_quaternion;
use motion::repr::hexanion::Hexanion;
use motion::repr::quaternion::to_quaternion_position;
use motion::repr::screw::Screw;
use motion::repr::sign::canonical_pose;
use motion::schema::{Exact, PoseObject};
use motion::wareham_lasenby::{convert::canonical_sign, from_pose as cga_rotor};
use motion::{Motor, Pose};
use serde_json::{Value, json};

fn motor_of<T: Ring>(s: &Pose<T>) -> Motor<T> {
    let [a, b, c, d, e, f, g, h] = s.to_array();
    Motor::new(a, b, c, d, e, f, g, h)
}

/// `|v|` without overflow or underflow of the squares (a tiny half-angle of 1e-200).
fn norm3<T: Real>(v: &[T; 3]) -> T {
    let m = v.iter().map(Real::abs).fold(T::zero(), |a, x| if x > a { x } else { a });
    if m.is_exact_zero() {
        return m;
    }
    let sum = v.iter().fold(T::zero(), |acc, x| {
        let y = x.div_ref(&m);
        acc.add_ref(&y.mul_ref(&y))
    });
    m.mul_ref(&Real::sqrt(&sum))
}

/// Every representation of a pose in one scalar: the fields of the contract's JSON object
/// (`None` where the scalar cannot hold them: the irrational ones under `rational`).
struct Representations<T> {
    matrix: [[T; 4]; 4],
    position: [T; 3],
    /// quaternion, axis, angle, motor, dual quaternion, hexanion, screw, cga rotor
    rest: Option<Rest<T>>,
}

struct Rest<T> {
    quaternion: [T; 4],
    axis: [T; 3],
    angle: T,
    motor: Multivector<T>,
    dual_quaternion: [T; 8],
    hexanion: Hexanion<T>,
    screw: Screw<T>,
    cga_rotor: Multivector<T>,
}

/// Every representation of a (non-singular) pose over a real scalar.
fn real_representations<T: Real + OutScalar>(s: &Pose<T>) -> Result<Representations<T>, CliError> {
    let math = |e: &dyn std::fmt::Display| CliError::math(e.to_string());
    let u = canonical_pose(&s.unitize().map_err(|e| math(&e))?);
    let matrix = u.to_matrix().map_err(|e| math(&e))?;
    let (q, position) = to_quaternion_position(&u).map_err(|e| math(&e))?;
    let v = [q[1].clone(), q[2].clone(), q[3].clone()];
    let sin_half = norm3(&v);
    let angle = T::from_i64(2).mul_ref(&sin_half.atan2(&q[0]));
    let axis = if sin_half > T::zero() { v.map(|x| x.div_ref(&sin_half)) } else { [T::zero(), T::zero(), T::zero()] };
    let mut d = to_dual_quaternion(&u).map_err(|e| math(&e))?;
    let r = &d.real;
    let dot = r.w.mul_ref(&q[0]).add_ref(&r.x.mul_ref(&q[1])).add_ref(&r.y.mul_ref(&q[2])).add_ref(&r.z.mul_ref(&q[3]));
    if dot < T::zero() {
        d = -d;
    }
    let hexanion = Hexanion::from_pose(&u).map_err(|e| math(&e))?;
    let screw = Screw::of_hexanion(&hexanion);
    let rotor = canonical_sign(cga_rotor(&u).map_err(|e| math(&e))?);
    let reps = Representations {
        matrix,
        position,
        rest: Some(Rest {
            quaternion: q,
            axis,
            angle,
            motor: motor_of(&u).to_multivector(),
            dual_quaternion: d.coeffs(),
            hexanion,
            screw,
            cga_rotor: rotor.to_multivector(),
        }),
    };
    if !reps.numbers().iter().all(|x| CliScalar::finite(*x)) {
        return Err(CliError::math("the pose's representations overflow (a translation near the largest f64)"));
    }
    Ok(reps)
}

impl<T: OutScalar> Representations<T> {
    /// Every number (for the finiteness check).
    fn numbers(&self) -> Vec<&T> {
        let mut all: Vec<&T> = self.matrix.iter().flatten().chain(&self.position).collect();
        if let Some(r) = &self.rest {
            let sc = &r.screw;
            all.extend(r.quaternion.iter().chain(&r.axis).chain([&r.angle]).chain(&r.dual_quaternion));
            all.extend(r.hexanion.omega.iter().chain(&r.hexanion.m).chain(&sc.axis).chain(&sc.point));
            all.extend([&sc.angle, &sc.translation].into_iter().chain(sc.pitch.as_ref()));
            all.extend(r.cga_rotor.coeffs());
        }
        all
    }

    /// The contract's JSON object.
    fn json(&self) -> Value {
        let mut out = json!({"matrix": self.matrix.iter().map(|r| json_list(r)).collect::<Vec<_>>(),
            "position": json_list(&self.position)});
        if let Some(r) = &self.rest {
            let sc = &r.screw;
            let more = json!({
                "quaternion": json_list(&r.quaternion),
                "axis": json_list(&r.axis),
                "angle": r.angle.json(),
                "motor": mv_json(&r.motor),
                "dual_quaternion": json_list(&r.dual_quaternion),
                "hexanion": {"omega": json_list(&r.hexanion.omega), "m": json_list(&r.hexanion.m)},
                "screw": {"axis": json_list(&sc.axis), "angle": sc.angle.json(), "translation": sc.translation.json(),
                          "point": json_list(&sc.point), "pitch": sc.pitch.as_ref().map(OutScalar::json)},
                "cga_rotor": mv_json(&r.cga_rotor),
            });
            if let (Some(o), Value::Object(m)) = (out.as_object_mut(), more) {
                o.extend(m);
            }
        }
        out
    }

    /// The human form, one representation per line.
    fn text(&self) -> String {
        let list = |v: &[T]| format!("[{}]", v.iter().map(OutScalar::text).collect::<Vec<_>>().join(", "));
        let rows: Vec<String> = self.matrix.iter().map(|r| list(r)).collect();
        let mut lines = vec![format!("matrix: [{}]", rows.join(", ")), format!("position: {}", list(&self.position))];
        if let Some(r) = &self.rest {
            let sc = &r.screw;
            let pitch = sc.pitch.as_ref().map_or_else(|| "none".to_string(), OutScalar::text);
            lines.extend([
                format!("quaternion: {}", list(&r.quaternion)),
                format!("axis: {}, angle: {}", list(&r.axis), r.angle.text()),
                format!("motor: {}", mv_human(&r.motor)),
                format!("dual_quaternion: {}", list(&r.dual_quaternion)),
                format!("hexanion: omega {}, m {}", list(&r.hexanion.omega), list(&r.hexanion.m)),
                format!(
                    "screw: axis {}, angle {}, translation {}, point {}, pitch {pitch}",
                    list(&sc.axis),
                    sc.angle.text(),
                    sc.translation.text(),
                    list(&sc.point)
                ),
                format!("cga_rotor: {}", mv_human(&r.cga_rotor)),
            ]);
        }
        lines.join("\n")
    }
}

/// Every representation of a (non-singular) pose, as the contract's JSON object.
pub(crate) fn representations(s: &Pose<f64>) -> Result<Value, CliError> {
    Ok(real_representations(s)?.json())
}

/// The pose of a pose object (`label` names the document in messages).
fn the_pose<T: Real>(label: &str, object: &PoseObject<T>) -> Result<Pose<T>, CliError> {
    object.to_pose().map_err(|e| crate::interpolate::usage(label, e.at("pose")))
}

/// `gam pose --json` of a pose object (`label` names the document in messages): the pose in
/// every representation of the contract.
pub fn pose_json(label: &str, object: &PoseObject) -> Result<Value, CliError> {
    representations(&the_pose(label, object)?)
}

/// The representations of an exact pose that are rational: the rigid matrix and the position.
fn exact_representations(
    label: &str,
    object: &PoseObject<Exact>,
) -> Result<Representations<algebra_core::rational::Q>, CliError> {
    let s = object.to_pose_exact().map_err(|e| crate::interpolate::usage(label, e.at("pose")))?;
    let matrix = s.to_matrix().map_err(|e| CliError::math(e.to_string()))?;
    let position = [matrix[0][3].clone(), matrix[1][3].clone(), matrix[2][3].clone()];
    Ok(Representations { matrix, position, rest: None })
}

/// Runs `gam pose`: `arg` is a pose object, or `@FILE` holding one; in the scalar of `--scalar`.
pub fn pose(arg: &str, json: bool, scalar: MotionScalar) -> Result<String, CliError> {
    let (label, text) = match arg.strip_prefix('@') {
        Some(file) => (
            file.to_string(),
            std::fs::read_to_string(file).map_err(|e| CliError::usage(format!("cannot read `{file}`: {e}")))?,
        ),
        None => ("POSE_JSON".to_string(), arg.to_string()),
    };
    let (value, text) = pose_in(&label, &text, scalar)?;
    Ok(if json { value.to_string() } else { text })
}

/// `gam pose` of the pose object text `text` (named `label` in messages) in `scalar`: the JSON
/// object and the human form.
pub(crate) fn pose_in(label: &str, text: &str, scalar: MotionScalar) -> Result<(Value, String), CliError> {
    let text = crate::hermite::strip_comments(text);
    match scalar {
        MotionScalar::F64 => {
            let object = PoseObject::from_json(&text, "pose").map_err(|e| crate::interpolate::usage(label, e))?;
            let r = real_representations(&the_pose(label, &object)?)?;
            Ok((r.json(), r.text()))
        }
        MotionScalar::Rational => {
            let r = exact_representations(label, &exact_object(label, &text)?)?;
            Ok((r.json(), r.text()))
        }
        MotionScalar::Mpfr(_) => scalar.run(|| {
            let object = exact_object(label, &text)?.map(&|x| MpFloat::from_rational(&x.0));
            let r = real_representations(&the_pose(label, &object)?)?;
            Ok((r.json(), r.text()))
        }),
    }
}

/// A pose object read with every literal exact.
fn exact_object(label: &str, text: &str) -> Result<PoseObject<Exact>, CliError> {
    PoseObject::<Exact>::read_json(text, "pose").map_err(|e| crate::interpolate::usage(label, e))
}
