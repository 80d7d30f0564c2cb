//! Jüttler, dual-quaternion curves, statement by statement: one test per numbered statement,
//! each running the check registered in `gam_verify::juttler` (what is compared, over which
//! scalars, and the hypotheses found are documented there).

use gam_tests::{assert_holds, assert_registry};
use gam_verify::Paper;

const IDS: &[&str] = &[
    "juttler/eq-8",
    "juttler/eq-9",
    "juttler/eq-12",
    "juttler/eq-29",
    // symbolic-under-hypotheses (tests in tests/tests/under_hypotheses.rs)
    "juttler/eq-9-symbolic",
];

#[test]
fn every_statement_of_the_paper_has_a_test() {
    assert_registry(Paper::Juttler, IDS).unwrap();
}

#[test]
fn eq_8() {
    let out = assert_holds("juttler/eq-8");
    assert!(out.notes.iter().any(|n| n.starts_with("counterexample") && n.contains("factor 2")), "{:?}", out.notes);
}

#[test]
fn eq_9() {
    let out = assert_holds("juttler/eq-9");
    assert!(out.notes.iter().any(|n| n.starts_with("counterexample") && n.contains("without (8)")), "{:?}", out.notes);
}

#[test]
fn eq_12() {
    assert_holds("juttler/eq-12");
}

#[test]
fn eq_29() {
    assert_holds("juttler/eq-29");
}
