//! Workspace-level integration tests: one file per paper in `tests/tests/`, one test per
//! numbered statement, each running the statement's check from `gam-verify` (the same
//! registry `gam verify` reports from).

/// Runs the statement `id` and panics with every failed comparison unless it holds.
/// Returns the outcome so a test can also look at the notes (counterexamples found).
///
/// ```
/// let out = gam_tests::assert_holds("cross2022/lemma-2.4");
/// assert!(out.checks >= 2);
/// ```
pub fn assert_holds(id: &str) -> gam_verify::Outcome {
    let statement = gam_verify::find(id).unwrap_or_else(|| panic!("no statement {id} in the registry"));
    let report = statement.run();
    let out = report.outcome;
    assert!(out.checks > 0, "{id}: the check compared nothing");
    assert!(out.failures.is_empty(), "{id} ({}) does not hold:\n  {}", statement.label, out.failures.join("\n  "));
    out
}

/// Asserts that the registry's statements of `paper` are exactly `ids` (in order), so a
/// statement added to the registry without a test (or the reverse) is caught.
///
/// ```
/// gam_tests::assert_registry(gam_verify::Paper::Cross2022, &[]).ok();
/// ```
pub fn assert_registry(paper: gam_verify::Paper, ids: &[&str]) -> Result<(), String> {
    let registered: Vec<&str> = gam_verify::statements().filter(|s| s.paper == paper).map(|s| s.id).collect();
    if registered == ids {
        Ok(())
    } else {
        Err(format!("registry of {}: {registered:?}\n tests: {ids:?}", paper.key()))
    }
}
