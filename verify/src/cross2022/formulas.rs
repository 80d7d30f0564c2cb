//! The main paper's symbolic even
//! element S of G_{123inf} and the closed forms the paper prints for its sandwiches.
//!
//! The closed forms are typed in from Cross, Cripps and Mullineux (2022), eqs. (5)-(9), so
//! they are an independent reference for the engine's products.

use algebra_core::{Algebra, Basis, Multivector, Poly, Ring};
use std::sync::Arc;

/// The paper's coefficient names for S (eq. 4), in the order of its basis
/// `1, e12, e13, e23, e1inf, e2inf, e3inf, omega = e123inf`, with the basis names.
pub const S_COEFFS: [(&str, &str); 8] = [
    ("S", "1"),
    ("S12", "e12"),
    ("S13", "e13"),
    ("S23", "e23"),
    ("S1inf", "e1inf"),
    ("S2inf", "e2inf"),
    ("S3inf", "e3inf"),
    ("Sw", "e123inf"),
];

/// The fully symbolic even element S of eq. (4) in `alg` (which must contain the labels
/// 1, 2, 3, inf), in `basis`.
///
/// ```
/// let alg = algebra_core::Algebra::builtin("cga-null").unwrap();
/// let s = gam_verify::cross2022::formulas::symbolic_s(&alg, algebra_core::Basis::Product);
/// assert_eq!(s.terms().count(), 8);
/// ```
pub fn symbolic_s(alg: &Arc<Algebra>, basis: Basis) -> Multivector<Poly> {
    Multivector::from_terms(alg, basis, S_COEFFS.iter().map(|(v, e)| (*e, Poly::var(v))))
        .expect("the algebra has the paper's generators")
}

/// The same S as a `gam eval` expression: `S + S12*e12 + ...`.
///
/// ```
/// assert!(gam_verify::cross2022::formulas::symbolic_s_expr().starts_with("(S + S12*e12"));
/// ```
pub fn symbolic_s_expr() -> String {
    let terms: Vec<String> =
        S_COEFFS.iter().map(|(v, e)| if *e == "1" { v.to_string() } else { format!("{v}*{e}") }).collect();
    format!("({})", terms.join(" + "))
}

/// Parses a polynomial written as a sum of signed products of integers and the S variables,
/// as the paper prints them, e.g. `S^2 - S12^2 + 2 S*S13`. Only for the fixed formulas below.
fn p(text: &str) -> Poly {
    let mut total = Poly::zero();
    let text = text.replace('-', "+-");
    for term in text.split('+').map(str::trim).filter(|t| !t.is_empty()) {
        let (neg, body) = match term.strip_prefix('-') {
            Some(rest) => (true, rest.trim()),
            None => (false, term),
        };
        let mut prod = Poly::from_i64(if neg { -1 } else { 1 });
        for factor in body.split(['*', ' ']).filter(|f| !f.is_empty()) {
            let (base, exp) = factor.split_once('^').map(|(b, e)| (b, e.parse().unwrap())).unwrap_or((factor, 1));
            let f = match base.parse::<i64>() {
                Ok(n) => Poly::from_i64(n),
                Err(_) => Poly::var(base),
            };
            prod = prod.mul_ref(&f.pow_u32(exp));
        }
        total = total + prod;
    }
    total
}

/// Eq. (5): rev(S) S = (S² + S12² + S13² + S23²) + 2(S Sw - S12 S3inf + S13 S2inf - S23 S1inf) omega.
pub fn eq5() -> Vec<(&'static str, Poly)> {
    vec![("1", p("S^2 + S12^2 + S13^2 + S23^2")), ("e123inf", p("2*S*Sw - 2*S12*S3inf + 2*S13*S2inf - 2*S23*S1inf"))]
}

/// Eq. (6): rev(S) e1 S.
pub fn eq6() -> Vec<(&'static str, Poly)> {
    vec![
        ("e1", p("S^2 - S12^2 - S13^2 + S23^2")),
        ("e2", p("2*S*S12 - 2*S13*S23")),
        ("e3", p("2*S*S13 + 2*S12*S23")),
        ("einf", p("2*S*S1inf + 2*S12*S2inf + 2*S13*S3inf + 2*S23*Sw")),
    ]
}

/// Eq. (7): rev(S) e2 S.
pub fn eq7() -> Vec<(&'static str, Poly)> {
    vec![
        ("e1", p("-2*S*S12 - 2*S13*S23")),
        ("e2", p("S^2 - S12^2 + S13^2 - S23^2")),
        ("e3", p("2*S*S23 - 2*S12*S13")),
        ("einf", p("2*S*S2inf - 2*S12*S1inf - 2*S13*Sw + 2*S23*S3inf")),
    ]
}

/// Eq. (8): rev(S) e3 S.
pub fn eq8() -> Vec<(&'static str, Poly)> {
    vec![
        ("e1", p("-2*S*S13 + 2*S12*S23")),
        ("e2", p("-2*S*S23 - 2*S12*S13")),
        ("e3", p("S^2 + S12^2 - S13^2 - S23^2")),
        ("einf", p("2*S*S3inf + 2*S12*Sw - 2*S13*S1inf - 2*S23*S2inf")),
    ]
}

/// Eq. (9): the vector part of rev(S) e0 S.
pub fn eq9_vector_part() -> Vec<(&'static str, Poly)> {
    vec![
        ("e0", p("S^2 + S12^2 + S13^2 + S23^2")),
        ("e1", p("2*S*S1inf - 2*S12*S2inf - 2*S13*S3inf + 2*S23*Sw")),
        ("e2", p("2*S*S2inf + 2*S12*S1inf - 2*S13*Sw - 2*S23*S3inf")),
        ("e3", p("2*S*S3inf + 2*S12*Sw + 2*S13*S1inf + 2*S23*S2inf")),
        ("einf", p("2*S1inf^2 + 2*S2inf^2 + 2*S3inf^2 + 2*Sw^2")),
    ]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn formula_reader_reads_what_it_is_given() {
        let (s, s12) = (Poly::var("S"), Poly::var("S12"));
        let expected = s.clone() * s.clone() - Poly::from_i64(2) * s * s12;
        assert_eq!(p("S^2 - 2*S*S12"), expected);
    }
}
