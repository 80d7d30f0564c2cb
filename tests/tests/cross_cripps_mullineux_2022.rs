//! Cross, Cripps and Mullineux (2022): the statements the exact engine can check so far.
//! (The motion-layer statements join this file with the motion issue.)

use algebra_core::{Algebra, Basis, Multivector, Poly, Ring};
use gam_tests::{eq5, eq6, eq7, eq8, eq9_vector_part, symbolic_s};

fn expected(alg: &std::sync::Arc<Algebra>, terms: Vec<(&str, Poly)>) -> Multivector<Poly> {
    Multivector::from_terms(alg, Basis::Product, terms.iter().map(|(n, p)| (*n, p.clone()))).unwrap()
}

/// Eq. (5), exactly, for a fully symbolic S, in both bases of G_{0123inf} and in G_{123inf}.
#[test]
fn eq_5_rev_s_s_is_a_pseudoscalar() {
    for alg in ["cga-null", "g123inf"].map(|a| Algebra::builtin(a).unwrap()) {
        for basis in Basis::ALL {
            let s = symbolic_s(&alg, basis);
            assert_eq!(&s.reverse() * &s, expected(&alg, eq5()), "{} {basis}", alg.name());
        }
    }
}

/// Eqs. (6)-(8): rev(S) e_i S for i = 1, 2, 3, exactly.
#[test]
fn eqs_6_7_8_sandwich_of_e1_e2_e3() {
    let alg = Algebra::builtin("cga-null").unwrap();
    for basis in Basis::ALL {
        let s = symbolic_s(&alg, basis);
        for (x, eq) in [("e1", eq6()), ("e2", eq7()), ("e3", eq8())] {
            let x = Multivector::<Poly>::basis_element(&alg, basis, x).unwrap();
            assert_eq!(s.sandwich(&x), expected(&alg, eq), "{basis}");
        }
    }
}

/// Eq. (9) and Lemma 2.2(i): rev(S) e0 S = v + λσ with v as printed and σ = -e123 + e0123inf
/// in the product basis.
#[test]
fn eq_9_and_lemma_2_2_i_sandwich_of_e0() {
    let alg = Algebra::builtin("cga-null").unwrap();
    let s = symbolic_s(&alg, Basis::Product);
    let e0 = Multivector::<Poly>::basis_element(&alg, Basis::Product, "e0").unwrap();
    let y = s.sandwich(&e0);
    let v = expected(&alg, eq9_vector_part());
    assert_eq!(y.basis_grade(1), v);
    let rest = &y - &v;
    let lambda = rest.coeff_by_name("e0123inf").unwrap().clone();
    assert!(!lambda.is_exact_zero(), "λ is a non-trivial polynomial here");
    let sigma = expected(&alg, vec![("e123", Poly::from_i64(-1)), ("e0123inf", Poly::one())]);
    assert_eq!(rest, sigma.scale(&lambda));
}

/// Lemma 2.2(iii): σ = e0 · ω = -e123 + e0123inf commutes with every element, so the paper's
/// "outer product" σ ∧ x = (σx - xσ)/2 (its Sec. 2 definition: our commutator product)
/// vanishes for every x. The paper's `·` and `∧` are our anticommutator and commutator
/// products; the true outer product σ ^ x does not vanish (σ ^ 1 = σ).
#[test]
fn lemma_2_2_iii_sigma_is_central() {
    let alg = Algebra::builtin("cga-null").unwrap();
    let e = |n: &str| Multivector::<algebra_core::rational::Q>::basis_element(&alg, Basis::Product, n).unwrap();
    let sigma_def = (&(e("e0") * e("e123inf")) + &(e("e123inf") * e("e0"))).scale(&algebra_core::rational::ratio(1, 2));
    assert_eq!(e("e0").anticommutator(&e("e123inf")), sigma_def);
    assert_eq!(sigma_def, &e("e0123inf") - &e("e123"));
    assert!(!(&sigma_def ^ &e("1")).is_zero());
    for m in 0..alg.dim() as u32 {
        let x = Multivector::from_mask(&alg, Basis::Product, m);
        assert_eq!(&sigma_def * &x, &x * &sigma_def, "σ must commute with {}", alg.name_of(m));
        assert!(sigma_def.commutator(&x).is_zero(), "σ ∧ {} (paper's ∧) must vanish", alg.name_of(m));
    }
}
