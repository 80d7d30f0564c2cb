//! The interpolation schemes of W-L Sec. 3 through key poses `P_i` at increasing times `t_i`,
//! each a [`Motion`] (so velocities come from dual numbers like every other motion):
//!
//! | type | paper | `R(t)` on `[t_i, t_{i+1}]`, `λ = (t - t_i)/(t_{i+1} - t_i)` |
//! |---|---|---|
//! | [`WlLinear`] | Sec. 3.1 | `exp(λ ℓ(R_{i+1} rev(R_i))) R_i` (piecewise screw motions) |
//! | [`WlBivectorLinear`] | Sec. 3.3 | `exp((1 - λ) ℓ(R_i) + λ ℓ(R_{i+1}))` |
//! | [`WlQuadratic`] | Sec. 3.2 | `exp(Q(t))`, `Q` the quadratic through `(t_i, ℓ(R_i))` (3 poses), smoothed for more |
//!
//! `R_i` is the displacement rotor of `P_i` ([`super::from_pose`]) after the key poses are
//! sign-aligned the short way ([`crate::trajectory::align_signs`], Jüttler's rule (24), the
//! contract's rule; for displacement rotors it is `<R_i rev(R_{i-1})>_0 ≥ 0`), so the relative
//! rotors turn by at most π.
//!
//! **Smoothed quadratic (more than 3 poses).** The paper points to Cendes–Wong's C1 quadratic
//! interpolation, which is made for scattered data over triangulations. For a sequence we use
//! parabolic blending (Overhauser): on `[t_i, t_{i+1}]`, `Q = (1 - λ) Q_{i-1} + λ Q_i` with
//! `Q_j` the quadratic through `(t_j, t_{j+1}, t_{j+2})` (only the one that exists on the end
//! intervals). It interpolates every `ℓ(R_i)`, is C1 in the bivectors (so the motion is C1),
//! local (a pose moves at most 4 segments), built from the paper's own three-point quadratic,
//! and with 3 poses it *is* the paper's quadratic.
//!
//! ```
//! use motion::{Motion, Pose, wareham_lasenby::WlQuadratic};
//! let poses = [
//!     Pose::<f64>::identity(),
//!     Pose::from_axis_angle_translation(&[0.0, 0.0, 1.0], &0.5, &[1.0, 0.0, 0.0]).unwrap(),
//!     Pose::from_axis_angle_translation(&[0.0, 1.0, 0.0], &0.3, &[2.0, 1.0, 0.0]).unwrap(),
//! ];
//! let m = WlQuadratic::new(&poses, &[0.0, 0.5, 1.0]).unwrap();
//! assert!(m.pose(&0.5).unwrap().is_equivalent(&poses[1], &1e-14).unwrap());
//! ```

use super::{Generator, WlError, from_pose, log, to_pose};
use crate::trajectory::align_signs;
use crate::{CurveError, MapScalar, Motion, MotionError, Pose};
use algebra_core::{Real, Ring};
use gam_algebras::cga::Motor;

/// Key rotors at increasing times, sign-aligned.
#[derive(Debug, Clone, PartialEq)]
struct Keys<T: Ring> {
    times: Vec<T>,
    rotors: Vec<Motor<T>>,
}

impl<T: Real> Keys<T> {
    fn new(poses: &[Pose<T>], times: &[T], need: usize) -> Result<Self, WlError> {
        if poses.len() < need {
            return Err(CurveError::TooFewPoses { need, got: poses.len() }.into());
        }
        if times.len() != poses.len() {
            return Err(CurveError::BreakCount { segments: poses.len() - 1, got: times.len() }.into());
        }
        for (index, t) in times.iter().enumerate() {
            if !t.is_finite() {
                return Err(CurveError::NotFiniteParameter { what: "breakpoint", index, value: t.to_string() }.into());
            }
            if index > 0 && t.partial_cmp(&times[index - 1]) != Some(std::cmp::Ordering::Greater) {
                let previous = times[index - 1].to_string();
                return Err(CurveError::BreaksNotIncreasing { index, value: t.to_string(), previous }.into());
            }
        }
        let mut aligned = poses.to_vec();
        align_signs(&mut aligned);
        let rotors = aligned.iter().map(from_pose).collect::<Result<_, _>>()?;
        Ok(Keys { times: times.to_vec(), rotors })
    }

    /// `(i, λ)` with `t` in `[t_i, t_{i+1}]` (end segments continued outside).
    fn locate(&self, t: &T) -> (usize, T) {
        let last = self.times.len() - 2;
        let i = (1..=last).rev().find(|&i| *t >= self.times[i]).unwrap_or(0);
        let (a, b) = (&self.times[i], &self.times[i + 1]);
        (i, t.sub_ref(a).div_ref(&b.sub_ref(a)))
    }

    fn logs(&self) -> Result<Vec<Generator<T>>, WlError> {
        self.rotors.iter().map(log).collect()
    }

    fn map_scalar<U: Real>(&self, f: &dyn Fn(&T) -> U) -> Keys<U> {
        Keys {
            times: self.times.iter().map(f).collect(),
            rotors: self.rotors.iter().map(|r| map_rotor(r, f)).collect(),
        }
    }

    fn domain(&self) -> [T; 2] {
        [self.times[0].clone(), self.times[self.times.len() - 1].clone()]
    }
}

fn map_rotor<T: Ring, U: Ring>(r: &Motor<T>, f: &dyn Fn(&T) -> U) -> Motor<U> {
    Motor::from_array(r.to_array().each_ref().map(f))
}

fn curve(e: WlError) -> CurveError {
    match e {
        WlError::Curve(c) => c,
        WlError::Pose(p) => CurveError::Pose(p),
        other => CurveError::Pose(MotionError::NotFinite { op: "wareham-lasenby", value: other.to_string() }),
    }
}

/// W-L Sec. 3.1: piecewise interpolation of the relative rotor,
/// `R(t) = exp(λ ΔB_i) R_i`, `ΔB_i = ℓ(R_{i+1} rev(R_i))`: between neighbours the screw motion
/// of [`super::helix_point`]; continuous, with a jump in velocity at the key poses.
///
/// ```
/// use motion::{Motion, Pose, wareham_lasenby::WlLinear};
/// let poses = [Pose::<f64>::identity(), Pose::translation(&[2.0, 0.0, 0.0])];
/// let m = WlLinear::new(&poses, &[0.0, 1.0]).unwrap();
/// assert!((m.pose(&0.25).unwrap().transform_point(&[0.0; 3]).unwrap()[0] - 0.5).abs() < 1e-15);
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct WlLinear<T: Ring> {
    keys: Keys<T>,
    steps: Vec<Generator<T>>,
}

impl<T: Real> WlLinear<T> {
    /// The motion through `poses` at `times` (at least 2, times finite and increasing).
    ///
    /// ```
    /// use motion::{Pose, wareham_lasenby::WlLinear};
    /// assert!(WlLinear::<f64>::new(&[Pose::identity()], &[0.0]).is_err());
    /// ```
    pub fn new(poses: &[Pose<T>], times: &[T]) -> Result<Self, WlError> {
        let keys = Keys::new(poses, times, 2)?;
        let steps = keys.rotors.windows(2).map(|w| log(&(&w[1] * &w[0].reverse()))).collect::<Result<_, _>>()?;
        Ok(WlLinear { keys, steps })
    }

    /// `ΔB_i = ℓ(R_{i+1} rev(R_i))`, the generator of segment `i`.
    ///
    /// ```
    /// use motion::{Pose, wareham_lasenby::WlLinear};
    /// let m = WlLinear::new(&[Pose::<f64>::identity(), Pose::translation(&[2.0, 0.0, 0.0])], &[0.0, 1.0]).unwrap();
    /// assert_eq!(m.step(0).t, [-1.0, 0.0, 0.0]);
    /// ```
    pub fn step(&self, i: usize) -> &Generator<T> {
        &self.steps[i]
    }

    /// The sign-aligned key rotors `R_i`.
    ///
    /// ```
    /// use motion::{Pose, wareham_lasenby::WlLinear};
    /// let m = WlLinear::new(&[Pose::<f64>::identity(), Pose::translation(&[2.0, 0.0, 0.0])], &[0.0, 1.0]).unwrap();
    /// assert_eq!(m.key_rotors()[0].scalar, 1.0);
    /// ```
    pub fn key_rotors(&self) -> &[Motor<T>] {
        &self.keys.rotors
    }

    /// The displacement rotor `R(t)` (any `t`: the end segments continue outside the domain).
    ///
    /// ```
    /// use motion::{Pose, wareham_lasenby::WlLinear};
    /// let m = WlLinear::new(&[Pose::<f64>::identity(), Pose::translation(&[2.0, 0.0, 0.0])], &[0.0, 1.0]).unwrap();
    /// assert_eq!(m.rotor(&1.0).unwrap().e14, -1.0);
    /// ```
    pub fn rotor(&self, t: &T) -> Result<Motor<T>, WlError> {
        let (i, lambda) = self.keys.locate(t);
        Ok(&self.steps[i].scale(&lambda).exp()? * &self.keys.rotors[i])
    }
}

impl<T: Real> Motion<T> for WlLinear<T> {
    fn evaluate(&self, t: &T) -> Result<Pose<T>, CurveError> {
        self.rotor(t).map(|r| to_pose(&r)).map_err(curve)
    }
    fn domain(&self) -> [T; 2] {
        self.keys.domain()
    }
}

impl<T: Real, U: Real> MapScalar<T, U> for WlLinear<T> {
    type Mapped = WlLinear<U>;
    fn map_scalar(&self, f: &dyn Fn(&T) -> U) -> WlLinear<U> {
        WlLinear { keys: self.keys.map_scalar(f), steps: self.steps.iter().map(|g| g.map_scalar(f)).collect() }
    }
}

/// W-L Sec. 3.3: direct (piecewise linear) interpolation of the bivectors `ℓ(R_i)`,
/// `R(t) = exp((1 - λ) ℓ(R_i) + λ ℓ(R_{i+1}))`. Passes through every key pose; between them it
/// differs from [`WlLinear`] unless the generators commute (the paper's closing remark).
///
/// ```
/// use motion::{Motion, Pose, wareham_lasenby::WlBivectorLinear};
/// let poses = [Pose::<f64>::translation(&[1.0, 0.0, 0.0]), Pose::translation(&[3.0, 0.0, 0.0])];
/// let m = WlBivectorLinear::new(&poses, &[0.0, 1.0]).unwrap();
/// assert!((m.pose(&0.5).unwrap().transform_point(&[0.0; 3]).unwrap()[0] - 2.0).abs() < 1e-15);
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct WlBivectorLinear<T: Ring> {
    keys: Keys<T>,
    logs: Vec<Generator<T>>,
}

impl<T: Real> WlBivectorLinear<T> {
    /// The motion through `poses` at `times` (at least 2).
    ///
    /// ```
    /// use motion::{Pose, wareham_lasenby::WlBivectorLinear};
    /// assert!(WlBivectorLinear::<f64>::new(&[Pose::identity(), Pose::identity()], &[1.0, 0.0]).is_err());
    /// ```
    pub fn new(poses: &[Pose<T>], times: &[T]) -> Result<Self, WlError> {
        let keys = Keys::new(poses, times, 2)?;
        let logs = keys.logs()?;
        Ok(WlBivectorLinear { keys, logs })
    }

    /// The displacement rotor `R(t)`.
    ///
    /// ```
    /// use motion::{Pose, wareham_lasenby::WlBivectorLinear};
    /// let m = WlBivectorLinear::new(&[Pose::<f64>::identity(), Pose::translation(&[2.0, 0.0, 0.0])], &[0.0, 1.0]).unwrap();
    /// assert_eq!(m.rotor(&0.5).unwrap().e14, -0.5);
    /// ```
    pub fn rotor(&self, t: &T) -> Result<Motor<T>, WlError> {
        let (i, lambda) = self.keys.locate(t);
        let g = Generator::combine(&T::one().sub_ref(&lambda), &self.logs[i], &lambda, &self.logs[i + 1]);
        g.exp()
    }
}

impl<T: Real> Motion<T> for WlBivectorLinear<T> {
    fn evaluate(&self, t: &T) -> Result<Pose<T>, CurveError> {
        self.rotor(t).map(|r| to_pose(&r)).map_err(curve)
    }
    fn domain(&self) -> [T; 2] {
        self.keys.domain()
    }
}

impl<T: Real, U: Real> MapScalar<T, U> for WlBivectorLinear<T> {
    type Mapped = WlBivectorLinear<U>;
    fn map_scalar(&self, f: &dyn Fn(&T) -> U) -> WlBivectorLinear<U> {
        WlBivectorLinear { keys: self.keys.map_scalar(f), logs: self.logs.iter().map(|g| g.map_scalar(f)).collect() }
    }
}

/// W-L Sec. 3.2: the quadratic in `t` through `(t_i, ℓ(R_i))` for three poses (with uniform
/// parameters the paper's `B'_λ`, `λ ∈ [-1, 1]`), then `exp`; for more poses the smoothed
/// (parabolically blended, C1) quadratic of the module docs.
///
/// ```
/// use motion::{Motion, Pose, wareham_lasenby::WlQuadratic};
/// let p = |x: f64| Pose::<f64>::translation(&[x, x * x, 0.0]);
/// let m = WlQuadratic::new(&[p(0.0), p(1.0), p(2.0)], &[0.0, 1.0, 2.0]).unwrap();
/// let y = m.pose(&1.5).unwrap().transform_point(&[0.0; 3]).unwrap();
/// assert!((y[0] - 1.5).abs() < 1e-15 && (y[1] - 2.25).abs() < 1e-14); // a parabola of translations
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct WlQuadratic<T: Ring> {
    keys: Keys<T>,
    logs: Vec<Generator<T>>,
}

impl<T: Real> WlQuadratic<T> {
    /// The motion through `poses` at `times` (at least 3).
    ///
    /// ```
    /// use motion::{Pose, wareham_lasenby::WlQuadratic};
    /// assert!(WlQuadratic::<f64>::new(&[Pose::identity(), Pose::identity()], &[0.0, 1.0]).is_err());
    /// ```
    pub fn new(poses: &[Pose<T>], times: &[T]) -> Result<Self, WlError> {
        let keys = Keys::new(poses, times, 3)?;
        let logs = keys.logs()?;
        Ok(WlQuadratic { keys, logs })
    }

    /// `Q_j(t)`: the quadratic (Lagrange form) through `(t_{j+k}, ℓ(R_{j+k}))`, `k = 0, 1, 2`.
    fn quadratic(&self, j: usize, t: &T) -> Generator<T> {
        let ts = &self.keys.times[j..j + 3];
        let basis = |k: usize| {
            let (a, b) = ((k + 1) % 3, (k + 2) % 3);
            t.sub_ref(&ts[a])
                .mul_ref(&t.sub_ref(&ts[b]))
                .div_ref(&ts[k].sub_ref(&ts[a]).mul_ref(&ts[k].sub_ref(&ts[b])))
        };
        let g = Generator::combine(&basis(0), &self.logs[j], &basis(1), &self.logs[j + 1]);
        Generator::combine(&T::one(), &g, &basis(2), &self.logs[j + 2])
    }

    /// The generator `Q(t)` (before `exp`): a quadratic for 3 poses, blended for more.
    ///
    /// ```
    /// use motion::{Pose, wareham_lasenby::WlQuadratic};
    /// let p = |x: f64| Pose::<f64>::translation(&[x, 0.0, 0.0]);
    /// let m = WlQuadratic::new(&[p(0.0), p(2.0), p(4.0), p(6.0)], &[0.0, 1.0, 2.0, 3.0]).unwrap();
    /// assert!((m.generator(&2.5).t[0] + 2.5).abs() < 1e-15); // ℓ(T_a) = -a n/2
    /// ```
    pub fn generator(&self, t: &T) -> Generator<T> {
        let (i, lambda) = self.keys.locate(t);
        let last = self.keys.times.len() - 3; // index of the last quadratic
        match (i.checked_sub(1), (i <= last).then_some(i)) {
            (Some(l), Some(r)) => {
                let (ql, qr) = (self.quadratic(l, t), self.quadratic(r, t));
                Generator::combine(&T::one().sub_ref(&lambda), &ql, &lambda, &qr)
            }
            (l, r) => self.quadratic(l.or(r).unwrap_or(0), t),
        }
    }

    /// The displacement rotor `R(t) = exp(Q(t))`.
    ///
    /// ```
    /// use motion::{Pose, wareham_lasenby::WlQuadratic};
    /// let p = |x: f64| Pose::<f64>::translation(&[x, 0.0, 0.0]);
    /// let m = WlQuadratic::new(&[p(0.0), p(2.0), p(4.0)], &[0.0, 1.0, 2.0]).unwrap();
    /// assert!((m.rotor(&0.5).unwrap().e14 + 0.5).abs() < 1e-15);
    /// ```
    pub fn rotor(&self, t: &T) -> Result<Motor<T>, WlError> {
        self.generator(t).exp()
    }
}

impl<T: Real> Motion<T> for WlQuadratic<T> {
    fn evaluate(&self, t: &T) -> Result<Pose<T>, CurveError> {
        self.rotor(t).map(|r| to_pose(&r)).map_err(curve)
    }
    fn domain(&self) -> [T; 2] {
        self.keys.domain()
    }
}

impl<T: Real, U: Real> MapScalar<T, U> for WlQuadratic<T> {
    type Mapped = WlQuadratic<U>;
    fn map_scalar(&self, f: &dyn Fn(&T) -> U) -> WlQuadratic<U> {
        WlQuadratic { keys: self.keys.map_scalar(f), logs: self.logs.iter().map(|g| g.map_scalar(f)).collect() }
    }
}

/// The motion of a W-L method of `gam interpolate` ([`crate::method::Method::build`]).
///
/// ```
/// use motion::{Motion, Pose, wareham_lasenby::{WlLinear, WlMotion}};
/// let poses = [Pose::<f64>::identity(), Pose::translation(&[2.0, 0.0, 0.0])];
/// let m = WlMotion::Linear(WlLinear::new(&poses, &[0.0, 1.0]).unwrap());
/// assert_eq!(m.domain(), [0.0, 1.0]);
/// ```
#[derive(Debug, Clone, PartialEq)]
pub enum WlMotion<T: Ring> {
    /// `wl-linear` (Sec. 3.1).
    Linear(WlLinear<T>),
    /// `wl-quadratic` (Sec. 3.2, smoothed for more than 3 poses).
    Quadratic(WlQuadratic<T>),
    /// `wl-direct` (Sec. 3.3).
    Direct(WlBivectorLinear<T>),
}

impl<T: Real> Motion<T> for WlMotion<T> {
    fn evaluate(&self, t: &T) -> Result<Pose<T>, CurveError> {
        match self {
            WlMotion::Linear(m) => m.evaluate(t),
            WlMotion::Quadratic(m) => m.evaluate(t),
            WlMotion::Direct(m) => m.evaluate(t),
        }
    }
    fn domain(&self) -> [T; 2] {
        match self {
            WlMotion::Linear(m) => m.domain(),
            WlMotion::Quadratic(m) => m.domain(),
            WlMotion::Direct(m) => m.domain(),
        }
    }
}

impl<T: Real, U: Real> MapScalar<T, U> for WlMotion<T> {
    type Mapped = WlMotion<U>;
    fn map_scalar(&self, f: &dyn Fn(&T) -> U) -> WlMotion<U> {
        match self {
            WlMotion::Linear(m) => WlMotion::Linear(m.map_scalar(f)),
            WlMotion::Quadratic(m) => WlMotion::Quadratic(m.map_scalar(f)),
            WlMotion::Direct(m) => WlMotion::Direct(m.map_scalar(f)),
        }
    }
}
