//! Printing a multivector as a sum of basis elements.

use super::Multivector;
use crate::scalar::Ring;
use std::fmt;

/// Formats one term `c*name` the way the CLI prints it: `e12`, `-e12`, `3/2*e12`,
/// `(x + y)*e12`, or just `c` for the scalar.
pub fn format_term(coeff: &str, name: &str) -> String {
    if name == "1" {
        return coeff.to_string();
    }
    match coeff {
        "1" => name.to_string(),
        "-1" => format!("-{name}"),
        c if c.get(1..).is_some_and(|rest| rest.contains([' ', '+', '-']) && !is_number(c)) => {
            format!("({c})*{name}")
        }
        c => format!("{c}*{name}"),
    }
}

/// True for a plain number like `-1.5e-3` or `3/4` (its signs need no parentheses).
fn is_number(s: &str) -> bool {
    s.parse::<f64>().is_ok() || crate::rational::parse_rational(s).is_ok()
}

/// Joins terms with ` + ` / ` - `; `0` when there are none.
pub fn join_terms(terms: impl IntoIterator<Item = String>) -> String {
    let mut out = String::new();
    for t in terms {
        if out.is_empty() {
            out = t;
        } else if let Some(rest) = t.strip_prefix('-') {
            out.push_str(" - ");
            out.push_str(rest);
        } else {
            out.push_str(" + ");
            out.push_str(&t);
        }
    }
    if out.is_empty() { "0".to_string() } else { out }
}

impl<T: Ring> Multivector<T> {
    /// The human form with each coefficient printed by `coeff` (for scalar types whose
    /// `Display` is not the wanted syntax).
    ///
    /// ```
    /// use algebra_core::{Algebra, Basis, Multivector};
    /// let alg = Algebra::builtin("g3").unwrap();
    /// let x = Multivector::from_terms(&alg, Basis::Blade, [("1", 0.5), ("e12", -2.0)]).unwrap();
    /// assert_eq!(x.format_with(|c| format!("{c:.2}")), "0.50 - 2.00*e12");
    /// ```
    pub fn format_with(&self, coeff: impl Fn(&T) -> String) -> String {
        join_terms(self.terms().map(|(_, name, c)| format_term(&coeff(c), name)))
    }
}

/// `coeff` for an error message: a floating-point coefficient in long positional form (f64's
/// `Display` prints `1e-200` as `0.` and 199 zeros, `1e200` with 200 digits) in exponent
/// notation instead; every other coefficient as it is.
fn compact(coeff: String) -> String {
    let digits = coeff.trim_start_matches('-');
    let long = digits.starts_with("0.000000000") || digits.split('.').next().is_some_and(|int| int.len() > 21);
    match coeff.parse::<f64>() {
        Ok(x) if long && x.is_finite() && x != 0.0 => format!("{x:e}"),
        _ => coeff,
    }
}

impl<T: Ring> Multivector<T> {
    /// The value as error messages print it: `Display`, with the coefficients of floating-point
    /// scalars far from unit scale in exponent notation (`1e-200*e1`, not 200 zeros), so that
    /// a message names the value instead of filling its line with digits.
    ///
    /// ```
    /// use algebra_core::{Algebra, Basis, Multivector, MvError};
    /// let alg = Algebra::builtin("g3").unwrap();
    /// let x = Multivector::from_terms(&alg, Basis::Blade, [("1", 1e-200), ("e1", 1e-200)]).unwrap();
    /// let Err(MvError::Undefined { value, .. }) = x.log() else { panic!() };
    /// assert_eq!(value, "1e-200 + 1e-200*e1");
    /// ```
    pub fn describe(&self) -> String {
        if T::relative_epsilon() == 0.0 {
            return self.to_string();
        }
        self.format_with(|c| compact(c.to_string()))
    }
}

impl<T: Ring> fmt::Debug for Multivector<T> {
    /// `Multivector<cga-null, product>(-2 - e0inf)`: the algebra, the basis and the value
    /// (the tables are not printed).
    ///
    /// ```
    /// use algebra_core::{Algebra, Basis, Multivector};
    /// let alg = Algebra::builtin("g3").unwrap();
    /// let x = Multivector::<f64>::basis_element(&alg, Basis::Blade, "e12").unwrap();
    /// assert_eq!(format!("{x:?}"), "Multivector<g3, blade>(e12)");
    /// ```
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "Multivector<{}, {}>({self})", self.algebra.name(), self.basis)
    }
}

impl<T: Ring> fmt::Display for Multivector<T> {
    /// `-2 - e0inf`, `1/2*e12 + e3`, `(x + 1)*e1`; `0` for zero. Terms in basis order.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.format_with(T::to_string))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn terms_format() {
        assert_eq!(format_term("1", "e1"), "e1");
        assert_eq!(format_term("-1", "e1"), "-e1");
        assert_eq!(format_term("-3/2", "e1"), "-3/2*e1");
        assert_eq!(format_term("1e-5", "e1"), "1e-5*e1");
        assert_eq!(format_term("x - y", "e1"), "(x - y)*e1");
        assert_eq!(format_term("-x*y", "e1"), "-x*y*e1");
        assert_eq!(format_term("a**2 - b", "e1"), "(a**2 - b)*e1");
        assert_eq!(format_term("1.5e-7", "e1"), "1.5e-7*e1");
        assert_eq!(format_term("-2", "1"), "-2");
        assert_eq!(join_terms(["-2".to_string(), "-e0inf".to_string()]), "-2 - e0inf");
    }

    #[test]
    fn compact_coefficients() {
        assert_eq!(compact(format!("{}", -1e-200)), "-1e-200");
        assert_eq!(compact(format!("{}", 2.5e200)), "2.5e200");
        assert_eq!(compact(format!("{}", 1e-9)), "0.000000001");
        assert_eq!(compact(format!("{}", 0.5)), "0.5");
        assert_eq!(compact("1/3".to_string()), "1/3");
        assert_eq!(compact("0".to_string()), "0");
    }
}
