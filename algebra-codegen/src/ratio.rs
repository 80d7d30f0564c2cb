//! Exact kernel constants as pairs of machine integers: every term list of the plan carries its
//! coefficient as a [`Ratio`] (`T::from_ratio(n, d)` in Rust, a literal in the other languages).

use crate::CodegenError;
use algebra_core::rational::Q;
use num_traits::ToPrimitive;

/// An exact constant of a kernel as `(numerator, denominator)`, for `T::from_ratio`.
pub type Ratio = (i64, i64);

/// Whether `c` is `±1`: a term with it needs no multiplication by the constant (the one test of
/// the emitters' constant placement and of every operation count).
pub(crate) fn is_unit(c: Ratio) -> bool {
    c.0.abs() == 1 && c.1 == 1
}

/// `c` as a [`Ratio`]; `CoefficientTooLarge` beyond 64 bits.
pub(crate) fn to_ratio(c: &Q) -> Result<Ratio, CodegenError> {
    match (c.numer().to_i64(), c.denom().to_i64()) {
        (Some(n), Some(d)) => Ok((n, d)),
        _ => Err(CodegenError::CoefficientTooLarge(algebra_core::rational::format_rational(c))),
    }
}
