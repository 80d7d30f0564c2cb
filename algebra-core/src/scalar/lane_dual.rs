//! [`LaneDual`]: a first-order dual number `re + eps ε` (`ε² = 0`) over any
//! [`LaneReal`](super::LaneReal), so derivatives run over SIMD lanes too.
//!
//! num-dual's types are generic over a `DualNum<F>` scalar whose `F` must be a
//! `num_traits::Float` (ordered, `Copy`, `NumCast`): a lane type is not one, so lanes get this
//! small dual of their own. Over a [`Real`](crate::Real) it agrees with [`Jet`](crate::Jet)
//! (tested); [`Jet`](crate::Jet) stays the type for ordered scalars.
//!
//! Decisions ([`Select`]) compare real parts, as num-dual's `<` does; `==`,
//! [`Ring::is_exact_zero`] and [`Ring::magnitude`] look at both parts.
//!
//! ```
//! use algebra_core::scalar::{Elementary, LaneDual};
//! // d/dx sin(x) at x = 0.5
//! let x = LaneDual::variable(0.5f64);
//! let y = x.sin();
//! assert_eq!((y.re, y.eps), (0.5f64.sin(), 0.5f64.cos()));
//! ```

use super::{Diagnostics, Elementary, Field, LaneReal, Ring, Select};
use crate::rational::Q;
use std::fmt;
use std::ops::{Add, Div, Mul, Neg, Sub};

/// `re + eps ε` with `ε² = 0`: the value and one directional derivative, over any
/// [`LaneReal`] (a lane type, or a scalar).
///
/// ```
/// use algebra_core::scalar::LaneDual;
/// use algebra_core::Ring;
/// let x = LaneDual::variable(3.0f64);
/// let y = x.mul_ref(&x); // x², derivative 2x
/// assert_eq!((y.re, y.eps), (9.0, 6.0));
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LaneDual<L> {
    /// The value.
    pub re: L,
    /// The derivative part (coefficient of ε).
    pub eps: L,
}

impl<L: LaneReal> LaneDual<L> {
    /// `re + eps ε`.
    pub fn new(re: L, eps: L) -> Self {
        LaneDual { re, eps }
    }
    /// The constant `re` (derivative zero).
    pub fn constant(re: L) -> Self {
        LaneDual { re, eps: L::zero() }
    }
    /// The variable `re + ε` (derivative one).
    pub fn variable(re: L) -> Self {
        LaneDual { re, eps: L::one() }
    }
    /// `f(re) + f'(re) eps ε` from `f(re)` and `f'(re)`.
    fn chain(&self, value: L, slope: L) -> Self {
        LaneDual { re: value, eps: slope.mul_ref(&self.eps) }
    }
}

impl<L: LaneReal> fmt::Display for LaneDual<L> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{} + {}ε", self.re, self.eps)
    }
}

/// `Op<Self>` and `Op<&Self>` through the `Ring`/`Field` reference method.
macro_rules! dual_binop {
    ($tr:ident, $f:ident, $by_ref:ident) => {
        impl<L: LaneReal> $tr for LaneDual<L> {
            type Output = Self;
            fn $f(self, rhs: Self) -> Self {
                self.$by_ref(&rhs)
            }
        }
        impl<'a, L: LaneReal> $tr<&'a LaneDual<L>> for LaneDual<L> {
            type Output = Self;
            fn $f(self, rhs: &'a Self) -> Self {
                self.$by_ref(rhs)
            }
        }
    };
}
dual_binop!(Add, add, add_ref);
dual_binop!(Sub, sub, sub_ref);
dual_binop!(Mul, mul, mul_ref);
dual_binop!(Div, div, div_ref);

impl<L: LaneReal> Neg for LaneDual<L> {
    type Output = Self;
    fn neg(self) -> Self {
        self.neg_ref()
    }
}

impl<L: LaneReal> Ring for LaneDual<L> {
    fn zero() -> Self {
        Self::constant(L::zero())
    }
    fn one() -> Self {
        Self::constant(L::one())
    }
    fn from_i64(n: i64) -> Self {
        Self::constant(L::from_i64(n))
    }
    fn from_ratio(num: i64, den: i64) -> Self {
        Self::constant(L::from_ratio(num, den))
    }
    fn from_rational(q: &Q) -> Self {
        Self::constant(L::from_rational(q))
    }
    /// Both parts are zero (in every lane).
    fn is_exact_zero(&self) -> bool {
        self.re.is_exact_zero() && self.eps.is_exact_zero()
    }
    /// The larger of the two parts' magnitudes.
    fn magnitude(&self) -> f64 {
        let (a, b) = (self.re.magnitude(), self.eps.magnitude());
        if a.is_nan() || b.is_nan() { f64::NAN } else { a.max(b) }
    }
    fn relative_epsilon() -> f64 {
        L::relative_epsilon()
    }
    fn is_finite_value(&self) -> bool {
        self.re.is_finite_value() && self.eps.is_finite_value()
    }
    fn add_ref(&self, rhs: &Self) -> Self {
        LaneDual { re: self.re.add_ref(&rhs.re), eps: self.eps.add_ref(&rhs.eps) }
    }
    fn sub_ref(&self, rhs: &Self) -> Self {
        LaneDual { re: self.re.sub_ref(&rhs.re), eps: self.eps.sub_ref(&rhs.eps) }
    }
    fn mul_ref(&self, rhs: &Self) -> Self {
        let eps = self.re.mul_ref(&rhs.eps).add_ref(&self.eps.mul_ref(&rhs.re));
        LaneDual { re: self.re.mul_ref(&rhs.re), eps }
    }
    fn neg_ref(&self) -> Self {
        LaneDual { re: self.re.neg_ref(), eps: self.eps.neg_ref() }
    }
}

impl<L: LaneReal> Field for LaneDual<L> {
    /// `None` when the real part has no reciprocal (in some lane).
    fn try_recip(&self) -> Option<Self> {
        let r = self.re.try_recip()?;
        let eps = self.eps.mul_ref(&r).mul_ref(&r).neg_ref();
        Some(LaneDual { re: r, eps })
    }
    fn div_ref(&self, rhs: &Self) -> Self {
        let re = self.re.div_ref(&rhs.re);
        let eps = self.eps.sub_ref(&re.mul_ref(&rhs.eps)).div_ref(&rhs.re);
        LaneDual { re, eps }
    }
}

impl<L: LaneReal> Elementary for LaneDual<L> {
    fn sqrt(&self) -> Self {
        let r = self.re.sqrt();
        let slope = L::one().div_ref(&r.add_ref(&r));
        self.chain(r, slope)
    }
    fn exp(&self) -> Self {
        let e = self.re.exp();
        self.chain(e.clone(), e)
    }
    fn ln(&self) -> Self {
        self.chain(self.re.ln(), L::one().div_ref(&self.re))
    }
    fn sin(&self) -> Self {
        self.chain(self.re.sin(), self.re.cos())
    }
    fn cos(&self) -> Self {
        self.chain(self.re.cos(), self.re.sin().neg_ref())
    }
    /// `d atan2(y, x) = (x dy - y dx) / (x² + y²)`.
    fn atan2(&self, x: &Self) -> Self {
        let (y, x) = (self, x);
        let r2 = x.re.mul_ref(&x.re).add_ref(&y.re.mul_ref(&y.re));
        let eps = x.re.mul_ref(&y.eps).sub_ref(&y.re.mul_ref(&x.eps)).div_ref(&r2);
        LaneDual { re: y.re.atan2(&x.re), eps }
    }
    /// The sign of the real part decides the derivative's (at 0: +1, the right derivative).
    fn abs(&self) -> Self {
        let neg = self.re.lt_mask(&L::zero());
        LaneDual { re: self.re.abs(), eps: L::select(&neg, &self.eps.neg_ref(), &self.eps) }
    }
    fn from_f64(x: f64) -> Self {
        Self::constant(L::from_f64(x))
    }
    fn pi() -> Self {
        Self::constant(L::pi())
    }
}

impl<L: LaneReal> Select for LaneDual<L> {
    type Mask = L::Mask;
    fn select(mask: &L::Mask, if_true: &Self, if_false: &Self) -> Self {
        LaneDual { re: L::select(mask, &if_true.re, &if_false.re), eps: L::select(mask, &if_true.eps, &if_false.eps) }
    }
    fn lt_mask(&self, other: &Self) -> L::Mask {
        self.re.lt_mask(&other.re)
    }
    fn le_mask(&self, other: &Self) -> L::Mask {
        self.re.le_mask(&other.re)
    }
    fn eq_mask(&self, other: &Self) -> L::Mask {
        self.re.eq_mask(&other.re)
    }
    fn finite_mask(&self) -> L::Mask {
        self.re.finite_mask() & self.eps.finite_mask()
    }
}

impl<L: LaneReal> Diagnostics for LaneDual<L> {
    const LANES: usize = L::LANES;
    /// The real part's lane.
    fn lane_to_f64(&self, lane: usize) -> Option<f64> {
        self.re.lane_to_f64(lane)
    }
}
