//! One build path for every method of `gam interpolate`: [`super::Method::build`] takes the
//! key poses and the optional inputs ([`MethodInput`]) and returns a [`BuiltMotion`]
//! (module `built`): the motion, its segments, its sampler and its rational trajectories.
//!
//! ```
//! use motion::{Motion, Pose, method::{Method, MethodInput}};
//! let poses = vec![Pose::<f64>::identity(), Pose::translation(&[1.0, 0.0, 0.0]), Pose::translation(&[1.0, 1.0, 0.0])];
//! for method in [Method::CcmAdditive, Method::WlLinear, Method::JuttlerQMotion] {
//!     let m = method.build(&MethodInput::new(poses.clone()))?;
//!     assert_eq!(m.times(), [0.0, 0.5, 1.0]);
//!     let p = m.pose(&0.5)?.transform_point(&[0.0; 3])?;
//!     assert!((p[0] - 1.0).abs() < 1e-14 && p[1].abs() < 1e-14, "{method}");
//! }
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use super::{BuiltMotion, Method, MethodMotion, MethodSegment};
use crate::juttler::bspline_tr::bspline_tr;
use crate::juttler::minimal::minimal;
use crate::juttler::minimal_spline::minimal_spline;
use crate::juttler::parametrisation::normalise;
use crate::juttler::projective::projective;
use crate::juttler::rotational::affine;
use crate::juttler::spline::algorithm2;
use crate::juttler::tr::{algorithm1, rotations, tr_method};
use crate::juttler::trt::trt;
use crate::juttler::velocity::estimate_velocities;
use crate::juttler::{JuttlerError, KeyVelocity, Parametrisation, QMotion, SplineQMotion, parameters};
use crate::repr::ReprError;
use crate::repr::dual_quaternion::to_dual_quaternion_exact;
use crate::repr::hexanion::Hexanion;
use crate::repr::hexanion::blend::{BlendWeights, HexanionBlend, HexanionDecoupled, HexanionLinear};
use crate::trajectory::{Trajectory, TrajectoryError, Velocities, align_signs};
use crate::velocity::Twist;
use crate::wareham_lasenby::{WlBivectorLinear, WlError, WlLinear, WlMotion, WlQuadratic};
use crate::{CurveError, HermiteShapes, JoinError, Motion, Piecewise, Pose};
use algebra_core::{Field, Real, Ring};

/// The parameters `t_i` of the key poses (`parameters` of the contract).
///
/// ```
/// use motion::{Pose, juttler::Parametrisation, method::{Method, MethodInput, Parameters}};
/// let poses = [[0.0, 0.0, 0.0], [3.0, 0.0, 0.0], [3.0, 4.0, 0.0]].map(|t| Pose::<f64>::translation(&t)).to_vec();
/// let input = MethodInput { parameters: Parameters::Rule(Parametrisation::Chordal), ..MethodInput::new(poses) };
/// assert_eq!(Method::CcmAdditive.build(&input)?.times(), [0.0, 3.0 / 7.0, 1.0]);
/// # Ok::<(), motion::method::BuildError>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub enum Parameters<T> {
    /// `t_i = i/m` (the default).
    Uniform,
    /// A rule of Jüttler's eq. (15), normalised to `[0, 1]` ([`crate::juttler::parameters`],
    /// measured on the sign-aligned key poses).
    Rule(Parametrisation<T>),
    /// One value per key pose, used as given (strictly increasing; checked by the method).
    Given(Vec<T>),
}

/// What a method is built from: the key poses and the optional inputs of the contract. An
/// input the method does not read ([`Method::inputs`]) is refused, never ignored.
///
/// ```
/// use motion::{Pose, method::{MethodInput, Parameters}};
/// let input = MethodInput::new(vec![Pose::<f64>::identity(), Pose::translation(&[1.0, 0.0, 0.0])]);
/// assert_eq!(input.parameters, Parameters::Uniform);
/// assert!(input.velocities.is_none() && input.shapes.is_none() && input.l1.is_none());
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct MethodInput<T: Ring> {
    /// The key poses `S_0, ..., S_m` (unitized, the first given a canonical sign, the others
    /// sign-aligned by rule (24): a non-zero multiple `λS` gives the same motion as `S`).
    pub poses: Vec<Pose<T>>,
    /// Their parameters.
    pub parameters: Parameters<T>,
    /// The space twists at the key poses per unit of `t` (`None`: the method estimates them).
    pub velocities: Option<Vec<Twist<T>>>,
    /// The `ccm-*` shapes (`shape`, `gamma`; `None`: unit shape, `γ = 0`).
    pub shapes: Option<HermiteShapes<T>>,
    /// The TRT split `l1` (`juttler-trt`).
    pub l1: Option<usize>,
    /// The weight functions of `hexanion-blend` (`None`: `lagrange`).
    pub weights: Option<BlendWeights>,
    /// The B-spline degree `p` of `juttler-bspline` (`None`: `min(3, m)`).
    pub degree: Option<usize>,
}

impl<T: Ring> MethodInput<T> {
    /// `poses` with uniform parameters and nothing else given.
    ///
    /// ```
    /// let input = motion::method::MethodInput::new(vec![motion::Pose::<f64>::identity()]);
    /// assert_eq!(input.poses.len(), 1);
    /// ```
    pub fn new(poses: Vec<Pose<T>>) -> Self {
        MethodInput {
            poses,
            parameters: Parameters::Uniform,
            velocities: None,
            shapes: None,
            l1: None,
            weights: None,
            degree: None,
        }
    }
}

/// Why [`Method::build`] (or a rational trajectory of a built motion) failed.
///
/// ```
/// use motion::{Pose, method::{BuildError, Method, MethodInput}};
/// let e = Method::CcmAdditive.build(&MethodInput::new(vec![Pose::<f64>::identity()])).unwrap_err();
/// assert!(matches!(e, BuildError::TooFewPoses { got: 1 }) && e.is_input());
/// ```
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum BuildError {
    /// An optional input the method does not read.
    #[error("`{key}` is not used by `{method}` ({})", uses(*method))]
    Unused {
        /// The input's spec key.
        key: &'static str,
        /// The method.
        method: Method,
    },
    /// Fewer than two key poses.
    #[error("at least two poses are needed (got {got})")]
    TooFewPoses {
        /// How many were given.
        got: usize,
    },
    /// Given parameters, not one per key pose.
    #[error("`parameters` has {got} values for {poses} poses")]
    ParameterCount {
        /// How many were given.
        got: usize,
        /// The number of key poses.
        poses: usize,
    },
    /// From a `ccm-*` method.
    #[error(transparent)]
    Trajectory(TrajectoryError),
    /// From a W-L method.
    #[error(transparent)]
    Wl(WlError),
    /// From `hexanion-linear`.
    #[error(transparent)]
    Repr(ReprError),
    /// From a Jüttler method or a parametrisation rule of eq. (15).
    #[error(transparent)]
    Juttler(JuttlerError),
    /// From joining segments.
    #[error(transparent)]
    Curve(CurveError),
    /// A global Jüttler interpolant (Algorithm 1, TRT, minimal order) that floating point
    /// cannot compute for this many poses (its collocation is ill-conditioned).
    #[error(
        "numerically unstable with {poses} poses: {why} (one interpolant of high degree: use fewer poses, or juttler-spline)"
    )]
    Unstable {
        /// The number of key poses.
        poses: usize,
        /// What went wrong.
        why: String,
    },
    /// A method (or an input of it) whose construction is not rational, asked of
    /// [`Method::build_exact`].
    #[error("{method} is not exact over the rationals: it needs {needs} (use --scalar mpfr:BITS or f64)")]
    NotExact {
        /// The method.
        method: &'static str,
        /// What it needs.
        needs: &'static str,
    },
    /// A key pose whose rotation has an irrational norm, for a method of
    /// [`Method::build_exact`] that normalises it.
    #[error(
        "{method} normalises the key rotations, and key pose {index}'s quaternion has norm² {norm_squared}, not the square of a rational (give quaternions of rational norm such as [3/5, 0, 0, 4/5], or use --scalar mpfr:BITS or f64)"
    )]
    IrrationalNorm {
        /// The method.
        method: &'static str,
        /// The key pose.
        index: usize,
        /// Its norm squared, `p/q`.
        norm_squared: String,
    },
    /// A parameter outside `[t_0, t_m]` asked of an exact motion.
    #[error("t = {t} is outside the motion's domain {domain}")]
    OutOfDomain {
        /// The parameter, `p/q`.
        t: String,
        /// The domain.
        domain: String,
    },
    /// A rational trajectory asked of a method whose motions are not rational.
    #[error(
        "the motions of `{method}` are not rational (their point trajectories are not rational curves; rational: ccm-additive and the juttler-* methods)"
    )]
    NotRational {
        /// The method.
        method: &'static str,
    },
}

/// The end of the [`BuildError::Unused`] message.
fn uses(method: Method) -> String {
    match method.inputs() {
        [] => "it interpolates the key poses only".to_string(),
        keys => format!("it uses {}", keys.join(", ")),
    }
}

impl BuildError {
    /// True when the input is bad (a key the method does not use, too few poses, parameters
    /// not increasing or not one per pose, a parametrisation step of zero), false for a
    /// numerical failure (a singular pose, a join that is not C1, overflow).
    ///
    /// ```
    /// use motion::method::{BuildError, Method};
    /// assert!(BuildError::Unused { key: "l1", method: Method::WlLinear }.is_input());
    /// ```
    pub fn is_input(&self) -> bool {
        match self {
            BuildError::Unused { .. }
            | BuildError::TooFewPoses { .. }
            | BuildError::ParameterCount { .. }
            | BuildError::NotRational { .. }
            | BuildError::NotExact { .. }
            | BuildError::IrrationalNorm { .. }
            | BuildError::OutOfDomain { .. }
            | BuildError::Curve(_) => true,
            BuildError::Unstable { .. } => false,
            BuildError::Trajectory(e) => {
                matches!(e, TrajectoryError::Input(_) | TrajectoryError::Join(JoinError::Input(_)))
            }
            BuildError::Wl(e) => matches!(e, WlError::Curve(_)),
            BuildError::Repr(e) => matches!(e, ReprError::Curve(_) | ReprError::Times { .. }),
            BuildError::Juttler(e) => matches!(
                e,
                JuttlerError::TooFewPositions { .. }
                    | JuttlerError::Parameters { .. }
                    | JuttlerError::ZeroStep { .. }
                    | JuttlerError::Split { .. }
                    | JuttlerError::ProjectiveCount { .. }
            ),
        }
    }
}

macro_rules! build_error_from {
    ($($variant:ident($ty:ty)),*) => {$(
        impl From<$ty> for BuildError {
            fn from(e: $ty) -> Self {
                BuildError::$variant(e)
            }
        }
    )*};
}

build_error_from!(Trajectory(TrajectoryError), Wl(WlError), Repr(ReprError), Juttler(JuttlerError), Curve(CurveError));

impl<T: Real> Parameters<T> {
    /// The values `t_0, ..., t_m` for the (sign-aligned) key poses.
    fn values(&self, poses: &[Pose<T>]) -> Result<Vec<T>, BuildError> {
        let m = poses.len();
        match self {
            Parameters::Uniform => Ok((0..m).map(|i| T::from_ratio(i as i64, m as i64 - 1)).collect()),
            Parameters::Rule(rule) => Ok(parameters(poses, rule)?),
            Parameters::Given(t) if t.len() != m => Err(BuildError::ParameterCount { got: t.len(), poses: m }),
            Parameters::Given(t) => Ok(t.clone()),
        }
    }
}

/// The spec's velocities as Jüttler's (`None` when not given), one per key pose.
pub(super) fn given_velocities<T: Field>(
    input: &MethodInput<T>,
    poses: &[Pose<T>],
) -> Result<Option<Vec<KeyVelocity<T>>>, BuildError> {
    match &input.velocities {
        None => Ok(None),
        Some(v) if v.len() != poses.len() => {
            let why = format!("{} velocities for {} poses", v.len(), poses.len());
            Err(JuttlerError::Parameters { why }.into())
        }
        Some(v) => Ok(Some(key_velocities(poses, v)?)),
    }
}

/// Space twists (`u` the velocity of the body point at the global origin) as Jüttler's
/// `v⃗_i`, `ω⃗_i` (the velocity of the moving origin, at the key pose's position `p_i`):
/// `v⃗_i = u + Ω × p_i`.
pub(super) fn key_velocities<T: Field>(
    poses: &[Pose<T>],
    twists: &[Twist<T>],
) -> Result<Vec<KeyVelocity<T>>, BuildError> {
    poses
        .iter()
        .zip(twists)
        .map(|(s, w)| {
            let p = s.transform_point(&[T::zero(), T::zero(), T::zero()]).map_err(JuttlerError::from)?;
            Ok(KeyVelocity::new(w.point_velocity(&p).into(), w.angular.to_array()))
        })
        .collect()
}

impl Method {
    /// The motion of this method through `input.poses` (module docs of [`crate::method`]):
    /// the key poses are sign-aligned (rule (24)), their parameters computed, and the method
    /// run. Typed errors for inputs the method does not read, too few poses, bad parameters
    /// and the method's own failures ([`BuildError::is_input`] tells bad input from a
    /// numerical failure).
    ///
    /// ```
    /// use motion::{Motion, Pose, method::{BuildError, Method, MethodInput}};
    /// let poses = vec![Pose::<f64>::identity(), Pose::rotation(&[0.0, 0.0, 1.0], &1.0)?];
    /// let m = Method::JuttlerQMotion.build(&MethodInput::new(poses.clone()))?;
    /// assert!(m.pose(&1.0)?.is_equivalent(&poses[1], &1e-15)?);
    /// let with_l1 = MethodInput { l1: Some(0), ..MethodInput::new(poses) };
    /// assert!(matches!(Method::JuttlerQMotion.build(&with_l1), Err(BuildError::Unused { key: "l1", .. })));
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn build<T: Real>(self, input: &MethodInput<T>) -> Result<BuiltMotion<T>, BuildError> {
        // S and λS are the same pose (Theorem 2.8), so the motion must not depend on λ: every
        // method starts from the unitized key poses (a singular or non-finite pose is passed on
        // unchanged, for the method's own error)
        let poses = self.key_poses(input, &|p| p.unitize().unwrap_or_else(|_| p.clone()))?;
        let m = poses.len();
        let times = input.parameters.values(&poses)?;
        let (segments, motion) = match self {
            Method::CcmAdditive | Method::CcmMultiplicative => self.hermite(input, &poses, &times)?,
            Method::WlLinear | Method::WlQuadratic | Method::WlDirect => {
                let wl = match self {
                    Method::WlLinear => WlMotion::Linear(WlLinear::new(&poses, &times)?),
                    Method::WlDirect => WlMotion::Direct(WlBivectorLinear::new(&poses, &times)?),
                    _ => WlMotion::Quadratic(WlQuadratic::new(&poses, &times)?),
                };
                let segments = (0..m - 1).map(|k| self.key_pose_segment(&poses, &times, k, None)).collect();
                (segments, MethodMotion::Wl(wl))
            }
            Method::HexanionLinear => {
                let h = HexanionLinear::through(&poses, &times)?;
                let segments = (0..m - 1)
                    .map(|k| {
                        let ends = [h.hexanions()[k].clone(), h.hexanions()[k + 1].clone()];
                        self.key_pose_segment(&poses, &times, k, Some(ends))
                    })
                    .collect();
                (segments, MethodMotion::Hexanion(h))
            }
            Method::HexanionBlend => {
                let weights = input.weights.unwrap_or(BlendWeights::Lagrange);
                let b = HexanionBlend::through(&poses, &times, weights)?;
                (vec![self.key_pose_segment(&poses, &times, 0, None)], MethodMotion::Blend(b))
            }
            Method::HexanionDecoupled => {
                let d = HexanionDecoupled::through(&poses, &times)?;
                let segments = (0..m - 1).map(|k| self.key_pose_segment(&poses, &times, k, None)).collect();
                (segments, MethodMotion::Decoupled(d))
            }
            Method::JuttlerQMotion
            | Method::JuttlerAffine
            | Method::JuttlerProjective
            | Method::JuttlerTrt
            | Method::JuttlerMinimal => self.global(input, &poses, &times)?,
            Method::JuttlerSpline => {
                let velocities = given_velocities(input, &poses)?;
                self.spline_parts(&algorithm2(&poses, &times, velocities.as_deref())?)?
            }
            Method::JuttlerMinimalSpline => {
                let velocities = match given_velocities(input, &poses)? {
                    Some(v) => v,
                    None => estimate_velocities(&poses, &times)?,
                };
                self.minimal_spline_parts(&poses, &times, &velocities)?
            }
            Method::JuttlerBSpline => {
                let p = input.degree.unwrap_or(3.min(m - 1));
                self.spline_parts(bspline_tr(&poses, &times, p)?.pieces())?
            }
        };
        Ok(BuiltMotion { method: self, times, key_poses: poses, segments, motion })
    }

    /// The key poses every method starts from, after the checks of the input (an input the
    /// method does not read, fewer than two poses): each scaled by `scale` (unitized, for the
    /// floating-point build), and since the sign of `λ` in `λS` must not matter either, the
    /// first takes the sign that makes the first non-zero of `S∅, S12, S13, S23` positive and
    /// rule (24) aligns the others to it.
    pub(super) fn key_poses<T: Ring + PartialOrd>(
        self,
        input: &MethodInput<T>,
        scale: &dyn Fn(&Pose<T>) -> Pose<T>,
    ) -> Result<Vec<Pose<T>>, BuildError> {
        let given = [
            ("velocities", input.velocities.is_some()),
            ("shape", input.shapes.is_some()),
            ("l1", input.l1.is_some()),
            ("weights", input.weights.is_some()),
            ("degree", input.degree.is_some()),
        ];
        if let Some((key, _)) = given.into_iter().find(|(key, given)| *given && !self.inputs().contains(key)) {
            return Err(BuildError::Unused { key, method: self });
        }
        let m = input.poses.len();
        if m < 2 {
            return Err(BuildError::TooFewPoses { got: m });
        }
        let mut poses: Vec<Pose<T>> = input.poses.iter().map(scale).collect();
        let first = poses[0].components()[..4].iter().find(|c| !c.is_exact_zero()).map(|c| **c < T::zero());
        if first == Some(true) {
            poses[0] = -&poses[0];
        }
        align_signs(&mut poses);
        Ok(poses)
    }

    /// The Jüttler methods with one interpolant over `[t_0, t_m]` (Algorithm 1, TRT, minimal
    /// order), built on the parameters mapped onto `[0, 1]`. Their Bernstein collocation of
    /// degree `m` is ill-conditioned in floating point (with 20 random poses f64 misses the
    /// key poses by 1e-3, with 40 by far more), so the result must reproduce every key pose
    /// (Theorem 2.8 to `1e-8 (1 + L)`, `L` the largest key position) or the build fails with
    /// [`BuildError::Unstable`]; a collocation matrix found singular for distinct parameters
    /// is the same failure.
    fn global<T: Real>(
        self,
        input: &MethodInput<T>,
        poses: &[Pose<T>],
        times: &[T],
    ) -> Result<(Vec<MethodSegment<T>>, MethodMotion<T>), BuildError> {
        let m = poses.len();
        let u = normalise(times, m)?;
        let unstable = |why: String| BuildError::Unstable { poses: m, why };
        let singular = |e: JuttlerError| match e {
            JuttlerError::Parameters { .. } => unstable("its collocation matrix is numerically singular".into()),
            e => e.into(),
        };
        let breaks = vec![times[0].clone(), times[m - 1].clone()];
        let (segment, motion) = match self {
            Method::JuttlerMinimal => {
                let motion = minimal(poses, &u).map_err(singular)?;
                // the control data: its Q-motion (36), the same motion
                let segment = self.q_motion_segment(&motion.q_motion(), &breaks);
                (segment, MethodMotion::Minimal(Piecewise::new(breaks, vec![motion])?))
            }
            _ => {
                let q = match self {
                    Method::JuttlerQMotion => algorithm1(poses, &u).map_err(singular)?,
                    // Jüttler (19)-(21): the affine rotations, then TR
                    Method::JuttlerAffine => {
                        tr_method(&affine(&rotations(poses)?, &u).map_err(singular)?, poses, &u).map_err(singular)?
                    }
                    // Jüttler (27)-(28): the projective rotations (m + 1 = 5, 9, 13, ... poses), then TR
                    Method::JuttlerProjective => {
                        tr_method(&projective(&rotations(poses)?, &u).map_err(singular)?, poses, &u)
                            .map_err(singular)?
                    }
                    // default l1 = m - 1 for m + 1 poses (l2 = 0)
                    _ => trt(poses, &u, input.l1.unwrap_or(m - 2)).map_err(singular)?,
                };
                (self.q_motion_segment(&q, &breaks), MethodMotion::QMotions(Piecewise::new(breaks, vec![q])?))
            }
        };
        let origin = [T::zero(), T::zero(), T::zero()];
        let mut size = T::zero();
        for p in poses {
            for x in p.transform_point(&origin).map_err(JuttlerError::from)? {
                if Real::abs(&x) > size {
                    size = Real::abs(&x);
                }
            }
        }
        let tol = T::from_f64(1e-8).mul_ref(&T::one().add_ref(&size));
        for (i, (p, t)) in poses.iter().zip(times).enumerate() {
            let hit = motion.pose(t).ok().and_then(|s| s.is_equivalent(p, &tol).ok()).unwrap_or(false);
            if !hit {
                let degree = segment.degree;
                return Err(unstable(format!(
                    "the interpolant of degree {degree} misses key pose {i} in floating point"
                )));
            }
        }
        Ok((vec![segment], motion))
    }

    /// The `ccm-*` methods: [`Trajectory::through`] with the given or estimated velocities.
    fn hermite<T: Real>(
        self,
        input: &MethodInput<T>,
        poses: &[Pose<T>],
        times: &[T],
    ) -> Result<(Vec<MethodSegment<T>>, MethodMotion<T>), BuildError> {
        let velocities = match &input.velocities {
            Some(v) => Velocities::Given(v.clone()),
            None => Velocities::CatmullRom,
        };
        let shapes = input.shapes.clone().unwrap_or_else(HermiteShapes::unit);
        let tr = Trajectory::through(poses, times, &velocities, self.kind(), &shapes)?;
        let segments = tr
            .segments()
            .iter()
            .enumerate()
            .map(|(k, seg)| MethodSegment {
                t0: times[k].clone(),
                t1: times[k + 1].clone(),
                representation: self.representation(),
                degree: seg.degree(),
                control_poses: seg.control_poses().to_vec(),
                dual_quaternions: (self == Method::CcmAdditive)
                    .then(|| seg.control_poses().iter().map(to_dual_quaternion_exact).collect()),
                hexanions: None,
            })
            .collect();
        Ok((segments, MethodMotion::Bezier(tr.motion().clone())))
    }

    /// Segment `k` of a method through the key poses only (W-L, hexanion): the key poses it
    /// depends on and the degree in `t` of the generator before exp.
    fn key_pose_segment<T: Real>(
        self,
        poses: &[Pose<T>],
        times: &[T],
        k: usize,
        hexanions: Option<[Hexanion<T>; 2]>,
    ) -> MethodSegment<T> {
        let last = poses.len() - 1;
        let (range, degree) = match self {
            Method::WlQuadratic if last == 2 => (0..=2, 2),
            Method::WlQuadratic => {
                let (lo, hi) = (k.saturating_sub(1), (k + 2).min(last));
                (lo..=hi, if hi - lo == 3 { 3 } else { 2 })
            }
            // one segment over [t_0, t_m]: every key pose, φ_i of degree m
            Method::HexanionBlend => (0..=last, last),
            _ => (k..=k + 1, 1),
        };
        let end = if self == Method::HexanionBlend { last } else { k + 1 };
        MethodSegment {
            t0: times[k].clone(),
            t1: times[end].clone(),
            representation: self.representation(),
            degree,
            control_poses: poses[range].to_vec(),
            dual_quaternions: None,
            hexanions,
        }
    }

    /// The segments and motion of a piecewise Q-motion (`juttler-spline`, `juttler-bspline`):
    /// one segment per piece, between its breaks.
    pub(super) fn spline_parts<T: Real>(
        self,
        spline: &SplineQMotion<T>,
    ) -> Result<(Vec<MethodSegment<T>>, MethodMotion<T>), BuildError> {
        let segments = spline
            .segments()
            .iter()
            .zip(spline.breaks().windows(2))
            .map(|(q, w)| self.q_motion_segment(q, w))
            .collect();
        let motion = Piecewise::new(spline.breaks().to_vec(), spline.segments().to_vec())?;
        Ok((segments, MethodMotion::QMotions(motion)))
    }

    /// The C1 spline of rational motions of order 6 (`juttler-minimal-spline`): one segment per
    /// interval, its control data the segment's Q-motion (36).
    pub(super) fn minimal_spline_parts<T: Real>(
        self,
        poses: &[Pose<T>],
        times: &[T],
        velocities: &[KeyVelocity<T>],
    ) -> Result<(Vec<MethodSegment<T>>, MethodMotion<T>), BuildError> {
        let pieces = minimal_spline(poses, times, velocities)?;
        let segments =
            pieces.iter().zip(times.windows(2)).map(|(p, w)| self.q_motion_segment(&p.q_motion(), w)).collect();
        Ok((segments, MethodMotion::Minimal(Piecewise::new(times.to_vec(), pieces)?)))
    }

    /// A Q-motion over `[t0, t1]`: its control dual quaternions, and the same as motors.
    pub(super) fn q_motion_segment<T: Ring>(self, q: &QMotion<T>, breaks: &[T]) -> MethodSegment<T> {
        MethodSegment {
            t0: breaks[0].clone(),
            t1: breaks[1].clone(),
            representation: self.representation(),
            degree: q.degree(),
            control_poses: q.control().iter().map(|b| Pose::from_motor(b.to_pose())).collect(),
            dual_quaternions: Some(q.control().to_vec()),
            hexanions: None,
        }
    }
}
