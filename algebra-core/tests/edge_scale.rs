//! f64 exp, log and sqrt of multivectors far from unit scale (issue 30): the branch decisions
//! are made at unit scale, so `log(1e-200 + 1e-200 e12)` is `ln(√2·1e-200) + (π/4) e12`, not
//! the "nilpotent" `ln(1e-200) + e12` that an underflowed `B² = -1e-400 = -0` used to give.
//! References: `tests/fixtures/mpmath/edge_scale.json`, written by `edge_scale.py` from
//! mpmath's matrix logm / sqrtm / expm of the left-multiplication matrix at 300 bits (an
//! independent computation: no power-of-two rescaling, no closed form).

use algebra_core::rational::ratio;
use algebra_core::{Algebra, Basis, Metric, Multivector, MvError};
use serde_json::Value;
use std::sync::Arc;

fn algebra(name: &str, squares: &[i64]) -> Arc<Algebra> {
    let labels = (1..=squares.len()).map(|i| i.to_string()).collect();
    Algebra::new(name, Metric::from_squares(labels, squares.iter().map(|&s| ratio(s, 1)).collect()).unwrap())
}

fn mv(alg: &Arc<Algebra>, coeffs: Vec<f64>) -> Multivector<f64> {
    Multivector::from_coeffs(alg, Basis::Blade, coeffs).unwrap()
}

/// Every coefficient within `tol` of the reference, relative to the reference's largest.
fn assert_close(got: &[f64], want: &[f64], tol: f64, what: &str) {
    let scale = want.iter().fold(0.0f64, |m, w| m.max(w.abs()));
    for (k, (g, w)) in got.iter().zip(want).enumerate() {
        assert!((g - w).abs() <= tol * scale, "{what}: coefficient {k} is {g}, want {w} (scale {scale:e})");
    }
}

#[test]
fn far_from_unit_scale_matches_mpmath() {
    let doc: Value = serde_json::from_str(include_str!("../../tests/fixtures/mpmath/edge_scale.json")).unwrap();
    let cases = doc["cases"].as_array().unwrap();
    assert!(cases.len() >= 40);
    for (i, case) in cases.iter().enumerate() {
        let squares: Vec<i64> = case["squares"].as_array().unwrap().iter().map(|s| s.as_i64().unwrap()).collect();
        let alg = algebra(case["algebra"].as_str().unwrap(), &squares);
        let num = |v: &Value| -> Vec<f64> {
            v.as_array().unwrap().iter().map(|s| s.as_str().unwrap().parse::<f64>().unwrap()).collect()
        };
        let x = mv(&alg, num(&case["input"]));
        let want = num(&case["output"]);
        let op = case["op"].as_str().unwrap();
        let got = match op {
            "log" => x.log(),
            "sqrt" => x.sqrt(),
            _ => x.exp(),
        };
        let what = format!("case {i}: {op}({x})");
        let got = got.unwrap_or_else(|e| panic!("{what}: {e}"));
        // the general method's f64 bound is 2^-26; the closed forms are near machine precision
        let tol = if case["algebra"] == "g4" && op != "exp" { 1e-9 } else { 1e-13 };
        assert_close(got.coeffs(), &want, tol, &what);
    }
}

#[test]
fn the_issue_reproducers() {
    let g3 = Algebra::builtin("g3").unwrap();
    let x = Multivector::from_terms(&g3, Basis::Blade, [("1", 1e-200), ("e12", 1e-200)]).unwrap();
    let l: Multivector<f64> = x.log().unwrap();
    // ln(√2 · 1e-200) = -460.1704450085291641667894 (mpmath), atan2(1, 1) = π/4
    assert!((l.coeff_by_name("1").unwrap() + 460.170_445_008_529_16).abs() < 1e-12, "{l}");
    assert!((l.coeff_by_name("e12").unwrap() - std::f64::consts::FRAC_PI_4).abs() < 1e-15, "{l}");
    // 1e-200 (1 + e1) is a zero divisor ((1 + e1)(1 - e1) = 0): no real logarithm, at any scale
    for c in [1e-200, 1.0, 1e200] {
        let z = Multivector::from_terms(&g3, Basis::Blade, [("1", c), ("e1", c)]).unwrap();
        assert!(matches!(z.log(), Err(MvError::Undefined { .. })), "log({z}) must be refused");
    }
}

#[test]
fn scaling_by_a_power_of_two_commutes_with_log_and_sqrt() {
    // log(2^k x) = log x + k ln 2 and sqrt(4^k x) = 2^k sqrt x, for k across the whole range
    let g3 = Algebra::builtin("g3").unwrap();
    let x =
        Multivector::from_terms(&g3, Basis::Blade, [("1", 0.6), ("e12", 0.48), ("e13", -0.64), ("e23", 0.1)]).unwrap();
    let (l, s) = (x.log().unwrap(), x.sqrt().unwrap());
    for k in [-1000, -700, -300, -200, 200, 300, 500] {
        let y = x.scale(&2f64.powi(k));
        let mut want = l.coeffs().to_vec();
        want[0] += f64::from(k) * std::f64::consts::LN_2;
        assert_close(y.log().unwrap().coeffs(), &want, 1e-14, &format!("log at 2^{k}"));
        let y = x.scale(&2f64.powi(k / 2)).scale(&2f64.powi(k - k / 2));
        let want: Vec<f64> = s.coeffs().iter().map(|c| c * 2f64.powi(k / 4) * 2f64.powi(k / 2 - k / 4)).collect();
        assert_close(y.sqrt().unwrap().coeffs(), &want, 1e-14, &format!("sqrt at 4^{}", k / 2));
    }
}

#[test]
fn near_a_half_angle_of_pi_f64_says_ill_conditioned_not_undefined() {
    // the screw exp(π(1 - 1e-9) e12 + 0.2 e03) has a logarithm (MPFR finds it); f64's repeated
    // square roots fail there, which is ill-conditioning, not "no real logarithm"
    let pga = Algebra::builtin("pga3").unwrap();
    let b = Multivector::from_terms(&pga, Basis::Blade, [("e12", std::f64::consts::PI * (1.0 - 1e-9)), ("e03", 0.2)])
        .unwrap();
    let e = b.exp().unwrap().log().unwrap_err().to_string();
    assert!(e.contains("is ill-conditioned") && !e.contains("not defined"), "{e}");
}
