//! `gam hermite`: the contract's example spec (shared/cli.md), which is the paper's Sec. 5.1
//! (Belta and Kumar end conditions), the Sec. 5.2 specs (shape factors and pseudoscalars), the
//! JSON shape (keys, basis order, zeros omitted, shortest round-trip f64 strings, identical to
//! the library), the human form, and the error rules (one `error:` line, exit 2 or 1).

use crate::common;

use common::{CONTRACT_EXAMPLE, TempFile, fails, ok};
use motion::hermite::hermite_segment;
use motion::paper::{self, mismatches};
use motion::spec::SpecKind;
use motion::{SegmentKind, Shape};
use serde_json::Value;

use paper::BLADES;

/// `gam hermite --json` on a spec text, parsed.
fn hermite_json(name: &str, text: &str) -> Value {
    let spec = TempFile::new(&format!("{name}.json"), text);
    serde_json::from_str(&ok(&["hermite", "--json", spec.path()])).expect("valid JSON")
}

/// A multivector object as its 8 coefficients in blade order (missing keys are zero); checks
/// the keys are known, non-zero, and in basis order.
fn coeffs(mv: &Value) -> [f64; 8] {
    let obj = mv.as_object().expect("a multivector is an object");
    let mut last = None;
    let mut out = [0.0; 8];
    for (key, v) in obj {
        let i = BLADES.iter().position(|b| b == key).unwrap_or_else(|| panic!("unknown blade {key}"));
        assert!(last.is_none_or(|l| l < i), "keys out of basis order: {obj:?}");
        last = Some(i);
        let x: f64 = v.as_str().expect("coefficient string").parse().expect("f64 string");
        assert!(x != 0.0, "zero coefficient printed: {obj:?}");
        out[i] = x;
    }
    out
}

fn list(v: &Value, key: &str) -> Vec<[f64; 8]> {
    v[key].as_array().unwrap_or_else(|| panic!("no list {key}")).iter().map(coeffs).collect()
}

use paper::sec_5_1::{ADDITIVE as ADD_51, MULTIPLICATIVE as MULT_51, S0, S3 as S3_51};
use paper::sec_5_2::{ADDITIVE as ADD_52, MULTIPLICATIVE as MULT_52, S3 as S3_52};

fn spec_51(kind: &str, angle: &str) -> String {
    CONTRACT_EXAMPLE.replace("\"additive\"", &format!("\"{kind}\"")).replace("1.959", angle)
}

/// The contract's example is the paper's Sec. 5.1 (not 5.2: no shape factors or pseudoscalars
/// there). With the printed end angle 1.959 every printed value is reproduced except three,
/// each one unit off in the third decimal (S3's ω: 7.1003 printed 7.101; additive S2's e3inf
/// and ω: 6.8777 and 4.7064 printed 6.877 and 4.707); with 1.959132 (112.25°, inside the
/// rounding interval of 1.959) all of them are.
#[test]
fn contract_example_is_section_5_1() {
    let v = hermite_json("contract", CONTRACT_EXAMPLE);
    let keys: Vec<&String> = v.as_object().unwrap().keys().collect();
    assert_eq!(keys, ["control_poses", "velocity_bivectors", "velocity_indicatrices"]);
    let poses = list(&v, "control_poses");
    assert_eq!(poses.len(), 4);
    assert_eq!(mismatches(&poses[0], &S0), [""; 0]);
    assert_eq!(mismatches(&poses[1], &ADD_51[0]), [""; 0]);
    assert_eq!(mismatches(&poses[2], &ADD_51[1]), ["e3inf", "e123inf"]);
    assert_eq!(mismatches(&poses[3], &S3_51), ["e123inf"]);
    assert!(
        (poses[2][6] - 6.877).abs() < 1e-3 && (poses[2][7] - 4.707).abs() < 1e-3 && (poses[3][7] - 7.101).abs() < 1e-3
    );
    // ν = Ψ (shape 1, γ = 0): ν0 = Ω0 e123 + v0 einf, ν3 with u3 = v3 - Ω3 × r3.
    let nu = list(&v, "velocity_bivectors");
    assert_eq!(nu, [[0.0, 3.0, -2.0, 1.0, 1.0, 1.0, 1.0, 0.0], [0.0, 1.0, -1.0, 2.0, -1.0, 21.0, -9.0, 0.0]]);
    assert_eq!(list(&v, "velocity_indicatrices"), nu);
    // The exact text of the zero-free first entries.
    assert_eq!(v["control_poses"][0].to_string(), r#"{"1":"1"}"#);
    assert_eq!(
        v["velocity_bivectors"][0].to_string(),
        r#"{"e12":"3","e13":"-2","e23":"1","e1inf":"1","e2inf":"1","e3inf":"1"}"#
    );

    for (kind, printed) in [("additive", ADD_51), ("multiplicative", MULT_51)] {
        let v = hermite_json(kind, &spec_51(kind, "1.959132"));
        let poses = list(&v, "control_poses");
        for (i, want) in [&S0, &printed[0], &printed[1], &S3_51].into_iter().enumerate() {
            assert_eq!(mismatches(&poses[i], want), [""; 0], "{kind} S{i}");
        }
        if kind == "multiplicative" {
            let v = hermite_json("mult-1959", &spec_51(kind, "1.959"));
            let poses = list(&v, "control_poses");
            assert_eq!(mismatches(&poses[1], &printed[0]), [""; 0]);
            assert_eq!(mismatches(&poses[2], &printed[1]), [""; 0]);
        }
    }
}

/// The Sec. 5.2 spec (`motion::paper`) with shape factor `shape` at both ends, as JSON.
fn spec_52(kind: &str, shape: f64) -> String {
    let kind = if kind == "additive" { SpecKind::Additive } else { SpecKind::Multiplicative };
    serde_json::to_string_pretty(&paper::sec_5_2::spec(kind, shape, shape)).unwrap()
}

/// Sec. 5.2: every printed value (ν0, ν3, S0, S3, and S1, S2 for λ = 1 and λ = 4, both kinds).
#[test]
fn section_5_2() {
    for (k, shape) in [1.0, 4.0].into_iter().enumerate() {
        for (kind, printed) in [("multiplicative", &MULT_52[k]), ("additive", &ADD_52[k])] {
            let v = hermite_json(&format!("52-{kind}-{shape}"), &spec_52(kind, shape));
            let poses = list(&v, "control_poses");
            assert_eq!(mismatches(&poses[0], &S0), [""; 0]);
            assert_eq!(mismatches(&poses[1], &printed[0]), [""; 0], "{kind} λ0 = {shape} S1");
            assert_eq!(mismatches(&poses[2], &printed[1]), [""; 0], "{kind} λ3 = {shape} S2");
            assert_eq!(mismatches(&poses[3], &S3_52), [""; 0]);
            let nu = list(&v, "velocity_bivectors");
            assert_eq!(mismatches(&nu[0], &paper::sec_5_2::NU0), [""; 0]);
            assert_eq!(mismatches(&nu[1], &paper::sec_5_2::NU3), [""; 0]);
            // Ψ = λ(ν + γ).
            let psi = list(&v, "velocity_indicatrices");
            let g = [paper::sec_5_2::GAMMA0, paper::sec_5_2::GAMMA3];
            for end in 0..2 {
                let mut want = nu[end].map(|x| x * shape);
                want[0] = shape * g[end][0];
                want[7] = shape * g[end][1];
                assert_eq!(psi[end], want);
            }
        }
    }
}

/// The JSON numbers are the library's f64 results, printed shortest round-trip; higher
/// degrees give n + 1 control poses.
#[test]
fn output_is_the_library_result() {
    for (kind, name) in [(SegmentKind::Additive, "additive"), (SegmentKind::Multiplicative, "multiplicative")] {
        for degree in [3usize, 5] {
            let text = spec_52(name, 1.5).replace("\"degree\": 3", &format!("\"degree\": {degree}"));
            let v = hermite_json(&format!("lib-{name}-{degree}"), &text);
            let (a, b) = paper::sec_5_2::end_conditions();
            let seg = hermite_segment(
                kind,
                degree,
                &a,
                &b,
                &Shape::new(1.5, paper::sec_5_2::gammas()[0]),
                &Shape::new(1.5, paper::sec_5_2::gammas()[1]),
            )
            .unwrap();
            let poses = list(&v, "control_poses");
            assert_eq!(poses.len(), degree + 1);
            for (got, want) in poses.iter().zip(seg.control_poses()) {
                assert_eq!(got.to_vec(), want.components().map(|x| *x).to_vec());
            }
            // Shortest round-trip strings: re-printing the parsed value gives the same text.
            for mv in v["control_poses"].as_array().unwrap() {
                for (_, s) in mv.as_object().unwrap() {
                    let s = s.as_str().unwrap();
                    assert_eq!(s.parse::<f64>().unwrap().to_string(), s);
                }
            }
        }
    }
}

#[test]
fn defaults_and_normalised_axes() {
    // shape and gamma omitted = 1 and [0, 0]; an axis of any length is normalised.
    let explicit = spec_51("multiplicative", "1.959");
    let implicit = explicit
        .replace(",\n            \"shape\": 1, \"gamma\": [0, 0]}", "}")
        .replace(r#""axis": [1,2,3]"#, r#""axis": [10,20,30]"#)
        .replace(r#""axis": [0,0,1]"#, r#""axis": [0,0,0.25]"#);
    assert!(!implicit.contains("shape") && implicit.contains("[10,20,30]") && implicit.contains("[0,0,0.25]"));
    let a = hermite_json("explicit", &explicit);
    let b = hermite_json("implicit", &implicit);
    let (pa, pb) = (list(&a, "control_poses"), list(&b, "control_poses"));
    for (x, y) in pa.iter().zip(&pb) {
        for (p, q) in x.iter().zip(y) {
            assert!((p - q).abs() < 1e-14, "{x:?} vs {y:?}");
        }
    }
}

#[test]
fn human_output() {
    let spec = TempFile::new("human.json", CONTRACT_EXAMPLE);
    let out = ok(&["hermite", spec.path()]);
    let lines: Vec<&str> = out.lines().collect();
    assert_eq!(lines[0], "additive segment of degree 3");
    assert_eq!(lines[1], "control poses:");
    assert_eq!(lines[2], "  S0 = 1");
    assert!(lines[3].starts_with("  S1 = 1 + 0.5*e12 - 0.3333333333333333*e13 + "), "{}", lines[3]);
    assert!(out.contains("  nu0 = 3*e12 - 2*e13 + e23 + e1inf + e2inf + e3inf"), "{out}");
    assert!(out.contains("  nu3 = e12 - e13 + 2*e23 - e1inf + 21*e2inf - 9*e3inf"), "{out}");
    assert!(out.contains("  Psi3 = e12 - e13 + 2*e23 - e1inf + 21*e2inf - 9*e3inf"), "{out}");
    // --json may come after the file.
    let json = ok(&["hermite", spec.path(), "--json"]);
    assert!(json.starts_with("{\"control_poses\":["));
}

#[test]
fn input_errors() {
    let run = |name: &str, text: &str, code: i32| {
        let spec = TempFile::new(&format!("{name}.json"), text);
        fails(&["hermite", "--json", spec.path()], code)
    };
    let e = fails(&["hermite", "/nonexistent/spec.json"], 2);
    assert!(e.contains("cannot read") && e.contains("/nonexistent/spec.json"), "{e}");
    let e = run("syntax", "{\"kind\": \"additive\",\n \"degree\": 3,,\n}", 2);
    assert!(e.contains("invalid JSON") && e.contains("line 2 column 14"), "{e}");
    let e = run("eof", "{\"kind\": ", 2);
    assert!(e.contains("invalid JSON"), "{e}");
    let e = run("missing-end-field", &CONTRACT_EXAMPLE.replace(r#""velocity": [1,5,3], "#, ""), 2);
    assert!(e.contains("missing field `end.velocity`") && e.contains("line "), "{e}");
    let e = run("missing-start-field", &CONTRACT_EXAMPLE.replace(r#""angle": 0,"#, ""), 2);
    assert!(e.contains("missing field `start.angle`"), "{e}");
    let e = run("missing-kind", &CONTRACT_EXAMPLE.replace(r#""kind": "additive","#, ""), 2);
    assert!(e.contains("missing field `kind`"), "{e}");
    let e = run("zero-axis", &CONTRACT_EXAMPLE.replace(r#""axis": [1,2,3]"#, r#""axis": [0,0,0]"#), 2);
    assert!(e.contains("`end.axis` has length zero"), "{e}");
    for degree in ["0", "-1", "1", "2"] {
        let e = run("degree", &CONTRACT_EXAMPLE.replace("\"degree\": 3", &format!("\"degree\": {degree}")), 2);
        assert!(e.contains("`degree` must be an integer from 3"), "{e}");
    }
    let e = run("degree-float", &CONTRACT_EXAMPLE.replace("\"degree\": 3", "\"degree\": 3.5"), 2);
    assert!(e.contains("invalid spec") && e.contains("line 3"), "{e}");
    let e = run("kind", &CONTRACT_EXAMPLE.replace("\"additive\"", "\"linear\""), 2);
    assert!(e.contains("unknown variant `linear`"), "{e}");
    let e = run("unknown-field", &CONTRACT_EXAMPLE.replace("\"shape\": 1", "\"shap\": 1"), 2);
    assert!(e.contains("unknown field `shap`"), "{e}");
    let e = run("shape", &CONTRACT_EXAMPLE.replace("\"shape\": 1", "\"shape\": 0"), 2);
    assert!(e.contains("`start.shape` must be positive"), "{e}");
    let e = run("length", &CONTRACT_EXAMPLE.replace("[8,10,12]", "[8,10]"), 2);
    assert!(e.contains("invalid spec"), "{e}");
    let e = run("range", &CONTRACT_EXAMPLE.replace("1.959", "1e400"), 2);
    assert!(e.contains("line 7"), "{e}");
    fails(&["hermite"], 2);
    fails(&["hermite", "--bogus", "x.json"], 2);
    // A mathematical failure: exp overflows (exit 1), or the additive result does.
    let e = run(
        "overflow",
        &CONTRACT_EXAMPLE.replace("\"additive\"", "\"multiplicative\"").replace("[0, 0]", "[1e4, 0]"),
        1,
    );
    assert!(e.contains("not finite"), "{e}");
    let e = run(
        "overflow-add",
        &CONTRACT_EXAMPLE.replace("[1,1,1]", "[1e308,1,1]").replace("\"shape\": 1", "\"shape\": 100"),
        1,
    );
    assert!(e.contains("not finite"), "{e}");
}
