//! The statements proved symbolically under their hypotheses (`gam_verify::under_hypotheses`,
//! method `symbolic-under-hypotheses`): one test per statement, each also requiring the
//! recorded counterexample showing the hypothesis is needed.

use gam_tests::assert_holds;
use gam_verify::Method;

fn holds_and_needs_its_hypothesis(id: &str) {
    let out = assert_holds(id);
    assert_eq!(gam_verify::find(id).unwrap().method, Method::SymbolicUnderHypotheses);
    assert!(out.notes.iter().any(|n| n.starts_with("counterexample")), "{id}: {:?}", out.notes);
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
