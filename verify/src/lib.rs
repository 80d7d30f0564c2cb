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
pub mod wareham_lasenby;

pub use check::{Checker, Outcome};
pub use statement::{Method, Paper, Report, Statement};

/// Every statement of the four papers, in paper order.
///
/// ```
/// let ids: Vec<_> = gam_verify::statements().map(|s| s.id).collect();
/// assert!(ids.contains(&"cross2022/lemma-2.2-ii"));
/// ```
pub fn statements() -> impl Iterator<Item = &'static Statement> {
    cross2022::statements()
        .chain(wareham_lasenby::STATEMENTS)
        .chain(juttler::STATEMENTS)
        .chain(angelidis::STATEMENTS)
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
