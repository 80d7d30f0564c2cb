//! Exact rationals used by metrics and product tables (`num-rational`'s `BigRational`, so the
//! tables build without GMP), with the parser and printer of the CLI's coefficient syntax.

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Signed, ToPrimitive, Zero};
use std::fmt;

/// An exact rational number.
pub type Q = BigRational;

/// The integer `n` as a rational.
///
/// ```
/// use algebra_core::rational::{q, parse_rational};
/// assert_eq!(q(-1), parse_rational("-1").unwrap());
/// ```
pub fn q(n: i64) -> Q {
    Q::from_integer(BigInt::from(n))
}

/// The ratio `num / den` as a rational (`den != 0`).
///
/// ```
/// use algebra_core::rational::{ratio, format_rational};
/// assert_eq!(format_rational(&ratio(2, -4)), "-1/2");
/// ```
pub fn ratio(num: i64, den: i64) -> Q {
    Q::new(BigInt::from(num), BigInt::from(den))
}

/// Why a rational literal could not be read.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum RationalParseError {
    /// Not of the form `p`, `p/q` or a decimal `d.ddd` (optionally with an exponent).
    Syntax(String),
    /// A zero denominator.
    ZeroDenominator(String),
    /// A decimal exponent beyond [`MAX_DECIMAL_EXPONENT`] in absolute value (its digits would
    /// not fit in memory).
    ExponentTooLarge(String),
}

impl std::fmt::Display for RationalParseError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            RationalParseError::Syntax(x) => {
                write!(f, "`{x}` is not a rational number (expected p, p/q or a decimal)")
            }
            RationalParseError::ZeroDenominator(x) => write!(f, "`{x}` has a zero denominator"),
            RationalParseError::ExponentTooLarge(x) => {
                write!(f, "`{x}`: the decimal exponent is limited to ±{MAX_DECIMAL_EXPONENT}")
            }
        }
    }
}

impl std::error::Error for RationalParseError {}

/// The largest decimal exponent `|e|` a literal such as `1e5000` may have: `10^e` is built
/// exactly, so an exponent of `2^31` would need gigabytes before any work is done.
pub const MAX_DECIMAL_EXPONENT: i64 = 100_000;

/// Parses `p`, `p/q`, or an exact decimal (`0.25`, `-1.5e-3`) into a rational.
///
/// ```
/// use algebra_core::rational::{parse_rational, ratio};
/// assert_eq!(parse_rational("0.25").unwrap(), ratio(1, 4));
/// assert_eq!(parse_rational("-3/6").unwrap(), ratio(-1, 2));
/// assert!(parse_rational("1/0").is_err());
/// assert!(parse_rational("1e2147483648").is_err()); // exponent cap, checked before any work
/// ```
pub fn parse_rational(text: &str) -> Result<Q, RationalParseError> {
    let s = text.trim();
    let err = || RationalParseError::Syntax(text.to_string());
    if let Some((n, d)) = s.split_once('/') {
        let n: BigInt = parse_int(n.trim()).ok_or_else(err)?;
        let d: BigInt = parse_int(d.trim()).ok_or_else(err)?;
        if d.is_zero() {
            return Err(RationalParseError::ZeroDenominator(text.to_string()));
        }
        return Ok(Q::new(n, d));
    }
    if let Some(i) = s.find(['e', 'E']) {
        // checked before any digits are built: 1e2147483647 must not allocate
        let too_large = match s[i + 1..].parse::<i64>() {
            Ok(e) => e.abs() > MAX_DECIMAL_EXPONENT,
            Err(_) => {
                let digits = s[i + 1..].trim_start_matches(['-', '+']);
                !digits.is_empty() && digits.bytes().all(|b| b.is_ascii_digit())
            }
        };
        if too_large || s.len() > MAX_DECIMAL_EXPONENT as usize {
            return Err(RationalParseError::ExponentTooLarge(text.to_string()));
        }
    }
    parse_decimal(s).ok_or_else(err)
}

fn parse_int(s: &str) -> Option<BigInt> {
    let digits = s.strip_prefix(['-', '+']).unwrap_or(s);
    if digits.is_empty() || !digits.bytes().all(|b| b.is_ascii_digit()) {
        return None;
    }
    s.parse().ok()
}

fn parse_decimal(s: &str) -> Option<Q> {
    let (mantissa, exponent) = match s.find(['e', 'E']) {
        Some(i) => (&s[..i], s[i + 1..].parse::<i32>().ok()?),
        None => (s, 0),
    };
    let (neg, body) = match mantissa.strip_prefix('-') {
        Some(rest) => (true, rest),
        None => (false, mantissa.strip_prefix('+').unwrap_or(mantissa)),
    };
    let (int_part, frac_part) = body.split_once('.').unwrap_or((body, ""));
    if int_part.is_empty() && frac_part.is_empty() {
        return None;
    }
    if !int_part.bytes().chain(frac_part.bytes()).all(|b| b.is_ascii_digit()) {
        return None;
    }
    let digits: BigInt = format!("{int_part}{frac_part}0").parse().ok()?;
    let digits = digits / BigInt::from(10);
    let scale = exponent.checked_sub(i32::try_from(frac_part.len()).ok()?)?;
    let ten = BigInt::from(10);
    let value = if scale >= 0 {
        Q::from_integer(digits * num_traits::pow(ten, scale as usize))
    } else {
        Q::new(digits, num_traits::pow(ten, (-scale) as usize))
    };
    Some(if neg { -value } else { value })
}

/// The rational square root of `x`, when `x ≥ 0` is the square of a rational (numerator and
/// denominator in lowest terms are perfect squares); `None` otherwise.
///
/// ```
/// use algebra_core::rational::{ratio, sqrt_rational};
/// assert_eq!(sqrt_rational(&ratio(9, 25)), Some(ratio(3, 5)));
/// assert_eq!(sqrt_rational(&ratio(2, 1)), None);
/// assert_eq!(sqrt_rational(&ratio(-4, 1)), None);
/// ```
pub fn sqrt_rational(x: &Q) -> Option<Q> {
    if x.is_negative() {
        return None;
    }
    let root = |n: &BigInt| Some(n.sqrt()).filter(|r| &(r * r) == n);
    Some(Q::new(root(x.numer())?, root(x.denom())?))
}

/// Prints `p` or `p/q` in lowest terms (the CLI's `rational` coefficient syntax).
///
/// ```
/// use algebra_core::rational::{format_rational, ratio};
/// assert_eq!(format_rational(&ratio(6, 4)), "3/2");
/// assert_eq!(format_rational(&ratio(-2, 1)), "-2");
/// ```
pub fn format_rational(x: &Q) -> String {
    if x.denom().is_one() { x.numer().to_string() } else { format!("{}/{}", x.numer(), x.denom()) }
}

/// `x` rounded to the nearest f64 (infinite if out of range).
///
/// ```
/// use algebra_core::rational::{rational_to_f64, ratio};
/// assert_eq!(rational_to_f64(&ratio(1, 4)), 0.25);
/// ```
pub fn rational_to_f64(x: &Q) -> f64 {
    x.to_f64().unwrap_or_else(|| if x.is_negative() { f64::NEG_INFINITY } else { f64::INFINITY })
}

/// The exact rational value of a finite f64, or `None` for NaN and infinities.
///
/// ```
/// use algebra_core::rational::{rational_from_f64, ratio};
/// assert_eq!(rational_from_f64(0.375), Some(ratio(3, 8)));
/// ```
pub fn rational_from_f64(x: f64) -> Option<Q> {
    Q::from_float(x)
}

/// A rational displayed in the CLI syntax.
#[derive(Clone, Debug, PartialEq)]
pub struct Display<'a>(pub &'a Q);

impl fmt::Display for Display<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&format_rational(self.0))
    }
}
