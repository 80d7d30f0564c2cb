//! `gam interpolate` with the Wareham–Lasenby methods `wl-linear`, `wl-quadratic` and
//! `wl-direct`: the
//! contract's JSON keys, the motion through every key pose (matrices by Rodrigues' formula
//! here, not by the library), point velocities against central differences of the sampled
//! points, and the error contract (exit 2 for keys W-L does not use and too few poses).

use crate::common;

use common::{TempFile, assert_velocities_match_differences, fails, ok, rodrigues};
use serde_json::Value;

const KEYS: [([f64; 3], f64, [f64; 3]); 4] = [
    ([0.0, 0.0, 1.0], 0.0, [0.0, 0.0, 0.0]),
    ([0.0, 0.0, 1.0], 1.2, [1.0, 0.0, 0.5]),
    ([0.0, 1.0, 0.0], 0.5, [2.0, 1.0, 0.0]),
    ([1.0, 1.0, 1.0], -0.7, [2.0, 2.0, -1.0]),
];

fn spec(method: &str, samples: usize, extra: &str) -> String {
    let poses: Vec<String> =
        KEYS.iter().map(|(a, phi, t)| format!(r#"{{"position": {t:?}, "axis": {a:?}, "angle": {phi}}}"#)).collect();
    format!(
        r#"{{"method": "{method}", "poses": [{}], "samples": {samples}, "body_points": [[0, 0, 0], [0.5, -1, 2]]{extra}}}"#,
        poses.join(", ")
    )
}

fn run_json(name: &str, text: &str) -> Value {
    let spec = TempFile::new(&format!("interp-wl-{name}.json"), text);
    serde_json::from_str(&ok(&["interpolate", "--json", spec.path()])).expect("JSON")
}

#[test]
fn output_keys_and_key_poses() {
    for (method, rep, degrees) in [
        ("wl-linear", "wl-relative-rotor", [1, 1, 1]),
        ("wl-quadratic", "wl-bivector-quadratic", [2, 3, 2]),
        ("wl-direct", "wl-bivector-linear", [1, 1, 1]),
    ] {
        let v = run_json(method, &spec(method, 7, ""));
        let keys: Vec<&String> = v.as_object().unwrap().keys().collect();
        assert_eq!(keys, ["method", "parameters", "segments", "samples"]);
        assert_eq!(v["method"], method);
        let segs = v["segments"].as_array().unwrap();
        assert_eq!(segs.len(), 3);
        for (s, d) in segs.iter().zip(degrees) {
            assert_eq!(s["representation"], rep);
            assert_eq!(s["degree"], d);
        }
        // samples at t = 0, 1/6, ..., 1: every second one is a key pose
        let samples = v["samples"].as_array().unwrap();
        assert_eq!(samples.len(), 7);
        for (i, (axis, phi, t)) in KEYS.iter().enumerate() {
            let s = &samples[2 * i];
            let keys: Vec<&String> = s.as_object().unwrap().keys().collect();
            assert_eq!(keys, ["t", "matrix", "points", "velocities", "angular_velocity"]);
            let got: [[f64; 4]; 4] = serde_json::from_value(s["matrix"].clone()).unwrap();
            let want = rodrigues(*axis, *phi, *t);
            let d = (0..4).flat_map(|r| (0..4).map(move |c| (got[r][c] - want[r][c]).abs())).fold(0.0, f64::max);
            assert!(d < 1e-13, "{method} key pose {i}: {got:?} vs {want:?}");
        }
    }
}

/// Velocities (dual numbers in the library) against central differences of sampled points.
#[test]
fn velocities_match_differences_of_points() {
    for method in ["wl-linear", "wl-quadratic"] {
        let n = 3001; // step 1/3000
        let v = run_json(&format!("{method}-fd"), &spec(method, n, ""));
        let samples = v["samples"].as_array().unwrap();
        assert_velocities_match_differences(method, samples, 1.0 / (n - 1) as f64, &[200, 700, 1300, 2600]);
    }
}

#[test]
fn errors() {
    let run = |name: &str, text: &str| {
        let spec = TempFile::new(&format!("interp-wl-err-{name}.json"), text);
        fails(&["interpolate", "--json", spec.path()], 2)
    };
    let e = run("shape", &spec("wl-linear", 0, r#", "shape": 2"#));
    assert!(e.contains("`shape` is not used by `wl-linear`"), "{e}");
    let e = run("two", r#"{"method": "wl-quadratic", "poses": [{"position": [0, 0, 0]}, {"position": [1, 0, 0]}]}"#);
    assert!(e.contains("wl-quadratic") && e.contains("at least 3"), "{e}");
    let e = run("times", &spec("wl-linear", 0, r#", "parameters": [0, 1, 1, 2]"#));
    assert!(e.contains("breakpoint"), "{e}");
}

/// `gam sample` accepts a W-L spec: the positions are those of `gam interpolate`.
#[test]
fn gam_sample_accepts_a_wl_spec() {
    let text = spec("wl-quadratic", 5, "");
    let v = run_json("sample-ref", &text);
    let file = TempFile::new("interp-wl-sample.json", &text);
    let out: Value = serde_json::from_str(&ok(&["sample", file.path(), "--samples", "5", "--json"])).expect("JSON");
    let got = out["samples"].as_array().unwrap();
    assert_eq!(got.len(), 5);
    for (s, r) in got.iter().zip(v["samples"].as_array().unwrap()) {
        let p: [f64; 3] = serde_json::from_value(s["position"].clone()).unwrap();
        let q: Vec<[f64; 3]> = serde_json::from_value(r["points"].clone()).unwrap();
        assert!((0..3).all(|k| (p[k] - q[0][k]).abs() < 1e-15), "{p:?} vs {:?}", q[0]);
    }
}

#[test]
fn direct_interpolation_of_the_bivectors() {
    // Two rotations about e3 at the origin: the logarithms commute, so halfway the direct
    // interpolation is the rotation by the mean angle (Rodrigues), like wl-linear.
    let two = |a: f64, b: f64, p: [f64; 3]| {
        format!(
            r#"{{"method": "METHOD", "poses": [{{"position": [0, 0, 0], "axis": [0, 0, 1], "angle": {a}}},
            {{"position": {p:?}, "axis": [1, 0, 0], "angle": {b}}}], "samples": 3}}"#
        )
    };
    let mid = |text: &str, method: &str| -> [[f64; 4]; 4] {
        let v = run_json(&format!("direct-{method}-{}", text.len()), &text.replace("METHOD", method));
        serde_json::from_value(v["samples"][1]["matrix"].clone()).unwrap()
    };
    let same_axis = r#"{"method": "METHOD", "poses": [{"position": [0, 0, 0], "axis": [0, 0, 1], "angle": 0.4},
        {"position": [0, 0, 0], "axis": [0, 0, 1], "angle": 1.6}], "samples": 3}"#;
    let want = rodrigues([0.0, 0.0, 1.0], 1.0, [0.0; 3]);
    for method in ["wl-direct", "wl-linear"] {
        let got = mid(same_axis, method);
        let d = (0..4).flat_map(|r| (0..4).map(move |c| (got[r][c] - want[r][c]).abs())).fold(0.0, f64::max);
        assert!(d < 1e-14, "{method}: {got:?}");
    }
    // A rotation and a screw about another axis: the generators do not commute, and halfway
    // the direct interpolation differs from the relative-rotor one (the paper's closing remark).
    let text = two(0.9, 1.3, [2.0, -1.0, 0.5]);
    let (a, b) = (mid(&text, "wl-direct"), mid(&text, "wl-linear"));
    let d = (0..4).flat_map(|r| (0..4).map(move |c| (a[r][c] - b[r][c]).abs())).fold(0.0, f64::max);
    assert!(d > 1e-2, "wl-direct and wl-linear agree halfway: {a:?}");
}
