//! algebra-core's integration tests: tables against galgebra and sympy, properties, precision against mpmath, Gröbner bases against Singular and sympy.
//!
//! One test binary for the whole directory: each file is a module of it. One binary links once
//! (instead of once per file) and its tests share the test threads, so `cargo test` keeps both
//! cores busy instead of running many small binaries one after the other (issue 29).
//! `cargo test -p algebra-core --test all -- MODULE::` runs one file's tests; a new file in this directory
//! must be added below (`every_test_file_is_a_module` fails otherwise).

mod common;
#[cfg(feature = "rug")]
mod sympy_fixture;

mod atan;
mod edge_scale;
#[cfg(feature = "rug")]
mod exp_blocks;
#[cfg(feature = "rug")]
mod exp_log;
mod finiteness;
mod galgebra;
#[cfg(feature = "rug")]
mod groebner_singular;
#[cfg(feature = "rug")]
mod groebner_sympy;
mod input_limits;
#[cfg(feature = "lanes")]
mod lanes;
mod precision;
mod properties;
mod reference;
#[cfg(feature = "rug")]
mod term_budget;

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
