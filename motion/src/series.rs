//! The scalar functions behind the closed-form exp and log ([`crate::exp_log`]), as functions
//! of a *squared* angle so that no square root is taken near zero rotation: there the power
//! series is used, which is exact at `0` and keeps the derivative parts of dual numbers finite
//! (`√x` has an infinite derivative at `0`). Away from zero the closed forms lose at most a few
//! ulps to cancellation (the thresholds bound the loss by a factor 16).
//!
//! Series stop when a term (every component, for dual numbers) is below the type's relative
//! epsilon over 16; the values are of order one.

use algebra_core::{Real, Ring};

const MAX_TERMS: i64 = 2000;

fn negligible<T: Ring>(x: &T) -> bool {
    // in the type's own precision: at more than ~1070 bits ε is below f64's range
    x.is_negligible(&T::from_ratio(1, 16), 1)
}

/// `[cos θ, sin θ / θ, (sin θ / θ - cos θ)/θ²]` for `u = θ² ≥ 0`: the exp kernel. Series for
/// `u ≤ 1`: `Σ (-u)^k/(2k)!`, `Σ (-u)^k/(2k+1)!`, `Σ (-u)^j 2(j+1)/(2j+3)!`.
pub(crate) fn exp_kernel<T: Real>(u: &T) -> [T; 3] {
    if *u > T::one() {
        let th = Real::sqrt(u);
        let c = Real::cos(&th);
        let s = Real::sin(&th).div_ref(&th);
        let t = s.sub_ref(&c).div_ref(u);
        return [c, s, t];
    }
    exp_series(u, |_, terms| terms.iter().all(negligible))
}

/// Whether `T` carries at most `f64`'s precision (f64, f32, dual numbers and jets over
/// them): then the fixed-length polynomials below are exact to its last bit, and the pose
/// layer's direct paths use them.
pub(crate) fn at_most_f64<T: Ring>() -> bool {
    T::relative_epsilon() >= f64::EPSILON
}

/// Whether `T` is one `f64` (not a dual number, jet, lanes or `f32`): eight bytes with
/// `f64`'s precision. Then `magnitude` is `|x|` (NaN for NaN) and the direct paths can fold
/// their finiteness tests into one number ([`crate::Pose::transform_point`]) or skip them for
/// inputs of bounded size (`Pose::modest_f64`).
pub(crate) fn plain_f64<T: Ring>() -> bool {
    std::mem::size_of::<T>() == 8 && T::relative_epsilon() == f64::EPSILON
}

/// Terms of the fixed exp polynomials, used up to `u = 4` (half-angles up to 2): there the
/// first omitted term is below `4^14/28! < 2^-69` (Estrin's scheme evaluates 14 terms in as
/// many dependent steps as 10).
const EXP_TERMS: usize = 14;

/// `[(-1)^k/(2k)!, (-1)^k/(2k+1)!, (-1)^k 2(k+1)/(2k+3)!]` for `k < EXP_TERMS`: the series
/// of `[C, S, T]` of [`exp_kernel`], as `f64` (the factorials up to 18! are exact in `f64`).
const EXP_COEFFS: [[f64; EXP_TERMS]; 3] = {
    let mut c = [[0.0; EXP_TERMS]; 3];
    let mut k = 0;
    while k < EXP_TERMS {
        let n = 2 * k as u64;
        let sign = if k % 2 == 0 { 1.0 } else { -1.0 };
        c[0][k] = sign / factorial(n);
        c[1][k] = sign / factorial(n + 1);
        c[2][k] = sign * (2 * (k as u64 + 1)) as f64 / factorial(n + 3);
        k += 1;
    }
    c
};

const fn factorial(n: u64) -> f64 {
    let mut f = 1.0;
    let mut i = 2;
    while i <= n {
        f *= i as f64;
        i += 1;
    }
    f
}

/// `Σ c_k x^k` (`N ≤ 32` coefficients) by Estrin's scheme: pairs `c_2i + c_2i+1 x`, then pairs
/// of those with `x²`, then `x⁴`, `x⁸`, `x¹⁶`: a dependent chain of `log2 N` steps instead of
/// Horner's `N`, for polynomials whose latency, not their operation count, limits the pose layer.
#[inline]
fn poly<T: Real, const N: usize>(c: &[f64; N], x: &T) -> T {
    const { assert!(N >= 1 && N <= 32) };
    let mut v: [T; 32] = std::array::from_fn(|i| if i < N { T::from_f64(c[i]) } else { T::zero() });
    let (mut n, mut p) = (N, x.clone());
    while n > 1 {
        for i in 0..n.div_ceil(2) {
            v[i] = if 2 * i + 1 < n { v[2 * i].add_ref(&v[2 * i + 1].mul_ref(&p)) } else { v[2 * i].clone() };
        }
        n = n.div_ceil(2);
        p = p.mul_ref(&p);
    }
    v[0].clone()
}

/// [`exp_kernel`] for types of at most `f64` precision ([`at_most_f64`]): the closed form above
/// `u = 4`, below it fixed polynomials of [`EXP_TERMS`] terms (no term-by-term test).
#[inline]
pub(crate) fn exp_kernel_fixed<T: Real>(u: &T) -> [T; 3] {
    if u.to_f64() > 4.0 {
        return exp_kernel(u);
    }
    [poly(&EXP_COEFFS[0], u), poly(&EXP_COEFFS[1], u), poly(&EXP_COEFFS[2], u)]
}

/// `(s - θ cos θ)/θ³ = Σ_{k≥1} (-1)^(k+1) 2k/(2k+1)! θ^(2k-2)`, 7 terms: at `θ ≤ π/6` the first
/// omitted term is below `2^-56` of the leading `1/3`.
const SIN_MINUS_THETA_COS: [f64; 7] = {
    let mut c = [0.0; 7];
    let mut k = 1;
    while k <= 7 {
        let sign = if k % 2 == 1 { 1.0 } else { -1.0 };
        c[k - 1] = sign * (2 * k) as f64 / factorial(2 * k as u64 + 1);
        k += 1;
    }
    c
};

/// The factors `(f, g)` of the logarithm of a unitary element with `u0 = cos θ ≥ 0` and
/// `x = sin² θ` (exp_log.rs, first case): `f = θ/sin θ`, `g = (sin θ - θ cos θ)/sin³ θ`, for
/// types of at most `f64` precision, given `s = sin θ` and `θ` (the caller takes them from the
/// pose before its normalisation: the angle is scale-invariant, so it is computed beside the
/// normalisation instead of after it). Below `x = 2^-20` three terms of the series of
/// [`log_kernel`]; up to `x = 1/4` (`θ = π/6`) the numerator of `g` from its own series in `θ`
/// (no cancellation), above it directly (as [`log_kernel`]'s caller does).
#[inline]
pub(crate) fn log_factors_fixed<T: Real>(u0: &T, x: &T, s: &T, th: &T) -> (T, T) {
    if x.to_f64() <= SMALL_X {
        // f = 1 + x/6 + 3x²/40 + 5x³/112, h = 1/3 + 3x/10 + 15x²/56, g = h u0
        let f = poly(&[1.0, 1.0 / 6.0, 3.0 / 40.0, 5.0 / 112.0], x);
        let h = poly(&[1.0 / 3.0, 3.0 / 10.0, 15.0 / 56.0], x);
        return (f, h.mul_ref(u0));
    }
    let r = T::one().div_ref(s);
    let num = if x.to_f64() <= 0.25 {
        let t2 = th.mul_ref(th);
        poly(&SIN_MINUS_THETA_COS, &t2).mul_ref(&t2).mul_ref(th)
    } else {
        s.sub_ref(&th.mul_ref(u0))
    };
    (th.mul_ref(&r), num.mul_ref(&r.mul_ref(&r).mul_ref(&r)))
}

/// `√α (sin θ - θ cos θ)` of a pose with `rev(S) S = α + βω`, given `|a| = √α sin θ`,
/// `S∅ = √α cos θ ≥ 0`, `θ` and `√α`: `|a| - θ S∅` directly, or with `series` (`θ ≤ π/6`)
/// `√α θ³ P(θ²)` by [`SIN_MINUS_THETA_COS`] (no cancellation). A branch, not a select of both:
/// on the pose bench (the same 256 poses each round) computing both cost 6 ns more than the
/// branch's mispredictions.
#[inline]
pub(crate) fn sin_minus_theta_cos_raw<T: Real>(th: &T, s_raw: &T, s0: &T, root: &T, series: bool) -> T {
    if series {
        let t2 = th.mul_ref(th);
        poly(&SIN_MINUS_THETA_COS, &t2).mul_ref(&t2).mul_ref(&th.mul_ref(root))
    } else {
        s_raw.sub_ref(&th.mul_ref(s0))
    }
}

/// `G(z) = (asin(√z)/√z - 1)/z` on `[0, 1/2]` as a polynomial in `z - 1/4`, lowest degree
/// first: a degree-18 Chebyshev fit (error 2.1e-17) from the committed script
/// `tests/fixtures/mpmath/asin_poly.py`, which also measures the evaluation below: `F = 1 + z G`
/// within 0.66 ulp, `θ²` within 3.1 ulp and `θ` within 1.7 ulp at 20,000 points.
const ASIN_G: [f64; 19] = [
    0.188790204786391,
    0.10486307831566742,
    0.07967743003164936,
    0.07032542600998264,
    0.06774274873843153,
    0.06909194196163959,
    0.07335776605124363,
    0.0802409827785538,
    0.08980591226486923,
    0.10235897562586345,
    0.11840125960250697,
    0.13853805662488142,
    0.16389931479149009,
    0.19825308382133286,
    0.23852995947167321,
    0.2503234447753555,
    0.3039650877985459,
    0.6795985842752457,
    0.8387674099544927,
];

/// `π/2` as `(hi, lo)`, `hi + lo` the value to about `2^-106`.
const PI_2: (f64, f64) = (std::f64::consts::FRAC_PI_2, 6.123_233_995_736_766e-17);

/// `(θ², f, g)` of the logarithm of a unitary element with `u0 = cos θ ≥ 0`, for types of at
/// most `f64` precision, from `x = sin² θ` and `y = cos² θ` (each computed from the pose, not
/// one from the other), `u0` and `s = sin θ`: `f = θ/sin θ`, `g = (sin θ - θ cos θ)/sin³ θ`
/// as in [`log_factors_fixed`], and `θ²` for the exp kernel of a power.
///
/// No square root and no division on the way to `θ²` (the chain that limits a slerp): with
/// `F(z) = asin(√z)/√z` at `z = min(x, y) ≤ 1/2` ([`ASIN_G`]), `θ = √x F(x)`, so `θ² = x F(x)²`
/// and `f = F(x)`, when `x ≤ y`; else `θ = π/2 - u0 F(y)` and `f = θ/s`. Then `g` from the
/// series of [`log_factors_fixed`] in `θ²` up to `x = 1/4` (`g = P(θ²) f³`, no cancellation),
/// above it `(1 - f u0)/x`. Below `x = 2^-20` the three-term series, exact at a translation.
#[inline(always)]
pub(crate) fn angle_factors_fixed<T: Real>(x: &T, y: &T, u0: &T, s: &T) -> (T, T, T) {
    if x.to_f64() <= SMALL_X {
        let f = poly(&[1.0, 1.0 / 6.0, 3.0 / 40.0, 5.0 / 112.0], x);
        let h = poly(&[1.0 / 3.0, 3.0 / 10.0, 15.0 / 56.0], x);
        return (x.mul_ref(&f.mul_ref(&f)), f, h.mul_ref(u0));
    }
    let small = x <= y;
    let z = if small { x } else { y };
    let fz = T::one().add_ref(&z.mul_ref(&poly(&ASIN_G, &z.sub_ref(&T::from_ratio(1, 4)))));
    let one_minus_fu0_over_x = |f: &T| T::one().sub_ref(&f.mul_ref(u0)).div_ref(x);
    if small {
        let th2 = x.mul_ref(&fz.mul_ref(&fz));
        let g = if x.to_f64() <= 0.25 {
            poly(&SIN_MINUS_THETA_COS, &th2).mul_ref(&fz.mul_ref(&fz).mul_ref(&fz))
        } else {
            one_minus_fu0_over_x(&fz)
        };
        return (th2, fz, g);
    }
    // π/2 as the type's nearest value and its remainder (for f32 the remainder of f32's π/2)
    let hi = T::from_f64(PI_2.0);
    let lo = T::from_f64((PI_2.0 - hi.to_f64()) + PI_2.1);
    let th = hi.add_ref(&lo.sub_ref(&u0.mul_ref(&fz)));
    let f = th.div_ref(s);
    let g = one_minus_fu0_over_x(&f);
    (th.mul_ref(&th), f, g)
}

/// `e^x` for types of at most `f64` precision: for `0 < |x| < 2^-20` (the scalar part of the
/// log of a unit pose, `ln α / 2` with `α` within rounding of 1) the cubic Taylor polynomial,
/// whose first omitted term is below `2^-84` (and that of its derivative, for dual numbers,
/// below `2^-62`); else [`crate::exp_log::exp_scalar`] (exactly 1 at `x = 0`).
#[inline]
pub(crate) fn exp_fixed<T: Real>(x: &T) -> T {
    if !x.is_exact_zero() && x.to_f64().abs() < SMALL_X {
        return poly(&[1.0, 1.0, 0.5, 1.0 / 6.0], x);
    }
    crate::exp_log::exp_scalar(x)
}

/// `ln α` for types of at most `f64` precision: for `|α - 1| < 2^-20` (the norm of a unit
/// pose up to rounding) `d - d²/2 + d³/3 - d⁴/4` with `d = α - 1` (exact: Sterbenz), whose
/// first omitted term is below `2^-80` of `d`; else the type's `ln`.
#[inline]
pub(crate) fn ln_fixed<T: Real>(alpha: &T) -> T {
    let d = alpha.sub_ref(&T::one());
    if d.to_f64().abs() < SMALL_X {
        return poly(&[0.0, 1.0, -0.5, 1.0 / 3.0, -0.25], &d);
    }
    Real::ln(alpha)
}

/// `2^-20`: below it the log factors' series of [`log_factors_fixed`] is exact to `f64`.
pub(crate) const SMALL_X: f64 = 9.5367431640625e-7;

/// The power series of the exp kernel `[C, S, T]` at `u`, summed until `done(k, terms)` holds
/// after the `k`-th terms (or `MAX_TERMS`): the `Real` kernel stops at negligible terms, the
/// branch-free one ([`crate::branch_free`]) after a number of terms fixed by the type.
pub(crate) fn exp_series<T: Ring>(u: &T, mut done: impl FnMut(i64, &[T; 3]) -> bool) -> [T; 3] {
    let neg_u = u.neg_ref();
    let (mut tc, mut ts, mut tt) = (T::one(), T::one(), T::from_ratio(1, 3));
    let (mut c, mut s, mut t) = (tc.clone(), ts.clone(), tt.clone());
    for k in 1..MAX_TERMS {
        tc = tc.mul_ref(&neg_u).mul_ref(&T::from_ratio(1, (2 * k - 1) * (2 * k)));
        ts = ts.mul_ref(&neg_u).mul_ref(&T::from_ratio(1, (2 * k) * (2 * k + 1)));
        tt = tt.mul_ref(&neg_u).mul_ref(&T::from_ratio(1, (2 * k) * (2 * k + 3)));
        c.add_assign_ref(&tc);
        s.add_assign_ref(&ts);
        t.add_assign_ref(&tt);
        let terms = [tc, ts, tt];
        if done(k, &terms) {
            break;
        }
        [tc, ts, tt] = terms;
    }
    [c, s, t]
}

/// `[f, h]` with `f = asin(s)/s` and `h = (df/ds)/s` for `x = s² ≤ 1/4`: the log kernel near
/// zero rotation. `f = Σ c_k x^k`, `h = Σ_{k≥1} 2k c_k x^{k-1}` with `c_0 = 1`,
/// `c_k = c_{k-1} (2k-1)²/(2k(2k+1))`.
pub(crate) fn log_kernel<T: Real>(x: &T) -> [T; 2] {
    log_series(x, |_, f_term, h_term| negligible(f_term) && negligible(h_term))
}

/// The series of the log kernel `[f, h]` at `x`, summed until `done(k, f_term, h_term)` holds
/// after the `k`-th terms (or `MAX_TERMS`), as [`exp_series`].
pub(crate) fn log_series<T: Ring>(x: &T, mut done: impl FnMut(i64, &T, &T) -> bool) -> [T; 2] {
    let mut ck = T::one();
    let mut xk = T::one(); // x^(k-1) at the top of the loop
    let mut f = T::one();
    let mut h = T::zero();
    for k in 1..MAX_TERMS {
        ck = ck.mul_ref(&T::from_ratio((2 * k - 1) * (2 * k - 1), (2 * k) * (2 * k + 1)));
        let h_term = ck.mul_ref(&xk).mul_ref(&T::from_i64(2 * k));
        xk = xk.mul_ref(x);
        let f_term = ck.mul_ref(&xk);
        f.add_assign_ref(&f_term);
        h.add_assign_ref(&h_term);
        if done(k, &f_term, &h_term) {
            break;
        }
    }
    [f, h]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn exp_kernel_series_and_closed_form_agree_at_the_threshold() {
        for u in [0.999_999f64, 1.000_001] {
            let [c, s, t] = exp_kernel(&u);
            let th = u.sqrt();
            assert!((c - th.cos()).abs() < 1e-15);
            assert!((s - th.sin() / th).abs() < 1e-15);
            assert!((t - (th.sin() / th - th.cos()) / u).abs() < 1e-14);
        }
        assert_eq!(exp_kernel(&0.0f64), [1.0, 1.0, 1.0 / 3.0]);
    }

    #[test]
    fn log_kernel_matches_closed_form() {
        for x in [0.25f64, 0.1, 1e-3] {
            let [f, h] = log_kernel(&x);
            let s = x.sqrt();
            let th = s.asin();
            let c = th.cos();
            assert!((f - th / s).abs() < 1e-15, "{x}");
            // g = f'(θ)/sin θ = c h, closed form (s - θ c)/s³
            assert!((c * h - (s - th * c) / (s * x)).abs() < 1e-12, "{x}");
        }
        assert_eq!(log_kernel(&0.0f64), [1.0, 1.0 / 3.0]);
    }
}
