//! The numbers of the format: every number of a pose object or spec is read as a
//! [`SpecNumber`], either `f64` (the default: what every document type means without a type
//! argument) or [`Exact`], an exact rational, for `--scalar rational` and `--scalar mpfr:BITS`
//! (the MPFR value is the correctly rounded exact one).
//!
//! Exactness needs the literal as written: serde_json reads a decimal literal such as `0.1`
//! into the nearest `f64`, and no rule gets `1/10` back from it for every literal. So a
//! document meant for [`Exact`] is first passed through [`quote_numbers`], which turns every
//! number literal that is not a small integer into a string holding the same literal; an
//! [`Exact`] reads integers, such strings, and `"p/q"` strings exactly.
//!
//! ```
//! use algebra_core::rational::ratio;
//! use motion::schema::{Exact, quote_numbers};
//! let text = quote_numbers(r#"{"position": [0.1, 2, "1/3"]}"#);
//! assert_eq!(text, r#"{"position": ["0.1", 2, "1/3"]}"#);
//! let v: serde_json::Value = serde_json::from_str(&text)?;
//! let p: [Exact; 3] = serde_json::from_value(v["position"].clone())?;
//! assert_eq!(p.map(|x| x.0), [ratio(1, 10), ratio(2, 1), ratio(1, 3)]);
//! # Ok::<(), serde_json::Error>(())
//! ```

use super::pose::{PoseError, PoseObject};
use algebra_core::Ring;
use algebra_core::rational::{Q, format_rational, parse_rational, rational_to_f64};
use serde::de::{self, Deserialize, Deserializer, Visitor};
use serde::{Serialize, Serializer};
use serde_json::Value;
use std::borrow::Cow;
use std::fmt;

/// A number type the format can be read into: `f64` or [`Exact`].
///
/// ```
/// use motion::schema::{Exact, SpecNumber};
/// assert_eq!(<f64 as SpecNumber>::from_json(&serde_json::json!(0.5)), Some(0.5));
/// assert_eq!(Exact::from_json(&serde_json::json!("-2/4")).map(|x| x.to_f64()), Some(-0.5));
/// ```
pub trait SpecNumber: Clone + PartialEq + fmt::Debug + Serialize + for<'de> Deserialize<'de> {
    /// The number of a JSON value: a JSON number, and for [`Exact`] also a string `"p/q"`, `"p"`
    /// or a decimal literal; `None` for anything else.
    fn from_json(v: &Value) -> Option<Self>;
    /// [`SpecNumber::from_json`], also accepting decimal strings (the `motor` form's
    /// coefficients, "numbers or decimal strings" in every precision).
    fn from_json_or_string(v: &Value) -> Option<Self> {
        Self::from_json(v)
    }
    /// The value as a JSON value (a number for `f64`, a `"p/q"` string for [`Exact`]).
    fn to_json(&self) -> Value;
    /// Zero.
    fn zero() -> Self;
    /// One.
    fn one() -> Self;
    /// Finite (always, for [`Exact`]).
    fn is_finite(&self) -> bool;
    /// The nearest `f64` (for messages).
    fn to_f64(&self) -> f64;
    /// Checks a pose object when a document is read: `f64` converts it
    /// ([`PoseObject::to_pose`]); [`Exact`] leaves the conversion to the precision it is
    /// used in (a rational document may hold an `axis`/`angle` pose meant for `mpfr:BITS`).
    fn check_pose(p: &PoseObject<Self>) -> Result<(), PoseError>;
    /// True when positive and finite.
    fn is_positive(&self) -> bool;
    /// The JSON text as this number type reads it: unchanged for `f64`, [`quote_numbers`]
    /// for [`Exact`].
    fn prepare_text(text: &str) -> Cow<'_, str> {
        Cow::Borrowed(text)
    }
}

impl SpecNumber for f64 {
    fn from_json(v: &Value) -> Option<f64> {
        v.as_f64()
    }
    fn from_json_or_string(v: &Value) -> Option<f64> {
        match v {
            Value::String(s) => s.trim().parse::<f64>().ok(),
            v => v.as_f64(),
        }
    }
    fn to_json(&self) -> Value {
        Value::from(*self)
    }
    fn zero() -> f64 {
        0.0
    }
    fn one() -> f64 {
        1.0
    }
    fn is_finite(&self) -> bool {
        f64::is_finite(*self)
    }
    fn to_f64(&self) -> f64 {
        *self
    }
    fn check_pose(p: &PoseObject<f64>) -> Result<(), PoseError> {
        p.to_pose().map(drop)
    }
    fn is_positive(&self) -> bool {
        *self > 0.0 && f64::is_finite(*self)
    }
}

/// An exact rational read from a document: a JSON integer, a `"p/q"` or `"p"` string or a
/// decimal literal (as a string, or as a number after [`quote_numbers`]); serialized as the
/// `"p/q"` string of the CLI's coefficient syntax.
///
/// A JSON number that reaches an [`Exact`] as an `f64` (a document not passed through
/// [`quote_numbers`], e.g. a `serde_json::Value` built in code) is read as its shortest
/// round-trip decimal: `0.1` is `1/10`, and every literal of at most 15 significant digits
/// is read as written.
///
/// ```
/// use algebra_core::rational::ratio;
/// use motion::schema::Exact;
/// let x: Exact = serde_json::from_str("0.1")?;
/// assert_eq!(x.0, ratio(1, 10));
/// assert_eq!(serde_json::to_string(&Exact(ratio(-1, 3)))?, r#""-1/3""#);
/// # Ok::<(), serde_json::Error>(())
/// ```
#[derive(Clone, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct Exact(pub Q);

impl Exact {
    /// The exact value of a decimal or `p/q` literal.
    fn parse(s: &str) -> Option<Exact> {
        parse_rational(s).ok().map(Exact)
    }
}

impl SpecNumber for Exact {
    fn from_json(v: &Value) -> Option<Exact> {
        match v {
            Value::String(s) => Exact::parse(s),
            Value::Number(n) => match (n.as_i64(), n.as_u64(), n.as_f64()) {
                (Some(i), _, _) => Some(Exact(Q::from_integer(i.into()))),
                (_, Some(u), _) => Some(Exact(Q::from_integer(u.into()))),
                (_, _, Some(x)) if x.is_finite() => Exact::parse(&format!("{x:e}")),
                _ => None,
            },
            _ => None,
        }
    }
    fn to_json(&self) -> Value {
        Value::String(format_rational(&self.0))
    }
    fn zero() -> Exact {
        Exact(<Q as Ring>::zero())
    }
    fn one() -> Exact {
        Exact(<Q as Ring>::one())
    }
    fn is_finite(&self) -> bool {
        true
    }
    fn to_f64(&self) -> f64 {
        rational_to_f64(&self.0)
    }
    fn check_pose(_: &PoseObject<Exact>) -> Result<(), PoseError> {
        Ok(())
    }
    fn is_positive(&self) -> bool {
        self.0 > <Q as Ring>::zero()
    }
    fn prepare_text(text: &str) -> Cow<'_, str> {
        Cow::Owned(quote_numbers(text))
    }
}

impl Serialize for Exact {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_str(&format_rational(&self.0))
    }
}

impl<'de> Deserialize<'de> for Exact {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        d.deserialize_any(ExactVisitor)
    }
}

struct ExactVisitor;

impl Visitor<'_> for ExactVisitor {
    type Value = Exact;

    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("a number, or a string \"p/q\", \"p\" or a decimal")
    }

    fn visit_i64<E>(self, x: i64) -> Result<Exact, E> {
        Ok(Exact(Q::from_integer(x.into())))
    }

    fn visit_u64<E>(self, x: u64) -> Result<Exact, E> {
        Ok(Exact(Q::from_integer(x.into())))
    }

    fn visit_f64<E: de::Error>(self, x: f64) -> Result<Exact, E> {
        Exact::from_json(&Value::from(x)).ok_or_else(|| E::custom(format!("the number {x} is not finite")))
    }

    fn visit_str<E: de::Error>(self, s: &str) -> Result<Exact, E> {
        parse_rational(s).map(Exact).map_err(E::custom)
    }
}

/// The JSON text with every number literal that serde_json would not read exactly (one with a
/// fraction or an exponent, or an integer of more than 15 digits) written as a string holding
/// the same literal, so that an [`Exact`] reads it exactly. Strings, keys and everything else
/// are left as they are; the text must be JSON (a syntax error is left for the parser).
///
/// ```
/// assert_eq!(motion::schema::quote_numbers(r#"{"a\"1.5": [-1.5e-3, 7]}"#), r#"{"a\"1.5": ["-1.5e-3", 7]}"#);
/// ```
pub fn quote_numbers(text: &str) -> String {
    let bytes = text.as_bytes();
    let mut out = String::with_capacity(text.len() + 16);
    let (mut i, mut copied) = (0, 0);
    while i < bytes.len() {
        match bytes[i] {
            b'"' => {
                // skip the string, escapes included
                i += 1;
                while i < bytes.len() && bytes[i] != b'"' {
                    i += if bytes[i] == b'\\' { 2 } else { 1 };
                }
                i += 1;
            }
            b'-' | b'0'..=b'9' => {
                let start = i;
                i += 1;
                while i < bytes.len() && matches!(bytes[i], b'0'..=b'9' | b'.' | b'e' | b'E' | b'+' | b'-') {
                    i += 1;
                }
                let literal = &text[start..i];
                let digits = literal.bytes().filter(u8::is_ascii_digit).count();
                if literal.contains(['.', 'e', 'E']) || digits > 15 {
                    out.push_str(&text[copied..start]);
                    out.push('"');
                    out.push_str(literal);
                    out.push('"');
                    copied = i;
                }
            }
            _ => i += 1,
        }
    }
    out.push_str(&text[copied.min(text.len())..]);
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use algebra_core::rational::ratio;

    #[test]
    fn literals_are_read_as_written() {
        let text = quote_numbers(r#"[0.1, 1e-30, -2.50, 12345678901234567890, 3, "1/7", "x1.5"]"#);
        assert_eq!(text, r#"["0.1", "1e-30", "-2.50", "12345678901234567890", 3, "1/7", "x1.5"]"#);
        let v: Vec<Value> = serde_json::from_str(&text).unwrap();
        let x: Vec<Option<Q>> = v.iter().map(|v| Exact::from_json(v).map(|e| e.0)).collect();
        let big: Q = parse_rational("12345678901234567890").unwrap();
        let tiny = parse_rational(&format!("1/1{}", "0".repeat(30))).unwrap();
        assert_eq!(
            x,
            [Some(ratio(1, 10)), Some(tiny), Some(ratio(-5, 2)), Some(big), Some(ratio(3, 1)), Some(ratio(1, 7)), None]
        );
        // a number not quoted is read as its shortest decimal; an f64 as a number only
        assert_eq!(Exact::from_json(&serde_json::json!(0.1)), Some(Exact(ratio(1, 10))));
        assert_eq!(<f64 as SpecNumber>::from_json(&serde_json::json!("0.5")), None);
        assert_eq!(<f64 as SpecNumber>::from_json_or_string(&serde_json::json!("0.5")), Some(0.5));
    }

    #[test]
    fn quoting_leaves_strings_and_structure() {
        let text = r#"{"k\\": "a \" 1.5", "n": [1, -0.0, true, null]}"#;
        assert_eq!(quote_numbers(text), r#"{"k\\": "a \" 1.5", "n": [1, "-0.0", true, null]}"#);
        assert_eq!(quote_numbers("[1.5"), r#"["1.5""#);
    }
}
