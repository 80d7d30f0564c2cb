//! Statements of this section (filled in by the verification work of issue 5).

use crate::Statement;

/// The statements of this section, in paper order.
pub const STATEMENTS: &[Statement] = &[];
