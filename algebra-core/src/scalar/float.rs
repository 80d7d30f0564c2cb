//! [`Ring`], [`Field`] and [`Real`] for `f32` and `f64`.

use super::{Field, Real, Ring};
use crate::rational::{Q, rational_to_f64};

macro_rules! impl_float {
    ($t:ty) => {
        impl Ring for $t {
            fn zero() -> Self {
                0.0
            }
            fn one() -> Self {
                1.0
            }
            fn from_i64(n: i64) -> Self {
                n as $t
            }
            fn from_ratio(num: i64, den: i64) -> Self {
                (num as f64 / den as f64) as $t
            }
            fn from_rational(q: &Q) -> Self {
                rational_to_f64(q) as $t
            }
            fn is_exact_zero(&self) -> bool {
                *self == 0.0
            }
            fn magnitude(&self) -> f64 {
                f64::from(self.abs())
            }
            fn relative_epsilon() -> f64 {
                f64::from(<$t>::EPSILON)
            }
            fn is_finite_value(&self) -> bool {
                <$t>::is_finite(*self)
            }
            native_ref_ops!();
            fn add_assign_ref(&mut self, rhs: &Self) {
                *self += rhs;
            }
            fn sub_assign_ref(&mut self, rhs: &Self) {
                *self -= rhs;
            }
        }

        impl Field for $t {
            fn try_recip(&self) -> Option<Self> {
                let r = 1.0 / self;
                (*self != 0.0 && r.is_finite()).then_some(r)
            }
            fn div_ref(&self, rhs: &Self) -> Self {
                self / rhs
            }
        }

        impl Real for $t {
            fn sqrt(&self) -> Self {
                <$t>::sqrt(*self)
            }
            fn exp(&self) -> Self {
                <$t>::exp(*self)
            }
            fn ln(&self) -> Self {
                <$t>::ln(*self)
            }
            fn sin(&self) -> Self {
                <$t>::sin(*self)
            }
            fn cos(&self) -> Self {
                <$t>::cos(*self)
            }
            fn sinh(&self) -> Self {
                <$t>::sinh(*self)
            }
            fn cosh(&self) -> Self {
                <$t>::cosh(*self)
            }
            fn atan2(&self, x: &Self) -> Self {
                <$t>::atan2(*self, *x)
            }
            #[inline]
            fn fast_atan2(&self, x: &Self) -> Self {
                super::atan2_f64(f64::from(*self), f64::from(*x)) as $t
            }
            fn atanh(&self) -> Self {
                <$t>::atanh(*self)
            }
            fn abs(&self) -> Self {
                <$t>::abs(*self)
            }
            fn to_f64(&self) -> f64 {
                f64::from(*self)
            }
            fn from_f64(x: f64) -> Self {
                x as $t
            }
            fn pi() -> Self {
                std::f64::consts::PI as $t
            }
            fn is_finite(&self) -> bool {
                <$t>::is_finite(*self)
            }
        }
    };
}

impl_float!(f32);
impl_float!(f64);
