//! The general exp, log and square root that work in every algebra (no closed form needed):
//! scaling and squaring, Denman–Beavers, inverse scaling and squaring. Every convergence test
//! runs in the scalar's own type ([`is_negligible`](crate::Ring::is_negligible)), so an MPFR computation converges
//! to its own precision, not to f64's.

use super::{Multivector, MvError};
use crate::scalar::Real;

const MAX_SERIES_TERMS: usize = 4000;

/// `log2(2^a + 2^b)` without overflow.
fn log2_add(a: f64, b: f64) -> f64 {
    let (hi, lo) = if a >= b { (a, b) } else { (b, a) };
    hi + (1.0 + (lo - hi).exp2()).log2()
}

impl<T: Real> Multivector<T> {
    /// `log2` of the unit roundoff of the working precision (from the coefficients'
    /// precision for multiple-precision types, so it does not underflow in f64).
    fn log2_epsilon(&self) -> f64 {
        match self.coeffs.iter().filter_map(Real::precision_bits).max() {
            Some(p) => 1.0 - f64::from(p),
            None => T::relative_epsilon().log2(),
        }
    }

    /// True when every coefficient of `self` is below one ulp of the largest coefficient
    /// of `of`.
    fn negligible_against(&self, of: &Self, ulps: u32) -> bool {
        let scale = of.largest_coeff();
        self.coeffs.iter().all(|c| c.is_negligible(&scale, ulps))
    }

    /// `ln` of the Euclidean norm of the coefficients, computed without squaring large or
    /// tiny values (scaled by the largest coefficient); `None` for zero.
    fn ln_norm2(&self) -> Option<T> {
        let m = Real::abs(&self.largest_coeff());
        if m.is_exact_zero() {
            return None;
        }
        let s = self.coeffs.iter().fold(T::zero(), |acc, c| {
            let r = c.div_ref(&m);
            acc.add_ref(&r.mul_ref(&r))
        });
        Some(Real::ln(&m).add_ref(&Real::ln(&s).mul_ref(&T::from_ratio(1, 2))))
    }

    /// exp by scaling and squaring, `exp(x) = exp(x / 2^k)^(2^k)`, with a running estimate of
    /// the relative error (Euclidean norm of the coefficients): `log2` of it is returned with
    /// the value. Each squaring `Y → Y²` turns a relative error `δ` into
    /// `(2δ + √dim·ε)·‖Y‖²/‖Y²‖`.
    pub(super) fn exp_scaled(&self, arg: &Self) -> Result<(Self, f64), MvError> {
        let norm = self.norm1().to_f64();
        if !norm.is_finite() {
            return Err(arg.undefined("exp", "overflow in the algorithm: the argument's norm is beyond the f64 range"));
        }
        let k = if norm > 0.25 { (norm / 0.25).log2().ceil() as u32 } else { 0 };
        let y = self.scale(&T::from_ratio(1, 2).pow_u32(k));
        let mut term = self.one_like();
        let mut sum = term.clone();
        let mut converged = false;
        for m in 1..MAX_SERIES_TERMS {
            term = (&term * &y).scale(&T::from_ratio(1, m as i64));
            sum = &sum + &term;
            if term.negligible_against(&sum, 1) {
                converged = true;
                break;
            }
        }
        if !converged {
            return Err(arg.undefined("exp", "the series did not converge"));
        }
        let dim = self.coeffs.len() as f64;
        let log2_rounding = self.log2_epsilon() + dim.log2() / 2.0;
        let mut log2_err = log2_rounding;
        let ln2 = std::f64::consts::LN_2;
        for _ in 0..k {
            let sq = &sum * &sum;
            if !sq.all_finite() {
                return Err(arg.undefined("exp", "overflow in the algorithm (scaling and squaring)"));
            }
            let growth = match (sum.ln_norm2(), sq.ln_norm2()) {
                (Some(l1), Some(l2)) => {
                    let g = l1.mul_ref(&T::from_i64(2)).sub_ref(&l2).to_f64() / ln2;
                    if g.is_finite() { g.max(0.0) } else { 0.0 }
                }
                _ => 0.0,
            };
            log2_err = log2_add(log2_err + 1.0, log2_rounding) + growth;
            sum = sq;
        }
        Ok((sum, log2_err))
    }

    /// Denman–Beavers: Y ← (Y + Z⁻¹)/2, Z ← (Z + Y⁻¹)/2 with Y₀ = x, Z₀ = 1; Y → √x.
    fn sqrt_db(&self) -> Result<Self, MvError> {
        let half = T::from_ratio(1, 2);
        let mut y = self.clone();
        let mut z = self.one_like();
        for _ in 0..200 {
            let yi = y.inverse().map_err(|_| self.undefined("sqrt", "the iteration met a non-invertible element"))?;
            let zi = z.inverse().map_err(|_| self.undefined("sqrt", "the iteration met a non-invertible element"))?;
            let y_next = (&y + &zi).scale(&half);
            z = (&z + &yi).scale(&half);
            let change = &y_next - &y;
            y = y_next;
            if !y.all_finite() {
                return Err(self.undefined("sqrt", "overflow in the algorithm (Denman-Beavers)"));
            }
            if change.negligible_against(&y, 16) {
                return Ok(y);
            }
        }
        Err(self.undefined("sqrt", "the Denman-Beavers iteration did not converge"))
    }

    /// Inverse scaling and squaring: log x = 2^k log(x^(1/2^k)); the result must exponentiate
    /// back to `x` (a backward-error check in the working precision).
    pub(super) fn log_general(&self) -> Result<Self, MvError> {
        let one = self.one_like();
        let quarter = T::from_ratio(1, 4);
        let mut y = self.clone();
        let mut k = 0u32;
        while (&y - &one).norm1() > quarter {
            if k >= 100 {
                return Err(self.undefined("log", "repeated square roots did not approach 1"));
            }
            y = y.sqrt_db().map_err(|_| {
                if self.fixed_precision() {
                    // f64 cannot tell the two apart: near a half-angle of π (a log exists,
                    // MPFR finds it) the iteration fails as it does where no log exists
                    self.undefined("log", "ill-conditioned or undefined: the repeated square roots failed in this precision (a rotation by a half-angle near π is ill-conditioned; mpfr:BITS decides)")
                } else {
                    self.undefined("log", "no real logarithm (square root failed)")
                }
            })?;
            k += 1;
        }
        let z = &y - &one;
        let mut power = z.clone();
        let mut sum = z.clone();
        let mut converged = z.is_zero();
        for m in 2..MAX_SERIES_TERMS as i64 {
            if converged {
                break;
            }
            power = &power * &z;
            let sign = if m % 2 == 0 { -1 } else { 1 };
            let term = power.scale(&T::from_ratio(sign, m));
            sum = &sum + &term;
            converged = term.negligible_against(&sum, 1) || power.is_zero();
        }
        if !converged {
            return Err(self.undefined("log", "the series did not converge"));
        }
        let out = sum.scale(&T::from_i64(2).pow_u32(k));
        if !out.all_finite() {
            return Err(self.undefined("log", "overflow in the algorithm"));
        }
        let back = out.exp_raw()?;
        let residual = (&back - self).norm1().to_f64() / self.norm1().to_f64();
        if residual.is_nan() || residual > 1e-3 {
            return Err(self.undefined("log", "no real logarithm (check exp(log x) = x failed)"));
        }
        if self.fixed_precision() && residual > super::exp_log::F64_GENERAL_BOUND {
            return Err(self.undefined("log", Self::ill_conditioned(residual.log2())));
        }
        Ok(out)
    }
}
