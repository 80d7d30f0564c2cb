//! An inlinable `f64` arctangent, [`atan2_f64`]: the angle kernel of the closed-form
//! logarithms ([`crate::closed_form::log_factors`] through [`crate::Real::fast_atan2`]).
//!
//! libm's `atan2` is an out-of-line call with its own special-case logic; on this project's
//! benchmark machine it took about half the time of a closed-form motor logarithm. This kernel
//! is straight-line arithmetic (one division, a degree-10 polynomial by Estrin's scheme, whose
//! dependency chain is 4 multiply-adds deep where Horner's is 10) behind three predictable
//! branches, so it inlines into the caller and pipelines with its other work.
//!
//! **Method.** With `(a, b)` the smaller and larger of `|y|, |x|`, `r = a / b` when
//! `a <= tan(π/8) b`, else `r = (a - b)/(a + b)` (and `π/4` is added), so `|r| <= tan(π/8)`;
//! `atan r = r + r z P(z)`, `z = r²`, with `P` a degree-10 Chebyshev fit of
//! `(atan √z - √z)/z^{3/2}` on `[0, tan²(π/8)]` (fit error 3.2e-17); the octant is restored as
//! `K + σ atan r` with `K ∈ {0, π/4, π/2, 3π/4, π}` held as two doubles.
//!
//! **Accuracy.** Within 2.33 ulp of the correctly rounded `atan2` (libm: 0.5 ulp), measured
//! by the committed script `tests/fixtures/mpmath/atan_poly.py` at 200,000 points (mpmath at
//! 200 bits); the script also emulates this kernel operation for operation, and the test
//! `algebra-core/tests/atan.rs` checks the kernel bit for bit against that emulation at the
//! script's 2,010 fixture points. Signed zeros follow IEEE `atan2`; non-finite input goes to
//! libm's `atan2`.
//!
//! ```
//! use algebra_core::scalar::atan2_f64;
//! for (y, x) in [(1.0, 2.0), (3.0, -0.5), (-0.25, -4.0), (0.0, -1.0), (1e-300, 1.0)] {
//!     let (fast, libm) = (atan2_f64(y, x), f64::atan2(y, x));
//!     assert!((fast - libm).abs() <= 3.0 * libm.abs() * f64::EPSILON, "{y} {x}");
//! }
//! assert_eq!(atan2_f64(f64::INFINITY, 1.0), std::f64::consts::FRAC_PI_2);
//! ```

/// `tan(π/8) = √2 - 1`, the reduction's break point.
const TAN_PI_8: f64 = 0.414_213_562_373_095_03;

/// The coefficients of `P`, highest degree first (from `atan_poly.py`).
const P: [f64; 11] = [
    -0.019_176_887_119_062_26,
    0.039_231_658_295_587_19,
    -0.050_854_497_379_402_6,
    0.058_581_489_128_022_1,
    -0.066_645_114_473_819_48,
    0.076_921_831_908_260_87,
    -0.090_909_045_781_239_03,
    0.111_111_110_152_563_61,
    -0.142_857_142_846_665_42,
    0.199_999_999_999_955_2,
    -0.333_333_333_333_333_3,
];

/// `π`, `π/2`, `π/4`, `3π/4` as `(hi, lo)` with `hi + lo` the value to about 2^-106.
const PI: (f64, f64) = (std::f64::consts::PI, 1.224_646_799_147_353_2e-16);
const PI_2: (f64, f64) = (std::f64::consts::FRAC_PI_2, 6.123_233_995_736_766e-17);
const PI_4: (f64, f64) = (std::f64::consts::FRAC_PI_4, 3.061_616_997_868_383e-17);
const PI_3_4: (f64, f64) = (2.356_194_490_192_345, 9.184_850_993_605_148e-17);

/// `atan2(y, x)`, the angle of `(x, y)` in `[-π, π]`, within 2.33 ulp of the correctly rounded
/// value for finite input (module docs); libm's `atan2` for infinite or NaN input.
///
/// ```
/// let t = algebra_core::scalar::atan2_f64(1.0, -1.0);
/// assert!((t - 0.75 * std::f64::consts::PI).abs() < 1e-15);
/// ```
#[inline]
pub fn atan2_f64(y: f64, x: f64) -> f64 {
    if !(y.is_finite() && x.is_finite()) {
        return y.atan2(x);
    }
    let (ay, ax) = (y.abs(), x.abs());
    let swapped = ay > ax;
    let (a, b) = if swapped { (ax, ay) } else { (ay, ax) };
    let neg_x = x.is_sign_negative();
    if b == 0.0 {
        let t = if neg_x { PI.0 } else { 0.0 };
        return t.copysign(y);
    }
    let split = a > TAN_PI_8 * b;
    let r = if split { (a - b) / (a + b) } else { a / b };
    let z = r * r;
    // P(z) by Estrin's scheme (a_i = P[10 - i]): depth 4 instead of Horner's 10, so the
    // angle's latency no longer dominates the closed-form logarithms.
    let (z2, z4) = (z * z, z * z * (z * z));
    let z8 = z4 * z4;
    let (e0, e1, e2) = (P[10] + P[9] * z, P[8] + P[7] * z, P[6] + P[5] * z);
    let (e3, e4) = (P[4] + P[3] * z, P[2] + P[1] * z);
    let (f0, f1, f2) = (e0 + e1 * z2, e2 + e3 * z2, e4 + P[0] * z2);
    let q = (f0 + f1 * z4) + f2 * z8;
    let p = r + r * (z * q);
    let (k, sign) = match (swapped, neg_x) {
        (false, false) => (if split { PI_4 } else { (0.0, 0.0) }, 1.0),
        (true, false) => (if split { PI_4 } else { PI_2 }, -1.0),
        (false, true) => (if split { PI_3_4 } else { PI }, -1.0),
        (true, true) => (if split { PI_3_4 } else { PI_2 }, 1.0),
    };
    let t = k.0 + (k.1 + sign * p);
    t.copysign(y)
}
