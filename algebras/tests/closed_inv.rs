//! The invariant-decomposition closed forms (`algebra_codegen::closed_inv`) on user algebras
//! of dimension 4 and 5, checked against the runtime series (`Multivector::exp`, an
//! independent algorithm): CGA `R^{4,1}` in the diagonal and a null basis, spacetime algebra,
//! Euclidean `R^4`, `R^{3,1}`, and `R^{2,2}` (complex invariants: the series fallback).

use algebra_core::Multivector as Mv;
use algebra_macros::algebra;
use proptest::prelude::*;

#[path = "user/cga41.rs"]
mod user_cga41;
use user_cga41::cga41;

algebra! {
    /// CGA with a null pair: eo · einf = -1, eo² = einf² = 0.
    pub mod cga_null {
        generators { e1, e2, e3, eo, einf }
        metric { (e1, e1) = 1, (e2, e2) = 1, (e3, e3) = 1, (eo, einf) = -1 }
        types {
            Bivector = grade 2;
            Motor = even;
        }
    }
}

algebra! {
    /// Spacetime algebra R^{1,3}.
    pub mod sta {
        generators { e0, e1, e2, e3 }
        metric { (e0, e0) = 1, (e1, e1) = -1, (e2, e2) = -1, (e3, e3) = -1 }
        types {
            Bivector = grade 2;
            Rotor = even;
        }
    }
}

algebra! {
    /// Euclidean R^4.
    pub mod r4 {
        generators { e1, e2, e3, e4 }
        metric { (e1, e1) = 1, (e2, e2) = 1, (e3, e3) = 1, (e4, e4) = 1 }
        types {
            Bivector = grade 2;
            Rotor = even;
        }
    }
}

algebra! {
    /// R^{3,1} (mostly plus).
    pub mod r31 {
        generators { e1, e2, e3, e4 }
        metric { (e1, e1) = 1, (e2, e2) = 1, (e3, e3) = 1, (e4, e4) = -1 }
        types {
            Bivector = grade 2;
            Rotor = even;
        }
    }
}

algebra! {
    /// R^{2,2}: B² = s + q I with I² = +1 and s² < q² possible (complex invariants).
    pub mod r22 {
        generators { e1, e2, e3, e4 }
        metric { (e1, e1) = 1, (e2, e2) = 1, (e3, e3) = -1, (e4, e4) = -1 }
        types {
            Bivector = grade 2;
            Rotor = even;
        }
    }
}

fn close(what: &str, a: &Mv<f64>, b: &Mv<f64>, tol: f64) {
    let err = (a - b).magnitude();
    assert!(err <= tol * b.magnitude().max(1.0), "{what}: {a} vs {b} (error {err:e})");
}

/// The exp tests of one module: the closed form against the series.
macro_rules! exp_tests {
    ($m:ident, $b:ident, $e:ident, $len:expr, $range:expr) => {
        mod $m {
            use super::*;
            use crate::$m::$b as B;

            pub fn biv(c: Vec<f64>) -> B<f64> {
                B::from_array(<[f64; $len]>::try_from(c).expect("length"))
            }

            pub fn coeffs() -> impl Strategy<Value = Vec<f64>> {
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
            }
        }
    };
}

mod family {
    use super::*;
    exp_tests!(cga41, Bivector, Motor, 10, -1.5..1.5f64);
    exp_tests!(cga_null, Bivector, Motor, 10, -1.5..1.5f64);
    exp_tests!(sta, Bivector, Rotor, 6, -1.5..1.5f64);
    exp_tests!(r4, Bivector, Rotor, 6, -1.5..1.5f64);
    exp_tests!(r31, Bivector, Rotor, 6, -1.5..1.5f64);
    exp_tests!(r22, Bivector, Rotor, 6, -1.5..1.5f64);
}

fn series<B: Fn() -> Mv<f64>>(b: B) -> Mv<f64> {
    b().exp().expect("runtime exp")
}

/// Zero, translations and transversions (`B² = 0`: exactly `1 + B`), a dilation (`e45² = 1`),
/// a screw (`λ2 = 0`, `Q` null), in R^{4,1}.
#[test]
fn conformal_edge_cases() {
    use cga41::{Bivector as B, Motor as M};
    assert_eq!(B::<f64>::zero().exp(), M::one());
    for sign in [1.0, -1.0] {
        // e1 ∧ (e4 ± e5) and e2 ∧ (e4 ± e5): translation (+) and transversion (-)
        let t = (B::<f64>::e14() + B::e15() * sign) * 0.7 - (B::e24() + B::e25() * sign) * 0.3;
        let m = t.exp();
        let mut one_plus = M::from(&t);
        one_plus.scalar = 1.0;
        assert_eq!(m, one_plus, "exp(t) = 1 + t exactly");
        close("translation", &m.to_multivector(), &series(|| t.to_multivector()), 1e-15);
    }
    let d = B::<f64>::e45() * 0.8;
    let m = d.exp();
    assert!((m.scalar - 0.8f64.cosh()).abs() < 1e-15 && (m.e45 - 0.8f64.sinh()).abs() < 1e-15);
    let screw = B::<f64>::e12() * 1.2 + (B::e34() + B::e35()) * 0.4;
    close("screw", &screw.exp().to_multivector(), &series(|| screw.to_multivector()), 1e-14);
    // a rotation, a dilation and a transversion together
    let mixed = B::<f64>::e12() * 2.5 + B::e45() * 0.6 + (B::e34() - B::e35()) * 0.9 + B::e13() * 0.2;
    close("mixed", &mixed.exp().to_multivector(), &series(|| mixed.to_multivector()), 1e-13);
}

/// Isoclinic rotations of R^4 (`λ1 = λ2`), nearly isoclinic ones, and an angle near π.
#[test]
fn isoclinic_and_near_pi() {
    use r4::Bivector as B;
    for theta in [1e-5, 0.5, 2.0, 3.0, std::f64::consts::PI - 1e-5] {
        for eps in [0.0, 1e-12, 1e-8, 1e-4] {
            let b = B::<f64>::e12() * theta + B::e34() * (theta + eps) + B::e13() * 0.0;
            close("isoclinic", &b.exp().to_multivector(), &series(|| b.to_multivector()), 1e-13);
            let c = B::<f64>::e12() * theta - B::e34() * (theta + eps);
            let r = c.exp();
            // cos θ cos θ' and the e1234 part sin θ sin θ' (with sign -) as in the product
            let (a, b2) = (theta, theta + eps);
            assert!((r.scalar - a.cos() * b2.cos()).abs() < 1e-14, "{theta} {eps}");
            assert!((r.e1234 + a.sin() * b2.sin()).abs() < 1e-14, "{theta} {eps}");
        }
    }
    let near = B::<f64>::e12() * (std::f64::consts::PI - 1e-7) + B::e34() * 0.3;
    close("near pi", &near.exp().to_multivector(), &series(|| near.to_multivector()), 1e-13);
}

/// Spacetime algebra: rotations, boosts and loxodromic (commuting boost + rotation) bivectors.
#[test]
fn spacetime_cases() {
    use sta::Bivector as B;
    let boost = B::<f64>::e01() * 1.3;
    let m = boost.exp();
    assert!((m.scalar - 1.3f64.cosh()).abs() < 1e-15 && (m.e01 - 1.3f64.sinh()).abs() < 1e-15);
    let rot = B::<f64>::e23() * 0.7;
    let m = rot.exp();
    assert!((m.scalar - 0.7f64.cos()).abs() < 1e-15 && (m.e23 - 0.7f64.sin()).abs() < 1e-15);
    // e01 and e23 commute: exp is the product of the two, e0123 part sinh·sin
    let lox = boost + rot;
    let m = lox.exp();
    assert!((m.scalar - 1.3f64.cosh() * 0.7f64.cos()).abs() < 1e-14);
    assert!((m.e0123 - 1.3f64.sinh() * 0.7f64.sin()).abs() < 1e-14);
    let general = B::<f64>::new(0.3, -1.1, 0.4, 2.0, -0.5, 0.25);
    close("general", &general.exp().to_multivector(), &series(|| general.to_multivector()), 1e-13);
}

/// R^{2,2}: complex invariants (s = 0, Q² = 16) go to the series; real ones stay closed.
#[test]
fn complex_invariants_fall_back() {
    use r22::Bivector as B;
    let b = B::<f64>::e12() + B::e34() + B::e13() - B::e24();
    assert!(algebra_core::closed_form::invariant_exp_factors(&0.0f64, &16.0).is_none());
    assert_eq!(b.exp().to_multivector(), series(|| b.to_multivector()));
    let real = B::<f64>::e12() * 0.5 + B::e34() * 0.25;
    close("real", &real.exp().to_multivector(), &series(|| real.to_multivector()), 1e-15);
}

/// Non-finite input: `try_exp` refuses it, `exp` gives NaN; f32 agrees with f64.
#[test]
fn non_finite_and_f32() {
    let mut nan = cga41::Bivector::<f64>::zero();
    nan.e23 = f64::NAN;
    assert!(nan.try_exp().unwrap_err().to_string().contains("not finite"));
    assert!(nan.exp().iter().any(|x| x.is_nan()));
    let mut inf = sta::Bivector::<f64>::e01();
    inf.e12 = f64::INFINITY;
    assert!(inf.try_exp().is_err());
    let c = [0.3, -1.1, 0.4, 2.0, -0.5, 0.25, 0.7, -0.2, 0.9, 0.1];
    let (b32, b64) = (cga41::Bivector::<f32>::from_array(c.map(|x| x as f32)), cga41::Bivector::<f64>::from_array(c));
    assert!(b32.exp().iter().zip(b64.exp().iter()).all(|(a, b)| (f64::from(*a) - b).abs() < 1e-5));
}
