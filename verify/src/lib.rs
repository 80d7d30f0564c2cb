//! Statement-by-statement verification of the four papers GAM implements.
//!
//! Every numbered statement we check is a [`Statement`]: an id such as
//! `cross2022/lemma-2.2-ii`, the paper, the statement in words, the [`Method`] (the strongest
//! scalar that fits: symbolic polynomials, exact rationals, or 256-bit MPFR floats with dual
//! numbers where exp/log appear), the hypotheses the text leaves implicit, and a check
//! function that records each comparison in a [`Checker`]. The same registry drives the
//! workspace tests (`tests/`, one test per statement) and `gam verify`.
//!
//! ```
//! let s = gam_verify::find("cross2022/lemma-2.4").unwrap();
//! let report = s.run();
//! assert!(report.outcome.holds(), "{:?}", report.outcome.failures);
//! ```

pub mod angelidis;
mod check;
pub mod cross2022;
pub mod juttler;
mod statement;
pub mod under_hypotheses;
pub mod wareham_lasenby;

pub use check::{Checker, Outcome};
pub use statement::{Method, Paper, Report, Statement};

/// A built-in algebra shared by all checks of the process, so its lazily built product
/// tables are built once (`Algebra::builtin` makes a fresh algebra on every call).
///
/// ```
/// let a = gam_verify::algebra("cga-null");
/// assert!(std::sync::Arc::ptr_eq(&a, &gam_verify::algebra("cga-null")));
/// ```
///
/// # Panics
/// If `name` is not a built-in algebra name (a programming error in a check).
pub fn algebra(name: &str) -> std::sync::Arc<algebra_core::Algebra> {
    use std::collections::HashMap;
    use std::sync::{Arc, Mutex, OnceLock};
    static CACHE: OnceLock<Mutex<HashMap<String, Arc<algebra_core::Algebra>>>> = OnceLock::new();
    let mut cache = CACHE.get_or_init(Default::default).lock().unwrap_or_else(|e| e.into_inner());
    cache
        .entry(name.to_string())
        .or_insert_with(|| algebra_core::Algebra::builtin(name).expect("a built-in algebra name"))
        .clone()
}

/// Every statement of the four papers, in paper order.
///
/// ```
/// let ids: Vec<_> = gam_verify::statements().map(|s| s.id).collect();
/// assert!(ids.contains(&"cross2022/lemma-2.2-ii"));
/// ```
pub fn statements() -> impl Iterator<Item = &'static Statement> {
    cross2022::statements()
        .chain(under_hypotheses::STATEMENTS)
        .chain(wareham_lasenby::STATEMENTS)
        .chain(under_hypotheses::wareham_lasenby::STATEMENTS)
        .chain(juttler::STATEMENTS)
        .chain(juttler::interpolation::STATEMENTS)
        .chain(juttler::converse::STATEMENTS)
        .chain(under_hypotheses::juttler::STATEMENTS)
        .chain(under_hypotheses::juttler_interpolation::STATEMENTS)
        .chain(angelidis::STATEMENTS)
        .chain(under_hypotheses::angelidis::STATEMENTS)
}

/// The statement with this id, if there is one.
///
/// ```
/// assert!(gam_verify::find("cross2022/theorem-2.8").is_some());
/// assert!(gam_verify::find("nope").is_none());
/// ```
pub fn find(id: &str) -> Option<&'static Statement> {
    statements().find(|s| s.id == id)
}
