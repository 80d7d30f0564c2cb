//! exp of a bivector by its invariant decomposition into commuting simple parts (Roelfs and
//! De Keninck, "Graded symmetry groups: plane and simple", 2021): in up to five generators a
//! bivector is `B = B₁ + B₂` with `B₁B₂ = B₂B₁` and each `Bᵢ² = λᵢ` a scalar, so
//! `exp B = exp B₁ exp B₂` with each factor in closed form. Used for fixed-precision scalars
//! where the general method is refused (large non-simple bivectors).
//!
//! With `B² = s + W` (`s = λ₁ + λ₂` the scalar part, `W = B∧B = 2B₁B₂` the 4-vector part),
//! `λ₁, λ₂` are the roots of `λ² - sλ + W²/4 = 0`, and `WB/2 = λ₂B₁ + λ₁B₂` gives
//! `B₁ = (WB/2 - λ₁B)/(λ₂ - λ₁)`, `B₂ = B - B₁`. The split is refused (`None`) when the roots
//! are complex or too close, or the angles too large: the relative error of `Bᵢ` is about
//! `ε (|λ₁| + |λ₂|)/|λ₁ - λ₂|`, and the angles `θᵢ = √|λᵢ|` are known to `θᵢ` times that, so
//! `(1 + θ₁ + θ₂) ε (|λ₁| + |λ₂|)/|λ₁ - λ₂|` must stay within [`super::F64_GENERAL_BOUND`]
//! (for well-separated blocks: angles up to about `10⁷` instead of the general method's `10⁵`).

use super::Multivector;
use super::exp_log::F64_GENERAL_BOUND;
use crate::scalar::Real;
use std::cmp::Ordering::{Equal, Greater, Less};

impl<T: Real> Multivector<T> {
    /// The commuting simple parts `(B₁, λ₁), (B₂, λ₂)` of a pure bivector in at most five
    /// generators, or `None` (not a bivector, more generators, complex or ill-separated roots).
    pub(super) fn commuting_blocks(&self) -> Option<[(Self, T); 2]> {
        if self.algebra.generators() > 5 || self.grade(2).coeffs != self.coeffs {
            return None;
        }
        let sq = self * self;
        let s = sq.grade(0).coeffs[0].clone();
        let w = sq.grade(4);
        let w2 = &w * &w;
        let p = w2.coeffs[0].mul_ref(&T::from_ratio(1, 4));
        let disc = s.mul_ref(&s).sub_ref(&p.mul_ref(&T::from_i64(4)));
        // NaN (an overflowing square) compares as neither: refused too
        if disc.partial_cmp(&T::zero()) != Some(Greater) {
            return None;
        }
        let root = Real::sqrt(&disc);
        // λ₁ the root of larger magnitude (no cancellation), λ₂ = p/λ₁
        let l1 = if s < T::zero() { s.sub_ref(&root) } else { s.add_ref(&root) }.mul_ref(&T::from_ratio(1, 2));
        let l2 = p.div_ref(&l1);
        let gap = Real::abs(&l1.sub_ref(&l2));
        let size = Real::abs(&l1).add_ref(&Real::abs(&l2));
        // the angles θᵢ = √|λᵢ| are known to about θᵢ ε · (|λ₁| + |λ₂|)/|λ₁ - λ₂| radians
        let angles = Real::sqrt(&Real::abs(&l1)).to_f64() + Real::sqrt(&Real::abs(&l2)).to_f64();
        let condition = size.to_f64() / gap.to_f64();
        let error = (1.0 + angles) * condition * T::epsilon().to_f64();
        // NaN anywhere (gap 0, an overflow) fails the test: refused
        if !matches!(error.partial_cmp(&F64_GENERAL_BOUND), Some(Less | Equal)) {
            return None;
        }
        let wb = (&w * self).scale(&T::from_ratio(1, 2));
        let b1 = (&wb - &self.scale(&l1)).scale(&T::one().div_ref(&l2.sub_ref(&l1)));
        let b2 = self - &b1;
        Some([(b1, l1), (b2, l2)])
    }

    /// `exp(B)` for a simple `B` with `B² = λ` (a scalar): `cos √-λ + B sin √-λ / √-λ`,
    /// `cosh √λ + B sinh √λ / √λ`, or `1 + B`.
    pub(super) fn exp_simple(&self, lambda: &T) -> Self {
        let (c, s_over) = if lambda.is_exact_zero() {
            (T::one(), T::one())
        } else if *lambda < T::zero() {
            let th = Real::sqrt(&lambda.neg_ref());
            (Real::cos(&th), Real::sin(&th).div_ref(&th))
        } else {
            let th = Real::sqrt(lambda);
            (Real::cosh(&th), Real::sinh(&th).div_ref(&th))
        };
        let mut out = self.scale(&s_over);
        out.coeffs[0] = c;
        out
    }

    /// `exp(B) = exp(B₁) exp(B₂)` by [`Multivector::commuting_blocks`], or `None`.
    pub(super) fn exp_by_blocks(&self) -> Option<Self> {
        let [(b1, l1), (b2, l2)] = self.commuting_blocks()?;
        Some(&b1.exp_simple(&l1) * &b2.exp_simple(&l2))
    }
}
