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
/// `θ = atan2(sin, cos) ∈ [0, π]`, one `atan2` and one division.
///
/// ```
/// let (inv, kk) = algebra_core::closed_form::log_factors(&0.0f64, &1.0);
/// assert_eq!((inv, kk), (1.0, -1.0 / 3.0));
/// ```
#[inline]
pub fn log_factors<T: Real>(sin: &T, cos: &T) -> (T, T) {
    let theta = sin.atan2(cos);
    if theta.to_f64() < SMALL {
        let r = |n, d| T::from_ratio(n, d);
        let t2 = theta.mul_ref(&theta);
        let t4 = t2.mul_ref(&t2);
        // θ/sin θ = 1 + θ²/6 + 7θ⁴/360; (θ cos θ - sin θ)/sin³ θ = -1/3 - 2θ²/15 - 2θ⁴/63
        let inv = T::one() + r(1, 6) * t2.clone() + r(7, 360) * t4.clone();
        let k = r(-1, 3) - r(2, 15) * t2 - r(2, 63) * t4;
        (inv, k)
    } else {
        let r = T::one() / sin.clone();
        let r2 = r.mul_ref(&r);
        let k = (theta.mul_ref(cos) - sin.clone()) * (r2 * r.clone());
        (theta * r, k)
    }
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
pub fn check_finite<'a, T: Real + 'a>(
    op: &'static str,
    value: &dyn std::fmt::Display,
    mut coeffs: impl Iterator<Item = &'a T>,
) -> Result<(), MvError> {
    if coeffs.all(T::is_finite) { Ok(()) } else { Err(undefined(op, value.to_string(), "coefficients are not finite")) }
}

// ---------------------------------------------------------------------------------------------
// The invariant decomposition (Roelfs & De Keninck, "Graded symmetry groups: plane and simple",
// 2021): the scalar factors of the third family, bivectors of 4D and 5D algebras with
// `B² = s + Q`, `Q` a 4-vector, `Q²` a scalar (see docs/codegen.md).
// ---------------------------------------------------------------------------------------------

/// `(C(λ), S(λ))`, the entire functions `C = Σ λ^k/(2k)!` and `S = Σ λ^k/(2k+1)!`:
/// `(cos θ, sin θ / θ)` for `λ = -θ² <= 0`, `(cosh φ, sinh φ / φ)` for `λ = φ² > 0`, so that
/// `exp(b) = C(λ) + S(λ) b` whenever `b² = λ` is a scalar.
///
/// ```
/// use algebra_core::closed_form::cs;
/// let (c, s) = cs(&-0.25f64);
/// assert!((c - 0.5f64.cos()).abs() < 1e-16 && (s - 0.5f64.sin() / 0.5).abs() < 1e-16);
/// let (c, s) = cs(&4.0f64);
/// assert!((c - 2f64.cosh()).abs() < 1e-15 && (s - 2f64.sinh() / 2.0).abs() < 1e-15);
/// assert_eq!(cs(&0.0f64), (1.0, 1.0));
/// ```
#[inline]
pub fn cs<T: Real>(lambda: &T) -> (T, T) {
    if lambda.to_f64() > 0.0 {
        let (s, c) = exp_factors_hyperbolic(lambda);
        (c, s)
    } else {
        let (s, _, c) = exp_factors(&-lambda.clone());
        (c, s)
    }
}

/// `Σ_{k>=1} h_{k-1}(x, y) / (2k + odd)!` with `h_j = Σ_i x^i y^(j-i)`: the divided difference
/// of `C` (`odd = 0`) or `S` (`odd = 1`) by its power series, free of cancellation; used for
/// `|x|, |y| <= 1`, where 13 terms reach below `10⁻²⁰`.
fn divided_series<T: Real>(x: &T, y: &T, odd: i64) -> T {
    let (mut h, mut ypow) = (T::one(), T::one());
    // (2 + odd)!, the k = 1 term's denominator
    let mut fact = T::from_ratio(if odd == 1 { 6 } else { 2 }, 1);
    let mut total = h.clone() / fact.clone();
    for k in 2..=13i64 {
        ypow = ypow * y.clone();
        h = x.mul_ref(&h) + ypow.clone();
        let n = 2 * k + odd;
        fact = fact * T::from_ratio((n - 1) * n, 1);
        total = total + h.clone() / fact.clone();
    }
    total
}

/// `σ, sqrt(σ x), sqrt(σ y), p², r²` for `x, y` of one sign `σ`: the half sum and half
/// difference of the square roots, squared.
fn half_angles<T: Real>(x: &T, y: &T) -> (T, T, T, T, T) {
    let sigma = if x.to_f64() + y.to_f64() > 0.0 { T::one() } else { -T::one() };
    let (a, b) = ((sigma.mul_ref(x)).abs().sqrt(), (sigma.mul_ref(y)).abs().sqrt());
    let half = T::from_ratio(1, 2);
    let p = (a.clone() + b.clone()) * half.clone();
    let r = (a.clone() - b.clone()) * half;
    (sigma.clone(), a, b, sigma.clone() * p.mul_ref(&p), sigma * r.mul_ref(&r))
}

/// The divided difference `C[x, y] = (C(x) - C(y)) / (x - y)` (`C'(x) = S(x)/2` when
/// `x = y`), without cancellation: the power series for `|x|, |y| <= 1`; for `x, y` of one sign
/// `S(σp²) S(σr²) / 2` with `p, r` the half sum and half difference of `sqrt(σx), sqrt(σy)`
/// (from `cos a - cos b = -2 sin p sin r`); otherwise `|x - y| > 1` and the quotient directly.
///
/// ```
/// use algebra_core::closed_form::{cs, divided_c};
/// let direct = (cs(&-2.0f64).0 - cs(&-3.0f64).0) / (-2.0 + 3.0);
/// assert!((divided_c(&-2.0f64, &-3.0) - direct).abs() < 1e-15);
/// assert!((divided_c(&-2.0f64, &-2.0) - cs(&-2.0f64).1 / 2.0).abs() < 1e-16);
/// ```
pub fn divided_c<T: Real>(x: &T, y: &T) -> T {
    let (xf, yf) = (x.to_f64(), y.to_f64());
    if xf.abs() <= 1.0 && yf.abs() <= 1.0 {
        return divided_series(x, y, 0);
    }
    if (xf >= 0.0) == (yf >= 0.0) {
        let (_, _, _, p2, r2) = half_angles(x, y);
        return cs(&p2).1 * cs(&r2).1 * T::from_ratio(1, 2);
    }
    (cs(x).0 - cs(y).0) / (x.clone() - y.clone())
}

/// The divided difference `S[x, y] = (S(x) - S(y)) / (x - y)` (`S'(x) = (C(x) - S(x))/(2x)`
/// when `x = y`), without cancellation: the power series for `|x|, |y| <= 1`; the quotient
/// directly when `|x - y| >= max(|x|, |y|)/2`; otherwise (one sign `σ`, close)
/// `(C(σp²) S(σr²) - S(σp²) C(σr²)) / (2σ ab)` with `a, b = sqrt(σx), sqrt(σy)` and `p, r`
/// their half sum and half difference.
///
/// ```
/// use algebra_core::closed_form::{cs, divided_s};
/// let direct = (cs(&-2.0f64).1 - cs(&-5.0f64).1) / (-2.0 + 5.0);
/// assert!((divided_s(&-2.0f64, &-5.0) - direct).abs() < 1e-15);
/// let (c, s) = cs(&-4.0f64);
/// assert!((divided_s(&-4.0f64, &-4.0) - (c - s) / -8.0).abs() < 1e-16);
/// ```
pub fn divided_s<T: Real>(x: &T, y: &T) -> T {
    let (xf, yf) = (x.to_f64(), y.to_f64());
    let big = xf.abs().max(yf.abs());
    if big <= 1.0 {
        return divided_series(x, y, 1);
    }
    if (xf - yf).abs() >= big / 2.0 {
        return (cs(x).1 - cs(y).1) / (x.clone() - y.clone());
    }
    let (sigma, a, b, p2, r2) = half_angles(x, y);
    let ((cp, sp), (cr, sr)) = (cs(&p2), cs(&r2));
    (cp * sr - sp * cr) / (T::from_ratio(2, 1) * sigma * a * b)
}

/// The factors of `exp(B) = C1 C2 + B (D1 - D2 Q/2) + S1 S2 Q/2` for a bivector with
/// `B² = s + Q`, `Q² = q4` scalar: the invariant decomposition `B = b1 + b2`, `b_i² = λ_i`
/// the roots of `λ² - s λ + q4/4`, `exp(B) = exp(b1) exp(b2)`, `(C_i, S_i) = `[`cs`]`(λ_i)`,
/// and the divided differences `D1 = (C2 S1 λ1 - C1 S2 λ2)/(λ1 - λ2)`,
/// `D2 = (C2 S1 - C1 S2)/(λ1 - λ2)` evaluated as `D2 = C2 S[λ1,λ2] - S2 C[λ1,λ2]`,
/// `D1 = C2 (S1 + λ2 S[λ1,λ2]) - λ2 S2 C[λ1,λ2]` ([`divided_c`], [`divided_s`]), so equal
/// roots (isoclinic rotations, `λ1 = λ2 = 0` translations) need no special case.
///
/// Returns `(C1 C2, D1, D2, S1 S2)`, or `None` when the roots are complex
/// (`s² - q4 < 0` beyond rounding, possible in signatures such as `(2, 2)`); a discriminant
/// that is negative only by rounding is taken as zero (the factors are even functions of
/// `λ1 - λ2`, so this costs a rounding error only).
///
/// ```
/// use algebra_core::closed_form::invariant_exp_factors;
/// // R^4: B = 0.3 e12 + 1.1 e34, so s = -(0.09 + 1.21), Q = 0.66 e1234, Q² = 0.4356
/// let (cc, d1, d2, ss) = invariant_exp_factors(&-1.3f64, &0.4356).unwrap();
/// let (a, b) = (0.3f64, 1.1f64);
/// assert!((cc - a.cos() * b.cos()).abs() < 1e-15 && (ss - a.sin() / a * b.sin() / b).abs() < 1e-15);
/// // exp(B) = cos a cos b + (sin a cos b/a) a e12 + (cos a sin b/b) b e34 + ...
/// // B Q/2 = -a b² e12 - a² b e34, so the e12 part of B (D1 - D2 Q/2) is a (D1 + D2 b²)
/// assert!((a * (d1 + d2 * b * b) - a.sin() * b.cos()).abs() < 1e-15);
/// assert!(invariant_exp_factors(&0.0f64, &1.0).is_none()); // complex roots
/// ```
pub fn invariant_exp_factors<T: Real>(s: &T, q4: &T) -> Option<(T, T, T, T)> {
    let (l1, l2) = invariant_roots(s, q4)?;
    let ((c1, s1), (c2, s2)) = (cs(&l1), cs(&l2));
    let (dc, ds) = (divided_c(&l1, &l2), divided_s(&l1, &l2));
    let d2 = c2.mul_ref(&ds) - s2.mul_ref(&dc);
    let d1 = c2.mul_ref(&(s1.clone() + l2.mul_ref(&ds))) - l2.mul_ref(&s2) * dc;
    Some((c1 * c2, d1, d2, s1 * s2))
}

/// The roots `λ1 >= λ2` of `λ² - s λ + q4/4` (the squares of the two commuting parts of a
/// bivector with `B² = s + Q`, `Q² = q4`), the smaller in magnitude from the product
/// `λ1 λ2 = q4/4` (no cancellation); `None` for complex roots (see
/// [`invariant_exp_factors`]).
///
/// ```
/// let (l1, l2) = algebra_core::closed_form::invariant_roots(&-5.0f64, &16.0).unwrap();
/// assert_eq!((l1, l2), (-1.0, -4.0));
/// ```
pub fn invariant_roots<T: Real>(s: &T, q4: &T) -> Option<(T, T)> {
    let s2 = s.mul_ref(s);
    let disc = s2.clone() - q4.clone();
    let tol = 64.0 * T::relative_epsilon() * (s2.to_f64() + q4.to_f64().abs());
    if disc.to_f64() < -tol {
        return None;
    }
    let half = T::from_ratio(1, 2);
    let d = if disc.to_f64() > 0.0 { disc.sqrt() * half.clone() } else { T::zero() };
    let m = s.mul_ref(&half);
    let quarter = q4.clone() * T::from_ratio(1, 4);
    if m.to_f64() >= 0.0 {
        let l1 = m + d;
        let l2 = if l1.to_f64() == 0.0 { T::zero() } else { quarter / l1.clone() };
        Some((l1, l2))
    } else {
        let l2 = m - d;
        Some((quarter / l2.clone(), l2))
    }
}
