//! The finiteness policy of algebra-core's float entry points (docs/robustness.md): a NaN or
//! infinite coefficient in `exp`, `log`, `sqrt` or `inverse` is a typed error, never a
//! multivector with a NaN coefficient.

use algebra_core::{Algebra, Basis, Multivector, MvError};

#[test]
fn non_finite_coefficients_are_typed_errors() {
    let mut cases = 0;
    for alg in ["g3", "cga", "g123inf", "cga-null"] {
        let a = Algebra::builtin(alg).unwrap();
        for basis in [Basis::Blade, Basis::Product] {
            for name in ["1", "e12", "e1", "e123"] {
                for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
                    let x = Multivector::from_terms(&a, basis, [("1", 1.0), (name, bad)]).unwrap();
                    for (op, r) in [("exp", x.exp()), ("log", x.log()), ("sqrt", x.sqrt())] {
                        match r {
                            Err(MvError::Undefined { op: o, why, .. }) => {
                                assert_eq!(o, op);
                                assert_eq!(why, "coefficients are not finite", "{alg} {name} {bad} {op}");
                            }
                            other => panic!("{alg} {name} {bad} {op}: {other:?}"),
                        }
                        cases += 1;
                    }
                    // the inverse says so too (not "not invertible", which a NaN pivot would give)
                    match x.inverse() {
                        Err(MvError::Undefined { op: "inverse", why, .. }) => {
                            assert_eq!(why, "coefficients are not finite", "{alg} {name} {bad}")
                        }
                        other => panic!("{alg} {name} {bad} inverse: {other:?}"),
                    }
                    cases += 1;
                }
            }
        }
    }
    assert_eq!(cases, 4 * 2 * 4 * 3 * 4);
}

#[test]
fn finite_inputs_near_the_range_limits_stay_finite_or_are_refused() {
    // exp of a huge scalar overflows: refused, not inf; a huge rotor angle is fine (closed form)
    let g3 = Algebra::builtin("g3").unwrap();
    let big = Multivector::scalar(&g3, Basis::Blade, 1e300);
    assert!(matches!(big.exp(), Err(MvError::Undefined { .. })));
    match big.exp() {
        Err(MvError::Undefined { why, .. }) => assert_eq!(why, "the result overflows"),
        other => panic!("{other:?}"),
    }
    // a rotor angle of 1e300 (known only to about 1e284 rad) is refused, not a NaN, and not
    // called an overflow: the unit rotor cannot overflow, θ² = 1e600 does
    let b = Multivector::from_terms(&g3, Basis::Blade, [("e12", 1e300)]).unwrap();
    match b.exp() {
        Err(MvError::Undefined { op: "exp", why, .. }) => {
            assert_eq!(why, "the rotation angle is too large for this scalar (θ² overflows)")
        }
        other => panic!("{other:?}"),
    }
    // a large but meaningful angle: cos and sin from libm, as an independent reference
    let b = Multivector::from_terms(&g3, Basis::Blade, [("e12", 1000.0)]).unwrap();
    let r = b.exp().unwrap();
    assert!(r.coeffs().iter().all(|c: &f64| c.is_finite()));
    assert!((r.coeff(0).unwrap() - 1000f64.cos()).abs() < 1e-12);
    assert!((r.coeff(0b011).unwrap() - 1000f64.sin()).abs() < 1e-12);
}
