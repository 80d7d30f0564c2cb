//! The closed-form motor `exp`, `log`, `normalize`, `sqrt`, `pow` of `g123inf`, `pga3` and
//! `cga_null` (its `Motor` and `PoseBivector`), and the `cga` exp/log/normalize/sqrt/pow of
//! rigid motions,
//! against the runtime series (`algebra_core::Multivector::exp`/`log`, an independent
//! algorithm), over random bivectors including the small-angle series branch.

use algebra_core::Multivector as Mv;
use proptest::prelude::*;

const TOL: f64 = 1e-12;

fn close(what: &str, a: &Mv<f64>, b: &Mv<f64>, scale: f64) {
    let err = (a - b).magnitude();
    assert!(err <= TOL * scale.max(1.0), "{what}: {a} vs {b} (error {err:e})");
}

/// Bivector coefficients: rotation half-angles up to 3 (below π) or tiny (series branch).
fn coeffs() -> impl Strategy<Value = [f64; 6]> {
    prop_oneof![
        3 => prop::array::uniform6(-1.7..1.7f64),
        1 => (prop::array::uniform3(-1e-4..1e-4f64), prop::array::uniform3(-2.0..2.0f64))
            .prop_map(|(r, t)| [r[0], r[1], r[2], t[0], t[1], t[2]]),
        1 => prop::array::uniform3(-2.0..2.0f64).prop_map(|t| [0.0, 0.0, 0.0, t[0], t[1], t[2]]),
    ]
}

macro_rules! closed_form_tests {
    ($m:ident, $b:ident, $ps:ident, [$i1:ident, $i2:ident, $i3:ident]) => {
        mod $m {
            use super::*;
            use gam_algebras::$m::{$b as Bivector, Motor};

            fn bivector(c: [f64; 6]) -> Bivector<f64> {
                let mut b = Bivector::zero();
                (b.e12, b.e13, b.e23, b.$i1, b.$i2, b.$i3) = (c[0], c[1], c[2], c[3], c[4], c[5]);
                b
            }

            proptest! {
                #[test]
                fn exp_matches_the_series(c in coeffs()) {
                    let b = bivector(c);
                    let m = b.exp();
                    let reference = b.to_multivector().exp().expect("runtime exp");
                    close("exp", &m.to_multivector(), &reference, b.to_multivector().magnitude());
                    // a unit motor
                    close("m rev(m) = 1", &(&m * &m.reverse()).to_multivector(), &Motor::<f64>::one().to_multivector(), 1.0);
                }

                #[test]
                fn log_inverts_exp(c in coeffs()) {
                    let b = bivector(c);
                    let back = b.exp().log().expect("log of a unit motor");
                    close("log(exp(B))", &back.to_multivector(), &b.to_multivector(), 1e3 * b.to_multivector().magnitude());
                }

                #[test]
                fn log_unit_matches_the_series_log(c in coeffs()) {
                    let b = bivector(c);
                    let m = b.exp();
                    let fast = m.log_unit().expect("log of a unit motor");
                    let reference = m.to_multivector().log().expect("runtime log");
                    close("log_unit(exp(B))", &fast.to_multivector(), &reference, 1e3 * b.to_multivector().magnitude());
                    close("log_unit = log", &fast.to_multivector(), &m.log().unwrap().to_multivector(), 1.0);
                }

                #[test]
                fn normalize_removes_a_dual_number_factor(c in coeffs(), a in 0.2..5.0f64, d in -3.0..3.0f64) {
                    let m = bivector(c).exp();
                    let mut lambda = Motor::<f64>::zero();
                    lambda.scalar = a;
                    lambda.$ps = d;
                    let scaled = &m * &lambda;
                    let n = scaled.normalize().expect("positive norm");
                    close("normalize", &n.to_multivector(), &m.to_multivector(), 1e2 * (1.0 + d.abs() / a));
                }

                #[test]
                fn sqrt_and_pow(c in coeffs(), t in -2.0..2.0f64) {
                    let b = bivector(c);
                    let m = b.exp();
                    let r = m.sqrt().expect("sqrt");
                    close("sqrt^2", &(&r * &r).to_multivector(), &m.to_multivector(), 1e2);
                    let p = m.pow(&t).expect("pow");
                    let reference = b.scale(&t).to_multivector().exp().expect("runtime exp");
                    close("pow", &p.to_multivector(), &reference, 1e3 * (1.0 + b.to_multivector().magnitude()));
                }
            }

            #[test]
            fn bad_input_is_an_error() {
                assert!(Motor::<f64>::zero().normalize().is_err());
                assert!(Motor::<f64>::zero().log().is_err());
                assert!((-Motor::<f64>::one()).log().is_err(), "a full turn");
                assert!((-Motor::<f64>::one()).log_unit().is_err(), "a full turn");
                assert_eq!(Bivector::<f64>::zero().exp(), Motor::one());
            }
        }
    };
}

closed_form_tests!(g123inf, Bivector, e123inf, [e1inf, e2inf, e3inf]);
closed_form_tests!(pga3, Bivector, e0123, [e01, e02, e03]);
closed_form_tests!(cga_null, PoseBivector, e123inf, [e1inf, e2inf, e3inf]);

/// `cga` (`R^{4,1}`, `gam_algebras::closed_form_cga`): on generators of rigid motions (the
/// closed-form path, `n = e4 + e5`) and on general bivectors (the runtime-series fallback).
mod cga {
    use super::*;
    use gam_algebras::cga::{Bivector, Motor};

    /// `Ω + t ∧ n` with `n = e4 + e5`: rotation coefficients `(e12, e13, e23)` and `t`.
    fn displacement(c: [f64; 6]) -> Bivector<f64> {
        let mut b = Bivector::zero();
        (b.e12, b.e13, b.e23) = (c[0], c[1], c[2]);
        (b.e14, b.e24, b.e34) = (c[3], c[4], c[5]);
        (b.e15, b.e25, b.e35) = (c[3], c[4], c[5]);
        b
    }

    proptest! {
        #[test]
        fn exp_of_a_rigid_motion_matches_the_series(c in coeffs()) {
            let b = displacement(c);
            prop_assert!(b.is_displacement());
            let m = b.exp().expect("finite");
            prop_assert!(m.is_displacement());
            let reference = b.to_multivector().exp().expect("runtime exp");
            close("exp", &m.to_multivector(), &reference, b.to_multivector().magnitude());
            close("m rev(m) = 1", &(m * m.reverse()).to_multivector(), &Motor::<f64>::one().to_multivector(), 1.0);
        }

        #[test]
        fn log_of_a_rigid_motion_inverts_exp_and_matches_the_series(c in coeffs()) {
            let b = displacement(c);
            let m = b.exp().expect("finite");
            let back = m.log().expect("log of a unit motor");
            close("log(exp(B))", &back.to_multivector(), &b.to_multivector(), 1e3 * b.to_multivector().magnitude());
            let reference = m.to_multivector().log().expect("runtime log");
            close("log = series log", &back.to_multivector(), &reference, 1e3 * b.to_multivector().magnitude());
            // log normalises: a scaled motor has the same logarithm
            let scaled = m.scale(&2.5).log().expect("log of a scaled motor");
            close("log(2.5 m)", &scaled.to_multivector(), &back.to_multivector(), 1e3 * b.to_multivector().magnitude());
        }

        /// Bivectors outside the displacement subalgebra (a dilation `e45`, `e_i4 ≠ e_i5`) take the
        /// runtime series and still give a unit motor whose log is the bivector.
        #[test]
        fn other_bivectors_fall_back_to_the_series(c in prop::array::uniform6(-0.6..0.6f64), d in 0.05..0.6f64, e in 0.05..0.6f64) {
            let mut b = displacement(c);
            (b.e45, b.e14) = (d, b.e14 + e);
            prop_assert!(!b.is_displacement());
            let m = b.exp().expect("finite");
            prop_assert!(!m.is_displacement());
            close("exp", &m.to_multivector(), &b.to_multivector().exp().unwrap(), b.to_multivector().magnitude());
            close("m rev(m) = 1", &(m * m.reverse()).to_multivector(), &Motor::<f64>::one().to_multivector(), 1e2);
            let back = m.log().expect("runtime log");
            close("log(exp(B))", &back.to_multivector(), &b.to_multivector(), 1e3);
        }
    }

    /// `α + β I` with `I = e1234 + e1235` (the image of g123inf's `e123inf`): central in the
    /// displacement subalgebra, so `m (α + β I)` satisfies the Study condition.
    fn dual_scalar(alpha: f64, beta: f64) -> Motor<f64> {
        let mut d = Motor::<f64>::zero();
        (d.scalar, d.e1234, d.e1235) = (alpha, beta, beta);
        d
    }

    proptest! {
        // each case runs the runtime series four times (unoptimised in tests)
        #![proptest_config(ProptestConfig::with_cases(48))]

        /// `normalize` removes a dual-number factor `α + β I` exactly (up to rounding): the
        /// unit motor comes back, against the runtime series for its norm.
        #[test]
        fn normalize_removes_a_dual_scalar_factor(c in coeffs(), alpha in 0.2..3.0f64, beta in -2.0..2.0f64) {
            let m = displacement(c).exp().expect("finite");
            let scaled = m * dual_scalar(alpha, beta);
            prop_assert!(scaled.is_displacement());
            let n = scaled.normalize().expect("positive norm");
            close("normalize(m (α + βI))", &n.to_multivector(), &m.to_multivector(), 1e2 * (1.0 + beta.abs() / alpha));
            close("n rev(n) = 1", &(n * n.reverse()).to_multivector(), &Motor::<f64>::one().to_multivector(), 1e2);
        }

        /// `log_unit`, `sqrt` and `pow` against the runtime series (`Multivector::log`/`exp`).
        #[test]
        fn log_unit_sqrt_and_pow_match_the_series(c in coeffs(), t in -2.0..2.0f64) {
            let b = displacement(c);
            let m = b.exp().expect("finite");
            let scale = 1e3 * (1.0 + b.to_multivector().magnitude());
            let series_log = m.to_multivector().log().expect("runtime log");
            close("log_unit", &m.log_unit().unwrap().to_multivector(), &series_log, scale);
            let r = m.sqrt().expect("sqrt");
            close("sqrt = exp(log/2)", &r.to_multivector(), &series_log.scale(&0.5).exp().unwrap(), scale);
            close("sqrt²", &(r * r).to_multivector(), &m.to_multivector(), scale);
            let p = m.pow(&t).expect("pow");
            close("pow = exp(t log)", &p.to_multivector(), &series_log.scale(&t).exp().unwrap(), scale * (1.0 + t.abs()));
            // on a scaled motor the same results (they act on normalize(self))
            let scaled = m * dual_scalar(1.5, 0.25);
            close("sqrt(scaled)", &scaled.sqrt().unwrap().to_multivector(), &r.to_multivector(), scale);
            close("pow(scaled)", &scaled.pow(&t).unwrap().to_multivector(), &p.to_multivector(), scale * (1.0 + t.abs()));
        }
    }

    /// The four operations equal g123inf's on the preimage (`e_i4, e_i5 ↦ e_i inf`), checked
    /// coefficient by coefficient at a fixed motor.
    #[test]
    fn operations_match_g123inf_on_the_preimage() {
        use gam_algebras::g123inf;
        let b = displacement([0.3, -0.7, 0.2, 1.5, -0.4, 0.9]);
        let m = b.exp().unwrap() * dual_scalar(2.0, 0.5);
        let g = g123inf::Motor::new(m.scalar, m.e12, m.e13, m.e23, m.e14, m.e24, m.e34, m.e1234);
        let image = |x: g123inf::Motor<f64>| {
            let mut out = Motor::<f64>::zero();
            (out.scalar, out.e12, out.e13, out.e23) = (x.scalar, x.e12, x.e13, x.e23);
            (out.e14, out.e24, out.e34, out.e15, out.e25, out.e35) =
                (x.e1inf, x.e2inf, x.e3inf, x.e1inf, x.e2inf, x.e3inf);
            (out.e1234, out.e1235) = (x.e123inf, x.e123inf);
            out
        };
        assert_eq!(m.normalize().unwrap(), image(g.normalize().unwrap()));
        assert_eq!(m.sqrt().unwrap(), image(g.sqrt().unwrap()));
        assert_eq!(m.pow(&0.3).unwrap(), image(g.pow(&0.3).unwrap()));
        let (l, lg) = (m.normalize().unwrap().log_unit().unwrap(), g.normalize().unwrap().log_unit().unwrap());
        assert_eq!((l.e12, l.e13, l.e23, l.e14, l.e15, l.e34), (lg.e12, lg.e13, lg.e23, lg.e1inf, lg.e1inf, lg.e3inf));
    }

    /// Non-rigid input (a dilation part, `e_i4 ≠ e_i5`, a four-vector outside the image) is a
    /// typed error naming the operation, as are a zero norm, a full turn and a non-finite `t`.
    #[test]
    fn non_rigid_motors_are_refused() {
        let m = displacement([0.3, 0.1, 0.0, 0.5, 0.0, 0.2]).exp().unwrap();
        let mut bad = [m; 3];
        bad[0].e45 = 0.1;
        bad[1].e14 += 0.1;
        bad[2].e2345 = 0.1;
        for x in bad {
            assert!(!x.is_displacement());
            for (op, r) in [
                ("normalize", x.normalize().map(|_| ())),
                ("log", x.log_unit().map(|_| ())),
                ("sqrt", x.sqrt().map(|_| ())),
                ("pow", x.pow(&0.5).map(|_| ())),
            ] {
                match r {
                    Err(algebra_core::MvError::Undefined { op: got, why, .. }) => {
                        assert_eq!(got, op);
                        assert!(why.starts_with("not a rigid motion"), "{why}");
                    }
                    other => panic!("{op}: {other:?}"),
                }
            }
        }
        assert!(Motor::<f64>::zero().normalize().is_err());
        assert!((-Motor::<f64>::one()).sqrt().is_err(), "a full turn");
        assert!(m.pow(&f64::NAN).is_err());
        assert!(m.pow(&f64::INFINITY).is_err());
    }

    /// Published-style exact values: a pure translation `exp(-t n / 2) = 1 - t n / 2` (the
    /// translator, no rounding), and a quarter turn `cos(π/4) + sin(π/4) e12`.
    #[test]
    fn translator_and_rotor_in_closed_form() {
        let b = displacement([0.0, 0.0, 0.0, -0.5, 0.25, -1.0]);
        let m = b.exp().unwrap();
        let mut t = Motor::<f64>::one();
        (t.e14, t.e24, t.e34, t.e15, t.e25, t.e35) = (-0.5, 0.25, -1.0, -0.5, 0.25, -1.0);
        assert_eq!(m, t);
        let r = displacement([std::f64::consts::FRAC_PI_4, 0.0, 0.0, 0.0, 0.0, 0.0]).exp().unwrap();
        assert!((r.scalar - 0.5f64.sqrt()).abs() < 4e-16 && (r.e12 - 0.5f64.sqrt()).abs() < 4e-16);
    }

    #[test]
    fn bad_input_is_an_error() {
        assert!(Motor::<f64>::zero().log().is_err());
        assert!((-Motor::<f64>::one()).log().is_err(), "a full turn");
        let mut b = Bivector::<f64>::zero();
        b.e12 = f64::NAN;
        assert!(b.exp().is_err());
        b.e45 = 1.0; // the fallback path refuses NaN too
        assert!(b.exp().is_err());
        // an even element whose logarithm is not a bivector
        let mut v = Motor::<f64>::one();
        v.e1234 = 0.5;
        assert!(v.log().is_err());
        assert_eq!(Bivector::<f64>::zero().exp().unwrap(), Motor::one());
    }
}
