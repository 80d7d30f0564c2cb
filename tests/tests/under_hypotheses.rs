//! The statements proved symbolically under their hypotheses (`gam_verify::under_hypotheses`,
//! method `symbolic-under-hypotheses`): one test per statement, each also requiring the
//! recorded counterexample showing the hypothesis is needed.

use gam_tests::assert_holds;
use gam_verify::Method;

fn holds_and_needs_its_hypothesis(id: &str) -> gam_verify::Outcome {
    let out = assert_holds(id);
    assert_eq!(gam_verify::find(id).unwrap().method, Method::SymbolicUnderHypotheses);
    assert!(out.notes.iter().any(|n| n.starts_with("counterexample")), "{id}: {:?}", out.notes);
    out
}

#[test]
fn lemma_2_2_null() {
    holds_and_needs_its_hypothesis("cross2022/lemma-2.2-null");
}

#[test]
fn lemma_2_2_inner_product() {
    holds_and_needs_its_hypothesis("cross2022/lemma-2.2-inner-product");
    let out = assert_holds("cross2022/lemma-2.2-inner-product");
    assert!(out.notes.iter().any(|n| n.contains("S = 2 gives")), "{:?}", out.notes);
}

#[test]
fn lemma_3_4_symbolic() {
    holds_and_needs_its_hypothesis("cross2022/lemma-3.4-symbolic");
}

/// Eq. (14) and Corollary 3.3 for a symbolic non-unit pose, its derivative and a body point:
/// nine checks (the weight of the image, two claims non-trivial, in the ideal, consistent, the
/// γ part, and the counterexample without α != 0).
#[test]
fn theorem_3_2_symbolic() {
    assert_eq!(needs_each("cross2022/theorem-3.2-symbolic", &["α != 0"]).checks, 9);
}

/// The counterexample notes of `id` (each hypothesis dropped in turn must leave the claim
/// outside the ideal), checked to name every one of `dropped`.
fn needs_each(id: &str, dropped: &[&str]) -> gam_verify::Outcome {
    let out = holds_and_needs_its_hypothesis(id);
    for d in dropped {
        assert!(
            out.notes.iter().any(|n| n.starts_with("counterexample") && n.contains(&format!("without {d}:"))),
            "{id}: no counterexample without {d}: {:?}",
            out.notes
        );
    }
    out
}

#[test]
fn juttler_eq_9_symbolic() {
    needs_each("juttler/eq-9-symbolic", &["(8)", "Q0 Q~0 != 0", "Q0 Q~0 = 1"]);
}

/// Jüttler's Propositions 1-4 with symbolic data: every claim proved (seven checks each: the
/// claims non-trivial, in the ideal, the hypotheses consistent, and the counterexample), and
/// the hypothesis each one needs.
#[test]
fn juttler_propositions_symbolic() {
    for (id, dropped) in [
        ("juttler/proposition-1-symbolic", "distinct parameters"),
        ("juttler/proposition-2-symbolic", "distinct parameters"),
        ("juttler/proposition-3-symbolic", "r_0 != 0"),
        ("juttler/proposition-4-symbolic", "distinct parameters"),
    ] {
        assert_eq!(needs_each(id, &[dropped]).checks, 7, "{id}");
    }
}

#[test]
fn wareham_lasenby_lemma_1_symbolic() {
    needs_each("wareham-lasenby/lemma-1-symbolic", &["P n = n P", "P² = -1", "t · n = 0"]);
}

#[test]
fn wareham_lasenby_theorem_8_symbolic() {
    needs_each("wareham-lasenby/theorem-8-symbolic", &["P n = n P", "P² = -1", "c² + s² = 1"]);
}

#[test]
fn angelidis_eq_14_symbolic() {
    needs_each("angelidis/eq-14-symbolic", &["ω·m = 0", "|ω|² = θ²"]);
}
