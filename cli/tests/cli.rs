//! End-to-end tests of the `gam` binary: the contract's examples (shared/cli.md), every
//! scalar type, tables, and the error rules (one `error:` line, exit 2 or 1, empty stdout).

use crate::common;

use common::{TempFile, fails, gam, ok};
use serde_json::Value;

/// `gam eval --json ARGS...` parsed as JSON.
fn eval_json(args: &[&str]) -> Value {
    let mut all = vec!["eval", "--json"];
    all.extend_from_slice(args);
    serde_json::from_str(&ok(&all)).expect("valid JSON")
}

#[test]
fn contract_example() {
    let out = gam(&["eval", "--algebra", "cga-null", "--basis", "product", "--json", "e1*e2*e3*einf*e0"]);
    assert!(out.status.success());
    assert_eq!(String::from_utf8(out.stdout).unwrap(), "{\"e123\":\"-2\",\"e0123inf\":\"1\"}\n");
    assert!(out.stderr.is_empty());
}

#[test]
fn null_vectors() {
    assert_eq!(ok(&["eval", "--basis", "product", "--json", "einf*e0"]), r#"{"1":"-2","e0inf":"-1"}"#);
    assert_eq!(ok(&["eval", "--json", "e0*e0"]), "{}");
    assert_eq!(ok(&["eval", "--json", "e0*einf"]), r#"{"1":"-1","e0inf":"1"}"#);
    // default algebra cga-null and basis blade; human form
    assert_eq!(ok(&["eval", "einf*e0"]), "-1 - e0inf");
    assert_eq!(ok(&["eval", "--basis", "product", "einf*e0"]), "-2 - e0inf");
    assert_eq!(ok(&["eval", "--basis", "product", "~e0inf"]), "-2 - e0inf");
    assert_eq!(ok(&["eval", "e0*e0"]), "0");
}

#[test]
fn sigma_products() {
    let sym = r#"{"e123":"-1","e0123inf":"1"}"#;
    let args = |e| ["eval", "--basis", "product", "--json", e];
    assert_eq!(ok(&args("(e0*e123inf + e123inf*e0)/2")), sym);
    assert_eq!(ok(&args("acomm(e0, e123inf)")), sym);
    let comm = ok(&args("comm(e0, e123inf)"));
    assert_eq!(comm, ok(&args("(e0*e123inf - e123inf*e0)/2")));
    assert_eq!(ok(&args("comm(e0, e123inf) + acomm(e0, e123inf)")), ok(&args("e0*e123inf")));
}

#[test]
fn grammar() {
    let g3 = |e| ok(&["eval", "--algebra", "g3", e]);
    assert_eq!(g3("1/2*e1 + 0.25*e2"), "1/2*e1 + 1/4*e2");
    assert_eq!(g3("e1^e2*e3"), "e123");
    assert_eq!(g3("e1*e2^e3"), "e123");
    assert_eq!(g3("e1 + e2^e1"), "e1 - e12");
    assert_eq!(g3("-e1^e2"), "-e12");
    assert_eq!(g3("~(e1*e2)"), "-e12");
    assert_eq!(g3("~e1^e2"), "e12"); // prefix binds tighter than ^
    assert_eq!(g3("2 - 3 - 4"), "-5");
    assert_eq!(g3("e12/e1"), "-e2");
    assert_eq!(g3("grade(1 + e1 + e12, 2)"), "e12");
    assert_eq!(g3("grade(1 + e1, 9)"), "0");
    assert_eq!(g3("lc(e1, e12) + rc(e12, e2) + sp(e1 + e2, e1)"), "1 + e1 + e2");
    assert_eq!(g3("dual(e1)"), "e23");
    assert_eq!(g3("undual(dual(e1 + e12))"), "e1 + e12");
    assert_eq!(g3("involute(1 + e1 + e12) + conj(e123)"), "1 - e1 + e12 + e123");
    assert_eq!(g3("gp(e1, e2) + op(e2, e1) + rp(e12, e23)"), "e2");
    assert_eq!(g3("inv(1 + e1*2)"), "-1/3 + 2/3*e1");
    // options after EXPR, and expressions starting with '-'
    assert_eq!(ok(&["eval", "-e1", "--algebra", "g3"]), "-e1");
    assert_eq!(ok(&["eval", "--algebra", "g3", "--", "-e1"]), "-e1");
    assert_eq!(ok(&["eval", "--algebra=g3", "--json", "-2*e3"]), r#"{"e3":"-2"}"#);
}

#[test]
fn product_basis_grades() {
    let p = |e| ok(&["eval", "--basis", "product", e]);
    assert_eq!(p("grade(e0inf, 0)"), "-1");
    assert_eq!(p("grade(e0inf, 2)"), "1 + e0inf");
    assert_eq!(p("bgrade(e0inf, 2)"), "e0inf");
    assert_eq!(p("brev(e0inf)"), "-e0inf");
    assert_eq!(p("rev(e0inf)"), "-2 - e0inf");
}

#[test]
fn poly_scalars() {
    let v = eval_json(&["--algebra", "g3", "--scalar", "poly", "(a*e1 + b*e2)*(a*e1 + b*e2)"]);
    assert_eq!(v.to_string(), r#"{"1":"a**2 + b**2"}"#);
    let v = eval_json(&["--algebra", "g3", "--scalar", "poly", "x/2*e1 + S12^e2 - e1/(2*e1)"]);
    assert_eq!(v.to_string(), r#"{"1":"-1/2","e1":"1/2*x","e2":"S12"}"#);
    let h = ok(&["eval", "--algebra", "g3", "--scalar", "poly", "(x + 1)*e1 - y*y"]);
    assert_eq!(h, "-y**2 + (x + 1)*e1");
    let e = fails(&["eval", "--algebra", "g3", "--scalar", "poly", "e1/x"], 2);
    assert!(e.contains("column 3"), "{e}");
    fails(&["eval", "--algebra", "g3", "--scalar", "poly", "inv(x*e1)"], 2);
    fails(&["eval", "--scalar", "poly", "x/e0"], 1);
}

#[test]
fn f64_exp() {
    let v = eval_json(&["--algebra", "g3", "--scalar", "f64", "exp(e12*0.5)"]);
    let c = |k: &str| v[k].as_str().expect("string").parse::<f64>().expect("f64");
    assert!((c("1") - 0.5f64.cos()).abs() < 1e-15, "{v}");
    assert!((c("e12") - 0.5f64.sin()).abs() < 1e-15, "{v}");
    assert_eq!(v.as_object().unwrap().len(), 2);
    // shortest round-trip decimals
    assert_eq!(ok(&["eval", "--algebra", "g3", "--scalar", "f64", "0.1 + 0.2"]), "0.30000000000000004");
    let v = eval_json(&["--algebra", "g3", "--scalar", "f64", "log(exp(e12*0.5))"]);
    assert!((v["e12"].as_str().unwrap().parse::<f64>().unwrap() - 0.5).abs() < 1e-15, "{v}");
}

#[test]
fn mpfr_sqrt2() {
    let v = eval_json(&["--algebra", "g3", "--scalar", "mpfr:256", "sqrt(2)"]);
    let s = v["1"].as_str().expect("string");
    let reference = "1.41421356237309504880168872420969807856967187537694807317667973799073247846210";
    assert!(s.starts_with(&reference[..72]), "{s}");
    let v = eval_json(&["--algebra", "g3", "--scalar", "mpfr:256", "1/3"]);
    assert!(
        v["1"]
            .as_str()
            .unwrap()
            .starts_with("3.33333333333333333333333333333333333333333333333333333333333333333333333")
    );
}

#[test]
fn tables() {
    let v: Value = serde_json::from_str(&ok(&["table", "--algebra", "g3", "--json"])).unwrap();
    let list = v.as_array().expect("list");
    assert_eq!(list.len(), 64);
    let find = |list: &[Value], a: &str, b: &str| {
        list.iter().find(|e| e["a"] == a && e["b"] == b).map(|e| e["result"].to_string()).expect("entry")
    };
    assert_eq!(find(list, "e1", "e2"), r#"{"e12":"1"}"#);
    assert_eq!(list[0].to_string(), r#"{"a":"1","b":"1","result":{"1":"1"}}"#);
    let v: Value = serde_json::from_str(&ok(&[
        "table",
        "--algebra",
        "cga-null",
        "--basis",
        "product",
        "--product",
        "gp",
        "--json",
    ]))
    .unwrap();
    let list = v.as_array().expect("list");
    assert_eq!(list.len(), 1024);
    assert_eq!(find(list, "einf", "e0"), r#"{"1":"-2","e0inf":"-1"}"#);
    let v: Value = serde_json::from_str(&ok(&["table", "--algebra", "g3", "--product", "op", "--json"])).unwrap();
    assert_eq!(find(v.as_array().unwrap(), "e1", "e1"), "{}");
    // human table: a title, a header, a rule, one row per basis element, aligned
    let t = ok(&["table", "--algebra", "g3"]);
    let lines: Vec<&str> = t.lines().collect();
    assert_eq!(lines.len(), 11);
    assert!(lines[1].starts_with("     | 1 "), "{t}");
    assert!(lines[5].starts_with("e2   | e2    -e12  1 "), "{t}");
}

#[test]
fn algebras_list() {
    let human = ok(&["algebras"]);
    for name in ["g3", "g123inf", "pga3", "cga", "cga-null"] {
        assert!(human.lines().any(|l| l.starts_with(name)), "{human}");
    }
    assert!(human.contains("e0.einf = -1"));
    let v: Value = serde_json::from_str(&ok(&["algebras", "--json"])).unwrap();
    let cga_null = v.as_array().unwrap().iter().find(|a| a["name"] == "cga-null").expect("cga-null");
    assert_eq!(cga_null["labels"].to_string(), r#"["0","1","2","3","inf"]"#);
    assert_eq!(cga_null["gram"][0].to_string(), r#"["0","0","0","0","-1"]"#);
    assert_eq!(cga_null["dimension"], 5);
}

#[test]
fn toml_algebra() {
    let f = TempFile::new("h.toml", "generators = [\"a\", \"b\"]\nmetric = { \"a,b\" = \"1/2\" }\n");
    assert_eq!(ok(&["eval", "--algebra", f.path(), "--json", "ea*eb + eb*ea"]), r#"{"1":"1"}"#);
    assert_eq!(ok(&["eval", "--algebra", f.path(), "ea*ea + eab"]), "eab");
    let v: Value = serde_json::from_str(&ok(&["table", "--algebra", f.path(), "--json"])).unwrap();
    assert_eq!(v.as_array().unwrap().len(), 16);
    assert!(ok(&["algebras", f.path()]).contains("ea.eb = 1/2"));
}

#[test]
fn usage_errors_exit_2() {
    let e = fails(&["eval", "--algebra", "g3", "e9"], 2);
    assert!(e.contains("e9") && e.contains("1, 2, 3"), "{e}");
    let e = fails(&["eval", "e1 * (e2 + "], 2);
    assert!(e.contains("column 12"), "{e}");
    let e = fails(&["eval", "e1 + foo(e2)"], 2);
    assert!(e.contains("foo") && e.contains("column 6"), "{e}");
    fails(&["eval", "--basis", "blades", "e1"], 2);
    fails(&["eval", "--algebra", "nope", "e1"], 2);
    fails(&["eval", "--scalar", "mpfr:x", "e1"], 2);
    fails(&["eval", "--scalar", "mpfr:1", "e1"], 2);
    fails(&["eval", "--scalar", "float", "e1"], 2);
    fails(&["eval", "grade(e1)"], 2);
    fails(&["eval", "grade(e1, e2)"], 2);
    fails(&["eval", "exp(e1)"], 2);
    fails(&["eval", "rev"], 2);
    fails(&["eval", "2 e1"], 2);
    fails(&["eval", "2einf"], 2);
    fails(&["eval", "x"], 2);
    fails(&["eval"], 2);
    fails(&["eval", "e1", "e2"], 2);
    fails(&["eval", "--jsn", "e1"], 2);
    fails(&["table", "--product", "xp"], 2);
    fails(&[], 2);
    fails(&["frobnicate"], 2);
}

#[test]
fn bad_algebra_files_exit_2() {
    let broken = TempFile::new("broken.toml", "generators = [\"a\", \"b\"\n");
    fails(&["eval", "--algebra", broken.path(), "ea"], 2);
    let asym = TempFile::new("asym.toml", "generators = [\"a\", \"b\"]\ngram = [[1, 2], [3, 1]]\n");
    let e = fails(&["eval", "--algebra", asym.path(), "ea"], 2);
    assert!(e.contains("symmetric"), "{e}");
    fails(&["table", "--algebra", asym.path()], 2);
    fails(&["eval", "--algebra", "/nonexistent/gam.toml", "e1"], 2);
    // a file's algebra never takes a built-in's name (its description and module name)
    let shadow =
        TempFile::new("shadow.toml", "name = \"pga3\"\ngenerators = [\"a\", \"b\"]\ngram = [[1, 0], [0, 1]]\n");
    for args in [
        vec!["algebras", shadow.path()],
        vec!["eval", "--algebra", shadow.path(), "ea"],
        vec!["codegen", "--algebra", shadow.path(), "--types", "V=grade1"],
    ] {
        let e = fails(&args, 2);
        assert!(e.contains("`name = \"pga3\"` is a built-in algebra's name") && e.contains("shadow.toml"), "{e}");
    }
    // labels that spell Rust keywords are prefixed (`efn`, `eself`), so the module compiles
    let kw = TempFile::new("kw.toml", "generators = [\"fn\", \"self\"]\ngram = [[1, 0], [0, 1]]\n");
    let module = ok(&["codegen", "--algebra", kw.path(), "--types", "V=grade1"]);
    assert!(module.contains("pub efn: T") && module.contains("pub eself: T"), "{module}");
}

#[test]
fn math_errors_exit_1() {
    let e = fails(&["eval", "1/e0"], 1);
    assert!(e.contains("not invertible") && e.contains("column 2"), "{e}");
    fails(&["eval", "inv(e0)"], 1);
    fails(&["eval", "--basis", "product", "inv(2 + e0inf)"], 1);
    fails(&["eval", "e1/0"], 1);
    fails(&["eval", "--algebra", "g3", "--scalar", "f64", "log(-1)"], 1);
    fails(&["eval", "--algebra", "g3", "--scalar", "f64", "sqrt(-1)"], 1);
    fails(&["eval", "--algebra", "g3", "--scalar", "mpfr:128", "log(0)"], 1);
    fails(&["eval", "--algebra", "g3", "--scalar", "f64", "exp(1000)"], 1);
}

#[test]
fn help_and_version_succeed() {
    assert!(ok(&["--help"]).contains("eval"));
    assert!(ok(&["eval", "--help"]).contains("--scalar"));
    assert!(ok(&["--version"]).starts_with("gam "));
    // every interpolation method is named in `gam interpolate --help`
    let help = ok(&["interpolate", "--help"]);
    for m in motion::method::Method::ALL {
        assert!(help.contains(m.name()), "`gam interpolate --help` does not list {}", m.name());
    }
}

#[test]
fn numbers_take_an_exponent() {
    let g3 = |scalar, e| ok(&["eval", "--algebra", "g3", "--scalar", scalar, e]);
    // exact under rational: 2.5E3 = 2500, 6e-17 = 6/10^17, 1e+3 = 1000
    assert_eq!(g3("rational", "2.5E3*e1"), "2500*e1");
    assert_eq!(g3("rational", "6e-17"), "3/50000000000000000");
    assert_eq!(g3("rational", "1e+3 - 1000"), "0");
    assert_eq!(g3("rational", ".5E1"), "5");
    // `2e1` could mean 2*e1 or 20: refused as ambiguous, the message offers both spellings
    let msg = fails(&["eval", "--algebra", "g3", "2e1"], 2);
    assert!(msg.contains("ambiguous") && msg.contains("`2*e1`") && msg.contains("`2e+1`"), "{msg}");
    let msg = fails(&["eval", "--algebra", "cga", "--scalar", "f64", "3.5e5"], 2);
    assert!(msg.contains("ambiguous") && msg.contains("basis element `e5`"), "{msg}");
    // g3 has no `e5`: the refusal names only the number's spellings, not a basis element `e5`
    let msg = fails(&["eval", "--algebra", "g3", "2e5"], 2);
    assert!(msg.contains("`2e+5` or `2E5`") && msg.contains("this algebra has no `e5`"), "{msg}");
    assert!(!msg.contains("ambiguous") && !msg.contains("`2*e5`"), "{msg}");
    assert_eq!(g3("rational", "2e+1"), "20");
    assert_eq!(g3("rational", "2*e1"), "2*e1");
    assert_eq!(g3("rational", "2E1*e1"), "20*e1");
    // f64: the literal as Rust (and C) read it
    assert_eq!(g3("f64", "6e-17*e2"), "6e-17*e2");
    assert_eq!(g3("f64", "2.5e+2*e1"), "250*e1");
    // the exponent cap of exact literals, and an f64 literal that overflows
    assert!(fails(&["eval", "--scalar", "rational", "1e+100001"], 2).contains("exponent"));
    assert!(fails(&["eval", "--algebra", "g3", "--scalar", "f64", "1E400*e1"], 1).contains("not finite"));
    // an `e` without digits starts a name: still an error, not a number
    fails(&["eval", "--algebra", "g3", "2e"], 2);
    fails(&["eval", "--algebra", "g3", "2e+"], 2);
}

#[test]
fn exp_refusals_say_why() {
    // a rotor angle of 1e300: θ² overflows (the unit rotor itself cannot)
    let line = fails(&["eval", "--algebra", "g3", "--scalar", "f64", "exp(1e+300*e12)"], 1);
    assert!(line.contains("the rotation angle is too large for this scalar"), "{line}");
    // e^1000 (cos 1 + e12 sin 1) does overflow
    let line = fails(&["eval", "--algebra", "g3", "--scalar", "f64", "exp(1000 + e12)"], 1);
    assert!(line.contains("the result overflows"), "{line}");
}

#[test]
fn an_overflowing_f64_literal_is_not_finite_not_inf() {
    let big = format!("1{}*e1", "0".repeat(400));
    let line = fails(&["eval", "--algebra", "g3", "--scalar", "f64", big.as_str()], 1);
    assert!(line.contains("not finite (overflow)"), "{line}");
}
