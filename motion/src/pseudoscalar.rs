//! Pseudoscalars `c = a + bω` (ω = e123inf, ω² = 0): Lemma 2.4 of the main paper.
//!
//! The pseudoscalars form a commutative subalgebra of G_{123inf}, central in G_{123inf}^+, and
//! behave as dual numbers `a + bε`. `c` is *non-singular* when `a ≠ 0`. [`Pseudoscalar`]
//! (fields `scalar` = a, `e123inf` = b) has the inherent methods [`Pseudoscalar::try_inverse`],
//! [`Pseudoscalar::sqrt`], [`Pseudoscalar::exp`], [`Pseudoscalar::ln`] and
//! [`Pseudoscalar::pow`]; the free functions of this module are the same operations under their
//! earlier names.
//!
//! ```
//! use motion::Pseudoscalar;
//! let c = Pseudoscalar::new(4.0, 2.0); // 4 + 2ω
//! let r = c.sqrt().unwrap(); // (2·4 + 2ω)/(2·2) = 2 + 0.5ω
//! assert_eq!((r.scalar, r.e123inf), (2.0, 0.5));
//! ```

use crate::{MotionError, Pseudoscalar};
use algebra_core::{Field, Real, Ring};

fn error<T: Ring>(op: &'static str, c: &Pseudoscalar<T>, need: &'static str) -> MotionError {
    MotionError::Pseudoscalar { op, value: c.to_string(), need }
}

impl<T: Field> Pseudoscalar<T> {
    /// The inverse `(a - bω)/a²` of a non-singular pseudoscalar (Lemma 2.4(i)); exact over exact
    /// scalars. (The generated `inverse` solves the same by elimination, with an
    /// [`algebra_core::MvError`].)
    ///
    /// ```
    /// use algebra_core::rational::{q, ratio};
    /// use motion::Pseudoscalar;
    /// let c = Pseudoscalar::new(q(2), q(3));
    /// let inv = c.try_inverse().unwrap();
    /// assert_eq!(inv, Pseudoscalar::new(ratio(1, 2), ratio(-3, 4)));
    /// assert_eq!(&c * &inv, Pseudoscalar::new(q(1), q(0)));
    /// assert!(Pseudoscalar::new(q(0), q(1)).try_inverse().is_err());
    /// ```
    pub fn try_inverse(&self) -> Result<Self, MotionError> {
        let c = self;
        let inv_a = c.scalar.try_recip().ok_or_else(|| error("inverse", c, "non-zero"))?;
        let minus_b_over_a2 = c.e123inf.mul_ref(&inv_a).mul_ref(&inv_a).neg_ref();
        Ok(Pseudoscalar::new(inv_a, minus_b_over_a2))
    }

    /// The square root `(2a + bω)/(2r)` of `a + bω` given a root `r` of `a` (`r² = a`, not
    /// checked): Lemma 2.4(ii) over any field, so the formula can be checked exactly. Pass `-r`
    /// for the other root.
    ///
    /// ```
    /// use algebra_core::rational::{q, ratio};
    /// use motion::Pseudoscalar;
    /// let c = Pseudoscalar::new(ratio(9, 4), q(5));
    /// let r = c.sqrt_with_root(&ratio(3, 2)).unwrap();
    /// assert_eq!(&r * &r, c);
    /// ```
    pub fn sqrt_with_root(&self, root: &T) -> Result<Self, MotionError> {
        let c = self;
        let inv_2r = root.add_ref(root).try_recip().ok_or_else(|| error("sqrt", c, "non-zero"))?;
        let two_a = c.scalar.add_ref(&c.scalar);
        Ok(Pseudoscalar::new(two_a.mul_ref(&inv_2r), c.e123inf.mul_ref(&inv_2r)))
    }
}

impl<T: Real> Pseudoscalar<T> {
    /// The principal square root `(2a + bω)/(2√a)` of `a + bω` with `a > 0` (Lemma 2.4(ii)).
    ///
    /// ```
    /// use motion::Pseudoscalar;
    /// assert!(Pseudoscalar::new(-1.0, 0.0).sqrt().is_err());
    /// let r = Pseudoscalar::new(2.0f64, 1.0).sqrt().unwrap();
    /// let back = &r * &r;
    /// assert!((back.scalar - 2.0).abs() < 1e-15 && (back.e123inf - 1.0).abs() < 1e-15);
    /// ```
    pub fn sqrt(&self) -> Result<Self, MotionError> {
        positive("sqrt", self)?;
        self.sqrt_with_root(&Real::sqrt(&self.scalar))
    }

    /// The logarithm `ln a + (b/a)ω` of `a + bω` with `a > 0` (the dual-number logarithm).
    ///
    /// ```
    /// use motion::Pseudoscalar;
    /// let l = Pseudoscalar::new(1.0, 3.0).ln().unwrap();
    /// assert_eq!((l.scalar, l.e123inf), (0.0, 3.0));
    /// assert!(Pseudoscalar::new(0.0, 3.0).ln().is_err());
    /// ```
    pub fn ln(&self) -> Result<Self, MotionError> {
        positive("ln", self)?;
        Ok(Pseudoscalar::new(Real::ln(&self.scalar), self.e123inf.div_ref(&self.scalar)))
    }

    /// The exponential `e^a (1 + bω)` of `a + bω`.
    ///
    /// ```
    /// use motion::Pseudoscalar;
    /// let e = Pseudoscalar::new(0.0, 3.0).exp();
    /// assert_eq!((e.scalar, e.e123inf), (1.0, 3.0));
    /// ```
    pub fn exp(&self) -> Self {
        let ea = Real::exp(&self.scalar);
        let b = self.e123inf.mul_ref(&ea);
        Pseudoscalar::new(ea, b)
    }

    /// The power `c^t = exp(t ln c) = a^t (1 + t (b/a) ω)` of `a + bω` with `a > 0`: the
    /// pseudoscalar factor `|S|^t` of the power of a non-unit pose (eq. 16).
    ///
    /// ```
    /// use motion::Pseudoscalar;
    /// let c = Pseudoscalar::new(4.0, 2.0);
    /// let h = c.pow(&0.5).unwrap();
    /// assert_eq!(h, c.sqrt().unwrap());
    /// assert!(Pseudoscalar::new(-4.0, 2.0).pow(&0.5).is_err());
    /// ```
    pub fn pow(&self, t: &T) -> Result<Self, MotionError> {
        let l = self.ln()?;
        Ok(l.scale(t).exp())
    }
}

/// [`Pseudoscalar::try_inverse`].
///
/// ```
/// use motion::Pseudoscalar;
/// assert_eq!(motion::pseudoscalar::inverse(&Pseudoscalar::new(2.0, 0.0)).unwrap().scalar, 0.5);
/// ```
pub fn inverse<T: Field>(c: &Pseudoscalar<T>) -> Result<Pseudoscalar<T>, MotionError> {
    c.try_inverse()
}

/// [`Pseudoscalar::sqrt_with_root`].
///
/// ```
/// use motion::Pseudoscalar;
/// assert_eq!(motion::pseudoscalar::sqrt_with_root(&Pseudoscalar::new(4.0, 0.0), &2.0).unwrap().scalar, 2.0);
/// ```
pub fn sqrt_with_root<T: Field>(c: &Pseudoscalar<T>, root: &T) -> Result<Pseudoscalar<T>, MotionError> {
    c.sqrt_with_root(root)
}

/// [`Pseudoscalar::sqrt`].
///
/// ```
/// use motion::Pseudoscalar;
/// assert_eq!(motion::pseudoscalar::sqrt(&Pseudoscalar::new(4.0, 0.0)).unwrap().scalar, 2.0);
/// ```
pub fn sqrt<T: Real>(c: &Pseudoscalar<T>) -> Result<Pseudoscalar<T>, MotionError> {
    c.sqrt()
}

/// [`Pseudoscalar::ln`].
///
/// ```
/// use motion::Pseudoscalar;
/// assert_eq!(motion::pseudoscalar::ln(&Pseudoscalar::new(1.0, 0.0)).unwrap().scalar, 0.0);
/// ```
pub fn ln<T: Real>(c: &Pseudoscalar<T>) -> Result<Pseudoscalar<T>, MotionError> {
    c.ln()
}

/// [`Pseudoscalar::exp`].
///
/// ```
/// use motion::Pseudoscalar;
/// assert_eq!(motion::pseudoscalar::exp(&Pseudoscalar::new(0.0, 1.0)).e123inf, 1.0);
/// ```
pub fn exp<T: Real>(c: &Pseudoscalar<T>) -> Pseudoscalar<T> {
    c.exp()
}

fn positive<T: Real>(op: &'static str, c: &Pseudoscalar<T>) -> Result<(), MotionError> {
    if !(c.scalar.is_finite() && c.e123inf.is_finite()) {
        return Err(MotionError::NotFinite { op, value: c.to_string() });
    }
    if c.scalar > T::zero() { Ok(()) } else { Err(error(op, c, "positive")) }
}
