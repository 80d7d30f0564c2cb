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

/// The longest message printed: with `error: ` the line stays within 300 characters.
pub const MAX_MESSAGE_CHARS: usize = 293;

impl fmt::Display for CliError {
    /// The message on one line: embedded line breaks become spaces, and a message longer than
    /// [`MAX_MESSAGE_CHARS`] (a long value echoed inside it) keeps its start (the place) and its
    /// end (the reason) around ` … `.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let one_line: Vec<&str> = self.message.lines().map(str::trim).filter(|l| !l.is_empty()).collect();
        f.write_str(&shorten(&one_line.join(" "), MAX_MESSAGE_CHARS))
    }
}

/// `text` if at most `max` characters, else its first and last characters around ` … `
/// (`max` characters in all).
fn shorten(text: &str, max: usize) -> String {
    let n = text.chars().count();
    if n <= max {
        return text.to_string();
    }
    let tail = max / 3;
    let head = max - tail - 3;
    let start: String = text.chars().take(head).collect();
    let end: String = text.chars().skip(n - tail).collect();
    format!("{start} … {end}")
}

impl From<algebra_core::MetricError> for CliError {
    fn from(e: algebra_core::MetricError) -> Self {
        CliError::usage(e.to_string())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn long_messages_keep_their_place_and_reason() {
        let value = "1.2345678901234567*e12 + ".repeat(100);
        let e = CliError::math(format!("log: the element {value} has no real logarithm"));
        let line = format!("error: {e}");
        assert_eq!(line.chars().count(), 300);
        assert!(
            line.starts_with("error: log: the element 1.2345") && line.ends_with("has no real logarithm"),
            "{line}"
        );
        assert_eq!(CliError::usage("short\n  two lines").to_string(), "short two lines");
    }
}
