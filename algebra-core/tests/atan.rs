//! The `f64` arctangent kernel `algebra_core::scalar::atan2_f64` (the angle of the closed-form
//! logarithms): bit for bit the operation-for-operation emulation of the committed script
//! `tests/fixtures/mpmath/atan_poly.py`, within its measured bound of the correctly rounded
//! value (mpmath at 200 bits), close to libm over every magnitude, IEEE on zeros and
//! non-finite input; `Real::fast_atan2` for `f32` and `Jet`.

use algebra_core::scalar::atan2_f64;
use algebra_core::{Jet, Real};
use proptest::prelude::*;
use serde_json::Value;

fn from_hex(v: &Value) -> f64 {
    f64::from_bits(u64::from_str_radix(v.as_str().unwrap(), 16).unwrap())
}

/// `|v - reference|` in units in the last place of the reference.
fn ulps(v: f64, reference: f64) -> f64 {
    let ulp = if reference == 0.0 { f64::from_bits(1) } else { next_up(reference.abs()) - reference.abs() };
    (v - reference).abs() / ulp
}

fn next_up(x: f64) -> f64 {
    f64::from_bits(x.to_bits() + 1)
}

#[test]
fn bit_identical_to_the_emulation_and_within_the_bound_of_mpmath() {
    let doc: Value = serde_json::from_str(include_str!("../../tests/fixtures/mpmath/atan2.json")).unwrap();
    let bound = doc["max_ulp"].as_f64().unwrap();
    assert!(bound < 2.5, "the script measured {bound} ulp");
    let cases = doc["cases"].as_array().unwrap();
    assert_eq!(cases.len(), 2010);
    let mut worst = 0.0f64;
    for case in cases {
        let [y, x, reference, emulated] = [0, 1, 2, 3].map(|i| from_hex(&case[i]));
        let got = atan2_f64(y, x);
        assert_eq!(
            got.to_bits(),
            emulated.to_bits(),
            "atan2({y:e}, {x:e}) = {got:e}, the emulation gives {emulated:e}"
        );
        let e = ulps(got, reference);
        assert!(e <= bound, "atan2({y:e}, {x:e}): {e} ulp from mpmath");
        worst = worst.max(e);
    }
    // the fixture exercises the bound, it is not loose by orders of magnitude
    assert!(worst > 1.0, "worst fixture error {worst} ulp");
}

#[test]
fn ieee_values_on_axes_zeros_and_non_finite_input() {
    use std::f64::consts::{FRAC_PI_2, FRAC_PI_4, PI};
    for (y, x, want) in [
        (0.0, 1.0, 0.0),
        (-0.0, 1.0, -0.0),
        (0.0, -1.0, PI),
        (-0.0, -1.0, -PI),
        (0.0, 0.0, 0.0),
        (0.0, -0.0, PI),
        (-0.0, -0.0, -PI),
        (1.0, 0.0, FRAC_PI_2),
        (-1.0, 0.0, -FRAC_PI_2),
        (2.0, 2.0, FRAC_PI_4),
        (-3.0, -3.0, -0.75 * PI),
    ] {
        let got = atan2_f64(y, x);
        assert!(
            got == want && got.is_sign_negative() == want.is_sign_negative(),
            "atan2({y}, {x}) = {got}, want {want}"
        );
    }
    let inf = f64::INFINITY;
    for (y, x) in [(inf, 1.0), (1.0, -inf), (inf, inf), (-inf, -inf), (f64::NAN, 1.0), (1.0, f64::NAN)] {
        let (got, libm) = (atan2_f64(y, x), y.atan2(x));
        assert!(got.to_bits() == libm.to_bits() || (got.is_nan() && libm.is_nan()), "atan2({y}, {x})");
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(4000))]

    /// Over every magnitude and quadrant (the kernel depends on the ratio only), within 2.9 ulp
    /// of libm's (itself within 0.5 ulp of the correctly rounded value).
    #[test]
    fn close_to_libm_over_every_magnitude(
        my in -1.0f64..1.0, ey in -300i32..300, mx in -1.0f64..1.0, ex in -300i32..300,
    ) {
        let (y, x) = (my * 2f64.powi(ey), mx * 2f64.powi(ex));
        let (got, libm) = (atan2_f64(y, x), y.atan2(x));
        prop_assert!(ulps(got, libm) <= 2.9, "atan2({y:e}, {x:e}) = {got:e}, libm {libm:e}");
    }

    /// `f32` rounds the `f64` kernel: within one f32 ulp of libm's `f32` atan2.
    #[test]
    fn f32_fast_atan2(y in -10.0f32..10.0, x in -10.0f32..10.0) {
        let (got, libm) = (Real::fast_atan2(&y, &x), y.atan2(x));
        prop_assert!((got - libm).abs() <= libm.abs() * f32::EPSILON + f32::MIN_POSITIVE, "{y} {x}: {got} {libm}");
    }

    /// `Jet`: the same derivative part as `atan2`, the real part from the kernel.
    #[test]
    fn jet_fast_atan2(y in -3.0f64..3.0, x in -3.0f64..3.0, dy in -1.0f64..1.0, dx in -1.0f64..1.0) {
        prop_assume!(y.abs() + x.abs() > 1e-3);
        let (jy, jx) = (Jet { re: y, eps: dy }, Jet { re: x, eps: dx });
        let (fast, libm) = (jy.fast_atan2(&jx), jy.atan2(&jx));
        prop_assert_eq!(fast.eps, libm.eps);
        prop_assert_eq!(fast.re, atan2_f64(y, x));
        // the derivative against a central difference of the kernel itself
        let h = 1e-6;
        let fd = (atan2_f64(y + h * dy, x + h * dx) - atan2_f64(y - h * dy, x - h * dx)) / (2.0 * h);
        prop_assert!((fast.eps - fd).abs() < 1e-6 * (1.0 + fd.abs()) / (x * x + y * y).min(1.0), "{} {}", fast.eps, fd);
    }
}
