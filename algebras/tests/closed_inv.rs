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

/// False for a unit `R = c + B' + W` with `c < 0` whose invariants `μ1, μ2` of `B'` are
/// close, `(μ1 - μ2)² < 10⁻⁴ s²`: near the cut between two logarithms of equal size.
fn far_from_the_cut(r: &Mv<f64>) -> bool {
    let b = r.grade(2);
    let sq = &b * &b;
    let (s, q) = (sq.scalar_part(), sq.grade(4));
    let q4 = (&q * &q).scalar_part();
    r.scalar_part() >= 0.0 || s * s - q4 >= 1e-4 * s * s
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
                #![proptest_config(ProptestConfig::with_cases(96))]

                #[test]
                fn exp_matches_the_series(c in coeffs()) {
                    let b = biv(c);
                    let reference = b.to_multivector().exp().expect("runtime exp");
                    close("exp", &b.exp().to_multivector(), &reference, 1e-12);
                    prop_assert_eq!(b.try_exp().unwrap(), b.exp());
                }

                #[test]
                fn log_inverts_exp_and_matches_the_series(c in prop::collection::vec(-0.5..0.5f64, $len)) {
                    let b = biv(c);
                    let m = b.exp();
                    close("log(exp(B))", &m.log().unwrap().to_multivector(), &b.to_multivector(), 1e-10);
                    let series = m.to_multivector().log().expect("runtime log");
                    close("log_unit", &m.log_unit().unwrap().to_multivector(), &series, 1e-10);
                }

                #[test]
                fn exp_log_of_products(c in coeffs(), d in coeffs()) {
                    let r = biv(c).exp() * biv(d).exp();
                    // away from the branch cut θ1 + θ2 = π (scalar part < 0, equal invariants),
                    // where the logarithm itself is ill-conditioned
                    prop_assume!(far_from_the_cut(&r.to_multivector()));
                    match r.log_unit() {
                        Ok(b) => close("exp(log(R))", &b.exp().to_multivector(), &r.to_multivector(), 1e-10),
                        // the exponential of a non-compact group is not onto: -exp(boost); and
                        // the runtime series (complex invariants, R^{2,2}) refuses at f64 what it
                        // cannot resolve, with the documented typed error naming mpfr:BITS
                        // (r22_product_with_an_ill_conditioned_log_is_refused pins one such input)
                        Err(e) => {
                            let e = e.to_string();
                            prop_assert!(
                                e.contains("no real logarithm") || (e.contains("ill-conditioned") && e.contains("mpfr")),
                                "{}", e
                            );
                        }
                    }
                }

                #[test]
                fn sqrt_pow_normalize(c in prop::collection::vec(-0.5..0.5f64, $len), t in -2.0..2.0f64, s in 0.1..10.0f64) {
                    let b = biv(c);
                    let m = b.exp();
                    let r = m.sqrt().unwrap();
                    close("sqrt²", &(r * r).to_multivector(), &m.to_multivector(), 1e-10);
                    let reference = (b * t).to_multivector().exp().expect("runtime exp");
                    close("pow", &m.pow(&t).unwrap().to_multivector(), &reference, 1e-10);
                    close("normalize", &m.scale(&s).normalize().unwrap().to_multivector(), &m.to_multivector(), 1e-12);
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

/// The logarithm's branch and refusals: translations invert exactly, isoclinic rotations and
/// θ1 + θ2 < π invert, θ1 + θ2 > π gives the smaller logarithm `(π - θ1, π - θ2)`, a full turn
/// and θ1 + θ2 = π are refused, and non-finite input is an error. The spacetime cases:
/// a loxodromic rotor, and `-exp(boost)` (a full turn in the dual plane: refused).
#[test]
fn log_branches_and_refusals() {
    use r4::{Bivector as B, Rotor as R};
    let t = (cga41::Bivector::<f64>::e14() + cga41::Bivector::e15()) * 0.7 - cga41::Bivector::e23() * 0.0;
    assert_eq!(t.exp().log().unwrap(), t);
    for (a, b) in [(0.5, 0.5), (1.5, 1.5), (2.0, 0.5), (0.3, 2.8), (1e-9, 2.0)] {
        let x = B::<f64>::e12() * a + B::e34() * b;
        close("log(exp)", &x.exp().log_unit().unwrap().to_multivector(), &x.to_multivector(), 1e-12);
    }
    // θ1 + θ2 = 4 > π: the other logarithm, angles π - 2.5 and π - 1.5 with reversed planes
    let x = B::<f64>::e12() * 2.5 + B::e34() * 1.5;
    let l = x.exp().log_unit().unwrap();
    let pi = std::f64::consts::PI;
    assert!((l.e12 + (pi - 2.5)).abs() < 1e-12 && (l.e34 + (pi - 1.5)).abs() < 1e-12, "{l}");
    close("exp(log)", &l.exp().to_multivector(), &x.exp().to_multivector(), 1e-14);
    // refusals
    assert!((-R::<f64>::one()).log().unwrap_err().to_string().contains("full turn"));
    let cut = (B::<f64>::e12() * 1.0 + B::e34() * (pi - 1.0)).exp();
    assert!(
        cut.log_unit().is_err() || {
            let l = cut.log_unit().unwrap();
            (&l.exp().to_multivector() - &cut.to_multivector()).magnitude() < 1e-9
        }
    );
    let mut bad = R::<f64>::one();
    bad.e1234 = f64::NAN;
    for e in [bad.log().err(), bad.log_unit().err(), bad.sqrt().err(), bad.normalize().err(), bad.pow(&0.5).err()] {
        assert!(e.expect("an error").to_string().contains("not finite"));
    }
    assert!(R::<f64>::one().pow(&f64::NAN).is_err());
    assert!(R::<f64>::zero().normalize().is_err());
    // a rotor times a non-versor even element: self rev(self) has a 4-vector part
    let mut not_versor = R::<f64>::one();
    not_versor.e1234 = 0.5;
    assert!(not_versor.normalize().unwrap_err().to_string().contains("not a scalar"));
    // far from unit scale: the same normalisation and logarithm (rescaled by a power of two)
    let m = cga41::Bivector::<f64>::from_array([0.3, -0.2, 0.5, 0.1, 0.7, -0.4, 0.2, 0.6, -0.3, 0.25]).exp();
    let l = m.log_unit().unwrap();
    for s in [1e-300, 1e-200, 1e-31, 1e31, 1e200, 1e300] {
        close("normalize at scale", &m.scale(&s).normalize().unwrap().to_multivector(), &m.to_multivector(), 1e-13);
        close("log at scale", &m.scale(&s).log().unwrap().to_multivector(), &l.to_multivector(), 1e-13);
    }
    // spacetime: a loxodromic rotor and its logarithm
    let lox = sta::Bivector::<f64>::e01() * 1.3 + sta::Bivector::e23() * 0.7;
    close("sta log", &lox.exp().log().unwrap().to_multivector(), &lox.to_multivector(), 1e-13);
    let minus_boost = -(sta::Bivector::<f64>::e01() * 0.5).exp();
    // -exp(0.5 e01) = exp(0.5 e01 ± π e23): two logarithms of equal size, refused
    assert!(minus_boost.log_unit().unwrap_err().to_string().contains("full turn"));
    let rotated = (sta::Bivector::<f64>::e01() * 0.5 + sta::Bivector::e23() * 3.0).exp();
    let l = rotated.log_unit().unwrap();
    assert!((l.e01 - 0.5).abs() < 1e-13 && (l.e23 - 3.0).abs() < 1e-13, "{l}");
}

/// `exp` of every `op = exp` case of an mpmath fixture through the closed form of the module
/// named by its `algebra`, at `1e-13` of the largest coefficient; returns how many were checked.
fn check_exp_fixture(text: &str) -> usize {
    let json: serde_json::Value = serde_json::from_str(text).unwrap();
    let num = |s: &str| -> f64 {
        match s.split_once('/') {
            Some((p, q)) => p.parse::<f64>().unwrap() / q.parse::<f64>().unwrap(),
            None => s.parse().unwrap(),
        }
    };
    macro_rules! exp_by {
        ($m:ident, $b:ident, $e:ident, $input:expr) => {{
            let b = $m::$b::from_array($m::$b::<f64>::MASKS.map(|m| $input[m as usize]));
            $m::$e::<f64>::MASKS.iter().copied().zip(b.exp().iter().copied()).collect::<Vec<(u32, f64)>>()
        }};
    }
    let mut seen = 0;
    for case in json["cases"].as_array().unwrap() {
        if case.get("op").is_some_and(|op| op != "exp") {
            continue;
        }
        let input: Vec<f64> = case["input"].as_array().unwrap().iter().map(|v| num(v.as_str().unwrap())).collect();
        let output: Vec<f64> = case["output"].as_array().unwrap().iter().map(|v| num(v.as_str().unwrap())).collect();
        let got = match case["algebra"].as_str().unwrap() {
            "cga" => exp_by!(cga41, Bivector, Motor, input),
            "g4" => exp_by!(r4, Bivector, Rotor, input),
            "sta" => exp_by!(sta, Bivector, Rotor, input),
            "r31" => exp_by!(r31, Bivector, Rotor, input),
            other => panic!("unknown algebra {other}"),
        };
        let scale = output.iter().fold(1.0f64, |a, x| a.max(x.abs()));
        for (mask, x) in &got {
            let want = output[*mask as usize];
            assert!((x - want).abs() < 1e-13 * scale, "{}: blade {mask}: {x} vs {want}", case["algebra"]);
        }
        // every coefficient outside the even type is zero in the reference
        let inside: Vec<u32> = got.iter().map(|(m, _)| *m).collect();
        assert!(output.iter().enumerate().all(|(m, x)| inside.contains(&(m as u32)) || x.abs() < 1e-30));
        seen += 1;
    }
    seen
}

/// The closed-form `exp` against mpmath: the non-simple `R^4` and `R^{4,1}` bivectors of
/// `tests/fixtures/mpmath/general.json` (360 digits, `make_fixtures.py`), and
/// `invariant_exp.json` (40 digits, `invariant_exp.py`: loxodromic and random STA rotors,
/// `R^{3,1}`, isoclinic, nearly isoclinic and near-π `R^4` rotations, a CGA screw and random
/// CGA bivectors), both `expm` of the left-multiplication matrix.
#[test]
fn exp_matches_mpmath_fixtures() {
    assert_eq!(check_exp_fixture(include_str!("../../tests/fixtures/mpmath/general.json")), 5);
    assert_eq!(check_exp_fixture(include_str!("../../tests/fixtures/mpmath/invariant_exp.json")), 11);
}

/// A product of two exponentials in R^{2,2} (found by `exp_log_of_products`) whose logarithm
/// the closed form leaves to the runtime series, which refuses it at f64 as ill-conditioned:
/// a typed error that names the precision to use, never a wrong bivector. The proptest accepts
/// only "no real logarithm" as a refusal, so this input would fail it; it stays out of the
/// proptest's regression file and is pinned here instead (see the issue 12 note).
#[test]
fn r22_product_with_an_ill_conditioned_log_is_refused() {
    use r22::Bivector as B;
    let c = B::from_array([
        -0.714344340590711,
        -0.15334101545788859,
        -1.3383197584693034,
        -1.2828837952519025,
        -0.5583277472576791,
        1.3663029457807445,
    ]);
    let d = B::from_array([
        1.2647165244001444,
        0.21748469544061877,
        -0.24503560372365946,
        0.9372671053499108,
        0.3299149123117115,
        0.6991241242656856,
    ]);
    let r = c.exp() * d.exp();
    let series = r.to_multivector().log().expect_err("the runtime series refuses it too").to_string();
    let e = r.log_unit().expect_err("ill-conditioned at f64").to_string();
    assert!(e.contains("ill-conditioned") && e.contains("mpfr"), "{e}");
    assert_eq!(e, series);
}
