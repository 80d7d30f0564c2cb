//! Scalar traits: [`Ring`] ⊂ [`Field`] ⊂ [`Real`].
//!
//! Every generic algorithm and every generated kernel in GAM is bounded on these traits, never
//! on `Copy` (rug numbers are not `Copy`) and never on a float literal: constants enter through
//! [`Ring::from_ratio`] or [`Ring::from_rational`], so the same code is exact over rationals and
//! polynomials and approximate over floats.
//!
//! | trait | adds | implemented for |
//! |---|---|---|
//! | [`Ring`] | `+ - *`, exact rational constants, exact zero test | everything below, and `Poly` (feature `rug`) |
//! | [`Field`] | division, checked reciprocal | all but polynomials |
//! | [`Real`] | `sqrt`, `exp`, `ln`, trig, ordering, precision-aware epsilon | `f32`, `f64`, num-dual types, [`Jet`], `MpFloat` (feature `rug`) |
//!
//! Beside them, the layer for code that must also run over SIMD lanes (module `decide`):
//! [`Elementary`] (the functions without an ordering), [`Select`] and [`Mask`] (decisions as
//! data), [`Diagnostics`] (sizes a lane type can give honestly) and [`LaneReal`] (all three).
//! Every [`Real`] has them by blanket impl; the lane types
#![cfg_attr(feature = "lanes", doc = "[`F32x4`], [`F32x8`], [`F64x2`], [`F64x4`]")]
#![cfg_attr(not(feature = "lanes"), doc = "`F32x4`, `F32x8`, `F64x2`, `F64x4`")]
//! (feature `lanes`) and [`LaneDual`] implement them and are never [`Real`].
//! [`Lanes`] (module `pack`) is the lane width and the packing of element columns into lane
//! values and back, for `f64`, `f32`, [`Q`] (width 1) and the SIMD lane types.
//!
//! Reference arithmetic (`&a * &b`) cannot be a supertrait bound that Rust elaborates at use
//! sites, so the trait offers it as methods ([`Ring::mul_ref`], ...) with efficient overrides
//! for types whose clones are expensive.

/// The [`Ring`] reference-arithmetic methods for a type whose references already implement
/// `&a + &b`, `&a - &b`, `&a * &b` and `-&a` (floats, num-dual types, `BigRational`).
macro_rules! native_ref_ops {
    () => {
        fn add_ref(&self, rhs: &Self) -> Self {
            self + rhs
        }
        fn sub_ref(&self, rhs: &Self) -> Self {
            self - rhs
        }
        fn mul_ref(&self, rhs: &Self) -> Self {
            self * rhs
        }
        fn neg_ref(&self) -> Self {
            -self
        }
    };
}

mod atan;
mod decide;
mod dual;
mod exact;
mod float;
mod jet;
mod lane_dual;
#[cfg(feature = "lanes")]
mod lanes;
#[cfg(feature = "rug")]
mod mpfloat;
#[cfg(feature = "rug")]
pub(crate) mod mprational;
mod pack;

pub use atan::atan2_f64;
pub use decide::{Diagnostics, Elementary, LaneReal, Mask, Select};
pub use jet::Jet;
pub use lane_dual::LaneDual;
#[cfg(feature = "lanes")]
pub use lanes::{F32x4, F32x8, F64x2, F64x4, MaskF32x4, MaskF32x8, MaskF64x2, MaskF64x4};
#[cfg(feature = "rug")]
pub use mpfloat::{MpFloat, PrecisionGuard, default_precision, set_default_precision};
#[cfg(feature = "rug")]
pub use mprational::MpRational;
pub use pack::Lanes;

use crate::rational::Q;
use std::fmt::{Debug, Display};
use std::ops::{Add, Div, Mul, Neg, Sub};

/// A commutative ring containing the rationals (a Q-algebra): the scalars of product tables,
/// sandwiches and polynomial identities.
///
/// Implementations must be exact where the type is exact: `from_ratio(1, 3) * 3 == one()` for
/// rationals and polynomials.
///
/// ```
/// use algebra_core::Ring;
/// fn double_then_halve<T: Ring>(x: &T) -> T {
///     x.mul_ref(&T::from_i64(2)).mul_ref(&T::from_ratio(1, 2))
/// }
/// assert_eq!(double_then_halve(&1.5f64), 1.5);
/// ```
pub trait Ring:
    Clone
    + Debug
    + Display
    + PartialEq
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Neg<Output = Self>
    + for<'a> Add<&'a Self, Output = Self>
    + for<'a> Sub<&'a Self, Output = Self>
    + for<'a> Mul<&'a Self, Output = Self>
{
    /// The additive identity.
    fn zero() -> Self;
    /// The multiplicative identity.
    fn one() -> Self;
    /// The integer `n`.
    fn from_i64(n: i64) -> Self;
    /// The exact ratio `num / den` (`den != 0`; kernels only use non-zero constant denominators).
    fn from_ratio(num: i64, den: i64) -> Self;
    /// An arbitrary-size exact rational (table coefficients).
    fn from_rational(q: &Q) -> Self;
    /// True only when *every* component is zero (for dual numbers: the real part and all
    /// derivative parts). Never used to drop terms in kernels; used for printing and pivots.
    fn is_exact_zero(&self) -> bool;
    /// A non-negative size used to choose pivots and test series convergence: `|x|` for
    /// floats, the largest absolute component for dual numbers, `|x|` rounded to f64 for
    /// rationals. Not for exact decisions.
    fn magnitude(&self) -> f64;
    /// The relative precision of the type: `0.0` for exact types, machine epsilon for floats,
    /// `2^(1 - bits)` for multiple-precision floats.
    fn relative_epsilon() -> f64;

    /// `|self|` compared with `|other|`, decided in the type's own precision and exponent
    /// range: exactly for rationals, in MPFR for `MpFloat` (feature `rug`). The default
    /// compares [`Ring::magnitude`] (exact for `f32`/`f64`; the largest component for dual
    /// numbers).
    ///
    /// ```
    /// use algebra_core::{Ring, rational::ratio};
    /// use std::cmp::Ordering;
    /// assert_eq!(ratio(-1, 2).cmp_magnitude(&ratio(1, 3)), Ordering::Greater);
    /// assert_eq!((-2.0f64).cmp_magnitude(&2.0), Ordering::Equal);
    /// ```
    fn cmp_magnitude(&self, other: &Self) -> std::cmp::Ordering {
        self.magnitude().total_cmp(&other.magnitude())
    }
    /// True when `|self| <= ulps · ε · |scale|`, with ε the type's relative precision, decided
    /// in the type's own precision and exponent range. For exact types (ε = 0) only an exact
    /// zero is negligible: pivots, convergence and zero tests never round a non-zero exact
    /// value to zero.
    ///
    /// ```
    /// use algebra_core::{Ring, rational::ratio};
    /// assert!(1e-17f64.is_negligible(&1.0, 1));
    /// assert!(!1e-15f64.is_negligible(&1.0, 1));
    /// assert!(!ratio(1, 1_000_000_000).is_negligible(&ratio(1, 1), 1_000));
    /// ```
    fn is_negligible(&self, scale: &Self, ulps: u32) -> bool {
        if self.is_exact_zero() {
            return true;
        }
        let eps = Self::relative_epsilon();
        eps > 0.0 && self.magnitude() <= f64::from(ulps) * eps * scale.magnitude()
    }

    /// False when the value (any component, for dual numbers) is NaN or infinite; always true
    /// for exact types. Lets code generic over a [`Ring`] or [`Field`] refuse non-finite
    /// input with a typed error.
    ///
    /// ```
    /// use algebra_core::{Ring, rational::ratio};
    /// assert!(!f64::NAN.is_finite_value() && 1.0f64.is_finite_value() && ratio(1, 3).is_finite_value());
    /// ```
    fn is_finite_value(&self) -> bool {
        true
    }

    /// `self + rhs` without consuming either operand.
    fn add_ref(&self, rhs: &Self) -> Self {
        self.clone() + rhs
    }
    /// `self - rhs` without consuming either operand.
    fn sub_ref(&self, rhs: &Self) -> Self {
        self.clone() - rhs
    }
    /// `self * rhs` without consuming either operand.
    fn mul_ref(&self, rhs: &Self) -> Self {
        self.clone() * rhs
    }
    /// `-self` without consuming it.
    fn neg_ref(&self) -> Self {
        -self.clone()
    }
    /// `self += rhs`.
    fn add_assign_ref(&mut self, rhs: &Self) {
        let lhs = std::mem::replace(self, Self::zero());
        *self = lhs + rhs;
    }
    /// `self -= rhs`.
    fn sub_assign_ref(&mut self, rhs: &Self) {
        let lhs = std::mem::replace(self, Self::zero());
        *self = lhs - rhs;
    }
    /// `self * q` for an exact rational `q`, with fast paths for `0` and `±1`.
    fn scale_rational(&self, q: &Q) -> Self {
        use num_traits::{One, Zero};
        if q.is_one() {
            self.clone()
        } else if q.is_zero() {
            Self::zero()
        } else if (-q).is_one() {
            self.neg_ref()
        } else {
            self.mul_ref(&Self::from_rational(q))
        }
    }
    /// `self^n` by repeated squaring.
    fn pow_u32(&self, mut n: u32) -> Self {
        let mut base = self.clone();
        let mut acc = Self::one();
        while n > 0 {
            if n & 1 == 1 {
                acc = acc.mul_ref(&base);
            }
            n >>= 1;
            if n > 0 {
                base = base.mul_ref(&base);
            }
        }
        acc
    }
}

/// A [`Ring`] with division.
///
/// ```
/// use algebra_core::Field;
/// assert_eq!(Field::try_recip(&4.0f64), Some(0.25));
/// assert_eq!(Field::try_recip(&0.0f64), None);
/// ```
pub trait Field: Ring + Div<Output = Self> + for<'a> Div<&'a Self, Output = Self> {
    /// `1 / self`, or `None` when `self` is zero (exactly zero for exact types; zero or with a
    /// non-finite reciprocal for floats).
    fn try_recip(&self) -> Option<Self>;
    /// `self / rhs` without consuming either operand (`rhs` must be non-zero).
    fn div_ref(&self, rhs: &Self) -> Self {
        self.clone() / rhs
    }
}

/// An ordered [`Field`] with the elementary functions: what exp, log and motion code need.
///
/// Comparisons look at the value (for dual numbers: the real part only, as num-dual does).
///
/// ```
/// use algebra_core::Real;
/// let x = 0.5f64;
/// assert!((Real::sin(&x).powi(2) + Real::cos(&x).powi(2) - 1.0).abs() < 1e-15);
/// ```
pub trait Real: Field + PartialOrd {
    /// Square root (of a non-negative value).
    fn sqrt(&self) -> Self;
    /// Exponential.
    fn exp(&self) -> Self;
    /// Natural logarithm (of a positive value).
    fn ln(&self) -> Self;
    /// Sine.
    fn sin(&self) -> Self;
    /// Cosine.
    fn cos(&self) -> Self;
    /// Hyperbolic sine.
    fn sinh(&self) -> Self;
    /// Hyperbolic cosine.
    fn cosh(&self) -> Self;
    /// Four-quadrant arctangent of `self / x`.
    fn atan2(&self, x: &Self) -> Self;
    /// [`Real::atan2`] by the fastest kernel the type has that is accurate to a few units in
    /// the last place: `f64` and `f32` use [`atan2_f64`] (inlined polynomial, within 2.33 ulp
    /// of the correctly rounded value at `f64`; libm's `atan2` is within 0.5 ulp but is an
    /// out-of-line call), [`Jet`] passes it to its real part, every other type (num-dual
    /// types, `MpFloat` at any precision) uses its `atan2`. The closed-form logarithms
    /// ([`crate::closed_form::log_factors`]) call it.
    ///
    /// ```
    /// use algebra_core::Real;
    /// let (y, x) = (0.3f64, -0.8);
    /// assert!((Real::fast_atan2(&y, &x) - y.atan2(x)).abs() < 3.0 * 2.8 * f64::EPSILON);
    /// ```
    fn fast_atan2(&self, x: &Self) -> Self {
        self.atan2(x)
    }
    /// Inverse hyperbolic tangent.
    fn atanh(&self) -> Self;
    /// Absolute value.
    fn abs(&self) -> Self;
    /// The value as f64 (the real part for dual numbers), rounded.
    fn to_f64(&self) -> f64;
    /// The nearest value to `x` (at the default precision for multiple-precision floats).
    fn from_f64(x: f64) -> Self;
    /// π at the type's precision.
    fn pi() -> Self;
    /// The precision-aware epsilon: [`Ring::relative_epsilon`] as a value of the type.
    fn epsilon() -> Self {
        Self::from_f64(Self::relative_epsilon())
    }
    /// True when the value is finite (for dual numbers: every component).
    fn is_finite(&self) -> bool;
    /// The bits of precision this value carries, for multiple-precision types; `None` for
    /// fixed-precision ones (`f32`, `f64`, dual numbers), which cannot add guard bits.
    ///
    /// ```
    /// assert_eq!(algebra_core::Real::precision_bits(&1.0f64), None);
    /// ```
    fn precision_bits(&self) -> Option<u32> {
        None
    }
    /// The value at `bits` bits of precision (rounded to nearest, or extended exactly), for
    /// multiple-precision types; unchanged for fixed-precision ones.
    ///
    /// ```
    /// assert_eq!(algebra_core::Real::with_precision(&0.1f64, 10), 0.1);
    /// ```
    fn with_precision(&self, bits: u32) -> Self {
        let _ = bits;
        self.clone()
    }
    /// Runs `f` with the precision of newly made constants (`one`, `from_ratio`, `pi`, ...)
    /// set to `bits`, for multiple-precision types; fixed-precision types just run `f`. The
    /// general exp/log/sqrt use it to compute with guard bits.
    ///
    /// ```
    /// assert_eq!(<f64 as algebra_core::Real>::with_working_precision(500, || 1.0 + 1.0), 2.0);
    /// ```
    fn with_working_precision<R>(bits: u32, f: impl FnOnce() -> R) -> R {
        let _ = bits;
        f()
    }
}
