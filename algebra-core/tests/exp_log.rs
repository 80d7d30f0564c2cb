//! exp, log and sqrt of the runtime multivector against independent references: the paper's
//! rotor and translator formulas (R = cos(φ/2) + sin(φ/2) b, T = 1 + v einf / 2), the
//! composition R T of commuting factors, hyperbolic closed forms, and derivatives from dual
//! numbers; over f64 and 256-bit MPFR floats; plus the typed failures.

use algebra_core::{Algebra, Basis, Jet, MpFloat, Multivector, PrecisionGuard, Real, Ring};
use num_dual::Dual64;
use std::sync::Arc;

fn mv<T: Ring>(alg: &Arc<Algebra>, terms: &[(&str, T)]) -> Multivector<T> {
    Multivector::from_terms(alg, Basis::Blade, terms.iter().map(|(n, c)| (*n, c.clone()))).unwrap()
}

fn max_diff<T: Ring>(a: &Multivector<T>, b: &Multivector<T>) -> f64 {
    (a - b).coeffs().iter().map(Ring::magnitude).fold(0.0, f64::max)
}

/// A screw in G_{123inf}: rotation by φ about the unit axis a = (1, 2, 2)/3 and translation by
/// d along a. b = a e123 and a einf commute, so exp(φ/2 b + d/2 a einf) = R T.
fn screw<T: Real>(phi: T, d: T) -> (Multivector<T>, Multivector<T>) {
    let alg = Algebra::builtin("g123inf").unwrap();
    let a = [T::from_ratio(1, 3), T::from_ratio(2, 3), T::from_ratio(2, 3)];
    // a e123 = a1 e23 - a2 e13 + a3 e12
    let b = mv(&alg, &[("e23", a[0].clone()), ("e13", a[1].neg_ref()), ("e12", a[2].clone())]);
    let a_einf = mv(&alg, &[("e1inf", a[0].clone()), ("e2inf", a[1].clone()), ("e3inf", a[2].clone())]);
    let half = T::from_ratio(1, 2);
    let generator = &b.scale(&phi.mul_ref(&half)) + &a_einf.scale(&d.mul_ref(&half));
    let c = phi.mul_ref(&half);
    let r = &Multivector::scalar(&alg, Basis::Blade, Real::cos(&c)) + &b.scale(&Real::sin(&c));
    let t = &Multivector::scalar(&alg, Basis::Blade, T::one()) + &a_einf.scale(&d.mul_ref(&half));
    (generator, &r * &t)
}

#[test]
fn screw_exp_is_rotor_times_translator_f64() {
    for (phi, d) in [(0.7, 1.3), (3.0, -2.0), (1e-9, 5.0), (0.0, 2.5), (std::f64::consts::PI, 0.25)] {
        let (b, rt) = screw(phi, d);
        let e = b.exp().unwrap();
        assert!(max_diff(&e, &rt) < 1e-14, "phi {phi} d {d}: {e} vs {rt}");
        if phi < 3.1 {
            let l = e.log().unwrap();
            assert!(max_diff(&l, &b) < 1e-12, "log: phi {phi} d {d}: {l} vs {b}");
        }
    }
}

#[test]
fn screw_exp_and_log_at_256_bits() {
    let _g = PrecisionGuard::new(256);
    let (b, rt) = screw(MpFloat::from_ratio(7, 10), MpFloat::from_ratio(13, 10));
    let e = b.exp().unwrap();
    assert!(max_diff(&e, &rt) < 1e-72, "{}", max_diff(&e, &rt));
    let l = e.log().unwrap();
    assert!(max_diff(&l, &b) < 1e-70, "{}", max_diff(&l, &b));
}

#[test]
fn rotation_by_pi_and_pure_translation_round_trip() {
    let alg = Algebra::builtin("g123inf").unwrap();
    // rotation by π about e3: R = e12 (cos(π/2) = 0); log R = π/2 e12
    let r = mv(&alg, &[("e12", 1.0)]);
    let l = r.log().unwrap();
    assert!((l.coeff_by_name("e12").unwrap() - std::f64::consts::FRAC_PI_2).abs() < 1e-15);
    assert!(max_diff(&l.exp().unwrap(), &r) < 1e-15);
    // pure translation T = 1 + (v/2) einf: log T = (v/2) einf exactly
    let t = mv(&alg, &[("1", 1.0), ("e1inf", 0.5), ("e3inf", -1.5)]);
    assert_eq!(t.log().unwrap(), mv(&alg, &[("e1inf", 0.5), ("e3inf", -1.5)]));
    assert_eq!(t.log().unwrap().exp().unwrap(), t);
}

#[test]
fn boost_uses_hyperbolic_functions() {
    let alg = Algebra::builtin("cga").unwrap();
    // e45^2 = +1 in R^{4,1}: exp(x e45) = cosh x + sinh x e45
    let x = 0.8f64;
    let e = mv(&alg, &[("e45", x)]).exp().unwrap();
    assert!((e.coeff_by_name("1").unwrap() - x.cosh()).abs() < 1e-15);
    assert!((e.coeff_by_name("e45").unwrap() - x.sinh()).abs() < 1e-15);
    assert!(max_diff(&e.log().unwrap(), &mv(&alg, &[("e45", x)])) < 1e-15);
}

#[test]
fn general_series_path_agrees_with_closed_forms_in_cga() {
    // a generic bivector of R^{4,1}: B^2 is not a scalar, so exp uses scaling and squaring;
    // check exp(B) exp(-B) = 1 and log(exp(B)) = B, and sqrt(x)^2 = x.
    let alg = Algebra::builtin("cga").unwrap();
    let b = mv(&alg, &[("e12", 0.3), ("e15", 0.2), ("e34", -0.4), ("e45", 0.1), ("e23", 0.25)]);
    let e = b.exp().unwrap();
    let one = Multivector::scalar(&alg, Basis::Blade, 1.0);
    assert!(max_diff(&(&e * &(-&b).exp().unwrap()), &one) < 1e-14);
    assert!(max_diff(&e.log().unwrap(), &b) < 1e-12);
    let s = e.sqrt().unwrap();
    assert!(max_diff(&(&s * &s), &e) < 1e-13);
}

#[test]
fn derivative_of_exp_from_dual_numbers() {
    // d/dt exp(t B) = B exp(t B) for the screw generator, via Dual64 and via Jet<f64>.
    let (b, _) = screw(0.7, 1.3);
    let t0 = 0.6;
    let expected = &b * &b.scale(&t0).exp().unwrap();
    let bd = b.map_coeffs(|c| Dual64::from(*c));
    let e = bd.scale(&Dual64::new(t0, 1.0)).exp().unwrap();
    let deriv = e.map_coeffs(|c| c.eps);
    assert!(max_diff(&deriv, &expected) < 1e-13, "{deriv} vs {expected}");
    let bj = b.map_coeffs(|c| Jet::constant(*c));
    let ej = bj.scale(&Jet::variable(t0)).exp().unwrap();
    assert!(max_diff(&ej.map_coeffs(|c| c.eps), &expected) < 1e-13);
}

#[test]
fn failures_are_typed_errors_not_nan() {
    let g3 = Algebra::builtin("g3").unwrap();
    assert!(Multivector::scalar(&g3, Basis::Blade, -1.0).log().is_err());
    assert!(Multivector::scalar(&g3, Basis::Blade, 0.0).log().is_err());
    assert!(Multivector::scalar(&g3, Basis::Blade, -4.0).sqrt().is_err());
    assert!(Multivector::scalar(&g3, Basis::Blade, f64::NAN).exp().is_err());
    let null = Algebra::builtin("cga-null").unwrap();
    let e0 = Multivector::<f64>::basis_element(&null, Basis::Product, "e0").unwrap();
    assert!(e0.log().is_err(), "e0 is nilpotent: no logarithm");
    assert!(e0.inverse().is_err());
    // exp of a nilpotent element is exact: 1 + e0
    assert_eq!(e0.exp().unwrap().to_string(), "1 + e0");
}
