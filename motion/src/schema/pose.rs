//! Pose objects: every JSON form of a pose in the CLI contract ("Pose objects"), read into a
//! [`PoseObject`] and turned into a [`Pose<f64>`] by one function, [`PoseObject::to_pose`].
//!
//! | form | JSON | pose |
//! |---|---|---|
//! | [`PoseObject::Translation`] | `{"position": [x, y, z]}` | `T = 1 + ½ t einf` |
//! | [`PoseObject::AxisAngle`] | `{"position": .., "axis": [a, b, c], "angle": φ}` | rotate by φ about the (normalised) axis through the origin, then translate |
//! | [`PoseObject::Quaternion`] | `{"position": .., "quaternion": [w, x, y, z]}` | the rotation of the (normalised, non-zero) quaternion, then translate |
//! | [`PoseObject::Matrix`] | `{"matrix": [[..4..] x 4]}` | a rigid 4x4 homogeneous matrix (orthonormal to 1e-9 relative) |
//! | [`PoseObject::Motor`] | `{"motor": {"1": .., "e12": .., ...}}` | the main paper's `S` in g123inf blade names (numbers or decimal strings; non-singular) |
//! | [`PoseObject::DualQuaternion`] | `{"dual_quaternion": [w, x, y, z, dw, dx, dy, dz]}` | Jüttler's eq. (12) action (non-zero real part, Plücker's (8) to 1e-9 relative) |
//! | [`PoseObject::Hexanion`] | `{"hexanion": {"omega": [..], "m": [..]}}` | Angelidis' `exp((ω, m))`, eqs. (4)/(14) |
//!
//! `position` may be left out (the origin); a form's keys may not be mixed with another's, and
//! no key may be given twice.
//!
//! ```
//! use motion::schema::PoseObject;
//! let p: PoseObject = serde_json::from_str(r#"{"axis": [0, 0, 2], "angle": 1.5707963267948966}"#)?;
//! let q = p.to_pose()?.transform_point(&[1.0, 0.0, 0.0])?;
//! assert!((q[0]).abs() < 1e-15 && (q[1] - 1.0).abs() < 1e-15);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use super::{SchemaError, StrictValue};
use crate::paper::BLADES;
use crate::repr::ReprError;
use crate::repr::dual_quaternion::{DualQuaternion, from_dual_quaternion};
use crate::repr::hexanion::Hexanion;
use crate::{MotionError, Pose};
use serde::{Deserialize, Serialize};
use serde_json::{Map, Value, json};

/// Plücker's relation (8) of a `dual_quaternion` must hold to this, relative (the cosine
/// between the real and the dual part).
pub const STUDY_TOL: f64 = 1e-9;

/// The upper-left block of a `matrix` must be orthonormal to this, relative.
pub const MATRIX_TOL: f64 = 1e-9;

/// One pose object as written: its form and its numbers (checked for shape, not yet for being
/// a pose: that is [`PoseObject::to_pose`]).
///
/// ```
/// use motion::schema::PoseObject;
/// let p = PoseObject::from_json(r#"{"quaternion": [0, 0, 0, 2], "position": [1, 0, 0]}"#, "pose")?;
/// assert_eq!(p, PoseObject::Quaternion { position: [1.0, 0.0, 0.0], quaternion: [0.0, 0.0, 0.0, 2.0] });
/// # Ok::<(), motion::schema::SchemaError>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub enum PoseObject {
    /// `{"position": [x, y, z]}`: a pure translation.
    Translation {
        /// The translation.
        position: [f64; 3],
    },
    /// `{"position": [x, y, z], "axis": [a, b, c], "angle": φ}`.
    AxisAngle {
        /// The translation applied after the rotation.
        position: [f64; 3],
        /// The rotation axis (normalised; not zero, except `[0, 0, 0]` with angle 0: the
        /// identity rotation, as `gam pose` prints it).
        axis: [f64; 3],
        /// The angle in radians, right-handed.
        angle: f64,
    },
    /// `{"position": [x, y, z], "quaternion": [w, x, y, z]}`.
    Quaternion {
        /// The translation applied after the rotation.
        position: [f64; 3],
        /// `[w, x, y, z]`, non-zero (normalised).
        quaternion: [f64; 4],
    },
    /// `{"matrix": [[..], [..], [..], [0, 0, 0, 1]]}`: rows of a rigid homogeneous matrix.
    Matrix([[f64; 4]; 4]),
    /// `{"motor": MV}`: the coefficients of `S` in the order of [`BLADES`]
    /// (`1, e12, e13, e23, e1inf, e2inf, e3inf, e123inf`).
    Motor([f64; 8]),
    /// `{"dual_quaternion": [w, x, y, z, dw, dx, dy, dz]}`.
    DualQuaternion([f64; 8]),
    /// `{"hexanion": {"omega": [..], "m": [..]}}`.
    Hexanion {
        /// Angelidis' ω.
        omega: [f64; 3],
        /// Angelidis' m.
        m: [f64; 3],
    },
}

/// Why a JSON value is not a pose object, or a pose object not a pose. The message names the
/// key it is about; [`PoseError::at`] places it in a document.
///
/// ```
/// use motion::schema::{PoseError, PoseObject};
/// let e = PoseObject::Motor([0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0]).to_pose().unwrap_err();
/// assert_eq!(e, PoseError::SingularMotor);
/// assert_eq!(e.at("poses[3]").to_string(), "`poses[3].motor` is singular (rev(S) S has zero scalar part)");
/// ```
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum PoseError {
    /// Not a JSON object.
    #[error("must be a pose object")]
    NotAnObject,
    /// A key that does not belong to the form (the form is told by its keys).
    #[error("unexpected key `{key}` (this pose form has {allowed:?})")]
    UnexpectedKey {
        /// The key.
        key: String,
        /// The keys of the form.
        allowed: &'static [&'static str],
    },
    /// A value of the wrong shape.
    #[error("must be {expected}")]
    Shape {
        /// The key (`matrix`, `motor.e12`, ...).
        key: String,
        /// What it must be (`4 rows of 4 numbers`, ...).
        expected: &'static str,
    },
    /// A `motor` key that is not a blade of g123inf^+.
    #[error("`{blade}` is not a blade of g123inf^+")]
    NotABlade {
        /// The key given.
        blade: String,
    },
    /// `axis` without `angle` or the other way round.
    #[error("`axis` and `angle` go together")]
    AxisWithoutAngle,
    /// A singular `motor` (`rev(S) S` has zero scalar part: no rigid motion).
    #[error("is singular (rev(S) S has zero scalar part)")]
    SingularMotor,
    /// A zero or non-finite `quaternion`.
    #[error("must be non-zero and finite")]
    ZeroQuaternion,
    /// The `axis`/`angle` rotation failed (a zero axis, ...).
    #[error(transparent)]
    Axis(MotionError),
    /// The `matrix` is not a rigid-body transform.
    #[error(transparent)]
    Matrix(MotionError),
    /// The `dual_quaternion` is no pose (zero real part, off the Study quadric).
    #[error(transparent)]
    DualQuaternion(ReprError),
    /// The `hexanion`'s exponential failed.
    #[error(transparent)]
    Hexanion(MotionError),
}

impl PoseError {
    /// The key of the pose object the error is about (`None`: the object itself).
    fn key(&self) -> Option<&str> {
        match self {
            PoseError::NotAnObject | PoseError::UnexpectedKey { .. } | PoseError::AxisWithoutAngle => None,
            PoseError::Matrix(_) => None,
            PoseError::Shape { key, .. } => Some(key),
            PoseError::NotABlade { .. } | PoseError::SingularMotor => Some("motor"),
            PoseError::ZeroQuaternion => Some("quaternion"),
            PoseError::Axis(_) => Some("axis"),
            PoseError::DualQuaternion(_) => Some("dual_quaternion"),
            PoseError::Hexanion(_) => Some("hexanion"),
        }
    }

    /// The message at the place `at` of a document (`pose`, `poses[2]`): `` `poses[2].axis`: ...``.
    pub(super) fn message_at(&self, at: &str) -> String {
        let place = match self.key() {
            Some(key) => format!("{at}.{key}"),
            None => at.to_string(),
        };
        let predicate = matches!(
            self,
            PoseError::NotAnObject | PoseError::Shape { .. } | PoseError::SingularMotor | PoseError::ZeroQuaternion
        );
        if predicate { format!("`{place}` {self}") } else { format!("`{place}`: {self}") }
    }

    /// This error at the place `at` of a document.
    ///
    /// ```
    /// use motion::schema::PoseError;
    /// assert_eq!(PoseError::NotAnObject.at("poses[0]").to_string(), "`poses[0]` must be a pose object");
    /// ```
    pub fn at(self, at: &str) -> SchemaError {
        SchemaError::Pose { at: at.to_string(), source: self }
    }
}

/// `T` read from `v`, or [`PoseError::Shape`] for `key`.
fn field<T: for<'de> Deserialize<'de>>(v: &Value, key: &str, expected: &'static str) -> Result<T, PoseError> {
    T::deserialize(v).map_err(|_| PoseError::Shape { key: key.to_string(), expected })
}

const POSITION: &str = "a list of 3 numbers";

/// The keys of each form, in the order the form is recognised: the first form one of whose
/// marker keys is present is the form (none: position, axis, angle).
const FORMS: [(&str, &[&str]); 5] = [
    ("dual_quaternion", &["dual_quaternion"]),
    ("hexanion", &["hexanion"]),
    ("motor", &["motor"]),
    ("matrix", &["matrix"]),
    ("quaternion", &["position", "quaternion"]),
];

impl PoseObject {
    /// The pose object of a JSON value (shape checks only; see [`PoseObject::to_pose`]).
    ///
    /// ```
    /// use motion::schema::{PoseError, PoseObject};
    /// let v = serde_json::json!({"motor": {"1": "0.8", "e12": 0.6}});
    /// assert_eq!(PoseObject::from_value(&v)?, PoseObject::Motor([0.8, 0.6, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0]));
    /// let bad = serde_json::json!({"position": [0, 0, 0], "angel": 1});
    /// assert!(matches!(PoseObject::from_value(&bad), Err(PoseError::UnexpectedKey { .. })));
    /// # Ok::<(), PoseError>(())
    /// ```
    pub fn from_value(v: &Value) -> Result<Self, PoseError> {
        let obj = v.as_object().ok_or(PoseError::NotAnObject)?;
        let (marker, allowed) = FORMS
            .iter()
            .find(|(marker, _)| obj.contains_key(*marker))
            .copied()
            .unwrap_or(("axis", &["position", "axis", "angle"]));
        if let Some(key) = obj.keys().find(|k| !allowed.contains(&k.as_str())) {
            return Err(PoseError::UnexpectedKey { key: key.clone(), allowed });
        }
        let position = || obj.get("position").map_or(Ok([0.0; 3]), |p| field(p, "position", POSITION));
        Ok(match marker {
            "dual_quaternion" => {
                PoseObject::DualQuaternion(field(&obj[marker], marker, "[w, x, y, z, dw, dx, dy, dz]")?)
            }
            "hexanion" => {
                #[derive(Deserialize)]
                #[serde(deny_unknown_fields)]
                struct H {
                    omega: [f64; 3],
                    m: [f64; 3],
                }
                let h: H = field(&obj[marker], marker, "{\"omega\": [x, y, z], \"m\": [x, y, z]}")?;
                PoseObject::Hexanion { omega: h.omega, m: h.m }
            }
            "motor" => PoseObject::Motor(motor(&obj[marker])?),
            "matrix" => PoseObject::Matrix(field(&obj[marker], marker, "4 rows of 4 numbers")?),
            "quaternion" => {
                let position = position()?;
                PoseObject::Quaternion { position, quaternion: field(&obj[marker], marker, "[w, x, y, z]")? }
            }
            _ => {
                let position = position()?;
                match (obj.get("axis"), obj.get("angle")) {
                    (None, None) => PoseObject::Translation { position },
                    (Some(axis), Some(angle)) => PoseObject::AxisAngle {
                        position,
                        axis: field(axis, "axis", POSITION)?,
                        angle: angle.as_f64().ok_or(PoseError::Shape { key: "angle".into(), expected: "a number" })?,
                    },
                    _ => return Err(PoseError::AxisWithoutAngle),
                }
            }
        })
    }

    /// The pose object of a JSON text (`at` names it in messages): a syntax error, a key given
    /// twice, or a bad form or shape is a [`SchemaError`].
    ///
    /// ```
    /// use motion::schema::PoseObject;
    /// let e = PoseObject::from_json(r#"{"matrix": [[1, 0, 0]]}"#, "poses[0]").unwrap_err();
    /// assert_eq!(e.to_string(), "`poses[0].matrix` must be 4 rows of 4 numbers");
    /// ```
    pub fn from_json(text: &str, at: &str) -> Result<Self, SchemaError> {
        let v: StrictValue = serde_json::from_str(text).map_err(|e| match SchemaError::of_json(&e) {
            SchemaError::Invalid(m) => SchemaError::InvalidPose(m),
            other => other,
        })?;
        PoseObject::from_value(&v.0).map_err(|e| e.at(at))
    }

    /// The pose: the one conversion of every form (see the module's table).
    ///
    /// ```
    /// use motion::{Pose, schema::PoseObject};
    /// let m = [[0.0, -1.0, 0.0, 1.0], [1.0, 0.0, 0.0, 2.0], [0.0, 0.0, 1.0, 3.0], [0.0, 0.0, 0.0, 1.0]];
    /// let p = PoseObject::Matrix(m).to_pose()?;
    /// assert_eq!(p.transform_point(&[1.0, 0.0, 0.0])?, [1.0, 3.0, 3.0]);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn to_pose(&self) -> Result<Pose<f64>, PoseError> {
        let finite_position = |p: &[f64; 3]| {
            if p.iter().all(|x| x.is_finite()) {
                Ok(())
            } else {
                Err(PoseError::Shape { key: "position".into(), expected: "a list of 3 finite numbers" })
            }
        };
        match self {
            PoseObject::Translation { position } => {
                finite_position(position)?;
                Ok(Pose::translation(position))
            }
            // `gam pose` prints the identity rotation as axis [0, 0, 0], angle 0: it reads back
            PoseObject::AxisAngle { position, axis: [0.0, 0.0, 0.0], angle: 0.0 } => {
                finite_position(position)?;
                Ok(Pose::translation(position))
            }
            PoseObject::AxisAngle { position, axis, angle } => {
                Pose::from_axis_angle_translation(axis, angle, position).map_err(PoseError::Axis)
            }
            PoseObject::Quaternion { position, quaternion } => {
                finite_position(position)?;
                Pose::from_quaternion_wxyz(quaternion, position).map_err(|_| PoseError::ZeroQuaternion)
            }
            PoseObject::Matrix(m) => Pose::from_matrix(m, &MATRIX_TOL).map_err(PoseError::Matrix),
            PoseObject::Motor(c) => {
                if let Some(k) = c.iter().position(|x| !x.is_finite()) {
                    return Err(PoseError::Shape { key: format!("motor.{}", BLADES[k]), expected: "a finite number" });
                }
                let s = Pose::new(c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7]);
                if s.is_singular() { Err(PoseError::SingularMotor) } else { Ok(s) }
            }
            PoseObject::DualQuaternion(c) => {
                from_dual_quaternion(&DualQuaternion::from_coeffs(*c), &STUDY_TOL).map_err(PoseError::DualQuaternion)
            }
            PoseObject::Hexanion { omega, m } => Hexanion::new(*omega, *m).to_pose().map_err(PoseError::Hexanion),
        }
    }

    /// The JSON form of the object (what [`PoseObject::from_value`] reads back to the same
    /// object; a motor lists its non-zero coefficients).
    ///
    /// ```
    /// use motion::schema::PoseObject;
    /// let p = PoseObject::Hexanion { omega: [0.0, 0.0, 1.0], m: [1.0, 0.0, 0.0] };
    /// assert_eq!(PoseObject::from_value(&p.to_value())?, p);
    /// # Ok::<(), motion::schema::PoseError>(())
    /// ```
    pub fn to_value(&self) -> Value {
        match self {
            PoseObject::Translation { position } => json!({ "position": position }),
            PoseObject::AxisAngle { position, axis, angle } => {
                json!({"position": position, "axis": axis, "angle": angle})
            }
            PoseObject::Quaternion { position, quaternion } => json!({"position": position, "quaternion": quaternion}),
            PoseObject::Matrix(m) => json!({ "matrix": m }),
            PoseObject::Motor(c) => {
                let mv: Map<String, Value> =
                    BLADES.iter().zip(c).filter(|(_, x)| **x != 0.0).map(|(b, x)| (b.to_string(), json!(x))).collect();
                json!({ "motor": mv })
            }
            PoseObject::DualQuaternion(c) => json!({ "dual_quaternion": c }),
            PoseObject::Hexanion { omega, m } => json!({"hexanion": {"omega": omega, "m": m}}),
        }
    }
}

/// The coefficients of a `motor` multivector object: blade names to numbers or decimal strings.
fn motor(v: &Value) -> Result<[f64; 8], PoseError> {
    let mv = v.as_object().ok_or(PoseError::Shape { key: "motor".into(), expected: "a multivector object" })?;
    let mut c = [0.0; 8];
    for (key, x) in mv {
        let k = BLADES.iter().position(|b| b == key).ok_or_else(|| PoseError::NotABlade { blade: key.clone() })?;
        c[k] = match x {
            Value::Number(n) => n.as_f64(),
            Value::String(s) => s.trim().parse::<f64>().ok(),
            _ => None,
        }
        .filter(|x| x.is_finite())
        .ok_or_else(|| PoseError::Shape { key: format!("motor.{key}"), expected: "a finite number" })?;
    }
    Ok(c)
}

impl From<&Pose<f64>> for PoseObject {
    /// The `motor` form of a pose.
    ///
    /// ```
    /// use motion::{Pose, schema::PoseObject};
    /// let s = Pose::translation(&[1.0, 0.0, 0.0]);
    /// assert_eq!(PoseObject::from(&s).to_pose()?, s);
    /// # Ok::<(), motion::schema::PoseError>(())
    /// ```
    fn from(s: &Pose<f64>) -> Self {
        PoseObject::Motor(s.to_array())
    }
}

impl Serialize for PoseObject {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        self.to_value().serialize(s)
    }
}

impl<'de> Deserialize<'de> for PoseObject {
    /// Reads a pose object (keys given twice are refused); the messages place it at `pose`.
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let v = StrictValue::deserialize(d)?;
        PoseObject::from_value(&v.0).map_err(|e| serde::de::Error::custom(e.message_at("pose")))
    }
}
