//! Closed forms emitted for user-declared algebras (`algebra_codegen::closed`): detected from
//! the tables, checked against the runtime series (`Multivector::exp`, an independent
//! algorithm) in every family — scalar squares (2D PGA at f32 and f64, 3D rotors, a boost,
//! a mixed-signature algebra) and dual-number squares (3D PGA in a user orientation, a copy of
//! `G_{123inf}`) — plus the edge cases. The 4D and 5D algebras (STA, CGA) are in
//! `tests/closed_inv.rs`.

use algebra_core::Multivector as Mv;
use algebra_macros::algebra;
use proptest::prelude::*;

#[path = "user/pga2.rs"]
mod user_pga2;
use user_pga2::pga2;

algebra! {
    /// 3D Euclidean rotors.
    pub mod rot3 {
        metric builtin "g3";
        types {
            Bivector = grade 2;
            Rotor = even;
        }
    }
}

algebra! {
    /// 3D PGA with ganja's orientation on the lines and another one on the motor.
    pub mod pga_user {
        metric builtin "pga3";
        types {
            Line = [e01, e20, e03, e12, e31, e23];
            Motor = [1, e01, e02, e30, e21, e13, e23, e1023];
        }
    }
}

algebra! {
    /// A copy of the main paper's G_{123inf} (dual quaternions), declared by its metric.
    pub mod dq {
        generators { e1, e2, e3, einf }
        metric { (e1, e1) = 1, (e2, e2) = 1, (e3, e3) = 1 }
        types {
            Bivector = grade 2;
            Motor = even;
        }
    }
}

algebra! {
    /// R^{1,1}: the boost e12 squares to +1 (hyperbolic).
    pub mod boost {
        generators { e1, e2 }
        metric { (e1, e1) = 1, (e2, e2) = -1 }
        types {
            Boost = [e12];
            Spinor = even;
        }
    }
}

algebra! {
    /// R^{2,1}: e12² = -1, e13² = e23² = +1 (a run-time choice by the sign of B²).
    pub mod mixed {
        generators { e1, e2, e3 }
        metric { (e1, e1) = 1, (e2, e2) = 1, (e3, e3) = -1 }
        types {
            Bivector = grade 2;
            Spinor = even;
        }
    }
}

fn close(what: &str, a: &Mv<f64>, b: &Mv<f64>, tol: f64) {
    let err = (a - b).magnitude();
    assert!(err <= tol * b.magnitude().max(1.0), "{what}: {a} vs {b} (error {err:e})");
}

/// The family tests of one module: exp against the series, log(exp(B)) = B, log_unit against
/// the series log, sqrt squared, pow, normalize.
macro_rules! family_tests {
    ($m:ident, $b:ident, $e:ident, $len:expr, $range:expr) => {
        mod $m {
            use super::*;
            use crate::$m::{$b as B, $e as M};

            fn biv(c: Vec<f64>) -> B<f64> {
                B::from_array(<[f64; $len]>::try_from(c).expect("length"))
            }

            fn coeffs() -> impl Strategy<Value = Vec<f64>> {
                prop_oneof![
                    3 => prop::collection::vec($range, $len),
                    1 => prop::collection::vec(-1e-4..1e-4f64, $len),
                ]
            }

            proptest! {
                #[test]
                fn exp_matches_the_series(c in coeffs()) {
                    let b = biv(c);
                    let reference = b.to_multivector().exp().expect("runtime exp");
                    close("exp", &b.exp().to_multivector(), &reference, 1e-12);
                    prop_assert_eq!(b.try_exp().unwrap(), b.exp());
                }

                #[test]
                fn log_inverts_exp_and_matches_the_series(c in coeffs()) {
                    let b = biv(c);
                    let m = b.exp();
                    close("log(exp(B))", &m.log().unwrap().to_multivector(), &b.to_multivector(), 1e-10);
                    let series = m.to_multivector().log().expect("runtime log");
                    close("log_unit", &m.log_unit().unwrap().to_multivector(), &series, 1e-10);
                }

                #[test]
                fn sqrt_pow_normalize(c in coeffs(), t in -2.0..2.0f64, s in 0.1..10.0f64) {
                    let b = biv(c);
                    let m = b.exp();
                    let r = m.sqrt().unwrap();
                    close("sqrt²", &(r * r).to_multivector(), &m.to_multivector(), 1e-10);
                    let reference = (b * t).to_multivector().exp().expect("runtime exp");
                    close("pow", &m.pow(&t).unwrap().to_multivector(), &reference, 1e-10);
                    close("normalize", &m.scale(&s).normalize().unwrap().to_multivector(), &m.to_multivector(), 1e-12);
                }
            }

            proptest! {
                /// `log` takes the logarithm of a non-unit element without normalising it
                /// first: the same as `log_unit` of the normalised element, at every scale
                /// (powers of ten from 1e-300 to 1e300: the rescaled and fallback paths too)
                /// and off the unit group (every coefficient perturbed).
                #[test]
                fn log_needs_no_normalisation(
                    c in coeffs(), e in -300i32..300, p in prop::collection::vec(-0.2..0.2f64, 8), off in any::<bool>(),
                ) {
                    let mut x = biv(c).exp();
                    if off {
                        for (k, v) in x.iter_mut().enumerate() {
                            *v += p[k % 8];
                        }
                    }
                    let x = x.scale(&10f64.powi(e));
                    match (x.log(), x.normalize().and_then(|n| n.log_unit())) {
                        (Ok(a), Ok(b)) => close("log", &a.to_multivector(), &b.to_multivector(), 1e-11),
                        (Err(_), Err(_)) => {}
                        (a, b) => prop_assert!(false, "log {a:?}, log_unit(normalize) {b:?}"),
                    }
                }
            }

            #[test]
            fn edge_cases() {
                // zero: exactly one; log of one exactly zero
                assert_eq!(B::<f64>::zero().exp(), M::one());
                assert_eq!(M::<f64>::one().log().unwrap(), B::zero());
                // non-finite input is an error, never NaN
                let mut nan = B::<f64>::zero();
                nan[0] = f64::NAN;
                assert!(nan.try_exp().is_err());
                assert!(nan.exp()[0].is_nan() || nan.exp().iter().any(|x| x.is_nan()));
                let mut bad = M::<f64>::one();
                bad[1] = f64::INFINITY;
                for r in [bad.normalize().err(), bad.log().err(), bad.log_unit().err(), bad.sqrt().err(), bad.pow(&0.5).err()] {
                    assert!(r.expect("an error").to_string().contains("not finite"));
                }
                assert!(M::<f64>::one().pow(&f64::NAN).is_err());
                assert!(M::<f64>::zero().normalize().is_err());
                assert!(M::<f64>::zero().log().is_err());
                // far from unit scale: the same logarithm (rescaled by a power of two)
                let m = biv(vec![0.3; $len]).exp();
                let l = m.log_unit().unwrap();
                for s in [1e-300, 1e-200, 1e-31, 1e31, 1e200, 1e300] {
                    close("log at scale", &m.scale(&s).log().unwrap().to_multivector(), &l.to_multivector(), 1e-13);
                    close("normalize at scale", &m.scale(&s).normalize().unwrap().to_multivector(), &m.to_multivector(), 1e-13);
                }
            }
        }
    };
}

/// The proptests of every module, one submodule each.
mod family {
    use super::*;
    family_tests!(pga2, Line, Motor, 3, -3.0..3.0f64);
    family_tests!(rot3, Bivector, Rotor, 3, -1.7..1.7f64);
    family_tests!(pga_user, Line, Motor, 6, -1.7..1.7f64);
    family_tests!(dq, Bivector, Motor, 6, -1.7..1.7f64);
    family_tests!(boost, Boost, Spinor, 1, -3.0..3.0f64);
    family_tests!(mixed, Bivector, Spinor, 3, -1.0..1.0f64);
}

/// The elliptic modules: a full turn has no logarithm, a pure translation is `1 + B` exactly,
/// and angles near π still invert.
#[test]
fn full_turn_translation_and_near_pi() {
    assert!((-pga2::Motor::<f64>::one()).log().unwrap_err().to_string().contains("full turn"));
    assert!((-rot3::Rotor::<f64>::one()).log_unit().is_err());
    assert!((-pga_user::Motor::<f64>::one()).log().is_err());
    assert!((-dq::Motor::<f64>::one()).log().is_err());
    let t = pga2::Line::<f64>::e01() * 0.75 - pga2::Line::e02() * 2.0;
    let m = t.exp();
    assert_eq!((m.scalar, m.e01, m.e02, m.e12), (1.0, 0.75, -2.0, 0.0));
    assert_eq!(m.log().unwrap(), t);
    let t = pga_user::Line::<f64>::e20() * 0.5 + pga_user::Line::e03();
    assert_eq!(t.exp().log().unwrap(), t);
    for eps in [1e-3, 1e-6] {
        let b = rot3::Bivector::<f64>::e12() * (std::f64::consts::PI - eps);
        close("near pi", &b.exp().log().unwrap().to_multivector(), &b.to_multivector(), 1e-9 / eps);
        let b = pga_user::Line::<f64>::e31() * (std::f64::consts::PI - eps) + pga_user::Line::e01() * 0.5;
        close("near pi", &b.exp().log().unwrap().to_multivector(), &b.to_multivector(), 1e-9 / eps);
    }
}

/// In a user orientation the emitted signs match the canonical predefined `pga3`.
#[test]
fn user_orientation_matches_pga3() {
    use gam_algebras::pga3;
    // the user's Line stores its fields as declared (e01 e20 e03 e12 e31 e23), pga3's grade 2
    // in the canonical order (e01 e02 e12 e03 e13 e23)
    let l = pga_user::Line::<f64>::new(0.3, -0.2, 0.7, 0.4, -0.9, 0.25);
    let b = pga3::Bivector::new(0.3, 0.2, 0.4, 0.7, 0.9, 0.25);
    assert_eq!((l.e03, l.e12, b.e03, b.e12), (0.7, 0.4, 0.7, 0.4));
    let (m, n) = (l.exp(), b.exp());
    assert!((m.e02 - n.e02).abs() < 1e-15 && (m.e30 + n.e03).abs() < 1e-15);
    assert!((m.e21 + n.e12).abs() < 1e-15 && (m.e13 - n.e13).abs() < 1e-15 && (m.e1023 + n.e0123).abs() < 1e-15);
}

/// Hyperbolic elements: exp is cosh + sinh, -1 and a non-positive scalar part have no real
/// logarithm.
#[test]
fn hyperbolic_cases() {
    let b = boost::Boost::<f64>::new(1.5);
    let m = b.exp();
    assert!((m.scalar - 1.5f64.cosh()).abs() < 1e-15 && (m.e12 - 1.5f64.sinh()).abs() < 1e-15);
    assert!((-boost::Spinor::<f64>::one()).log().is_err());
    // a spacelike rotation and a boost in the mixed algebra take the two branches
    let r = mixed::Bivector::<f64>::e12() * 0.5;
    assert!((r.exp().scalar - 0.5f64.cos()).abs() < 1e-15);
    let h = mixed::Bivector::<f64>::e13() * 0.5;
    assert!((h.exp().scalar - 0.5f64.cosh()).abs() < 1e-15);
}

/// f32: the same closed forms, against the f64 results.
#[test]
fn pga2_at_f32() {
    let b32 = pga2::Line::<f32>::new(0.5, -1.25, 1.1);
    let b64 = pga2::Line::<f64>::new(0.5, -1.25, 1.1);
    let (m32, m64) = (b32.exp(), b64.exp());
    assert!(m32.iter().zip(m64.iter()).all(|(a, b)| (f64::from(*a) - b).abs() < 1e-6));
    let back = m32.log().unwrap();
    assert!(back.iter().zip(b32.iter()).all(|(a, b)| (a - b).abs() < 1e-5));
    let r = m32.sqrt().unwrap();
    assert!((r * r).iter().zip(m32.iter()).all(|(a, b)| (a - b).abs() < 1e-6));
}
