//! [`MpFloat`]: MPFR floats (rug) at a chosen precision, as a [`Real`].
//!
//! A value carries its own precision; a binary operation rounds to the larger of its operands'
//! precisions. Constants (`zero`, `one`, `from_ratio`, `pi`, ...) are made at the *default
//! precision* of the current thread, which [`set_default_precision`] or a scoped
//! [`PrecisionGuard`] sets (initially 256 bits).

use super::mprational::rug_rational;
use super::{Field, Real, Ring};
use crate::rational::Q;
use rug::Float;
use rug::float::Constant;
use std::cell::Cell;
use std::fmt;
use std::ops::{Add, Div, Mul, Neg, Sub};

thread_local! {
    static DEFAULT_PRECISION: Cell<u32> = const { Cell::new(256) };
}

/// The current thread's default precision in bits for new [`MpFloat`] constants.
///
/// ```
/// let _g = algebra_core::PrecisionGuard::new(128);
/// assert_eq!(algebra_core::default_precision(), 128);
/// ```
pub fn default_precision() -> u32 {
    DEFAULT_PRECISION.with(Cell::get)
}

/// Sets the current thread's default precision in bits (clamped to MPFR's valid range).
///
/// ```
/// algebra_core::set_default_precision(300);
/// assert_eq!(algebra_core::default_precision(), 300);
/// ```
pub fn set_default_precision(bits: u32) {
    let bits = bits.clamp(rug::float::prec_min(), rug::float::prec_max());
    DEFAULT_PRECISION.with(|p| p.set(bits));
}

/// Sets the default precision for its lifetime and restores the previous one when dropped.
///
/// ```
/// use algebra_core::{PrecisionGuard, default_precision};
/// let before = default_precision();
/// {
///     let _g = PrecisionGuard::new(512);
///     assert_eq!(default_precision(), 512);
/// }
/// assert_eq!(default_precision(), before);
/// ```
#[derive(Debug)]
pub struct PrecisionGuard {
    previous: u32,
}

impl PrecisionGuard {
    /// Sets `bits` as the default precision until the guard is dropped.
    pub fn new(bits: u32) -> Self {
        let previous = default_precision();
        set_default_precision(bits);
        PrecisionGuard { previous }
    }
}

impl Drop for PrecisionGuard {
    fn drop(&mut self) {
        set_default_precision(self.previous);
    }
}

/// A multiple-precision float (a newtype over `rug::Float`).
///
/// ```
/// use algebra_core::{MpFloat, PrecisionGuard, Real, Ring};
/// let _g = PrecisionGuard::new(256);
/// let two = MpFloat::from_i64(2);
/// let r = Real::sqrt(&two);
/// let err = r.mul_ref(&r).sub_ref(&two);
/// assert!(err.magnitude() < 1e-75);
/// ```
#[derive(Clone, Debug, PartialEq, PartialOrd)]
pub struct MpFloat(pub Float);

impl MpFloat {
    /// Wraps a value at the default precision.
    ///
    /// ```
    /// let x = algebra_core::MpFloat::new(0.5);
    /// assert_eq!(x.0.prec(), algebra_core::default_precision());
    /// ```
    pub fn new<V>(value: V) -> Self
    where
        Float: rug::Assign<V>,
    {
        MpFloat(Float::with_val(default_precision(), value))
    }

    /// The precision of this value in bits.
    ///
    /// ```
    /// let x = algebra_core::MpFloat(rug::Float::with_val(100, 1));
    /// assert_eq!(x.precision(), 100);
    /// ```
    pub fn precision(&self) -> u32 {
        self.0.prec()
    }

    fn prec2(&self, rhs: &Self) -> u32 {
        self.0.prec().max(rhs.0.prec())
    }

    /// Decimal digits that identify a value of this precision.
    fn digits(&self) -> usize {
        (f64::from(self.0.prec()) * std::f64::consts::LOG10_2).ceil() as usize + 1
    }
}

impl fmt::Display for MpFloat {
    /// Enough significant decimal digits to identify the value at its precision (trailing
    /// zeros dropped), plain for moderate exponents and with `e` otherwise: `1.5`,
    /// `-2.5e-7`.
    ///
    /// ```
    /// use algebra_core::{MpFloat, PrecisionGuard, Ring};
    /// let _g = PrecisionGuard::new(256);
    /// assert_eq!(MpFloat::from_ratio(3, 2).to_string(), "1.5");
    /// assert_eq!(MpFloat::from_i64(-1234).to_string(), "-1234");
    /// assert!(MpFloat::from_ratio(1, 3).to_string().starts_with("3.33333333333333333333333333333333333333333333333333333333333333333333333333"));
    /// ```
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.0.is_zero() {
            return f.write_str("0");
        }
        let s = self.0.to_string_radix(10, Some(self.digits()));
        let (mantissa, exponent) = match s.find('e') {
            Some(i) => s.split_at(i),
            None => (s.as_str(), ""),
        };
        let mantissa =
            if mantissa.contains('.') { mantissa.trim_end_matches('0').trim_end_matches('.') } else { mantissa };
        write!(f, "{mantissa}{exponent}")
    }
}

macro_rules! binop {
    ($tr:ident, $m:ident) => {
        impl $tr for MpFloat {
            type Output = Self;
            fn $m(self, rhs: Self) -> Self {
                let p = self.prec2(&rhs);
                MpFloat(Float::with_val(p, (&self.0).$m(&rhs.0)))
            }
        }
        impl<'a> $tr<&'a MpFloat> for MpFloat {
            type Output = Self;
            fn $m(self, rhs: &'a Self) -> Self {
                let p = self.prec2(rhs);
                MpFloat(Float::with_val(p, (&self.0).$m(&rhs.0)))
            }
        }
    };
}
binop!(Add, add);
binop!(Sub, sub);
binop!(Mul, mul);
binop!(Div, div);

impl Neg for MpFloat {
    type Output = Self;
    fn neg(self) -> Self {
        MpFloat(-self.0)
    }
}

impl Ring for MpFloat {
    fn zero() -> Self {
        MpFloat::new(0)
    }
    fn one() -> Self {
        MpFloat::new(1)
    }
    fn from_i64(n: i64) -> Self {
        MpFloat::new(n)
    }
    fn from_ratio(num: i64, den: i64) -> Self {
        MpFloat::new(&rug::Rational::from((num, den)))
    }
    fn from_rational(q: &Q) -> Self {
        MpFloat::new(&rug_rational(q))
    }
    fn is_exact_zero(&self) -> bool {
        self.0.is_zero()
    }
    fn magnitude(&self) -> f64 {
        self.0.to_f64().abs()
    }
    fn relative_epsilon() -> f64 {
        2f64.powi(1 - default_precision() as i32)
    }
    fn is_finite_value(&self) -> bool {
        self.0.is_finite()
    }
    fn cmp_magnitude(&self, other: &Self) -> std::cmp::Ordering {
        self.0.cmp_abs(&other.0).unwrap_or_else(|| self.0.is_nan().cmp(&other.0.is_nan()))
    }
    /// `|self| <= ulps · 2^(1 - p) · |scale|` in MPFR, `p` the larger precision of the two.
    fn is_negligible(&self, scale: &Self, ulps: u32) -> bool {
        if self.0.is_zero() {
            return true;
        }
        let p = self.prec2(scale);
        let mut bound = Float::with_val(p + 32, scale.0.abs_ref()) * ulps;
        bound >>= p as i32 - 1;
        self.0.cmp_abs(&bound).is_some_and(|o| o.is_le())
    }
    fn add_ref(&self, rhs: &Self) -> Self {
        MpFloat(Float::with_val(self.prec2(rhs), &self.0 + &rhs.0))
    }
    fn sub_ref(&self, rhs: &Self) -> Self {
        MpFloat(Float::with_val(self.prec2(rhs), &self.0 - &rhs.0))
    }
    fn mul_ref(&self, rhs: &Self) -> Self {
        MpFloat(Float::with_val(self.prec2(rhs), &self.0 * &rhs.0))
    }
    fn neg_ref(&self) -> Self {
        MpFloat(Float::with_val(self.0.prec(), -&self.0))
    }
    fn add_assign_ref(&mut self, rhs: &Self) {
        if rhs.0.prec() > self.0.prec() {
            self.0.set_prec(rhs.0.prec());
        }
        self.0 += &rhs.0;
    }
    fn sub_assign_ref(&mut self, rhs: &Self) {
        if rhs.0.prec() > self.0.prec() {
            self.0.set_prec(rhs.0.prec());
        }
        self.0 -= &rhs.0;
    }
}

impl Field for MpFloat {
    fn try_recip(&self) -> Option<Self> {
        let r = Float::with_val(self.0.prec(), self.0.recip_ref());
        (!self.0.is_zero() && r.is_finite()).then_some(MpFloat(r))
    }
    fn div_ref(&self, rhs: &Self) -> Self {
        MpFloat(Float::with_val(self.prec2(rhs), &self.0 / &rhs.0))
    }
}

macro_rules! unary {
    ($name:ident, $rug:ident) => {
        fn $name(&self) -> Self {
            MpFloat(Float::with_val(self.0.prec(), self.0.$rug()))
        }
    };
}

impl Real for MpFloat {
    unary!(sqrt, sqrt_ref);
    unary!(exp, exp_ref);
    unary!(ln, ln_ref);
    unary!(sin, sin_ref);
    unary!(cos, cos_ref);
    unary!(sinh, sinh_ref);
    unary!(cosh, cosh_ref);
    unary!(atanh, atanh_ref);
    unary!(abs, abs_ref);
    fn atan2(&self, x: &Self) -> Self {
        MpFloat(Float::with_val(self.prec2(x), self.0.atan2_ref(&x.0)))
    }
    fn to_f64(&self) -> f64 {
        self.0.to_f64()
    }
    fn from_f64(x: f64) -> Self {
        MpFloat::new(x)
    }
    fn pi() -> Self {
        MpFloat::new(Constant::Pi)
    }
    fn epsilon() -> Self {
        let p = default_precision();
        MpFloat(Float::with_val(p, Float::u_exp(1, 1 - p as i32)))
    }
    fn is_finite(&self) -> bool {
        self.0.is_finite()
    }
    fn precision_bits(&self) -> Option<u32> {
        Some(self.0.prec())
    }
    fn with_precision(&self, bits: u32) -> Self {
        MpFloat(Float::with_val(bits, &self.0))
    }
    fn with_working_precision<R>(bits: u32, f: impl FnOnce() -> R) -> R {
        let _guard = PrecisionGuard::new(bits);
        f()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pi_at_256_bits_has_75_correct_digits() {
        let _g = PrecisionGuard::new(256);
        let pi = MpFloat::pi().to_string();
        let reference = "3.14159265358979323846264338327950288419716939937510582097494459230781640628";
        assert!(pi.starts_with(&reference[..76]), "{pi}");
    }

    #[test]
    fn exact_constants() {
        let _g = PrecisionGuard::new(200);
        let third = MpFloat::from_ratio(1, 3);
        let back = third.mul_ref(&MpFloat::from_i64(3));
        assert!(back.sub_ref(&MpFloat::one()).magnitude() < 1e-59);
        assert!(MpFloat::relative_epsilon() < 1e-59);
    }
}
