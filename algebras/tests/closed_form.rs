//! The closed-form motor `exp`, `log`, `normalize`, `sqrt`, `pow` of `g123inf`, `pga3` and
//! `cga_null` (its `Motor` and `PoseBivector`)
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
