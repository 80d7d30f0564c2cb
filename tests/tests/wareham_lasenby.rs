//! Wareham and Lasenby, statement by statement: one test per numbered statement, each running
//! the check registered in `gam_verify::wareham_lasenby` (what is compared, over which
//! scalars, and the hypotheses found are documented there).

use gam_tests::{assert_holds, assert_registry};
use gam_verify::Paper;

const IDS: &[&str] = &[
    "wareham-lasenby/lemma-1",
    "wareham-lasenby/lemma-2",
    "wareham-lasenby/theorem-3",
    "wareham-lasenby/lemma-5",
    "wareham-lasenby/lemma-6",
    "wareham-lasenby/theorem-7",
    "wareham-lasenby/theorem-8",
    "wareham-lasenby/theorem-9",
    // symbolic-under-hypotheses (tests in tests/tests/under_hypotheses.rs)
    "wareham-lasenby/lemma-1-symbolic",
    "wareham-lasenby/theorem-8-symbolic",
];

/// Asserts that a counterexample mentioning `what` was recorded.
fn has_counterexample(out: &gam_verify::Outcome, what: &str) -> bool {
    out.notes.iter().any(|n| n.starts_with("counterexample") && n.contains(what))
}

#[test]
fn every_statement_of_the_paper_has_a_test() {
    assert_registry(Paper::WarehamLasenby, IDS).unwrap();
}

#[test]
fn lemma_1() {
    let out = assert_holds("wareham-lasenby/lemma-1");
    assert!(has_counterexample(&out, "e14"), "{:?}", out.notes);
}

#[test]
fn lemma_2() {
    assert_holds("wareham-lasenby/lemma-2");
}

#[test]
fn theorem_3() {
    assert_holds("wareham-lasenby/theorem-3");
}

#[test]
fn lemma_5() {
    assert_holds("wareham-lasenby/lemma-5");
}

#[test]
fn lemma_6() {
    assert_holds("wareham-lasenby/lemma-6");
}

#[test]
fn theorem_7() {
    assert_holds("wareham-lasenby/theorem-7");
}

#[test]
fn theorem_8() {
    let out = assert_holds("wareham-lasenby/theorem-8");
    assert!(has_counterexample(&out, "e14"), "{:?}", out.notes);
}

#[test]
fn theorem_9() {
    let out = assert_holds("wareham-lasenby/theorem-9");
    assert!(has_counterexample(&out, "pure translation"), "{:?}", out.notes);
    assert!(has_counterexample(&out, "||ab|| = π"), "{:?}", out.notes);
}
