//! Jacobians of a trajectory with respect to its key poses and key times, in one pass, by
//! multi-directional dual numbers.
//!
//! [`JetN<N>`] is `re + Σ eps_k ε_k` (`ε_j ε_k = 0`) over `f64`: a [`Real`] scalar carrying `N`
//! directional derivatives at once. [`key_sensitivity`] lifts the key poses and times of a
//! [`Trajectory`] to `JetN<N>` with `N = 7m` for `m` key poses — 6 se(3) directions per pose,
//! then one per time — builds the trajectory over `JetN` with the same code as over `f64` (the
//! velocity estimate, the joins and the segments all differentiate through), and evaluates a
//! body point and the space twist at `t`.
//!
//! Pose parameters: key pose `S_i` becomes `S_i exp(½ Σ_k δ_{6i+k} ν_k)` with `ν_0..ν_2 = e23,
//! -e13, e12` (unit angular velocity about x, y, z) and `ν_3..ν_5 = e1inf, e2inf, e3inf` (unit
//! velocity of the body point at the origin): a space-frame twist applied after `S_i`
//! (`U * V` applies `U` first), so `d/dδ` at 0 is the motion's response to moving the key pose
//! by that twist for unit time. Time parameter `δ_{6m+i}` moves `t_i`.
//!
//! ```
//! use motion::jacobian::key_sensitivity;
//! use motion::trajectory::Velocities;
//! use motion::{HermiteShapes, Pose, SegmentKind};
//! let poses = [Pose::<f64>::identity(), Pose::translation(&[1.0, 0.0, 0.0])];
//! let s = key_sensitivity::<14>(&poses, &[0.0, 1.0], &Velocities::Zero, SegmentKind::Additive,
//!     &HermiteShapes::unit(), 1.0, &[0.0; 3])?;
//! // At t = 1 the body origin is at the second key pose: moving that pose along x moves it 1:1.
//! assert!((s.position[0].eps[6 + 3] - 1.0).abs() < 1e-14);
//! assert!(s.position[0].eps[3].abs() < 1e-14); // the first pose does not matter there
//! # Ok::<(), motion::trajectory::TrajectoryError>(())
//! ```

use crate::hermite::HermiteShapes;
use crate::joins::{SegmentKind, Shape};
use crate::trajectory::{Trajectory, TrajectoryError, Velocities};
use crate::velocity::{Twist, velocity};
use crate::{Pose, Pseudoscalar, Vec3};
use algebra_core::rational::{Q, rational_to_f64};
use algebra_core::{Field, Jet, Real, Ring};
use std::cmp::Ordering;
use std::fmt;
use std::ops::{Add, Div, Mul, Neg, Sub};

/// A dual number with `N` independent infinitesimal directions, over `f64`.
///
/// ```
/// use motion::jacobian::JetN;
/// use algebra_core::Real;
/// let x = JetN::<2>::variable(3.0, 0);
/// let y = JetN::<2>::variable(2.0, 1);
/// let f = Real::sin(&(x * y)); // d/dx = y cos(xy), d/dy = x cos(xy)
/// assert!((f.eps[0] - 2.0 * 6f64.cos()).abs() < 1e-15 && (f.eps[1] - 3.0 * 6f64.cos()).abs() < 1e-15);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct JetN<const N: usize> {
    /// The value.
    pub re: f64,
    /// The derivatives along each direction.
    pub eps: [f64; N],
}

impl<const N: usize> JetN<N> {
    /// A constant (all derivatives zero).
    ///
    /// ```
    /// assert_eq!(motion::jacobian::JetN::<3>::constant(2.0).eps, [0.0; 3]);
    /// ```
    pub fn constant(re: f64) -> Self {
        JetN { re, eps: [0.0; N] }
    }

    /// The variable along direction `k`: `re + ε_k`.
    ///
    /// ```
    /// assert_eq!(motion::jacobian::JetN::<3>::variable(2.0, 1).eps, [0.0, 1.0, 0.0]);
    /// ```
    pub fn variable(re: f64, k: usize) -> Self {
        let mut eps = [0.0; N];
        eps[k] = 1.0;
        JetN { re, eps }
    }

    /// `f(self)` given `f(re)` and `f'(re)`.
    fn chain(&self, value: f64, d: f64) -> Self {
        JetN { re: value, eps: self.eps.map(|e| e * d) }
    }
}

impl<const N: usize> fmt::Display for JetN<N> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{} + {:?}ε", self.re, self.eps)
    }
}

impl<const N: usize> PartialOrd for JetN<N> {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        self.re.partial_cmp(&other.re)
    }
}

macro_rules! binary {
    ($tr:ident, $f:ident, $method:ident) => {
        impl<const N: usize> $tr for JetN<N> {
            type Output = Self;
            fn $f(self, rhs: Self) -> Self {
                self.$method(&rhs)
            }
        }
        impl<'a, const N: usize> $tr<&'a JetN<N>> for JetN<N> {
            type Output = Self;
            fn $f(self, rhs: &'a Self) -> Self {
                self.$method(rhs)
            }
        }
    };
}

binary!(Add, add, add_ref);
binary!(Sub, sub, sub_ref);
binary!(Mul, mul, mul_ref);
binary!(Div, div, div_ref);

impl<const N: usize> Neg for JetN<N> {
    type Output = Self;
    fn neg(self) -> Self {
        self.neg_ref()
    }
}

impl<const N: usize> Ring for JetN<N> {
    fn zero() -> Self {
        Self::constant(0.0)
    }
    fn one() -> Self {
        Self::constant(1.0)
    }
    fn from_i64(n: i64) -> Self {
        Self::constant(n as f64)
    }
    fn from_ratio(num: i64, den: i64) -> Self {
        Self::constant(num as f64 / den as f64)
    }
    fn from_rational(q: &Q) -> Self {
        Self::constant(rational_to_f64(q))
    }
    fn is_exact_zero(&self) -> bool {
        self.re == 0.0 && self.eps.iter().all(|e| *e == 0.0)
    }
    fn magnitude(&self) -> f64 {
        self.eps.iter().fold(self.re.abs(), |m, e| m.max(e.abs()))
    }
    fn relative_epsilon() -> f64 {
        f64::EPSILON
    }
    fn add_ref(&self, rhs: &Self) -> Self {
        JetN { re: self.re + rhs.re, eps: std::array::from_fn(|k| self.eps[k] + rhs.eps[k]) }
    }
    fn sub_ref(&self, rhs: &Self) -> Self {
        JetN { re: self.re - rhs.re, eps: std::array::from_fn(|k| self.eps[k] - rhs.eps[k]) }
    }
    fn mul_ref(&self, rhs: &Self) -> Self {
        JetN { re: self.re * rhs.re, eps: std::array::from_fn(|k| self.re * rhs.eps[k] + self.eps[k] * rhs.re) }
    }
    fn neg_ref(&self) -> Self {
        JetN { re: -self.re, eps: self.eps.map(|e| -e) }
    }
}

impl<const N: usize> Field for JetN<N> {
    fn try_recip(&self) -> Option<Self> {
        let r = 1.0 / self.re;
        (self.re != 0.0 && r.is_finite()).then(|| self.chain(r, -r * r))
    }
    fn div_ref(&self, rhs: &Self) -> Self {
        let r = 1.0 / rhs.re;
        let q = self.re * r;
        JetN { re: q, eps: std::array::from_fn(|k| (self.eps[k] - q * rhs.eps[k]) * r) }
    }
}

impl<const N: usize> Real for JetN<N> {
    fn sqrt(&self) -> Self {
        let s = self.re.sqrt();
        self.chain(s, 0.5 / s)
    }
    fn exp(&self) -> Self {
        let e = self.re.exp();
        self.chain(e, e)
    }
    fn ln(&self) -> Self {
        self.chain(self.re.ln(), 1.0 / self.re)
    }
    fn sin(&self) -> Self {
        self.chain(self.re.sin(), self.re.cos())
    }
    fn cos(&self) -> Self {
        self.chain(self.re.cos(), -self.re.sin())
    }
    fn sinh(&self) -> Self {
        self.chain(self.re.sinh(), self.re.cosh())
    }
    fn cosh(&self) -> Self {
        self.chain(self.re.cosh(), self.re.sinh())
    }
    fn atan2(&self, x: &Self) -> Self {
        let r2 = x.re * x.re + self.re * self.re;
        JetN { re: self.re.atan2(x.re), eps: std::array::from_fn(|k| (x.re * self.eps[k] - self.re * x.eps[k]) / r2) }
    }
    fn atanh(&self) -> Self {
        self.chain(self.re.atanh(), 1.0 / (1.0 - self.re * self.re))
    }
    fn abs(&self) -> Self {
        if self.re < 0.0 { self.neg_ref() } else { *self }
    }
    fn to_f64(&self) -> f64 {
        self.re
    }
    fn from_f64(x: f64) -> Self {
        Self::constant(x)
    }
    fn pi() -> Self {
        Self::constant(std::f64::consts::PI)
    }
    fn is_finite(&self) -> bool {
        self.re.is_finite() && self.eps.iter().all(|e| e.is_finite())
    }
}

/// A body point and the space twist at one `t`, with their derivatives along every key-pose and
/// key-time direction ([`key_sensitivity`]).
#[derive(Clone, Debug, PartialEq)]
pub struct KeySensitivity<const N: usize> {
    /// `F_{S(t)}(p)`.
    pub position: [JetN<N>; 3],
    /// Its velocity `d/dt`.
    pub velocity: [JetN<N>; 3],
    /// The space twist `(Ω, u)` at `t`.
    pub space_twist: Twist<JetN<N>>,
}

/// The body point `p` (body coordinates) and the space twist of the trajectory through `poses`
/// at `times` (as [`Trajectory::through`]) at parameter `t`, with their derivatives with respect
/// to all `6m` key-pose parameters and `m` key times (module docs), from one evaluation over
/// [`JetN<N>`]. `N` must be `7m`. [`Velocities::Given`] twists are held fixed.
///
/// ```
/// use motion::jacobian::key_sensitivity;
/// use motion::trajectory::Velocities;
/// use motion::{HermiteShapes, Pose, SegmentKind};
/// let poses = [Pose::<f64>::identity(), Pose::translation(&[1.0, 0.0, 0.0])];
/// assert!(key_sensitivity::<13>(&poses, &[0.0, 1.0], &Velocities::Zero, SegmentKind::Additive,
///     &HermiteShapes::unit(), 0.5, &[0.0; 3]).is_err()); // N = 14 for two poses
/// ```
pub fn key_sensitivity<const N: usize>(
    poses: &[Pose<f64>],
    times: &[f64],
    velocities: &Velocities<f64>,
    kind: SegmentKind,
    shapes: &HermiteShapes<f64>,
    t: f64,
    p: &[f64; 3],
) -> Result<KeySensitivity<N>, TrajectoryError> {
    let m = poses.len();
    if N != 7 * m || times.len() != m {
        return Err(TrajectoryError::Input(format!(
            "key_sensitivity needs N = 7 × poses (got N = {N} for {m} poses and {} times)",
            times.len()
        )));
    }
    let (position, velocity, space_twist) =
        lifted_evaluation::<f64, JetN<N>>(poses, times, velocities, kind, shapes, &t, p, Some)?;
    Ok(KeySensitivity { position, velocity, space_twist })
}

/// The derivatives of the body point, its velocity and the space twist at one `t` along every
/// key-pose and key-time direction ([`key_jacobian`]): row `k` of each field is the derivative
/// along parameter `k` (`6i..6i+6`: the twist directions of key pose `i`; `6m + i`: key time
/// `i`; the module docs give the directions).
#[derive(Clone, Debug, PartialEq)]
pub struct KeyJacobian<T = f64> {
    /// `F_{S(t)}(p)`.
    pub position: [T; 3],
    /// Its velocity `d/dt`.
    pub velocity: [T; 3],
    /// The space twist `(Ω, u)` at `t`.
    pub space_twist: Twist<T>,
    /// `d position / d parameter_k` for `k` in `0..7m`.
    pub d_position: Vec<[T; 3]>,
    /// `d velocity / d parameter_k`.
    pub d_velocity: Vec<[T; 3]>,
    /// `d (Ω, u) / d parameter_k` as `[Ωx, Ωy, Ωz, ux, uy, uz]`.
    pub d_space_twist: Vec<[T; 6]>,
}

/// [`key_sensitivity`] without the const parameter and over any [`Real`] scalar (`f64`, MPFR,
/// ...): the same derivatives for any number of key poses, one evaluation per parameter (`7m`
/// evaluations over the single-direction dual numbers [`Jet<T>`] instead of one over
/// `JetN<7m>`; over `f64` the values are identical).
///
/// ```
/// use motion::jacobian::key_jacobian;
/// use motion::trajectory::Velocities;
/// use motion::{HermiteShapes, Pose, SegmentKind};
/// let poses = [Pose::<f64>::identity(), Pose::translation(&[1.0, 0.0, 0.0])];
/// let j = key_jacobian(&poses, &[0.0, 1.0], &Velocities::Zero, SegmentKind::Additive,
///     &HermiteShapes::unit(), 1.0, &[0.0; 3])?;
/// assert_eq!(j.d_position.len(), 14); // 6 twist + 1 time parameter per key pose
/// assert!((j.d_position[6 + 3][0] - 1.0).abs() < 1e-14); // moving the second pose along x
/// # Ok::<(), motion::trajectory::TrajectoryError>(())
/// ```
pub fn key_jacobian<T: Real>(
    poses: &[Pose<T>],
    times: &[T],
    velocities: &Velocities<T>,
    kind: SegmentKind,
    shapes: &HermiteShapes<T>,
    t: T,
    p: &[T; 3],
) -> Result<KeyJacobian<T>, TrajectoryError> {
    let m = poses.len();
    if times.len() != m {
        return Err(TrajectoryError::Input(format!("key_jacobian: {m} poses and {} times", times.len())));
    }
    let re = |x: &[Jet<T>; 3]| x.clone().map(|c| c.re);
    let d = |x: &[Jet<T>; 3]| x.clone().map(|c| c.eps);
    let twist_d = |w: &Twist<Jet<T>>| {
        let (a, l) = (&w.angular, &w.linear);
        [&a.x, &a.y, &a.z, &l.x, &l.y, &l.z].map(|c| c.eps.clone())
    };
    let mut out: Option<KeyJacobian<T>> = None;
    for k in 0..7 * m {
        let (position, velocity, twist) =
            lifted_evaluation::<T, Jet<T>>(poses, times, velocities, kind, shapes, &t, p, |j| (j == k).then_some(0))?;
        let j = out.get_or_insert_with(|| KeyJacobian {
            position: re(&position),
            velocity: re(&velocity),
            space_twist: Twist {
                angular: twist.angular.map(|c| c.re.clone()),
                linear: twist.linear.map(|c| c.re.clone()),
            },
            d_position: Vec::with_capacity(7 * m),
            d_velocity: Vec::with_capacity(7 * m),
            d_space_twist: Vec::with_capacity(7 * m),
        });
        j.d_position.push(d(&position));
        j.d_velocity.push(d(&velocity));
        j.d_space_twist.push(twist_d(&twist));
    }
    out.ok_or_else(|| TrajectoryError::Input("key_jacobian needs at least one key pose".into()))
}

/// A scalar the key parameters are lifted to: derivative directions over a base scalar `T`
/// ([`JetN`] over `f64`, [`Jet`] over any [`Real`]).
trait Lift<T>: Real {
    /// `x` with no derivative.
    fn constant_of(x: &T) -> Self;
    /// `x` plus `e` times the infinitesimal of direction `dir` (`None`: a constant).
    fn seeded(x: &T, dir: Option<usize>, e: &T) -> Self;
}

impl<const N: usize> Lift<f64> for JetN<N> {
    fn constant_of(x: &f64) -> Self {
        JetN::constant(*x)
    }
    fn seeded(x: &f64, dir: Option<usize>, e: &f64) -> Self {
        JetN { re: *x, eps: std::array::from_fn(|j| if dir == Some(j) { *e } else { 0.0 }) }
    }
}

impl<T: Real> Lift<T> for Jet<T> {
    fn constant_of(x: &T) -> Self {
        Jet::constant(x.clone())
    }
    fn seeded(x: &T, dir: Option<usize>, e: &T) -> Self {
        Jet::new(x.clone(), if dir == Some(0) { e.clone() } else { T::zero() })
    }
}

/// The evaluation of [`key_sensitivity`] over the lifted scalar `L` (`JetN<N>` or `Jet<T>`),
/// parameter `k` (module docs) carried by the direction `slot(k)` (`None`: held fixed): the
/// body point, its velocity and the space twist.
#[allow(clippy::too_many_arguments, clippy::type_complexity)]
fn lifted_evaluation<T: Real, L: Lift<T>>(
    poses: &[Pose<T>],
    times: &[T],
    velocities: &Velocities<T>,
    kind: SegmentKind,
    shapes: &HermiteShapes<T>,
    t: &T,
    p: &[T; 3],
    slot: impl Fn(usize) -> Option<usize>,
) -> Result<([L; 3], [L; 3], Twist<L>), TrajectoryError> {
    let m = poses.len();
    let c = |x: &T| L::constant_of(x);
    let half = T::from_ratio(1, 2);
    let mut lifted = Vec::with_capacity(m);
    for (i, s) in poses.iter().enumerate() {
        let d = |k: usize| L::seeded(&T::zero(), slot(6 * i + k), &half);
        let g = Twist { angular: Vec3::new(d(0), d(1), d(2)), linear: Vec3::new(d(3), d(4), d(5)) }.to_bivector();
        lifted.push(s.map_scalar(&c) * Pose::exp(&Pose::from(&g))?);
    }
    let times: Vec<L> = times.iter().enumerate().map(|(i, x)| L::seeded(x, slot(6 * m + i), &T::one())).collect();
    let velocities = match velocities {
        Velocities::Given(v) => Velocities::Given(
            v.iter().map(|w| Twist { angular: w.angular.clone().map(c), linear: w.linear.clone().map(c) }).collect(),
        ),
        Velocities::CatmullRom => Velocities::CatmullRom,
        Velocities::Zero => Velocities::Zero,
    };
    let shape = |s: &Shape<T>| Shape::new(c(&s.lambda), Pseudoscalar::new(c(&s.gamma.scalar), c(&s.gamma.e123inf)));
    let shapes = match shapes {
        HermiteShapes::Common(s) => HermiteShapes::Common(shape(s)),
        HermiteShapes::PerPose(v) => HermiteShapes::PerPose(v.iter().map(shape).collect()),
        HermiteShapes::PerSegment(v) => {
            HermiteShapes::PerSegment(v.iter().map(|[a, b]| [shape(a), shape(b)]).collect())
        }
    };
    let tr = Trajectory::through(&lifted, &times, &velocities, kind, &shapes)?;
    let tj = c(t);
    let vel = velocity(tr.motion(), &tj)?;
    let (position, v) = vel.body_point_velocity(&p.each_ref().map(c))?;
    Ok((position, v, vel.twist()))
}
