//! `gam interpolate` with Angelidis' `hexanion-linear` (eq. 56): the contract's JSON keys, the
//! motion through every key pose (matrices by Rodrigues' formula and by the power series of
//! the hexanion matrix (4), both here, not by the library), the segment midpoints as the
//! series exponential of the averaged hexanions, point velocities against central differences
//! of the sampled points, and the error contract (exit 2).

use crate::common;

use common::{TempFile, assert_velocities_match_differences, fails, max_diff, ok, rodrigues};
use serde_json::Value;

type M4 = [[f64; 4]; 4];

/// Key hexanions `<ω, m>` with `|ω| < π` (so they are the principal ones the method uses).
const HEX: [([f64; 3], [f64; 3]); 3] =
    [([0.0, 0.0, 0.0], [0.0, 0.0, 0.0]), ([0.3, -0.2, 1.1], [1.0, 0.5, -0.25]), ([-0.4, 1.3, 0.2], [2.0, -1.0, 0.75])];

/// A fourth key as axis + angle + position.
const LAST: ([f64; 3], f64, [f64; 3]) = ([1.0, 1.0, 1.0], -0.7, [2.0, 2.0, -1.0]);

fn spec(samples: usize, extra: &str) -> String {
    let mut poses: Vec<String> =
        HEX.iter().map(|(w, m)| format!(r#"{{"hexanion": {{"omega": {w:?}, "m": {m:?}}}}}"#)).collect();
    let (a, phi, t) = LAST;
    poses.push(format!(r#"{{"position": {t:?}, "axis": {a:?}, "angle": {phi}}}"#));
    format!(
        r#"{{"method": "hexanion-linear", "poses": [{}], "samples": {samples}, "body_points": [[0, 0, 0], [0.5, -1, 2]]{extra}}}"#,
        poses.join(", ")
    )
}

fn run_json(name: &str, text: &str) -> Value {
    let spec = TempFile::new(&format!("interp-hex-{name}.json"), text);
    serde_json::from_str(&ok(&["interpolate", "--json", spec.path()])).expect("JSON")
}

/// `exp` of the matrix form (4) of `<ω, m>` by its power series (eq. 13), 60 terms.
fn series_exp(w: [f64; 3], m: [f64; 3]) -> M4 {
    let a: M4 = [[0.0, -w[2], w[1], m[0]], [w[2], 0.0, -w[0], m[1]], [-w[1], w[0], 0.0, m[2]], [0.0; 4]];
    let mut sum: M4 = std::array::from_fn(|i| std::array::from_fn(|j| if i == j { 1.0 } else { 0.0 }));
    let mut term = sum;
    for k in 1..60 {
        term = std::array::from_fn(|i| {
            std::array::from_fn(|j| (0..4).map(|l| term[i][l] * a[l][j]).sum::<f64>() / k as f64)
        });
        for i in 0..4 {
            for j in 0..4 {
                sum[i][j] += term[i][j];
            }
        }
    }
    sum
}

fn vec3(v: &Value) -> [f64; 3] {
    serde_json::from_value(v.clone()).unwrap()
}

#[test]
fn output_keys_key_poses_and_midpoints() {
    let v = run_json("keys", &spec(7, ""));
    let keys: Vec<&String> = v.as_object().unwrap().keys().collect();
    assert_eq!(keys, ["method", "parameters", "segments", "samples"]);
    assert_eq!(v["method"], "hexanion-linear");
    let segs = v["segments"].as_array().unwrap();
    assert_eq!(segs.len(), 3);
    let samples = v["samples"].as_array().unwrap();
    assert_eq!(samples.len(), 7); // t = 0, 1/6, ..., 1: even ones are key poses, odd ones midpoints
    let matrix = |k: usize| -> M4 { serde_json::from_value(samples[k]["matrix"].clone()).unwrap() };
    for (k, s) in segs.iter().enumerate() {
        assert_eq!(s["representation"], "hexanion-linear");
        assert_eq!(s["degree"], 1);
        assert_eq!(s["control_poses"].as_array().unwrap().len(), 2);
        let h = s["hexanions"].as_array().unwrap();
        assert_eq!(h.len(), 2);
        let (w0, m0, w1, m1) = (vec3(&h[0]["omega"]), vec3(&h[0]["m"]), vec3(&h[1]["omega"]), vec3(&h[1]["m"]));
        // principal branch, and each printed hexanion is its key pose (series exp)
        for (w, m, key) in [(w0, m0, 2 * k), (w1, m1, 2 * k + 2)] {
            assert!(w.iter().map(|x| x * x).sum::<f64>().sqrt() <= std::f64::consts::PI);
            let d = max_diff(&series_exp(w, m), &matrix(key));
            assert!(d < 1e-13, "segment {k}: hexanion of key {key} off by {d}");
        }
        // the midpoint of the segment is exp of the averaged hexanions (eq. 56 at u = 1/2)
        let avg = |a: [f64; 3], b: [f64; 3]| std::array::from_fn(|i| 0.5 * (a[i] + b[i]));
        let d = max_diff(&series_exp(avg(w0, w1), avg(m0, m1)), &matrix(2 * k + 1));
        assert!(d < 1e-13, "segment {k}: midpoint off by {d}");
    }
    // the given hexanions come back unchanged (they are principal), and the keys are the poses
    for (i, (w, m)) in HEX.iter().enumerate() {
        let h = &segs[i]["hexanions"][0];
        let close = |a: [f64; 3], b: &[f64; 3]| (0..3).all(|r| (a[r] - b[r]).abs() < 1e-14);
        assert!(close(vec3(&h["omega"]), w) && close(vec3(&h["m"]), m), "key {i}: {h}");
        assert!(max_diff(&matrix(2 * i), &series_exp(*w, *m)) < 1e-13, "key {i}");
    }
    let (a, phi, t) = LAST;
    let d = max_diff(&matrix(6), &rodrigues(a, phi, t));
    assert!(d < 1e-13, "last key pose off by {d}");
}

/// Velocities (dual numbers in the library) against central differences of sampled points.
#[test]
fn velocities_match_differences_of_points() {
    let n = 3001; // step 1/3000
    let v = run_json("fd", &spec(n, ""));
    let samples = v["samples"].as_array().unwrap();
    assert_velocities_match_differences("hexanion-linear", samples, 1.0 / (n - 1) as f64, &[200, 700, 1300, 2600]);
}

#[test]
fn errors() {
    let run = |name: &str, text: &str| {
        let spec = TempFile::new(&format!("interp-hex-err-{name}.json"), text);
        fails(&["interpolate", "--json", spec.path()], 2)
    };
    let e = run("velocities", &spec(0, r#", "velocities": []"#));
    assert!(e.contains("`velocities` is not used by `hexanion-linear`"), "{e}");
    let e = run("one", r#"{"method": "hexanion-linear", "poses": [{"position": [0, 0, 0]}]}"#);
    assert!(e.contains("at least two poses"), "{e}");
    let e = run("times", &spec(0, r#", "parameters": [0, 1, 1, 2]"#));
    assert!(e.contains("time 2 is not larger than time 1"), "{e}");
    let e = run(
        "matrix",
        r#"{"method": "hexanion-linear", "poses": [{"position": [0, 0, 0]}, {"matrix": [[2,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1]]}]}"#,
    );
    assert!(e.contains("poses[1]"), "{e}");
}

/// Key poses of the decoupled motion: (axis, angle, position), turns below a half turn
/// between neighbours.
const DECOUPLED: [([f64; 3], f64, [f64; 3]); 3] = [
    ([0.0, 0.0, 1.0], 0.0, [0.0, 0.0, 0.0]),
    ([0.0, 0.0, 1.0], 1.2, [2.0, 1.0, 0.0]),
    ([1.0, 1.0, 0.0], 1.0, [3.0, 3.0, 1.0]),
];

fn decoupled_spec(shift: [f64; 3]) -> String {
    let poses: Vec<String> = DECOUPLED
        .iter()
        .map(|(a, phi, t)| {
            let t: [f64; 3] = std::array::from_fn(|k| t[k] + shift[k]);
            format!(r#"{{"position": {t:?}, "axis": {a:?}, "angle": {phi}}}"#)
        })
        .collect();
    format!(
        r#"{{"method": "hexanion-decoupled", "poses": [{}], "samples": 21, "body_points": [[0, 0, 0], [0.5, -1, 2]]}}"#,
        poses.join(", ")
    )
}

#[test]
fn decoupled_motion_moves_the_origin_straight() {
    let v = run_json("decoupled", &decoupled_spec([0.0; 3]));
    let samples = v["samples"].as_array().unwrap();
    // through every key pose (samples at t = 0, 0.1, ..., 2: keys at 0, 10, 20)
    for (k, (axis, phi, pos)) in DECOUPLED.iter().enumerate() {
        let got: M4 = serde_json::from_value(samples[10 * k]["matrix"].clone()).unwrap();
        assert!(max_diff(&got, &rodrigues(*axis, *phi, *pos)) < 1e-13, "key {k}: {got:?}");
    }
    for (i, s) in samples.iter().enumerate() {
        // the body origin on the straight segment between the key positions, linear in t
        let (seg, u) = ((i / 10).min(1), (i as f64 - 10.0 * ((i / 10).min(1)) as f64) / 10.0);
        let (a, b) = (DECOUPLED[seg].2, DECOUPLED[seg + 1].2);
        let p: [f64; 3] = serde_json::from_value(s["points"][0].clone()).unwrap();
        for k in 0..3 {
            assert!((p[k] - (a[k] + u * (b[k] - a[k]))).abs() < 1e-12, "t = {}: {p:?}", s["t"]);
        }
    }
    // on the first segment both keys turn about e3 (by 0 and 1.2): a constant |Ω| = 1.2/Δt
    let dt = samples[10]["t"].as_f64().unwrap() - samples[0]["t"].as_f64().unwrap();
    for s in &samples[1..10] {
        let w: [f64; 3] = serde_json::from_value(s["angular_velocity"].clone()).unwrap();
        let n = w.iter().map(|x| x * x).sum::<f64>().sqrt();
        assert!((n - 1.2 / dt).abs() < 1e-12 && w[0].abs() < 1e-12 && w[1].abs() < 1e-12, "{w:?}");
    }
    // moving every key pose by the same translation moves the motion by it
    let shift = [5.0, -3.0, 2.0];
    let moved = run_json("decoupled-moved", &decoupled_spec(shift));
    for (s, t) in samples.iter().zip(moved["samples"].as_array().unwrap()) {
        let (a, b): (M4, M4) = (
            serde_json::from_value(s["matrix"].clone()).unwrap(),
            serde_json::from_value(t["matrix"].clone()).unwrap(),
        );
        for r in 0..3 {
            for c in 0..3 {
                assert!((a[r][c] - b[r][c]).abs() < 1e-12);
            }
            assert!((a[r][3] + shift[r] - b[r][3]).abs() < 1e-12);
        }
    }
    // velocities (dual numbers) against differences of the points, 2001 samples
    let fine = run_json("decoupled-fine", &decoupled_spec([0.0; 3]).replace(r#""samples": 21"#, r#""samples": 2001"#));
    let fine = fine["samples"].as_array().unwrap();
    let h = fine[1]["t"].as_f64().unwrap() - fine[0]["t"].as_f64().unwrap();
    assert_velocities_match_differences("hexanion-decoupled", fine, h, &[150, 700, 1300, 1900]);
}

/// Angelidis' blend (57) with named weights (`hexanion-blend`): every sample is the power-series
/// exponential of `Σ φ_i(t) H_i` with the weights computed here (Lagrange polynomials of the
/// key parameters; Bernstein polynomials), so `lagrange` passes through every key pose.
#[test]
fn blend_is_the_series_exp_of_the_weighted_hexanions() {
    let poses: Vec<String> =
        HEX.iter().map(|(w, m)| format!(r#"{{"hexanion": {{"omega": {w:?}, "m": {m:?}}}}}"#)).collect();
    let times = [0.0, 0.5, 1.0];
    let lagrange = |t: f64| -> Vec<f64> {
        (0..3).map(|i| (0..3).filter(|&j| j != i).map(|j| (t - times[j]) / (times[i] - times[j])).product()).collect()
    };
    let bernstein = |t: f64| vec![(1.0 - t) * (1.0 - t), 2.0 * t * (1.0 - t), t * t];
    for (name, phi) in [("lagrange", &lagrange as &dyn Fn(f64) -> Vec<f64>), ("bernstein", &bernstein)] {
        let text = format!(
            r#"{{"method": "hexanion-blend", "weights": "{name}", "poses": [{}], "samples": 5}}"#,
            poses.join(", ")
        );
        let out = run_json(name, &text);
        let seg = &out["segments"][0];
        assert_eq!((seg["representation"].as_str(), seg["degree"].as_u64()), (Some("hexanion-blend"), Some(2)));
        assert_eq!(out["segments"].as_array().unwrap().len(), 1);
        for s in out["samples"].as_array().unwrap() {
            let t = s["t"].as_f64().unwrap();
            let f = phi(t);
            let w: [f64; 3] = std::array::from_fn(|k| (0..3).map(|i| f[i] * HEX[i].0[k]).sum());
            let m: [f64; 3] = std::array::from_fn(|k| (0..3).map(|i| f[i] * HEX[i].1[k]).sum());
            let want = series_exp(w, m);
            let got: M4 = serde_json::from_value(s["matrix"].clone()).unwrap();
            assert!(max_diff(&got, &want) < 1e-12, "{name} at t = {t}");
        }
        if name == "lagrange" {
            let key: M4 = serde_json::from_value(out["samples"][2]["matrix"].clone()).unwrap();
            assert!(max_diff(&key, &series_exp(HEX[1].0, HEX[1].1)) < 1e-12);
        }
    }
    // weights belong to hexanion-blend only, and must be named
    let other = TempFile::new("interp-hex-weights.json", &spec(0, r#", "weights": "lagrange""#));
    let e = fails(&["interpolate", other.path()], 2);
    assert!(e.contains("`weights` is not used by `hexanion-linear`"), "{e}");
    let bad = TempFile::new(
        "interp-hex-bad-weights.json",
        &format!(r#"{{"method": "hexanion-blend", "weights": "cubic", "poses": [{}]}}"#, poses.join(", ")),
    );
    let e = fails(&["interpolate", bad.path()], 2);
    assert!(e.contains("unknown weights `cubic` (lagrange or bernstein)"), "{e}");
}
