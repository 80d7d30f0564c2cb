//! `gam verify`: runs the papers' statements (the `gam-verify` registry) as a report.

use crate::error::CliError;
use crate::output::text_table;
use gam_verify::{Report, Statement};
use rayon::prelude::*;
use serde_json::{Map, Value, json};

/// The printed report and, when some statement does not hold, the error that sets the exit
/// status (the report is still printed: it says which and why).
pub struct Verified {
    /// The report (text table or JSON list).
    pub output: String,
    /// `Some` when at least one selected statement does not hold.
    pub failure: Option<CliError>,
}

/// The statements whose id, label, paper or method contains `filter` (case-insensitive; all
/// when `None`); a filter that matches nothing is a usage error.
fn select(filter: Option<&str>) -> Result<Vec<&'static Statement>, CliError> {
    let needle = filter.map(str::to_lowercase);
    let selected: Vec<_> = gam_verify::statements()
        .filter(|s| {
            needle.as_ref().is_none_or(|n| {
                [s.id, s.label, s.paper.key(), s.method.key()].iter().any(|h| h.to_lowercase().contains(n.as_str()))
            })
        })
        .collect();
    if selected.is_empty() {
        return Err(CliError::usage(format!(
            "no statement matches the filter '{}' (ids look like cross2022/lemma-2.2-ii)",
            filter.unwrap_or_default()
        )));
    }
    Ok(selected)
}

/// `gam verify --list`: the statements `filter` selects, without running them: a table of id,
/// label, paper and method, or (`json`) a list of `{"id", "paper", "label", "statement",
/// "method", "hypotheses"}`.
///
/// ```
/// let out = gam::verify::list(Some("lemma-2.2-iii"), false)?;
/// assert!(out.contains("cross2022/lemma-2.2-iii") && out.ends_with("\n1 statement"));
/// # Ok::<(), gam::error::CliError>(())
/// ```
pub fn list(filter: Option<&str>, json: bool) -> Result<String, CliError> {
    let selected = select(filter)?;
    if json {
        let list: Vec<Value> = selected
            .iter()
            .map(|s| {
                let mut entry = identity(s);
                entry.insert("hypotheses".into(), s.hypotheses.into());
                Value::Object(entry)
            })
            .collect();
        return Ok(serde_json::to_string_pretty(&Value::Array(list)).unwrap_or_default());
    }
    let mut rows = vec![["id", "label", "paper", "method"].map(String::from).to_vec()];
    rows.extend(
        selected.iter().map(|s| vec![s.id.into(), s.label.into(), s.paper.key().into(), s.method.key().into()]),
    );
    let n = selected.len();
    Ok(format!("{}\n{n} statement{}", text_table(&rows), if n == 1 { "" } else { "s" }))
}

/// Runs every statement whose id, label, paper or method matches `filter` (case-insensitive
/// substring; all when `None`).
pub fn verify(filter: Option<&str>, json: bool) -> Result<Verified, CliError> {
    let selected = select(filter)?;
    // A check that panics is reported as a failed statement; keep stderr for the error line.
    let previous_hook = std::panic::take_hook();
    std::panic::set_hook(Box::new(|_| {}));
    // The statements are independent: run on every core (rayon), reported in registry order.
    let reports: Vec<Report> = selected.into_par_iter().map(|s| s.run()).collect();
    std::panic::set_hook(previous_hook);

    let failed: Vec<&str> = reports.iter().filter(|r| !r.outcome.holds()).map(|r| r.statement.id).collect();
    let failure = (!failed.is_empty()).then(|| {
        CliError::math(format!("{} of {} statements do not hold: {}", failed.len(), reports.len(), failed.join(", ")))
    });
    let output = if json { json_report(&reports) } else { text_report(&reports) };
    Ok(Verified { output, failure })
}

/// The hypotheses of the statement and the notes of its run, one string.
fn note(r: &Report) -> String {
    let mut parts: Vec<String> = Vec::new();
    if !r.statement.hypotheses.is_empty() {
        parts.push(r.statement.hypotheses.to_string());
    }
    parts.extend(r.outcome.notes.iter().cloned());
    parts.join("; ")
}

/// The fields that name a statement, first in both JSON forms (the listing and the report).
fn identity(s: &Statement) -> Map<String, Value> {
    let mut m = Map::new();
    m.insert("id".into(), s.id.into());
    m.insert("paper".into(), s.paper.key().into());
    m.insert("label".into(), s.label.into());
    m.insert("statement".into(), s.statement.into());
    m.insert("method".into(), s.method.key().into());
    m
}

fn millis(r: &Report) -> f64 {
    r.elapsed.as_secs_f64() * 1e3
}

fn json_report(reports: &[Report]) -> String {
    let list: Vec<Value> = reports
        .iter()
        .map(|r| {
            let mut entry = identity(r.statement);
            entry.insert("holds".into(), r.outcome.holds().into());
            entry.insert("checks".into(), r.outcome.checks.into());
            entry.insert("failures".into(), json!(r.outcome.failures));
            entry.insert("note".into(), note(r).into());
            entry.insert("time_ms".into(), json!((millis(r) * 1e3).round() / 1e3));
            Value::Object(entry)
        })
        .collect();
    serde_json::to_string_pretty(&Value::Array(list)).unwrap_or_default()
}

fn text_report(reports: &[Report]) -> String {
    let mut rows = vec![["id", "label", "method", "holds", "checks", "time"].map(String::from).to_vec()];
    for r in reports {
        rows.push(vec![
            r.statement.id.to_string(),
            r.statement.label.to_string(),
            r.statement.method.key().to_string(),
            if r.outcome.holds() { "yes" } else { "NO" }.to_string(),
            r.outcome.checks.to_string(),
            format!("{:.1} ms", millis(r)),
        ]);
    }
    let mut out = text_table(&rows);
    let mut details = String::new();
    for r in reports {
        let n = note(r);
        if n.is_empty() && r.outcome.failures.is_empty() {
            continue;
        }
        details.push_str(&format!("\n{} ({}): {}\n", r.statement.id, r.statement.label, r.statement.statement));
        for f in &r.outcome.failures {
            details.push_str(&format!("  FAILED: {f}\n"));
        }
        if !n.is_empty() {
            details.push_str(&format!("  note: {n}\n"));
        }
    }
    let holding = reports.iter().filter(|r| r.outcome.holds()).count();
    let total: f64 = reports.iter().map(millis).sum();
    if !details.is_empty() {
        out.push('\n');
        out.push_str(details.trim_end());
        out.push('\n');
    }
    out.push_str(&format!("\n{holding} of {} statements hold ({total:.0} ms)", reports.len()));
    out
}
