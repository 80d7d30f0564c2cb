//! What [`super::Method::build`] returns: a [`BuiltMotion`], a [`Motion`] over `[t_0, t_m]`
//! that knows its segments ([`MethodSegment`]: the contract's `segments[]`), samples itself
//! ([`BuiltMotion::sample`]) and gives the rational Bézier trajectories of body points where
//! the method's motions are rational ([`BuiltMotion::rational_trajectories`], `gam
//! trajectory`); its motion is one [`MethodMotion`] enum over the families of motions the
//! methods build.

use super::{BuildError, Method};
use crate::juttler::minimal::MinimalMotion;
use crate::juttler::surface::RationalBezierSurface;
use crate::juttler::{JuttlerError, QMotion, RationalBezier, RationalMotion};
use crate::repr::dual_quaternion::DualQuaternion;
use crate::repr::hexanion::Hexanion;
use crate::repr::hexanion::blend::{HexanionBlend, HexanionDecoupled, HexanionLinear};
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
    /// `hexanion-blend`.
    Blend(HexanionBlend<T>),
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
            MethodMotion::Blend(m) => m.evaluate(t),
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
            MethodMotion::Blend(m) => m.domain(),
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
            MethodMotion::Blend(m) => MethodMotion::Blend(m.map_scalar(f)),
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
        self.rational_pieces(&|m| m.rational_trajectory(x))
            .map(|v| v.into_iter().map(|(t0, t1, curve)| RationalSegment { t0, t1, curve }).collect())
    }

    /// The kinematic (sweep) surface of the rational curve `curve` (body coordinates) under
    /// each segment, as a rational tensor-product Bézier surface in (`u`, `v`), `u` the
    /// segment's local parameter (Jüttler Sec. 5, Fig. 5b:
    /// [`RationalBezierSurface::kinematic`]); [`BuildError::NotRational`] as for
    /// [`BuiltMotion::rational_trajectories`].
    ///
    /// ```
    /// use motion::{Pose, juttler::RationalBezier, method::{Method, MethodInput}};
    /// let poses = vec![Pose::<f64>::identity(), Pose::translation(&[0.0, 0.0, 2.0])];
    /// let m = Method::JuttlerQMotion.build(&MethodInput::new(poses))?;
    /// let segment = RationalBezier::new(vec![[1.0, 0.0, 0.0, 0.0], [1.0, 1.0, 0.0, 0.0]]).unwrap();
    /// let s = &m.kinematic_surfaces(&segment)?[0].surface;
    /// let p = s.point(&0.5, &0.5).unwrap();
    /// assert!((p[0] - 0.5).abs() < 1e-15 && p[1].abs() < 1e-15 && (p[2] - 1.0).abs() < 1e-15);
    /// # Ok::<(), motion::method::BuildError>(())
    /// ```
    pub fn kinematic_surfaces(&self, curve: &RationalBezier<T>) -> Result<Vec<SurfaceSegment<T>>, BuildError> {
        self.rational_pieces(&|m| RationalBezierSurface::kinematic(m, curve))
            .map(|v| v.into_iter().map(|(t0, t1, surface)| SurfaceSegment { t0, t1, surface }).collect())
    }

    /// `f` of each segment's rational motion, with the segment's interval.
    fn rational_pieces<R>(
        &self,
        f: &dyn Fn(&dyn RationalMotion<T>) -> Result<R, JuttlerError>,
    ) -> Result<Vec<(T, T, R)>, BuildError> {
        let not_rational = || BuildError::NotRational { method: self.method.name() };
        let pieces: Vec<(&dyn RationalMotion<T>, &[T])> = match &self.motion {
            MethodMotion::QMotions(p) => pieces_of(p),
            MethodMotion::Minimal(p) => pieces_of(p),
            MethodMotion::Bezier(p) if self.method.is_rational() => p
                .segments()
                .iter()
                .zip(p.breaks().windows(2))
                .map(|(m, w)| match m {
                    AnyMotion::AdditiveBezier(b) => Ok((b as &dyn RationalMotion<T>, w)),
                    _ => Err(not_rational()),
                })
                .collect::<Result<_, _>>()?,
            _ => return Err(not_rational()),
        };
        pieces.into_iter().map(|(m, w)| Ok((w[0].clone(), w[1].clone(), f(m)?))).collect()
    }
}

/// The segments of a piecewise rational motion with their intervals.
fn pieces_of<T: Real, M: RationalMotion<T> + Motion<T>>(p: &Piecewise<T, M>) -> Vec<(&dyn RationalMotion<T>, &[T])> {
    p.segments().iter().map(|m| m as &dyn RationalMotion<T>).zip(p.breaks().windows(2)).collect()
}

/// The kinematic surface of a rational curve under one segment `[t0, t1]` of a rational
/// method ([`BuiltMotion::kinematic_surfaces`], [`super::ExactMotion::kinematic_surfaces`]).
///
/// ```
/// use algebra_core::rational::q;
/// use motion::{Pose, juttler::RationalBezier, method::{Method, MethodInput}};
/// let poses = vec![Pose::translation(&[q(0), q(0), q(0)]), Pose::translation(&[q(0), q(0), q(2)])];
/// let m = Method::JuttlerAffine.build_exact(&MethodInput::new(poses))?;
/// let point = RationalBezier::new(vec![[q(1), q(1), q(0), q(0)]]).unwrap();
/// let s = &m.kinematic_surfaces(&point)?[0];
/// assert_eq!((s.t0.clone(), s.t1.clone(), s.surface.degrees()), (q(0), q(1), (4, 0)));
/// # Ok::<(), motion::method::BuildError>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct SurfaceSegment<T> {
    /// The segment's first parameter.
    pub t0: T,
    /// Its last parameter.
    pub t1: T,
    /// The surface, `u` along the segment's local parameter, `v` the curve's.
    pub surface: RationalBezierSurface<T>,
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
