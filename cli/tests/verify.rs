//! `gam verify`: the papers' statements as a report (JSON list or text table), filtered.

use crate::common;

use common::{fails, ok};
use serde_json::Value;

fn verify_json(extra: &[&str]) -> Vec<Value> {
    let mut args = vec!["verify", "--json"];
    args.extend_from_slice(extra);
    let v: Value = serde_json::from_str(&ok(&args)).expect("valid JSON");
    v.as_array().expect("a JSON list").clone()
}

#[test]
fn json_lists_every_registered_statement_and_all_hold() {
    let list = verify_json(&[]);
    assert_eq!(list.len(), gam_verify::statements().count());
    for (entry, s) in list.iter().zip(gam_verify::statements()) {
        assert_eq!(entry["id"], s.id);
        assert_eq!(entry["paper"], s.paper.key());
        assert_eq!(entry["method"], s.method.key());
        assert_eq!(entry["holds"], true, "{entry}");
        assert!(entry["checks"].as_u64().unwrap() > 0, "{entry}");
        assert!(entry["failures"].as_array().unwrap().is_empty());
        assert!(entry["note"].is_string() && entry["statement"].is_string() && entry["time_ms"].is_number());
    }
    for paper in ["cross2022", "wareham-lasenby", "juttler", "angelidis"] {
        assert!(list.iter().any(|e| e["paper"] == paper), "no statement of {paper}");
    }
}

#[test]
fn notes_carry_the_implicit_hypotheses() {
    let list = verify_json(&["--filter", "theorem-4.5-multiplicative"]);
    assert_eq!(list.len(), 1);
    let note = list[0]["note"].as_str().unwrap();
    assert!(note.contains("counterexample"), "{note}");
}

/// `--list --json`: the selection, not run (the filters below are the same code as a run's;
/// `listing_names_what_a_run_runs` checks that the two agree).
fn listed(filter: &str) -> Vec<Value> {
    verify_json(&["--list", "--filter", filter])
}

#[test]
fn filter_selects_by_id_label_paper_or_method() {
    let ids = |f: &str| -> Vec<String> { listed(f).iter().map(|e| e["id"].as_str().unwrap().to_string()).collect() };
    assert_eq!(
        ids("lemma-2.2"),
        [
            "cross2022/lemma-2.2-i",
            "cross2022/lemma-2.2-ii",
            "cross2022/lemma-2.2-iii",
            "cross2022/lemma-2.2-null",
            "cross2022/lemma-2.2-inner-product"
        ]
    );
    assert_eq!(ids("LEMMA 2.2 (II)"), ["cross2022/lemma-2.2-ii"]);
    assert!(ids("juttler").iter().all(|id| id.starts_with("juttler/")));
    assert!(listed("symbolic").iter().all(|e| e["method"].as_str().unwrap().starts_with("symbolic")));
    let under = listed("symbolic-under-hypotheses");
    assert!(under.len() >= 3 && under.iter().all(|e| e["method"] == "symbolic-under-hypotheses"));
    let all = verify_json(&["--list"]);
    assert_eq!(all.len(), gam_verify::statements().count());
    assert_eq!(
        ids("juttler"),
        all.iter().filter(|e| e["paper"] == "juttler").map(|e| e["id"].as_str().unwrap()).collect::<Vec<_>>()
    );
}

/// The listing names exactly what a run with the same filter runs, with the same fields, and
/// its text form is a table with a count; a filter that matches nothing fails the same way.
#[test]
fn listing_names_what_a_run_runs() {
    for filter in ["lemma-2.2", "eq-1"] {
        let (list, run) = (listed(filter), verify_json(&["--filter", filter]));
        assert_eq!(list.len(), run.len(), "{filter}");
        for (l, r) in list.iter().zip(&run) {
            for key in ["id", "paper", "label", "statement", "method"] {
                assert_eq!(l[key], r[key], "{filter}: {key}");
            }
            assert!(l["hypotheses"].is_string() && l.get("holds").is_none(), "{l}");
        }
    }
    let out = ok(&["verify", "--list", "--filter", "lemma-2.2"]);
    assert!(out.lines().next().unwrap().starts_with("id "), "{out}");
    assert_eq!(out.lines().filter(|l| l.starts_with("cross2022/lemma-2.2-")).count(), 5, "{out}");
    assert_eq!(out.lines().last(), Some("5 statements"), "{out}");
    let line = fails(&["verify", "--list", "--filter", "lemma-99"], 2);
    assert!(line.contains("lemma-99"), "{line}");
}

#[test]
fn text_report_has_a_row_per_statement_and_a_summary() {
    let out = ok(&["verify", "--filter", "cross2022/eq-"]);
    let n = gam_verify::statements().filter(|s| s.id.contains("cross2022/eq-")).count();
    assert!(n >= 7);
    assert_eq!(out.lines().filter(|l| l.starts_with("cross2022/eq-") && l.contains(" yes ")).count(), n, "{out}");
    let summary = out.lines().last().unwrap();
    assert!(summary.starts_with(&format!("{n} of {n} statements hold (")) && summary.ends_with(" ms)"), "{summary}");
}

#[test]
fn a_filter_that_matches_nothing_is_a_usage_error() {
    let line = fails(&["verify", "--filter", "lemma-99"], 2);
    assert!(line.contains("lemma-99"), "{line}");
}
