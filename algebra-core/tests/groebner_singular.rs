//! Reduced Gröbner bases against Singular's (fixture: tests/fixtures/singular/groebner.json,
//! written by the committed script tests/fixtures/singular/groebner.py from Singular 4.3.1's
//! `std` under `option(redSB)`): cyclic-6, katsura-5/6, word-overflow (coefficients near 2^63:
//! the engine's machine-word reductions overflow and continue over GMP) and the papers' ideals of the benchmark
//! suite (docs/performance.md; Jüttler's Propositions 1-4 included), the systems sympy's fixture
//! is too slow for.

use algebra_core::Poly;
use algebra_core::ideal::{Budget, MonomialOrder, PolyRing};
use rug::Rational;
use serde_json::Value;
use std::time::Duration;

const FIXTURE: &str = include_str!("../../tests/fixtures/singular/groebner.json");

/// `[[coefficient, [exponents...]], ...]` over `vars`.
fn poly(vars: &[String], terms: &Value) -> Poly {
    Poly::from_terms(terms.as_array().expect("terms").iter().map(|t| {
        let c: Rational = t[0].as_str().expect("coefficient").parse().expect("rational");
        let e = t[1].as_array().expect("exponents").iter().map(|k| k.as_u64().expect("exponent") as u32);
        (c, vars.iter().cloned().zip(e).collect())
    }))
}

#[test]
fn reduced_bases_match_singular() {
    let data: Value = serde_json::from_str(FIXTURE).expect("fixture is JSON");
    let systems = data["systems"].as_array().expect("systems");
    let names: Vec<&str> = systems.iter().map(|s| s["name"].as_str().unwrap()).collect();
    for expected in [
        "cyclic-6",
        "katsura-5",
        "katsura-6",
        "word-overflow",
        "docs-example",
        "lemma-2.2",
        "lemma-3.4",
        "study-3",
        "juttler-1",
        "juttler-2",
        "juttler-3",
        "juttler-4",
    ] {
        assert!(names.contains(&expected), "{expected} missing from the fixture");
    }
    // Debug builds on a shared machine: a generous clock, the other limits as by default.
    let budget = Budget { time: Some(Duration::from_secs(300)), ..Budget::default() };
    for s in systems {
        let name = s["name"].as_str().unwrap();
        assert_eq!(s["order"], "grevlex");
        let vars: Vec<String> =
            s["variables"].as_array().unwrap().iter().map(|v| v.as_str().unwrap().to_string()).collect();
        let ring = PolyRing::new(&vars, MonomialOrder::GrevLex);
        let gens: Vec<Poly> = s["generators"].as_array().unwrap().iter().map(|g| poly(&vars, g)).collect();
        let basis = ring.groebner(&gens, &budget).unwrap();
        // Both bases are reduced and monic, so they agree as sets; Singular lists its elements
        // in its own order.
        let mut ours: Vec<String> = basis.polys().iter().map(Poly::to_string).collect();
        let mut theirs: Vec<String> =
            s["basis"].as_array().unwrap().iter().map(|g| poly(&vars, g).to_string()).collect();
        ours.sort();
        theirs.sort();
        assert_eq!(ours.len(), theirs.len(), "{name}: basis size");
        assert_eq!(ours, theirs, "{name}: reduced basis");
    }
}
