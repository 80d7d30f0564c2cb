//! The `gam` command line as a library: the commands behind the `gam` binary (src/main.rs
//! parses the arguments and calls them) and [`api`], the same commands for other front ends
//! (the Python package in python/): they take already-parsed inputs and return the JSON value
//! that the command prints with `--json`, or the [`api::CliError`] whose message is the
//! command's `error:` line. One implementation, so every door gives the same answer.
//!
//! The command modules are public for the binary only (hidden from the docs); [`api`] is the
//! interface for other callers.

// The command modules' own docs (written for the binary) link their private helpers; those
// modules are hidden from the library's docs, so the links lead nowhere a reader goes.
#![allow(rustdoc::private_intra_doc_links)]

pub mod api;
#[doc(hidden)]
pub mod budget;
#[doc(hidden)]
pub mod codegen;
#[doc(hidden)]
pub mod commands;
#[doc(hidden)]
pub mod error;
#[doc(hidden)]
pub mod eval;
#[doc(hidden)]
pub mod expr;
#[doc(hidden)]
pub mod figures;
#[doc(hidden)]
pub mod finite_guard;
#[doc(hidden)]
pub mod hermite;
#[doc(hidden)]
pub mod interpolate;
#[doc(hidden)]
pub mod output;
#[doc(hidden)]
pub mod plot;
#[doc(hidden)]
pub mod pose;
#[doc(hidden)]
pub mod precision;
#[doc(hidden)]
pub mod prove;
#[doc(hidden)]
pub mod sample;
#[doc(hidden)]
pub mod scalar;
#[doc(hidden)]
pub mod surface;
#[doc(hidden)]
pub mod trajectory;
#[doc(hidden)]
pub mod verify;

/// The `--algebra` help, naming the built-ins from algebra-core's one table.
#[doc(hidden)]
pub fn algebra_help() -> String {
    format!("A built-in algebra ({}) or a path to a TOML file", algebra_core::algebra::builtin_names())
}
