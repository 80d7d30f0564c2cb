//! Motions from hexanions (Angelidis Sec. 7): the linear interpolation (56), the weighted
//! blend (57), the decoupled translation + rotation motion (58)-(60), and
//! [`HexanionLinear`], the piecewise linear interpolation (56) of the principal hexanions of
//! key poses (method `hexanion-linear` of `gam interpolate`), and [`HexanionDecoupled`], the
//! decoupled motion (58)-(60) between consecutive key poses (method `hexanion-decoupled`).
//!
//! Note on (60): as printed, `C(p, u) = p + u m + (1 - cos|uω|)/|uω|² ω × ξ + sin|uω|/|uω| ξ`
//! with `ξ = ω × (p - c)` lacks the factors `u²` and `u` that the rotation by `uω` about `c`
//! (eq. 59, with (29)) gives; [`Decoupled::trajectory`] uses
//! `C(p, u) = p + u m + a(uω) u² ω × ξ + b(uω) u ξ` (so `C(p, 0) = p`, which the printed form
//! violates), checked against the pose of (59) in the tests.
//!
//! ```
//! use motion::repr::hexanion::Hexanion;
//! let a = Hexanion::new([0.0, 0.0, 1.0], [0.0; 3]);
//! let b = Hexanion::new([0.0, 0.0, 3.0], [2.0, 0.0, 0.0]);
//! assert_eq!(Hexanion::lerp(&a, &b, &0.5), Hexanion::new([0.0, 0.0, 2.0], [1.0, 0.0, 0.0]));
//! ```

use super::Hexanion;
use super::exp::coefficients;
use crate::repr::ReprError;
use crate::repr::vec3::{add, cross, dot, scale, sub};
use crate::{CurveError, MapScalar, Motion, MotionError, Pose};
use algebra_core::{Field, Real, Ring};

impl<T: Ring> Hexanion<T> {
    /// `(1 - u) A + u B` (eq. 56); `u · A` (55) is the case `A = 0`.
    ///
    /// ```
    /// use motion::repr::hexanion::Hexanion;
    /// let b = Hexanion::new([0.0, 0.0, 2.0], [0.0; 3]);
    /// assert_eq!(Hexanion::lerp(&Hexanion::zero(), &b, &0.25), b.scale(&0.25));
    /// ```
    pub fn lerp(a: &Self, b: &Self, u: &T) -> Self {
        &a.scale(&T::one().sub_ref(u)) + &b.scale(u)
    }
}

impl<T: Field> Hexanion<T> {
    /// The weighted blend `Σ φ_i <ω_i, m_i> / Σ φ_i` (eq. 57). Fails for no input or
    /// `Σ φ_i = 0` exactly.
    ///
    /// ```
    /// use motion::repr::hexanion::Hexanion;
    /// let a = Hexanion::new([1.0, 0.0, 0.0], [0.0; 3]);
    /// let b = Hexanion::new([0.0, 1.0, 0.0], [0.0; 3]);
    /// assert_eq!(Hexanion::blend(&[(1.0, a), (3.0, b)]).unwrap(), Hexanion::new([0.25, 0.75, 0.0], [0.0; 3]));
    /// assert!(Hexanion::<f64>::blend(&[]).is_err());
    /// ```
    pub fn blend(weighted: &[(T, Self)]) -> Result<Self, ReprError> {
        let total = weighted.iter().fold(T::zero(), |s, (w, _)| s.add_ref(w));
        let inv = total.try_recip().ok_or(ReprError::ZeroWeight)?;
        let sum = weighted.iter().fold(Hexanion::zero(), |s, (w, h)| &s + &h.scale(w));
        Ok(sum.scale(&inv))
    }
}

/// Angelidis' decoupled motion (58)-(59): the straight translation by `u m` together with the
/// rotation by `u ω` about the moving centre `c + u m`:
/// `<uω, (<0, um> * c) × (uω)> * <0, um>`, `u ∈ [0, 1]`.
///
/// ```
/// use motion::{Motion, repr::hexanion::blend::Decoupled};
/// let d = Decoupled { omega: [0.0, 0.0, std::f64::consts::PI], m: [2.0, 0.0, 0.0], centre: [1.0, 0.0, 0.0] };
/// let p = d.trajectory(&[1.0, 1.0, 0.0], &1.0);
/// assert!((p[0] - 3.0).abs() < 1e-15 && (p[1] + 1.0).abs() < 1e-15);
/// let q = d.pose(&1.0).unwrap().transform_point(&[1.0, 1.0, 0.0]).unwrap();
/// assert!((q[0] - 3.0).abs() < 1e-15 && (q[1] + 1.0).abs() < 1e-15);
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct Decoupled<T> {
    /// `ω`: the total rotation vector.
    pub omega: [T; 3],
    /// `m`: the total translation.
    pub m: [T; 3],
    /// `c`: the centre of rotation at `u = 0`.
    pub centre: [T; 3],
}

impl<T: Real> Decoupled<T> {
    /// The pose at `u` (eq. 59): the translation by `u m` followed by the rotation hexanion
    /// `<uω, (c + um) × uω>` (so every point moves as in (60)).
    ///
    /// ```
    /// use motion::repr::hexanion::blend::Decoupled;
    /// let d = Decoupled { omega: [0.0; 3], m: [2.0, 0.0, 0.0], centre: [0.0; 3] };
    /// assert_eq!(d.pose_at(&0.5).unwrap(), motion::Pose::translation(&[1.0, 0.0, 0.0]));
    /// ```
    pub fn pose_at(&self, u: &T) -> Result<Pose<T>, MotionError> {
        let um = scale(u, &self.m);
        let uw = scale(u, &self.omega);
        let moved = add(&self.centre, &um);
        let rotation = Hexanion::new(uw.clone(), cross(&moved, &uw)).to_pose()?;
        Ok(Pose::translation(&um) * rotation)
    }

    /// The closed-form trajectory `C(p, u)` of (60), with the `u` factors restored (module
    /// docs): `p + u m + a(uω) u² ω × ξ + b(uω) u ξ`, `ξ = ω × (p - c)`.
    ///
    /// ```
    /// use motion::repr::hexanion::blend::Decoupled;
    /// let d = Decoupled { omega: [0.0, 0.0, 1.0], m: [0.0, 0.0, 1.0], centre: [0.0; 3] };
    /// assert_eq!(d.trajectory(&[1.0, 0.0, 0.0], &0.0), [1.0, 0.0, 0.0]);
    /// ```
    pub fn trajectory(&self, p: &[T; 3], u: &T) -> [T; 3] {
        let uw = scale(u, &self.omega);
        let [a, b, _] = coefficients(&dot(&uw, &uw));
        let xi = cross(&self.omega, &sub(p, &self.centre));
        let rot = add(&scale(&a.mul_ref(u).mul_ref(u), &cross(&self.omega, &xi)), &scale(&b.mul_ref(u), &xi));
        add(&add(p, &scale(u, &self.m)), &rot)
    }
}

impl<T: Real> Motion<T> for Decoupled<T> {
    fn evaluate(&self, t: &T) -> Result<Pose<T>, CurveError> {
        Ok(self.pose_at(t)?)
    }
    fn domain(&self) -> [T; 2] {
        [T::zero(), T::one()]
    }
}

impl<T: Real, U: Real> MapScalar<T, U> for Decoupled<T> {
    type Mapped = Decoupled<U>;
    fn map_scalar(&self, f: &dyn Fn(&T) -> U) -> Decoupled<U> {
        Decoupled {
            omega: self.omega.clone().map(|x| f(&x)),
            m: self.m.clone().map(|x| f(&x)),
            centre: self.centre.clone().map(|x| f(&x)),
        }
    }
}

/// The `hexanion-linear` motion through key poses `S_i` at increasing times `t_i`: on
/// `[t_i, t_{i+1}]` with `u = (t - t_i)/(t_{i+1} - t_i)`, the pose `exp((1 - u) h_i + u h_{i+1})`
/// (eq. 56) of the principal hexanions `h_i` of the key poses ([`Hexanion::from_pose`]). It
/// passes through every key pose; it is continuous but not C1 at the inner key poses, and (as
/// Angelidis' absolute interpolation) depends on the choice of the fixed frame's origin.
///
/// ```
/// use motion::{Motion, Pose, repr::hexanion::blend::HexanionLinear};
/// let poses = [Pose::<f64>::identity(), Pose::translation(&[2.0, 0.0, 0.0])];
/// let m = HexanionLinear::through(&poses, &[0.0, 1.0]).unwrap();
/// let p = m.pose(&0.5).unwrap().transform_point(&[0.0; 3]).unwrap();
/// assert!((p[0] - 1.0).abs() < 1e-15);
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct HexanionLinear<T> {
    times: Vec<T>,
    hexanions: Vec<Hexanion<T>>,
}

impl<T: Real> HexanionLinear<T> {
    /// The motion through `poses` at `times` (at least one pose; times finite and strictly
    /// increasing; as many as poses).
    ///
    /// ```
    /// use motion::{Pose, repr::hexanion::blend::HexanionLinear};
    /// let poses = [Pose::<f64>::identity(), Pose::identity()];
    /// assert!(HexanionLinear::through(&poses, &[1.0, 1.0]).is_err());
    /// ```
    pub fn through(poses: &[Pose<T>], times: &[T]) -> Result<Self, ReprError> {
        if poses.is_empty() {
            return Err(CurveError::TooFewPoses { need: 1, got: 0 }.into());
        }
        crate::repr::check_times(times, poses.len())?;
        let hexanions = poses.iter().map(Hexanion::from_pose).collect::<Result<Vec<_>, _>>()?;
        Ok(HexanionLinear { times: times.to_vec(), hexanions })
    }

    /// The principal hexanions of the key poses.
    ///
    /// ```
    /// use motion::{Pose, repr::hexanion::{Hexanion, blend::HexanionLinear}};
    /// let m = HexanionLinear::through(&[Pose::<f64>::identity()], &[0.0]).unwrap();
    /// assert_eq!(m.hexanions(), &[Hexanion::zero()]);
    /// ```
    pub fn hexanions(&self) -> &[Hexanion<T>] {
        &self.hexanions
    }

    /// The key times.
    ///
    /// ```
    /// use motion::{Pose, repr::hexanion::blend::HexanionLinear};
    /// let m = HexanionLinear::through(&[Pose::<f64>::identity()], &[2.0]).unwrap();
    /// assert_eq!(m.times(), &[2.0]);
    /// ```
    pub fn times(&self) -> &[T] {
        &self.times
    }

    /// The hexanion at `t` (the segment's (56), continued linearly outside the domain).
    ///
    /// ```
    /// use motion::{Pose, repr::hexanion::{Hexanion, blend::HexanionLinear}};
    /// let poses = [Pose::<f64>::identity(), Pose::translation(&[2.0, 0.0, 0.0])];
    /// let m = HexanionLinear::through(&poses, &[0.0, 2.0]).unwrap();
    /// assert_eq!(m.hexanion_at(&1.0), Hexanion::new([0.0; 3], [1.0, 0.0, 0.0]));
    /// ```
    pub fn hexanion_at(&self, t: &T) -> Hexanion<T> {
        if self.times.len() == 1 {
            return self.hexanions[0].clone();
        }
        let (i, u) = locate(&self.times, t);
        Hexanion::lerp(&self.hexanions[i], &self.hexanions[i + 1], &u)
    }
}

/// The segment `i` of `times` (at least two) holding `t`, the first or last for `t` outside,
/// and `t`'s local parameter `u = (t - t_i)/(t_(i+1) - t_i)` on it.
fn locate<T: Field + PartialOrd>(times: &[T], t: &T) -> (usize, T) {
    let n = times.len();
    let i = (0..n - 2).find(|&i| *t < times[i + 1]).unwrap_or(n - 2);
    (i, t.sub_ref(&times[i]).div_ref(&times[i + 1].sub_ref(&times[i])))
}

impl<T: Real> Motion<T> for HexanionLinear<T> {
    fn evaluate(&self, t: &T) -> Result<Pose<T>, CurveError> {
        Ok(self.hexanion_at(t).to_pose()?)
    }
    fn domain(&self) -> [T; 2] {
        [self.times[0].clone(), self.times[self.times.len() - 1].clone()]
    }
}

impl<T: Real, U: Real> MapScalar<T, U> for HexanionLinear<T> {
    type Mapped = HexanionLinear<U>;
    fn map_scalar(&self, f: &dyn Fn(&T) -> U) -> HexanionLinear<U> {
        let h = |x: &Hexanion<T>| Hexanion::new(x.omega.clone().map(|c| f(&c)), x.m.clone().map(|c| f(&c)));
        HexanionLinear { times: self.times.iter().map(f).collect(), hexanions: self.hexanions.iter().map(h).collect() }
    }
}

/// Angelidis' decoupled motion (58)-(60) through key poses: on `[t_i, t_(i+1)]` the body
/// origin moves on the straight line from its key position to the next while the body turns
/// at a constant rate about it, by the relative rotation's principal rotation vector (at most
/// a half turn): with `A, B` the key poses, `c = A(0)`, `m = B(0) - c` and `ω` the rotation of
/// `A⁻¹ B` (`A` first), the pose at `u = (t - t_i)/(t_(i+1) - t_i)` is `A` then
/// [`Decoupled`]`{ω, m, c}` at `u`. Through every key pose; unlike `hexanion-linear` it does
/// not depend on where the fixed frame's origin is, but on the body's (its origin moves
/// straight).
///
/// ```
/// use motion::{Motion, Pose, repr::hexanion::blend::HexanionDecoupled};
/// let a = Pose::<f64>::identity();
/// let b = Pose::from_axis_angle_translation(&[0.0, 0.0, 1.0], &1.0, &[2.0, 0.0, 0.0]).unwrap();
/// let m = HexanionDecoupled::through(&[a, b], &[0.0, 1.0]).unwrap();
/// // halfway: the body origin at (1, 0, 0), turned by half the angle
/// let p = m.pose(&0.5).unwrap().transform_point(&[0.0; 3]).unwrap();
/// assert!((p[0] - 1.0).abs() < 1e-15 && p[1].abs() < 1e-15);
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct HexanionDecoupled<T: Ring> {
    times: Vec<T>,
    starts: Vec<Pose<T>>,
    parts: Vec<Decoupled<T>>,
}

impl<T: Real> HexanionDecoupled<T> {
    /// The motion through `poses` at `times` (at least two poses; times finite and strictly
    /// increasing; as many as poses). Fails for a singular or non-finite pose.
    ///
    /// ```
    /// use motion::{Pose, repr::hexanion::blend::HexanionDecoupled};
    /// assert!(HexanionDecoupled::<f64>::through(&[Pose::identity()], &[0.0]).is_err());
    /// ```
    pub fn through(poses: &[Pose<T>], times: &[T]) -> Result<Self, ReprError> {
        if poses.len() < 2 {
            return Err(CurveError::TooFewPoses { need: 2, got: poses.len() }.into());
        }
        crate::repr::check_times(times, poses.len())?;
        let origin = [T::zero(), T::zero(), T::zero()];
        let mut parts = Vec::with_capacity(poses.len() - 1);
        for w in poses.windows(2) {
            let (a, b) = (&w[0], &w[1]);
            let relative = a.try_inverse()?.then(b);
            let omega = Hexanion::from_pose(&relative)?.omega;
            let c = a.transform_point(&origin)?;
            let m = sub(&b.transform_point(&origin)?, &c);
            parts.push(Decoupled { omega, m, centre: c });
        }
        Ok(HexanionDecoupled { times: times.to_vec(), starts: poses[..poses.len() - 1].to_vec(), parts })
    }

    /// The decoupled motions of the segments.
    ///
    /// ```
    /// use motion::{Pose, repr::hexanion::blend::HexanionDecoupled};
    /// let m = HexanionDecoupled::through(&[Pose::<f64>::identity(), Pose::translation(&[0.0, 3.0, 0.0])], &[0.0, 1.0]).unwrap();
    /// assert_eq!(m.parts()[0].m, [0.0, 3.0, 0.0]);
    /// ```
    pub fn parts(&self) -> &[Decoupled<T>] {
        &self.parts
    }
}

impl<T: Real> Motion<T> for HexanionDecoupled<T> {
    fn evaluate(&self, t: &T) -> Result<Pose<T>, CurveError> {
        let (i, u) = locate(&self.times, t);
        Ok(self.starts[i].then(&self.parts[i].pose_at(&u)?))
    }
    fn domain(&self) -> [T; 2] {
        [self.times[0].clone(), self.times[self.times.len() - 1].clone()]
    }
}

impl<T: Real, U: Real> MapScalar<T, U> for HexanionDecoupled<T> {
    type Mapped = HexanionDecoupled<U>;
    fn map_scalar(&self, f: &dyn Fn(&T) -> U) -> HexanionDecoupled<U> {
        let v = |x: &[T; 3]| x.clone().map(|c| f(&c));
        HexanionDecoupled {
            times: self.times.iter().map(f).collect(),
            starts: self.starts.iter().map(|p| p.map_scalar(f)).collect(),
            parts: self
                .parts
                .iter()
                .map(|d| Decoupled { omega: v(&d.omega), m: v(&d.m), centre: v(&d.centre) })
                .collect(),
        }
    }
}

/// The named weight functions `φ_i(t)` of Angelidis' blend (57) through key poses
/// ([`HexanionBlend`]); both sum to one at every `t`.
///
/// ```
/// use motion::repr::hexanion::blend::BlendWeights;
/// assert_eq!("lagrange".parse::<BlendWeights>(), Ok(BlendWeights::Lagrange));
/// assert_eq!(BlendWeights::Lagrange.weights(&[0.0, 1.0, 2.0], &1.0), vec![0.0, 1.0, 0.0]);
/// assert_eq!(BlendWeights::Bernstein.weights(&[0.0, 1.0, 2.0], &1.0), vec![0.25, 0.5, 0.25]);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BlendWeights {
    /// The Lagrange polynomials of the key parameters, `φ_i(t_j) = δ_ij`: the blend passes
    /// through every key pose; a polynomial of degree `m` in `t` (it oscillates for many
    /// poses, as polynomial interpolation does).
    Lagrange,
    /// The Bernstein polynomials `b_i^m(u)`, `u = (t - t_0)/(t_m - t_0)`: a Bézier curve of
    /// hexanions with the principal hexanions as control points, through the first and last
    /// key pose only (smooth, within their convex hull).
    Bernstein,
}

crate::names::named!("motion::repr::hexanion::blend::BlendWeights", BlendWeights {
    Lagrange => "lagrange",
    Bernstein => "bernstein"
});

impl std::str::FromStr for BlendWeights {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, String> {
        BlendWeights::from_name(s).ok_or_else(|| format!("unknown weights `{s}` (lagrange or bernstein)"))
    }
}

impl BlendWeights {
    /// `φ_0(t), ..., φ_m(t)` for the key parameters `times` (at least one, distinct).
    ///
    /// ```
    /// use motion::repr::hexanion::blend::BlendWeights;
    /// let w = BlendWeights::Lagrange.weights(&[0.0, 1.0, 3.0], &2.0);
    /// assert_eq!(w, vec![-1.0 / 3.0, 1.0, 1.0 / 3.0]); // sums to one
    /// ```
    pub fn weights<T: Field>(self, times: &[T], t: &T) -> Vec<T> {
        let m = times.len() - 1;
        match self {
            BlendWeights::Lagrange => (0..=m)
                .map(|i| {
                    (0..=m).filter(|&j| j != i).fold(T::one(), |acc, j| {
                        acc.mul_ref(&t.sub_ref(&times[j]).div_ref(&times[i].sub_ref(&times[j])))
                    })
                })
                .collect(),
            BlendWeights::Bernstein if m == 0 => vec![T::one()],
            BlendWeights::Bernstein => {
                let u = t.sub_ref(&times[0]).div_ref(&times[m].sub_ref(&times[0]));
                crate::juttler::bernstein_values(m, &u)
            }
        }
    }
}

/// Angelidis' blend (57) through key poses: `exp(Σ φ_i(t) H_i / Σ φ_i(t))` of the key poses'
/// principal hexanions `H_i` with named weight functions `φ_i` ([`BlendWeights`]). With
/// `lagrange` it passes through every key pose; with `bernstein` through the first and last.
/// Like `hexanion-linear` it depends on where the fixed frame's origin is.
///
/// ```
/// use motion::{Motion, Pose, repr::hexanion::blend::{BlendWeights, HexanionBlend}};
/// let poses = [[0.0, 0.0, 0.0], [1.0, 1.0, 0.0], [2.0, 0.0, 0.0]].map(|t| Pose::<f64>::translation(&t));
/// let m = HexanionBlend::through(&poses, &[0.0, 1.0, 2.0], BlendWeights::Lagrange).unwrap();
/// let p = m.pose(&1.0).unwrap().transform_point(&[0.0; 3]).unwrap();
/// assert!((p[0] - 1.0).abs() < 1e-15 && (p[1] - 1.0).abs() < 1e-15);
/// let b = HexanionBlend::through(&poses, &[0.0, 1.0, 2.0], BlendWeights::Bernstein).unwrap();
/// let q = b.pose(&1.0).unwrap().transform_point(&[0.0; 3]).unwrap();
/// assert!((q[1] - 0.5).abs() < 1e-15); // the quadratic Bézier's midpoint
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct HexanionBlend<T> {
    weights: BlendWeights,
    /// The key times and principal hexanions (those of `hexanion-linear`).
    keys: HexanionLinear<T>,
}

impl<T: Real> HexanionBlend<T> {
    /// The blend through `poses` at `times` (at least one pose; times finite and strictly
    /// increasing; as many as poses).
    ///
    /// ```
    /// use motion::{Pose, repr::hexanion::blend::{BlendWeights, HexanionBlend}};
    /// let poses = [Pose::<f64>::identity(), Pose::identity()];
    /// assert!(HexanionBlend::through(&poses, &[1.0, 1.0], BlendWeights::Lagrange).is_err());
    /// ```
    pub fn through(poses: &[Pose<T>], times: &[T], weights: BlendWeights) -> Result<Self, ReprError> {
        Ok(HexanionBlend { weights, keys: HexanionLinear::through(poses, times)? })
    }

    /// The weight functions.
    ///
    /// ```
    /// use motion::{Pose, repr::hexanion::blend::{BlendWeights, HexanionBlend}};
    /// let m = HexanionBlend::through(&[Pose::<f64>::identity()], &[0.0], BlendWeights::Bernstein).unwrap();
    /// assert_eq!(m.weights(), BlendWeights::Bernstein);
    /// ```
    pub fn weights(&self) -> BlendWeights {
        self.weights
    }

    /// The principal hexanions of the key poses.
    ///
    /// ```
    /// use motion::{Pose, repr::hexanion::{Hexanion, blend::{BlendWeights, HexanionBlend}}};
    /// let m = HexanionBlend::through(&[Pose::<f64>::identity()], &[0.0], BlendWeights::Lagrange).unwrap();
    /// assert_eq!(m.hexanions(), &[Hexanion::zero()]);
    /// ```
    pub fn hexanions(&self) -> &[Hexanion<T>] {
        self.keys.hexanions()
    }

    /// The blended hexanion (57) at `t`: `Σ φ_i(t) H_i` (both weight families sum to one
    /// identically in `t`, so (57)'s division is by one).
    ///
    /// ```
    /// use motion::{Pose, repr::hexanion::{Hexanion, blend::{BlendWeights, HexanionBlend}}};
    /// let poses = [Pose::<f64>::identity(), Pose::translation(&[2.0, 0.0, 0.0])];
    /// let m = HexanionBlend::through(&poses, &[0.0, 2.0], BlendWeights::Bernstein).unwrap();
    /// assert_eq!(m.hexanion_at(&1.0), Hexanion::new([0.0; 3], [1.0, 0.0, 0.0]));
    /// ```
    pub fn hexanion_at(&self, t: &T) -> Hexanion<T> {
        let phi = self.weights.weights(self.keys.times(), t);
        phi.iter().zip(self.hexanions()).fold(Hexanion::zero(), |s, (w, h)| &s + &h.scale(w))
    }
}

impl<T: Real> Motion<T> for HexanionBlend<T> {
    fn evaluate(&self, t: &T) -> Result<Pose<T>, CurveError> {
        Ok(self.hexanion_at(t).to_pose()?)
    }
    fn domain(&self) -> [T; 2] {
        self.keys.domain()
    }
}

impl<T: Real, U: Real> MapScalar<T, U> for HexanionBlend<T> {
    type Mapped = HexanionBlend<U>;
    fn map_scalar(&self, f: &dyn Fn(&T) -> U) -> HexanionBlend<U> {
        HexanionBlend { weights: self.weights, keys: self.keys.map_scalar(f) }
    }
}
