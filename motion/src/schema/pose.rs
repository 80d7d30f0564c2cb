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

use super::{Exact, SchemaError, SpecNumber, StrictValue};
use crate::paper::BLADES;
use crate::repr::ReprError;
use crate::repr::dual_quaternion::{DualQuaternion, from_dual_quaternion, from_dual_quaternion_exact};
use crate::repr::hexanion::Hexanion;
use crate::{MotionError, Pose};
use algebra_core::rational::Q;
use algebra_core::{Real, Ring};
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
pub enum PoseObject<N = f64> {
    /// `{"position": [x, y, z]}`: a pure translation.
    Translation {
        /// The translation.
        position: [N; 3],
    },
    /// `{"position": [x, y, z], "axis": [a, b, c], "angle": φ}`.
    AxisAngle {
        /// The translation applied after the rotation.
        position: [N; 3],
        /// The rotation axis (normalised; not zero, except `[0, 0, 0]` with angle 0: the
        /// identity rotation, as `gam pose` prints it).
        axis: [N; 3],
        /// The angle in radians, right-handed.
        angle: N,
    },
    /// `{"position": [x, y, z], "quaternion": [w, x, y, z]}`.
    Quaternion {
        /// The translation applied after the rotation.
        position: [N; 3],
        /// `[w, x, y, z]`, non-zero (normalised).
        quaternion: [N; 4],
    },
    /// `{"matrix": [[..], [..], [..], [0, 0, 0, 1]]}`: rows of a rigid homogeneous matrix.
    Matrix([[N; 4]; 4]),
    /// `{"motor": MV}`: the coefficients of `S` in the order of [`BLADES`]
    /// (`1, e12, e13, e23, e1inf, e2inf, e3inf, e123inf`).
    Motor([N; 8]),
    /// `{"dual_quaternion": [w, x, y, z, dw, dx, dy, dz]}`.
    DualQuaternion([N; 8]),
    /// `{"hexanion": {"omega": [..], "m": [..]}}`.
    Hexanion {
        /// Angelidis' ω.
        omega: [N; 3],
        /// Angelidis' m.
        m: [N; 3],
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
    /// A form that is not rational in its numbers, read for exact rationals.
    #[error(
        "needs {needs}: not rational (give a quaternion, matrix, motor or dual_quaternion, or use --scalar mpfr:BITS or f64)"
    )]
    NotRational {
        /// The form's key.
        key: &'static str,
        /// What it needs.
        needs: &'static str,
    },
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
            PoseError::NotRational { key, .. } => Some(key),
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

impl PoseObject<f64> {
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
        PoseObject::read_value(v)
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
        PoseObject::read_json(text, at)
    }
}

impl<N: SpecNumber> PoseObject<N> {
    /// [`PoseObject::from_value`] in any number type.
    ///
    /// ```
    /// use algebra_core::rational::ratio;
    /// use motion::schema::{Exact, PoseObject};
    /// let p = PoseObject::<Exact>::read_value(&serde_json::json!({"position": ["1/3", 0, 0]}))?;
    /// assert_eq!(p, PoseObject::Translation { position: [ratio(1, 3), ratio(0, 1), ratio(0, 1)].map(Exact) });
    /// # Ok::<(), motion::schema::PoseError>(())
    /// ```
    pub fn read_value(v: &Value) -> Result<Self, PoseError> {
        let obj = v.as_object().ok_or(PoseError::NotAnObject)?;
        let (marker, allowed) = FORMS
            .iter()
            .find(|(marker, _)| obj.contains_key(*marker))
            .copied()
            .unwrap_or(("axis", &["position", "axis", "angle"]));
        if let Some(key) = obj.keys().find(|k| !allowed.contains(&k.as_str())) {
            return Err(PoseError::UnexpectedKey { key: key.clone(), allowed });
        }
        let position =
            || obj.get("position").map_or(Ok([N::zero(), N::zero(), N::zero()]), |p| field(p, "position", POSITION));
        Ok(match marker {
            "dual_quaternion" => {
                PoseObject::DualQuaternion(field(&obj[marker], marker, "[w, x, y, z, dw, dx, dy, dz]")?)
            }
            "hexanion" => {
                #[derive(Deserialize)]
                #[serde(deny_unknown_fields)]
                struct H<M> {
                    omega: [M; 3],
                    m: [M; 3],
                }
                let h: H<N> = field(&obj[marker], marker, "{\"omega\": [x, y, z], \"m\": [x, y, z]}")?;
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
                        angle: N::from_json(angle)
                            .ok_or(PoseError::Shape { key: "angle".into(), expected: "a number" })?,
                    },
                    _ => return Err(PoseError::AxisWithoutAngle),
                }
            }
        })
    }

    /// [`PoseObject::from_json`] in any number type ([`Exact`] reads every literal as written,
    /// [`super::quote_numbers`]).
    ///
    /// ```
    /// use algebra_core::rational::ratio;
    /// use motion::schema::{Exact, PoseObject};
    /// let p = PoseObject::<Exact>::read_json(r#"{"position": [0.1, 0, 0]}"#, "pose")?;
    /// assert_eq!(p, PoseObject::Translation { position: [ratio(1, 10), ratio(0, 1), ratio(0, 1)].map(Exact) });
    /// # Ok::<(), motion::schema::SchemaError>(())
    /// ```
    pub fn read_json(text: &str, at: &str) -> Result<Self, SchemaError> {
        let text = N::prepare_text(text);
        let v: StrictValue = serde_json::from_str(&text).map_err(|e| match SchemaError::of_json(&e) {
            SchemaError::Invalid(m) => SchemaError::InvalidPose(m),
            other => other,
        })?;
        PoseObject::read_value(&v.0).map_err(|e| e.at(at))
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
                let mv: Map<String, Value> = BLADES
                    .iter()
                    .zip(c)
                    .filter(|(_, x)| **x != N::zero())
                    .map(|(b, x)| (b.to_string(), x.to_json()))
                    .collect();
                json!({ "motor": mv })
            }
            PoseObject::DualQuaternion(c) => json!({ "dual_quaternion": c }),
            PoseObject::Hexanion { omega, m } => json!({"hexanion": {"omega": omega, "m": m}}),
        }
    }

    /// The same object with every number mapped by `f` (e.g. exact rationals rounded to a
    /// precision).
    ///
    /// ```
    /// use motion::schema::PoseObject;
    /// let p = PoseObject::Translation { position: [1.0, 2.0, 3.0] };
    /// assert_eq!(p.map(&|x: &f64| 2.0 * x), PoseObject::Translation { position: [2.0, 4.0, 6.0] });
    /// ```
    pub fn map<M>(&self, f: &dyn Fn(&N) -> M) -> PoseObject<M> {
        let a3 = |v: &[N; 3]| v.each_ref().map(f);
        match self {
            PoseObject::Translation { position } => PoseObject::Translation { position: a3(position) },
            PoseObject::AxisAngle { position, axis, angle } => {
                PoseObject::AxisAngle { position: a3(position), axis: a3(axis), angle: f(angle) }
            }
            PoseObject::Quaternion { position, quaternion } => {
                PoseObject::Quaternion { position: a3(position), quaternion: quaternion.each_ref().map(f) }
            }
            PoseObject::Matrix(m) => PoseObject::Matrix(m.each_ref().map(|r| r.each_ref().map(f))),
            PoseObject::Motor(c) => PoseObject::Motor(c.each_ref().map(f)),
            PoseObject::DualQuaternion(c) => PoseObject::DualQuaternion(c.each_ref().map(f)),
            PoseObject::Hexanion { omega, m } => PoseObject::Hexanion { omega: a3(omega), m: a3(m) },
        }
    }
}

impl<T: Real> PoseObject<T> {
    /// The pose: the one conversion of every form (see the module's table).
    ///
    /// ```
    /// use motion::{Pose, schema::PoseObject};
    /// let m = [[0.0, -1.0, 0.0, 1.0], [1.0, 0.0, 0.0, 2.0], [0.0, 0.0, 1.0, 3.0], [0.0, 0.0, 0.0, 1.0]];
    /// let p = PoseObject::Matrix(m).to_pose()?;
    /// assert_eq!(p.transform_point(&[1.0, 0.0, 0.0])?, [1.0, 3.0, 3.0]);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn to_pose(&self) -> Result<Pose<T>, PoseError> {
        let finite_position = |p: &[T; 3]| {
            if p.iter().all(Real::is_finite) {
                Ok(())
            } else {
                Err(PoseError::Shape { key: "position".into(), expected: "a list of 3 finite numbers" })
            }
        };
        let tol = |x: f64| T::from_f64(x);
        match self {
            PoseObject::Translation { position } => {
                finite_position(position)?;
                Ok(Pose::translation(position))
            }
            // `gam pose` prints the identity rotation as axis [0, 0, 0], angle 0: it reads back
            PoseObject::AxisAngle { position, axis, angle } if axis.iter().chain([angle]).all(Ring::is_exact_zero) => {
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
            PoseObject::Matrix(m) => Pose::from_matrix(m, &tol(MATRIX_TOL)).map_err(PoseError::Matrix),
            PoseObject::Motor(c) => {
                if let Some(k) = c.iter().position(|x| !Real::is_finite(x)) {
                    return Err(PoseError::Shape { key: format!("motor.{}", BLADES[k]), expected: "a finite number" });
                }
                motor_pose(c)
            }
            PoseObject::DualQuaternion(c) => {
                from_dual_quaternion(&DualQuaternion::from_coeffs(c.clone()), &tol(STUDY_TOL))
                    .map_err(PoseError::DualQuaternion)
            }
            PoseObject::Hexanion { omega, m } => {
                Hexanion::new(omega.clone(), m.clone()).to_pose().map_err(PoseError::Hexanion)
            }
        }
    }
}

/// The pose of a `motor` form's coefficients, refused when singular.
fn motor_pose<T: Ring>(c: &[T; 8]) -> Result<Pose<T>, PoseError> {
    let [a, b, c2, d, e, f, g, h] = c.clone();
    let s = Pose::new(a, b, c2, d, e, f, g, h);
    if s.is_singular() { Err(PoseError::SingularMotor) } else { Ok(s) }
}

impl PoseObject<Exact> {
    /// The pose over exact rationals, for the forms that are rational in their numbers: a
    /// translation, a quaternion (`q` and `λq` are the same rotation: the rotor is `q` as
    /// given, not normalised), a rigid matrix (checked exactly; its rotor is a non-zero row of
    /// Shepperd's symmetric matrix, proportional to the unit quaternion), a motor and a dual
    /// quaternion (Plücker's relation (8) exactly). The result is a pose up to a non-zero
    /// factor (Theorem 2.8), as every method reads it. `axis`/`angle` (sine and cosine) and
    /// `hexanion` (exp) are not rational: [`PoseError::NotRational`], except the identity
    /// rotation `axis` `[0, 0, 0]`, `angle` 0.
    ///
    /// ```
    /// use algebra_core::rational::{q, ratio};
    /// use motion::schema::{Exact, PoseObject, quote_numbers};
    /// let text = quote_numbers(r#"{"quaternion": [1, 0, 0, 1], "position": [0.5, 0, 0]}"#);
    /// let p: PoseObject<Exact> = serde_json::from_str(&text)?;
    /// let s = p.to_pose_exact()?;
    /// assert_eq!(s.transform_point(&[q(1), q(0), q(0)])?, [ratio(1, 2), q(1), q(0)]); // a quarter turn about z, then x + 1/2
    /// let turn: PoseObject<Exact> = serde_json::from_str(r#"{"axis": [0, 0, 1], "angle": 1}"#)?;
    /// assert!(turn.to_pose_exact().unwrap_err().to_string().contains("sine and cosine"));
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn to_pose_exact(&self) -> Result<Pose<Q>, PoseError> {
        let x = self.map(&|e: &Exact| e.0.clone());
        match x {
            PoseObject::Translation { position } => Ok(Pose::translation(&position)),
            PoseObject::AxisAngle { position, axis, angle } if axis.iter().chain([&angle]).all(Ring::is_exact_zero) => {
                Ok(Pose::translation(&position))
            }
            PoseObject::AxisAngle { .. } => Err(PoseError::NotRational { key: "axis", needs: "sine and cosine" }),
            PoseObject::Hexanion { .. } => Err(PoseError::NotRational { key: "hexanion", needs: "exp" }),
            PoseObject::Quaternion { position, quaternion: [w, a, b, c] } => {
                if [&w, &a, &b, &c].iter().all(|x| x.is_exact_zero()) {
                    return Err(PoseError::ZeroQuaternion);
                }
                Ok(Pose::rotor_from_parts(&w, &Q::one(), &[a, b, c]) * Pose::translation(&position))
            }
            PoseObject::Matrix(m) => exact_matrix_pose(&m),
            PoseObject::Motor(c) => motor_pose(&c),
            PoseObject::DualQuaternion(c) => {
                from_dual_quaternion_exact(&DualQuaternion::from_coeffs(c)).map_err(PoseError::DualQuaternion)
            }
        }
    }
}

/// The pose of a rigid homogeneous matrix over the rationals, checked exactly: bottom row
/// `[0, 0, 0, 1]`, `RᵀR = I`, `det R = 1`. The rotor is the first non-zero row of Shepperd's
/// symmetric matrix `K` (`K = 4 q qᵀ` for the unit quaternion `q`), so it is `4 q_k q`: rational.
fn exact_matrix_pose(m: &[[Q; 4]; 4]) -> Result<Pose<Q>, PoseError> {
    let not_rigid = |why: String| PoseError::Matrix(MotionError::NotRigid { why });
    let (zero, one) = (Q::zero(), Q::one());
    if m[3] != [zero.clone(), zero.clone(), zero.clone(), one.clone()] {
        return Err(not_rigid("the bottom row is not [0, 0, 0, 1] (exactly)".into()));
    }
    let r = |i: usize, j: usize| m[i][j].clone();
    for i in 0..3 {
        for j in 0..3 {
            let dot = r(0, i) * r(0, j) + r(1, i) * r(1, j) + r(2, i) * r(2, j);
            if dot != if i == j { one.clone() } else { zero.clone() } {
                return Err(not_rigid(format!("columns {i} and {j} of the 3x3 part are not orthonormal (exactly)")));
            }
        }
    }
    let det = r(0, 0) * (r(1, 1) * r(2, 2) - r(1, 2) * r(2, 1)) - r(0, 1) * (r(1, 0) * r(2, 2) - r(1, 2) * r(2, 0))
        + r(0, 2) * (r(1, 0) * r(2, 1) - r(1, 1) * r(2, 0));
    if det != one {
        return Err(not_rigid("the 3x3 part has determinant -1 (a reflection)".into()));
    }
    let tr = r(0, 0) + r(1, 1) + r(2, 2);
    let rows = [
        [one.clone() + tr.clone(), r(2, 1) - r(1, 2), r(0, 2) - r(2, 0), r(1, 0) - r(0, 1)],
        [r(2, 1) - r(1, 2), one.clone() + r(0, 0) - r(1, 1) - r(2, 2), r(0, 1) + r(1, 0), r(0, 2) + r(2, 0)],
        [r(0, 2) - r(2, 0), r(0, 1) + r(1, 0), one.clone() - r(0, 0) + r(1, 1) - r(2, 2), r(1, 2) + r(2, 1)],
        [r(1, 0) - r(0, 1), r(0, 2) + r(2, 0), r(1, 2) + r(2, 1), one.clone() - r(0, 0) - r(1, 1) + r(2, 2)],
    ];
    // the diagonal of K sums to 4: some row has a non-zero diagonal entry
    let [w, a, b, c] = rows.into_iter().find(|row| row.iter().any(|x| !x.is_exact_zero())).unwrap_or_default();
    let position = [r(0, 3), r(1, 3), r(2, 3)];
    Ok(Pose::rotor_from_parts(&w, &one, &[a, b, c]) * Pose::translation(&position))
}

/// The coefficients of a `motor` multivector object: blade names to numbers or decimal strings.
fn motor<N: SpecNumber>(v: &Value) -> Result<[N; 8], PoseError> {
    let mv = v.as_object().ok_or(PoseError::Shape { key: "motor".into(), expected: "a multivector object" })?;
    let mut c: [N; 8] = std::array::from_fn(|_| N::zero());
    for (key, x) in mv {
        let k = BLADES.iter().position(|b| b == key).ok_or_else(|| PoseError::NotABlade { blade: key.clone() })?;
        c[k] = N::from_json_or_string(x)
            .filter(SpecNumber::is_finite)
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

impl<N: SpecNumber> Serialize for PoseObject<N> {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        self.to_value().serialize(s)
    }
}

impl<'de, N: SpecNumber> Deserialize<'de> for PoseObject<N> {
    /// Reads a pose object (keys given twice are refused); the messages place it at `pose`.
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let v = StrictValue::deserialize(d)?;
        PoseObject::read_value(&v.0).map_err(|e| serde::de::Error::custom(e.message_at("pose")))
    }
}
