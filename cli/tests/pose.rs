//! `gam pose` (Wave 2 contract, shared/cli.md): the JSON keys, every representation against an
//! independent computation here (Rodrigues' matrix, the quaternion formula, the Hamilton
//! product q + ε ½ t q, the screw axis as the fixed line of the matrix), every input form
//! giving the same pose, the sign rules, and bad input as one `error:` line with exit 2. Also
//! the `dual_quaternion`/`hexanion` pose forms and `segments[].dual_quaternions` in
//! `gam interpolate`.

use crate::common;

use common::{TempFile, fails, ok};
use serde_json::Value;

fn pose(arg: &str) -> Value {
    serde_json::from_str(&ok(&["pose", "--json", arg])).expect("JSON")
}

fn nums(v: &Value) -> Vec<f64> {
    v.as_array().expect("array").iter().map(|x| x.as_f64().expect("number")).collect()
}

/// All numbers of a (nested) JSON array, flattened.
fn flat(v: &Value) -> Vec<f64> {
    match v {
        Value::Array(a) => a.iter().flat_map(flat).collect(),
        x => vec![x.as_f64().expect("number")],
    }
}

fn close(a: &[f64], b: &[f64], tol: f64) -> bool {
    a.len() == b.len() && a.iter().zip(b).all(|(x, y)| (x - y).abs() <= tol)
}

/// Hamilton product of [w, x, y, z] quaternions.
fn qmul(a: [f64; 4], b: [f64; 4]) -> [f64; 4] {
    [
        a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3],
        a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2],
        a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1],
        a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0],
    ]
}

const AXIS: [f64; 3] = [1.0 / 3.0, -2.0 / 3.0, 2.0 / 3.0];
const ANGLE: f64 = 2.2;
const T: [f64; 3] = [0.3, 0.1, -0.4];

fn axis_angle_json() -> String {
    format!(r#"{{"position": {T:?}, "axis": {AXIS:?}, "angle": {ANGLE}}}"#)
}

#[test]
fn every_representation_against_independent_formulas() {
    let out = pose(&axis_angle_json());
    let keys: Vec<&str> = out.as_object().unwrap().keys().map(String::as_str).collect();
    for k in ["matrix", "position", "quaternion", "axis", "angle", "motor", "dual_quaternion", "hexanion", "screw"] {
        assert!(keys.contains(&k), "missing {k}: {keys:?}");
    }
    // Rodrigues
    let [x, y, z] = AXIS;
    let (s, c) = ANGLE.sin_cos();
    let k = 1.0 - c;
    let r = [
        [c + x * x * k, x * y * k - z * s, x * z * k + y * s],
        [y * x * k + z * s, c + y * y * k, y * z * k - x * s],
        [z * x * k - y * s, z * y * k + x * s, c + z * z * k],
    ];
    let m: Vec<Vec<f64>> = out["matrix"].as_array().unwrap().iter().map(nums).collect();
    for i in 0..3 {
        assert!(close(&m[i], &[r[i][0], r[i][1], r[i][2], T[i]], 1e-15), "row {i}: {:?}", m[i]);
    }
    assert_eq!(m[3], vec![0.0, 0.0, 0.0, 1.0]);
    assert!(close(&nums(&out["position"]), &T, 1e-15));
    let q = [(ANGLE / 2.0).cos(), x * (ANGLE / 2.0).sin(), y * (ANGLE / 2.0).sin(), z * (ANGLE / 2.0).sin()];
    assert!(close(&nums(&out["quaternion"]), &q, 1e-15));
    assert!(close(&nums(&out["axis"]), &AXIS, 1e-15) && (out["angle"].as_f64().unwrap() - ANGLE).abs() < 1e-15);
    // q + ε ½ t q
    let tq = qmul([0.0, T[0] / 2.0, T[1] / 2.0, T[2] / 2.0], q);
    assert!(close(&nums(&out["dual_quaternion"]), &[q, tq].concat(), 1e-15));
    // hexanion: ω = angle * axis; m = θ c × n + d n with the screw's c, d
    let h = &out["hexanion"];
    assert!(close(&nums(&h["omega"]), &AXIS.map(|a| a * ANGLE), 1e-15));
    let sc = &out["screw"];
    let (n, p, d) = (nums(&sc["axis"]), nums(&sc["point"]), sc["translation"].as_f64().unwrap());
    assert!(close(&n, &AXIS, 1e-15) && (sc["angle"].as_f64().unwrap() - ANGLE).abs() < 1e-15);
    // the screw axis point moves by d along the axis under the matrix (the fixed line)
    let img: Vec<f64> = (0..3).map(|i| (0..3).map(|j| r[i][j] * p[j]).sum::<f64>() + T[i]).collect();
    assert!(close(&img, &[p[0] + d * n[0], p[1] + d * n[1], p[2] + d * n[2]], 1e-14), "{img:?}");
    assert!((p.iter().zip(&n).map(|(a, b)| a * b).sum::<f64>()).abs() < 1e-15);
    assert!((sc["pitch"].as_f64().unwrap() - d / ANGLE).abs() < 1e-15);
    let cross = [p[1] * n[2] - p[2] * n[1], p[2] * n[0] - p[0] * n[2], p[0] * n[1] - p[1] * n[0]];
    let mm: Vec<f64> = (0..3).map(|i| ANGLE * cross[i] + d * n[i]).collect();
    assert!(close(&nums(&h["m"]), &mm, 1e-14));
    // the motor: scalar part cos(φ/2) ≥ 0
    assert!((out["motor"]["1"].as_str().unwrap().parse::<f64>().unwrap() - q[0]).abs() < 1e-15);
}

#[test]
fn every_input_form_gives_the_same_pose() {
    let reference = pose(&axis_angle_json());
    let m = reference["matrix"].to_string();
    let q = reference["quaternion"].to_string();
    let dq = reference["dual_quaternion"].to_string();
    let dq_scaled: Vec<f64> = nums(&reference["dual_quaternion"]).iter().map(|x| -3.0 * x).collect();
    let h = reference["hexanion"].to_string();
    let motor = reference["motor"].to_string();
    let file = TempFile::new("pose-file.json", &format!(r#"{{"matrix": {m}}} // a comment"#));
    let at_file = format!("@{}", file.path());
    for arg in [
        format!(r#"{{"matrix": {m}}}"#),
        format!(r#"{{"position": {T:?}, "quaternion": {q}}}"#),
        format!(r#"{{"dual_quaternion": {dq}}}"#),
        format!(r#"{{"dual_quaternion": {dq_scaled:?}}}"#),
        format!(r#"{{"hexanion": {h}}}"#),
        format!(r#"{{"motor": {motor}}}"#),
        at_file,
    ] {
        let out = pose(&arg);
        for key in ["matrix", "quaternion", "dual_quaternion"] {
            let (a, b) = (flat(&out[key]), flat(&reference[key]));
            assert!(close(&a, &b, 1e-14), "{arg}: {key} {a:?} vs {b:?}");
        }
        assert!(close(&nums(&out["hexanion"]["omega"]), &nums(&reference["hexanion"]["omega"]), 1e-14), "{arg}");
    }
}

#[test]
fn edge_cases_and_sign_rules() {
    let id = pose(r#"{"position": [0, 0, 0]}"#);
    assert_eq!(nums(&id["axis"]), vec![0.0; 3]);
    assert_eq!(id["screw"]["pitch"], Value::Null);
    assert_eq!(nums(&id["screw"]["axis"]), vec![0.0; 3]);
    let tr = pose(r#"{"position": [0, 3, 4]}"#);
    assert!(close(&nums(&tr["screw"]["axis"]), &[0.0, 0.6, 0.8], 1e-15));
    assert_eq!(tr["screw"]["translation"].as_f64(), Some(5.0));
    assert_eq!(nums(&tr["screw"]["point"]), vec![0.0; 3]);
    // a half turn given with a negative quaternion: w = 0, first non-zero of x, y, z positive
    let half = pose(r#"{"quaternion": [0, 0, -1, 0], "position": [0, 0, 0]}"#);
    assert_eq!(nums(&half["quaternion"]), vec![0.0, 0.0, 1.0, 0.0]);
    assert!(close(&nums(&half["dual_quaternion"])[..4], &[0.0, 0.0, 1.0, 0.0], 0.0));
    assert!((half["angle"].as_f64().unwrap() - std::f64::consts::PI).abs() < 1e-15);
    // the human form has one line per representation
    let text = ok(&["pose", &axis_angle_json()]);
    for k in ["matrix:", "position:", "quaternion:", "axis:", "motor:", "dual_quaternion:", "hexanion:", "screw:"] {
        assert!(text.lines().any(|l| l.starts_with(k)), "{k} in {text}");
    }
}

#[test]
fn bad_input_is_one_error_line_with_exit_2() {
    for (arg, what) in [
        (r#"{"matrix": [[1,0.5,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1]]}"#, "not a rigid-body transform"),
        (r#"{"dual_quaternion": [1,0,0,0, 1,0,0,0]}"#, "Study quadric"),
        (r#"{"dual_quaternion": [0,0,0,0, 0,1,0,0]}"#, "zero real part"),
        (r#"{"dual_quaternion": [1,0,0]}"#, "must be [w, x, y, z, dw, dx, dy, dz]"),
        (r#"{"hexanion": {"omega": [0,0,1]}}"#, "must be {\"omega\""),
        (r#"{"hexanion": {"omega": [0,0,1], "m": [0,0,0]}, "position": [1,2,3]}"#, "unexpected key `position`"),
        (r#"{"axis": [0,0,0], "angle": 1}"#, "length zero"),
        ("not json", "invalid JSON"),
        ("@/nonexistent/pose.json", "cannot read"),
    ] {
        let e = fails(&["pose", "--json", arg], 2);
        assert!(e.contains(what), "{arg}: {e}");
    }
}

#[test]
fn overflow_is_an_error_not_null() {
    let e = fails(&["pose", "--json", r#"{"dual_quaternion": [1,0,0,0, 0,1e308,1e308,0]}"#], 1);
    assert!(e.contains("overflow"), "{e}");
}

#[test]
fn interpolate_accepts_the_new_forms_and_prints_dual_quaternions() {
    let reference = pose(&axis_angle_json());
    let spec = format!(
        r#"{{"method": "ccm-additive", "poses": [{{"dual_quaternion": [1,0,0,0,0,0,0,0]}}, {{"hexanion": {}}}, {{"dual_quaternion": {}}}], "samples": 5}}"#,
        reference["hexanion"], reference["dual_quaternion"]
    );
    let f = TempFile::new("pose-interp.json", &spec);
    let out: Value = serde_json::from_str(&ok(&["interpolate", "--json", f.path()])).unwrap();
    let samples = out["samples"].as_array().unwrap();
    let last = flat(&samples[4]["matrix"]);
    let want = flat(&reference["matrix"]);
    assert!(close(&last, &want, 1e-12));
    // each segment's dual quaternions are its control poses under the pose map: the first
    // control dual quaternion of segment 0 is the identity pose's, the last of segment 1 is
    // proportional to the key pose's
    for seg in out["segments"].as_array().unwrap() {
        assert_eq!(seg["dual_quaternions"].as_array().unwrap().len(), seg["control_poses"].as_array().unwrap().len());
    }
    let seg1 = &out["segments"][1]["dual_quaternions"];
    let lastq = nums(&seg1[3]);
    let refq = nums(&reference["dual_quaternion"]);
    let k = lastq[0] / refq[0];
    assert!(close(&lastq, &refq.iter().map(|x| k * x).collect::<Vec<_>>(), 1e-12), "{lastq:?} vs {refq:?}");
}
