//! Velocities of motions (Sec. 3 of the main paper), with every derivative taken by running
//! the motion's own evaluation code over dual numbers: the control poses are lifted with
//! [`MapScalar::map_scalar`] to [`Jet<T>`] (or `Jet<Jet<T>>` for second derivatives) and the motion
//! is evaluated at `t + ε`. No derivative formula is written by hand.
//!
//! * the velocity indicatrix `Ψ(t) = 2 S(t)⁻¹ dS/dt` (eq. 11), for unit and non-unit motions;
//! * its pseudoscalar part `γ = ½(Ψ + rev Ψ)` and bivector part, the velocity bivector
//!   `ν = ½(Ψ - rev Ψ)`;
//! * `ν = Ω e123 + u einf` (Theorem 3.2): the angular velocity `Ω` and the velocity `u` of the
//!   body point instantaneously at the global origin, both in global (space) coordinates. With
//!   `a e123 = a1 e23 - a2 e13 + a3 e12`, `Ω = (ν23, -ν13, ν12)` and `u = (ν1∞, ν2∞, ν3∞)`;
//! * the velocity of the body point currently at `q`: `v = u + (q ∧ Ω) e123 = u + Ω × q`
//!   (eq. 14, Lemma 2.1);
//! * Corollary 3.3: `ν = Ω e123 + v einf + (Ω ∧ r) ω` from the velocity `v` of the point at `r`;
//! * second derivatives: `d²S/dt²`, `dΨ/dt` (so `dΩ/dt`, `du/dt`), and the acceleration of a
//!   body point.
//!
//! Conventions: `S` acts by `x ↦ rev(S) x S` (`U * V` applies `U` first); the rotation
//! `cos(φ/2) + sin(φ/2) e12` turns e1 towards e2, so `S(t) = exp(t e12/2)` has `Ω = (0, 0, 1)`.
//!
//! ```
//! use motion::velocity::velocity;
//! use motion::{MultiplicativeBezier, Pose};
//! // A quarter turn about e3 while translating by (2, 0, 0): a screw-free slerp.
//! let a = Pose::<f64>::identity();
//! let b = Pose::from_axis_angle_translation(&[0.0, 0.0, 1.0], &std::f64::consts::FRAC_PI_2, &[2.0, 0.0, 0.0]).unwrap();
//! let m = MultiplicativeBezier::new(vec![a, b]).unwrap();
//! let v = velocity(&m, &0.5).unwrap();
//! let w = v.twist().angular;
//! assert!(w[0].abs() < 1e-15 && w[1].abs() < 1e-15 && (w[2] - std::f64::consts::FRAC_PI_2).abs() < 1e-15);
//! assert!(v.gamma().scalar.abs() < 1e-15); // unitary motion: Ψ = ν (Lemma 3.4)
//! ```

use crate::bezier::{CurveError, MapScalar, Motion, check_domain};
use crate::{Bivector, Even, Pseudoscalar, Vec3};
use crate::{MotionError, Pose};
use algebra_core::{Field, Jet, Real, Ring};

fn lift<T: Ring>(x: &T) -> Jet<T> {
    Jet::constant(x.clone())
}

fn lift2<T: Ring>(x: &T) -> Jet<Jet<T>> {
    Jet::constant(Jet::constant(x.clone()))
}

/// The value and derivative parts `(M, M')` of an even element over dual numbers
/// `M + M'ε`.
///
/// ```
/// use algebra_core::Jet;
/// use motion::Even;
/// let m = Even::new(Jet::new(1.0, 2.0), Jet::constant(0.0), Jet::constant(0.0), Jet::constant(0.0),
///     Jet::new(0.5, -1.0), Jet::constant(0.0), Jet::constant(0.0), Jet::constant(0.0));
/// let (v, d) = motion::velocity::split_jet(&m);
/// assert_eq!((v.scalar, v.e1inf, d.scalar, d.e1inf), (1.0, 0.5, 2.0, -1.0));
/// ```
pub fn split_jet<T: Ring>(m: &Even<Jet<T>>) -> (Even<T>, Even<T>) {
    let re = |x: &Jet<T>| x.re.clone();
    let eps = |x: &Jet<T>| x.eps.clone();
    let parts = |f: &dyn Fn(&Jet<T>) -> T| {
        Even::new(f(&m.scalar), f(&m.e12), f(&m.e13), f(&m.e23), f(&m.e1inf), f(&m.e2inf), f(&m.e3inf), f(&m.e123inf))
    };
    (parts(&re), parts(&eps))
}

/// `S(t)` and `dS/dt`, from evaluating the motion over [`Jet<T>`] at `t + ε`.
///
/// ```
/// use motion::velocity::pose_derivative;
/// use motion::{AdditiveBezier, Pose};
/// let m = AdditiveBezier::new(vec![Pose::<f64>::identity(), Pose::translation(&[2.0, 0.0, 0.0])]).unwrap();
/// let (s, ds) = pose_derivative(&m, &0.5).unwrap();
/// assert_eq!(s, Pose::translation(&[1.0, 0.0, 0.0]));
/// assert_eq!(ds.e1inf, 1.0); // S_1 - S_0 = e1inf
/// ```
pub fn pose_derivative<T: Field + PartialOrd, M: MapScalar<T, Jet<T>>>(
    motion: &M,
    t: &T,
) -> Result<(Pose<T>, Even<T>), CurveError> {
    check_domain(t, &motion.domain())?;
    let s = motion.map_scalar(&lift::<T>).evaluate(&Jet::variable(t.clone()))?;
    Ok(split_jet(&s))
}

/// `(S, dS/dt, d²S/dt²)` at one parameter value, as returned by [`pose_second_derivative`].
///
/// ```
/// use motion::velocity::SecondOrder;
/// use motion::{Even, Pose};
/// let d: SecondOrder<f64> = (Pose::identity(), Even::zero(), Even::zero());
/// assert_eq!(d.1, d.2);
/// ```
pub type SecondOrder<T> = (Pose<T>, Even<T>, Even<T>);

/// `S(t)`, `dS/dt` and `d²S/dt²`, from evaluating the motion over `Jet<Jet<T>>` at
/// `(t + ε₁) + ε₂` (nested dual numbers).
///
/// ```
/// use motion::velocity::pose_second_derivative;
/// use motion::{AdditiveBezier, Pose};
/// let m = AdditiveBezier::new(vec![Pose::<f64>::identity(), Pose::identity(), Pose::translation(&[2.0, 0.0, 0.0])]).unwrap();
/// let (_, ds, dds) = pose_second_derivative(&m, &0.5).unwrap();
/// assert_eq!((ds.e1inf, dds.e1inf), (1.0, 2.0)); // S = 1 + t² e1inf
/// ```
pub fn pose_second_derivative<T: Real, M: MapScalar<T, Jet<Jet<T>>>>(
    motion: &M,
    t: &T,
) -> Result<SecondOrder<T>, CurveError> {
    let s = evaluate2(motion, t)?;
    let (value, derivative) = split_jet(&s);
    let (s0, s1) = split_jet(&value);
    let (_, s2) = split_jet(&derivative);
    Ok((s0, s1, s2))
}

/// The motion over `Jet<Jet<T>>` at `Jet(Jet(t, 1), Jet(1, 0))`: the value part is
/// `S + S'ε₁`, the derivative part `S' + S''ε₁`.
fn evaluate2<T: Real, M: MapScalar<T, Jet<Jet<T>>>>(motion: &M, t: &T) -> Result<Pose<Jet<Jet<T>>>, CurveError> {
    let tt = Jet::new(Jet::variable(t.clone()), Jet::constant(T::one()));
    check_domain(t, &motion.domain())?;
    motion.map_scalar(&lift2::<T>).evaluate(&tt)
}

/// The definition `Ψ = 2 S⁻¹ dS/dt` (eq. 11) for a pose and its derivative, over any field
/// (exact over rationals). Fails for singular `S` (Lemma 2.6).
///
/// ```
/// use algebra_core::rational::{q, Q};
/// use motion::velocity::indicatrix_from_derivative;
/// use motion::{Even, Pose};
/// // S = 2 (non-unit identity), dS/dt = e12: Ψ = 2 · ½ · e12 = e12.
/// let s = Pose::<Q>::identity().scale(&q(2));
/// let ds = Even::new(q(0), q(1), q(0), q(0), q(0), q(0), q(0), q(0));
/// assert_eq!(indicatrix_from_derivative(&s, &ds).unwrap(), ds);
/// ```
pub fn indicatrix_from_derivative<T: Field>(s: &Pose<T>, ds: &Even<T>) -> Result<Even<T>, MotionError> {
    let inverse = s.try_inverse()?;
    Ok((&inverse * ds).scale(&T::from_i64(2)))
}

/// The velocity indicatrix `Ψ(t) = 2 S(t)⁻¹ dS/dt` (eq. 11), `dS/dt` from dual numbers. Fails
/// outside the domain and where `S(t)` is singular.
///
/// ```
/// use motion::velocity::velocity_indicatrix;
/// use motion::{AdditiveBezier, Pose};
/// // Non-unit: S(t) = (1 - t) + 2t = 1 + t, Ψ = 2/(1 + t), a pure scalar (γ), ν = 0.
/// let m = AdditiveBezier::new(vec![Pose::<f64>::identity(), Pose::identity().scale(&2.0)]).unwrap();
/// let psi = velocity_indicatrix(&m, &1.0).unwrap();
/// assert_eq!((psi.scalar, psi.e12), (1.0, 0.0));
/// ```
pub fn velocity_indicatrix<T: Field + PartialOrd, M: MapScalar<T, Jet<T>>>(
    motion: &M,
    t: &T,
) -> Result<Even<T>, CurveError> {
    let (s, ds) = pose_derivative(motion, t)?;
    Ok(indicatrix_from_derivative(&s, &ds)?)
}

/// `Ψ(t)` and `dΨ/dt`: the definition of [`indicatrix_from_derivative`] run over `Jet<T>` on
/// the second-order dual-number evaluation of the motion.
///
/// ```
/// use motion::velocity::velocity_indicatrix_derivative;
/// use motion::{AdditiveBezier, Pose};
/// // S(t) = 1 + t, Ψ = 2/(1 + t), dΨ/dt = -2/(1 + t)².
/// let m = AdditiveBezier::new(vec![Pose::<f64>::identity(), Pose::identity().scale(&2.0)]).unwrap();
/// let (psi, dpsi) = velocity_indicatrix_derivative(&m, &1.0).unwrap();
/// assert_eq!((psi.scalar, dpsi.scalar), (1.0, -0.5));
/// ```
pub fn velocity_indicatrix_derivative<T: Real, M: MapScalar<T, Jet<Jet<T>>>>(
    motion: &M,
    t: &T,
) -> Result<(Even<T>, Even<T>), CurveError> {
    let s = evaluate2(motion, t)?;
    let (value, derivative) = split_jet(&s);
    let psi = indicatrix_from_derivative(&value, &derivative)?;
    Ok(split_jet(&psi))
}

/// `(γ, ν)`: the pseudoscalar part `γ = ½(Ψ + rev Ψ)` and the bivector part
/// `ν = ½(Ψ - rev Ψ)` of an even element (Sec. 3), computed with the reverse as printed.
///
/// ```
/// use motion::{Bivector, Even};
/// use motion::velocity::split_indicatrix;
/// let psi = Even::new(0.5, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0);
/// let (gamma, nu) = split_indicatrix(&psi);
/// assert_eq!((gamma.scalar, gamma.e123inf), (0.5, 7.0));
/// assert_eq!(nu, Bivector::new(1.0, 2.0, 3.0, 4.0, 5.0, 6.0));
/// assert_eq!(&Even::from(&gamma) + &Even::from(&nu), psi); // Ψ = γ + ν
/// ```
pub fn split_indicatrix<T: Ring>(psi: &Even<T>) -> (Pseudoscalar<T>, Bivector<T>) {
    let half = T::from_ratio(1, 2);
    let rev = psi.reverse();
    let gamma = (psi + &rev).scale(&half);
    let nu = (psi - &rev).scale(&half);
    (gamma.project_to_pseudoscalar(), nu.project_to_bivector())
}

/// The velocity bivector `ν(t)`: the bivector part of [`velocity_indicatrix`].
///
/// ```
/// use motion::velocity::velocity_bivector;
/// use motion::{AdditiveBezier, Pose};
/// let m = AdditiveBezier::new(vec![Pose::<f64>::identity(), Pose::translation(&[3.0, 0.0, 0.0])]).unwrap();
/// let nu = velocity_bivector(&m, &0.5).unwrap();
/// assert_eq!(nu.e1inf, 3.0); // u = (3, 0, 0)
/// ```
pub fn velocity_bivector<T: Field + PartialOrd, M: MapScalar<T, Jet<T>>>(
    motion: &M,
    t: &T,
) -> Result<Bivector<T>, CurveError> {
    Ok(split_indicatrix(&velocity_indicatrix(motion, t)?).1)
}

/// A twist: the angular velocity `Ω` and the linear velocity `u` of a velocity bivector
/// `ν = Ω e123 + u einf` (Theorem 3.2). Which frame the two vectors are in depends on where the
/// twist came from:
///
/// * the **space twist** ([`Velocity::twist`], [`Velocity::space_twist`], `ν` of
///   `Ψ = 2 S⁻¹ dS/dt`): `Ω` in the fixed frame, and `u` the velocity of the body point that is
///   instantaneously at the *global origin* (not of the body origin), in the fixed frame;
/// * the **body twist** ([`Velocity::body_twist`], `ν_b = S ν S⁻¹`): `Ω` and the velocity of
///   the *body origin*, both in body coordinates (nalgebra/robotics "body velocity").
///
/// The velocity of any body point follows from either ([`Twist::point_velocity`]).
///
/// ```
/// use motion::velocity::Twist;
/// use motion::Vec3;
/// let t = Twist { angular: Vec3::new(0.0, 0.0, 1.0), linear: Vec3::new(1.0, 0.0, 0.0) };
/// let nu = t.to_bivector();
/// assert_eq!((nu.e12, nu.e1inf), (1.0, 1.0));
/// assert_eq!(Twist::from_bivector(&nu), t);
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct Twist<T> {
    /// `Ω`.
    pub angular: Vec3<T>,
    /// `u`.
    pub linear: Vec3<T>,
}

impl<T: Ring> Twist<T> {
    /// Reads `Ω = (ν23, -ν13, ν12)` and `u = (ν1∞, ν2∞, ν3∞)` off `ν`.
    ///
    /// ```
    /// use motion::{Bivector, velocity::Twist};
    /// let nu = Bivector::new(3.0, 2.0, 1.0, 4.0, 5.0, 6.0);
    /// let t = Twist::from_bivector(&nu);
    /// assert_eq!((t.angular, t.linear), ([1.0, -2.0, 3.0].into(), [4.0, 5.0, 6.0].into()));
    /// ```
    pub fn from_bivector(nu: &Bivector<T>) -> Self {
        Twist { angular: nu.rotational(), linear: nu.translational() }
    }

    /// `ν = Ω e123 + u einf` (Theorem 3.2).
    ///
    /// ```
    /// use motion::{Bivector, Vec3, velocity::Twist};
    /// let t = Twist { angular: Vec3::new(1.0, -2.0, 3.0), linear: Vec3::new(4.0, 5.0, 6.0) };
    /// assert_eq!(t.to_bivector(), Bivector::new(3.0, 2.0, 1.0, 4.0, 5.0, 6.0));
    /// ```
    pub fn to_bivector(&self) -> Bivector<T> {
        Bivector::from_parts(&self.angular, &self.linear)
    }

    /// The velocity of the body point instantaneously at `q` (in the twist's frame):
    /// `v_Q = u + (q ∧ Ω) e123 = u + Ω × q` (eq. 14 with Lemma 2.1). For a space twist `q` is
    /// the point's current global position; for a body twist, its body coordinates (and the
    /// result is in body coordinates).
    ///
    /// ```
    /// use motion::{Vec3, velocity::Twist};
    /// // Spinning about e3 at unit rate: the point at (1, 0, 0) moves along e2.
    /// let t = Twist { angular: Vec3::new(0.0, 0.0, 1.0), linear: Vec3::zero() };
    /// assert_eq!(t.point_velocity(&[1.0, 0.0, 0.0]), [0.0, 1.0, 0.0]);
    /// ```
    pub fn point_velocity(&self, q: &[T; 3]) -> Vec3<T> {
        self.linear.add(&self.angular.cross(&Vec3::from(q)))
    }
}

/// Corollary 3.3: the velocity bivector `ν = Ω e123 + v einf + (Ω ∧ r) ω` of a body with
/// angular velocity `Ω` whose point instantaneously at `r` has velocity `v`. Computed as
/// printed: `Ω ∧ r` is the bivector `Σ (Ω_i r_j - Ω_j r_i) e_ij` of G_123, multiplied by
/// `ω = e123inf` with the geometric product of G_{123inf}.
///
/// ```
/// use motion::velocity::{Twist, bivector_from_point_velocity};
/// // Spinning about e3 at unit rate with the origin fixed: the point at (1, 0, 0) moves along e2.
/// let nu = bivector_from_point_velocity(&[0.0, 0.0, 1.0], &[1.0, 0.0, 0.0], &[0.0, 1.0, 0.0]);
/// assert_eq!(Twist::from_bivector(&nu), Twist { angular: [0.0, 0.0, 1.0].into(), linear: [0.0, 0.0, 0.0].into() });
/// ```
pub fn bivector_from_point_velocity<T: Ring>(omega: &[T; 3], r: &[T; 3], v: &[T; 3]) -> Bivector<T> {
    let z = T::zero;
    let wedge = |i: usize, j: usize| omega[i].mul_ref(&r[j]).sub_ref(&omega[j].mul_ref(&r[i]));
    let omega_wedge_r = Bivector::new(wedge(0, 1), wedge(0, 2), wedge(1, 2), z(), z(), z());
    let pseudo = Pseudoscalar::new(z(), T::one());
    let base = Bivector::from_parts(&Vec3::from(omega), &Vec3::from(v));
    let rotated: Bivector<T> = &omega_wedge_r * &pseudo;
    &base + &rotated
}

/// The first-order state of a motion at one parameter value: `S`, `dS/dt` and `Ψ`.
///
/// ```
/// use motion::velocity::velocity;
/// use motion::{AdditiveBezier, Pose};
/// let m = AdditiveBezier::new(vec![Pose::<f64>::identity(), Pose::translation(&[3.0, 0.0, 0.0])]).unwrap();
/// let v = velocity(&m, &0.0).unwrap();
/// assert_eq!(v.twist().linear, [3.0, 0.0, 0.0]);
/// assert_eq!(v.pose, Pose::identity());
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct Velocity<T: Ring> {
    /// `S(t)`.
    pub pose: Pose<T>,
    /// `dS/dt`.
    pub derivative: Even<T>,
    /// `Ψ(t) = 2 S⁻¹ dS/dt`.
    pub indicatrix: Even<T>,
}

/// [`Velocity`] of a motion at `t`.
///
/// ```
/// use motion::velocity::velocity;
/// use motion::{MultiplicativeBezier, Pose};
/// let m = MultiplicativeBezier::new(vec![Pose::<f64>::identity(), Pose::rotation(&[1.0, 0.0, 0.0], &2.0).unwrap()]).unwrap();
/// assert!((velocity(&m, &0.3).unwrap().twist().angular[0] - 2.0).abs() < 1e-15);
/// ```
pub fn velocity<T: Field + PartialOrd, M: MapScalar<T, Jet<T>>>(motion: &M, t: &T) -> Result<Velocity<T>, CurveError> {
    let (pose, derivative) = pose_derivative(motion, t)?;
    let indicatrix = indicatrix_from_derivative(&pose, &derivative)?;
    Ok(Velocity { pose, derivative, indicatrix })
}

impl<T: Real> Velocity<T> {
    /// The pseudoscalar part `γ` of `Ψ` (zero for unitary motions, Lemma 3.4).
    ///
    /// ```
    /// use motion::velocity::velocity;
    /// use motion::{AdditiveBezier, Pose};
    /// let m = AdditiveBezier::new(vec![Pose::<f64>::identity(), Pose::identity().scale(&3.0)]).unwrap();
    /// assert_eq!(velocity(&m, &0.0).unwrap().gamma().scalar, 4.0); // 2 · (3 - 1) / 1
    /// ```
    pub fn gamma(&self) -> Pseudoscalar<T> {
        split_indicatrix(&self.indicatrix).0
    }

    /// The velocity bivector `ν` (the bivector part of `Ψ`).
    ///
    /// ```
    /// use motion::velocity::velocity;
    /// use motion::{AdditiveBezier, Pose};
    /// let m = AdditiveBezier::new(vec![Pose::<f64>::identity(), Pose::translation(&[0.0, 2.0, 0.0])]).unwrap();
    /// assert_eq!(velocity(&m, &0.0).unwrap().nu().e2inf, 2.0);
    /// ```
    pub fn nu(&self) -> Bivector<T> {
        split_indicatrix(&self.indicatrix).1
    }

    /// `Ω` and `u` from `ν = Ω e123 + u einf` (Theorem 3.2).
    ///
    /// ```
    /// use motion::velocity::velocity;
    /// use motion::{MultiplicativeBezier, Pose};
    /// let m = MultiplicativeBezier::new(vec![Pose::<f64>::identity(), Pose::rotation(&[0.0, 1.0, 0.0], &1.0).unwrap()]).unwrap();
    /// let w = velocity(&m, &0.5).unwrap().twist().angular;
    /// assert!(w[0].abs() < 1e-15 && (w[1] - 1.0).abs() < 1e-15 && w[2].abs() < 1e-15);
    /// ```
    pub fn twist(&self) -> Twist<T> {
        Twist::from_bivector(&self.nu())
    }

    /// The space twist: the same as [`Velocity::twist`] (`Ω` in the fixed frame, `u` the
    /// velocity of the body point at the global origin), named for the frame.
    ///
    /// ```
    /// use motion::velocity::velocity;
    /// use motion::{MultiplicativeBezier, Pose};
    /// let m = MultiplicativeBezier::new(vec![Pose::<f64>::identity(), Pose::translation(&[1.0, 0.0, 0.0])]).unwrap();
    /// let v = velocity(&m, &0.5).unwrap();
    /// assert_eq!(v.space_twist(), v.twist());
    /// ```
    pub fn space_twist(&self) -> Twist<T> {
        self.twist()
    }

    /// The body twist: `ν_b = S ν S⁻¹` read as `Ω_b e123 + u_b einf`, so `Ω_b` is the angular
    /// velocity in body coordinates and `u_b` the velocity of the body origin in body
    /// coordinates (`Ω = A Ω_b`, `F_S(0)' = A u_b` for the rotation `A` of `F_S`). Fails for
    /// singular `S`.
    ///
    /// ```
    /// use motion::velocity::velocity;
    /// use motion::{MultiplicativeBezier, Pose};
    /// use std::f64::consts::FRAC_PI_2;
    /// // A quarter turn about e3, then moving along the fixed e1 axis at unit speed.
    /// let a = Pose::from_axis_angle_translation(&[0.0, 0.0, 1.0], &FRAC_PI_2, &[0.0, 0.0, 0.0]).unwrap();
    /// let b = Pose::from_axis_angle_translation(&[0.0, 0.0, 1.0], &FRAC_PI_2, &[1.0, 0.0, 0.0]).unwrap();
    /// let v = velocity(&MultiplicativeBezier::new(vec![a, b]).unwrap(), &0.5).unwrap();
    /// let body = v.body_twist().unwrap();
    /// // In body coordinates the body moves along its own -e2 axis (e1 = A(-e2)).
    /// assert!(body.linear[0].abs() < 1e-15 && (body.linear[1] + 1.0).abs() < 1e-15);
    /// ```
    pub fn body_twist(&self) -> Result<Twist<T>, MotionError> {
        let nu = Even::from(&self.nu());
        let body = &(&self.pose * &nu) * &self.pose.try_inverse()?;
        Ok(Twist::from_bivector(&body.project_to_bivector()))
    }

    /// The velocity of the body point currently at `q` (global coordinates), eq. (14).
    ///
    /// ```
    /// use motion::velocity::velocity;
    /// use motion::{MultiplicativeBezier, Pose};
    /// let m = MultiplicativeBezier::new(vec![Pose::<f64>::identity(), Pose::rotation(&[0.0, 0.0, 1.0], &1.0).unwrap()]).unwrap();
    /// let v = velocity(&m, &0.0).unwrap().point_velocity(&[2.0, 0.0, 0.0]);
    /// assert!(v[0].abs() < 1e-15 && (v[1] - 2.0).abs() < 1e-15);
    /// ```
    pub fn point_velocity(&self, q: &[T; 3]) -> Vec3<T> {
        self.twist().point_velocity(q)
    }

    /// The current position `q = F_S(p)` and velocity (eq. 14) of the body point with body
    /// coordinates `p`. Fails for singular `S`.
    ///
    /// ```
    /// use motion::velocity::velocity;
    /// use motion::{MultiplicativeBezier, Pose};
    /// let m = MultiplicativeBezier::new(vec![Pose::<f64>::identity(), Pose::rotation(&[0.0, 0.0, 1.0], &1.0).unwrap()]).unwrap();
    /// let (q, v) = velocity(&m, &0.0).unwrap().body_point_velocity(&[0.0, 3.0, 0.0]).unwrap();
    /// assert_eq!(q, [0.0, 3.0, 0.0]);
    /// assert!((v[0] + 3.0).abs() < 1e-15 && v[1].abs() < 1e-15);
    /// ```
    pub fn body_point_velocity(&self, p: &[T; 3]) -> Result<([T; 3], [T; 3]), MotionError> {
        let q = self.pose.transform_point(p)?;
        let v = self.point_velocity(&q).into();
        Ok((q, v))
    }
}

/// The second-order state of a motion at one parameter value: the [`Velocity`], `d²S/dt²` and
/// `dΨ/dt`, all from one evaluation over `Jet<Jet<T>>`.
///
/// ```
/// use motion::velocity::acceleration;
/// use motion::{AdditiveBezier, Pose};
/// let m = AdditiveBezier::new(vec![Pose::<f64>::identity(), Pose::identity(), Pose::translation(&[2.0, 0.0, 0.0])]).unwrap();
/// let a = acceleration(&m, &0.5).unwrap(); // S = 1 + t² e1inf: a translation by 2t², u = 4t
/// assert_eq!(a.twist_derivative().linear, [4.0, 0.0, 0.0]);
/// assert_eq!(a.second_derivative.e1inf, 2.0);
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct Acceleration<T: Ring> {
    /// `S`, `dS/dt`, `Ψ`.
    pub velocity: Velocity<T>,
    /// `d²S/dt²`.
    pub second_derivative: Even<T>,
    /// `dΨ/dt`.
    pub indicatrix_derivative: Even<T>,
}

/// [`Acceleration`] of a motion at `t`.
///
/// ```
/// use motion::velocity::acceleration;
/// use motion::{MultiplicativeBezier, Pose};
/// // Constant-rate rotation: dΩ/dt = 0.
/// let m = MultiplicativeBezier::new(vec![Pose::<f64>::identity(), Pose::rotation(&[0.0, 0.0, 1.0], &1.0).unwrap()]).unwrap();
/// let a = acceleration(&m, &0.4).unwrap();
/// assert!(a.twist_derivative().angular.to_array().iter().all(|x| x.abs() < 1e-15));
/// ```
pub fn acceleration<T: Real, M: MapScalar<T, Jet<Jet<T>>>>(motion: &M, t: &T) -> Result<Acceleration<T>, CurveError> {
    let s = evaluate2(motion, t)?;
    let (value, derivative) = split_jet(&s);
    let psi = indicatrix_from_derivative(&value, &derivative)?;
    let (pose, ds) = split_jet(&value);
    let (_, dds) = split_jet(&derivative);
    let (indicatrix, indicatrix_derivative) = split_jet(&psi);
    Ok(Acceleration {
        velocity: Velocity { pose, derivative: ds, indicatrix },
        second_derivative: dds,
        indicatrix_derivative,
    })
}

impl<T: Real> Acceleration<T> {
    /// `dγ/dt`, the pseudoscalar part of `dΨ/dt`.
    ///
    /// ```
    /// use motion::velocity::acceleration;
    /// use motion::{AdditiveBezier, Pose};
    /// // S = 1 + t: γ = 2/(1 + t), dγ/dt = -2/(1 + t)².
    /// let m = AdditiveBezier::new(vec![Pose::<f64>::identity(), Pose::identity().scale(&2.0)]).unwrap();
    /// assert_eq!(acceleration(&m, &0.0).unwrap().gamma_derivative().scalar, -2.0);
    /// ```
    pub fn gamma_derivative(&self) -> Pseudoscalar<T> {
        split_indicatrix(&self.indicatrix_derivative).0
    }

    /// `dν/dt`, the bivector part of `dΨ/dt`.
    ///
    /// ```
    /// use motion::velocity::acceleration;
    /// use motion::{AdditiveBezier, Pose};
    /// let m = AdditiveBezier::new(vec![Pose::<f64>::identity(), Pose::identity(), Pose::translation(&[0.0, 0.0, 2.0])]).unwrap();
    /// assert_eq!(acceleration(&m, &0.0).unwrap().nu_derivative().e3inf, 4.0); // ν = 4t e3inf
    /// ```
    pub fn nu_derivative(&self) -> Bivector<T> {
        split_indicatrix(&self.indicatrix_derivative).1
    }

    /// `dΩ/dt` and `du/dt` (global coordinates). `du/dt` is the rate of change of the velocity of
    /// whichever body point is at the origin, not the acceleration of one body point: see
    /// [`body_point_kinematics`].
    ///
    /// ```
    /// use motion::velocity::acceleration;
    /// use motion::{AdditiveBezier, Pose};
    /// let m = AdditiveBezier::new(vec![Pose::<f64>::identity(), Pose::identity(), Pose::translation(&[0.0, 0.0, 2.0])]).unwrap();
    /// assert_eq!(acceleration(&m, &0.3).unwrap().twist_derivative().linear, [0.0, 0.0, 4.0]);
    /// ```
    pub fn twist_derivative(&self) -> Twist<T> {
        Twist::from_bivector(&self.nu_derivative())
    }
}

/// Position, velocity and acceleration of one body point.
///
/// ```
/// use motion::velocity::PointKinematics;
/// let k = PointKinematics { position: [0.0; 3], velocity: [1.0, 0.0, 0.0], acceleration: [0.0; 3] };
/// assert_eq!(k.velocity[0], 1.0);
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct PointKinematics<T> {
    /// `F_{S(t)}(p)`.
    pub position: [T; 3],
    /// Its first derivative.
    pub velocity: [T; 3],
    /// Its second derivative.
    pub acceleration: [T; 3],
}

/// Position, velocity and acceleration of the body point with body coordinates `p`:
/// [`Pose::transform_point`] run over `Jet<Jet<T>>` on the motion evaluated at
/// `(t + ε₁) + ε₂` (independent of Ψ, so it checks eq. 14).
///
/// ```
/// use motion::velocity::body_point_kinematics;
/// use motion::{MultiplicativeBezier, Pose};
/// // Unit-rate rotation about e3: the point (1, 0, 0) has centripetal acceleration -q.
/// let m = MultiplicativeBezier::new(vec![Pose::<f64>::identity(), Pose::rotation(&[0.0, 0.0, 1.0], &1.0).unwrap()]).unwrap();
/// let k = body_point_kinematics(&m, &0.0, &[1.0, 0.0, 0.0]).unwrap();
/// assert!((k.velocity[1] - 1.0).abs() < 1e-15 && (k.acceleration[0] + 1.0).abs() < 1e-15);
/// ```
pub fn body_point_kinematics<T: Real, M: MapScalar<T, Jet<Jet<T>>>>(
    motion: &M,
    t: &T,
    p: &[T; 3],
) -> Result<PointKinematics<T>, CurveError> {
    let s = evaluate2(motion, t)?;
    let x = s.transform_point(&p.clone().map(|c| lift2(&c)))?;
    Ok(PointKinematics {
        position: x.clone().map(|c| c.re.re),
        velocity: x.clone().map(|c| c.re.eps),
        acceleration: x.map(|c| c.eps.eps),
    })
}
