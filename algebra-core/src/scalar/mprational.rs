//! [`MpRational`]: GMP rationals (rug) as an exact [`Field`].

use super::{Field, Ring};
use crate::rational::Q;
use std::fmt;
use std::ops::{Add, Div, Mul, Neg, Sub};

/// An exact GMP rational (a newtype over `rug::Rational`, so that `&a * &b` yields a value).
///
/// ```
/// use algebra_core::{MpRational, Ring, Field};
/// let third = MpRational::from_ratio(1, 3);
/// assert_eq!(third.mul_ref(&MpRational::from_i64(3)), MpRational::one());
/// assert!(MpRational::zero().try_recip().is_none());
/// ```
#[derive(Clone, Debug, PartialEq, PartialOrd, Default)]
pub struct MpRational(pub rug::Rational);

/// Converts a num-rational value to a rug rational exactly.
pub(crate) fn rug_rational(q: &Q) -> rug::Rational {
    let n: rug::Integer = q.numer().to_string().parse().expect("BigInt prints as an integer");
    let d: rug::Integer = q.denom().to_string().parse().expect("BigInt prints as an integer");
    rug::Rational::from((n, d))
}

impl MpRational {
    /// The exact value of a num-rational `Q`.
    ///
    /// ```
    /// use algebra_core::{MpRational, rational::ratio};
    /// assert_eq!(MpRational::from_q(&ratio(2, 4)).to_string(), "1/2");
    /// ```
    pub fn from_q(q: &Q) -> Self {
        MpRational(rug_rational(q))
    }
    /// The value as a num-rational `Q` (exact).
    ///
    /// ```
    /// use algebra_core::{MpRational, Ring, rational::ratio};
    /// assert_eq!(MpRational::from_ratio(-3, 9).to_q(), ratio(-1, 3));
    /// ```
    pub fn to_q(&self) -> Q {
        let n: num_bigint::BigInt = self.0.numer().to_string().parse().expect("integer");
        let d: num_bigint::BigInt = self.0.denom().to_string().parse().expect("integer");
        Q::new(n, d)
    }
}

impl fmt::Display for MpRational {
    /// `p` or `p/q` in lowest terms.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if *self.0.denom() == 1 {
            write!(f, "{}", self.0.numer())
        } else {
            write!(f, "{}/{}", self.0.numer(), self.0.denom())
        }
    }
}

macro_rules! binop {
    ($tr:ident, $m:ident) => {
        impl $tr for MpRational {
            type Output = Self;
            fn $m(self, rhs: Self) -> Self {
                MpRational(self.0.$m(rhs.0))
            }
        }
        impl<'a> $tr<&'a MpRational> for MpRational {
            type Output = Self;
            fn $m(self, rhs: &'a Self) -> Self {
                MpRational(self.0.$m(&rhs.0))
            }
        }
    };
}
binop!(Add, add);
binop!(Sub, sub);
binop!(Mul, mul);
binop!(Div, div);

impl Neg for MpRational {
    type Output = Self;
    fn neg(self) -> Self {
        MpRational(-self.0)
    }
}

impl Ring for MpRational {
    fn zero() -> Self {
        MpRational(rug::Rational::new())
    }
    fn one() -> Self {
        MpRational(rug::Rational::from(1))
    }
    fn from_i64(n: i64) -> Self {
        MpRational(rug::Rational::from(n))
    }
    fn from_ratio(num: i64, den: i64) -> Self {
        MpRational(rug::Rational::from((num, den)))
    }
    fn from_rational(q: &Q) -> Self {
        MpRational::from_q(q)
    }
    fn is_exact_zero(&self) -> bool {
        self.0 == 0
    }
    fn magnitude(&self) -> f64 {
        self.0.to_f64().abs()
    }
    fn relative_epsilon() -> f64 {
        0.0
    }
    fn cmp_magnitude(&self, other: &Self) -> std::cmp::Ordering {
        self.0.cmp_abs(&other.0)
    }
    fn add_ref(&self, rhs: &Self) -> Self {
        MpRational(rug::Rational::from(&self.0 + &rhs.0))
    }
    fn sub_ref(&self, rhs: &Self) -> Self {
        MpRational(rug::Rational::from(&self.0 - &rhs.0))
    }
    fn mul_ref(&self, rhs: &Self) -> Self {
        MpRational(rug::Rational::from(&self.0 * &rhs.0))
    }
    fn neg_ref(&self) -> Self {
        MpRational(rug::Rational::from(-&self.0))
    }
    fn add_assign_ref(&mut self, rhs: &Self) {
        self.0 += &rhs.0;
    }
    fn sub_assign_ref(&mut self, rhs: &Self) {
        self.0 -= &rhs.0;
    }
}

impl Field for MpRational {
    fn try_recip(&self) -> Option<Self> {
        (self.0 != 0).then(|| MpRational(rug::Rational::from(self.0.recip_ref())))
    }
    fn div_ref(&self, rhs: &Self) -> Self {
        MpRational(rug::Rational::from(&self.0 / &rhs.0))
    }
}
