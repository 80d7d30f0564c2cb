//! Statements of the paper (filled in by the verification work of issue 5).

use crate::Statement;

/// The statements of this paper, in paper order.
pub const STATEMENTS: &[Statement] = &[];
