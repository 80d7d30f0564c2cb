//! exp, log and sqrt over a [`Real`] scalar.
//!
//! * Closed forms when `x = a + B` with `B² = β` a scalar (rotors, boosts, null
//!   translators): `exp`, `log`.
//! * Otherwise general methods that work in every algebra: `exp` by scaling and squaring with
//!   a Taylor series, `sqrt` by the Denman–Beavers iteration, `log` by inverse scaling and
//!   squaring (repeated square roots, then the series of `log(1 + z)`). Each result is
//!   checked, and a failure is a typed [`MvError::Undefined`], never a NaN.

use super::{Multivector, MvError};
use crate::scalar::{Real, Ring};

const MAX_SERIES_TERMS: usize = 2000;

impl<T: Real> Multivector<T> {
    fn undefined(&self, op: &'static str, why: impl Into<String>) -> MvError {
        MvError::Undefined { op, value: self.to_string(), why: why.into() }
    }

    fn one_like(&self) -> Self {
        Multivector::scalar(&self.algebra, self.basis, T::one())
    }

    /// Splits `self = a + B` (a = identity coefficient) and returns `(a, B, β)` when
    /// `B² = β` exactly (all other coefficients exactly zero).
    fn scalar_square_split(&self) -> (T, Self, Option<T>) {
        let a = self.coeffs[0].clone();
        let mut b = self.clone();
        b.coeffs[0] = T::zero();
        let b2 = &b * &b;
        let is_scalar = b2.coeffs.iter().skip(1).all(Ring::is_exact_zero);
        let beta = is_scalar.then(|| b2.coeffs[0].clone());
        (a, b, beta)
    }

    fn check_finite(self, op: &'static str, arg: &Self) -> Result<Self, MvError> {
        if self.coeffs.iter().all(Real::is_finite) {
            Ok(self)
        } else {
            Err(arg.undefined(op, "the result is not finite"))
        }
    }

    /// The exponential.
    ///
    /// ```
    /// use algebra_core::{Algebra, Basis, Multivector};
    /// let alg = Algebra::builtin("g3").unwrap();
    /// let b = Multivector::from_terms(&alg, Basis::Blade, [("e12", std::f64::consts::FRAC_PI_2)]).unwrap();
    /// let r = b.exp().unwrap(); // cos(π/2) + e12 sin(π/2)
    /// assert!((r.coeff_by_name("e12").unwrap() - 1.0).abs() < 1e-15);
    /// assert!(r.coeff_by_name("1").unwrap().abs() < 1e-15);
    /// ```
    pub fn exp(&self) -> Result<Self, MvError> {
        let (a, b, beta) = self.scalar_square_split();
        let ea = Real::exp(&a);
        let eps = T::relative_epsilon().max(1e-300);
        if let Some(beta) = beta.filter(|beta| beta.is_exact_zero() || beta.magnitude() > eps.sqrt()) {
            let (c, s_over) = if beta.is_exact_zero() {
                (T::one(), T::one())
            } else if beta < T::zero() {
                let th = Real::sqrt(&beta.neg_ref());
                (Real::cos(&th), Real::sin(&th).div_ref(&th))
            } else {
                let th = Real::sqrt(&beta);
                (Real::cosh(&th), Real::sinh(&th).div_ref(&th))
            };
            let mut out = b.scale(&s_over.mul_ref(&ea));
            out.coeffs[0] = c.mul_ref(&ea);
            return out.check_finite("exp", self);
        }
        self.exp_series()
    }

    /// exp by scaling and squaring: exp(x) = exp(x / 2^k)^(2^k).
    fn exp_series(&self) -> Result<Self, MvError> {
        let norm = self.magnitude();
        if !norm.is_finite() {
            return Err(self.undefined("exp", "coefficients are not finite"));
        }
        let k = if norm > 0.25 { (norm / 0.25).log2().ceil() as u32 } else { 0 };
        let y = self.scale(&T::from_ratio(1, 1).div_ref(&T::from_i64(1i64 << k.min(62))));
        let eps = T::relative_epsilon();
        let mut term = self.one_like();
        let mut sum = term.clone();
        for m in 1..MAX_SERIES_TERMS {
            term = (&term * &y).scale(&T::from_ratio(1, m as i64));
            sum = &sum + &term;
            if term.magnitude() <= eps * 0.5 * sum.magnitude() || term.is_zero() {
                let mut out = sum;
                for _ in 0..k {
                    out = &out * &out;
                }
                return out.check_finite("exp", self);
            }
        }
        Err(self.undefined("exp", "the series did not converge"))
    }

    /// The principal square root: closed form when `x = a + B` with `B²` scalar, else the
    /// Denman–Beavers iteration. Fails when no real square root exists (e.g. `-1` in g3).
    ///
    /// ```
    /// use algebra_core::{Algebra, Basis, Multivector};
    /// let alg = Algebra::builtin("g123inf").unwrap();
    /// let t = Multivector::<f64>::from_terms(&alg, Basis::Blade, [("1", 1.0), ("e1inf", 1.0)]).unwrap();
    /// let s = t.sqrt().unwrap();
    /// assert!((s.coeff_by_name("e1inf").unwrap() - 0.5).abs() < 1e-15);
    /// assert!(Multivector::scalar(&alg, Basis::Blade, -1.0).sqrt().is_err());
    /// ```
    pub fn sqrt(&self) -> Result<Self, MvError> {
        let l = self.log().map_err(|_| self.undefined("sqrt", "no real square root (no real logarithm)"))?;
        l.scale(&T::from_ratio(1, 2)).exp()
    }

    /// Denman–Beavers: Y ← (Y + Z⁻¹)/2, Z ← (Z + Y⁻¹)/2 with Y₀ = x, Z₀ = 1; Y → √x.
    fn sqrt_db(&self) -> Result<Self, MvError> {
        let half = T::from_ratio(1, 2);
        let eps = T::relative_epsilon().max(1e-300);
        let mut y = self.clone();
        let mut z = self.one_like();
        for _ in 0..100 {
            let yi = y.inverse().map_err(|_| self.undefined("sqrt", "the iteration met a non-invertible element"))?;
            let zi = z.inverse().map_err(|_| self.undefined("sqrt", "the iteration met a non-invertible element"))?;
            let y_next = (&y + &zi).scale(&half);
            z = (&z + &yi).scale(&half);
            let change = (&y_next - &y).magnitude();
            y = y_next;
            if change <= 16.0 * eps * y.magnitude() {
                return y.check_finite("sqrt", self);
            }
        }
        Err(self.undefined("sqrt", "the Denman-Beavers iteration did not converge"))
    }

    /// The principal logarithm (inverse of [`Multivector::exp`]).
    ///
    /// ```
    /// use algebra_core::{Algebra, Basis, Multivector};
    /// let alg = Algebra::builtin("g3").unwrap();
    /// let r = Multivector::from_terms(&alg, Basis::Blade, [("1", 0.6), ("e12", 0.8)]).unwrap();
    /// let b = r.log().unwrap();
    /// assert!((b.coeff_by_name("e12").unwrap() - 0.8f64.atan2(0.6)).abs() < 1e-15);
    /// assert!(Multivector::scalar(&alg, Basis::Blade, 0.0).log().is_err());
    /// ```
    pub fn log(&self) -> Result<Self, MvError> {
        let (a, b, beta) = self.scalar_square_split();
        let eps = T::relative_epsilon().max(1e-300);
        if let Some(beta) = beta.filter(|beta| beta.is_exact_zero() || beta.magnitude() > eps.sqrt()) {
            let zero = T::zero();
            let (ln_r, f) = if beta.is_exact_zero() {
                if a <= zero {
                    return Err(self.undefined("log", "the scalar part must be positive when the rest squares to 0"));
                }
                (Real::ln(&a), T::one().div_ref(&a))
            } else if beta < zero {
                let s = Real::sqrt(&beta.neg_ref());
                let r2 = a.mul_ref(&a).sub_ref(&beta);
                (Real::ln(&r2).mul_ref(&T::from_ratio(1, 2)), Real::atan2(&s, &a).div_ref(&s))
            } else {
                let s = Real::sqrt(&beta);
                if a <= s {
                    return Err(self.undefined("log", "no real logarithm: need scalar part > sqrt(B^2)"));
                }
                let r2 = a.mul_ref(&a).sub_ref(&beta);
                (Real::ln(&r2).mul_ref(&T::from_ratio(1, 2)), Real::atanh(&s.div_ref(&a)).div_ref(&s))
            };
            let mut out = b.scale(&f);
            out.coeffs[0] = ln_r;
            return out.check_finite("log", self);
        }
        self.log_general()
    }

    /// Inverse scaling and squaring: log x = 2^k log(x^(1/2^k)).
    fn log_general(&self) -> Result<Self, MvError> {
        let one = self.one_like();
        let eps = T::relative_epsilon().max(1e-300);
        let mut y = self.clone();
        let mut k = 0u32;
        while (&y - &one).magnitude() > 0.25 {
            if k >= 60 {
                return Err(self.undefined("log", "repeated square roots did not approach 1"));
            }
            y = y.sqrt_db().map_err(|_| self.undefined("log", "no real logarithm (square root failed)"))?;
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
            converged = term.magnitude() <= eps * 0.5 * sum.magnitude().max(eps) || power.is_zero();
        }
        if !converged {
            return Err(self.undefined("log", "the series did not converge"));
        }
        let out = sum.scale(&T::from_i64(1i64 << k));
        // The result must exponentiate back.
        let back = out.exp()?;
        let err = (&back - self).magnitude();
        if err > 1e3 * eps.sqrt().max(eps * 1e6) * self.magnitude().max(1.0) {
            return Err(self.undefined("log", "no real logarithm (check exp(log x) = x failed)"));
        }
        out.check_finite("log", self)
    }
}
