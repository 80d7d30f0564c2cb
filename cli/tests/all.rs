//! The `gam` command's tests: contract, commands, figures, fuzzing, precision.
//!
//! One test binary for the whole directory: each file is a module of it. One binary links once
//! (instead of once per file) and its tests share the test threads, so `cargo test` keeps both
//! cores busy instead of running many small binaries one after the other (issue 29).
//! `cargo test -p gam --test all -- MODULE::` runs one file's tests; a new file in this directory
//! must be added below (`all_modules::every_test_file_is_a_module` fails otherwise).

mod common;

mod animate;
mod budgets;
mod cli;
mod codegen;
mod duplicate_keys;
mod edge_scale;
mod figures_detail;
mod figures_juttler;
mod figures_more;
mod figures_reader;
mod fuzz_commands;
mod fuzz_contract;
mod fuzz_values;
mod hermite;
mod interpolate;
mod interpolate_hexanion;
mod interpolate_juttler;
mod interpolate_wl;
mod paper_equations;
mod plot;
mod plot_png;
mod pose;
mod pose_cga;
mod pose_conventions;
mod precision;
mod proptest_grammar;
mod prove;
mod sample_plot;
mod trajectory;
mod verify;

#[path = "../../tests/support/all_modules.rs"]
mod all_modules;
