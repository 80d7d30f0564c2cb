//! [`Jet`]: a first-order dual number over any [`Real`], so derivatives work over rug floats
//! too (num-dual needs a `Copy` float). Nest it (`Jet<Jet<T>>`) for second derivatives.

use super::{Field, Real, Ring};
use crate::rational::Q;
use std::cmp::Ordering;
use std::fmt;
use std::ops::{Add, Div, Mul, Neg, Sub};

/// `re + eps·ε` with `ε² = 0`: evaluating `f(Jet::variable(x))` gives `f(x)` and `f'(x)`.
///
/// Equality compares both parts (unlike num-dual); ordering compares real parts.
///
/// ```
/// use algebra_core::{Jet, Real};
/// let x = Jet::variable(2.0f64);
/// let y = x.clone() * x.clone() * x; // x^3
/// assert_eq!(y.re, 8.0);
/// assert_eq!(y.eps, 12.0);
/// let s = Real::sin(&Jet::variable(0.0f64));
/// assert_eq!(s.eps, 1.0);
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct Jet<T> {
    /// The value.
    pub re: T,
    /// The derivative part (coefficient of ε).
    pub eps: T,
}

impl<T: Ring> Jet<T> {
    /// `re + eps·ε`.
    ///
    /// ```
    /// let j = algebra_core::Jet::new(1.0, 2.0);
    /// assert_eq!(j.eps, 2.0);
    /// ```
    pub fn new(re: T, eps: T) -> Self {
        Jet { re, eps }
    }
    /// A constant: derivative part zero.
    ///
    /// ```
    /// assert_eq!(algebra_core::Jet::constant(3.0).eps, 0.0);
    /// ```
    pub fn constant(re: T) -> Self {
        Jet { re, eps: T::zero() }
    }
    /// The independent variable: derivative part one.
    ///
    /// ```
    /// assert_eq!(algebra_core::Jet::variable(3.0).eps, 1.0);
    /// ```
    pub fn variable(re: T) -> Self {
        Jet { re, eps: T::one() }
    }
    /// `f(re) + f'(re)·eps·ε` for a scalar function with value `f` and derivative `df`.
    fn chain(&self, f: T, df: T) -> Self {
        Jet { re: f, eps: df.mul_ref(&self.eps) }
    }
}

impl<T: fmt::Display> fmt::Display for Jet<T> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{} + {}ε", self.re, self.eps)
    }
}

impl<T: Ring> Add for Jet<T> {
    type Output = Self;
    fn add(self, rhs: Self) -> Self {
        Jet { re: self.re + rhs.re, eps: self.eps + rhs.eps }
    }
}
impl<'a, T: Ring> Add<&'a Jet<T>> for Jet<T> {
    type Output = Self;
    fn add(self, rhs: &'a Self) -> Self {
        Jet { re: self.re + &rhs.re, eps: self.eps + &rhs.eps }
    }
}
impl<T: Ring> Sub for Jet<T> {
    type Output = Self;
    fn sub(self, rhs: Self) -> Self {
        Jet { re: self.re - rhs.re, eps: self.eps - rhs.eps }
    }
}
impl<'a, T: Ring> Sub<&'a Jet<T>> for Jet<T> {
    type Output = Self;
    fn sub(self, rhs: &'a Self) -> Self {
        Jet { re: self.re - &rhs.re, eps: self.eps - &rhs.eps }
    }
}
impl<T: Ring> Mul for Jet<T> {
    type Output = Self;
    fn mul(self, rhs: Self) -> Self {
        self * &rhs
    }
}
impl<'a, T: Ring> Mul<&'a Jet<T>> for Jet<T> {
    type Output = Self;
    fn mul(self, rhs: &'a Self) -> Self {
        let eps = self.re.mul_ref(&rhs.eps) + &self.eps.mul_ref(&rhs.re);
        Jet { re: self.re * &rhs.re, eps }
    }
}
impl<T: Ring> Neg for Jet<T> {
    type Output = Self;
    fn neg(self) -> Self {
        Jet { re: -self.re, eps: -self.eps }
    }
}
impl<T: Field> Div for Jet<T> {
    type Output = Self;
    fn div(self, rhs: Self) -> Self {
        self / &rhs
    }
}
impl<'a, T: Field> Div<&'a Jet<T>> for Jet<T> {
    type Output = Self;
    #[allow(clippy::suspicious_arithmetic_impl)] // the quotient rule subtracts
    fn div(self, rhs: &'a Self) -> Self {
        // (a + a'ε)/(b + b'ε) = a/b + (a'b - ab')/b² ε
        let re = self.re.div_ref(&rhs.re);
        let eps = (self.eps - &re.mul_ref(&rhs.eps)).div_ref(&rhs.re);
        Jet { re, eps }
    }
}
impl<T: Real> PartialOrd for Jet<T> {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        self.re.partial_cmp(&other.re)
    }
}

impl<T: Ring> Ring for Jet<T> {
    fn zero() -> Self {
        Jet::constant(T::zero())
    }
    fn one() -> Self {
        Jet::constant(T::one())
    }
    fn from_i64(n: i64) -> Self {
        Jet::constant(T::from_i64(n))
    }
    fn from_ratio(num: i64, den: i64) -> Self {
        Jet::constant(T::from_ratio(num, den))
    }
    fn from_rational(q: &Q) -> Self {
        Jet::constant(T::from_rational(q))
    }
    fn is_exact_zero(&self) -> bool {
        self.re.is_exact_zero() && self.eps.is_exact_zero()
    }
    fn magnitude(&self) -> f64 {
        self.re.magnitude().max(self.eps.magnitude())
    }
    fn relative_epsilon() -> f64 {
        T::relative_epsilon()
    }
    fn is_finite_value(&self) -> bool {
        self.re.is_finite_value() && self.eps.is_finite_value()
    }
    fn mul_ref(&self, rhs: &Self) -> Self {
        let eps = self.re.mul_ref(&rhs.eps) + &self.eps.mul_ref(&rhs.re);
        Jet { re: self.re.mul_ref(&rhs.re), eps }
    }
    fn add_ref(&self, rhs: &Self) -> Self {
        Jet { re: self.re.add_ref(&rhs.re), eps: self.eps.add_ref(&rhs.eps) }
    }
    fn sub_ref(&self, rhs: &Self) -> Self {
        Jet { re: self.re.sub_ref(&rhs.re), eps: self.eps.sub_ref(&rhs.eps) }
    }
    fn neg_ref(&self) -> Self {
        Jet { re: self.re.neg_ref(), eps: self.eps.neg_ref() }
    }
}

impl<T: Field> Field for Jet<T> {
    fn try_recip(&self) -> Option<Self> {
        let r = self.re.try_recip()?;
        let eps = r.mul_ref(&r).mul_ref(&self.eps).neg_ref();
        Some(Jet { re: r, eps })
    }
}

impl<T: Real> Jet<T> {
    /// The derivative part of `atan2(self, x)`: `(x dy - y dx) / (x² + y²)`.
    fn atan2_eps(&self, x: &Self) -> T {
        let r2 = x.re.mul_ref(&x.re) + &self.re.mul_ref(&self.re);
        (x.re.mul_ref(&self.eps) - &self.re.mul_ref(&x.eps)).div_ref(&r2)
    }
}

impl<T: Real> Real for Jet<T> {
    fn sqrt(&self) -> Self {
        let s = self.re.sqrt();
        let ds = T::from_ratio(1, 2).div_ref(&s);
        self.chain(s, ds)
    }
    fn exp(&self) -> Self {
        let e = self.re.exp();
        self.chain(e.clone(), e)
    }
    fn ln(&self) -> Self {
        self.chain(self.re.ln(), T::one().div_ref(&self.re))
    }
    fn sin(&self) -> Self {
        self.chain(self.re.sin(), self.re.cos())
    }
    fn cos(&self) -> Self {
        self.chain(self.re.cos(), self.re.sin().neg_ref())
    }
    fn sinh(&self) -> Self {
        self.chain(self.re.sinh(), self.re.cosh())
    }
    fn cosh(&self) -> Self {
        self.chain(self.re.cosh(), self.re.sinh())
    }
    fn atan2(&self, x: &Self) -> Self {
        Jet { re: self.re.atan2(&x.re), eps: self.atan2_eps(x) }
    }
    fn fast_atan2(&self, x: &Self) -> Self {
        Jet { re: self.re.fast_atan2(&x.re), eps: self.atan2_eps(x) }
    }
    fn atanh(&self) -> Self {
        let d = T::one().div_ref(&(T::one() - &self.re.mul_ref(&self.re)));
        self.chain(self.re.atanh(), d)
    }
    fn abs(&self) -> Self {
        if self.re < T::zero() { self.neg_ref() } else { self.clone() }
    }
    fn to_f64(&self) -> f64 {
        self.re.to_f64()
    }
    fn from_f64(x: f64) -> Self {
        Jet::constant(T::from_f64(x))
    }
    fn pi() -> Self {
        Jet::constant(T::pi())
    }
    fn is_finite(&self) -> bool {
        self.re.is_finite() && self.eps.is_finite()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: f64, b: f64) -> bool {
        (a - b).abs() <= 1e-14 * (1.0 + b.abs())
    }

    #[test]
    fn derivatives_match_num_dual() {
        use num_dual::{Dual64, DualNum};
        let x0 = 0.7;
        let j = Jet::variable(x0);
        let d = Dual64::new(x0, 1.0);
        let f_j = Real::atan2(&Real::sinh(&j), &Real::cosh(&j).mul_ref(&Real::sqrt(&j)))
            .add_ref(&Real::ln(&j).div_ref(&Real::exp(&j)))
            .add_ref(&Real::atanh(&(j.clone() * Jet::constant(0.5))));
        let f_d = DualNum::atan2(&DualNum::sinh(&d), DualNum::cosh(&d) * DualNum::sqrt(&d))
            + DualNum::ln(&d) / DualNum::exp(&d)
            + DualNum::atanh(&(d * 0.5));
        assert!(close(f_j.re, f_d.re));
        assert!(close(f_j.eps, f_d.eps));
    }

    #[test]
    fn nested_jet_gives_second_derivative() {
        // f(x) = x^3 at 2: f'' = 12.
        let x = Jet::new(Jet::variable(2.0), Jet::constant(1.0));
        let y = x.clone() * x.clone() * x;
        assert_eq!(y.eps.eps, 12.0);
    }
}
