//! [`Ring`] and [`Field`] for num-rational's `BigRational` ([`Q`]): exact scalars that build
//! without GMP.

use super::{Field, Ring};
use crate::rational::{Q, ratio, rational_to_f64};
use num_bigint::BigInt;
use num_traits::{One, Zero};

impl Ring for Q {
    fn zero() -> Self {
        Zero::zero()
    }
    fn one() -> Self {
        One::one()
    }
    fn from_i64(n: i64) -> Self {
        Q::from_integer(BigInt::from(n))
    }
    fn from_ratio(num: i64, den: i64) -> Self {
        ratio(num, den)
    }
    fn from_rational(q: &Q) -> Self {
        q.clone()
    }
    fn is_exact_zero(&self) -> bool {
        Zero::is_zero(self)
    }
    fn magnitude(&self) -> f64 {
        rational_to_f64(self).abs()
    }
    fn relative_epsilon() -> f64 {
        0.0
    }
    fn cmp_magnitude(&self, other: &Self) -> std::cmp::Ordering {
        num_traits::Signed::abs(self).cmp(&num_traits::Signed::abs(other))
    }
    native_ref_ops!();
    fn add_assign_ref(&mut self, rhs: &Self) {
        *self += rhs;
    }
    fn sub_assign_ref(&mut self, rhs: &Self) {
        *self -= rhs;
    }
    fn scale_rational(&self, q: &Q) -> Self {
        self * q
    }
}

impl Field for Q {
    fn try_recip(&self) -> Option<Self> {
        (!Zero::is_zero(self)).then(|| self.recip())
    }
    fn div_ref(&self, rhs: &Self) -> Self {
        self / rhs
    }
}
