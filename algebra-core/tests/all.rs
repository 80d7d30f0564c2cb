//! algebra-core's integration tests: tables against galgebra and sympy, properties, precision against mpmath, Gröbner bases against Singular and sympy.
//!
//! One test binary for the whole directory: each file is a module of it. One binary links once
//! (instead of once per file) and its tests share the test threads, so `cargo test` keeps both
//! cores busy instead of running many small binaries one after the other (issue 29).
//! `cargo test -p algebra-core --test all -- MODULE::` runs one file's tests; a new file in this directory
//! must be added below (`all_modules::every_test_file_is_a_module` fails otherwise).

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

#[path = "../../tests/support/all_modules.rs"]
mod all_modules;
