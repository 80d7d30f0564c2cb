//! What [`super::Method::build`] returns: a [`BuiltMotion`], a [`Motion`] over `[t_0, t_m]`
//! that knows its segments ([`MethodSegment`]: the contract's `segments[]`), samples itself
//! ([`BuiltMotion::sample`]) and gives the rational Bézier trajectories of body points where
//! the method's motions are rational ([`BuiltMotion::rational_trajectories`], `gam
//! trajectory`); its motion is one [`MethodMotion`] enum over the families of motions the
//! methods build.

use super::{BuildError, Method};
use crate::juttler::minimal::MinimalMotion;
use crate::juttler::{QMotion, RationalBezier, RationalMotion};
use crate::repr::dual_quaternion::DualQuaternion;
use crate::repr::hexanion::Hexanion;
use crate::repr::hexanion::blend::{HexanionDecoupled, HexanionLinear};
use crate::trajectory::{TrajectoryError, TrajectorySample, sample_motion};
use crate::wareham_lasenby::WlMotion;
use crate::{AnyMotion, CurveError, MapScalar, Motion, Piecewise, Pose};
use algebra_core::{Real, Ring};

/// One segment of a built motion over `[t0, t1]` (`segments[]` of the contract).
///
/// ```
/// use motion::{Pose, method::{Method, MethodInput}};
/// let poses = vec![Pose::<f64>::identity(), Pose::translation(&[1.0, 0.0, 0.0])];
/// let m = Method::JuttlerQMotion.build(&MethodInput::new(poses))?;
/// let s = &m.segments()[0];
/// assert_eq!((s.t0, s.t1, s.representation, s.degree), (0.0, 1.0, "dual-quaternion-bezier", 2));
/// assert_eq!(s.control_poses.len(), 3);
/// # Ok::<(), motion::method::BuildError>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct MethodSegment<T: Ring> {
    /// Start of the segment's parameter interval.
    pub t0: T,
    /// End of the segment's parameter interval.
    pub t1: T,
    /// What the control data mean ([`Method::representation`]).
    pub representation: &'static str,
    /// The degree in `t` (of the Bézier curve, or of the generator before exp).
    pub degree: usize,
    /// The control data as poses (g123inf motors acting by `F_S`): Bézier control poses, or
    /// the key poses the segment depends on (W-L, hexanion).
    pub control_poses: Vec<Pose<T>>,
    /// The same control data as dual quaternions acting by Jüttler's (12), where they describe
    /// the same motion (additive combinations: `ccm-additive`, Q-motions); the map is the one
    /// `gam pose` uses ([`crate::repr::dual_quaternion::to_dual_quaternion_exact`], linear).
    pub dual_quaternions: Option<Vec<DualQuaternion<T>>>,
    /// `hexanion-linear`: the segment's two end hexanions.
    pub hexanions: Option<[Hexanion<T>; 2]>,
}

/// The trajectory of a body point over one segment `[t0, t1]` of a rational method, as a
/// rational Bézier curve in the segment's local parameter `u = (t - t0)/(t1 - t0)` on `[0, 1]`.
///
/// ```
/// use motion::{Pose, method::{Method, MethodInput}};
/// let poses = vec![Pose::<f64>::identity(), Pose::translation(&[2.0, 0.0, 0.0])];
/// let m = Method::JuttlerQMotion.build(&MethodInput::new(poses))?;
/// let seg = &m.rational_trajectories(&[0.0, 0.0, 0.0])?[0];
/// assert_eq!((seg.t0, seg.t1, seg.curve.degree()), (0.0, 1.0, 4));
/// assert!((seg.curve.point(&0.5)?[0] - 1.0).abs() < 1e-15);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct RationalSegment<T> {
    /// Start of the segment's parameter interval.
    pub t0: T,
    /// End of the segment's parameter interval.
    pub t1: T,
    /// The trajectory on `[0, 1]`.
    pub curve: RationalBezier<T>,
}

/// The motion a method builds, one variant per family of motions; a [`Motion`] over
/// `[t_0, t_m]` (what [`BuiltMotion`]'s `map_scalar` returns).
///
/// ```
/// use motion::{Motion, Pose, method::{Method, MethodInput, MethodMotion}};
/// let poses = vec![Pose::<f64>::identity(), Pose::translation(&[1.0, 0.0, 0.0])];
/// let m = Method::HexanionLinear.build(&MethodInput::new(poses))?;
/// assert!(matches!(m.motion(), MethodMotion::Hexanion(_)));
/// assert_eq!(m.motion().domain(), [0.0, 1.0]);
/// # Ok::<(), motion::method::BuildError>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub enum MethodMotion<T: Ring> {
    /// `ccm-additive`, `ccm-multiplicative`: Bézier segments at the breakpoints `t_i`.
    Bezier(Piecewise<T, AnyMotion<T>>),
    /// `wl-linear`, `wl-quadratic`.
    Wl(WlMotion<T>),
    /// `hexanion-linear`.
    Hexanion(HexanionLinear<T>),
    /// `hexanion-decoupled`.
    Decoupled(HexanionDecoupled<T>),
    /// `juttler-q-motion`, `juttler-trt`, `juttler-spline`: Q-motions (eq. 13) at their
    /// breakpoints (one segment for Algorithm 1 and TRT, one per interval for Algorithm 2).
    QMotions(Piecewise<T, QMotion<T>>),
    /// `juttler-minimal`: the rational motion of minimal order (35) over `[t_0, t_m]`.
    Minimal(Piecewise<T, MinimalMotion<T>>),
}

impl<T: Real> Motion<T> for MethodMotion<T> {
    fn evaluate(&self, t: &T) -> Result<Pose<T>, CurveError> {
        match self {
            MethodMotion::Bezier(m) => m.evaluate(t),
            MethodMotion::Wl(m) => m.evaluate(t),
            MethodMotion::Hexanion(m) => m.evaluate(t),
            MethodMotion::Decoupled(m) => m.evaluate(t),
            MethodMotion::QMotions(m) => m.evaluate(t),
            MethodMotion::Minimal(m) => m.evaluate(t),
        }
    }

    fn domain(&self) -> [T; 2] {
        match self {
            MethodMotion::Bezier(m) => m.domain(),
            MethodMotion::Wl(m) => m.domain(),
            MethodMotion::Hexanion(m) => m.domain(),
            MethodMotion::Decoupled(m) => m.domain(),
            MethodMotion::QMotions(m) => m.domain(),
            MethodMotion::Minimal(m) => m.domain(),
        }
    }
}

impl<T: Real, U: Real> MapScalar<T, U> for MethodMotion<T> {
    type Mapped = MethodMotion<U>;
    fn map_scalar(&self, f: &dyn Fn(&T) -> U) -> MethodMotion<U> {
        match self {
            MethodMotion::Bezier(m) => MethodMotion::Bezier(m.map_scalar(f)),
            MethodMotion::Wl(m) => MethodMotion::Wl(m.map_scalar(f)),
            MethodMotion::Hexanion(m) => MethodMotion::Hexanion(m.map_scalar(f)),
            MethodMotion::Decoupled(m) => MethodMotion::Decoupled(m.map_scalar(f)),
            MethodMotion::QMotions(m) => MethodMotion::QMotions(m.map_scalar(f)),
            MethodMotion::Minimal(m) => MethodMotion::Minimal(m.map_scalar(f)),
        }
    }
}

/// The motion of a method through key poses ([`Method::build`]): the method, the parameters
/// `t_0 < ... < t_m`, the sign-aligned key poses, the segments and the motion itself.
///
/// ```
/// use motion::{Motion, Pose, method::{Method, MethodInput}};
/// let poses = vec![Pose::<f64>::identity(), Pose::translation(&[1.0, 0.0, 0.0]), Pose::translation(&[1.0, 1.0, 0.0])];
/// let m = Method::WlQuadratic.build(&MethodInput::new(poses))?;
/// assert_eq!((m.method(), m.segments().len(), m.max_degree()), (Method::WlQuadratic, 2, 2));
/// let s = m.sample(&1.0, &[[0.0; 3]])?;
/// assert!((s.points[0].position[1] - 1.0).abs() < 1e-14);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct BuiltMotion<T: Ring> {
    pub(super) method: Method,
    pub(super) times: Vec<T>,
    pub(super) key_poses: Vec<Pose<T>>,
    pub(super) segments: Vec<MethodSegment<T>>,
    pub(super) motion: MethodMotion<T>,
}

impl<T: Real> BuiltMotion<T> {
    /// The method that built it.
    pub fn method(&self) -> Method {
        self.method
    }

    /// The parameters `t_0 < ... < t_m` of the key poses.
    pub fn times(&self) -> &[T] {
        &self.times
    }

    /// The key poses after sign alignment.
    pub fn key_poses(&self) -> &[Pose<T>] {
        &self.key_poses
    }

    /// The segments, in order.
    pub fn segments(&self) -> &[MethodSegment<T>] {
        &self.segments
    }

    /// The largest segment degree (the sampling work of `gam interpolate` is counted with it).
    pub fn max_degree(&self) -> usize {
        self.segments.iter().map(|s| s.degree).max().unwrap_or(0)
    }

    /// The motion.
    pub fn motion(&self) -> &MethodMotion<T> {
        &self.motion
    }

    /// Pose, twists, twist rate and the kinematics of `body_points` at `t`
    /// ([`sample_motion`]: one evaluation over second-order dual numbers).
    pub fn sample(&self, t: &T, body_points: &[[T; 3]]) -> Result<TrajectorySample<T>, TrajectoryError> {
        sample_motion(&self.motion, t, body_points)
    }

    /// The trajectory of the body point `x` (body coordinates) as one rational Bézier curve
    /// per segment (through [`RationalMotion`]); [`BuildError::NotRational`] for the methods
    /// whose motions are not rational ([`Method::is_rational`]).
    ///
    /// ```
    /// use motion::{Pose, method::{BuildError, Method, MethodInput}};
    /// let poses = vec![Pose::<f64>::identity(), Pose::translation(&[1.0, 0.0, 0.0])];
    /// let m = Method::CcmMultiplicative.build(&MethodInput::new(poses))?;
    /// assert!(matches!(m.rational_trajectories(&[0.0; 3]), Err(BuildError::NotRational { .. })));
    /// # Ok::<(), BuildError>(())
    /// ```
    pub fn rational_trajectories(&self, x: &[T; 3]) -> Result<Vec<RationalSegment<T>>, BuildError> {
        let not_rational = || BuildError::NotRational { method: self.method.name() };
        match &self.motion {
            MethodMotion::QMotions(p) => rational_segments(p, x),
            MethodMotion::Minimal(p) => rational_segments(p, x),
            MethodMotion::Bezier(p) if self.method.is_rational() => p
                .segments()
                .iter()
                .zip(p.breaks().windows(2))
                .map(|(m, w)| match m {
                    AnyMotion::AdditiveBezier(b) => {
                        Ok(RationalSegment { t0: w[0].clone(), t1: w[1].clone(), curve: b.rational_trajectory(x)? })
                    }
                    _ => Err(not_rational()),
                })
                .collect(),
            _ => Err(not_rational()),
        }
    }
}

/// The rational trajectories of `x` under the segments of a piecewise rational motion.
fn rational_segments<T: Real, M: RationalMotion<T> + Motion<T>>(
    p: &Piecewise<T, M>,
    x: &[T; 3],
) -> Result<Vec<RationalSegment<T>>, BuildError> {
    p.segments()
        .iter()
        .zip(p.breaks().windows(2))
        .map(|(m, w)| Ok(RationalSegment { t0: w[0].clone(), t1: w[1].clone(), curve: m.rational_trajectory(x)? }))
        .collect()
}

impl<T: Real> Motion<T> for BuiltMotion<T> {
    fn evaluate(&self, t: &T) -> Result<Pose<T>, CurveError> {
        self.motion.evaluate(t)
    }

    fn domain(&self) -> [T; 2] {
        self.motion.domain()
    }
}

impl<T: Real, U: Real> MapScalar<T, U> for BuiltMotion<T> {
    type Mapped = MethodMotion<U>;
    fn map_scalar(&self, f: &dyn Fn(&T) -> U) -> MethodMotion<U> {
        self.motion.map_scalar(f)
    }
}
