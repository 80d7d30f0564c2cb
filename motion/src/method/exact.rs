//! [`Method::build_exact`]: the methods whose construction is rational, over exact rationals
//! (`--scalar rational` of the motion commands). From rational key poses (any non-zero
//! multiple of a pose is the same pose, Theorem 2.8, so they are not unitized) and rational
//! parameters, Jüttler's constructions solve linear systems only, and their Q-motions, point
//! trajectories and samples are rational: they come out exactly.
//!
//! | method | exact when |
//! |---|---|
//! | `juttler-affine`, `juttler-projective` | always (no key rotation may be a half turn for `juttler-affine`) |
//! | `juttler-q-motion`, `juttler-trt`, `juttler-minimal` | every key rotation quaternion has a rational norm (the elliptic method (23) normalises them) |
//! | `juttler-spline`, `juttler-minimal-spline`, `juttler-bspline` | every key pose has a rational norm (they take unit poses); the splines with `velocities` given (the estimate of step 1 takes logarithms) |
//! | `ccm-additive` | every key pose has a rational norm, and `velocities` are given: the additive joins (22) are rational |
//! | `ccm-multiplicative`, `wl-*`, `hexanion-*` | never: exp and log ([`BuildError::NotExact`]) |
//!
//! The parameters must be `uniform` or given; the rules of eq. (15) measure distances and
//! angles (square roots, arc cosines).
//!
//! ```
//! use algebra_core::rational::{q, ratio};
//! use motion::{Pose, method::{Method, MethodInput}};
//! let poses = vec![Pose::translation(&[q(0), q(0), q(0)]), Pose::rotor_from_parts(&q(1), &q(1), &[q(0), q(0), q(1)]) * Pose::translation(&[q(1), q(0), q(0)])];
//! let m = Method::JuttlerAffine.build_exact(&MethodInput::new(poses))?;
//! let p = m.pose(&ratio(1, 2))?.transform_point(&[q(0), q(0), q(0)])?;
//! assert_eq!(p, [ratio(1, 2), q(0), q(0)]); // exactly
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use super::build::given_velocities;
use super::{BuildError, Method, MethodInput, MethodSegment, Parameters, RationalSegment, SurfaceSegment};
use crate::joins::{EndCondition, additive_end, additive_start};
use crate::juttler::bspline_tr::bspline_tr;
use crate::juttler::minimal::{MinimalMotion, minimal_method};
use crate::juttler::minimal_spline::minimal_spline;
use crate::juttler::parametrisation::normalise;
use crate::juttler::projective::projective;
use crate::juttler::rotational::{affine, elliptic_normalised};
use crate::juttler::surface::RationalBezierSurface;
use crate::juttler::tr::{rotations, tr_method};
use crate::juttler::trt::trt_method;
use crate::juttler::{JuttlerError, QMotion, RationalBezier, RationalMotion, SplineQMotion};
use crate::repr::dual_quaternion::to_dual_quaternion_exact;
use crate::repr::dual_quaternion::{Quaternion, from_dual_quaternion_exact};
use crate::trajectory::TrajectoryError;
use crate::{AdditiveBezier, HermiteShapes, MapScalar, Motion, MotionError, Pose, Pseudoscalar};
use algebra_core::rational::{Q, format_rational, sqrt_rational};
use algebra_core::{Jet, Ring};

/// One segment of an exact motion on its local parameter `u ∈ [0, 1]`: a Q-motion, a motion of
/// minimal order (with its Q-motion (36), the same motion), or an additive Bézier motion
/// (`ccm-additive`: its sums of poses need not lie on the Study quadric, so it is kept as the
/// main paper's motion, not as a Q-motion).
#[derive(Debug, Clone, PartialEq)]
enum Piece {
    Q(QMotion<Q>),
    Minimal(MinimalMotion<Q>, QMotion<Q>),
    Additive(AdditiveBezier<Q>),
}

impl Piece {
    /// The pose at `u`.
    fn pose(&self, u: &Q) -> Result<Pose<Q>, BuildError> {
        match self {
            Piece::Q(q) | Piece::Minimal(_, q) => Ok(q.pose_exact(u)?),
            Piece::Additive(b) => Ok(b.evaluate(u)?),
        }
    }

    /// The pose at `u` over exact dual numbers (value and `d/du`).
    fn jet_pose(&self, u: &Q) -> Result<Pose<Jet<Q>>, BuildError> {
        let jet = |x: &Q| Jet::constant(x.clone());
        let u = Jet::variable(u.clone());
        match self {
            Piece::Q(q) | Piece::Minimal(_, q) => {
                Ok(from_dual_quaternion_exact(&q.map_ring(&jet).eval(&u)).map_err(JuttlerError::from)?)
            }
            Piece::Additive(b) => Ok(MapScalar::<Q, Jet<Q>>::map_scalar(b, &jet).evaluate(&u)?),
        }
    }

    /// The rational motion whose point trajectories the segment has (for `juttler-minimal`, of
    /// minimal order).
    fn rational(&self) -> &dyn RationalMotion<Q> {
        match self {
            Piece::Q(q) => q,
            Piece::Minimal(m, _) => m,
            Piece::Additive(b) => b,
        }
    }

    /// The contract's segment of the piece over `breaks`.
    fn segment(&self, method: Method, breaks: &[Q]) -> MethodSegment<Q> {
        match self {
            Piece::Q(q) | Piece::Minimal(_, q) => method.q_motion_segment(q, breaks),
            Piece::Additive(b) => MethodSegment {
                t0: breaks[0].clone(),
                t1: breaks[1].clone(),
                representation: method.representation(),
                degree: b.poses().len() - 1,
                control_poses: b.poses().to_vec(),
                dual_quaternions: Some(b.poses().iter().map(to_dual_quaternion_exact).collect()),
                hexanions: None,
            },
        }
    }
}

/// A motion of [`Method::build_exact`]: the method's segments (the contract's `segments[]`,
/// exactly), its poses at rational parameters, samples with velocities, and the rational
/// Bézier trajectories of body points, all exact.
///
/// ```
/// use algebra_core::rational::{q, ratio};
/// use motion::{Pose, method::{Method, MethodInput}};
/// let poses = [[0, 0, 0], [2, 0, 0], [2, 2, 0]].map(|t| Pose::translation(&t.map(q))).to_vec();
/// let m = Method::JuttlerQMotion.build_exact(&MethodInput::new(poses))?;
/// assert_eq!(m.times(), [q(0), ratio(1, 2), q(1)]);
/// let curve = &m.rational_trajectories(&[q(0), q(0), q(0)])?[0].curve;
/// assert_eq!(curve.point(&ratio(1, 2))?, [q(2), q(0), q(0)]);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct ExactMotion {
    method: Method,
    times: Vec<Q>,
    key_poses: Vec<Pose<Q>>,
    segments: Vec<MethodSegment<Q>>,
    /// The parameters where the pieces meet (`t_0`, `t_m` for one global interpolant).
    breaks: Vec<Q>,
    pieces: Vec<Piece>,
}

/// The pose and first-order kinematics of an [`ExactMotion`] at one parameter, exactly.
///
/// ```
/// use algebra_core::rational::{q, ratio};
/// use motion::{Pose, method::{Method, MethodInput}};
/// let poses = vec![Pose::translation(&[q(0), q(0), q(0)]), Pose::translation(&[q(3), q(0), q(0)])];
/// let m = Method::JuttlerAffine.build_exact(&MethodInput::new(poses))?;
/// let s = m.sample(&ratio(1, 3), &[[q(0), q(1), q(0)]])?;
/// assert_eq!((s.points[0].clone(), s.velocities[0].clone()), ([q(1), q(1), q(0)], [q(3), q(0), q(0)]));
/// assert_eq!(s.angular_velocity, [q(0), q(0), q(0)]);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct ExactSample {
    /// The parameter.
    pub t: Q,
    /// The rigid homogeneous matrix of the pose (rows).
    pub matrix: [[Q; 4]; 4],
    /// The positions of the body points.
    pub points: Vec<[Q; 3]>,
    /// Their velocities per unit of `t`.
    pub velocities: Vec<[Q; 3]>,
    /// The angular velocity `Ω` (fixed frame) per unit of `t`.
    pub angular_velocity: [Q; 3],
}

impl ExactMotion {
    /// The method.
    ///
    /// ```
    /// # use algebra_core::rational::q;
    /// # use motion::{Pose, method::{Method, MethodInput}};
    /// let poses = vec![Pose::translation(&[q(0), q(0), q(0)]), Pose::translation(&[q(1), q(0), q(0)])];
    /// assert_eq!(Method::JuttlerAffine.build_exact(&MethodInput::new(poses))?.method(), Method::JuttlerAffine);
    /// # Ok::<(), motion::method::BuildError>(())
    /// ```
    pub fn method(&self) -> Method {
        self.method
    }

    /// The parameters `t_i` of the key poses.
    ///
    /// ```
    /// # use algebra_core::rational::q;
    /// # use motion::{Pose, method::{Method, MethodInput, Parameters}};
    /// let poses = vec![Pose::translation(&[q(0), q(0), q(0)]), Pose::translation(&[q(1), q(0), q(0)])];
    /// let input = MethodInput { parameters: Parameters::Given(vec![q(2), q(5)]), ..MethodInput::new(poses) };
    /// assert_eq!(Method::JuttlerAffine.build_exact(&input)?.times(), [q(2), q(5)]);
    /// # Ok::<(), motion::method::BuildError>(())
    /// ```
    pub fn times(&self) -> &[Q] {
        &self.times
    }

    /// The key poses as the method used them (signs aligned by rule (24); not unitized).
    ///
    /// ```
    /// # use algebra_core::rational::q;
    /// # use motion::{Pose, method::{Method, MethodInput}};
    /// let poses = vec![Pose::translation(&[q(0), q(0), q(0)]), Pose::translation(&[q(1), q(0), q(0)]).scale(&q(-2))];
    /// let m = Method::JuttlerAffine.build_exact(&MethodInput::new(poses.clone()))?;
    /// assert_eq!(m.key_poses()[1], -&poses[1]);
    /// # Ok::<(), motion::method::BuildError>(())
    /// ```
    pub fn key_poses(&self) -> &[Pose<Q>] {
        &self.key_poses
    }

    /// The segments (parameter interval, representation, degree, control data), exactly.
    ///
    /// ```
    /// # use algebra_core::rational::q;
    /// # use motion::{Pose, method::{Method, MethodInput}};
    /// let poses = vec![Pose::translation(&[q(0), q(0), q(0)]), Pose::translation(&[q(1), q(0), q(0)])];
    /// let m = Method::JuttlerAffine.build_exact(&MethodInput::new(poses))?;
    /// assert_eq!((m.segments().len(), m.segments()[0].degree), (1, 2));
    /// # Ok::<(), motion::method::BuildError>(())
    /// ```
    pub fn segments(&self) -> &[MethodSegment<Q>] {
        &self.segments
    }

    /// The segment of `t` and the local parameter `u ∈ [0, 1]` in it; `t` outside
    /// `[t_0, t_m]` is [`BuildError::OutOfDomain`].
    fn locate(&self, t: &Q) -> Result<(usize, Q), BuildError> {
        let b = &self.breaks;
        let (first, last) = (&b[0], &b[b.len() - 1]);
        if t < first || t > last {
            let domain = format!("[{}, {}]", format_rational(first), format_rational(last));
            return Err(BuildError::OutOfDomain { t: format_rational(t), domain });
        }
        let k = b.windows(2).position(|w| t <= &w[1]).unwrap_or(b.len() - 2);
        let (t0, t1) = (&b[k], &b[k + 1]);
        Ok((k, (t - t0) / (t1 - t0)))
    }

    /// The pose at `t` (a non-zero multiple of the unit pose), exactly.
    ///
    /// ```
    /// # use algebra_core::rational::{q, ratio};
    /// # use motion::{Pose, method::{Method, MethodInput}};
    /// let poses = vec![Pose::translation(&[q(0), q(0), q(0)]), Pose::translation(&[q(4), q(0), q(0)])];
    /// let m = Method::JuttlerAffine.build_exact(&MethodInput::new(poses))?;
    /// assert_eq!(m.pose(&ratio(1, 4))?.transform_point(&[q(0), q(0), q(0)])?, [q(1), q(0), q(0)]);
    /// assert!(m.pose(&q(2)).is_err());
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn pose(&self, t: &Q) -> Result<Pose<Q>, BuildError> {
        let (k, u) = self.locate(t)?;
        self.pieces[k].pose(&u)
    }

    /// The sample at `t` of `body_points`: the rigid matrix, the points, their velocities and
    /// the angular velocity, exactly (derivatives by exact dual numbers `Jet<Q>`).
    ///
    /// ```
    /// # use algebra_core::rational::q;
    /// # use motion::{Pose, method::{Method, MethodInput}};
    /// let poses = vec![Pose::translation(&[q(0), q(0), q(0)]), Pose::rotor_from_parts(&q(1), &q(1), &[q(0), q(0), q(1)])];
    /// let m = Method::JuttlerAffine.build_exact(&MethodInput::new(poses))?;
    /// let s = m.sample(&q(0), &[])?;
    /// assert_eq!(s.angular_velocity, [q(0), q(0), q(2)]); // affine: q(t) = 1 + t k, Ω = 2 q' q* / |q|²
    /// # Ok::<(), motion::method::BuildError>(())
    /// ```
    pub fn sample(&self, t: &Q, body_points: &[[Q; 3]]) -> Result<ExactSample, BuildError> {
        let (k, u) = self.locate(t)?;
        let dt = &self.breaks[k + 1] - &self.breaks[k];
        let pose = self.pieces[k].jet_pose(&u)?;
        let m = pose.to_matrix().map_err(JuttlerError::from)?;
        let rate = |x: &Jet<Q>| &x.eps / &dt;
        let mut points = Vec::with_capacity(body_points.len());
        let mut velocities = Vec::with_capacity(body_points.len());
        for x in body_points {
            let p = pose.transform_point(&x.clone().map(Jet::constant)).map_err(JuttlerError::from)?;
            points.push(p.each_ref().map(|c| c.re.clone()));
            velocities.push(p.each_ref().map(rate));
        }
        // Ω^ = R' Rᵀ (fixed frame)
        let w = |i: usize, j: usize| (0..3).fold(Q::zero(), |acc, l| acc + rate(&m[i][l]) * &m[j][l].re);
        Ok(ExactSample {
            t: t.clone(),
            matrix: m.each_ref().map(|r| r.each_ref().map(|c| c.re.clone())),
            points,
            velocities,
            angular_velocity: [w(2, 1), w(0, 2), w(1, 0)],
        })
    }

    /// The rational Bézier curve of body point `x` in each segment (local parameter
    /// `u ∈ [0, 1]`), exactly; for `juttler-minimal` of the minimal order.
    ///
    /// ```
    /// # use algebra_core::rational::q;
    /// # use motion::{Pose, method::{Method, MethodInput}};
    /// let poses = vec![Pose::translation(&[q(0), q(0), q(0)]), Pose::translation(&[q(1), q(0), q(0)])];
    /// let m = Method::JuttlerAffine.build_exact(&MethodInput::new(poses))?;
    /// assert_eq!(m.rational_trajectories(&[q(0), q(0), q(0)])?[0].curve.degree(), 4); // twice the Q-motion's
    /// # Ok::<(), motion::method::BuildError>(())
    /// ```
    pub fn rational_trajectories(&self, x: &[Q; 3]) -> Result<Vec<RationalSegment<Q>>, BuildError> {
        self.rational_pieces(&|m| m.rational_trajectory(x))
            .map(|v| v.into_iter().map(|(t0, t1, curve)| RationalSegment { t0, t1, curve }).collect())
    }

    /// The kinematic (sweep) surface of the rational curve `curve` under each segment, exactly
    /// (as [`super::BuiltMotion::kinematic_surfaces`]).
    ///
    /// ```
    /// # use algebra_core::rational::{q, ratio};
    /// # use motion::{Pose, juttler::RationalBezier, method::{Method, MethodInput}};
    /// let poses = vec![Pose::translation(&[q(0), q(0), q(0)]), Pose::translation(&[q(0), q(0), q(2)])];
    /// let m = Method::JuttlerAffine.build_exact(&MethodInput::new(poses))?;
    /// let segment = RationalBezier::new(vec![[q(1), q(0), q(0), q(0)], [q(1), q(1), q(0), q(0)]]).unwrap();
    /// let s = &m.kinematic_surfaces(&segment)?[0].surface;
    /// assert_eq!(s.point(&ratio(1, 2), &ratio(1, 2))?, [ratio(1, 2), q(0), q(1)]);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn kinematic_surfaces(&self, curve: &RationalBezier<Q>) -> Result<Vec<SurfaceSegment<Q>>, BuildError> {
        self.rational_pieces(&|m| RationalBezierSurface::kinematic(m, curve))
            .map(|v| v.into_iter().map(|(t0, t1, surface)| SurfaceSegment { t0, t1, surface }).collect())
    }

    /// `f` of each segment's rational motion (for `juttler-minimal` the motion of minimal
    /// order), with the segment's interval.
    fn rational_pieces<R>(
        &self,
        f: &dyn Fn(&dyn RationalMotion<Q>) -> Result<R, JuttlerError>,
    ) -> Result<Vec<(Q, Q, R)>, BuildError> {
        self.pieces
            .iter()
            .zip(self.breaks.windows(2))
            .map(|(p, w)| Ok((w[0].clone(), w[1].clone(), f(p.rational())?)))
            .collect()
    }
}

/// `ccm-additive` over the rationals: the main paper's C1 Hermite interpolation (Sec. 5.3) with
/// additive cubic segments, on the (unit) key poses with the given space twists: segment `k` on
/// `[t_k, t_(k+1)]` of length `h` has `S1 = S_k (1 + Ψ0/6)`, `S2 = S_(k+1) (1 - Ψ1/6)` (eq. 22)
/// with `Ψ = h λ(ν + γ)`, as [`crate::HermiteSegment::through_at`] computes in floating point.
fn additive_hermite(
    poses: &[Pose<Q>],
    times: &[Q],
    twists: &[crate::velocity::Twist<Q>],
    shapes: Option<&HermiteShapes<Q>>,
) -> Result<Vec<Piece>, BuildError> {
    let m = poses.len();
    if twists.len() != m {
        let why = format!("{} velocities for {m} poses", twists.len());
        return Err(JuttlerError::Parameters { why }.into());
    }
    let zero = [Q::zero(), Q::zero(), Q::zero()];
    let conditions = poses
        .iter()
        .zip(twists)
        .map(|(s, w)| {
            let p = s.transform_point(&zero).map_err(JuttlerError::from)?;
            let v = w.point_velocity(&p);
            Ok(EndCondition::new(s.clone(), p, v.into(), w.angular.to_array()))
        })
        .collect::<Result<Vec<_>, BuildError>>()?;
    let unit = HermiteShapes::unit();
    let shapes = shapes.unwrap_or(&unit);
    (0..m - 1)
        .map(|k| {
            let h = &times[k + 1] - &times[k];
            if h <= Q::zero() {
                let why = format!("parameter {} is not larger than parameter {k}", k + 1);
                return Err(JuttlerError::Parameters { why }.into());
            }
            let [a, b] = shapes.for_segment(k, m).map_err(TrajectoryError::from)?;
            let (c0, c1) = (&conditions[k], &conditions[k + 1]);
            let psi0 = a.stretched(&h).indicatrix(&c0.velocity_bivector());
            let psi1 = b.stretched(&h).indicatrix(&c1.velocity_bivector());
            let s1 = additive_start(&c0.pose, &psi0, 3).map_err(TrajectoryError::from)?;
            let s2 = additive_end(&c1.pose, &psi1, 3).map_err(TrajectoryError::from)?;
            let b = AdditiveBezier::new(vec![c0.pose.clone(), s1, s2, c1.pose.clone()])?;
            Ok(Piece::Additive(b))
        })
        .collect()
}

/// The pieces and breaks of a piecewise Q-motion.
fn spline_pieces(spline: &SplineQMotion<Q>) -> (Vec<Piece>, Vec<Q>) {
    (spline.segments().iter().cloned().map(Piece::Q).collect(), spline.breaks().to_vec())
}

/// The unit quaternion of `r`, when its norm is rational; else the method cannot be exact.
fn unit_exact(method: Method, index: usize, r: &Quaternion<Q>) -> Result<Quaternion<Q>, BuildError> {
    let n2 = r.norm_squared();
    match sqrt_rational(&n2) {
        Some(n) if !n.is_exact_zero() => Ok(r.scale(&n.recip())),
        Some(_) => Err(JuttlerError::ZeroQuaternion { index }.into()),
        None => Err(BuildError::IrrationalNorm { method: method.name(), index, norm_squared: format_rational(&n2) }),
    }
}

/// The unitized pose `S/|S|`, when `|S|` is rational (Lemma 2.4(ii): `|S| = √α + β/(2√α) ω`
/// for `rev(S) S = α + βω`, rational when `√α` is).
fn unitize_exact(method: Method, index: usize, s: &Pose<Q>) -> Result<Pose<Q>, BuildError> {
    let n2 = s.pseudo_norm_squared();
    let root = sqrt_rational(&n2.scalar).filter(|r| !r.is_exact_zero()).ok_or_else(|| BuildError::IrrationalNorm {
        method: method.name(),
        index,
        norm_squared: format_rational(&n2.scalar),
    })?;
    let norm = Pseudoscalar::new(root.clone(), &n2.e123inf / (&root + &root));
    let inv = norm.try_inverse().map_err(|e: MotionError| BuildError::from(JuttlerError::from(e)))?;
    Ok(s.scale_pseudoscalar(&inv))
}

impl Method {
    /// The motion of this method through `input.poses` over exact rationals, for the methods
    /// whose construction is rational (module docs of `method::exact`): the same construction
    /// as [`Method::build`] without rounding. A method or input that needs a square root or a
    /// transcendental function is [`BuildError::NotExact`] or [`BuildError::IrrationalNorm`]
    /// (bad input for this scalar: use `mpfr:BITS` or `f64`).
    ///
    /// ```
    /// use algebra_core::rational::q;
    /// use motion::{Pose, method::{BuildError, Method, MethodInput}};
    /// let poses = vec![Pose::translation(&[q(0), q(0), q(0)]), Pose::translation(&[q(1), q(0), q(0)])];
    /// let e = Method::WlLinear.build_exact(&MethodInput::new(poses)).unwrap_err();
    /// assert!(matches!(e, BuildError::NotExact { .. }) && e.is_input());
    /// assert!(e.to_string().contains("mpfr:BITS"));
    /// ```
    pub fn build_exact(self, input: &MethodInput<Q>) -> Result<ExactMotion, BuildError> {
        let not_exact = |needs: &'static str| BuildError::NotExact { method: self.name(), needs };
        let poses = self.key_poses(input, &|p| p.clone())?;
        let m = poses.len();
        for (index, p) in poses.iter().enumerate() {
            if p.is_singular() {
                return Err(
                    JuttlerError::from(MotionError::Singular { op: "key pose", value: format!("{index}") }).into()
                );
            }
        }
        let times = match &input.parameters {
            Parameters::Uniform => (0..m).map(|i| Q::from_ratio(i as i64, m as i64 - 1)).collect(),
            Parameters::Given(t) if t.len() != m => return Err(BuildError::ParameterCount { got: t.len(), poses: m }),
            Parameters::Given(t) => t.clone(),
            Parameters::Rule(_) => return Err(not_exact("a parametrisation rule of eq. (15) (distances and angles)")),
        };
        // the spline methods take unit key poses (their velocities and rotational parts are at
        // the poses' scale): exact when the norms are rational
        let unit_poses = |poses: &[Pose<Q>]| -> Result<Vec<Pose<Q>>, BuildError> {
            poses.iter().enumerate().map(|(i, p)| unitize_exact(self, i, p)).collect()
        };
        let unit_rotations = |poses: &[Pose<Q>]| -> Result<Vec<Quaternion<Q>>, BuildError> {
            rotations(poses)?.iter().enumerate().map(|(i, r)| unit_exact(self, i, r)).collect()
        };
        let (pieces, breaks) = match self {
            Method::JuttlerAffine
            | Method::JuttlerProjective
            | Method::JuttlerQMotion
            | Method::JuttlerTrt
            | Method::JuttlerMinimal => {
                let u = normalise(&times, m)?;
                let piece = match self {
                    Method::JuttlerAffine => Piece::Q(tr_method(&affine(&rotations(&poses)?, &u)?, &poses, &u)?),
                    Method::JuttlerProjective => {
                        Piece::Q(tr_method(&projective(&rotations(&poses)?, &u)?, &poses, &u)?)
                    }
                    Method::JuttlerQMotion => {
                        let rot = elliptic_normalised(&unit_rotations(&poses)?, &u)?;
                        Piece::Q(tr_method(&rot, &poses, &u)?)
                    }
                    Method::JuttlerTrt => {
                        let rot = elliptic_normalised(&unit_rotations(&poses)?, &u)?;
                        Piece::Q(trt_method(&rot, &poses, &u, input.l1.unwrap_or(m - 2))?)
                    }
                    _ => {
                        let rot = elliptic_normalised(&unit_rotations(&poses)?, &u)?;
                        let motion = minimal_method(&rot, &poses, &u)?;
                        Piece::Minimal(motion.clone(), motion.q_motion())
                    }
                };
                (vec![piece], vec![times[0].clone(), times[m - 1].clone()])
            }
            Method::JuttlerSpline | Method::JuttlerMinimalSpline => {
                if input.velocities.is_none() {
                    return Err(not_exact(
                        "the velocity estimate of Algorithm 2's step 1 (logarithms): give `velocities`",
                    ));
                }
                let unit = unit_poses(&poses)?;
                let v = given_velocities(input, &unit)?.unwrap_or_default();
                if self == Method::JuttlerSpline {
                    spline_pieces(&SplineQMotion::hermite(&unit, &times, &v)?)
                } else {
                    let pieces = minimal_spline(&unit, &times, &v)?;
                    (pieces.into_iter().map(|p| Piece::Minimal(p.clone(), p.q_motion())).collect(), times.clone())
                }
            }
            Method::JuttlerBSpline => {
                let p = input.degree.unwrap_or(3.min(m - 1));
                spline_pieces(bspline_tr(&unit_poses(&poses)?, &times, p)?.pieces())
            }
            Method::CcmAdditive => {
                let Some(twists) = &input.velocities else {
                    return Err(not_exact(
                        "the velocity estimate of Sec. 5.3 (logarithms of relative poses): give `velocities`",
                    ));
                };
                let unit = unit_poses(&poses)?;
                (additive_hermite(&unit, &times, twists, input.shapes.as_ref())?, times.clone())
            }
            Method::CcmMultiplicative => {
                return Err(not_exact("exp and log (the multiplicative joins (23))"));
            }
            Method::WlLinear
            | Method::WlQuadratic
            | Method::WlDirect
            | Method::HexanionLinear
            | Method::HexanionDecoupled
            | Method::HexanionBlend => return Err(not_exact("exp and log")),
        };
        let segments: Vec<MethodSegment<Q>> =
            pieces.iter().zip(breaks.windows(2)).map(|(p, w)| p.segment(self, w)).collect();
        let motion = ExactMotion { method: self, times, key_poses: poses, segments, breaks, pieces };
        // the construction interpolates by design; checked exactly all the same
        for (i, (p, t)) in motion.key_poses.iter().zip(&motion.times).enumerate() {
            if !motion.pose(t)?.is_equivalent_exact(p) {
                return Err(BuildError::Unstable {
                    poses: m,
                    why: format!("the exact interpolant misses key pose {i}"),
                });
            }
        }
        Ok(motion)
    }
}
