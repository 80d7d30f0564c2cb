//! The main paper's eqs. (5)-(9) through the command line: `gam eval --algebra cga-null
//! --basis product --scalar poly --json "rev(S)*x*S"` for a fully symbolic even S of
//! G_{123inf} must print exactly the paper's polynomials (typed in from the paper in
//! `gam_verify::cross2022::formulas`).

use algebra_core::Poly;
use gam_verify::cross2022::formulas::{eq5, eq6, eq7, eq8, eq9_vector_part, symbolic_s_expr};
use serde_json::{Map, Value};
use std::process::Command;

fn eval_poly(expr: &str) -> Map<String, Value> {
    let out = Command::new(env!("CARGO_BIN_EXE_gam"))
        .args(["eval", "--algebra", "cga-null", "--basis", "product", "--scalar", "poly", "--json", expr])
        .output()
        .expect("gam runs");
    assert!(out.status.success(), "gam failed: {}", String::from_utf8_lossy(&out.stderr));
    match serde_json::from_slice(&out.stdout).expect("one JSON value") {
        Value::Object(m) => m,
        other => panic!("expected an object, got {other}"),
    }
}

fn as_strings(expected: Vec<(&str, Poly)>) -> Map<String, Value> {
    expected.into_iter().map(|(k, p)| (k.to_string(), Value::String(p.to_string()))).collect()
}

#[test]
fn eq_5_rev_s_s() {
    let s = symbolic_s_expr();
    assert_eq!(eval_poly(&format!("rev({s})*{s}")), as_strings(eq5()));
}

#[test]
fn eqs_6_7_8_rev_s_ei_s() {
    let s = symbolic_s_expr();
    for (x, eq) in [("e1", eq6()), ("e2", eq7()), ("e3", eq8())] {
        let got = eval_poly(&format!("rev({s})*{x}*{s}"));
        assert_eq!(got, as_strings(eq), "x = {x}");
        // key order is the algebra's basis order
        let keys: Vec<&String> = got.keys().collect();
        assert_eq!(keys, ["e1", "e2", "e3", "einf"]);
    }
}

#[test]
fn eq_9_vector_part_of_rev_s_e0_s() {
    let s = symbolic_s_expr();
    let got = eval_poly(&format!("bgrade(rev({s})*e0*{s}, 1)"));
    assert_eq!(got, as_strings(eq9_vector_part()));
    // The rest is λσ with σ = -e123 + e0123inf (Lemma 2.2(i)).
    let rest = eval_poly(&format!("rev({s})*e0*{s} - bgrade(rev({s})*e0*{s}, 1)"));
    let keys: Vec<&String> = rest.keys().collect();
    assert_eq!(keys, ["e123", "e0123inf"]);
    // coefficient of e123 is -λ: gam's canonical print of -(λ) must match it
    let lambda = rest["e0123inf"].as_str().unwrap();
    let minus_lambda = eval_poly(&format!("-({lambda})*e1"));
    assert_eq!(rest["e123"], minus_lambda["e1"]);
}
