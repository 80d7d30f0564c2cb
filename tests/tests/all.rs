//! The workspace's paper-level tests: each paper's statements, the registry under hypotheses, the paper map's paths.
//!
//! One test binary for the whole directory: each file is a module of it. One binary links once
//! (instead of once per file) and its tests share the test threads, so `cargo test` keeps both
//! cores busy instead of running many small binaries one after the other (issue 29).
//! `cargo test -p gam-tests --test all -- MODULE::` runs one file's tests; a new file in this directory
//! must be added below (`every_test_file_is_a_module` fails otherwise).

mod angelidis;
mod cross_cripps_mullineux_2022;
mod juttler;
mod paper_map_paths;
mod under_hypotheses;
mod wareham_lasenby;

/// Cargo no longer finds this directory's files itself (`autotests = false`): a file that is
/// not declared above would silently not run.
#[test]
fn every_test_file_is_a_module() {
    let root = include_str!("all.rs");
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests");
    for entry in std::fs::read_dir(&dir).expect("the tests directory") {
        let path = entry.expect("a directory entry").path();
        let Some(stem) = path.file_stem().and_then(|s| s.to_str()) else { continue };
        let declared =
            if path.is_dir() { path.join("mod.rs").exists() } else { path.extension().is_some_and(|e| e == "rs") };
        if declared && stem != "all" {
            assert!(root.lines().any(|l| l == format!("mod {stem};")), "tests/{stem} is not a module of tests/all.rs");
        }
    }
}
