//! Issue 30 end to end: no wrong answer and no infinity printed at the edges of f64, a closed
//! standard output is an error. References: mpmath (tests/fixtures/mpmath/edge_scale.json,
//! whose values are quoted here) and hand computations.

use crate::common;

use common::{TempFile, fails, gam, ok};
use serde_json::Value;

fn coeff(v: &Value, k: &str) -> f64 {
    v[k].as_str().unwrap_or_else(|| panic!("{k} in {v}")).parse().unwrap()
}

#[test]
fn log_and_sqrt_of_tiny_elements() {
    let v: Value =
        serde_json::from_str(&ok(&["eval", "--json", "--algebra", "g3", "--scalar", "f64", "log(1E-200+1E-200*e12)"]))
            .unwrap();
    // mpmath: -4.601704450085291641667894e+2 + 7.853981633974483096156608e-1 e12 (= π/4)
    assert!((coeff(&v, "1") + 460.170_445_008_529_16).abs() < 1e-12, "{v}");
    assert!((coeff(&v, "e12") - std::f64::consts::FRAC_PI_4).abs() < 1e-15, "{v}");
    let v: Value =
        serde_json::from_str(&ok(&["eval", "--json", "--algebra", "g3", "--scalar", "f64", "sqrt(1E-200+1E-200*e12)"]))
            .unwrap();
    // mpmath: 1.098684113467809956206723e-100 + 4.550898605622273372313632e-101 e12
    assert!((coeff(&v, "1") / 1.098_684_113_467_81e-100 - 1.0).abs() < 1e-14, "{v}");
    assert!((coeff(&v, "e12") / 4.550_898_605_622_273e-101 - 1.0).abs() < 1e-14, "{v}");
    // 1e-200 (1 + e1) is a zero divisor: no logarithm (exit 1), never the nilpotent branch's value
    let e = fails(&["eval", "--algebra", "g3", "--scalar", "f64", "log(1E-200+1E-200*e1)"], 1);
    // the message names the value in exponent notation (it printed 1e-200 as 200 zeros)
    assert!(e.contains("log is not defined for 1e-200 + 1e-200*e1: no real logarithm"), "{e}");
}

#[test]
fn tiny_angles_and_tiny_motors_are_poses() {
    let v: Value = serde_json::from_str(&ok(&["pose", "--json", r#"{"axis":[0,0,1],"angle":1e-200}"#])).unwrap();
    assert!((v["angle"].as_f64().unwrap() / 1e-200 - 1.0).abs() < 1e-15, "{v}");
    assert_eq!(v["axis"], serde_json::json!([0.0, 0.0, 1.0]));
    for motor in [r#"{"motor":{"1":1e-300}}"#, r#"{"motor":{"1":1e-300,"e12":1e-300}}"#] {
        let v: Value = serde_json::from_str(&ok(&["pose", "--json", motor])).unwrap();
        let m = v["matrix"].as_array().unwrap();
        assert_eq!(m.len(), 4, "{v}");
    }
    // the quarter turn 1e-300 (1 + e12): e1 -> e2 (hand computation)
    let v: Value = serde_json::from_str(&ok(&["pose", "--json", r#"{"motor":{"1":1e-300,"e12":1e-300}}"#])).unwrap();
    assert!((v["matrix"][1][0].as_f64().unwrap() - 1.0).abs() < 1e-15, "{v}");
    assert!((v["angle"].as_f64().unwrap() - std::f64::consts::FRAC_PI_2).abs() < 1e-15, "{v}");
    // a dual quaternion c ((1 + k) + ε i) at any scale: the quarter turn about z, then the
    // translation 2 Q^ε Q̃⁰/|Q⁰|² = (1, 1, 0) (hand computation); below c ≈ 1e-154 it was
    // refused as "a zero real part" (|Q⁰|² underflowed)
    for c in ["1", "1e-200", "1e-300", "1e300"] {
        let pose = format!(r#"{{"dual_quaternion": [{c}, 0, 0, {c}, 0, {c}, 0, 0]}}"#);
        let v: Value = serde_json::from_str(&ok(&["pose", "--json", &pose])).unwrap();
        let m = common::matrix(&v["matrix"]);
        let want = [[0.0, -1.0, 0.0, 1.0], [1.0, 0.0, 0.0, 1.0], [0.0, 0.0, 1.0, 0.0], [0.0, 0.0, 0.0, 1.0]];
        assert!(common::max_diff(&m, &want) < 1e-15, "{c}: {v}");
    }
}

#[test]
fn no_infinity_from_parameters_1e300_apart() {
    let spec = TempFile::new(
        "edge-spline-1e-300.json",
        r#"{"method": "juttler-spline", "poses": [{"position": [0,0,0]}, {"position": [1,0,0]}, {"position": [1,1,0], "axis": [0,0,1], "angle": 1}], "parameters": [0, 1e-300, 1]}"#,
    );
    for json in [false, true] {
        let mut args = vec!["interpolate"];
        if json {
            args.push("--json");
        }
        args.push(spec.path());
        let out = gam(&args);
        let stdout = String::from_utf8_lossy(&out.stdout);
        let stderr = String::from_utf8_lossy(&out.stderr);
        if out.status.success() {
            for w in ["inf", "NaN"] {
                assert!(!stdout.split(|c: char| !c.is_ascii_alphanumeric()).any(|t| t == w), "{w} printed: {stdout}");
            }
        } else {
            assert_eq!(out.status.code(), Some(1), "{stderr}");
            assert!(stdout.is_empty() && stderr.lines().count() == 1 && stderr.starts_with("error: "), "{stderr}");
        }
    }
}

#[test]
fn ccm_multiplicative_through_non_unit_dual_quaternions() {
    let run = |poses: &str| {
        let spec = TempFile::new(
            &format!("edge-ccm-mult-{}.json", poses.len()),
            &format!(r#"{{"method": "ccm-multiplicative", "poses": {poses}}}"#),
        );
        let v: Value = serde_json::from_str(&ok(&["sample", "--samples", "5", "--json", spec.path()])).unwrap();
        v["samples"].as_array().unwrap().iter().map(|s| s["position"].clone()).collect::<Vec<_>>()
    };
    // [2,0,0,0,0,1,0,0] is twice the unit [1,0,0,0,0,1/2,0,0]: the same pose
    let scaled = run(
        r#"[{"dual_quaternion": [1,0,0,0,0,0,0,0]}, {"dual_quaternion": [2,0,0,0,0,1,0,0]}, {"dual_quaternion": [-3,0,0,0,0,-1.5,-1.5,0]}]"#,
    );
    let unit = run(
        r#"[{"dual_quaternion": [1,0,0,0,0,0,0,0]}, {"dual_quaternion": [1,0,0,0,0,0.5,0,0]}, {"dual_quaternion": [1,0,0,0,0,0.5,0.5,0]}]"#,
    );
    assert_eq!(scaled.len(), unit.len());
    for (a, b) in scaled.iter().zip(&unit) {
        for k in 0..3 {
            assert!((a[k].as_f64().unwrap() - b[k].as_f64().unwrap()).abs() < 1e-12, "{a} vs {b}");
        }
    }
}

#[test]
fn a_closed_stdout_is_an_error() {
    let bin = env!("CARGO_BIN_EXE_gam");
    for cmd in ["eval e1", "algebras", "pose '{\"position\":[1,2,3]}'"] {
        let out =
            std::process::Command::new("sh").arg("-c").arg(format!("exec '{bin}' {cmd} >&-")).output().expect("run sh");
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "gam {cmd}: {stderr}");
        assert_eq!(stderr.lines().count(), 1, "{stderr}");
        assert!(stderr.starts_with("error: ") && stderr.contains("closed"), "{stderr}");
    }
    // an output sent to /dev/null on purpose is no error
    let out =
        std::process::Command::new("sh").arg("-c").arg(format!("exec '{bin}' eval e1 >/dev/null")).output().unwrap();
    assert_eq!(out.status.code(), Some(0), "{}", String::from_utf8_lossy(&out.stderr));
}

#[test]
fn keyword_type_names_are_refused_clearly() {
    let e = fails(&["codegen", "--algebra", "g3", "--types", "Self=grade1"], 2);
    assert!(e.contains("--types: `Self` is a Rust keyword"), "{e}");
    for types in ["fn=grade 1", "r#type=grade 1", "Even=even;Self=grade 2"] {
        let e = fails(&["codegen", "--algebra", "g3", "--types", types], 2);
        assert!(!e.contains("internal") && !e.contains("does not parse"), "{types}: {e}");
    }
}
