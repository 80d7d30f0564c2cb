//! Closed-form exp and log on G_{123inf}^+: round trips at the edge cases (zero rotation,
//! rotation by π, pure translation, tiny angles, large translations, rotations past π, the
//! 2π rotation) over f64 and 256-bit MPFR floats; agreement with the runtime's general
//! `Multivector::exp`/`log` (a different algorithm: scaling and squaring, Denman–Beavers);
//! derivatives from dual numbers through the same code; typed errors, never NaN.

use crate::common;

use algebra_core::{Jet, MpFloat, PrecisionGuard, Real, Ring};
use common::*;
use motion::{Even, MotionError, Pose, Pseudoscalar};
use num_dual::Dual64;
use proptest::prelude::*;
use std::f64::consts::PI;

/// A generator `σ + (φ/2)(n e123) + c einf + pω` from an axis n (normalised), a half-angle and
/// the rest.
fn generator<T: Real>(axis: [T; 3], half: T, c: [T; 3], sigma: T, p: T) -> Even<T> {
    let n2 = axis[0].mul_ref(&axis[0]) + axis[1].mul_ref(&axis[1]) + axis[2].mul_ref(&axis[2]);
    let k = if n2 > T::zero() { half.div_ref(&Real::sqrt(&n2)) } else { T::zero() };
    let a = axis.map(|x| x.mul_ref(&k));
    let [c1, c2, c3] = c;
    Even::new(sigma, a[2].clone(), a[1].neg_ref(), a[0].clone(), c1, c2, c3, p)
}

/// The f64 edge cases: (axis, half-angle θ, translation part c, σ, p).
fn edge_generators() -> Vec<(&'static str, Even<f64>)> {
    let z = [0.0; 3];
    vec![
        ("identity", generator([0.0, 0.0, 1.0], 0.0, z, 0.0, 0.0)),
        ("pure translation", generator([0.0, 0.0, 1.0], 0.0, [0.5, -1.0, 2.0], 0.0, 0.0)),
        ("non-unit pure translation", generator([0.0, 0.0, 1.0], 0.0, [0.5, -1.0, 2.0], 0.7, -0.3)),
        ("tiny angle", generator([1.0, 2.0, 3.0], 1e-9, [0.5, -1.0, 2.0], 0.0, 0.0)),
        ("tiny angle, translation along axis", generator([1.0, 2.0, 3.0], 1e-9, [1.0, 2.0, 3.0], 0.0, 0.0)),
        ("tiny angle only", generator([1.0, -2.0, 3.0], 1e-9, z, 0.0, 0.0)),
        ("generic screw", generator([1.0, 2.0, 3.0], 0.35, [0.3, 0.1, -0.4], 0.2, 0.1)),
        ("large translation", generator([0.0, 1.0, 1.0], 0.4, [1e6, -2e6, 5e5], 0.0, 0.0)),
        ("rotation by pi", generator([0.0, 0.0, 1.0], PI / 2.0, z, 0.0, 0.0)),
        ("rotation by pi with translation", generator([1.0, 1.0, 0.0], PI / 2.0, [1.0, -1.0, 3.0], 0.0, 0.0)),
        ("rotation past pi", generator([1.0, -1.0, 2.0], 2.2, [1.0, 0.5, -3.0], 0.0, 0.0)),
        ("rotation near 2 pi", generator([1.0, 0.0, 0.0], PI - 1e-6, [0.0, 0.0, 0.0], 0.0, 0.0)),
        ("rotation near 2 pi along axis", generator([1.0, 0.0, 0.0], PI - 1e-6, [2.0, 0.0, 0.0], 0.0, 0.0)),
        ("threshold s^2 = 1/4", generator([0.0, 1.0, 0.0], PI / 6.0, [1.0, 1.0, 1.0], 0.0, 0.0)),
        ("threshold u = 1", generator([0.0, 1.0, 0.0], 1.0, [1.0, 1.0, 1.0], 0.0, 0.0)),
    ]
}

fn rel(x: &Even<f64>) -> f64 {
    size(x).max(1.0)
}

#[test]
fn exp_log_round_trips_f64() {
    for (name, b) in edge_generators() {
        let s = Pose::exp(&b).unwrap();
        let l = s.log().unwrap();
        assert!(diff(&l, &b) < 1e-12 * rel(&b), "{name}: log(exp B) = {l} vs {b}");
        let back = Pose::exp(&l).unwrap();
        assert!(diff(&back, &s) < 1e-12 * rel(&s), "{name}: exp(log S)");
    }
}

#[test]
fn exp_is_r_times_t_and_pure_cases_are_exact() {
    // exp(½ v einf) = 1 + ½ v einf, log back exactly.
    let t = Pose::translation(&[1e6, -3.0, 0.25]);
    let l = t.log().unwrap();
    assert_eq!(l, Even::new(0.0, 0.0, 0.0, 0.0, 5e5, -1.5, 0.125, 0.0));
    assert_eq!(Pose::exp(&l).unwrap(), t);
    assert_eq!(Pose::<f64>::identity().log().unwrap(), Even::zero());
    assert_eq!(Pose::exp(&Even::<f64>::zero()).unwrap(), Pose::identity());
    // A screw along its axis n = (1, 2, 2)/3: exp((φ/2) n e123 + (d/2) n einf) = R T (they commute).
    for (phi, d) in [(0.7, 1), (PI, 2), (1e-9, 5), (5.0, -1), (0.0, 3)] {
        let df = d as f64;
        let b = generator([1.0, 2.0, 2.0], phi / 2.0, [df / 6.0, df / 3.0, df / 3.0], 0.0, 0.0);
        let rt = screw([1, 2, 2], phi, [d, 2 * d, 2 * d], 3);
        assert!(diff(&Pose::exp(&b).unwrap(), &rt) < 1e-15, "{phi} {d}");
    }
}

/// Rotation by exactly 2π: S = -T. exp(log S) = S with the axis chosen along the translation.
#[test]
fn two_pi_rotation_and_minus_one() {
    // -T(2, 0, 0) = -1 + c einf with c = (-1, 0, 0): axis n = c/|c| = -e1, log = π n e123 - c einf.
    let minus_t = -Pose::translation(&[2.0, 0.0, 0.0]);
    let l = minus_t.log().unwrap();
    assert!((l.e23 + PI).abs() < 1e-15 && (l.e1inf - 1.0).abs() < 1e-15, "{l}");
    assert!(diff(&Pose::exp(&l).unwrap(), &minus_t) < 1e-15);
    let minus_one = Pose::<f64>::identity().scale(&-1.0);
    let l = minus_one.log().unwrap();
    assert!((l.e12 - PI).abs() < 1e-15);
    assert!(diff(&Pose::exp(&l).unwrap(), &minus_one) < 1e-15);
    // log_shortest picks +1: the identity transform, rotation angle 0.
    assert_eq!(minus_one.log_shortest().unwrap(), Even::zero());
}

#[test]
fn log_shortest_has_rotation_angle_at_most_pi() {
    for (name, b) in edge_generators() {
        let s = Pose::exp(&b).unwrap();
        let l = s.log_shortest().unwrap();
        let half = (l.e12 * l.e12 + l.e13 * l.e13 + l.e23 * l.e23).sqrt();
        assert!(half <= PI / 2.0 + 1e-15, "{name}: {half}");
        let back = Pose::exp(&l).unwrap();
        let w = back * s.reverse();
        assert!(back.is_equivalent(&s, &(1e-14 * rel(&b))).unwrap(), "{name}: {w}");
    }
}

#[test]
fn agrees_with_runtime_multivector_exp_log() {
    for (name, b) in edge_generators() {
        if name.contains("large") || name.contains("near 2 pi") {
            continue; // the runtime's series and square-root iterations lose accuracy there
        }
        let mine = Pose::exp(&b).unwrap();
        let runtime = b.to_multivector().exp().unwrap();
        assert!(diff(&mine, &Even::project(&runtime)) < 1e-13, "{name}: exp");
        let l_runtime = runtime.log().unwrap();
        let l_mine = mine.log().unwrap();
        assert!(diff(&l_mine, &Even::project(&l_runtime)) < 1e-10, "{name}: log {l_mine} vs {l_runtime}");
    }
}

#[test]
fn agrees_with_runtime_at_256_bits() {
    let _g = PrecisionGuard::new(256);
    let m = |n: i64, d: i64| MpFloat::from_ratio(n, d);
    let b = generator([m(1, 1), m(2, 1), m(-2, 1)], m(7, 10), [m(3, 10), m(-1, 2), m(1, 5)], m(1, 10), m(-1, 3));
    let mine = Pose::exp(&b).unwrap();
    let runtime = b.to_multivector().exp().unwrap();
    assert!(diff(&mine, &Even::project(&runtime)) < 1e-70);
    let l = runtime.log().unwrap();
    assert!(diff(&mine.log().unwrap(), &Even::project(&l)) < 1e-65);
}

/// The edge cases at 256 bits, to 1e-70.
#[test]
fn exp_log_round_trips_at_256_bits() {
    let _g = PrecisionGuard::new(256);
    let m = |n: i64, d: i64| MpFloat::from_ratio(n, d);
    let pi = MpFloat::pi();
    let half_pi = pi.mul_ref(&m(1, 2));
    let tiny = MpFloat::from_f64(1e-9);
    let tinier = MpFloat::from_f64(1e-30);
    let z = || [m(0, 1), m(0, 1), m(0, 1)];
    let cases: Vec<(&str, Even<MpFloat>)> = vec![
        ("identity", generator([m(0, 1), m(0, 1), m(1, 1)], m(0, 1), z(), m(0, 1), m(0, 1))),
        (
            "pure translation",
            generator([m(0, 1), m(0, 1), m(1, 1)], m(0, 1), [m(1, 2), m(-1, 1), m(2, 1)], m(0, 1), m(0, 1)),
        ),
        (
            "tiny angle",
            generator([m(1, 1), m(2, 1), m(3, 1)], tiny.clone(), [m(1, 2), m(-1, 1), m(2, 1)], m(0, 1), m(0, 1)),
        ),
        (
            "tinier angle",
            generator([m(1, 1), m(2, 1), m(3, 1)], tinier, [m(1, 2), m(-1, 1), m(2, 1)], m(1, 3), m(1, 7)),
        ),
        (
            "generic",
            generator([m(1, 1), m(2, 1), m(3, 1)], m(7, 20), [m(3, 10), m(1, 10), m(-2, 5)], m(1, 5), m(1, 10)),
        ),
        (
            "large translation",
            generator(
                [m(0, 1), m(1, 1), m(1, 1)],
                m(2, 5),
                [m(1000000, 1), m(-2000000, 1), m(500000, 1)],
                m(0, 1),
                m(0, 1),
            ),
        ),
        ("rotation by pi", generator([m(0, 1), m(0, 1), m(1, 1)], half_pi.clone(), z(), m(0, 1), m(0, 1))),
        (
            "rotation by pi with translation",
            generator([m(1, 1), m(1, 1), m(0, 1)], half_pi, [m(1, 1), m(-1, 1), m(3, 1)], m(0, 1), m(0, 1)),
        ),
        (
            "rotation past pi",
            generator([m(1, 1), m(-1, 1), m(2, 1)], m(11, 5), [m(1, 1), m(1, 2), m(-3, 1)], m(0, 1), m(0, 1)),
        ),
        (
            "near 2 pi",
            generator([m(1, 1), m(0, 1), m(0, 1)], pi.sub_ref(&tiny), [m(2, 1), m(0, 1), m(0, 1)], m(0, 1), m(0, 1)),
        ),
    ];
    for (name, b) in cases {
        let s = Pose::exp(&b).unwrap();
        let l = s.log().unwrap();
        let scale = size(&b).max(1.0);
        assert!(diff(&l, &b) < 1e-70 * scale, "{name}: {}", diff(&l, &b));
        let back = Pose::exp(&l).unwrap();
        assert!(diff(&back, &s) < 1e-70 * size(&s).max(1.0), "{name}");
    }
}

/// d/dt exp(tB) = B exp(tB), from running exp over Dual64 and Jet (no hand-derived formula),
/// including t = 0 and pure translations, where the series keeps the derivative finite.
#[test]
fn derivative_of_exp_from_dual_numbers() {
    let bs = [
        generator([1.0, 2.0, 3.0], 0.35, [0.3, 0.1, -0.4], 0.2, 0.1),
        generator([0.0, 0.0, 1.0], 0.0, [0.5, -1.0, 2.0], 0.0, 0.0),
        generator([1.0, -1.0, 0.0], 1.4, [2.0, 0.0, 1.0], 0.0, 0.3),
    ];
    for b in &bs {
        for t0 in [0.0, 1e-9, 0.6, 2.5] {
            let expected = b * Pose::exp(&b.scale(&t0)).unwrap();
            let lift = |x: &f64| Dual64::from(*x);
            let bd = Even::new(
                lift(&b.scalar),
                lift(&b.e12),
                lift(&b.e13),
                lift(&b.e23),
                lift(&b.e1inf),
                lift(&b.e2inf),
                lift(&b.e3inf),
                lift(&b.e123inf),
            );
            let e = Pose::exp(&bd.scale(&Dual64::new(t0, 1.0))).unwrap();
            let got = Even::new(
                e.scalar.eps,
                e.e12.eps,
                e.e13.eps,
                e.e23.eps,
                e.e1inf.eps,
                e.e2inf.eps,
                e.e3inf.eps,
                e.e123inf.eps,
            );
            assert!(diff(&got, &expected) < 1e-13, "t0 {t0}: {got} vs {expected}");
            let liftj = |x: &f64| Jet::constant(*x);
            let bj = Even::new(
                liftj(&b.scalar),
                liftj(&b.e12),
                liftj(&b.e13),
                liftj(&b.e23),
                liftj(&b.e1inf),
                liftj(&b.e2inf),
                liftj(&b.e3inf),
                liftj(&b.e123inf),
            );
            let ej = Pose::exp(&bj.scale(&Jet::variable(t0))).unwrap();
            let gotj = Even::new(
                ej.scalar.eps,
                ej.e12.eps,
                ej.e13.eps,
                ej.e23.eps,
                ej.e1inf.eps,
                ej.e2inf.eps,
                ej.e3inf.eps,
                ej.e123inf.eps,
            );
            assert!(diff(&gotj, &expected) < 1e-13, "jet t0 {t0}");
        }
    }
}

/// d/dt log(exp(tB)) = B while the rotation half-angle tθ stays below π: exercises every log
/// branch (series, closed form, past π) over dual numbers.
#[test]
fn derivative_of_log_from_dual_numbers() {
    let b = generator([1.0, 2.0, 3.0], 1.0, [0.3, 0.1, -0.4], 0.0, 0.0);
    for t0 in [0.0, 1e-9, 0.3, 1.0, 2.0, 3.0] {
        let lift = |x: &f64| Dual64::from(*x);
        let bd = Even::new(
            lift(&b.scalar),
            lift(&b.e12),
            lift(&b.e13),
            lift(&b.e23),
            lift(&b.e1inf),
            lift(&b.e2inf),
            lift(&b.e3inf),
            lift(&b.e123inf),
        );
        let l = Pose::exp(&bd.scale(&Dual64::new(t0, 1.0))).unwrap().log().unwrap();
        let got = Even::new(
            l.scalar.eps,
            l.e12.eps,
            l.e13.eps,
            l.e23.eps,
            l.e1inf.eps,
            l.e2inf.eps,
            l.e3inf.eps,
            l.e123inf.eps,
        );
        assert!(diff(&got, &b) < 1e-9, "t0 {t0}: {got}");
        assert!(
            [&l.scalar, &l.e12, &l.e13, &l.e23, &l.e1inf, &l.e2inf, &l.e3inf, &l.e123inf]
                .iter()
                .all(|x| x.re.is_finite() && x.eps.is_finite())
        );
    }
}

/// Derivatives at 256 bits: Jet<MpFloat> through exp.
#[test]
fn derivative_of_exp_at_256_bits() {
    let _g = PrecisionGuard::new(256);
    let m = |n: i64, d: i64| MpFloat::from_ratio(n, d);
    let b = generator([m(1, 1), m(2, 1), m(-2, 1)], m(7, 10), [m(3, 10), m(-1, 2), m(1, 5)], m(0, 1), m(1, 3));
    let t0 = m(3, 4);
    let expected = &b * &Pose::exp(&b.scale(&t0)).unwrap();
    let j = |x: &MpFloat| Jet::constant(x.clone());
    let bj =
        Even::new(j(&b.scalar), j(&b.e12), j(&b.e13), j(&b.e23), j(&b.e1inf), j(&b.e2inf), j(&b.e3inf), j(&b.e123inf));
    let e = Pose::exp(&bj.scale(&Jet::variable(t0))).unwrap();
    let got =
        Even::new(e.scalar.eps, e.e12.eps, e.e13.eps, e.e23.eps, e.e1inf.eps, e.e2inf.eps, e.e3inf.eps, e.e123inf.eps);
    assert!(diff(&got, &expected) < 1e-70);
}

#[test]
fn singular_and_non_finite_input_are_typed_errors() {
    let sing = Pose::new(0.0, 0.0, 0.0, 0.0, 1.0, 2.0, 3.0, 4.0);
    assert!(matches!(sing.log(), Err(MotionError::Singular { .. })));
    assert!(matches!(sing.power(&0.5), Err(MotionError::Singular { .. })));
    let nan = Pose::new(f64::NAN, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
    assert!(matches!(nan.log(), Err(MotionError::NotFinite { .. })));
    assert!(matches!(Pose::exp(&nan), Err(MotionError::NotFinite { .. })));
    assert!(matches!(
        Pose::exp(&Even::new(1e4, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0)),
        Err(MotionError::NotFinite { .. })
    ));
    // A pseudoscalar multiple: log|S| is exact.
    let s = Pose::translation(&[1.0, 2.0, 3.0]).scale_pseudoscalar(&Pseudoscalar::new(3.0, 0.5));
    let l = s.log().unwrap();
    assert!((l.scalar - 3f64.ln()).abs() < 1e-15 && (l.e123inf - 0.5 / 3.0).abs() < 1e-15);
}

fn arb_generator() -> impl Strategy<Value = Even<f64>> {
    (prop::array::uniform3(-1.0f64..1.0), 0.0f64..3.1, prop::array::uniform3(-5.0f64..5.0), -1.0f64..1.0, -1.0f64..1.0)
        .prop_map(|(axis, half, c, sigma, p)| generator(axis, half, c, sigma, p))
}

proptest! {
    #[test]
    fn prop_log_exp_round_trip(b in arb_generator()) {
        let s = Pose::exp(&b).unwrap();
        let l = s.log().unwrap();
        // Ill-conditioned only near the 2π rotation (half-angle near π).
        let half = (b.e12 * b.e12 + b.e13 * b.e13 + b.e23 * b.e23).sqrt();
        prop_assert!(diff(&l, &b) < 1e-11 / (std::f64::consts::PI - half).min(1.0), "{} vs {}", l, b);
        prop_assert!(diff(&Pose::exp(&l).unwrap(), &s) < 1e-12 * size(&s).max(1.0));
    }

    #[test]
    fn prop_exp_matches_runtime(b in arb_generator()) {
        let runtime = Even::project(&b.to_multivector().exp().unwrap());
        prop_assert!(diff(&Pose::exp(&b).unwrap(), &runtime) < 1e-12 * size(&runtime).max(1.0));
    }
}
