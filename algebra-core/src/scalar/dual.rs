//! [`Ring`], [`Field`] and [`Real`] for num-dual's `Dual64`, `Dual2_64` and `HyperDual64`.
//!
//! num-dual's `==` and `<` look only at the real part; [`Ring::is_exact_zero`] and
//! [`Ring::magnitude`] look at every component, so nothing that GAM decides from them can drop
//! a derivative.

use super::{Field, Real, Ring};
use crate::rational::{Q, rational_to_f64};
use num_dual::{Dual2_64, Dual64, DualNum, HyperDual64};

macro_rules! impl_dual {
    ($t:ty, [$($part:ident),*]) => {
        impl Ring for $t {
            fn zero() -> Self {
                <$t>::from(0.0)
            }
            fn one() -> Self {
                <$t>::from(1.0)
            }
            fn from_i64(n: i64) -> Self {
                <$t>::from(n as f64)
            }
            fn from_ratio(num: i64, den: i64) -> Self {
                <$t>::from(num as f64 / den as f64)
            }
            fn from_rational(q: &Q) -> Self {
                <$t>::from(rational_to_f64(q))
            }
            fn is_exact_zero(&self) -> bool {
                true $(&& self.$part == 0.0)*
            }
            fn magnitude(&self) -> f64 {
                [$(self.$part.abs()),*].into_iter().fold(0.0, f64::max)
            }
            fn relative_epsilon() -> f64 {
                f64::EPSILON
            }
            fn is_finite_value(&self) -> bool {
                true $(&& self.$part.is_finite())*
            }
            native_ref_ops!();
        }

        impl Field for $t {
            fn try_recip(&self) -> Option<Self> {
                if self.re == 0.0 {
                    return None;
                }
                let r = DualNum::recip(self);
                Real::is_finite(&r).then_some(r)
            }
            fn div_ref(&self, rhs: &Self) -> Self {
                self / rhs
            }
        }

        impl Real for $t {
            fn sqrt(&self) -> Self {
                DualNum::sqrt(self)
            }
            fn exp(&self) -> Self {
                DualNum::exp(self)
            }
            fn ln(&self) -> Self {
                DualNum::ln(self)
            }
            fn sin(&self) -> Self {
                DualNum::sin(self)
            }
            fn cos(&self) -> Self {
                DualNum::cos(self)
            }
            fn sinh(&self) -> Self {
                DualNum::sinh(self)
            }
            fn cosh(&self) -> Self {
                DualNum::cosh(self)
            }
            fn atan2(&self, x: &Self) -> Self {
                DualNum::atan2(self, *x)
            }
            fn atanh(&self) -> Self {
                DualNum::atanh(self)
            }
            fn abs(&self) -> Self {
                if self.re < 0.0 { -*self } else { *self }
            }
            fn to_f64(&self) -> f64 {
                self.re
            }
            fn from_f64(x: f64) -> Self {
                <$t>::from(x)
            }
            fn pi() -> Self {
                <$t>::from(std::f64::consts::PI)
            }
            fn is_finite(&self) -> bool {
                true $(&& self.$part.is_finite())*
            }
        }
    };
}

impl_dual!(Dual64, [re, eps]);
impl_dual!(Dual2_64, [re, v1, v2]);
impl_dual!(HyperDual64, [re, eps1, eps2, eps1eps2]);

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn zero_test_sees_derivative_parts() {
        let x = Dual64::new(0.0, 1.0);
        assert!(x == 0.0, "num-dual compares real parts only");
        assert!(!x.is_exact_zero(), "GAM must not");
        assert_eq!(x.magnitude(), 1.0);
    }

    #[test]
    fn derivative_of_sin_via_trait() {
        let x = Dual64::new(0.3, 1.0);
        let y = Real::sin(&x).mul_ref(&Real::exp(&x));
        let expected = 0.3f64.cos() * 0.3f64.exp() + 0.3f64.sin() * 0.3f64.exp();
        assert!((y.eps - expected).abs() < 1e-15);
    }
}
