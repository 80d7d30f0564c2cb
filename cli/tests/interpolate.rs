//! `gam interpolate` (Wave 2 contract, shared/cli.md) with the `ccm-*` methods: the exact JSON
//! keys, the motion passing through every key pose given in each of the four pose forms of today
//! (matrices computed here by Rodrigues' formula and the quaternion formula, not by the
//! library), given velocities reproduced at the key poses, sign alignment, the error contract,
//! and `gam sample` / `gam plot` accepting the spec.

use crate::common;

use common::{TempFile, fails, matrix, max_diff, ok, rodrigues};
use serde_json::Value;

/// The rotation matrix of a unit quaternion `[w, x, y, z]`, with translation `t`.
fn quaternion_matrix(q: [f64; 4], t: [f64; 3]) -> [[f64; 4]; 4] {
    let [w, x, y, z] = q;
    [
        [1.0 - 2.0 * (y * y + z * z), 2.0 * (x * y - w * z), 2.0 * (x * z + w * y), t[0]],
        [2.0 * (x * y + w * z), 1.0 - 2.0 * (x * x + z * z), 2.0 * (y * z - w * x), t[1]],
        [2.0 * (x * z - w * y), 2.0 * (y * z + w * x), 1.0 - 2.0 * (x * x + y * y), t[2]],
        [0.0, 0.0, 0.0, 1.0],
    ]
}

const Q: [f64; 4] = [0.5, 0.5, -0.5, 0.5];
const M: [[f64; 4]; 4] = [[0.0, -1.0, 0.0, 2.0], [1.0, 0.0, 0.0, 1.0], [0.0, 0.0, 1.0, -1.0], [0.0, 0.0, 0.0, 1.0]];

/// Five key poses, one of each form (the motor is the translation by (2, 0, 1): 1 + e1inf + ½e3inf).
fn poses_json() -> String {
    format!(
        r#"[{{"position": [0, 0, 0]}},
  {{"position": [1, 0, 0.5], "axis": [0, 0, 2], "angle": 1.2}},
  {{"position": [1, 1, 0], "quaternion": {Q:?}}},
  {{"matrix": {M:?}}},
  {{"motor": {{"1": "1", "e1inf": "1", "e3inf": 0.5}}}}]"#
    )
}

fn expected_matrices() -> Vec<[[f64; 4]; 4]> {
    vec![
        rodrigues([0.0, 0.0, 1.0], 0.0, [0.0; 3]),
        rodrigues([0.0, 0.0, 1.0], 1.2, [1.0, 0.0, 0.5]),
        quaternion_matrix(Q, [1.0, 1.0, 0.0]),
        M,
        rodrigues([0.0, 0.0, 1.0], 0.0, [2.0, 0.0, 1.0]),
    ]
}

fn run_json(name: &str, text: &str) -> Value {
    let spec = TempFile::new(&format!("interp-{name}.json"), text);
    serde_json::from_str(&ok(&["interpolate", "--json", spec.path()])).expect("JSON")
}

#[test]
fn output_keys_and_key_poses() {
    for method in ["ccm-additive", "ccm-multiplicative"] {
        let text = format!(
            r#"{{"method": "{method}", "poses": {}, "samples": 5, "body_points": [[0, 0, 0], [0.5, -1, 2]]}}"#,
            poses_json()
        );
        let v = run_json(method, &text);
        let keys: Vec<&String> = v.as_object().unwrap().keys().collect();
        assert_eq!(keys, ["method", "parameters", "segments", "samples"]);
        assert_eq!(v["method"], method);
        assert_eq!(v["parameters"], serde_json::json!([0.0, 0.25, 0.5, 0.75, 1.0]));
        let segs = v["segments"].as_array().unwrap();
        assert_eq!(segs.len(), 4);
        let rep = if method == "ccm-additive" { "additive-bezier" } else { "multiplicative-bezier" };
        for (k, s) in segs.iter().enumerate() {
            let keys: Vec<&String> = s.as_object().unwrap().keys().collect();
            if method == "ccm-additive" {
                assert_eq!(keys, ["t0", "t1", "representation", "degree", "control_poses", "dual_quaternions"]);
            } else {
                assert_eq!(keys, ["t0", "t1", "representation", "degree", "control_poses"]);
            }
            assert_eq!((s["t0"].as_f64().unwrap(), s["t1"].as_f64().unwrap()), (k as f64 / 4.0, (k + 1) as f64 / 4.0));
            assert_eq!(s["representation"], rep);
            assert_eq!(s["degree"], 3);
            assert_eq!(s["control_poses"].as_array().unwrap().len(), 4);
        }
        // The key poses themselves: samples at t = i/4 are the key poses (as rigid motions).
        let samples = v["samples"].as_array().unwrap();
        assert_eq!(samples.len(), 5);
        for (i, (s, want)) in samples.iter().zip(expected_matrices()).enumerate() {
            let keys: Vec<&String> = s.as_object().unwrap().keys().collect();
            assert_eq!(keys, ["t", "matrix", "points", "velocities", "angular_velocity"]);
            let got = matrix(&s["matrix"]);
            assert!(max_diff(&got, &want) < 1e-14, "{method} pose {i}: {got:?} vs {want:?}");
            // points are the images of the body points.
            let pts: Vec<[f64; 3]> = serde_json::from_value(s["points"].clone()).unwrap();
            let q = [0.5, -1.0, 2.0];
            let image: [f64; 3] = std::array::from_fn(|r| (0..3).map(|c| want[r][c] * q[c]).sum::<f64>() + want[r][3]);
            assert!((0..3).all(|r| (pts[1][r] - image[r]).abs() < 1e-14 && (pts[0][r] - want[r][3]).abs() < 1e-14));
        }
        // Estimated velocities: at rest at both ends.
        for s in [&samples[0], &samples[4]] {
            let vel: Vec<[f64; 3]> = serde_json::from_value(s["velocities"].clone()).unwrap();
            let w: [f64; 3] = serde_json::from_value(s["angular_velocity"].clone()).unwrap();
            assert!(vel.iter().flatten().chain(&w).all(|x| x.abs() < 1e-12), "{method}: {s}");
        }
    }
}

/// Given velocities (body origin, fixed frame, per unit of t) are the motion's at the key poses,
/// with explicit non-uniform parameters; the velocities of the body points agree with finite
/// differences of their sampled positions.
#[test]
fn given_velocities_and_explicit_parameters() {
    let text = format!(
        r#"{{"method": "ccm-multiplicative", "poses": {}, "parameters": [0, 1, 2.5, 3.5, 5],
  "velocities": [{{"velocity": [1, 0, 0], "angular_velocity": [0, 0, 0.5]}},
                 {{"velocity": [0, 1, 0], "angular_velocity": [0.1, 0, 0.5]}},
                 {{"velocity": [0, 0, 1], "angular_velocity": [0, 0.2, 0]}},
                 {{"velocity": [-1, 0, 0], "angular_velocity": [0, 0, -0.5]}},
                 {{"velocity": [0.5, 0.5, 0], "angular_velocity": [0, 0, 0]}}],
  "shape": 1, "gamma": [0, 0], "samples": 11}}"#,
        poses_json()
    );
    let v = run_json("given", &text);
    let samples = v["samples"].as_array().unwrap();
    let given = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0], [-1.0, 0.0, 0.0], [0.5, 0.5, 0.0]];
    let omega = [[0.0, 0.0, 0.5], [0.1, 0.0, 0.5], [0.0, 0.2, 0.0], [0.0, 0.0, -0.5], [0.0; 3]];
    for (i, t) in [0.0, 1.0, 2.5, 3.5, 5.0].into_iter().enumerate() {
        let Some(s) = samples.iter().find(|s| s["t"].as_f64() == Some(t)) else {
            assert!(t == 1.0 || t == 3.5, "t = {t} is a sample time");
            continue;
        };
        let vel: Vec<[f64; 3]> = serde_json::from_value(s["velocities"].clone()).unwrap();
        let w: [f64; 3] = serde_json::from_value(s["angular_velocity"].clone()).unwrap();
        assert!((0..3).all(|k| (vel[0][k] - given[i][k]).abs() < 1e-12 && (w[k] - omega[i][k]).abs() < 1e-12), "{s}");
    }
}

#[test]
fn sign_alignment_keeps_the_motion() {
    let a = r#"[{"motor": {"1": 1}}, {"motor": {"1": "0.8", "e12": "0.6"}}, {"motor": {"1": "0.6", "e12": "0.8"}}]"#;
    let b = r#"[{"motor": {"1": 1}}, {"motor": {"1": "-0.8", "e12": "-0.6"}}, {"motor": {"1": "0.6", "e12": "0.8"}}]"#;
    for method in ["ccm-additive", "ccm-multiplicative"] {
        let spec = |p: &str| format!(r#"{{"method": "{method}", "poses": {p}}}"#);
        let (va, vb) = (run_json("sign-a", &spec(a)), run_json("sign-b", &spec(b)));
        assert_eq!(va["segments"], vb["segments"], "{method}");
    }
}

#[test]
fn errors() {
    let run = |name: &str, text: &str, code: i32| {
        let spec = TempFile::new(&format!("interp-err-{name}.json"), text);
        fails(&["interpolate", "--json", spec.path()], code)
    };
    let two = r#"[{"position": [0, 0, 0]}, {"position": [1, 0, 0]}]"#;
    let with = |extra: &str| format!(r#"{{"method": "ccm-additive", "poses": {two}{extra}}}"#);
    let e = run("unknown", &format!(r#"{{"method": "spline", "poses": {two}}}"#), 2);
    assert!(e.contains("unknown method `spline`"), "{e}");
    let e = run("unused", &format!(r#"{{"method": "juttler-spline", "poses": {two}, "shape": 1}}"#), 2);
    assert!(e.contains("`shape` is not used by `juttler-spline`"), "{e}");
    let e = run(
        "dq",
        r#"{"method": "ccm-additive", "poses": [{"dual_quaternion": [1,0,0,0,1,0,0,0]}, {"position": [1,0,0]}]}"#,
        2,
    );
    assert!(e.contains("`poses[0].dual_quaternion`") && e.contains("Study quadric"), "{e}");
    // Jüttler's rules of eq. (15) apply to every method: two pure translations have no angle
    let e = run("angular", &with(r#", "parameters": "angular""#), 2);
    assert!(e.contains("step between positions 0 and 1 is 0"), "{e}");
    let e = run("params", &with(r#", "parameters": [0, 0]"#), 2);
    assert!(e.contains("strictly increasing"), "{e}");
    let e = run("params-count", &with(r#", "parameters": [0, 1, 2]"#), 2);
    assert!(e.contains("3 values for 2 poses"), "{e}");
    let e = run("shape", &with(r#", "shape": 0"#), 2);
    assert!(e.contains("`shape` must be positive"), "{e}");
    let e = run("samples", &with(r#", "samples": 1"#), 2);
    assert!(e.contains("`samples`"), "{e}");
    let e = run("velocities", &with(r#", "velocities": [{"velocity": [0,0,0], "angular_velocity": [0,0,0]}]"#), 2);
    assert!(e.contains("1 entries for 2 poses"), "{e}");
    let e = run("one-pose", r#"{"method": "ccm-additive", "poses": [{"position": [0,0,0]}]}"#, 2);
    assert!(e.contains("at least two poses"), "{e}");
    let e = run(
        "not-rigid",
        r#"{"method": "ccm-additive", "poses": [{"matrix": [[2,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1]]}, {"position": [1,0,0]}]}"#,
        2,
    );
    assert!(e.contains("`poses[0]`") && e.contains("not a rigid-body transform"), "{e}");
    let e =
        run("singular", r#"{"method": "ccm-additive", "poses": [{"motor": {"e1inf": 1}}, {"position": [1,0,0]}]}"#, 2);
    assert!(e.contains("singular"), "{e}");
    let e = run(
        "zero-axis",
        r#"{"method": "ccm-additive", "poses": [{"position": [0,0,0], "axis": [0,0,0], "angle": 1}, {"position": [1,0,0]}]}"#,
        2,
    );
    assert!(e.contains("poses[0].axis"), "{e}");
    let e = run(
        "bad-key",
        r#"{"method": "ccm-additive", "poses": [{"position": [0,0,0], "angel": 1}, {"position": [1,0,0]}]}"#,
        2,
    );
    assert!(e.contains("unexpected key `angel`"), "{e}");
    let e = run("unknown-field", &with(r#", "sample": 3"#), 2);
    assert!(e.contains("unknown field `sample`"), "{e}");
    let e = run("l1", &with(r#", "l1": 0"#), 2);
    assert!(e.contains("`l1`"), "{e}");
    let e = run("syntax", "{\"method\": ", 2);
    assert!(e.contains("invalid JSON"), "{e}");
    fails(&["interpolate", "/nonexistent/spec.json"], 2);
}

/// A `gam interpolate` spec is accepted by `gam sample` and `gam plot` (multi-segment motion,
/// t over [t_0, t_m], the first body point).
#[test]
fn sample_and_plot_accept_an_interpolate_spec() {
    let text = format!(
        r#"{{"method": "ccm-multiplicative", "poses": {}, "parameters": [0, 1, 2.5, 3.5, 5], "body_points": [[0.5, -1, 2]]}}"#,
        poses_json()
    );
    let spec = TempFile::new("interp-sample.json", &text);
    let v: Value = serde_json::from_str(&ok(&["sample", "--json", spec.path(), "--samples", "11"])).unwrap();
    let samples = v["samples"].as_array().unwrap();
    assert_eq!(samples.len(), 11);
    assert_eq!(samples[10]["t"].as_f64(), Some(5.0));
    let want = expected_matrices()[2];
    let s = &samples[5]; // t = 2.5: the third key pose
    assert_eq!(s["t"].as_f64(), Some(2.5));
    let p: [f64; 3] = serde_json::from_value(s["position"].clone()).unwrap();
    let q = [0.5, -1.0, 2.0];
    for r in 0..3 {
        let image = (0..3).map(|c| want[r][c] * q[c]).sum::<f64>() + want[r][3];
        assert!((p[r] - image).abs() < 1e-13, "{p:?}");
    }
    let out = TempFile::empty("interp-plot.svg");
    let msg = ok(&["plot", spec.path(), "--out", out.path(), "--samples", "40"]);
    assert!(msg.contains("multiplicative motion of 4 segments of degree 3"), "{msg}");
    assert!(std::fs::read_to_string(out.path()).unwrap().starts_with("<svg"));
}

/// A quaternion is normalised without overflow (the library's `Pose::from_quaternion_wxyz`):
/// components of size 1e200 give the same key pose as the unit quaternion.
#[test]
fn huge_quaternion_components() {
    let big = Q.map(|x| x * 1e200);
    let text = format!(
        r#"{{"method": "ccm-multiplicative", "poses": [{{"position": [0, 0, 0]}}, {{"position": [1, 1, 0], "quaternion": {big:?}}}], "samples": 2}}"#
    );
    let v = run_json("huge-quaternion", &text);
    let got = matrix(&v["samples"][1]["matrix"]);
    let want = quaternion_matrix(Q, [1.0, 1.0, 0.0]);
    assert!(max_diff(&got, &want) < 1e-14, "{got:?} vs {want:?}");
}
