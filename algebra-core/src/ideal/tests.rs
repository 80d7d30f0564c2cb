//! Property tests of the ideal module (the sympy cross-checks are in
//! `algebra-core/tests/groebner_sympy.rs`).

use super::*;
use crate::Ring;
use proptest::prelude::*;

fn poly_from(coeffs: &[(i64, [u32; 3])]) -> Poly {
    let names = ["x", "y", "z"];
    Poly::from_terms(
        coeffs
            .iter()
            .map(|(c, e)| (Rational::from(*c), names.iter().zip(e).map(|(n, k)| (n.to_string(), *k)).collect())),
    )
}

fn arb_poly(max_terms: usize) -> impl Strategy<Value = Poly> {
    prop::collection::vec((-5i64..=5, [0u32..3, 0u32..3, 0u32..3]), 1..=max_terms).prop_map(|ts| poly_from(&ts))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    /// For random f, g and a random basis G = groebner(g_1, g_2): f*g_1 + h reduces to the
    /// normal form of h, and the normal form is unique (reducing twice changes nothing).
    #[test]
    fn multiples_of_the_ideal_reduce_away(
        f in arb_poly(3), g1 in arb_poly(3), g2 in arb_poly(3), h in arb_poly(4), lex in any::<bool>()
    ) {
        let order = if lex { MonomialOrder::Lex } else { MonomialOrder::GrevLex };
        let ring = PolyRing::new(["x", "y", "z"], order);
        let budget = Budget { time: Some(std::time::Duration::from_secs(5)), ..Budget::default() };
        let basis = match ring.groebner(&[g1.clone(), g2.clone()], &budget) {
            Ok(b) => b,
            Err(IdealError::Undecided { .. }) => return Ok(()),
            Err(e) => panic!("{e}"),
        };
        let nh = basis.normal_form(&h).unwrap();
        let lhs = f.clone() * g1.clone() + f.clone() * f.clone() * g2.clone() + h.clone();
        prop_assert_eq!(basis.normal_form(&lhs).unwrap(), nh.clone());
        prop_assert_eq!(basis.normal_form(&nh).unwrap(), nh.clone());
        prop_assert!(basis.contains(&g1).unwrap() && basis.contains(&g2).unwrap());
        // The division identity f = sum q_i g_i + r, checked by expanding.
        let d = ring.divide(&lhs, &[g1.clone(), g2.clone()], &budget).unwrap();
        let back = d.quotients[0].clone() * g1 + d.quotients[1].clone() * g2 + d.remainder;
        prop_assert_eq!(back, lhs);
    }
}

#[test]
fn budget_gives_undecided_not_a_hang() {
    let (x, y, z) = (Poly::var("x"), Poly::var("y"), Poly::var("z"));
    let gens = [
        x.pow_u32(5) + y.pow_u32(4) + z.pow_u32(3) - Poly::one(),
        x.pow_u32(3) + y.pow_u32(3) + z.pow_u32(2) - Poly::one(),
        x.clone() * y.clone() * z.clone() - Poly::from_i64(2),
    ];
    let ring = PolyRing::new(["x", "y", "z"], MonomialOrder::Lex);
    let tiny = Budget { max_basis: 3, ..Budget::default() };
    match ring.groebner(&gens, &tiny) {
        Err(IdealError::Undecided { limit: Limit::BasisSize, .. }) => {}
        other => panic!("expected undecided, got {other:?}"),
    }
    let no_time = Budget { time: Some(std::time::Duration::ZERO), ..Budget::default() };
    assert!(matches!(ring.groebner(&gens, &no_time), Err(IdealError::Undecided { limit: Limit::Time, .. })));
}

#[test]
fn unknown_variables_and_inconsistent_systems() {
    let x = Poly::var("x");
    let ring = PolyRing::new(["x"], MonomialOrder::GrevLex);
    assert_eq!(ring.groebner(&[Poly::var("w")], &Budget::default()), Err(IdealError::UnknownVariable("w".into())));
    // x = 0 and x = 1 together: the unit ideal.
    let g = ring.groebner(&[x.clone(), x - Poly::one()], &Budget::default()).unwrap();
    assert!(g.is_unit());
    assert!(g.contains(&Poly::var("x").pow_u32(7)).unwrap());
    assert!(ring.groebner(&[], &Budget::default()).unwrap().is_empty());
}

#[test]
fn rabinowitsch_needs_the_nonvanishing_hypothesis() {
    // x^2 = x y with x != 0 gives x = y; without it, x = y is not in the ideal (x = 0 is a
    // solution with any y).
    let (x, y) = (Poly::var("x"), Poly::var("y"));
    let eq = x.clone() * x.clone() - x.clone() * y.clone();
    let claim = x.clone() - y.clone();
    let with = Hypotheses { equations: vec![eq.clone()], nonzero: vec![x.clone()] };
    let d = decide(std::slice::from_ref(&claim), &with, &Budget::default()).unwrap();
    assert!(d.holds && !d.inconsistent);
    let without = Hypotheses { equations: vec![eq], nonzero: vec![] };
    let d = decide(&[claim], &without, &Budget::default()).unwrap();
    assert!(!d.holds);
    assert_eq!(d.failures.len(), 1);
    // x != 0 and x = 0: inconsistent, everything holds.
    let bad = Hypotheses { equations: vec![x.clone()], nonzero: vec![x] };
    assert!(decide(&[y], &bad, &Budget::default()).unwrap().inconsistent);
}
