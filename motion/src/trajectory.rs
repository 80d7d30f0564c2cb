//! A C1 motion through key poses in one call, and a sampler for it.
//!
//! [`Trajectory::through`] takes key poses `S_0..S_m` at strictly increasing times
//! `t_0 < ... < t_m`, a [`Velocities`] policy, the [`SegmentKind`] and the shape factors, and
//! builds one cubic Hermite segment per interval (Sec. 5.3 of the main paper, eqs. 22-23 with
//! `Ψ = h λ(ν + γ)` for an interval of length `h`, [`crate::hermite::hermite_with_parameters`]),
//! joined into one [`Piecewise`] motion over `[t_0, t_m]`. Before anything else the key poses
//! are sign-aligned ([`align_signs`]: `S` and `-S` are the same rigid motion, but an additive
//! segment from `S` to `-S` passes through 0 and a multiplicative one turns the long way). Every
//! inner join is then checked to be C1 in `t` (same pose, same velocity bivector `ν` from the
//! left and from the right, by dual numbers): [`Trajectory::joins`].
//!
//! Velocities are space twists ([`Twist`]: `ν = Ω e123 + u einf`, `u` the velocity of the body
//! point at the global origin, Theorem 3.2), per unit of `t`:
//! * [`Velocities::Given`]: one twist per key pose;
//! * [`Velocities::CatmullRom`] (the estimate): zero at the two ends; at an inner pose, the
//!   one-sided twists of the screw motions to the neighbours,
//!   `ν⁻ = 2 log(S_{i-1}⁻¹ S_i)/(t_i - t_{i-1})` and `ν⁺ = 2 log(S_i⁻¹ S_{i+1})/(t_{i+1} - t_i)`
//!   (the constant `Ψ` of `S_{i-1} exp(τ L)`, bivector part), weighted as the derivative of a
//!   quadratic through three points: `ν_i = (h⁺ ν⁻ + h⁻ ν⁺)/(h⁻ + h⁺)` (equal weights for
//!   uniform times: Catmull-Rom in the Lie algebra);
//! * [`Velocities::Zero`]: at rest at every key pose.
//!
//! [`Trajectory::sample`] gives, at one `t`, the pose, the space and body twists, the rate of
//! change of the space twist and position, velocity and acceleration of chosen body points, all
//! from ONE evaluation of the motion over second-order dual numbers ([`acceleration`]).
//!
//! ```
//! use motion::trajectory::{Trajectory, Velocities};
//! use motion::{HermiteShapes, Pose, SegmentKind};
//! let z = [0.0, 0.0, 1.0];
//! let poses = [Pose::<f64>::identity(), Pose::from_axis_angle_translation(&z, &1.0, &[1.0, 0.0, 0.0])?,
//!     Pose::from_axis_angle_translation(&z, &2.0, &[1.0, 1.0, 0.0])?];
//! let tr = Trajectory::through(&poses, &[0.0, 1.0, 3.0], &Velocities::CatmullRom, SegmentKind::Multiplicative,
//!     &HermiteShapes::unit())?;
//! assert!(tr.joins().iter().all(|j| j.is_c1(1e-12)));
//! let s = tr.sample(&2.0, &[[0.0, 0.0, 0.0]])?;
//! assert_eq!(s.points.len(), 1);
//! # Ok::<(), motion::trajectory::TrajectoryError>(())
//! ```

use crate::bezier::{CurveError, MapScalar, Motion};
use crate::hermite::{AnyHermiteSegment, HermiteShapes, hermite_with_parameters};
use crate::joins::{EndCondition, JoinError, SegmentKind};
use crate::piecewise::{AnyMotion, Piecewise};
use crate::pose::is_positive;
use crate::velocity::{PointKinematics, Twist, acceleration, velocity};
use crate::{MotionError, Pose, Vec3};
use algebra_core::Jet;
use algebra_core::{Real, Ring};

/// How the velocities at the key poses are chosen (module docs).
///
/// ```
/// use motion::{trajectory::Velocities, velocity::Twist};
/// let given = Velocities::Given(vec![Twist { angular: [0.0; 3].into(), linear: [1.0, 0.0, 0.0].into() }; 2]);
/// assert!(matches!(given, Velocities::Given(ref v) if v.len() == 2));
/// ```
#[derive(Clone, Debug, PartialEq)]
pub enum Velocities<T> {
    /// One space twist per key pose (per unit of `t`).
    Given(Vec<Twist<T>>),
    /// Zero at the ends, the weighted mean of the one-sided screw twists inside.
    CatmullRom,
    /// Zero at every key pose.
    Zero,
}

/// Why a trajectory could not be built or sampled.
///
/// ```
/// use motion::trajectory::{Trajectory, TrajectoryError, Velocities};
/// use motion::{HermiteShapes, Pose, SegmentKind};
/// let e = Trajectory::through(&[Pose::<f64>::identity()], &[0.0], &Velocities::Zero, SegmentKind::Additive,
///     &HermiteShapes::unit());
/// assert!(matches!(e, Err(TrajectoryError::Input(_))));
/// ```
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum TrajectoryError {
    /// Too few poses, lists of the wrong length, times not finite and increasing.
    #[error("{0}")]
    Input(String),
    /// A segment could not be built.
    #[error(transparent)]
    Join(#[from] JoinError),
    /// A pose operation failed (singular pose, overflow).
    #[error(transparent)]
    Motion(#[from] MotionError),
    /// Evaluating the motion failed (outside its domain, singular pose).
    #[error(transparent)]
    Curve(#[from] CurveError),
    /// A join that is not C1 (only with per-segment shapes, which give G1 joins).
    #[error("the join at t = {time} is not C1 (largest jump in the velocity bivector {jump:e})")]
    NotC1 {
        /// The key time of the join.
        time: f64,
        /// The largest component of the jump in `ν`.
        jump: f64,
    },
}

/// Sign alignment of consecutive key poses (Jüttler's rule (24)): each pose after the first is
/// negated when its rotation part (`1, e12, e13, e23`) has a negative dot product with its
/// predecessor's (all 8 components when the rotation dot product is zero). `S` and `-S` are the
/// same rigid motion.
///
/// ```
/// use motion::{Pose, trajectory::align_signs};
/// let a = Pose::<f64>::rotation(&[0.0, 0.0, 1.0], &3.0)?;
/// let b = Pose::<f64>::rotation(&[0.0, 0.0, 1.0], &-3.0)?; // the short way from a is through π
/// let mut poses = vec![a, b.clone()];
/// align_signs(&mut poses);
/// assert_eq!(poses[1], -&b);
/// # Ok::<(), motion::MotionError>(())
/// ```
pub fn align_signs<T: Ring + PartialOrd>(poses: &mut [Pose<T>]) {
    for i in 1..poses.len() {
        let (a, b) = (poses[i - 1].components(), poses[i].components());
        let dot = |range: std::ops::Range<usize>| range.fold(T::zero(), |acc, k| acc.add_ref(&a[k].mul_ref(b[k])));
        let rot = dot(0..4);
        let d = if rot.magnitude() == 0.0 { dot(0..8) } else { rot };
        if is_positive(&d.neg_ref()) {
            poses[i] = -&poses[i];
        }
    }
}

/// One inner join of a trajectory, checked from both sides (values from dual numbers).
///
/// ```
/// let j = motion::trajectory::JoinReport { time: 1.0, pose_gap: 0.0, nu_jump: 1e-15, scale: 1.0 };
/// assert!(j.is_c1(1e-12));
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct JoinReport {
    /// The key time `t_i`.
    pub time: f64,
    /// The largest component of `S(t_i⁻) - S(t_i⁺)`.
    pub pose_gap: f64,
    /// The largest component of `ν(t_i⁻) - ν(t_i⁺)`.
    pub nu_jump: f64,
    /// The largest component of `S(t_i)` and `ν(t_i)` (for a relative tolerance).
    pub scale: f64,
}

impl JoinReport {
    /// Both gaps within `tol` relative to `1 + scale`.
    ///
    /// ```
    /// let j = motion::trajectory::JoinReport { time: 1.0, pose_gap: 0.0, nu_jump: 0.1, scale: 1.0 };
    /// assert!(!j.is_c1(1e-9));
    /// ```
    pub fn is_c1(&self, tol: f64) -> bool {
        self.pose_gap.max(self.nu_jump) <= tol * (1.0 + self.scale)
    }
}

/// Everything the sampler gives at one `t`.
///
/// ```
/// # use motion::trajectory::{Trajectory, Velocities};
/// # use motion::{HermiteShapes, Pose, SegmentKind};
/// let tr = Trajectory::through(&[Pose::<f64>::identity(), Pose::translation(&[2.0, 0.0, 0.0])], &[0.0, 1.0],
///     &Velocities::Zero, SegmentKind::Additive, &HermiteShapes::unit())?;
/// let s = tr.sample(&0.5, &[[0.0, 0.0, 0.0]])?;
/// assert!((s.points[0].position[0] - 1.0).abs() < 1e-15); // halfway, by symmetry
/// assert!((s.space_twist.linear[0] - 3.0).abs() < 1e-14); // cubic ease: peak speed 1.5 × 2
/// # Ok::<(), motion::trajectory::TrajectoryError>(())
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct TrajectorySample<T: Ring> {
    /// The parameter.
    pub t: T,
    /// `S(t)` (not unitized: additive motions are not unitary between key poses).
    pub pose: Pose<T>,
    /// The space twist `(Ω, u)` of `ν` (Theorem 3.2).
    pub space_twist: Twist<T>,
    /// The body twist: `Ω` and the velocity of the body origin, both in body coordinates
    /// (`R^T Ω`, `R^T v_0` with `R` the rotation of `F_S`).
    pub body_twist: Twist<T>,
    /// `(dΩ/dt, du/dt)`, from `dν/dt`.
    pub space_twist_derivative: Twist<T>,
    /// Position, velocity and acceleration of each body point asked for.
    pub points: Vec<PointKinematics<T>>,
}

/// A C1 motion through key poses (module docs).
#[derive(Clone, Debug, PartialEq)]
pub struct Trajectory<T: Ring> {
    kind: SegmentKind,
    poses: Vec<Pose<T>>,
    twists: Vec<Twist<T>>,
    segments: Vec<AnyHermiteSegment<T>>,
    motion: Piecewise<T, AnyMotion<T>>,
}

impl<T: Real> Trajectory<T> {
    /// Builds the motion through `poses` at `times` (module docs); fails with a typed error for
    /// bad input and when a join is not C1 within `1e-9` relative (per-segment shapes).
    ///
    /// The key poses are used as given, not unitized: a multiple `λS` is the same pose, but its
    /// scale enters the segments as a weight (by design, docs/robustness.md). For the same
    /// motion whatever multiples the key poses come as, unitize them first, as
    /// [`crate::method::Method::build`] (the CLI, the Python package) does.
    ///
    /// ```
    /// use motion::trajectory::{Trajectory, Velocities};
    /// use motion::{HermiteShapes, Motion, Pose, SegmentKind};
    /// let poses = [Pose::<f64>::identity(), Pose::translation(&[1.0, 0.0, 0.0]), Pose::translation(&[1.0, 1.0, 0.0])];
    /// let tr = Trajectory::through(&poses, &[0.0, 1.0, 2.0], &Velocities::CatmullRom, SegmentKind::Additive,
    ///     &HermiteShapes::unit())?;
    /// assert_eq!(tr.motion().domain(), [0.0, 2.0]);
    /// assert_eq!(tr.key_twists()[1].linear, [0.5, 0.5, 0.0]); // the mean of (1, 0, 0) and (0, 1, 0)
    /// # Ok::<(), motion::trajectory::TrajectoryError>(())
    /// ```
    pub fn through(
        poses: &[Pose<T>],
        times: &[T],
        velocities: &Velocities<T>,
        kind: SegmentKind,
        shapes: &HermiteShapes<T>,
    ) -> Result<Self, TrajectoryError> {
        let m = poses.len();
        if m < 2 {
            return Err(TrajectoryError::Input(format!("at least two key poses are needed (got {m})")));
        }
        if times.len() != m {
            return Err(TrajectoryError::Input(format!("{} times given for {m} key poses", times.len())));
        }
        let mut poses = poses.to_vec();
        align_signs(&mut poses);
        let twists = match velocities {
            Velocities::Given(v) if v.len() == m => v.clone(),
            Velocities::Given(v) => {
                return Err(TrajectoryError::Input(format!("{} velocities given for {m} key poses", v.len())));
            }
            Velocities::Zero => vec![zero_twist(); m],
            Velocities::CatmullRom => catmull_rom(&poses, times)?,
        };
        let conditions = poses
            .iter()
            .zip(&twists)
            .map(|(s, w)| {
                let p = s.transform_point(&[T::zero(), T::zero(), T::zero()])?;
                let v = w.point_velocity(&p);
                Ok(EndCondition::new(s.clone(), p, v.into(), w.angular.to_array()))
            })
            .collect::<Result<Vec<_>, MotionError>>()?;
        let segments = hermite_with_parameters(kind, 3, &conditions, times, shapes)?;
        let pieces = segments.iter().map(|seg| seg.clone().into_motion()).collect::<Result<Vec<_>, CurveError>>()?;
        let motion = Piecewise::new(times.to_vec(), pieces)?;
        let tr = Trajectory { kind, poses, twists, segments, motion };
        if !matches!(shapes, HermiteShapes::PerSegment(_)) {
            for j in tr.joins() {
                if !j.is_c1(1e-9) {
                    return Err(TrajectoryError::NotC1 { time: j.time, jump: j.nu_jump.max(j.pose_gap) });
                }
            }
        }
        Ok(tr)
    }

    /// The motion over `[t_0, t_m]`.
    ///
    /// ```
    /// # use motion::trajectory::{Trajectory, Velocities};
    /// # use motion::{HermiteShapes, Motion, Pose, SegmentKind};
    /// let tr = Trajectory::through(&[Pose::<f64>::identity(), Pose::translation(&[1.0, 0.0, 0.0])], &[2.0, 3.0],
    ///     &Velocities::Zero, SegmentKind::Multiplicative, &HermiteShapes::unit())?;
    /// assert_eq!(tr.motion().pose(&3.0)?, Pose::translation(&[1.0, 0.0, 0.0]));
    /// # Ok::<(), motion::trajectory::TrajectoryError>(())
    /// ```
    pub fn motion(&self) -> &Piecewise<T, AnyMotion<T>> {
        &self.motion
    }

    /// The Hermite segments (control poses, end indicatrices), one per interval.
    ///
    /// ```
    /// # use motion::trajectory::{Trajectory, Velocities};
    /// # use motion::{HermiteShapes, Pose, SegmentKind};
    /// let tr = Trajectory::through(&[Pose::<f64>::identity(), Pose::translation(&[1.0, 0.0, 0.0])], &[0.0, 1.0],
    ///     &Velocities::Zero, SegmentKind::Additive, &HermiteShapes::unit())?;
    /// assert_eq!(tr.segments()[0].control_poses()[1], Pose::identity()); // at rest: S1 = S0
    /// # Ok::<(), motion::trajectory::TrajectoryError>(())
    /// ```
    pub fn segments(&self) -> &[AnyHermiteSegment<T>] {
        &self.segments
    }

    /// The key poses after sign alignment.
    ///
    /// ```
    /// # use motion::trajectory::{Trajectory, Velocities};
    /// # use motion::{HermiteShapes, Pose, SegmentKind};
    /// let b = -&Pose::<f64>::translation(&[1.0, 0.0, 0.0]);
    /// let tr = Trajectory::through(&[Pose::identity(), b.clone()], &[0.0, 1.0], &Velocities::Zero,
    ///     SegmentKind::Additive, &HermiteShapes::unit())?;
    /// assert_eq!(tr.key_poses()[1], -&b);
    /// # Ok::<(), motion::trajectory::TrajectoryError>(())
    /// ```
    pub fn key_poses(&self) -> &[Pose<T>] {
        &self.poses
    }

    /// The space twist used at each key pose (given or estimated).
    ///
    /// ```
    /// # use motion::trajectory::{Trajectory, Velocities};
    /// # use motion::{HermiteShapes, Pose, SegmentKind};
    /// let tr = Trajectory::through(&[Pose::<f64>::identity(), Pose::translation(&[1.0, 0.0, 0.0])], &[0.0, 1.0],
    ///     &Velocities::CatmullRom, SegmentKind::Additive, &HermiteShapes::unit())?;
    /// assert_eq!(tr.key_twists()[0].linear, [0.0; 3]); // zero at the ends
    /// # Ok::<(), motion::trajectory::TrajectoryError>(())
    /// ```
    pub fn key_twists(&self) -> &[Twist<T>] {
        &self.twists
    }

    /// Additive or multiplicative.
    ///
    /// ```
    /// # use motion::trajectory::{Trajectory, Velocities};
    /// # use motion::{HermiteShapes, Pose, SegmentKind};
    /// let tr = Trajectory::through(&[Pose::<f64>::identity(), Pose::identity()], &[0.0, 1.0],
    ///     &Velocities::Zero, SegmentKind::Additive, &HermiteShapes::unit())?;
    /// assert_eq!(tr.kind(), SegmentKind::Additive);
    /// # Ok::<(), motion::trajectory::TrajectoryError>(())
    /// ```
    pub fn kind(&self) -> SegmentKind {
        self.kind
    }

    /// Each inner join checked from both sides: the pose and `ν` of segment `k - 1` at `t_k`
    /// against those of segment `k` (dual numbers, [`velocity`]).
    ///
    /// ```
    /// # use motion::trajectory::{Trajectory, Velocities};
    /// # use motion::{HermiteShapes, Pose, SegmentKind};
    /// let poses = [Pose::<f64>::identity(), Pose::translation(&[1.0, 0.0, 0.0]), Pose::translation(&[1.0, 2.0, 0.0])];
    /// let tr = Trajectory::through(&poses, &[0.0, 1.0, 4.0], &Velocities::CatmullRom, SegmentKind::Multiplicative,
    ///     &HermiteShapes::unit())?;
    /// assert_eq!(tr.joins().len(), 1);
    /// assert!(tr.joins()[0].is_c1(1e-12));
    /// # Ok::<(), motion::trajectory::TrajectoryError>(())
    /// ```
    pub fn joins(&self) -> Vec<JoinReport> {
        let breaks = self.motion.breaks();
        (1..self.segments.len())
            .map(|k| {
                let t = &breaks[k];
                let side = |j: usize| self.motion.piece(j).and_then(|p| velocity(&p, t).ok());
                match (side(k - 1), side(k)) {
                    (Some(l), Some(r)) => {
                        let (sl, sr) = (l.pose.components(), r.pose.components());
                        let (nl, nr) = (l.nu(), r.nu());
                        let (nl, nr) = (Pose::from(&nl), Pose::from(&nr));
                        let (nl, nr) = (nl.components(), nr.components());
                        let gap =
                            |a: [&T; 8], b: [&T; 8]| (0..8).map(|i| a[i].sub_ref(b[i]).magnitude()).fold(0.0, f64::max);
                        let size = sl.iter().chain(&nl).map(|x| x.magnitude()).fold(0.0, f64::max);
                        JoinReport { time: t.to_f64(), pose_gap: gap(sl, sr), nu_jump: gap(nl, nr), scale: size }
                    }
                    _ => JoinReport { time: t.to_f64(), pose_gap: f64::NAN, nu_jump: f64::NAN, scale: 0.0 },
                }
            })
            .collect()
    }

    /// The pose, twists, twist rate and body-point kinematics at `t` (body points in body
    /// coordinates), from one second-order dual-number evaluation.
    ///
    /// ```
    /// # use motion::trajectory::{Trajectory, Velocities};
    /// # use motion::{HermiteShapes, Pose, SegmentKind};
    /// let tr = Trajectory::through(&[Pose::<f64>::identity(), Pose::translation(&[1.0, 0.0, 0.0])], &[0.0, 1.0],
    ///     &Velocities::Zero, SegmentKind::Additive, &HermiteShapes::unit())?;
    /// assert!(tr.sample(&1.5, &[]).is_err()); // outside [0, 1]
    /// # Ok::<(), motion::trajectory::TrajectoryError>(())
    /// ```
    pub fn sample(&self, t: &T, body_points: &[[T; 3]]) -> Result<TrajectorySample<T>, TrajectoryError> {
        sample_motion(&self.motion, t, body_points)
    }

    /// [`Trajectory::sample`] at `n ≥ 2` evenly spaced times from `t_0` to `t_m` (both ends).
    ///
    /// ```
    /// # use motion::trajectory::{Trajectory, Velocities};
    /// # use motion::{HermiteShapes, Pose, SegmentKind};
    /// let tr = Trajectory::through(&[Pose::<f64>::identity(), Pose::translation(&[1.0, 0.0, 0.0])], &[0.0, 2.0],
    ///     &Velocities::Zero, SegmentKind::Additive, &HermiteShapes::unit())?;
    /// let s = tr.sample_evenly(5, &[])?;
    /// assert_eq!(s.iter().map(|x| x.t).collect::<Vec<_>>(), [0.0, 0.5, 1.0, 1.5, 2.0]);
    /// # Ok::<(), motion::trajectory::TrajectoryError>(())
    /// ```
    pub fn sample_evenly(&self, n: usize, body_points: &[[T; 3]]) -> Result<Vec<TrajectorySample<T>>, TrajectoryError> {
        if n < 2 {
            return Err(TrajectoryError::Input(format!("at least two samples are needed (got {n})")));
        }
        let [t0, t1] = self.motion.domain();
        let span = t1.sub_ref(&t0);
        (0..n)
            .map(|i| {
                let t = if i + 1 == n {
                    t1.clone()
                } else {
                    t0.add_ref(&span.mul_ref(&T::from_ratio(i as i64, n as i64 - 1)))
                };
                self.sample(&t, body_points)
            })
            .collect()
    }

    /// [`Trajectory::sample`] at a fixed rate (samples per unit of `t`, e.g. 1000 for 1 kHz
    /// with `t` in seconds): `t_0 + k/rate` for every `k` with `t_0 + k/rate ≤ t_m`.
    ///
    /// ```
    /// # use motion::trajectory::{Trajectory, Velocities};
    /// # use motion::{HermiteShapes, Pose, SegmentKind};
    /// let tr = Trajectory::through(&[Pose::<f64>::identity(), Pose::translation(&[1.0, 0.0, 0.0])], &[0.0, 1.0],
    ///     &Velocities::Zero, SegmentKind::Additive, &HermiteShapes::unit())?;
    /// assert_eq!(tr.sample_at_rate(10.0, &[])?.len(), 11);
    /// # Ok::<(), motion::trajectory::TrajectoryError>(())
    /// ```
    pub fn sample_at_rate(
        &self,
        rate: f64,
        body_points: &[[T; 3]],
    ) -> Result<Vec<TrajectorySample<T>>, TrajectoryError> {
        let [t0, t1] = self.motion.domain();
        let span = t1.sub_ref(&t0).to_f64();
        let count = span * rate;
        if !(rate > 0.0 && count.is_finite() && count < 1e9) {
            return Err(TrajectoryError::Input(format!(
                "the rate must be positive and give fewer than 1e9 samples (got {rate})"
            )));
        }
        let n = (count * (1.0 + 1e-12)).floor() as usize + 1;
        (0..n).map(|k| self.sample(&t0.add_ref(&T::from_f64(k as f64 / rate)), body_points)).collect()
    }
}

fn zero_twist<T: Ring>() -> Twist<T> {
    Twist { angular: Vec3::zero(), linear: Vec3::zero() }
}

/// The [`Velocities::CatmullRom`] estimate (module docs).
fn catmull_rom<T: Real>(poses: &[Pose<T>], times: &[T]) -> Result<Vec<Twist<T>>, TrajectoryError> {
    let m = poses.len();
    // The twist of the screw motion from pose k to pose k + 1 over its interval.
    let screw = |k: usize| -> Result<(Twist<T>, T), TrajectoryError> {
        let h = times[k + 1].sub_ref(&times[k]);
        let rel = &poses[k].try_inverse()? * &poses[k + 1];
        let l = rel.log_shortest()?;
        let w = Twist::from_bivector(&l.project_to_bivector());
        let s = T::from_i64(2).div_ref(&h);
        Ok((Twist { angular: w.angular.scale(&s), linear: w.linear.scale(&s) }, h))
    };
    let mut out = vec![zero_twist()];
    for i in 1..m - 1 {
        let (left, hl) = screw(i - 1)?;
        let (right, hr) = screw(i)?;
        let sum = hl.add_ref(&hr);
        let (wl, wr) = (hr.div_ref(&sum), hl.div_ref(&sum));
        let mix = |a: &Vec3<T>, b: &Vec3<T>| a.scale(&wl).add(&b.scale(&wr));
        out.push(Twist { angular: mix(&left.angular, &right.angular), linear: mix(&left.linear, &right.linear) });
    }
    out.push(zero_twist());
    Ok(out)
}

/// [`Trajectory::sample`] for any motion: the pose, twists, twist rate and body-point
/// kinematics at `t` (body points in body coordinates), from one second-order dual-number
/// evaluation ([`acceleration`]). Every method of `gam interpolate` is sampled by it
/// ([`crate::method::BuiltMotion::sample`]).
///
/// ```
/// use motion::{MultiplicativeBezier, Pose, trajectory::sample_motion};
/// let m = MultiplicativeBezier::new(vec![Pose::<f64>::identity(), Pose::translation(&[2.0, 0.0, 0.0])])?;
/// let s = sample_motion(&m, &0.5, &[[0.0, 1.0, 0.0]])?;
/// assert_eq!(s.points[0].position, [1.0, 1.0, 0.0]);
/// assert_eq!(s.points[0].velocity, [2.0, 0.0, 0.0]);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn sample_motion<T: Real, M: MapScalar<T, Jet<Jet<T>>>>(
    motion: &M,
    t: &T,
    body_points: &[[T; 3]],
) -> Result<TrajectorySample<T>, TrajectoryError> {
    let acc = acceleration(motion, t)?;
    let space = acc.velocity.twist();
    let rate = acc.twist_derivative();
    let body_twist = acc.velocity.body_twist()?;
    let pose = acc.velocity.pose;
    let points = body_points
        .iter()
        .map(|p| {
            let q = pose.transform_point(p)?;
            let v = space.point_velocity(&q);
            // d/dt (u + Ω × q) = du/dt + dΩ/dt × q + Ω × dq/dt.
            let a1 = rate.point_velocity(&q);
            let a = a1.add(&space.angular.cross(&v));
            Ok(PointKinematics { position: q, velocity: v.into(), acceleration: a.into() })
        })
        .collect::<Result<Vec<_>, MotionError>>()?;
    Ok(TrajectorySample { t: t.clone(), pose, space_twist: space, body_twist, space_twist_derivative: rate, points })
}
