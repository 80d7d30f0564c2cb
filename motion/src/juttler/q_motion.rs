//! Q-motions (Jüttler eq. 13): Bézier curves `Q(t) = Σ b_i^n(t) B_i` of dual quaternions
//! `B_i ∈ H[ε]` that satisfy Plücker's (Study's) relation (8) for every `t`.
//!
//! The relation is a polynomial condition: `Scal(Q⁰(t) Q̃^ε(t)) = Q⁰(t)·Q^ε(t)` is a polynomial
//! of degree `2n` whose Bernstein coefficients follow from the product formula (29)
//! ([`QMotion::study_polynomial`]); a Q-motion is a curve for which it vanishes identically,
//! checked exactly over rationals ([`QMotion::new_exact`]) or relative to the coefficients'
//! size in floating point ([`QMotion::new`]).
//!
//! ```
//! use algebra_core::rational::{q, ratio};
//! use gam_algebras::DualQuaternion;
//! use motion::juttler::QMotion;
//! // a quarter turn about z: Q(t) = (1 - t) + t (1 + k), no dual part
//! let rot = QMotion::new_exact(vec![
//!     DualQuaternion::from_coeffs([q(1), q(0), q(0), q(0), q(0), q(0), q(0), q(0)]),
//!     DualQuaternion::from_coeffs([q(1), q(0), q(0), q(1), q(0), q(0), q(0), q(0)]),
//! ]).unwrap();
//! let end = rot.pose_exact(&q(1)).unwrap();
//! assert_eq!(end.transform_point(&[q(1), q(0), q(0)]).unwrap(), [q(0), q(1), q(0)]);
//! ```

use super::{JuttlerError, bernstein_product, de_casteljau_with, elevate_with};
use crate::repr::ReprError;
use crate::repr::dual_quaternion::{DualQuaternion, from_dual_quaternion, from_dual_quaternion_exact};
use crate::{CurveError, MapScalar, Motion, MotionError, Pose};
use algebra_core::{Field, Real, Ring};

/// A Q-motion of degree `n` (eq. 13) on `[0, 1]`: `n + 1` dual-quaternion control points
/// `B_i` whose Bézier curve lies on the Study quadric (8). Proportional curves are the same
/// motion.
///
/// ```
/// use gam_algebras::DualQuaternion;
/// use motion::{Motion, juttler::QMotion};
/// // the translation from 0 to (2, 0, 0): Q(t) = 2 + ε t (2, 0, 0)
/// let m = QMotion::new(vec![
///     DualQuaternion::from_coeffs([2.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0]),
///     DualQuaternion::from_coeffs([2.0, 0.0, 0.0, 0.0, 0.0, 2.0, 0.0, 0.0]),
/// ], 1e-12).unwrap();
/// let p: [f64; 3] = m.pose(&0.25).unwrap().transform_point(&[0.0, 0.0, 0.0]).unwrap();
/// assert!((p[0] - 0.5).abs() < 1e-15);
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct QMotion<T> {
    control: Vec<DualQuaternion<T>>,
}

fn lerp<T: Ring>(a: &DualQuaternion<T>, b: &DualQuaternion<T>, s: &T, t: &T) -> DualQuaternion<T> {
    &a.scale(s) + &b.scale(t)
}

impl<T: Ring> QMotion<T> {
    /// The Q-motion with control points `control`, if its Study polynomial
    /// ([`QMotion::study_polynomial`]) is zero up to `tol` relative to `max|B_i⁰| max|B_j^ε|`
    /// (`tol = 0`: exactly zero). Fails for no control points or off the quadric.
    ///
    /// ```
    /// use gam_algebras::DualQuaternion;
    /// use motion::juttler::{JuttlerError, QMotion};
    /// // 1 and ε: the curve (1 - t) + ε t has Q⁰·Q^ε = t(1 - t) ≠ 0
    /// let off = QMotion::new(vec![
    ///     DualQuaternion::from_coeffs([1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0]),
    ///     DualQuaternion::from_coeffs([0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0]),
    /// ], 1e-12);
    /// assert!(matches!(off, Err(JuttlerError::NotQMotion { index: 1, .. })));
    /// ```
    pub fn new(control: Vec<DualQuaternion<T>>, tol: f64) -> Result<Self, JuttlerError> {
        if control.is_empty() {
            return Err(JuttlerError::TooFewPositions { need: 1, got: 0 });
        }
        let m = QMotion { control };
        let max = |f: &dyn Fn(&DualQuaternion<T>) -> f64| m.control.iter().map(f).fold(0.0, f64::max);
        let scale = (max(&|b| b.real.norm_squared().magnitude()) * max(&|b| b.dual.norm_squared().magnitude())).sqrt();
        for (index, s) in m.study_polynomial().iter().enumerate() {
            let off = if tol == 0.0 {
                !s.is_exact_zero()
            } else {
                s.magnitude().partial_cmp(&(tol * scale)).is_none_or(|o| o == std::cmp::Ordering::Greater)
            };
            if off {
                return Err(JuttlerError::NotQMotion { index, value: s.to_string() });
            }
        }
        Ok(m)
    }

    /// [`QMotion::new`] with `tol = 0`: the Study polynomial must vanish exactly (for exact
    /// scalars such as [`algebra_core::rational::Q`]).
    ///
    /// ```
    /// use algebra_core::rational::q;
    /// use gam_algebras::DualQuaternion;
    /// let one = DualQuaternion::from_coeffs([q(1), q(0), q(0), q(0), q(0), q(0), q(0), q(0)]);
    /// assert_eq!(motion::juttler::QMotion::new_exact(vec![one]).unwrap().degree(), 0);
    /// ```
    pub fn new_exact(control: Vec<DualQuaternion<T>>) -> Result<Self, JuttlerError> {
        Self::new(control, 0.0)
    }

    /// The curve with these control points, without the Study check: for sums and products of
    /// Q-motions that lie on the quadric by construction.
    pub(crate) fn from_control_unchecked(control: Vec<DualQuaternion<T>>) -> Self {
        QMotion { control }
    }

    /// The control points `B_0, …, B_n`.
    ///
    /// ```
    /// use gam_algebras::DualQuaternion;
    /// let m = motion::juttler::QMotion::new(vec![DualQuaternion::<f64>::one()], 0.0).unwrap();
    /// assert_eq!(m.control(), [DualQuaternion::one()]);
    /// ```
    pub fn control(&self) -> &[DualQuaternion<T>] {
        &self.control
    }

    /// The degree `n`.
    ///
    /// ```
    /// use gam_algebras::DualQuaternion;
    /// let m = motion::juttler::QMotion::new(vec![DualQuaternion::<f64>::one(); 3], 0.0).unwrap();
    /// assert_eq!(m.degree(), 2);
    /// ```
    pub fn degree(&self) -> usize {
        self.control.len() - 1
    }

    /// `Q(t)` by de Casteljau's algorithm, at any `t` (exact over rationals).
    ///
    /// ```
    /// use algebra_core::rational::{q, ratio};
    /// use gam_algebras::DualQuaternion;
    /// let c = |w: i64, z: i64| DualQuaternion::from_coeffs([q(w), q(0), q(0), q(z), q(0), q(0), q(0), q(0)]);
    /// let m = motion::juttler::QMotion::new_exact(vec![c(1, 0), c(1, 1)]).unwrap();
    /// assert_eq!(m.eval(&ratio(1, 2)), c(2, 1).scale(&ratio(1, 2)));
    /// ```
    pub fn eval(&self, t: &T) -> DualQuaternion<T> {
        de_casteljau_with(&self.control, t, lerp)
    }

    /// The same curve with degree `n + 1` (degree elevation; exact).
    ///
    /// ```
    /// use algebra_core::rational::{q, ratio};
    /// use gam_algebras::DualQuaternion;
    /// let c = |w: i64, z: i64| DualQuaternion::from_coeffs([q(w), q(0), q(0), q(z), q(0), q(0), q(0), q(0)]);
    /// let m = motion::juttler::QMotion::new_exact(vec![c(1, 0), c(1, 1)]).unwrap();
    /// let e = m.elevate();
    /// assert_eq!(e.degree(), 2);
    /// assert_eq!(e.eval(&ratio(1, 3)), m.eval(&ratio(1, 3)));
    /// ```
    pub fn elevate(&self) -> Self {
        let control = elevate_with(&self.control, |a, s, b, t: &T| &a.scale(s) + &b.scale(t));
        QMotion { control }
    }

    /// The product `Q(t) = self(t) * other(t)` (degree `n + l`) by the product formula (29);
    /// the product of two Q-motions is a Q-motion (the Study quadric is closed under
    /// multiplication), and it applies `other`'s displacement first (Jüttler's `Q_trans * Q_rot`
    /// of (30) rotates, then translates).
    ///
    /// ```
    /// use algebra_core::rational::{q, ratio};
    /// use gam_algebras::DualQuaternion;
    /// use motion::juttler::QMotion;
    /// let d = |c: [i64; 8]| DualQuaternion::from_coeffs(c.map(q));
    /// let rot = QMotion::new_exact(vec![d([1, 0, 0, 0, 0, 0, 0, 0]), d([1, 0, 0, 1, 0, 0, 0, 0])]).unwrap();
    /// let tr = QMotion::new_exact(vec![d([2, 0, 0, 0, 0, 0, 0, 0]), d([2, 0, 0, 0, 0, 1, 0, 0])]).unwrap();
    /// let m = tr.product(&rot);
    /// assert_eq!(m.degree(), 2);
    /// assert_eq!(m.eval(&ratio(1, 3)), &tr.eval(&ratio(1, 3)) * &rot.eval(&ratio(1, 3)));
    /// ```
    pub fn product(&self, other: &Self) -> Self {
        let control = bernstein_product(
            &self.control,
            &other.control,
            DualQuaternion::zero(),
            |a, b| a * b,
            |acc, x, f: &T| acc + &x.scale(f),
        );
        QMotion { control }
    }

    /// The Bernstein coefficients (degree `2n`) of the Study polynomial `Q⁰(t)·Q^ε(t)`, the
    /// dual part of `Q Q̃` halved (Plücker's relation (8) along the curve), by (29); all zero
    /// exactly when the curve is a Q-motion.
    ///
    /// ```
    /// use algebra_core::rational::{q, ratio};
    /// use gam_algebras::DualQuaternion;
    /// let d = |c: [i64; 8]| DualQuaternion::from_coeffs(c.map(q));
    /// // (1 - t) + ε t: Q⁰·Q^ε = t (1 - t) = ½ b_1^2
    /// let m = motion::juttler::QMotion::new(vec![d([1, 0, 0, 0, 0, 0, 0, 0]), d([0, 0, 0, 0, 1, 0, 0, 0])], 1.0).unwrap();
    /// assert_eq!(m.study_polynomial(), [q(0), ratio(1, 2), q(0)]);
    /// ```
    pub fn study_polynomial(&self) -> Vec<T> {
        let c = &self.control;
        bernstein_product(c, c, T::zero(), |a, b| a.real.dot(&b.dual), |acc, x, f: &T| acc.add_ref(&x.mul_ref(f)))
    }

    /// The same Q-motion over the scalar `U`, each coefficient mapped by `f`.
    ///
    /// ```
    /// use algebra_core::rational::{q, rational_to_f64};
    /// use gam_algebras::DualQuaternion;
    /// let m = motion::juttler::QMotion::new_exact(vec![DualQuaternion::from_coeffs([q(1), q(0), q(0), q(0), q(0), q(0), q(0), q(0)])]).unwrap();
    /// assert_eq!(m.map_ring(&rational_to_f64).control()[0], DualQuaternion::one());
    /// ```
    pub fn map_ring<U: Ring>(&self, f: &dyn Fn(&T) -> U) -> QMotion<U> {
        QMotion {
            control: self.control.iter().map(|b| DualQuaternion::from_coeffs(b.coeffs().map(|x| f(&x)))).collect(),
        }
    }
}

impl<T: Field> QMotion<T> {
    /// The pose at `t` through the exact dual quaternion -> pose map
    /// ([`from_dual_quaternion_exact`]): exact over rationals at any `t`; fails where `Q⁰(t) = 0`
    /// (a pole of the motion) or, for inexact scalars, where rounding leaves `Q(t)` off the
    /// quadric (use [`Motion::pose`] there).
    ///
    /// ```
    /// use algebra_core::rational::{q, ratio};
    /// use gam_algebras::DualQuaternion;
    /// let d = |c: [i64; 8]| DualQuaternion::from_coeffs(c.map(q));
    /// let m = motion::juttler::QMotion::new_exact(vec![d([2, 0, 0, 0, 0, 0, 0, 0]), d([2, 0, 0, 0, 0, 2, 0, 0])]).unwrap();
    /// let p = m.pose_exact(&ratio(1, 4)).unwrap().transform_point(&[q(0), q(0), q(0)]).unwrap();
    /// assert_eq!(p, [ratio(1, 2), q(0), q(0)]);
    /// ```
    pub fn pose_exact(&self, t: &T) -> Result<Pose<T>, JuttlerError> {
        Ok(from_dual_quaternion_exact(&self.eval(t))?)
    }
}

/// The pose of a dual quaternion of a curve on the Study quadric (checked as a polynomial, so
/// the pointwise check is off); a pole (`Q⁰ = 0`) is [`MotionError::Singular`].
pub(crate) fn pose_of<T: Real>(q: &DualQuaternion<T>) -> Result<Pose<T>, CurveError> {
    from_dual_quaternion(q, &T::one()).map_err(|e| match e {
        ReprError::Motion(m) => CurveError::Pose(m),
        ReprError::Curve(c) => c,
        ReprError::NotFinite => CurveError::Pose(MotionError::NotFinite { op: "Q-motion", value: q.to_string() }),
        _ => CurveError::Pose(MotionError::Singular { op: "Q-motion (pole, zero real part)", value: q.to_string() }),
    })
}

/// A Q-motion is a [`Motion`] on `[0, 1]`: the pose of `Q(t)` by the map of
/// [`crate::repr::dual_quaternion`]. The Study condition was checked as a polynomial when the
/// motion was built, so the pointwise check is off (`tol = 1` bounds every cosine); a pole
/// (`Q⁰(t) = 0`) is [`MotionError::Singular`].
impl<T: Real> Motion<T> for QMotion<T> {
    fn evaluate(&self, t: &T) -> Result<Pose<T>, CurveError> {
        pose_of(&self.eval(t))
    }

    fn domain(&self) -> [T; 2] {
        [T::zero(), T::one()]
    }
}

impl<T: Real, U: Real> MapScalar<T, U> for QMotion<T> {
    type Mapped = QMotion<U>;
    fn map_scalar(&self, f: &dyn Fn(&T) -> U) -> QMotion<U> {
        self.map_ring(f)
    }
}
