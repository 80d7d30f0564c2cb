//! Reading tests/fixtures/sympy/groebner.json (written by the committed script
//! tests/fixtures/sympy/groebner.py): shared by the `groebner_sympy` test and the `groebner`
//! bench, which includes this file by path.

use algebra_core::Poly;
use algebra_core::ideal::MonomialOrder;
use rug::Rational;
use serde_json::Value;

/// The fixture's text.
pub const FIXTURE: &str = include_str!("../../../tests/fixtures/sympy/groebner.json");

/// The systems of the fixture.
pub fn systems() -> Vec<Value> {
    let data: Value = serde_json::from_str(FIXTURE).expect("fixture is JSON");
    data["systems"].as_array().expect("systems").clone()
}

/// A system's variable names, in the fixture's order.
pub fn variables(system: &Value) -> Vec<String> {
    system["variables"].as_array().expect("variables").iter().map(|v| v.as_str().expect("name").into()).collect()
}

/// A system's monomial order (`lex`, else grevlex).
pub fn order(system: &Value) -> MonomialOrder {
    if system["order"] == "lex" { MonomialOrder::Lex } else { MonomialOrder::GrevLex }
}

/// A polynomial given as `[[coefficient, [exponents...]], ...]` over `vars`.
pub fn poly(vars: &[String], terms: &Value) -> Poly {
    Poly::from_terms(terms.as_array().expect("terms").iter().map(|t| {
        let c: Rational = t[0].as_str().expect("coefficient").parse().expect("rational");
        let e = t[1].as_array().expect("exponents").iter().map(|k| k.as_u64().expect("exponent") as u32);
        (c, vars.iter().cloned().zip(e).collect())
    }))
}
