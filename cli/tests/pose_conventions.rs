//! `gam pose` against pytransform3d, an independent implementation with documented conventions
//! (fixture written by tests/fixtures/pytransform3d/conventions.py): the `hexanion` output is
//! pytransform3d's exponential coordinates `[omega, v]`, and `dual_quaternion` is its unit dual
//! quaternion `[pw, px, py, pz, qw, qx, qy, qz]` with the dual part `1/2 t p`
//! (docs/conventions.md, "Other tools' conventions").

use crate::common;

use serde_json::Value;

const FIXTURE: &str = include_str!("../../tests/fixtures/pytransform3d/conventions.json");

fn numbers(v: &Value) -> Vec<f64> {
    match v {
        Value::Array(items) => items.iter().flat_map(numbers).collect(),
        Value::Number(n) => vec![n.as_f64().expect("a finite number")],
        other => panic!("not a number or list: {other}"),
    }
}

fn close(what: &str, ours: &[f64], theirs: &[f64]) {
    assert_eq!(ours.len(), theirs.len(), "{what}: lengths");
    for (i, (a, b)) in ours.iter().zip(theirs).enumerate() {
        assert!((a - b).abs() <= 1e-12 * (1.0 + b.abs()), "{what}[{i}]: gam {a}, pytransform3d {b}");
    }
}

#[test]
fn hexanion_and_dual_quaternion_are_pytransform3d_conventions() {
    let fixture: Value = serde_json::from_str(FIXTURE).expect("fixture parses");
    let cases = fixture["cases"].as_array().expect("cases");
    assert!(cases.len() >= 12);
    for case in cases {
        let pose = case["pose"].to_string();
        let out: Value = serde_json::from_str(&common::ok(&["pose", "--json", &pose])).expect("json");
        close(&format!("{pose} matrix"), &numbers(&out["matrix"]), &numbers(&case["matrix"]));
        let hexanion = [numbers(&out["hexanion"]["omega"]), numbers(&out["hexanion"]["m"])].concat();
        close(&format!("{pose} hexanion"), &hexanion, &numbers(&case["exponential_coordinates"]));
        close(
            &format!("{pose} dual_quaternion"),
            &numbers(&out["dual_quaternion"]),
            &numbers(&case["dual_quaternion"]),
        );
    }
}
