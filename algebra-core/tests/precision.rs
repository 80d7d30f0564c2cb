//! The general exp / log / sqrt / inverse are correct to the requested precision: differential
//! tests against mpmath at 1100 bits (fixtures in `tests/fixtures/mpmath/`, written by
//! `make_fixtures.py` from the *matrix* functions of the left-multiplication matrix, an
//! independent computation), the f64 results within [`F64_GENERAL_BOUND`] or refused, and
//! regressions for the exp scaling bug and for tiny exact pivots.
#![cfg(feature = "rug")]

use crate::common;

use algebra_core::rational::{Q, parse_rational, ratio};
use algebra_core::{
    Algebra, Basis, F64_GENERAL_BOUND, Metric, MpFloat, Multivector, MvError, PrecisionGuard, Real, Ring,
};
use num_bigint::BigInt;
use rug::Float;
use serde_json::Value;
use std::sync::Arc;

/// The precision the tests ask for (above 1000 bits and above f64's exponent range for ε).
const BITS: u32 = 1100;

fn algebra(name: &str, squares: &[i64]) -> Arc<Algebra> {
    let labels = (1..=squares.len()).map(|i| i.to_string()).collect();
    Algebra::new(name, Metric::from_squares(labels, squares.iter().map(|&s| ratio(s, 1)).collect()).unwrap())
}

/// `max_k |got_k - want_k| <= 2^-bits · max_k |want_k|`, decided in MPFR.
fn assert_close(got: &Multivector<MpFloat>, want: &[Float], bits: u32, what: &str) {
    let scale =
        want.iter().map(|w| Float::with_val(BITS + 64, w.abs_ref())).fold(Float::new(BITS + 64), |a, b| a.max(&b));
    let mut worst = Float::new(BITS + 64);
    for (g, w) in got.coeffs().iter().zip(want) {
        let d = Float::with_val(BITS + 64, &g.0 - w).abs();
        worst = worst.max(&d);
    }
    let rel = Float::with_val(BITS + 64, &worst / &scale);
    let bound = Float::with_val(64, Float::u_exp(1, -(bits as i32)));
    assert!(rel <= bound, "{what}: relative error {} > 2^-{bits}", rel.to_f64().log2());
}

fn fixture() -> Value {
    serde_json::from_str(include_str!("../../tests/fixtures/mpmath/general.json")).unwrap()
}

fn strings(v: &Value) -> Vec<&str> {
    v.as_array().unwrap().iter().map(|s| s.as_str().unwrap()).collect()
}

#[test]
fn general_methods_match_mpmath_at_1100_bits() {
    let doc = fixture();
    let _g = PrecisionGuard::new(BITS);
    let mut counts = std::collections::BTreeMap::new();
    for (i, case) in doc["cases"].as_array().unwrap().iter().enumerate() {
        let squares: Vec<i64> = case["squares"].as_array().unwrap().iter().map(|s| s.as_i64().unwrap()).collect();
        let alg = algebra(case["algebra"].as_str().unwrap(), &squares);
        let input: Vec<Q> = strings(&case["input"]).into_iter().map(|s| parse_rational(s).unwrap()).collect();
        let op = case["op"].as_str().unwrap();
        let x =
            Multivector::from_coeffs(&alg, Basis::Blade, input.iter().map(MpFloat::from_rational).collect()).unwrap();
        let what = format!("case {i} ({op} in {})", alg.name());
        if op == "inverse" {
            let want: Vec<Q> = strings(&case["output"]).into_iter().map(|s| parse_rational(s).unwrap()).collect();
            let exact = Multivector::from_coeffs(&alg, Basis::Blade, input.clone()).unwrap().inverse().unwrap();
            assert_eq!(exact.coeffs(), &want[..], "{what}: exact");
            let want: Vec<Float> = want.iter().map(|q| MpFloat::from_rational(q).0).collect();
            assert_close(&x.inverse().unwrap(), &want, BITS - 40, &what);
        } else {
            let want: Vec<Float> = strings(&case["output"])
                .into_iter()
                .map(|s| Float::with_val(BITS + 128, Float::parse(s).unwrap()))
                .collect();
            let got = match op {
                "exp" => x.exp(),
                "log" => x.log(),
                "sqrt" => x.sqrt(),
                _ => unreachable!("{op}"),
            }
            .unwrap_or_else(|e| panic!("{what}: {e}"));
            assert!(got.coeffs().iter().all(|c| c.precision() == BITS), "{what}: rounded to the requested precision");
            assert_close(&got, &want, BITS - 4, &what);
            // f64: within the documented bound, or refused as ill-conditioned.
            let xf = x.map_coeffs(|c| c.to_f64());
            let gf = match op {
                "exp" => xf.exp(),
                "log" => xf.log(),
                _ => xf.sqrt(),
            };
            match gf {
                Ok(gf) => {
                    let scale = want.iter().map(|w| w.to_f64().abs()).fold(0.0, f64::max);
                    let err = gf.coeffs().iter().zip(&want).map(|(g, w)| (g - w.to_f64()).abs()).fold(0.0, f64::max);
                    assert!(err <= F64_GENERAL_BOUND * scale, "{what}: f64 error {err:e}");
                }
                Err(e) => assert!(e.to_string().contains("ill-conditioned"), "{what}: {e}"),
            }
        }
        *counts.entry(op).or_insert(0) += 1;
    }
    assert_eq!(counts.values().sum::<usize>(), 22, "{counts:?}");
}

/// exp(t (e12 + 2 e34)) = exp(t e12) exp(2t e34): commuting blocks, closed forms each.
fn two_plane_rotation<T: Real>(alg: &Arc<Algebra>, t: &T) -> (Multivector<T>, Multivector<T>) {
    let b =
        Multivector::from_terms(alg, Basis::Blade, [("e12", t.clone()), ("e34", t.mul_ref(&T::from_i64(2)))]).unwrap();
    let r1 = Multivector::from_terms(alg, Basis::Blade, [("1", Real::cos(t)), ("e12", Real::sin(t))]).unwrap();
    let t2 = t.mul_ref(&T::from_i64(2));
    let r2 = Multivector::from_terms(alg, Basis::Blade, [("1", Real::cos(&t2)), ("e34", Real::sin(&t2))]).unwrap();
    (b, &r1 * &r2)
}

#[test]
fn exp_of_huge_non_simple_bivector_is_a_unit_rotor_not_exp_of_a_multiple() {
    // The scaling bug: 2^-min(k, 62) but k squarings gave exp(2x)..exp(32x) past 1.15e18.
    let alg = algebra("g4", &[1, 1, 1, 1]);
    let _g = PrecisionGuard::new(256);
    for t in [1e18, 3.5e18, 1e19, 1e25] {
        let (b, want) = two_plane_rotation(&alg, &MpFloat::from_f64(t));
        let got = b.exp().unwrap();
        let want: Vec<Float> = want.coeffs().iter().map(|c| c.0.clone()).collect();
        assert_close(&got, &want, 250, &format!("t = {t:e}"));
    }
    // f64: refused, never a coefficient like 1e222 with exit 0.
    for t in [1e18, 1e9, 1e300] {
        let (b, _) = two_plane_rotation(&alg, &t);
        let e = b.exp().unwrap_err().to_string();
        assert!(e.contains("ill-conditioned") || e.contains("overflow in the algorithm"), "{t:e}: {e}");
    }
}

#[test]
fn f64_general_exp_is_within_the_documented_bound_on_random_instances() {
    let alg = algebra("g4", &[1, 1, 1, 1]);
    let mut rng = common::Xorshift(0x9e3779b97f4a7c15);
    let mut next = || rng.unit();
    let (mut ok, mut refused) = (0, 0);
    for _ in 0..200 {
        let t = (next() - 0.5) * 10f64.powf(next() * 10.0);
        let (b, want) = two_plane_rotation(&alg, &t);
        match b.exp() {
            Ok(got) => {
                let err = got.coeffs().iter().zip(want.coeffs()).map(|(g, w)| (g - w).abs()).fold(0.0, f64::max);
                // the argument itself is only known to 1 ulp, so the angle to |t| ε.
                assert!(err <= F64_GENERAL_BOUND.max(4.0 * t.abs() * f64::EPSILON), "t {t:e}: error {err:e}");
                ok += 1;
            }
            Err(e) => {
                assert!(e.to_string().contains("ill-conditioned"), "{e}");
                assert!(t.abs() > 1e5, "refused a moderate argument {t:e}: {e}");
                refused += 1;
            }
        }
    }
    assert!(ok > 100 && refused > 10, "ok {ok}, refused {refused}");
}

#[test]
fn exact_inverse_with_pivots_below_f64_range() {
    let alg = Algebra::builtin("g3").unwrap();
    let tiny = Q::new(BigInt::from(1), BigInt::from(10).pow(400));
    let x = Multivector::from_terms(&alg, Basis::Blade, [("1", tiny.clone())]).unwrap();
    assert_eq!(x.inverse().unwrap().coeffs()[0], Q::new(BigInt::from(10).pow(400), BigInt::from(1)));
    // (ε + e12)^-1 = (ε - e12) / (ε² + 1)
    let x = Multivector::from_terms(&alg, Basis::Blade, [("1", tiny.clone()), ("e12", ratio(1, 1))]).unwrap();
    let d = &tiny * &tiny + ratio(1, 1);
    let want = Multivector::from_terms(&alg, Basis::Blade, [("1", &tiny / &d), ("e12", -ratio(1, 1) / &d)]).unwrap();
    assert_eq!(x.inverse().unwrap().coeffs(), want.coeffs());
    // MPFR too: 2^-5000 is far below f64's range but a fine pivot at 200 bits.
    let _g = PrecisionGuard::new(200);
    let tiny = MpFloat(Float::with_val(200, Float::u_exp(1, -5000)));
    let x = Multivector::from_terms(&alg, Basis::Blade, [("1", tiny.clone()), ("e1", tiny)]).unwrap();
    assert!(x.inverse().is_err(), "1 + e1 is a zero divisor, scaled or not");
    let y =
        Multivector::from_terms(&alg, Basis::Blade, [("e1", MpFloat(Float::with_val(200, Float::u_exp(1, -5000))))])
            .unwrap();
    let yi = y.inverse().unwrap();
    assert_eq!(yi.coeff_by_name("e1").unwrap().0, Float::with_val(200, Float::u_exp(1, 5000)));
}

#[test]
fn non_finite_arguments_are_typed_errors() {
    let alg = algebra("g4", &[1, 1, 1, 1]);
    for bad in [f64::NAN, f64::INFINITY] {
        let x = Multivector::from_terms(&alg, Basis::Blade, [("e12", bad), ("e34", 1.0)]).unwrap();
        for r in [x.exp(), x.log(), x.sqrt()] {
            assert!(matches!(r, Err(MvError::Undefined { .. })), "{r:?}");
        }
    }
}
