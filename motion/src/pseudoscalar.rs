//! Pseudoscalars `c = a + bω` (ω = e123inf, ω² = 0): Lemma 2.4 of the main paper.
//!
//! The pseudoscalars form a commutative subalgebra of G_{123inf}, central in G_{123inf}^+, and
//! behave as dual numbers `a + bε`. `c` is *non-singular* when `a ≠ 0`. The functions here act
//! on the generated [`Pseudoscalar`] type (fields `scalar` = a, `e123inf` = b); they are free
//! functions because the type is generated in another crate.
//!
//! ```
//! use gam_algebras::g123inf::Pseudoscalar;
//! use motion::pseudoscalar;
//! let c = Pseudoscalar::new(4.0, 2.0); // 4 + 2ω
//! let r = pseudoscalar::sqrt(&c).unwrap(); // (2·4 + 2ω)/(2·2) = 2 + 0.5ω
//! assert_eq!((r.scalar, r.e123inf), (2.0, 0.5));
//! ```

use crate::MotionError;
use algebra_core::{Field, Real, Ring};
use gam_algebras::g123inf::Pseudoscalar;

fn error<T: Ring>(op: &'static str, c: &Pseudoscalar<T>, need: &'static str) -> MotionError {
    MotionError::Pseudoscalar { op, value: c.to_string(), need }
}

/// The inverse `(a - bω)/a²` of a non-singular pseudoscalar (Lemma 2.4(i)); exact over exact
/// scalars.
///
/// ```
/// use algebra_core::rational::{q, ratio};
/// use gam_algebras::g123inf::Pseudoscalar;
/// let c = Pseudoscalar::new(q(2), q(3));
/// let inv = motion::pseudoscalar::inverse(&c).unwrap();
/// assert_eq!(inv, Pseudoscalar::new(ratio(1, 2), ratio(-3, 4)));
/// assert_eq!(&c * &inv, Pseudoscalar::new(q(1), q(0)));
/// assert!(motion::pseudoscalar::inverse(&Pseudoscalar::new(q(0), q(1))).is_err());
/// ```
pub fn inverse<T: Field>(c: &Pseudoscalar<T>) -> Result<Pseudoscalar<T>, MotionError> {
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
/// use gam_algebras::g123inf::Pseudoscalar;
/// let c = Pseudoscalar::new(ratio(9, 4), q(5));
/// let r = motion::pseudoscalar::sqrt_with_root(&c, &ratio(3, 2)).unwrap();
/// assert_eq!(&r * &r, c);
/// ```
pub fn sqrt_with_root<T: Field>(c: &Pseudoscalar<T>, root: &T) -> Result<Pseudoscalar<T>, MotionError> {
    let inv_2r = root.add_ref(root).try_recip().ok_or_else(|| error("sqrt", c, "non-zero"))?;
    let two_a = c.scalar.add_ref(&c.scalar);
    Ok(Pseudoscalar::new(two_a.mul_ref(&inv_2r), c.e123inf.mul_ref(&inv_2r)))
}

/// The principal square root `(2a + bω)/(2√a)` of `a + bω` with `a > 0` (Lemma 2.4(ii)).
///
/// ```
/// use gam_algebras::g123inf::Pseudoscalar;
/// assert!(motion::pseudoscalar::sqrt(&Pseudoscalar::new(-1.0, 0.0)).is_err());
/// let r = motion::pseudoscalar::sqrt(&Pseudoscalar::new(2.0f64, 1.0)).unwrap();
/// let back = &r * &r;
/// assert!((back.scalar - 2.0).abs() < 1e-15 && (back.e123inf - 1.0).abs() < 1e-15);
/// ```
pub fn sqrt<T: Real>(c: &Pseudoscalar<T>) -> Result<Pseudoscalar<T>, MotionError> {
    positive("sqrt", c)?;
    sqrt_with_root(c, &Real::sqrt(&c.scalar))
}

/// The logarithm `ln a + (b/a)ω` of `a + bω` with `a > 0` (the dual-number logarithm).
///
/// ```
/// use gam_algebras::g123inf::Pseudoscalar;
/// let l = motion::pseudoscalar::ln(&Pseudoscalar::new(1.0, 3.0)).unwrap();
/// assert_eq!((l.scalar, l.e123inf), (0.0, 3.0));
/// assert!(motion::pseudoscalar::ln(&Pseudoscalar::new(0.0, 3.0)).is_err());
/// ```
pub fn ln<T: Real>(c: &Pseudoscalar<T>) -> Result<Pseudoscalar<T>, MotionError> {
    positive("ln", c)?;
    Ok(Pseudoscalar::new(Real::ln(&c.scalar), c.e123inf.div_ref(&c.scalar)))
}

/// The exponential `e^a (1 + bω)` of `a + bω`.
///
/// ```
/// use gam_algebras::g123inf::Pseudoscalar;
/// let e = motion::pseudoscalar::exp(&Pseudoscalar::new(0.0, 3.0));
/// assert_eq!((e.scalar, e.e123inf), (1.0, 3.0));
/// ```
pub fn exp<T: Real>(c: &Pseudoscalar<T>) -> Pseudoscalar<T> {
    let ea = Real::exp(&c.scalar);
    let b = c.e123inf.mul_ref(&ea);
    Pseudoscalar::new(ea, b)
}

fn positive<T: Real>(op: &'static str, c: &Pseudoscalar<T>) -> Result<(), MotionError> {
    if !(c.scalar.is_finite() && c.e123inf.is_finite()) {
        return Err(MotionError::NotFinite { op, value: c.to_string() });
    }
    if c.scalar > T::zero() { Ok(()) } else { Err(error(op, c, "positive")) }
}
