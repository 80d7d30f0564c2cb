//! The scalar factors of the closed-form `exp` and `log` that the code generator emits on
//! bivector and even types (`algebra_codegen::closed`): one copy of the trigonometric and
//! hyperbolic factors, their small-angle series, and the error helpers, called by the
//! generated methods of every module (the predefined `gam_algebras` ones and users').
//!
//! Two families are closed (see docs/codegen.md, "Closed-form exp and log"):
//!
//! - every bivector squares to a scalar, `B² = q`: `exp(B) = C + S B` with `(S, C) =
//!   (sinc θ, cos θ)` for `q = -θ² <= 0` ([`exp_factors`]) and `(sinh φ / φ, cosh φ)` for
//!   `q = φ² >= 0` ([`exp_factors_hyperbolic`]);
//! - `B² = -θ² + c I` with `I` central in the even subalgebra and `I² = 0` (3D PGA, the dual
//!   quaternions): `exp(B) = cos θ + (c/2) sinc θ I + (sinc θ - (c/2) k(θ) I) B`,
//!   `k(θ) = (cos θ - sinc θ)/θ²`, with the same factors.
//!
//! Below [`SMALL`] the factors come from their Taylor series (truncation error `θ⁶`), so a
//! zero angle (a pure translation, `1 + B`) needs no special case.
//!
//! ```
//! use algebra_core::closed_form::{exp_factors, log_factors};
//! let (sinc, k, cos) = exp_factors(&0.25f64); // θ = 1/2
//! assert!((cos - 0.5f64.cos()).abs() < 1e-16 && (sinc - 0.5f64.sin() / 0.5).abs() < 1e-16);
//! assert!((k - (cos - sinc) / 0.25).abs() < 1e-15);
//! // log_factors: θ / sin θ and (θ cos θ - sin θ) / sin³ θ, from sin θ and cos θ
//! let (inv, kk) = log_factors(&0.5f64.sin(), &0.5f64.cos());
//! let direct = (0.5 * 0.5f64.cos() - 0.5f64.sin()) / 0.5f64.sin().powi(3);
//! assert!((inv - 1.0 / sinc).abs() < 1e-15 && (kk - direct).abs() < 1e-15);
//! ```

use crate::multivector::MvError;
use crate::scalar::Real;

/// Below this angle the factors are evaluated by their series (truncation error `θ⁶`).
pub const SMALL: f64 = 1e-3;

/// `(sinc θ, k(θ) = (cos θ - sinc θ)/θ², cos θ)` from `θ² >= 0`, with one division.
///
/// ```
/// let (sinc, k, cos) = algebra_core::closed_form::exp_factors(&0.0f64);
/// assert_eq!((sinc, k, cos), (1.0, -1.0 / 3.0, 1.0));
/// ```
#[inline]
pub fn exp_factors<T: Real>(theta2: &T) -> (T, T, T) {
    let theta = theta2.sqrt();
    if theta.to_f64() < SMALL {
        let r = |n, d| T::from_ratio(n, d);
        // sinc θ = 1 - θ²/6 + θ⁴/120; k = -1/3 + θ²/30 - θ⁴/840; cos θ = 1 - θ²/2 + θ⁴/24
        let t4 = theta2.mul_ref(theta2);
        let sinc = T::one() - r(1, 6) * theta2.clone() + r(1, 120) * t4.clone();
        let k = r(-1, 3) + r(1, 30) * theta2.clone() - r(1, 840) * t4.clone();
        let cos = T::one() - r(1, 2) * theta2.clone() + r(1, 24) * t4;
        (sinc, k, cos)
    } else {
        let (s, c) = (theta.sin(), theta.cos());
        let inv = T::one() / theta;
        let sinc = s * inv.clone();
        let k = (c.clone() - sinc.clone()) * (inv.clone() * inv);
        (sinc, k, c)
    }
}

/// The factors of the logarithm of a unit element from `sin θ >= 0` and `cos θ`: `(θ / sin θ, (θ cos θ - sin θ) / sin³ θ)`, i.e. `1/sinc θ` and
/// `(cos θ - sinc θ)/(θ sin θ sinc² θ)` (the dual part of the logarithm), with
/// `θ = atan2(sin, cos) ∈ [0, π]` ([`Real::fast_atan2`]: an inlined polynomial at `f64` and
/// `f32`) and one division.
///
/// ```
/// let (inv, kk) = algebra_core::closed_form::log_factors(&0.0f64, &1.0);
/// assert_eq!((inv, kk), (1.0, -1.0 / 3.0));
/// ```
#[inline]
pub fn log_factors<T: Real>(sin: &T, cos: &T) -> (T, T) {
    let theta = sin.fast_atan2(cos);
    if theta.to_f64() < SMALL {
        log_series(&theta)
    } else {
        let r = T::one() / sin.clone();
        let r2 = r.mul_ref(&r);
        let k = (theta.mul_ref(cos) - sin.clone()) * (r2 * r.clone());
        (theta * r, k)
    }
}

/// `(θ / sin θ, (θ cos θ - sin θ) / sin³ θ)` by their series (truncation error `θ⁶`).
fn log_series<T: Real>(theta: &T) -> (T, T) {
    let r = |n, d| T::from_ratio(n, d);
    let t2 = theta.mul_ref(theta);
    let t4 = t2.mul_ref(&t2);
    // θ/sin θ = 1 + θ²/6 + 7θ⁴/360; (θ cos θ - sin θ)/sin³ θ = -1/3 - 2θ²/15 - 2θ⁴/63
    let inv = T::one() + r(1, 6) * t2.clone() + r(7, 360) * t4.clone();
    let k = r(-1, 3) - r(2, 15) * t2 - r(2, 63) * t4;
    (inv, k)
}

/// [`log_factors`] for an element that is not unit, `ρ (cos θ + sin θ …)` with `ρ > 0`: from
/// `sin = ρ sin θ >= 0`, `cos = ρ cos θ` and `alpha = ρ²` (the caller has it), the triple
/// `(θ / sin, 1 / alpha, (θ cos - sin) / sin³)`, so the generated `log` needs no
/// normalisation: one `atan2` ([`Real::fast_atan2`]) and one division, as [`log_factors`].
/// Below [`SMALL`] the series of [`log_factors`] scaled by `1/ρ` and `1/ρ²` (one square
/// root). `None` when `alpha · sin³` is not a positive normal `f64`-range number (an element
/// too large or too small to scale this way): the caller then normalises first.
///
/// ```
/// use algebra_core::closed_form::{log_factors, log_factors_nonunit};
/// let (rho, t) = (3.0f64, 0.7f64);
/// let (inv, ia, k) = log_factors_nonunit(&(rho * t.sin()), &(rho * t.cos()), &(rho * rho)).unwrap();
/// let (inv1, k1) = log_factors(&t.sin(), &t.cos());
/// assert!((inv * rho - inv1).abs() < 1e-15 && (k * rho * rho - k1).abs() < 1e-15);
/// assert!((ia - 1.0 / 9.0).abs() < 1e-17);
/// ```
#[inline]
pub fn log_factors_nonunit<T: Real>(sin: &T, cos: &T, alpha: &T) -> Option<(T, T, T)> {
    let theta = sin.fast_atan2(cos);
    if theta.to_f64() < SMALL {
        let (inv, k) = log_series(&theta);
        let ia = T::one() / alpha.clone();
        let inv_rho = alpha.sqrt() * ia.clone();
        if !(inv_rho.is_finite() && ia.to_f64().is_normal()) {
            return None;
        }
        Some((inv * inv_rho, ia.clone(), k * ia))
    } else {
        let sin2 = sin.mul_ref(sin);
        let sin3 = sin2.mul_ref(sin);
        let den = alpha.mul_ref(&sin3);
        if !den.to_f64().is_normal() || den.to_f64() < 0.0 {
            return None;
        }
        let r = T::one() / den;
        let ar = alpha.mul_ref(&r);
        let k = (theta.mul_ref(cos) - sin.clone()) * ar.clone();
        Some((theta * (sin2 * ar), sin3 * r, k))
    }
}

/// The power of two that brings the largest coefficient magnitude near 1 when it is a finite,
/// non-zero number outside `[2^-64, 2^64]` (as `f64`), else `None`. The generated `normalize`
/// and `log`, which do not depend on the element's scale, rescale by it first when the norm
/// `α = self rev(self)` would overflow or underflow; a power of two scales exactly.
///
/// ```
/// use algebra_core::closed_form::rescale;
/// assert_eq!(rescale([1e200f64, -3e199].iter()), Some(2f64.powi(-664)));
/// assert_eq!(rescale([0.5f64, 2.0].iter()), None);
/// assert_eq!(rescale([0.0f64, f64::NAN].iter()), None);
/// ```
pub fn rescale<'a, T: Real + 'a>(coeffs: impl Iterator<Item = &'a T>) -> Option<T> {
    let big = coeffs.map(|c| c.to_f64().abs()).fold(0.0, f64::max);
    let in_range = (2f64.powi(-64)..=2f64.powi(64)).contains(&big);
    if !big.is_finite() || big == 0.0 || in_range {
        return None;
    }
    // |e| <= 1000 keeps 2^-e a normal f64; a subnormal maximum takes a second step
    let e = (big.log2().round() as i32).clamp(-1000, 1000);
    Some(T::from_f64(2f64.powi(-e)))
}

/// `(sinh φ / φ, cosh φ)` from `φ² >= 0`: the factors of `exp(B) = cosh φ + (sinh φ/φ) B`
/// when `B² = φ²`.
///
/// ```
/// let (shc, ch) = algebra_core::closed_form::exp_factors_hyperbolic(&1.0f64);
/// assert!((shc - 1f64.sinh()).abs() < 1e-15 && (ch - 1f64.cosh()).abs() < 1e-15);
/// ```
#[inline]
pub fn exp_factors_hyperbolic<T: Real>(phi2: &T) -> (T, T) {
    let phi = phi2.sqrt();
    if phi.to_f64() < SMALL {
        let r = |n, d| T::from_ratio(n, d);
        let t4 = phi2.mul_ref(phi2);
        let shc = T::one() + r(1, 6) * phi2.clone() + r(1, 120) * t4.clone();
        let ch = T::one() + r(1, 2) * phi2.clone() + r(1, 24) * t4;
        (shc, ch)
    } else {
        (phi.sinh() / phi.clone(), phi.cosh())
    }
}

/// `φ / sinh` with `φ = atanh(sinh/cosh)`, from `sinh >= 0` and `cosh > sinh`:
/// the factor of the logarithm when `B² = φ² >= 0`.
///
/// ```
/// let f = algebra_core::closed_form::log_factor_hyperbolic(&1f64.sinh(), &1f64.cosh());
/// assert!((f - 1.0 / 1f64.sinh()).abs() < 1e-15);
/// ```
#[inline]
pub fn log_factor_hyperbolic<T: Real>(sinh: &T, cosh: &T) -> T {
    let t = sinh.clone() / cosh.clone();
    if t.to_f64() < SMALL {
        // atanh t / t = 1 + t²/3 + t⁴/5 + O(t⁶), and φ / sinh = (atanh t / t) / cosh
        let r = |n, d| T::from_ratio(n, d);
        let t2 = t.mul_ref(&t);
        let t4 = t2.mul_ref(&t2);
        (T::one() + r(1, 3) * t2 + r(1, 5) * t4) / cosh.clone()
    } else {
        t.atanh() / sinh.clone()
    }
}

/// `MvError::Undefined { op, value, why }`, the error of the closed forms.
///
/// ```
/// let e = algebra_core::closed_form::undefined("log", "-1".into(), "a full turn");
/// assert!(e.to_string().contains("a full turn"));
/// ```
pub fn undefined(op: &'static str, value: String, why: &str) -> MvError {
    MvError::Undefined { op, value, why: why.to_string() }
}

/// `Ok` when every coefficient is finite, else the runtime's "coefficients are not finite"
/// (`MvError::Undefined` naming `op` and `value`).
///
/// ```
/// use algebra_core::closed_form::check_finite;
/// assert!(check_finite("exp", &"x", [1.0f64, 2.0].iter()).is_ok());
/// assert!(check_finite("exp", &"x", [1.0f64, f64::NAN].iter()).is_err());
/// ```
#[inline]
pub fn check_finite<'a, T: Real + 'a>(
    op: &'static str,
    value: &dyn std::fmt::Display,
    mut coeffs: impl Iterator<Item = &'a T>,
) -> Result<(), MvError> {
    if coeffs.all(T::is_finite) { Ok(()) } else { Err(undefined(op, value.to_string(), "coefficients are not finite")) }
}

// The invariant decomposition's factors (4D and 5D algebras), in their own file.
pub use crate::closed_form_inv::{
    cs, divided_c, divided_s, invariant_exp_factors, invariant_log_factors, invariant_roots,
};
