//! Conversions from runtime multivectors check the algebra: a multivector of another algebra
//! (smaller or larger, or the same size with another metric) is an `AlgebraMismatch` error,
//! never an out-of-bounds index or a silent reinterpretation of its coefficients.

use algebra_core::rational::{Q, q};
use algebra_core::{Algebra, Basis, Multivector, MvError};
use gam_algebras::{cga, g3, g123inf};

fn ones(alg: &str) -> Multivector<Q> {
    let alg = Algebra::builtin(alg).unwrap();
    let n = alg.dim();
    Multivector::from_coeffs(&alg, Basis::Blade, (1..=n as i64).map(q).collect()).unwrap()
}

#[test]
fn try_project_refuses_other_algebras() {
    // g3 (8 elements) into cga (32): `project` would index past the end
    let small = ones("g3");
    let err = cga::Vector::try_project(&small).unwrap_err();
    assert_eq!(err, MvError::AlgebraMismatch { left: "g3".into(), right: "cga".into() });
    assert!(matches!(cga::Multivector::try_from(&small), Err(MvError::AlgebraMismatch { .. })));
    // cga (32) into g3 (8): larger, refused as well
    assert!(matches!(g3::Vector::try_project(&ones("cga")), Err(MvError::AlgebraMismatch { .. })));
    // g123inf and pga3 both have 16 elements: same size, other metric, refused
    assert!(matches!(g123inf::Motor::try_project(&ones("pga3")), Err(MvError::AlgebraMismatch { .. })));
    assert!(matches!(g123inf::Motor::try_from(&ones("pga3")), Err(MvError::AlgebraMismatch { .. })));
}

#[test]
fn try_project_of_the_own_algebra_is_the_projection() {
    // blade coefficients 1..=8 of g3: e1, e2, e3 are masks 1, 2, 4 -> coefficients 2, 3, 5
    let x = ones("g3");
    assert_eq!(g3::Vector::try_project(&x).unwrap(), g3::Vector::new(q(2), q(3), q(5)));
    assert_eq!(g3::Vector::try_project(&x).unwrap(), g3::Vector::project(&x));
    // a multivector of an equal algebra built separately (not the same Arc) is accepted
    let again = Multivector::from_coeffs(&Algebra::builtin("g3").unwrap(), Basis::Blade, x.coeffs().to_vec()).unwrap();
    assert_eq!(g3::Rotor::try_project(&again).unwrap(), g3::Rotor::project(&x));
}
