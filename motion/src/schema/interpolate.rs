//! The spec of `gam interpolate` (also read by `gam trajectory`, `gam sample` and `gam plot`):
//! a motion through key poses by a named [`Method`], as [`InterpolateSpec`].
//!
//! ```json
//! {"method": "ccm-additive", "poses": [POSE, POSE, ...], "parameters": "uniform",
//!  "velocities": [{"velocity": [..], "angular_velocity": [..]}, ...],
//!  "shape": 1, "gamma": [0, 0], "l1": 1, "weights": "lagrange", "degree": 3, "samples": 101, "body_points": [[0, 0, 0]]}
//! ```
//!
//! Every key but `method` and `poses` may be left out; a key the method does not read
//! ([`Method::inputs`]) is refused. [`InterpolateSpec::from_json`] / [`InterpolateSpec::from_value`]
//! read and check a spec, [`InterpolateSpec::method_input`] gives the [`MethodInput`] of
//! [`Method::build`], [`InterpolateSpec::build`] builds the motion.
//!
//! ```
//! use motion::schema::InterpolateSpec;
//! let spec = InterpolateSpec::from_json(
//!     r#"{"method": "ccm-additive", "poses": [{"position": [0, 0, 0]}, {"position": [2, 0, 0]}], "samples": 3}"#,
//! )?;
//! let built = spec.build()?;
//! assert_eq!(built.times(), &[0.0, 1.0]);
//! # Ok::<(), motion::schema::SchemaError>(())
//! ```

use super::{SchemaError, SpecNumber, StrictValue, pose::PoseError, pose::PoseObject};
use crate::juttler::Parametrisation;
use crate::method::{BuildError, BuiltMotion, Method, MethodInput, Parameters};
use crate::repr::hexanion::blend::BlendWeights;
use crate::velocity::Twist;
use crate::{HermiteShapes, Pose, Pseudoscalar, Shape, Vec3};
use algebra_core::Field;
use serde::{Deserialize, Serialize};
use serde_json::Value;

/// The most `samples` a spec may ask for.
pub const MAX_SAMPLES: usize = 1_000_000;

/// The velocity of the body origin and the angular velocity (fixed frame) at one key pose, per
/// unit of `t`.
///
/// ```
/// let v: motion::schema::interpolate::VelocitySpec =
///     serde_json::from_str(r#"{"velocity": [1, 0, 0], "angular_velocity": [0, 0, 1]}"#)?;
/// assert_eq!(v.angular_velocity, [0.0, 0.0, 1.0]);
/// # Ok::<(), serde_json::Error>(())
/// ```
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct VelocitySpec<N = f64> {
    /// The velocity of the body point at the origin of the body frame.
    pub velocity: [N; 3],
    /// The angular velocity `Ω`.
    pub angular_velocity: [N; 3],
}

impl<N> VelocitySpec<N> {
    /// The same velocity with every number mapped by `f`.
    fn map<U>(&self, f: &dyn Fn(&N) -> U) -> VelocitySpec<U> {
        VelocitySpec {
            velocity: self.velocity.each_ref().map(f),
            angular_velocity: self.angular_velocity.each_ref().map(f),
        }
    }
}

impl<T: Field> VelocitySpec<T> {
    /// The space twist at `pose`: `Ω` and `u = v - Ω × p`, the velocity of the body point at the
    /// global origin (`p` is where `pose` puts the body origin).
    ///
    /// ```
    /// use motion::{Pose, schema::interpolate::VelocitySpec};
    /// let v = VelocitySpec { velocity: [0.0, 1.0, 0.0], angular_velocity: [0.0, 0.0, 1.0] };
    /// let tw = v.twist(&Pose::translation(&[1.0, 0.0, 0.0]))?;
    /// assert_eq!(tw.linear.to_array(), [0.0, 0.0, 0.0]); // a turn about the z axis
    /// # Ok::<(), motion::MotionError>(())
    /// ```
    pub fn twist(&self, pose: &Pose<T>) -> Result<Twist<T>, crate::MotionError> {
        let p = pose.transform_point(&[T::zero(), T::zero(), T::zero()])?;
        let o = &self.angular_velocity;
        let cross = |i: usize, j: usize| o[i].mul_ref(&p[j]).sub_ref(&o[j].mul_ref(&p[i]));
        let c = [cross(1, 2), cross(2, 0), cross(0, 1)];
        Ok(Twist {
            angular: o.clone().into(),
            linear: Vec3::from(std::array::from_fn(|k| self.velocity[k].sub_ref(&c[k]))),
        })
    }
}

/// One value for every key pose, or one per key pose (`shape`, `gamma`).
///
/// ```
/// use motion::schema::interpolate::PerPose;
/// assert_eq!(PerPose::Each(vec![1.0, 2.0]).get(1), 2.0);
/// assert_eq!(PerPose::Common(3.0).get(7), 3.0);
/// ```
#[derive(Debug, Clone, PartialEq)]
pub enum PerPose<T> {
    /// The same value at every pose.
    Common(T),
    /// Value `i` at pose `i`.
    Each(Vec<T>),
}

impl<T: Clone> PerPose<T> {
    /// The value at pose `i` (the last one past the end of a list).
    pub fn get(&self, i: usize) -> T {
        match self {
            PerPose::Common(x) => x.clone(),
            PerPose::Each(v) => v[i.min(v.len().saturating_sub(1))].clone(),
        }
    }

    fn values(&self) -> &[T] {
        match self {
            PerPose::Common(x) => std::slice::from_ref(x),
            PerPose::Each(v) => v,
        }
    }
}

/// A parametrisation rule of Jüttler's eq. (15), normalised to `[0, 1]`.
///
/// ```
/// use motion::schema::interpolate::ParameterRule;
/// assert_eq!("angular-chordal".parse::<ParameterRule>(), Ok(ParameterRule::AngularChordal));
/// assert_eq!(ParameterRule::StarChordal.name(), "star-chordal");
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ParameterRule {
    /// `chordal`: distances of the origins.
    Chordal,
    /// `star-chordal`: translations along the screw axes.
    StarChordal,
    /// `centripetal`: square roots of the distances.
    Centripetal,
    /// `angular`: angles of the relative rotations.
    Angular,
    /// `angular-chordal`: angle plus distance.
    AngularChordal,
}

const RULES: [(ParameterRule, &str); 5] = [
    (ParameterRule::Chordal, "chordal"),
    (ParameterRule::StarChordal, "star-chordal"),
    (ParameterRule::Centripetal, "centripetal"),
    (ParameterRule::Angular, "angular"),
    (ParameterRule::AngularChordal, "angular-chordal"),
];

impl ParameterRule {
    /// The name in a spec.
    pub fn name(self) -> &'static str {
        RULES.iter().find(|(r, _)| *r == self).map_or("", |(_, n)| n)
    }

    /// The rule of the method input.
    fn parametrisation<T>(self) -> Parametrisation<T> {
        match self {
            ParameterRule::Chordal => Parametrisation::Chordal,
            ParameterRule::StarChordal => Parametrisation::StarChordal,
            ParameterRule::Centripetal => Parametrisation::Centripetal,
            ParameterRule::Angular => Parametrisation::Angular,
            ParameterRule::AngularChordal => Parametrisation::AngleDistance,
        }
    }
}

impl std::str::FromStr for ParameterRule {
    type Err = SchemaError;
    fn from_str(s: &str) -> Result<Self, SchemaError> {
        RULES.iter().find(|(_, n)| *n == s).map(|(r, _)| *r).ok_or(SchemaError::UnknownRule { got: s.to_string() })
    }
}

/// `parameters` of a spec.
///
/// ```
/// use motion::schema::interpolate::{ParameterRule, ParameterSpec};
/// assert_eq!(ParameterSpec::<f64>::default(), ParameterSpec::Uniform);
/// let _: ParameterSpec = ParameterSpec::Rule(ParameterRule::Chordal);
/// ```
#[derive(Debug, Clone, PartialEq, Default)]
pub enum ParameterSpec<N = f64> {
    /// `uniform` (the default): `t_i = i/m`.
    #[default]
    Uniform,
    /// A rule of eq. (15).
    Rule(ParameterRule),
    /// One value per pose, strictly increasing, used as given (checked by the method).
    Given(Vec<N>),
}

impl<N: SpecNumber> ParameterSpec<N> {
    fn of(v: &Value) -> Result<Self, SchemaError> {
        match v {
            Value::String(s) if s == "uniform" => Ok(ParameterSpec::Uniform),
            Value::String(s) => s.parse().map(ParameterSpec::Rule),
            Value::Array(_) => {
                Vec::<N>::deserialize(v).map(ParameterSpec::Given).map_err(|_| SchemaError::ParameterList)
            }
            other => Err(SchemaError::ParameterType { got: other.to_string() }),
        }
    }

    fn to_value(&self) -> Value {
        match self {
            ParameterSpec::Uniform => Value::from("uniform"),
            ParameterSpec::Rule(r) => Value::from(r.name()),
            ParameterSpec::Given(v) => Value::from(v.iter().map(SpecNumber::to_json).collect::<Vec<_>>()),
        }
    }

    /// The parameters of the method input, every given value mapped by `f`.
    fn parameters_with<T>(&self, f: &dyn Fn(&N) -> T) -> Parameters<T> {
        match self {
            ParameterSpec::Uniform => Parameters::Uniform,
            ParameterSpec::Rule(r) => Parameters::Rule(r.parametrisation()),
            ParameterSpec::Given(v) => Parameters::Given(v.iter().map(f).collect()),
        }
    }
}

impl ParameterSpec {
    /// The parameters of the method input.
    ///
    /// ```
    /// use motion::{method::Parameters, schema::interpolate::ParameterSpec};
    /// assert_eq!(ParameterSpec::Given(vec![0.0, 2.0]).to_parameters(), Parameters::Given(vec![0.0, 2.0]));
    /// ```
    pub fn to_parameters(&self) -> Parameters<f64> {
        self.parameters_with(&|x| *x)
    }
}

/// The spec of `gam interpolate`, read and checked (see the module doc). Deserializing one
/// (any serde format) applies every rule; [`InterpolateSpec::from_json`] and
/// [`InterpolateSpec::from_value`] do the same with a typed [`SchemaError`].
///
/// ```
/// use motion::{method::Method, schema::{InterpolateSpec, interpolate::PerPose}};
/// let spec = InterpolateSpec::from_value(&serde_json::json!({
///     "method": "ccm-multiplicative", "shape": [1, 2],
///     "poses": [{"position": [0, 0, 0]}, {"motor": {"1": 1, "e1inf": -0.5}}]}))?;
/// assert_eq!((spec.method, &spec.shape), (Method::CcmMultiplicative, &Some(PerPose::Each(vec![1.0, 2.0]))));
/// // and back
/// let again: InterpolateSpec = serde_json::from_value(serde_json::to_value(&spec).unwrap()).unwrap();
/// assert_eq!(again, spec);
/// # Ok::<(), motion::schema::SchemaError>(())
/// ```
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(try_from = "RawSpec<N>", into = "RawSpec<N>", bound = "N: SpecNumber")]
pub struct InterpolateSpec<N = f64> {
    /// The method.
    pub method: Method,
    /// The key poses (at least two).
    pub poses: Vec<PoseObject<N>>,
    /// Their parameters.
    pub parameters: ParameterSpec<N>,
    /// The velocities at the key poses (`None`: the method estimates them).
    pub velocities: Option<Vec<VelocitySpec<N>>>,
    /// The shape factors λ (`ccm-*`; positive).
    pub shape: Option<PerPose<N>>,
    /// `[α, β]` of `γ = α + βω` (`ccm-*`).
    pub gamma: Option<PerPose<[N; 2]>>,
    /// Evenly spaced samples over `[t_0, t_m]` (0: none; else 2 to [`MAX_SAMPLES`]).
    pub samples: usize,
    /// The body points to sample (`None`: the origin).
    pub body_points: Option<Vec<[N; 3]>>,
    /// The TRT split of `juttler-trt`.
    pub l1: Option<usize>,
    /// The weight functions of `hexanion-blend` (`"lagrange"`, `"bernstein"`).
    pub weights: Option<BlendWeights>,
    /// The B-spline degree of `juttler-bspline`.
    pub degree: Option<usize>,
}

/// The spec as serde reads it; every part whose shape is not fixed by a type is a
/// [`StrictValue`] (keys given twice are refused), checked by [`InterpolateSpec::try_from`].
#[derive(Debug, Clone, Serialize, Deserialize)]
#[serde(deny_unknown_fields, bound = "N: SpecNumber")]
struct RawSpec<N> {
    method: String,
    poses: Vec<StrictValue>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    parameters: Option<StrictValue>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    velocities: Option<Vec<VelocitySpec<N>>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    shape: Option<StrictValue>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    gamma: Option<StrictValue>,
    #[serde(default)]
    samples: usize,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    body_points: Option<Vec<[N; 3]>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    l1: Option<i64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    weights: Option<String>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    degree: Option<i64>,
}

impl<N: SpecNumber> TryFrom<RawSpec<N>> for InterpolateSpec<N> {
    type Error = SchemaError;
    fn try_from(raw: RawSpec<N>) -> Result<Self, SchemaError> {
        let method: Method = raw.method.parse()?;
        let poses = raw
            .poses
            .iter()
            .enumerate()
            .map(|(i, v)| PoseObject::read_value(&v.0).map_err(|e| e.at(&format!("poses[{i}]"))))
            .collect::<Result<Vec<_>, _>>()?;
        let shape = match &raw.shape {
            None => None,
            Some(StrictValue(v @ Value::Array(_))) => {
                Some(PerPose::Each(Vec::<N>::deserialize(v).map_err(|_| SchemaError::ShapeForm)?))
            }
            Some(StrictValue(v)) => Some(PerPose::Common(N::from_json(v).ok_or(SchemaError::ShapeForm)?)),
        };
        let gamma = match &raw.gamma {
            None => None,
            Some(StrictValue(v)) => Some(match <[N; 2]>::deserialize(v) {
                Ok(g) => PerPose::Common(g),
                Err(_) => PerPose::Each(Vec::<[N; 2]>::deserialize(v).map_err(|_| SchemaError::GammaForm)?),
            }),
        };
        let l1 = match raw.l1 {
            None => None,
            Some(k) => Some(usize::try_from(k).map_err(|_| SchemaError::L1 { got: k })?),
        };
        let spec = InterpolateSpec {
            method,
            poses,
            parameters: raw.parameters.map_or(Ok(ParameterSpec::Uniform), |v| ParameterSpec::of(&v.0))?,
            velocities: raw.velocities,
            shape,
            gamma,
            samples: raw.samples,
            body_points: raw.body_points,
            l1,
            weights: raw.weights.as_deref().map(str::parse).transpose().map_err(SchemaError::Weights)?,
            degree: raw.degree.map(|d| usize::try_from(d).map_err(|_| SchemaError::Degree { got: d })).transpose()?,
        };
        spec.check()?;
        Ok(spec)
    }
}

impl<N: SpecNumber> From<InterpolateSpec<N>> for RawSpec<N> {
    fn from(s: InterpolateSpec<N>) -> Self {
        let per_pose = |p: Option<Value>| p.map(StrictValue);
        RawSpec {
            method: s.method.name().to_string(),
            poses: s.poses.iter().map(|p| StrictValue(p.to_value())).collect(),
            parameters: Some(StrictValue(s.parameters.to_value())),
            velocities: s.velocities,
            shape: per_pose(s.shape.map(|x| match x {
                PerPose::Common(x) => x.to_json(),
                PerPose::Each(v) => Value::from(v.iter().map(SpecNumber::to_json).collect::<Vec<_>>()),
            })),
            gamma: per_pose(s.gamma.map(|x| {
                let pair = |g: &[N; 2]| Value::from(g.iter().map(SpecNumber::to_json).collect::<Vec<_>>());
                match x {
                    PerPose::Common(g) => pair(&g),
                    PerPose::Each(v) => Value::from(v.iter().map(pair).collect::<Vec<_>>()),
                }
            })),
            samples: s.samples,
            body_points: s.body_points,
            l1: s.l1.map(|k| i64::try_from(k).unwrap_or(i64::MAX)),
            weights: s.weights.map(|w| w.name().to_string()),
            degree: s.degree.map(|d| i64::try_from(d).unwrap_or(i64::MAX)),
        }
    }
}

impl InterpolateSpec {
    /// Reads and checks a spec from JSON text; the line and column of a syntax or serde error
    /// are in its message.
    ///
    /// ```
    /// use motion::schema::InterpolateSpec;
    /// let e = InterpolateSpec::from_json(r#"{"method": "ccm-additive", "poses": [], "sample": 3}"#).unwrap_err();
    /// assert!(e.to_string().starts_with("invalid spec: unknown field `sample`"));
    /// let two = r#"[{"position": [0, 0, 0]}, {"position": [1, 0, 0], "position": [2, 0, 0]}]"#;
    /// let e = InterpolateSpec::from_json(&format!(r#"{{"method": "wl-linear", "poses": {two}}}"#)).unwrap_err();
    /// assert!(e.to_string().contains("duplicate key `position`"));
    /// ```
    pub fn from_json(text: &str) -> Result<Self, SchemaError> {
        InterpolateSpec::read_json(text)
    }

    /// Reads and checks a spec from a parsed JSON value (as another front door has it).
    ///
    /// ```
    /// use motion::schema::{InterpolateSpec, SchemaError};
    /// let v = serde_json::json!({"method": "wl-linear", "poses": [{"position": [0, 0, 0]}], "samples": 1});
    /// let e = InterpolateSpec::from_value(&v).unwrap_err();
    /// assert_eq!(e.to_string(), "at least two poses are needed (got 1)");
    /// ```
    pub fn from_value(v: &Value) -> Result<Self, SchemaError> {
        InterpolateSpec::read_value(v)
    }

    /// The key poses, every rule of the format checked ([`InterpolateSpec::poses_with`]).
    ///
    /// ```
    /// let spec = motion::schema::InterpolateSpec::from_json(r#"{"method": "wl-linear", "poses": [{}, {"position": [1, 0, 0]}]}"#)?;
    /// assert_eq!(spec.poses()?[1].transform_point(&[0.0; 3])?, [1.0, 0.0, 0.0]);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn poses(&self) -> Result<Vec<Pose<f64>>, SchemaError> {
        self.poses_with(&PoseObject::to_pose)
    }

    /// The input of [`Method::build`]: the key poses, parameters, the space twists of the
    /// velocities, the shapes (one common shape when `shape` and `gamma` are, else one per pose)
    /// and `l1`. A velocity that cannot be computed is [`SchemaError::Velocity`].
    ///
    /// ```
    /// use motion::schema::InterpolateSpec;
    /// let spec = InterpolateSpec::from_json(r#"{"method": "ccm-additive", "shape": 2,
    ///     "poses": [{"position": [0, 0, 0]}, {"position": [1, 0, 0]}]}"#)?;
    /// let input = spec.method_input()?;
    /// assert_eq!(input.poses.len(), 2);
    /// assert!(matches!(input.shapes, Some(motion::HermiteShapes::Common(s)) if s.lambda == 2.0));
    /// # Ok::<(), motion::schema::SchemaError>(())
    /// ```
    pub fn method_input(&self) -> Result<MethodInput<f64>, SchemaError> {
        self.method_input_with(self.poses()?, &|x| *x)
    }

    /// Checks the spec and builds its motion ([`Method::build`]); a failure of the method is
    /// [`SchemaError::Build`], named after the method where the failure is its own.
    ///
    /// ```
    /// use motion::schema::InterpolateSpec;
    /// let spec = InterpolateSpec::from_json(r#"{"method": "juttler-trt",
    ///     "poses": [{"position": [0, 0, 0]}, {"position": [1, 0, 0], "axis": [0, 0, 1], "angle": 1}]}"#)?;
    /// let e = spec.build().unwrap_err();
    /// assert!(!e.is_input() && e.to_string().starts_with("juttler-trt: "));
    /// # Ok::<(), motion::schema::SchemaError>(())
    /// ```
    pub fn build(&self) -> Result<BuiltMotion<f64>, SchemaError> {
        let input = self.method_input()?;
        self.method.build(&input).map_err(|source| SchemaError::Build { method: self.method, source })
    }

    /// The body points (`[[0, 0, 0]]` when left out).
    ///
    /// ```
    /// let spec = motion::schema::InterpolateSpec::from_json(r#"{"method": "wl-linear", "poses": [{}, {}]}"#)?;
    /// assert_eq!(spec.body_points(), vec![[0.0; 3]]);
    /// # Ok::<(), motion::schema::SchemaError>(())
    /// ```
    pub fn body_points(&self) -> Vec<[f64; 3]> {
        self.body_points.clone().unwrap_or_else(|| vec![[0.0; 3]])
    }
}

impl<N: SpecNumber> InterpolateSpec<N> {
    /// [`InterpolateSpec::from_json`] in any number type ([`super::Exact`] reads every literal
    /// as written).
    ///
    /// ```
    /// use algebra_core::rational::ratio;
    /// use motion::schema::{Exact, InterpolateSpec, interpolate::ParameterSpec};
    /// let spec = InterpolateSpec::<Exact>::read_json(r#"{"method": "juttler-affine", "parameters": [0, 0.1, 1],
    ///     "poses": [{"position": [0, 0, 0]}, {"position": [1, 0, 0]}, {"position": [1, 1, 0]}]}"#)?;
    /// assert_eq!(spec.parameters, ParameterSpec::Given([ratio(0, 1), ratio(1, 10), ratio(1, 1)].map(Exact).to_vec()));
    /// # Ok::<(), motion::schema::SchemaError>(())
    /// ```
    pub fn read_json(text: &str) -> Result<Self, SchemaError> {
        let raw: RawSpec<N> = serde_json::from_str(&N::prepare_text(text)).map_err(|e| SchemaError::of_json(&e))?;
        InterpolateSpec::try_from(raw)
    }

    /// [`InterpolateSpec::from_value`] in any number type.
    ///
    /// ```
    /// use motion::schema::{Exact, InterpolateSpec};
    /// let v = serde_json::json!({"method": "wl-linear", "poses": [{}, {"position": ["1/3", 0, 0]}]});
    /// assert_eq!(InterpolateSpec::<Exact>::read_value(&v)?.poses.len(), 2);
    /// # Ok::<(), motion::schema::SchemaError>(())
    /// ```
    pub fn read_value(v: &Value) -> Result<Self, SchemaError> {
        let raw = RawSpec::<N>::deserialize(v).map_err(|e| SchemaError::Invalid(e.to_string()))?;
        InterpolateSpec::try_from(raw)
    }

    /// The optional keys the spec gives.
    fn given_keys(&self) -> [(&'static str, bool); 6] {
        [
            ("velocities", self.velocities.is_some()),
            ("shape", self.shape.is_some()),
            ("gamma", self.gamma.is_some()),
            ("l1", self.l1.is_some()),
            ("weights", self.weights.is_some()),
            ("degree", self.degree.is_some()),
        ]
    }

    /// Every rule of the format, in the order the CLI reports them: keys the method does not
    /// read, at least two poses, each pose (converted by `pose`), one velocity per pose, shapes
    /// and `gamma`, `samples`. Returns the converted key poses.
    ///
    /// ```
    /// use motion::schema::{InterpolateSpec, SchemaError, interpolate::PerPose};
    /// let mut spec = InterpolateSpec::from_value(&serde_json::json!({
    ///     "method": "ccm-additive", "poses": [{"position": [0, 0, 0]}, {"position": [1, 0, 0]}]}))?;
    /// spec.shape = Some(PerPose::Common(-1.0));
    /// assert_eq!(spec.poses_with(&|_| Ok(())).unwrap_err(), SchemaError::ShapeValue { got: -1.0 });
    /// # Ok::<(), SchemaError>(())
    /// ```
    pub fn poses_with<P>(&self, pose: &dyn Fn(&PoseObject<N>) -> Result<P, PoseError>) -> Result<Vec<P>, SchemaError> {
        let method = self.method;
        if let Some((key, _)) = self.given_keys().into_iter().find(|(k, given)| *given && !method.inputs().contains(k))
        {
            return Err(SchemaError::Build { method, source: BuildError::Unused { key, method } });
        }
        let m = self.poses.len();
        if m < 2 {
            return Err(SchemaError::Build { method, source: BuildError::TooFewPoses { got: m } });
        }
        let poses = self
            .poses
            .iter()
            .enumerate()
            .map(|(i, p)| pose(p).map_err(|e| e.at(&format!("poses[{i}]"))))
            .collect::<Result<Vec<_>, _>>()?;
        if let Some(v) = &self.velocities
            && v.len() != m
        {
            return Err(SchemaError::VelocityCount { got: v.len(), poses: m });
        }
        if let Some(shape) = &self.shape {
            if matches!(shape, PerPose::Each(v) if v.len() != m) {
                return Err(SchemaError::ShapeForm);
            }
            if let Some(x) = shape.values().iter().find(|x| !x.is_positive()) {
                return Err(SchemaError::ShapeValue { got: x.to_f64() });
            }
        }
        if let Some(gamma) = &self.gamma
            && (matches!(gamma, PerPose::Each(v) if v.len() != m)
                || gamma.values().iter().flatten().any(|x| !SpecNumber::is_finite(x)))
        {
            return Err(SchemaError::GammaForm);
        }
        if self.samples == 1 || self.samples > MAX_SAMPLES {
            return Err(SchemaError::Samples { got: self.samples });
        }
        Ok(poses)
    }

    /// Checks every rule of the format ([`InterpolateSpec::poses_with`]); the key poses are
    /// converted where the number type can tell ([`SpecNumber::check_pose`]).
    ///
    /// ```
    /// use motion::schema::InterpolateSpec;
    /// let mut spec = InterpolateSpec::from_json(r#"{"method": "wl-linear", "poses": [{}, {"position": [1, 0, 0]}]}"#)?;
    /// spec.l1 = Some(1);
    /// assert_eq!(spec.check().unwrap_err().to_string(), "`l1` is not used by `wl-linear` (it interpolates the key poses only)");
    /// # Ok::<(), motion::schema::SchemaError>(())
    /// ```
    pub fn check(&self) -> Result<(), SchemaError> {
        self.poses_with(&|p| N::check_pose(p)).map(drop)
    }

    /// [`InterpolateSpec::method_input`] over any field: the key poses already converted (by
    /// [`InterpolateSpec::poses_with`]) and every other number mapped by `f`.
    ///
    /// ```
    /// use motion::schema::InterpolateSpec;
    /// let spec = InterpolateSpec::from_json(r#"{"method": "ccm-additive", "shape": 2,
    ///     "poses": [{"position": [0, 0, 0]}, {"position": [1, 0, 0]}]}"#)?;
    /// let input = spec.method_input_with(spec.poses()?, &|x| *x)?;
    /// assert_eq!(input.poses.len(), 2);
    /// assert!(matches!(input.shapes, Some(motion::HermiteShapes::Common(s)) if s.lambda == 2.0));
    /// # Ok::<(), motion::schema::SchemaError>(())
    /// ```
    pub fn method_input_with<T: Field>(
        &self,
        poses: Vec<Pose<T>>,
        f: &dyn Fn(&N) -> T,
    ) -> Result<MethodInput<T>, SchemaError> {
        let m = poses.len();
        let velocities = match &self.velocities {
            None => None,
            Some(v) => Some(
                v.iter()
                    .zip(&poses)
                    .map(|(w, s)| w.map(f).twist(s).map_err(SchemaError::Velocity))
                    .collect::<Result<Vec<_>, _>>()?,
            ),
        };
        let shapes = if self.shape.is_some() || self.gamma.is_some() {
            let lambda = self.shape.clone().unwrap_or(PerPose::Common(N::one()));
            let gamma = self.gamma.clone().unwrap_or(PerPose::Common([N::zero(), N::zero()]));
            let shape = |k: usize| {
                let g = gamma.get(k);
                Shape::new(f(&lambda.get(k)), Pseudoscalar::new(f(&g[0]), f(&g[1])))
            };
            Some(match (&lambda, &gamma) {
                (PerPose::Common(_), PerPose::Common(_)) => HermiteShapes::Common(shape(0)),
                _ => HermiteShapes::PerPose((0..m).map(shape).collect()),
            })
        } else {
            None
        };
        Ok(MethodInput {
            parameters: self.parameters.parameters_with(f),
            velocities,
            shapes,
            l1: self.l1,
            weights: self.weights,
            degree: self.degree,
            ..MethodInput::new(poses)
        })
    }
}
