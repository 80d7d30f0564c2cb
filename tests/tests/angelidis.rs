//! Angelidis, hexanions, statement by statement: one test per numbered statement, each running
//! the check registered in `gam_verify::angelidis` (what is compared, over which scalars, and
//! the hypotheses found are documented there).

use gam_tests::{assert_holds, assert_registry};
use gam_verify::Paper;

const IDS: &[&str] = &[
    "angelidis/eq-14",
    "angelidis/eq-22",
    "angelidis/eq-27",
    "angelidis/eq-29",
    "angelidis/eq-30",
    "angelidis/eq-35",
    "angelidis/eq-36",
    "angelidis/eq-37",
    "angelidis/eq-38",
    "angelidis/eq-39",
    "angelidis/eq-41",
    "angelidis/sec-6",
    "angelidis/eq-60",
    // symbolic-under-hypotheses (tests in tests/tests/under_hypotheses.rs)
    "angelidis/eq-14-symbolic",
];

/// Asserts that the outcome's notes record a counterexample mentioning `needle`.
fn has_counterexample(out: &gam_verify::Outcome, needle: &str) {
    assert!(out.notes.iter().any(|n| n.starts_with("counterexample") && n.contains(needle)), "{:?}", out.notes);
}

#[test]
fn every_statement_of_the_paper_has_a_test() {
    assert_registry(Paper::Angelidis, IDS).unwrap();
}

#[test]
fn eq_14() {
    has_counterexample(&assert_holds("angelidis/eq-14"), "without ω·m = 0");
}

#[test]
fn eq_29() {
    let out = assert_holds("angelidis/eq-29");
    has_counterexample(&out, "without ω·m = 0");
    has_counterexample(&out, "at ω = 0");
}

#[test]
fn eq_30() {
    has_counterexample(&assert_holds("angelidis/eq-30"), "at ω = 0");
}

#[test]
fn eq_35() {
    has_counterexample(&assert_holds("angelidis/eq-35"), "at ω = 0");
}

#[test]
fn eq_36() {
    has_counterexample(&assert_holds("angelidis/eq-36"), "at ω = 0");
}

#[test]
fn eq_37() {
    assert_holds("angelidis/eq-37");
}

#[test]
fn eq_38() {
    assert_holds("angelidis/eq-38");
}

#[test]
fn eq_39() {
    assert_holds("angelidis/eq-39");
}

#[test]
fn eq_22() {
    assert_holds("angelidis/eq-22");
}

#[test]
fn eq_27() {
    assert_holds("angelidis/eq-27");
}

#[test]
fn eq_41() {
    has_counterexample(&assert_holds("angelidis/eq-41"), "|ω| > π");
}

#[test]
fn sec_6() {
    assert_holds("angelidis/sec-6");
}

#[test]
fn eq_60() {
    let out = assert_holds("angelidis/eq-60");
    // 6 symbolic checks for each of three axes, then 7 at 256 bits: nothing skipped
    assert_eq!(out.checks, 3 * 6 + 7);
    has_counterexample(&out, "printed (60) for every u");
    has_counterexample(&out, "starts at p");
}
