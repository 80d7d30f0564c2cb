//! The one error type of the binary: a message for the single `error:` line on stderr and
//! the exit status it maps to (2 for bad usage or input, 1 for a mathematical failure).

use std::fmt;

/// Exit status for bad usage or input: unknown algebra, bad basis name, parse error, ...
pub const EXIT_USAGE: u8 = 2;
/// Exit status for a mathematical failure: a non-invertible element, an undefined log, ...
pub const EXIT_MATH: u8 = 1;

/// A failure of a command, printed as `error: MESSAGE` on one line.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct CliError {
    /// The exit status, [`EXIT_USAGE`] or [`EXIT_MATH`].
    pub code: u8,
    /// What went wrong and where (no leading `error:`).
    pub message: String,
}

impl CliError {
    /// Bad usage or input (exit status 2).
    pub fn usage(message: impl Into<String>) -> Self {
        CliError { code: EXIT_USAGE, message: message.into() }
    }

    /// A mathematical failure (exit status 1).
    pub fn math(message: impl Into<String>) -> Self {
        CliError { code: EXIT_MATH, message: message.into() }
    }
}

impl fmt::Display for CliError {
    /// The message on one line: embedded line breaks become spaces.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let one_line: Vec<&str> = self.message.lines().map(str::trim).filter(|l| !l.is_empty()).collect();
        f.write_str(&one_line.join(" "))
    }
}

impl From<algebra_core::MetricError> for CliError {
    fn from(e: algebra_core::MetricError) -> Self {
        CliError::usage(e.to_string())
    }
}
