//! Exact agreement with galgebra (symbolic GA on sympy), an independent implementation that
//! supports non-orthogonal metrics and both basis representations.
//!
//! The fixtures in `tests/fixtures/galgebra/` were written by `make_fixtures.py` (see its
//! header for the format and the conventions it asserts): each case holds `a`, `b` and the
//! galgebra results `gp = a b`, `op = a ^ b`, `lc = a ⌋ b`, `rc = a ⌊ b`, `rev_a = rev(a)`, as
//! maps basis name -> exact rational, all in the file's basis. Every key of every case is
//! compared exactly, in that basis, and every coefficient of the result (missing = 0).

use crate::common;

use algebra_core::rational::{Q, parse_rational, q};
use algebra_core::{Algebra, Basis};
use common::*;
use serde_json::{Map, Value};
use std::sync::Arc;

const KEYS: [&str; 5] = ["gp", "op", "lc", "rc", "rev_a"];

/// Reads a `{name: "p/q"}` map into a multivector of `alg` in `basis`.
fn read_mv(alg: &Arc<Algebra>, basis: Basis, v: &Value, at: &str) -> Mv {
    let obj = v.as_object().unwrap_or_else(|| panic!("{at}: expected an object"));
    let mut terms = Vec::with_capacity(obj.len());
    for (name, c) in obj {
        let mask = alg.mask_of(name).unwrap_or_else(|e| panic!("{at}: {e}"));
        let text = c.as_str().unwrap_or_else(|| panic!("{at}.{name}: expected a string"));
        let c: Q = parse_rational(text).unwrap_or_else(|e| panic!("{at}.{name}: {e}"));
        assert_ne!(c, q(0), "{at}.{name}: zero coefficients are omitted by the generator");
        terms.push((mask, c));
    }
    mv(alg, basis, &terms)
}

/// Checks one fixture file; returns the number of cases.
fn check_file(file: &str, text: &str, algebra: &str, basis: Basis) -> usize {
    let doc: Map<String, Value> = serde_json::from_str(text).unwrap_or_else(|e| panic!("{file}: {e}"));
    assert_eq!(doc["algebra"], algebra, "{file}: algebra");
    assert_eq!(doc["basis"], basis.to_string().as_str(), "{file}: basis");
    let alg = builtin(algebra);
    let cases = doc["cases"].as_array().unwrap_or_else(|| panic!("{file}: no cases"));
    for (i, case) in cases.iter().enumerate() {
        let case = case.as_object().unwrap_or_else(|| panic!("{file} case {i}: not an object"));
        let mut keys: Vec<&str> = case.keys().map(String::as_str).collect();
        keys.sort_unstable();
        assert_eq!(keys, ["a", "b", "gp", "lc", "op", "rc", "rev_a"], "{file} case {i}: keys");
        let a = read_mv(&alg, basis, &case["a"], &format!("{file} case {i} a"));
        let b = read_mv(&alg, basis, &case["b"], &format!("{file} case {i} b"));
        for key in KEYS {
            let expected = read_mv(&alg, basis, &case[key], &format!("{file} case {i} {key}"));
            let got = match key {
                "gp" => &a * &b,
                "op" => &a ^ &b,
                "lc" => a.lc(&b),
                "rc" => a.rc(&b),
                "rev_a" => a.reverse(),
                _ => unreachable!(),
            };
            assert_eq!(got.basis(), basis, "{file} case {i} {key}: result basis");
            for m in 0..alg.dim() as u32 {
                assert_eq!(
                    got.coeff(m).unwrap(),
                    expected.coeff(m).unwrap(),
                    "{file} case {i} key {key}: coefficient of {}\n  a = {a}\n  b = {b}\n  GAM:      {got}\n  galgebra: {expected}",
                    alg.name_of(m).unwrap()
                );
            }
        }
    }
    cases.len()
}

#[test]
fn cga_null_blade_basis_agrees_with_galgebra() {
    let text = include_str!("../../tests/fixtures/galgebra/cga_null_blade.json");
    assert_eq!(check_file("cga_null_blade.json", text, "cga-null", Basis::Blade), 40);
}

#[test]
fn cga_null_product_basis_agrees_with_galgebra() {
    let text = include_str!("../../tests/fixtures/galgebra/cga_null_product.json");
    assert_eq!(check_file("cga_null_product.json", text, "cga-null", Basis::Product), 40);
}

#[test]
fn cga_blade_basis_agrees_with_galgebra() {
    let text = include_str!("../../tests/fixtures/galgebra/cga_blade.json");
    assert_eq!(check_file("cga_blade.json", text, "cga", Basis::Blade), 40);
}

/// The same galgebra cases give the same elements whichever basis GAM computes in: the
/// product-basis fixture's results, converted to blades, equal GAM's blade-basis results.
#[test]
fn cga_null_product_fixture_computed_in_the_blade_basis() {
    let text = include_str!("../../tests/fixtures/galgebra/cga_null_product.json");
    let doc: Value = serde_json::from_str(text).unwrap();
    let alg = builtin("cga-null");
    for (i, case) in doc["cases"].as_array().unwrap().iter().enumerate() {
        let at = format!("cga_null_product.json case {i}");
        let a = read_mv(&alg, Basis::Product, &case["a"], &at).in_basis(Basis::Blade);
        let b = read_mv(&alg, Basis::Product, &case["b"], &at).in_basis(Basis::Blade);
        let gp = read_mv(&alg, Basis::Product, &case["gp"], &at).in_basis(Basis::Blade);
        let rev = read_mv(&alg, Basis::Product, &case["rev_a"], &at).in_basis(Basis::Blade);
        assert_mv_eq(&(&a * &b), &gp, format!("{at} gp (blade basis)"));
        assert_mv_eq(&a.reverse(), &rev, format!("{at} rev_a (blade basis)"));
    }
}
