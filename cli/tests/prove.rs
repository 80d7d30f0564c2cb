//! `gam prove` and the relations / `diff` of `gam eval` (shared/cli.md, Wave 2 contract).

use crate::common;
use common::{fails, gam, ok, one_error_line};
use serde_json::Value;

const NULL_CLAIM: &str = r#"let X = even("S"); (rev(X)*e0*X)*(rev(X)*e0*X) = 0"#;

#[test]
fn contract_example_holds_with_the_unitarity_hypothesis() {
    let args =
        ["prove", "--algebra", "cga-null", "--basis", "product", "--assume", "rev(X)*X = 1", "--json", NULL_CLAIM];
    let v: Value = serde_json::from_str(&ok(&args)).unwrap();
    assert_eq!(v["holds"], true);
    assert_eq!(v["method"], "groebner");
    assert!(v["basis_size"].as_u64().unwrap() > 0);
    assert!(v["time_ms"].is_u64());
    assert!(v["witness"].is_null());
    let human = ok(&args[..args.len() - 2].iter().copied().chain([NULL_CLAIM]).collect::<Vec<_>>());
    assert!(human.starts_with("holds: "), "{human}");
}

#[test]
fn contract_example_fails_without_the_hypothesis_with_a_witness() {
    let args = ["prove", "--algebra", "cga-null", "--basis", "product", "--json", NULL_CLAIM];
    let out = gam(&args);
    assert_eq!(out.status.code(), Some(1));
    let line = one_error_line(&args, &String::from_utf8_lossy(&out.stderr));
    assert!(line.contains("does not follow"), "{line}");
    let v: Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["holds"], false);
    // The witness point makes the scalar component non-zero: check it independently with
    // `gam eval` at that point (each symbol replaced by its integer).
    let w = &v["witness"];
    assert_eq!(w["component"], "1");
    let point = w["point"].as_object().unwrap();
    let terms: Vec<String> = point
        .iter()
        .map(|(sym, x)| {
            let label = sym.strip_prefix('S').unwrap();
            if label.is_empty() { format!("({x})") } else { format!("({x})*e{label}") }
        })
        .collect();
    let x = format!("({})", terms.join(" + "));
    let claim = format!("(rev({x})*e0*{x})*(rev({x})*e0*{x})");
    let value: Value =
        serde_json::from_str(&ok(&["eval", "--algebra", "cga-null", "--basis", "product", "--json", &claim])).unwrap();
    assert!(value.get("1").is_some_and(|c| c != "0"), "{value}");
}

#[test]
fn nonvanishing_hypotheses_and_witness_points() {
    let holds = ok(&["prove", "--assume", "x != 0", "--assume", "x*x = x*y", "--json", "x = y"]);
    assert_eq!(serde_json::from_str::<Value>(&holds).unwrap()["holds"], true);
    let args = ["prove", "--assume", "x*x = x*y", "--json", "x = y"];
    let out = gam(&args);
    assert_eq!(out.status.code(), Some(1));
    let v: Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["witness"]["normal_form"], "x - y");
    // Without equations the witness is a point where the claim is non-zero: x = -5, y = 2 here.
    let args = ["prove", "--assume", "x != 0", "--json", "x*x = y"];
    let out = gam(&args);
    let v: Value = serde_json::from_slice(&out.stdout).unwrap();
    let (x, y) = (v["witness"]["point"]["x"].as_i64().unwrap(), v["witness"]["point"]["y"].as_i64().unwrap());
    assert!(x != 0 && x * x != y);
}

#[test]
fn builders_name_their_symbols_in_the_chosen_basis() {
    // The Plücker condition: a general PGA bivector B has B ^ B = 2 (P01 P23 - P02 P13 + P03 P12) e0123.
    let args = ["prove", "--algebra", "pga3", "--json", r#"grade("P", 2) ^ grade("P", 2) = 0"#];
    let out = gam(&args);
    assert_eq!(out.status.code(), Some(1));
    let v: Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["witness"]["component"], "e0123");
    assert_eq!(v["witness"]["normal_form"], "2*P01*P23 - 2*P02*P13 + 2*P03*P12");
    // ... and under the Plücker hypothesis it holds.
    let plucker = "P01*P23 - P02*P13 + P03*P12 = 0";
    let r = ok(&["prove", "--algebra", "pga3", "--assume", plucker, r#"grade("P", 2) ^ grade("P", 2) = 0"#]);
    assert!(r.starts_with("holds"), "{r}");
    // A vector of g3 squares to its norm.
    ok(&["prove", "--algebra", "g3", r#"vector("v")*vector("v") = v1*v1 + v2*v2 + v3*v3"#]);
    ok(&["prove", "--algebra", "g3", r#"let A = all("a"); rev(rev(A)) = A"#]);
    ok(&["prove", "--algebra", "g3", r#"odd("a") = grade("a", 1) + grade("a", 3)"#]);
}

#[test]
fn malformed_claims_exit_2_with_one_error_line() {
    let cases: [&[&str]; 9] = [
        &["prove", "let X = even(\"S\"); X = "],
        &["prove", "let X = even(\"S\"); X"],
        &["prove", "x != 0"],
        &["prove", "let S = even(\"S\"); S = S"],
        &["prove", "let e1 = 2; e1 = 2"],
        &["prove", "even(\"1S\") = 0"],
        &["prove", "--assume", "e1 != 0", "x = x"],
        &["prove", "let X = 1"],
        &["prove", "x = y = z"],
    ];
    for args in cases {
        fails(args, 2);
    }
    let line = fails(&["prove", "--timeout", "0", "x = x"], 2);
    assert!(line.contains("--timeout"), "{line}");
}

#[test]
fn undecided_within_budget_is_exit_1_never_a_hang() {
    // A tiny time budget on a large system.
    let args = [
        "prove",
        "--algebra",
        "cga",
        "--timeout",
        "0.000001",
        "--assume",
        "rev(X)*X = 1",
        "--assume",
        "X*Y = Y*X + 1",
        r#"let X = all("S"); let Y = all("T"); X*Y*X = Y"#,
    ];
    let out = gam(&args);
    assert_eq!(out.status.code(), Some(1));
    let line = one_error_line(&args, &String::from_utf8_lossy(&out.stderr));
    assert!(line.contains("undecided within budget"), "{line}");
}

#[test]
fn a_degree_past_the_engine_is_undecided_exit_1() {
    // x**40000 is past the packed monomials' 32767: undecided, not a budget option to raise;
    // x**30000 is within it and decided.
    let args = ["prove", "--algebra", "g3", "--assume", "x = 0", "x**40000 = 0"];
    let out = gam(&args);
    assert_eq!(out.status.code(), Some(1));
    let line = one_error_line(&args, &String::from_utf8_lossy(&out.stderr));
    assert!(line.contains("undecided within budget: degree limit") && line.contains("32767"), "{line}");
    assert!(!line.contains("--timeout"), "{line}");
    assert!(ok(&["prove", "--algebra", "g3", "--assume", "x = 0", "x**30000 = 0"]).starts_with("holds"));
}

#[test]
fn eval_relations_and_diff() {
    assert_eq!(ok(&["eval", "--scalar", "poly", "(a+b)*(a+b) == a*a + 2*a*b + b*b"]), "true");
    assert_eq!(ok(&["eval", "--scalar", "poly", "a*e1 != b*e1"]), "true");
    assert_eq!(ok(&["eval", "--json", "e1*e1 == 1"]), r#"{"value":true}"#);
    let out = gam(&["eval", "--scalar", "poly", "a*e1 == b*e1"]);
    assert_eq!(out.status.code(), Some(1));
    assert_eq!(String::from_utf8_lossy(&out.stdout), "false\n");
    assert_eq!(ok(&["eval", "--scalar", "poly", "diff(x*x*x*e1 + x*y, x)"]), "y + 3*x**2*e1");
    assert_eq!(ok(&["eval", "--scalar", "poly", "diff(x*y, z)"]), "0");
    fails(&["eval", "diff(2, x)"], 2);
    fails(&["eval", "--scalar", "poly", "diff(x, 2)"], 2);
    fails(&["eval", "--scalar", "f64", "1 == 1"], 2);
    fails(&["eval", "--scalar", "poly", "a = b"], 2);
}
