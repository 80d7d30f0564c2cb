//! `gam interpolate` with Jüttler's methods `juttler-q-motion` (Algorithm 1), `juttler-affine`
//! and `juttler-projective` (the affine and projective rotations with TR), `juttler-trt`,
//! `juttler-minimal` and `juttler-spline` (Algorithm 2): the contract's JSON keys and the
//! papers' degrees, the motion through every key pose (matrices by Rodrigues' formula here,
//! not by the library), the segments' dual quaternions checked by evaluating their Bézier
//! curves and Jüttler's point map (12) in this file, the motor <-> dual quaternion
//! correspondence of `gam pose`, the parametrisation rules of eq. (15) against hand-computed
//! values, sign alignment, point velocities against differences (across the spline's knots:
//! C1), given spline velocities reproduced, TRT's split and singular system, and the error
//! contract.

use crate::common;

use common::{
    TempFile, assert_velocities_match_differences, exact_c1_segments, fails, max_diff, ok, rodrigues, rodrigues_wxyz,
};
use serde_json::Value;

/// (axis, angle, position) of four key poses.
const KEYS: [([f64; 3], f64, [f64; 3]); 4] = [
    ([0.0, 0.0, 1.0], 0.0, [0.0, 0.0, 0.0]),
    ([0.0, 0.0, 1.0], 1.2, [1.0, 0.0, 0.5]),
    ([0.0, 1.0, 0.0], 0.5, [2.0, 1.0, 0.0]),
    ([1.0, 1.0, 1.0], -0.7, [2.0, 2.0, -1.0]),
];

fn poses() -> String {
    let p: Vec<String> =
        KEYS.iter().map(|(a, phi, t)| format!(r#"{{"position": {t:?}, "axis": {a:?}, "angle": {phi}}}"#)).collect();
    format!("[{}]", p.join(", "))
}

fn run_json(name: &str, text: &str) -> Value {
    let spec = TempFile::new(&format!("interp-jq-{name}.json"), text);
    serde_json::from_str(&ok(&["interpolate", "--json", spec.path()])).expect("JSON")
}

/// Hamilton product of quaternions `[w, x, y, z]`.
fn qmul(a: [f64; 4], b: [f64; 4]) -> [f64; 4] {
    [
        a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3],
        a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2],
        a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1],
        a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0],
    ]
}

/// The image of `x` under the dual quaternion `q = r + ε d` by Jüttler's (12):
/// `y = Du(q (2 + ε x) conj(r)) / |r|²`, with `Du(q (2 + ε x) conj(r)) = 2 d conj(r) + r x conj(r)`.
fn jut_image(q: &[f64; 8], x: [f64; 3]) -> [f64; 3] {
    let r = [q[0], q[1], q[2], q[3]];
    let d = [q[4], q[5], q[6], q[7]];
    let rc = [r[0], -r[1], -r[2], -r[3]];
    let a = qmul(d, rc);
    let b = qmul(qmul(r, [0.0, x[0], x[1], x[2]]), rc);
    let n = r.iter().map(|c| c * c).sum::<f64>();
    std::array::from_fn(|k| (2.0 * a[k + 1] + b[k + 1]) / n)
}

/// The Bézier curve of `control` at `u` (de Casteljau).
fn bezier(control: &[[f64; 8]], u: f64) -> [f64; 8] {
    let mut col = control.to_vec();
    for len in (1..col.len()).rev() {
        for i in 0..len {
            col[i] = std::array::from_fn(|k| (1.0 - u) * col[i][k] + u * col[i + 1][k]);
        }
    }
    col[0]
}

/// The segment of `segs` holding `t` and the local parameter there.
fn segment_at(segs: &[Value], t: f64) -> (&Value, f64) {
    let seg = segs
        .iter()
        .find(|g| g["t0"].as_f64().unwrap() <= t && t <= g["t1"].as_f64().unwrap())
        .expect("a segment holds t");
    let (t0, t1) = (seg["t0"].as_f64().unwrap(), seg["t1"].as_f64().unwrap());
    (seg, (t - t0) / (t1 - t0))
}

/// (method, extra spec keys, segments, degree of each segment's control data) for the four
/// key poses (m = 3): 2m; TRT max(l1, l2) + m; the minimal motion's Q-motion (36) of degree
/// k + n = m + 2m; the spline's segments 6.
const METHODS: [(&str, &str, usize, u64); 6] = [
    ("juttler-q-motion", "", 1, 6),
    ("juttler-affine", "", 1, 6),
    ("juttler-trt", "", 1, 5),
    ("juttler-trt", r#", "l1": 1"#, 1, 4),
    ("juttler-minimal", "", 1, 9),
    ("juttler-spline", "", 3, 6),
];

#[test]
fn output_keys_key_poses_and_dual_quaternions() {
    for (method, extra, nseg, degree) in METHODS {
        // explicit parameters, used as given: samples at t = 0, 0.5, ..., 5 hit every key
        let text = format!(
            r#"{{"method": "{method}", "poses": {}, "parameters": [0, 1, 2.5, 5], "samples": 11,
  "body_points": [[0, 0, 0], [0.5, -1, 2]]{extra}}}"#,
            poses()
        );
        let v = run_json(&format!("keys-{method}{}", extra.len()), &text);
        let keys: Vec<&String> = v.as_object().unwrap().keys().collect();
        assert_eq!(keys, ["method", "parameters", "segments", "samples"]);
        assert_eq!(v["method"], method);
        assert_eq!(v["parameters"], serde_json::json!([0.0, 1.0, 2.5, 5.0]));
        let segs = v["segments"].as_array().unwrap();
        assert_eq!(segs.len(), nseg, "{method}");
        let mut dqs = Vec::new();
        for (k, s) in segs.iter().enumerate() {
            let keys: Vec<&String> = s.as_object().unwrap().keys().collect();
            assert_eq!(keys, ["t0", "t1", "representation", "degree", "control_poses", "dual_quaternions"]);
            let ends = if nseg == 1 { (0.0, 5.0) } else { ([0.0, 1.0, 2.5][k], [1.0, 2.5, 5.0][k]) };
            assert_eq!((s["t0"].as_f64().unwrap(), s["t1"].as_f64().unwrap()), ends);
            assert_eq!(s["representation"], "dual-quaternion-bezier");
            assert_eq!(s["degree"], degree, "{method}{extra}");
            assert_eq!(s["control_poses"].as_array().unwrap().len(), degree as usize + 1);
            let dq: Vec<[f64; 8]> = serde_json::from_value(s["dual_quaternions"].clone()).unwrap();
            assert_eq!(dq.len(), degree as usize + 1);
            dqs.push(dq);
        }
        let samples = v["samples"].as_array().unwrap();
        assert_eq!(samples.len(), 11);
        let body = [[0.0, 0.0, 0.0], [0.5, -1.0, 2.0]];
        for s in samples {
            let keys: Vec<&String> = s.as_object().unwrap().keys().collect();
            assert_eq!(keys, ["t", "matrix", "points", "velocities", "angular_velocity"]);
            // the points are the images of the body points under the curve of the printed dual
            // quaternions (local parameter u), by (12) computed here
            let t = s["t"].as_f64().unwrap();
            let (seg, u) = segment_at(segs, t);
            let k = segs.iter().position(|g| g == seg).unwrap();
            let q = bezier(&dqs[k], u);
            let pts: Vec<[f64; 3]> = serde_json::from_value(s["points"].clone()).unwrap();
            for (p, x) in pts.iter().zip(body) {
                let want = jut_image(&q, x);
                assert!((0..3).all(|k| (p[k] - want[k]).abs() < 1e-12), "{method} t = {t}: {p:?} vs {want:?}");
            }
        }
        // through every key pose, as a rigid motion
        for ((axis, phi, pos), t) in KEYS.iter().zip([0.0, 1.0, 2.5, 5.0]) {
            let s = samples.iter().find(|s| s["t"].as_f64() == Some(t)).expect("a sample at the key's parameter");
            let got: [[f64; 4]; 4] = serde_json::from_value(s["matrix"].clone()).unwrap();
            let want = rodrigues(*axis, *phi, *pos);
            assert!(max_diff(&got, &want) < 1e-13, "{method} t = {t}: {got:?} vs {want:?}");
        }
    }
}

/// Given velocities (body origin, fixed frame, per unit of t) are the spline's at the key
/// poses, with explicit non-uniform parameters.
#[test]
fn spline_reproduces_given_velocities() {
    let given = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0], [-1.0, 0.5, 0.0]];
    let omega = [[0.0, 0.0, 0.5], [0.1, 0.0, 0.5], [0.0, 0.2, 0.0], [0.0, 0.0, -0.5]];
    let v: Vec<String> =
        given.iter().zip(&omega).map(|(v, w)| format!(r#"{{"velocity": {v:?}, "angular_velocity": {w:?}}}"#)).collect();
    let text = format!(
        r#"{{"method": "juttler-spline", "poses": {}, "parameters": [0, 1, 2.5, 5], "velocities": [{}], "samples": 11}}"#,
        poses(),
        v.join(", ")
    );
    let out = run_json("spline-given", &text);
    let samples = out["samples"].as_array().unwrap();
    for (i, t) in [0.0, 1.0, 2.5, 5.0].into_iter().enumerate() {
        let s = samples.iter().find(|s| s["t"].as_f64() == Some(t)).unwrap();
        let vel: Vec<[f64; 3]> = serde_json::from_value(s["velocities"].clone()).unwrap();
        let w: [f64; 3] = serde_json::from_value(s["angular_velocity"].clone()).unwrap();
        assert!((0..3).all(|k| (vel[0][k] - given[i][k]).abs() < 1e-12 && (w[k] - omega[i][k]).abs() < 1e-12), "{s}");
    }
}

/// TRT: every split l1 = 0, 1, 2 passes through the key poses with degree max(l1, l2) + m;
/// l1 > m - 1 is bad input; two positions make (34) singular: exit 1 naming the method.
#[test]
fn trt_splits_and_singular_system() {
    for l1 in 0..3 {
        let text = format!(r#"{{"method": "juttler-trt", "poses": {}, "l1": {l1}, "samples": 4}}"#, poses());
        let v = run_json(&format!("trt-{l1}"), &text);
        assert_eq!(v["segments"][0]["degree"], l1.max(2 - l1) + 3);
        for (s, (axis, phi, pos)) in v["samples"].as_array().unwrap().iter().zip(KEYS) {
            let got: [[f64; 4]; 4] = serde_json::from_value(s["matrix"].clone()).unwrap();
            assert!(max_diff(&got, &rodrigues(axis, phi, pos)) < 1e-13, "l1 = {l1}: {got:?}");
        }
    }
    let spec = TempFile::new(
        "interp-jq-trt-split.json",
        &format!(r#"{{"method": "juttler-trt", "poses": {}, "l1": 3}}"#, poses()),
    );
    let e = fails(&["interpolate", spec.path()], 2);
    assert!(e.contains("juttler-trt") && e.contains("l1 = 3 exceeds m - 1 = 2"), "{e}");
    let two = r#"[{"position": [0, 0, 0]}, {"position": [1, 0, 0], "axis": [0, 0, 1], "angle": 1}]"#;
    let spec = TempFile::new("interp-jq-trt-two.json", &format!(r#"{{"method": "juttler-trt", "poses": {two}}}"#));
    let e = fails(&["interpolate", "--json", spec.path()], 1);
    assert!(e.contains("juttler-trt") && e.contains("(34) is singular") && e.contains("l1 = l2 even"), "{e}");
    // six positions in general position: the split l1 = l2 = 2 is singular whatever the
    // positions (docs/verification.md, Result 5) and the error says so; l1 = 1 works
    let six = r#"[{"position": [0, 0, 0]},
        {"position": [2, 1, 0], "axis": [0, 0, 1], "angle": 0.7},
        {"position": [4, -1, 1], "axis": [1, 0, 0], "angle": 1.1},
        {"position": [6, 0, 2], "axis": [0, 1, 1], "angle": 0.4},
        {"position": [8, 2, 1], "axis": [1, 1, 0], "angle": 1.3},
        {"position": [10, 1, 0], "axis": [1, -1, 2], "angle": 0.9}]"#;
    let at = |l1: usize| {
        TempFile::new(
            &format!("interp-jq-trt-six-{l1}.json"),
            &format!(r#"{{"method": "juttler-trt", "poses": {six}, "l1": {l1}}}"#),
        )
    };
    let e = fails(&["interpolate", at(2).path()], 1);
    assert!(e.contains("l1 = l2 even") && e.contains("choose another l1"), "{e}");
    let v = run_json("trt-six-1", &std::fs::read_to_string(at(1).path()).unwrap());
    assert_eq!(v["segments"][0]["degree"], 3 + 5);
}

/// `control_poses` and `dual_quaternions` are the same control data under `gam pose`'s map
/// (r = S + S23 i - S13 j + S12 k, d = -S123inf + S1inf i + S2inf j + S3inf k): checked
/// coefficient by coefficient, and the end control points (the key poses up to a factor)
/// against `gam pose`'s `dual_quaternion`.
#[test]
fn control_poses_and_dual_quaternions_agree() {
    let v = run_json("map", &format!(r#"{{"method": "juttler-q-motion", "poses": {}}}"#, poses()));
    let s = &v["segments"][0];
    let dq: Vec<[f64; 8]> = serde_json::from_value(s["dual_quaternions"].clone()).unwrap();
    let motors = s["control_poses"].as_array().unwrap();
    let c = |m: &Value, k: &str| m.get(k).map_or(0.0, |x| x.as_str().unwrap().parse::<f64>().unwrap());
    for (m, d) in motors.iter().zip(&dq) {
        let want = [
            c(m, "1"),
            c(m, "e23"),
            -c(m, "e13"),
            c(m, "e12"),
            -c(m, "e123inf"),
            c(m, "e1inf"),
            c(m, "e2inf"),
            c(m, "e3inf"),
        ];
        assert!((0..8).all(|k| (d[k] - want[k]).abs() < 1e-15), "{m} vs {d:?}");
    }
    for (motor, d) in [(&motors[0], dq[0]), (&motors[motors.len() - 1], dq[dq.len() - 1])] {
        let pose: Value =
            serde_json::from_str(&ok(&["pose", "--json", &format!(r#"{{"motor": {motor}}}"#)])).expect("JSON");
        let unit: [f64; 8] = serde_json::from_value(pose["dual_quaternion"].clone()).unwrap();
        let scale = d[0] / unit[0];
        assert!((0..8).all(|k| (d[k] - scale * unit[k]).abs() < 1e-14), "{d:?} vs {scale} {unit:?}");
    }
}

/// The rules of eq. (15) on three translations (distances 3 and 4): chordal, *-chordal and
/// angle + distance give t_1 = 3/7, centripetal √3/(√3 + 2); angular has a zero step (exit 2).
#[test]
fn parametrisation_rules() {
    let poses = r#"[{"position": [0, 0, 0]}, {"position": [3, 0, 0]}, {"position": [3, 4, 0]}]"#;
    let r3 = 3f64.sqrt();
    for (rule, t1) in [
        ("chordal", 3.0 / 7.0),
        ("star-chordal", 3.0 / 7.0),
        ("angular-chordal", 3.0 / 7.0),
        ("centripetal", r3 / (r3 + 2.0)),
    ] {
        for method in ["juttler-q-motion", "ccm-additive"] {
            let text = format!(r#"{{"method": "{method}", "poses": {poses}, "parameters": "{rule}", "samples": 2}}"#);
            let v = run_json(&format!("{rule}-{method}"), &text);
            let t: Vec<f64> = serde_json::from_value(v["parameters"].clone()).unwrap();
            assert!(t[0] == 0.0 && t[2] == 1.0 && (t[1] - t1).abs() < 1e-15, "{rule} {method}: {t:?}");
        }
    }
    let spec = TempFile::new(
        "interp-jq-angular.json",
        &format!(r#"{{"method": "juttler-q-motion", "poses": {poses}, "parameters": "angular"}}"#),
    );
    let e = fails(&["interpolate", spec.path()], 2);
    assert!(e.contains("juttler-q-motion") && e.contains("step between positions 0 and 1 is 0"), "{e}");
}

/// Negating a key pose (the same rigid motion) gives the same motion (rule (24)).
#[test]
fn sign_alignment_keeps_the_motion() {
    let a = r#"[{"motor": {"1": 1}}, {"motor": {"1": "0.8", "e12": "0.6", "e1inf": 1}}, {"motor": {"1": "0.6", "e12": "0.8"}}]"#;
    let b = r#"[{"motor": {"1": 1}}, {"motor": {"1": "-0.8", "e12": "-0.6", "e1inf": -1}}, {"motor": {"1": "0.6", "e12": "0.8"}}]"#;
    let spec = |p: &str| format!(r#"{{"method": "juttler-q-motion", "poses": {p}, "samples": 5}}"#);
    let (va, vb) = (run_json("sign-a", &spec(a)), run_json("sign-b", &spec(b)));
    assert_eq!(va["segments"], vb["segments"]);
    assert_eq!(va["samples"], vb["samples"]);
}

/// Velocities (dual numbers) against central differences of the sampled points; `gam sample`
/// gives the same positions.
/// At the spline's inner knots t = 1/3, 2/3 (k = 1000, 2000) the velocity from the left and
/// from the right (second-order one-sided differences of the sampled points, each within one
/// segment) both equal the sampled velocity: C1.
#[test]
fn velocities_and_gam_sample() {
    let n = 3001;
    for method in ["juttler-q-motion", "juttler-trt", "juttler-minimal", "juttler-spline"] {
        let text = format!(
            r#"{{"method": "{method}", "poses": {}, "samples": {n}, "body_points": [[0, 0, 0], [0.5, -1, 2]]}}"#,
            poses()
        );
        let v = run_json(&format!("fd-{method}"), &text);
        let samples = v["samples"].as_array().unwrap();
        let h = 1.0 / (n - 1) as f64;
        assert_velocities_match_differences(method, samples, h, &[200, 1500, 2900]);
        for k in [1000, 2000] {
            let p = |j: usize| -> Vec<[f64; 3]> { serde_json::from_value(samples[j]["points"].clone()).unwrap() };
            let vel: Vec<[f64; 3]> = serde_json::from_value(samples[k]["velocities"].clone()).unwrap();
            let (a, b, c, d, e) = (p(k - 2), p(k - 1), p(k), p(k + 1), p(k + 2));
            for (q, v) in vel.iter().enumerate() {
                let left: [f64; 3] = std::array::from_fn(|r| (3.0 * c[q][r] - 4.0 * b[q][r] + a[q][r]) / (2.0 * h));
                let right: [f64; 3] = std::array::from_fn(|r| (-3.0 * c[q][r] + 4.0 * d[q][r] - e[q][r]) / (2.0 * h));
                let close = |x: &[f64; 3]| (0..3).all(|r| (x[r] - v[r]).abs() < 1e-5 * (1.0 + v[r].abs()));
                assert!(close(&left) && close(&right), "{method} knot {k}: {left:?} {right:?} vs {v:?}");
            }
        }
        let spec = TempFile::new(&format!("interp-jq-sample-{method}.json"), &text);
        let out: Value = serde_json::from_str(&ok(&["sample", spec.path(), "--samples", "3001", "--json"])).unwrap();
        for k in [0, 1000, 3000] {
            let p: [f64; 3] = serde_json::from_value(out["samples"][k]["position"].clone()).unwrap();
            let q: Vec<[f64; 3]> = serde_json::from_value(samples[k]["points"].clone()).unwrap();
            assert_eq!(p, q[0], "{method}");
        }
    }
}

#[test]
fn errors() {
    let run = |name: &str, extra: &str| {
        let text = format!(r#"{{"method": "juttler-q-motion", "poses": {}{extra}}}"#, poses());
        let spec = TempFile::new(&format!("interp-jq-err-{name}.json"), &text);
        fails(&["interpolate", "--json", spec.path()], 2)
    };
    let e = run("velocities", r#", "velocities": []"#);
    assert!(e.contains("`velocities` is not used by `juttler-q-motion`"), "{e}");
    let e = run("l1", r#", "l1": 1"#);
    assert!(e.contains("`l1` is not used by `juttler-q-motion`"), "{e}");
    let e = run("shape", r#", "shape": 2"#);
    assert!(e.contains("`shape` is not used"), "{e}");
    let e = run("params", r#", "parameters": [0, 1, 1, 2]"#);
    assert!(e.contains("juttler-q-motion") && e.contains("not larger than"), "{e}");
    let e = run("rule", r#", "parameters": "chordial""#);
    assert!(e.contains("unknown rule `chordial`"), "{e}");
    let run = |name: &str, method: &str, extra: &str| {
        let text = format!(r#"{{"method": "{method}", "poses": {}{extra}}}"#, poses());
        let spec = TempFile::new(&format!("interp-jq-err-{name}.json"), &text);
        fails(&["interpolate", spec.path()], 2)
    };
    let e = run("trt-negative", "juttler-trt", r#", "l1": -1"#);
    assert!(e.contains("`l1` must be 0 or more"), "{e}");
    let e = run("spline-l1", "juttler-spline", r#", "l1": 1"#);
    assert!(e.contains("`l1` is not used by `juttler-spline` (it uses velocities)"), "{e}");
    let e = run("minimal-velocities", "juttler-minimal", r#", "velocities": []"#);
    assert!(e.contains("`velocities` is not used by `juttler-minimal`"), "{e}");
    let e = run("spline-velocities", "juttler-spline", r#", "velocities": []"#);
    assert!(e.contains("`velocities` has 0 entries for 4 poses"), "{e}");
    let e = run("spline-params", "juttler-spline", r#", "parameters": [0, 2, 1, 3]"#);
    assert!(e.contains("juttler-spline") && e.contains("not strictly increasing"), "{e}");
}

/// One global interpolant of high degree is ill-conditioned in f64: with these 20 poses the
/// Q-motion (degree 38) and TRT methods refuse (exit 1, "numerically unstable") instead of
/// printing a motion that misses its key poses (the minimal-order motion still meets the
/// key-pose check here); the spline (local, degree 6) passes through all 20.
#[test]
fn many_poses_global_methods_refuse_the_spline_interpolates() {
    let keys: Vec<([f64; 3], f64, [f64; 3])> = (0..20)
        .map(|i| {
            let x = i as f64;
            ([x.sin(), x.cos(), 0.5], 0.1 * x - 1.0, [x, (0.7 * x).sin() * 3.0, (0.3 * x).cos()])
        })
        .collect();
    let poses: Vec<String> =
        keys.iter().map(|(a, phi, t)| format!(r#"{{"position": {t:?}, "axis": {a:?}, "angle": {phi}}}"#)).collect();
    let spec = |method: &str| {
        format!(r#"{{"method": "{method}", "poses": [{}], "parameters": "chordal", "samples": 0}}"#, poses.join(", "))
    };
    for method in ["juttler-q-motion", "juttler-trt"] {
        let file = TempFile::new(&format!("interp-jq-many-{method}.json"), &spec(method));
        let e = fails(&["interpolate", "--json", file.path()], 1);
        assert!(e.contains(method) && e.contains("numerically unstable with 20 poses"), "{e}");
    }
    let v = run_json("many-spline", &spec("juttler-spline"));
    let segs = v["segments"].as_array().unwrap();
    assert_eq!(segs.len(), 19);
    for (i, (axis, phi, pos)) in keys.iter().enumerate().skip(1) {
        // the end control dual quaternion of segment i - 1 is λ P_i: its image of the origin
        // and of the unit points are the key pose's
        let dq: Vec<[f64; 8]> = serde_json::from_value(segs[i - 1]["dual_quaternions"].clone()).unwrap();
        let want = rodrigues(*axis, *phi, *pos);
        for x in [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]] {
            let got = jut_image(dq.last().unwrap(), x);
            let w: [f64; 3] = std::array::from_fn(|r| (0..3).map(|c| want[r][c] * x[c]).sum::<f64>() + want[r][3]);
            assert!((0..3).all(|k| (got[k] - w[k]).abs() < 1e-12), "key {i}: {got:?} vs {w:?}");
        }
    }
}

#[test]
fn projective_rotations_with_tr() {
    // five key poses (m = 4): the projective rotation has degree 3m/4 = 3, with TR 7m/4 = 7;
    // the motion passes through every key pose (Rodrigues here) and `gam trajectory` accepts it
    let five: [([f64; 3], f64, [f64; 3]); 5] = [
        ([0.0, 0.0, 1.0], 0.0, [0.0, 0.0, 0.0]),
        ([0.0, 0.0, 1.0], 0.8, [3.0, 1.0, 0.0]),
        ([1.0, 0.0, 0.0], 1.2, [6.0, 0.0, 1.0]),
        ([0.0, 1.0, 1.0], 1.6, [8.0, 2.0, 0.0]),
        ([1.0, 1.0, 0.0], 2.0, [12.0, 0.0, 0.0]),
    ];
    let p: Vec<String> =
        five.iter().map(|(a, phi, t)| format!(r#"{{"position": {t:?}, "axis": {a:?}, "angle": {phi}}}"#)).collect();
    let text = format!(r#"{{"method": "juttler-projective", "poses": [{}], "samples": 9}}"#, p.join(", "));
    let v = run_json("projective", &text);
    assert_eq!(v["segments"][0]["degree"], 7);
    let samples = v["samples"].as_array().unwrap();
    for (k, (axis, phi, pos)) in five.iter().enumerate() {
        let s = &samples[2 * k];
        let got: [[f64; 4]; 4] = serde_json::from_value(s["matrix"].clone()).unwrap();
        assert!(max_diff(&got, &rodrigues(*axis, *phi, *pos)) < 1e-12, "key {k}: {got:?}");
    }
    let spec = TempFile::new("interp-jq-projective-traj.json", &text);
    // gam plot draws it in every view (the paths end at the first and last key positions)
    for view in ["xy", "3d"] {
        let out = TempFile::empty(&format!("interp-jq-projective-{view}.svg"));
        let data: Value =
            serde_json::from_str(&ok(&["plot", "--json", "--out", out.path(), spec.path(), "--view", view])).unwrap();
        let path = data["series"][0]["paths"][0].as_array().unwrap();
        let end: [f64; 3] = serde_json::from_value(path[path.len() - 1].clone()).unwrap();
        assert!((0..3).all(|k| (end[k] - five[4].2[k]).abs() < 1e-9), "{end:?}");
        assert!(std::fs::read_to_string(out.path()).unwrap().starts_with("<svg"));
    }
    let t: Value = serde_json::from_str(&ok(&["trajectory", "--json", spec.path(), "--point", "0,0,1"])).unwrap();
    assert_eq!(t["segments"][0]["degree"], 2 * 7);
    // four poses: the projective method needs m divisible by 4
    let spec = TempFile::new(
        "interp-jq-projective-four.json",
        &format!(r#"{{"method": "juttler-projective", "poses": {}}}"#, poses()),
    );
    let out = common::gam(&["interpolate", spec.path()]);
    let e = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{e}");
    assert!(e.contains("juttler-projective") && e.contains("divisible by 4"), "{e}");
}

/// `juttler-bspline` (Jüttler Sec. 6, B-spline Q-motions by the TR method): through every key
/// pose (Rodrigues here), the points the images of the printed pieces under (12), the pieces
/// joined C^(p-1) exactly (derivatives of the printed rational control data at the breaks, here),
/// and with `degree` = m the TR method on the elliptic rotations, i.e. `juttler-q-motion`,
/// coefficient for coefficient.
#[test]
fn bspline_q_motions() {
    // six key poses with rational quaternion norms, so --scalar rational runs too
    let keys = r#"[{"position": [0, 0, 0]}, {"position": [1, 1, 0], "quaternion": [0.6, 0, 0, 0.8]},
        {"position": [2, 0, 0.5]}, {"position": [3, 1, 1], "quaternion": [2, 1, 2, 0]},
        {"position": [4, 0, 0], "quaternion": [0, 0.6, 0.8, 0]}, {"position": [5, 1, 0]}]"#;
    let spec = |extra: &str| format!(r#"{{"method": "juttler-bspline", "poses": {keys}, "samples": 11{extra}}}"#);
    // p = 3 by default: knots 0, 0, 0, 0, 2/5, 3/5, 1, 1, 1, 1 (averages of 3 parameters)
    let v = run_json("bspline", &spec(""));
    let segs = v["segments"].as_array().unwrap();
    let ends: Vec<(f64, f64)> = segs.iter().map(|s| (s["t0"].as_f64().unwrap(), s["t1"].as_f64().unwrap())).collect();
    assert_eq!(ends, [(0.0, 0.4), (0.4, 0.6), (0.6, 1.0)]);
    assert!(segs.iter().all(|s| s["degree"] == 6));
    let quats: [[f64; 4]; 6] = [
        [1.0, 0.0, 0.0, 0.0],
        [0.6, 0.0, 0.0, 0.8],
        [1.0, 0.0, 0.0, 0.0],
        [2.0, 1.0, 2.0, 0.0],
        [0.0, 0.6, 0.8, 0.0],
        [1.0, 0.0, 0.0, 0.0],
    ];
    let positions =
        [[0.0, 0.0, 0.0], [1.0, 1.0, 0.0], [2.0, 0.0, 0.5], [3.0, 1.0, 1.0], [4.0, 0.0, 0.0], [5.0, 1.0, 0.0]];
    let samples = v["samples"].as_array().unwrap();
    for (i, (q, p)) in quats.iter().zip(positions).enumerate() {
        let s = &samples[2 * i]; // t = i/5
        let got: [[f64; 4]; 4] = serde_json::from_value(s["matrix"].clone()).unwrap();
        assert!(max_diff(&got, &rodrigues_wxyz(*q, p)) < 1e-13, "key pose {i}");
        // the printed point: the origin's image under the printed piece, by (12) here
        let (seg, u) = segment_at(segs, s["t"].as_f64().unwrap());
        let dq: Vec<[f64; 8]> = serde_json::from_value(seg["dual_quaternions"].clone()).unwrap();
        let y = jut_image(&bezier(&dq, u), [0.0; 3]);
        assert!((0..3).all(|k| (y[k] - p[k]).abs() < 1e-12), "key {i}: {y:?}");
    }
    // exactly C2 (p = 3) at the breaks: the first and second derivatives of the homogeneous
    // pieces, from their rational control points
    let file = TempFile::new("interp-jq-bspline-exact.json", &spec(""));
    let exact: Value =
        serde_json::from_str(&ok(&["interpolate", "--json", "--scalar", "rational", file.path()])).unwrap();
    let q = |s: &str| algebra_core::rational::parse_rational(s).unwrap();
    let pieces: Vec<(Vec<Vec<algebra_core::rational::Q>>, algebra_core::rational::Q)> = exact["segments"]
        .as_array()
        .unwrap()
        .iter()
        .map(|s| {
            let b = s["dual_quaternions"]
                .as_array()
                .unwrap()
                .iter()
                .map(|d| d.as_array().unwrap().iter().map(|x| q(x.as_str().unwrap())).collect())
                .collect();
            (b, q(s["t1"].as_str().unwrap()) - q(s["t0"].as_str().unwrap()))
        })
        .collect();
    for w in pieces.windows(2) {
        let ((a, ha), (b, hb)) = (&w[0], &w[1]);
        let n = a.len() - 1;
        for k in 0..8 {
            // n (B_n - B_(n-1)) / h_a = n (B'_1 - B'_0) / h_b, and the second differences / h²
            let d1 = (&a[n][k] - &a[n - 1][k]) / ha;
            let e1 = (&b[1][k] - &b[0][k]) / hb;
            assert_eq!(d1, e1, "C1 at a break, coefficient {k}");
            let d2 = (&a[n][k] - &a[n - 1][k] * algebra_core::rational::q(2) + &a[n - 2][k]) / (ha * ha);
            let e2 = (&b[2][k] - &b[1][k] * algebra_core::rational::q(2) + &b[0][k]) / (hb * hb);
            assert_eq!(d2, e2, "C2 at a break, coefficient {k}");
        }
    }
    // degree = m: one Bézier piece, the elliptic TR method of juttler-q-motion, exactly
    let one = TempFile::new("interp-jq-bspline-m.json", &spec(r#", "degree": 5"#));
    let qm = TempFile::new("interp-jq-qmotion.json", &spec("").replace("juttler-bspline", "juttler-q-motion"));
    let a: Value = serde_json::from_str(&ok(&["interpolate", "--json", "--scalar", "rational", one.path()])).unwrap();
    let b: Value = serde_json::from_str(&ok(&["interpolate", "--json", "--scalar", "rational", qm.path()])).unwrap();
    assert_eq!(a["segments"][0]["dual_quaternions"], b["segments"][0]["dual_quaternions"]);
    // refusals
    let high = TempFile::new("interp-jq-bspline-high.json", &spec(r#", "degree": 6"#));
    let e = fails(&["interpolate", high.path()], 2);
    assert!(e.contains("degree 6 for 6 positions"), "{e}");
    let neg = TempFile::new("interp-jq-bspline-neg.json", &spec(r#", "degree": -1"#));
    assert!(fails(&["interpolate", neg.path()], 2).contains("`degree` must be 1 or more"));
    let other =
        TempFile::new("interp-jq-degree.json", &spec(r#", "degree": 2"#).replace("juttler-bspline", "juttler-spline"));
    assert!(fails(&["interpolate", other.path()], 2).contains("`degree` is not used by `juttler-spline`"));
}

/// `juttler-minimal-spline` (Jüttler Sec. 6's closing remark: a C1 spline of rational motions
/// of order 6): through every key pose, the given velocities and angular velocities at the
/// keys, trajectories of degree 6 (the Q-motion spline's are 12), and exactly C1 at the joins:
/// the rational curves of `gam trajectory --scalar rational` (their values and derivatives at
/// the breaks, computed here from the control points).
#[test]
fn minimal_order_spline() {
    let keys = r#"[{"position": [0, 0, 0]}, {"position": [1, 1, 0], "quaternion": [0.6, 0, 0, 0.8]},
        {"position": [2, 0, 0.5], "quaternion": [2, 1, 2, 0]}, {"position": [3, 1, 1]}]"#;
    let given = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.5], [0.5, 0.0, 1.0], [-1.0, 0.5, 0.0]];
    let omega = [[0.0, 0.0, 0.5], [0.1, 0.0, 0.5], [0.0, 0.2, 0.0], [0.0, 0.0, -0.5]];
    let v: Vec<String> =
        given.iter().zip(&omega).map(|(v, w)| format!(r#"{{"velocity": {v:?}, "angular_velocity": {w:?}}}"#)).collect();
    let text = format!(
        r#"{{"method": "juttler-minimal-spline", "poses": {keys}, "parameters": [0, 0.5, 1.25, 2], "velocities": [{}], "samples": 9, "body_points": [[0, 0, 0]]}}"#,
        v.join(", ")
    );
    let out = run_json("minimal-spline", &text);
    let samples = out["samples"].as_array().unwrap();
    let quats = [[1.0, 0.0, 0.0, 0.0], [0.6, 0.0, 0.0, 0.8], [2.0, 1.0, 2.0, 0.0], [1.0, 0.0, 0.0, 0.0]];
    let positions = [[0.0, 0.0, 0.0], [1.0, 1.0, 0.0], [2.0, 0.0, 0.5], [3.0, 1.0, 1.0]];
    for (i, t) in [0.0, 0.5, 1.25, 2.0].into_iter().enumerate() {
        let s = samples.iter().find(|s| s["t"].as_f64() == Some(t)).expect("a sample at the key");
        let got: [[f64; 4]; 4] = serde_json::from_value(s["matrix"].clone()).unwrap();
        assert!(max_diff(&got, &rodrigues_wxyz(quats[i], positions[i])) < 1e-13, "key {i}");
        let vel: Vec<[f64; 3]> = serde_json::from_value(s["velocities"].clone()).unwrap();
        let w: [f64; 3] = serde_json::from_value(s["angular_velocity"].clone()).unwrap();
        assert!((0..3).all(|k| (vel[0][k] - given[i][k]).abs() < 1e-12 && (w[k] - omega[i][k]).abs() < 1e-12), "{s}");
    }
    // exact trajectories of order 6, C1 at the joins
    let file = TempFile::new("interp-jq-minimal-spline.json", &text);
    let segs = exact_c1_segments(file.path(), "1/2,-1,2");
    assert_eq!(segs.len(), 3);
    assert!(segs.iter().all(|s| s["degree"] == 6), "order 6");
    // the Q-motion spline's trajectories have degree 12
    let q_spline = TempFile::new("interp-jq-q-spline.json", &text.replace("juttler-minimal-spline", "juttler-spline"));
    let tr: Value =
        serde_json::from_str(&ok(&["trajectory", "--json", q_spline.path(), "--point", "0.5,-1,2"])).unwrap();
    assert_eq!(tr["segments"][0]["degree"], 12);
}
