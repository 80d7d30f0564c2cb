//! The workspace's paper-level tests: each paper's statements, the registry under hypotheses, the paper map's paths.
//!
//! One test binary for the whole directory: each file is a module of it. One binary links once
//! (instead of once per file) and its tests share the test threads, so `cargo test` keeps both
//! cores busy instead of running many small binaries one after the other (issue 29).
//! `cargo test -p gam-tests --test all -- MODULE::` runs one file's tests; a new file in this directory
//! must be added below (`all_modules::every_test_file_is_a_module` fails otherwise).

mod angelidis;
mod cross_cripps_mullineux_2022;
mod juttler;
mod paper_map_paths;
mod under_hypotheses;
mod wareham_lasenby;

#[path = "../support/all_modules.rs"]
mod all_modules;
