//! exp, log and sqrt over a [`Real`] scalar.
//!
//! * Closed forms when `x = a + B` with `B² = β` a scalar (rotors, boosts, null
//!   translators): `exp`, `log`.
//! * Otherwise general methods that work in every algebra ([`super::general`]): `exp` by
//!   scaling and squaring with a Taylor series, `sqrt` by the Denman–Beavers iteration, `log`
//!   by inverse scaling and squaring (repeated square roots, then the series of `log(1 + z)`).
//!
//! Precision: every convergence and zero test runs in the scalar's own type. For
//! multiple-precision scalars the whole computation is repeated with more guard bits until
//! two runs agree to the requested precision (the largest precision among the argument's
//! coefficients), and the result is rounded to it; for fixed-precision scalars (`f64`, dual
//! numbers) a result whose error estimate exceeds [`F64_GENERAL_BOUND`] is refused as
//! ill-conditioned. A failure is a typed [`MvError::Undefined`], never a NaN.

use super::{Multivector, MvError};
use crate::scalar::Real;
use std::cmp::Ordering;

/// The largest relative error (in the 1-norm of the coefficients) that the general exp, log
/// and sqrt accept for fixed-precision scalars (`f64`, dual numbers): `2^-26 ≈ 1.5e-8`. A
/// result whose running error estimate is larger is refused with an "ill-conditioned" error.
pub const F64_GENERAL_BOUND: f64 = 1.0 / 67_108_864.0;

/// Guard bits beyond which a multiple-precision computation is declared ill-conditioned.
const MAX_GUARD_BITS: u32 = 8192;

impl<T: Real> Multivector<T> {
    pub(super) fn undefined(&self, op: &'static str, why: impl Into<String>) -> MvError {
        MvError::Undefined { op, value: self.describe(), why: why.into() }
    }

    pub(super) fn one_like(&self) -> Self {
        Multivector::scalar(&self.algebra, self.basis, T::one())
    }

    pub(super) fn check_finite(self, op: &'static str, arg: &Self, why: &str) -> Result<Self, MvError> {
        if self.all_finite() { Ok(self) } else { Err(arg.undefined(op, why)) }
    }

    /// The result of `exp` if finite, else "the result overflows" (`exp(1000)`, `exp(1000 e1)`
    /// with `e1² = 1`).
    fn exp_result(self, arg: &Self) -> Result<Self, MvError> {
        if self.all_finite() { Ok(self) } else { Err(arg.undefined("exp", "the result overflows")) }
    }

    pub(super) fn all_finite(&self) -> bool {
        self.coeffs.iter().all(Real::is_finite)
    }

    fn require_finite(&self, op: &'static str) -> Result<(), MvError> {
        if self.all_finite() { Ok(()) } else { Err(self.undefined(op, "coefficients are not finite")) }
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
        self.require_finite("exp")?;
        self.at_requested_precision("exp", Self::exp_raw)
    }

    /// exp at the working precision: closed form, or `e^a · exp(B)` by the general method
    /// (the scalar part commutes with everything).
    pub(super) fn exp_raw(&self) -> Result<Self, MvError> {
        let (a, b, square) = self.scalar_square_split();
        let ea = Real::exp(&a);
        if let Some(sq) = square {
            if sq.sign == Ordering::Less && !sq.beta.is_finite() {
                // `1e300·e12`: a unit rotor cannot overflow, but θ² does, and cos θ of an
                // infinite angle is NaN (an angle that large is meaningless in this precision)
                return Err(self.undefined("exp", "the rotation angle is too large for this scalar (θ² overflows)"));
            }
            let th = sq.root;
            let (c, s_over) = match sq.sign {
                Ordering::Equal => (T::one(), T::one()),
                Ordering::Less => (Real::cos(&th), Real::sin(&th).div_ref(&th)),
                Ordering::Greater => (Real::cosh(&th), Real::sinh(&th).div_ref(&th)),
            };
            let mut out = b.scale(&s_over.mul_ref(&ea));
            out.coeffs[0] = c.mul_ref(&ea);
            return out.exp_result(self);
        }
        let general = b.exp_scaled(self);
        let refused = match &general {
            Ok((_, log2_err)) => self.fixed_precision() && *log2_err > F64_GENERAL_BOUND.log2(),
            Err(_) => true,
        };
        if refused && self.fixed_precision() {
            // large non-simple bivectors: closed forms per commuting block (super::blocks)
            if let Some(eb) = b.exp_by_blocks() {
                return eb.scale(&ea).exp_result(self);
            }
        }
        let (eb, log2_err) = general?;
        if self.fixed_precision() && log2_err > F64_GENERAL_BOUND.log2() {
            return Err(self.undefined("exp", Self::ill_conditioned(log2_err)));
        }
        eb.scale(&ea).exp_result(self)
    }

    /// The principal square root: closed form when `x = a + B` with `B²` scalar, else the
    /// general log. Fails when no real square root exists (e.g. `-1` in g3).
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
        self.require_finite("sqrt")?;
        self.at_requested_precision("sqrt", Self::sqrt_raw)
    }

    fn sqrt_raw(&self) -> Result<Self, MvError> {
        if let Some(e) = self.unusual_exponent() {
            // √x = 2^k √(x/4^k), exactly: the decisions are made at unit scale
            let k = e.div_euclid(2);
            let r = self.scale_pow2(-2 * k).sqrt_unit_scale().map_err(|err| self.restate(err))?;
            return r.scale_pow2(k).check_finite("sqrt", self, "the result is not finite (overflow in the algorithm)");
        }
        self.sqrt_unit_scale()
    }

    /// sqrt of an element whose largest coefficient is of ordinary size.
    fn sqrt_unit_scale(&self) -> Result<Self, MvError> {
        let l = self.log_unit_scale().map_err(|e| match e {
            MvError::Undefined { why, .. } if why.starts_with("ill-conditioned") => self.undefined("sqrt", why),
            _ => self.undefined("sqrt", "no real square root (no real logarithm)"),
        })?;
        l.scale(&T::from_ratio(1, 2)).exp_raw()
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
        self.require_finite("log")?;
        self.at_requested_precision("log", Self::log_raw)
    }

    pub(super) fn log_raw(&self) -> Result<Self, MvError> {
        if let Some(e) = self.unusual_exponent() {
            // log x = log(x/2^e) + e ln 2 (a positive scalar commutes with everything)
            let mut l = self.scale_pow2(-e).log_unit_scale().map_err(|err| self.restate(err))?;
            let shift = T::from_i64(i64::from(e)).mul_ref(&Real::ln(&T::from_i64(2)));
            l.coeffs[0] = l.coeffs[0].add_ref(&shift);
            return l.check_finite("log", self, "the result is not finite (overflow in the algorithm)");
        }
        self.log_unit_scale()
    }

    /// An error of a computation on a rescaled copy, restated about `self`.
    fn restate(&self, err: MvError) -> MvError {
        match err {
            MvError::Undefined { op, why, .. } => self.undefined(op, why),
            other => other,
        }
    }

    /// log of an element whose largest coefficient is of ordinary size.
    fn log_unit_scale(&self) -> Result<Self, MvError> {
        let (a, b, square) = self.scalar_square_split();
        if let Some(sq) = square {
            let zero = T::zero();
            let (beta, s) = (&sq.beta, &sq.root);
            let (ln_r, f) = match sq.sign {
                Ordering::Equal => {
                    if a <= zero {
                        return Err(
                            self.undefined("log", "the scalar part must be positive when the rest squares to 0")
                        );
                    }
                    (Real::ln(&a), T::one().div_ref(&a))
                }
                Ordering::Less => {
                    let r2 = a.mul_ref(&a).sub_ref(beta);
                    (Real::ln(&r2).mul_ref(&T::from_ratio(1, 2)), Real::atan2(s, &a).div_ref(s))
                }
                Ordering::Greater => {
                    if a <= *s {
                        return Err(self.undefined("log", "no real logarithm: need scalar part > sqrt(B^2)"));
                    }
                    let r2 = a.mul_ref(&a).sub_ref(beta);
                    (Real::ln(&r2).mul_ref(&T::from_ratio(1, 2)), Real::atanh(&s.div_ref(&a)).div_ref(s))
                }
            };
            let mut out = b.scale(&f);
            out.coeffs[0] = ln_r;
            return out.check_finite("log", self, "the result is not finite (overflow in the algorithm)");
        }
        self.log_general()
    }

    /// True for fixed-precision scalars (no coefficient reports a precision).
    pub(super) fn fixed_precision(&self) -> bool {
        self.coeffs.iter().all(|c| c.precision_bits().is_none())
    }

    pub(super) fn ill_conditioned(log2_err: f64) -> String {
        format!(
            "ill-conditioned: the estimated relative error 2^{log2_err:.0} of the general method exceeds the bound {F64_GENERAL_BOUND:.1e} (use mpfr:BITS)"
        )
    }

    /// The coefficients rounded (or extended) to `bits` bits.
    pub(super) fn at_precision(&self, bits: u32) -> Self {
        self.map_coeffs(|c| c.with_precision(bits))
    }

    /// Runs `f` at the working precision. Fixed-precision scalars: once. Multiple precision
    /// `p` (the largest among the coefficients): with `g` and then `2g` guard bits (g = 32,
    /// doubling) until two runs agree to within `2^(1-p)` of the largest coefficient, then
    /// rounds to `p` bits.
    fn at_requested_precision(&self, op: &'static str, f: fn(&Self) -> Result<Self, MvError>) -> Result<Self, MvError> {
        let Some(p) = self.coeffs.iter().filter_map(Real::precision_bits).max() else {
            return f(self);
        };
        let run = |guard: u32| {
            let w = p.saturating_add(guard);
            T::with_working_precision(w, || f(&self.at_precision(w)))
        };
        let mut guard = 32;
        let mut prev = run(guard)?;
        while guard < MAX_GUARD_BITS {
            guard *= 2;
            let next = run(guard)?;
            let scale = next.largest_coeff().with_precision(p);
            let agree = next
                .coeffs
                .iter()
                .zip(&prev.coeffs)
                .all(|(x, y)| x.sub_ref(y).with_precision(p).is_negligible(&scale, 1));
            if agree {
                return Ok(next.at_precision(p));
            }
            prev = next;
        }
        Err(self.undefined(op, format!("ill-conditioned: {MAX_GUARD_BITS} guard bits did not reach {p} correct bits")))
    }

    /// The coefficient of largest magnitude (compared in the scalar's own type).
    pub(super) fn largest_coeff(&self) -> T {
        self.coeffs
            .iter()
            .reduce(|a, b| if b.cmp_magnitude(a).is_gt() { b } else { a })
            .cloned()
            .unwrap_or_else(T::zero)
    }

    /// The sum of the absolute values of the coefficients, in the scalar's own type.
    pub(super) fn norm1(&self) -> T {
        self.coeffs.iter().fold(T::zero(), |acc, c| acc.add_ref(&Real::abs(c)))
    }
}
