//! Exact kernel constants as pairs of machine integers: every term list of the plan carries its
//! coefficient as a [`Ratio`] (`T::from_ratio(n, d)` in Rust, a literal in the other languages).

use crate::CodegenError;
use algebra_core::rational::Q;
use num_traits::ToPrimitive;

/// An exact constant of a kernel as `(numerator, denominator)`, for `T::from_ratio`.
pub type Ratio = (i64, i64);

/// `c` as a [`Ratio`]; `CoefficientTooLarge` beyond 64 bits.
pub(crate) fn to_ratio(c: &Q) -> Result<Ratio, CodegenError> {
    match (c.numer().to_i64(), c.denom().to_i64()) {
        (Some(n), Some(d)) => Ok((n, d)),
        _ => Err(CodegenError::CoefficientTooLarge(algebra_core::rational::format_rational(c))),
    }
}
