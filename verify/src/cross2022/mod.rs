//! Cross, Cripps and Mullineux (2022): rigid-body motions in the null-basis CGA G_{0123inf}.
//!
//! Section 2 (the algebra, poses, transforms) in [`sec2`], Section 3 (velocity) in [`sec3`],
//! Section 4 (motion construction) in [`sec4`], the claims of the worked examples of Section 5 in
//! [`sec5`]; the paper's printed closed forms (eqs. 5-9),
//! typed in as an independent reference, in [`formulas`].

pub mod formulas;
pub mod sec2;
pub mod sec3;
pub mod sec4;
pub mod sec5;

use crate::Statement;

/// The statements of the paper, in paper order.
///
/// ```
/// assert!(gam_verify::cross2022::statements().any(|s| s.id == "cross2022/lemma-2.1"));
/// ```
pub fn statements() -> impl Iterator<Item = &'static Statement> {
    sec2::STATEMENTS.iter().chain(sec3::STATEMENTS).chain(sec4::STATEMENTS).chain(sec5::STATEMENTS)
}
