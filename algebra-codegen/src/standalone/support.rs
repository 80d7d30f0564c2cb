// Items a standalone file needs beyond what `standalone.rs` takes from algebra-core's own
// sources (the product traits, `Ring`/`Field` reduced to what kernels call, `linalg::solve`).
// Not a module of algebra-codegen: this text is parsed and appended to every `gam codegen
// --standalone` file, and compiled through examples/vendored. `format_term` follows
// algebra-core's `multivector::display` (without its rational-number parser).

use ::core::fmt::{Debug, Display};
use ::core::ops::{Add, Div, Mul, Neg, Sub};

macro_rules! float_scalar {
    ($($t:ty),*) => {$(
        impl Ring for $t {
            fn zero() -> Self { 0.0 }
            fn one() -> Self { 1.0 }
            fn from_ratio(num: i64, den: i64) -> Self { num as $t / den as $t }
            fn is_exact_zero(&self) -> bool { *self == 0.0 }
            fn magnitude(&self) -> f64 { f64::from(self.abs()) }
            fn relative_epsilon() -> f64 { f64::from(<$t>::EPSILON) }
            fn add_ref(&self, rhs: &Self) -> Self { self + rhs }
            fn sub_ref(&self, rhs: &Self) -> Self { self - rhs }
            fn mul_ref(&self, rhs: &Self) -> Self { self * rhs }
            fn neg_ref(&self) -> Self { -self }
        }
        impl Field for $t {
            fn div_ref(&self, rhs: &Self) -> Self { self / rhs }
            fn try_recip(&self) -> Option<Self> { if *self == 0.0 { None } else { Some(1.0 / self) } }
        }
    )*};
}
float_scalar!(f32, f64);

/// Why an operation failed.
#[derive(Debug, Clone, PartialEq)]
pub enum MvError {
    /// The element has no inverse (it is a zero divisor).
    NotInvertible(String),
    /// No real logarithm or square root exists, or the input is not finite (the closed forms).
    Undefined {
        /// `log`, `sqrt`, `exp`, ...
        op: &'static str,
        /// The argument, printed.
        value: String,
        /// Why.
        why: String,
    },
}

impl ::core::fmt::Display for MvError {
    fn fmt(&self, f: &mut ::core::fmt::Formatter<'_>) -> ::core::fmt::Result {
        match self {
            MvError::NotInvertible(x) => write!(f, "{x} is not invertible"),
            MvError::Undefined { op, value, why } => write!(f, "{op} is not defined for {value}: {why}"),
        }
    }
}

impl ::std::error::Error for MvError {}

/// One term `c*name` as the CLI prints it: `e12`, `-e12`, `1.5*e12`, or `c` for the scalar.
fn format_term(coeff: &str, name: &str) -> String {
    if name == "1" {
        return coeff.to_string();
    }
    let plain = coeff.parse::<f64>().is_ok()
        || coeff.split_once('/').is_some_and(|(p, q)| p.parse::<i64>().is_ok() && q.parse::<u64>().is_ok());
    match coeff {
        "1" => name.to_string(),
        "-1" => format!("-{name}"),
        c if !plain && c.get(1..).is_some_and(|rest| rest.contains([' ', '+', '-'])) => format!("({c})*{name}"),
        c => format!("{c}*{name}"),
    }
}
