//! Exact power-of-two rescaling for the f64 exp, log and sqrt: the branch decisions (is
//! `B²` a scalar, is it zero, negative or positive, is it far enough from zero for the closed
//! form) are made on quantities of unit scale, never on a square that underflowed to zero or
//! overflowed to infinity (`1e-200 + 1e-200 e12`: `B² = -1e-400` is `-0.0` in f64).
//!
//! Only fixed-precision scalars far from unit scale take the careful path: one pass over the
//! coefficients' magnitudes decides it, so ordinary input runs exactly the arithmetic it ran
//! before (a power-of-two scaling inside the exponent range is exact and commutes with
//! rounding, so the results are bit-identical where both apply).

use super::Multivector;
use crate::scalar::{Real, Ring};
use std::cmp::Ordering;

/// Binary exponents within `±TAME_LOG2` are used as they are: their squares and products of
/// two stay far inside f64's normal range (`2^±1022`).
const TAME_LOG2: i32 = 250;

/// `2^e` (exact for `|e| <= 1000`; larger ones are split by [`scale_pow2`]).
fn pow2<T: Real>(e: i32) -> T {
    T::from_f64(2f64.powi(e))
}

/// `x · 2^e`, exactly, for `|e|` up to about 2000 (two factors within f64's range).
pub(super) fn scale_pow2<T: Real>(x: &T, e: i32) -> T {
    let h = e / 2;
    x.mul_ref(&pow2(h)).mul_ref(&pow2(e - h))
}

/// The binary exponent of a positive finite `m` (`m ∈ [2^e, 2^(e+1))`).
fn exponent(m: f64) -> i32 {
    m.log2().floor() as i32
}

/// The square `B² = β` of a bivector-like part when it is a scalar, its sign decided at
/// unit scale.
pub(super) struct Square<T> {
    /// The sign of `β` (decided on `B/2^j`; `Equal`: `B` is nilpotent).
    pub sign: Ordering,
    /// `β` itself (may have underflowed to zero or overflowed to infinity).
    pub beta: T,
    /// `√|β|` computed as `√|β/4^j| · 2^j`: neither under- nor overflows.
    pub root: T,
}

impl<T: Real> Multivector<T> {
    /// The binary exponent of the largest coefficient when `self` is of fixed precision and far
    /// from unit scale (outside `2^±TAME_LOG2`); `None` otherwise (ordinary input, zero,
    /// non-finite or multiple precision, whose exponent range needs no rescaling).
    pub(super) fn unusual_exponent(&self) -> Option<i32> {
        let m = self.coeffs.iter().map(Ring::magnitude).fold(0.0, f64::max);
        if !(m > 0.0 && m.is_finite()) || (m >= 2f64.powi(-TAME_LOG2) && m < 2f64.powi(TAME_LOG2)) {
            return None;
        }
        self.fixed_precision().then(|| exponent(m))
    }

    /// `self · 2^e`, exactly.
    pub(super) fn scale_pow2(&self, e: i32) -> Self {
        self.map_coeffs(|c| scale_pow2(c, e))
    }

    /// Splits `self = a + B` (a = identity coefficient) and returns `(a, B, square)` with
    /// `square` present when `B²` is a scalar (every other coefficient exactly zero) and the
    /// closed forms apply: `B²` exactly zero, or `|B²|` above `√ε` times the square of `B`'s
    /// largest coefficient (a relatively tiny `β` would lose accuracy, and for dual numbers
    /// give an infinite derivative, in `√β`). Both tests are made on `B/2^j` with `2^j` the
    /// scale of `B` when that is far from 1, so no square under- or overflows.
    pub(super) fn scalar_square_split(&self) -> (T, Self, Option<Square<T>>) {
        let a = self.coeffs[0].clone();
        let mut b = self.clone();
        b.coeffs[0] = T::zero();
        let j = b.unusual_exponent();
        let bs = match j {
            Some(j) => b.scale_pow2(-j),
            None => b.clone(),
        };
        let b2 = &bs * &bs;
        if !b2.coeffs.iter().skip(1).all(Ring::is_exact_zero) {
            return (a, b, None);
        }
        let beta_s = b2.coeffs[0].clone();
        let zero = T::zero();
        let sign = if beta_s.is_exact_zero() {
            Ordering::Equal
        } else {
            let mb = Real::abs(&bs.largest_coeff());
            if Real::abs(&beta_s) <= Real::sqrt(&T::epsilon()).mul_ref(&mb).mul_ref(&mb) {
                return (a, b, None);
            }
            if beta_s < zero { Ordering::Less } else { Ordering::Greater }
        };
        let root_s = Real::sqrt(&Real::abs(&beta_s));
        let square = match j {
            None => Square { sign, beta: beta_s, root: root_s },
            Some(j) => Square { sign, beta: scale_pow2(&beta_s, 2 * j), root: scale_pow2(&root_s, j) },
        };
        (a, b, Some(square))
    }
}
