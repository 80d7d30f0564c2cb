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
    "juttler/proposition-1",
    "juttler/proposition-2",
    "juttler/proposition-3",
    "juttler/proposition-4",
    "juttler/result-5",
    "juttler/theorem-6",
    "juttler/theorem-6-converse",
    // symbolic-under-hypotheses (tests in tests/tests/under_hypotheses.rs)
    "juttler/eq-9-symbolic",
    "juttler/proposition-1-symbolic",
    "juttler/proposition-2-symbolic",
    "juttler/proposition-3-symbolic",
    "juttler/proposition-4-symbolic",
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

#[test]
fn proposition_1() {
    // every comparison ran (no early return on a failed construction)
    assert_eq!(assert_holds("juttler/proposition-1").checks, 8);
}

#[test]
fn proposition_2() {
    // every comparison ran (no early return on a failed construction)
    assert_eq!(assert_holds("juttler/proposition-2").checks, 11);
}

#[test]
fn proposition_3() {
    let out = assert_holds("juttler/proposition-3");
    assert_eq!(out.checks, 14);
    assert!(out.notes.iter().any(|n| n.starts_with("counterexample") && n.contains("rank 1")), "{:?}", out.notes);
}

#[test]
fn proposition_4() {
    // every comparison ran (no early return on a failed construction)
    assert_eq!(assert_holds("juttler/proposition-4").checks, 5);
}

#[test]
fn result_5() {
    let out = assert_holds("juttler/result-5");
    // 17 for m = 4 and two positions, 40 for the splits of m = 2..6 on two position sets
    assert_eq!(out.checks, 57);
    assert!(out.notes.iter().any(|n| n.contains("l1 = l2 is even")), "{:?}", out.notes);
    assert!(
        out.notes.iter().any(|n| n.starts_with("counterexample") && n.contains("two positions")),
        "{:?}",
        out.notes
    );
}

#[test]
fn theorem_6() {
    // every comparison ran (no early return on a failed construction)
    assert_eq!(assert_holds("juttler/theorem-6").checks, 10);
}

#[test]
fn theorem_6_converse() {
    // 3 construction-independent checks, then 12 per rational motion for all seven (no early
    // return: every motion reached R = ξ M)
    let out = assert_holds("juttler/theorem-6-converse");
    assert_eq!(out.checks, 3 + 7 * 12 + 1);
    assert!(out.notes.iter().any(|n| n.starts_with("counterexample") && n.contains("mirrored")), "{:?}", out.notes);
    assert!(out.notes.iter().any(|n| n.contains("(36)") && n.contains("n = 3, k = 1")), "{:?}", out.notes);
}
