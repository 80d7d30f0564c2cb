//! `--scalar f64|rational|mpfr:BITS` of the motion commands (shared/cli.md, "Precision of the
//! motion commands"), against an independent exact computation: the fixture
//! tests/fixtures/fractions/juttler_trajectory.json, written by the committed script
//! juttler_trajectory.py next to it (Jüttler's TR method with the elliptic and affine
//! rotations, in Python's `fractions` only).
//!
//! - `rational`: `gam trajectory` prints the script's control points and weights, fraction for
//!   fraction; `gam interpolate` samples are exact (key poses hit exactly).
//! - `f64`: the same specs agree with the fractions to 1e-12.
//! - `mpfr:256`: key poses hit to 1e-70.
//! - refusals: methods and pose forms that need square roots or transcendental functions exit 2
//!   naming the method or the key.

use crate::common;

use algebra_core::rational::{Q, parse_rational, rational_to_f64};
use common::{TempFile, exact, exact_c1_segments, fails, ok};
use serde_json::Value;

/// The fixture's cases.
fn cases() -> Vec<Value> {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../tests/fixtures/fractions/juttler_trajectory.json");
    serde_json::from_str(&std::fs::read_to_string(path).expect("fixture")).expect("fixture JSON")
}

/// `C(n, k) u^k (1 - u)^(n - k)`, exactly.
fn bernstein(n: usize, k: usize, u: &Q) -> Q {
    let c = (0..k).fold(Q::from_integer(1.into()), |acc, i| acc * Q::new((n - i).into(), (i + 1).into()));
    let one = Q::from_integer(1.into());
    let mut b = c;
    for _ in 0..k {
        b *= u;
    }
    for _ in k..n {
        b *= &one - u;
    }
    b
}

/// A `segments[]` curve at the local parameter `u`, exactly.
fn point_at(seg: &Value, u: &Q) -> [Q; 3] {
    let w: Vec<Q> = seg["weights"].as_array().unwrap().iter().map(exact).collect();
    let p: Vec<Vec<Q>> =
        seg["points"].as_array().unwrap().iter().map(|q| q.as_array().unwrap().iter().map(exact).collect()).collect();
    let d = w.len() - 1;
    let den: Q = (0..=d).map(|j| bernstein(d, j, u) * &w[j]).sum();
    std::array::from_fn(|k| (0..=d).map(|j| bernstein(d, j, u) * &w[j] * &p[j][k]).sum::<Q>() / &den)
}

fn trajectory(spec: &TempFile, point: &str, scalar: &str) -> Value {
    let out = ok(&["trajectory", "--json", "--scalar", scalar, spec.path(), "--point", point]);
    serde_json::from_str(&out).expect("JSON")
}

#[test]
fn rational_trajectories_equal_the_independent_fractions() {
    for case in cases() {
        let spec = TempFile::new("precision-exact.json", &case["spec"].to_string());
        let got = trajectory(&spec, case["point"].as_str().unwrap(), "rational");
        assert_eq!(got["segments"], case["segments"], "{}", case["name"]);
        // every number is a coefficient string
        assert!(got["segments"][0]["weights"].as_array().unwrap().iter().all(Value::is_string));
    }
}

#[test]
fn f64_agrees_with_the_fractions_to_1e_12() {
    for case in cases() {
        let spec = TempFile::new("precision-f64.json", &case["spec"].to_string());
        let got = trajectory(&spec, case["point"].as_str().unwrap(), "f64");
        let (a, b) = (&got["segments"][0], &case["segments"][0]);
        assert_eq!(a["degree"], b["degree"]);
        let flat = |s: &Value| -> Vec<f64> {
            let w = s["weights"].as_array().unwrap().iter();
            let p = s["points"].as_array().unwrap().iter().flat_map(|q| q.as_array().unwrap().iter());
            w.chain(p).map(|x| rational_to_f64(&exact(x))).collect()
        };
        let (x, y) = (flat(a), flat(b));
        let scale = y.iter().fold(1.0f64, |m, v| m.max(v.abs()));
        for (i, (x, y)) in x.iter().zip(&y).enumerate() {
            assert!((x - y).abs() <= 1e-12 * scale, "{}: number {i}: {x} vs {y}", case["name"]);
        }
    }
}

/// The key poses of a fixture case (its `keys`: rotation quaternion and translation, whatever
/// form the spec gives them in), exactly, and the image of `x` under each.
fn key_images(case: &Value, x: &[Q; 3]) -> Vec<[Q; 3]> {
    let keys = case["keys"].as_array().unwrap();
    keys.iter()
        .map(|p| {
            let q: Vec<Q> = p["quaternion"].as_array().unwrap().iter().map(exact).collect();
            let t: Vec<Q> = p["position"].as_array().unwrap().iter().map(exact).collect();
            // q x q* / |q|², Hamilton
            let (w, v) = (&q[0], [&q[1], &q[2], &q[3]]);
            let n2: Q = q.iter().map(|c| c * c).sum();
            let cross = |a: [&Q; 3], b: &[Q; 3]| -> [Q; 3] {
                [a[1] * &b[2] - a[2] * &b[1], a[2] * &b[0] - a[0] * &b[2], a[0] * &b[1] - a[1] * &b[0]]
            };
            let vx = cross(v, x);
            let vvx = cross(v, &vx);
            let two = Q::from_integer(2.into());
            std::array::from_fn(|k| (&x[k] * &n2 + &two * w * &vx[k] + &two * &vvx[k]) / &n2 + &t[k])
        })
        .collect()
}

/// The local parameters `u_i` of the key poses (uniform, or the given ones mapped onto [0, 1]).
fn key_parameters(case: &Value) -> Vec<Q> {
    let m = case["spec"]["poses"].as_array().unwrap().len() - 1;
    match case["spec"].get("parameters") {
        Some(Value::Array(t)) => {
            let t: Vec<Q> = t.iter().map(exact).collect();
            t.iter().map(|ti| (ti - &t[0]) / (&t[m] - &t[0])).collect()
        }
        _ => (0..=m).map(|i| Q::new((i as i64).into(), (m as i64).into())).collect(),
    }
}

#[test]
fn rational_curves_hit_the_key_poses_exactly_and_mpfr_to_1e_70() {
    for case in cases() {
        let spec = TempFile::new("precision-keys.json", &case["spec"].to_string());
        let point = case["point"].as_str().unwrap();
        let x: [Q; 3] = std::array::from_fn(|k| parse_rational(point.split(',').nth(k).unwrap()).unwrap());
        let want = key_images(&case, &x);
        let exact_curve = trajectory(&spec, point, "rational");
        let mpfr_curve = trajectory(&spec, point, "mpfr:256");
        for (u, p) in key_parameters(&case).iter().zip(&want) {
            assert_eq!(&point_at(&exact_curve["segments"][0], u), p, "{}", case["name"]);
            let got = point_at(&mpfr_curve["segments"][0], u);
            for k in 0..3 {
                let err = rational_to_f64(&(&got[k] - &p[k])).abs();
                assert!(err < 1e-70, "{}: u = {u}: error {err:e}", case["name"]);
            }
        }
    }
}

#[test]
fn rational_interpolate_samples_are_exact_at_the_key_parameters() {
    let case = &cases()[1]; // given parameters 0, 1/4, 1/2, 2
    let mut spec = case["spec"].clone();
    spec["samples"] = 9.into(); // t = 0, 1/4, ..., 2
    spec["body_points"] = serde_json::json!([[0.5, -1, 2]]);
    let file = TempFile::new("precision-interpolate.json", &spec.to_string());
    let out: Value =
        serde_json::from_str(&ok(&["interpolate", "--json", "--scalar", "rational", file.path()])).unwrap();
    assert_eq!(out["parameters"], serde_json::json!(["0", "1/4", "1/2", "2"]));
    let x = [Q::new(1.into(), 2.into()), Q::from_integer((-1).into()), Q::from_integer(2.into())];
    let want = key_images(case, &x);
    let samples = out["samples"].as_array().unwrap();
    for (sample, key) in [(0, 0), (1, 1), (2, 2), (8, 3)] {
        let p: Vec<Q> = samples[sample]["points"][0].as_array().unwrap().iter().map(exact).collect();
        assert_eq!(p, want[key].to_vec(), "sample {sample}");
    }
    // the rigid matrix of an exact sample is exactly orthonormal
    let m: Vec<Vec<Q>> = samples[3]["matrix"]
        .as_array()
        .unwrap()
        .iter()
        .map(|r| r.as_array().unwrap().iter().map(exact).collect())
        .collect();
    for i in 0..3 {
        for j in 0..3 {
            let dot: Q = (0..3).map(|k| &m[k][i] * &m[k][j]).sum();
            assert_eq!(dot, Q::from_integer(i64::from(i == j).into()), "R^T R at ({i}, {j})");
        }
    }
    // velocities agree with the f64 motion
    let f64_out: Value = serde_json::from_str(&ok(&["interpolate", "--json", file.path()])).unwrap();
    for i in [3, 5] {
        for key in ["velocities", "angular_velocity"] {
            let a = &samples[i][key];
            let b = &f64_out["samples"][i][key];
            for (x, y) in numbers(a).iter().zip(numbers(b)) {
                assert!((x - y).abs() < 1e-9 * (1.0 + y.abs()), "{key} at sample {i}: {x} vs {y}");
            }
        }
    }
}

/// The numbers of a nested JSON list, as f64.
fn numbers(v: &Value) -> Vec<f64> {
    match v {
        Value::Array(a) => a.iter().flat_map(numbers).collect(),
        x => vec![rational_to_f64(&exact(x))],
    }
}

#[test]
fn decimal_literals_and_fractions_are_read_exactly() {
    // 0.1 and "1/10" are the same exact key translation; 0.1 + 0.2 is exactly 0.3
    let spec = r#"{"method": "juttler-affine", "poses": [{"position": [0.1, 0, 0]},
        {"position": ["1/10", 0.2, 0]}, {"position": [0.3, "0.2", 1e-30]}], "samples": 2}"#;
    let file = TempFile::new("precision-decimals.json", spec);
    let out: Value =
        serde_json::from_str(&ok(&["interpolate", "--json", "--scalar", "rational", file.path()])).unwrap();
    assert_eq!(out["samples"][0]["points"][0], serde_json::json!(["1/10", "0", "0"]));
    let tiny = format!("1/1{}", "0".repeat(30));
    assert_eq!(out["samples"][1]["points"][0], serde_json::json!(["3/10", "1/5", tiny]));
}

#[test]
fn what_is_not_rational_exits_2_naming_it() {
    let poses =
        r#"[{"position": [0, 0, 0]}, {"quaternion": [1, 0, 0, 1], "position": [1, 0, 0]}, {"position": [2, 1, 0]}]"#;
    let spec = |method: &str| {
        TempFile::new("precision-refuse.json", &format!(r#"{{"method": "{method}", "poses": {poses}}}"#))
    };
    // ccm-additive without velocities: the estimate takes logarithms
    for method in ["wl-linear", "hexanion-linear", "ccm-additive", "ccm-multiplicative"] {
        let f = spec(method);
        let e = fails(&["interpolate", "--scalar", "rational", f.path()], 2);
        assert!(e.contains(method) && e.contains("not exact") && e.contains("mpfr:BITS"), "{e}");
        // the same spec at 128 bits runs
        ok(&["interpolate", "--scalar", "mpfr:128", f.path()]);
    }
    // the elliptic method normalises [1, 0, 0, 1]: |q| = √2
    let f = spec("juttler-q-motion");
    let e = fails(&["trajectory", "--scalar", "rational", f.path(), "--point", "0,0,0"], 2);
    assert!(e.contains("key pose 1") && e.contains("norm² 2"), "{e}");
    // ... the affine one does not
    let f = spec("juttler-affine");
    ok(&["trajectory", "--scalar", "rational", f.path(), "--point", "0,0,0"]);
    // a pose form with sine and cosine
    let f = TempFile::new(
        "precision-axis.json",
        r#"{"method": "juttler-affine", "poses": [{}, {"axis": [0, 0, 1], "angle": 1}]}"#,
    );
    let e = fails(&["interpolate", "--scalar", "rational", f.path()], 2);
    assert!(e.contains("`poses[1].axis`") && e.contains("sine and cosine"), "{e}");
    // a parametrisation rule measures distances
    let f = TempFile::new(
        "precision-rule.json",
        r#"{"method": "juttler-affine", "parameters": "chordal", "poses": [{}, {"position": [1, 0, 0]}]}"#,
    );
    let e = fails(&["interpolate", "--scalar", "rational", f.path()], 2);
    assert!(e.contains("parametrisation rule"), "{e}");
    let e = fails(&["interpolate", "--scalar", "poly", f.path()], 2);
    assert!(e.contains("not a scalar of the motion commands"), "{e}");
}

#[test]
fn pose_prints_what_is_rational_exactly_and_mpfr_everything() {
    // q = (3/5, 0, 0, 4/5): cos φ = 2w² - 1 = -7/25, sin φ = 2wz = 24/25 (by hand)
    let pose = r#"{"quaternion": [0.6, 0, 0, 0.8], "position": [1, "1/3", 0]}"#;
    let want = serde_json::json!([
        ["-7/25", "-24/25", "0", "1"],
        ["24/25", "-7/25", "0", "1/3"],
        ["0", "0", "1", "0"],
        ["0", "0", "0", "1"]
    ]);
    let out: Value = serde_json::from_str(&ok(&["pose", "--json", "--scalar", "rational", pose])).unwrap();
    assert_eq!(out["matrix"], want);
    assert_eq!(out["position"], serde_json::json!(["1", "1/3", "0"]));
    // the irrational representations are left out, not approximated
    assert_eq!(out.as_object().unwrap().len(), 2, "{out}");
    // the same non-unit quaternion (scaled by 5) gives the same exact matrix
    let scaled = r#"{"quaternion": [3, 0, 0, 4], "position": [1, "1/3", 0]}"#;
    let again: Value = serde_json::from_str(&ok(&["pose", "--json", "--scalar", "rational", scaled])).unwrap();
    assert_eq!(again["matrix"], want);
    // mpfr:256: every representation, the matrix within 1e-70 of the exact one
    let hi: Value = serde_json::from_str(&ok(&["pose", "--json", "--scalar", "mpfr:256", pose])).unwrap();
    for (i, row) in want.as_array().unwrap().iter().enumerate() {
        for (j, x) in row.as_array().unwrap().iter().enumerate() {
            let err = rational_to_f64(&(exact(&hi["matrix"][i][j]) - exact(x))).abs();
            assert!(err < 1e-70, "matrix[{i}][{j}]: {err:e}");
        }
    }
    for key in ["quaternion", "axis", "angle", "motor", "dual_quaternion", "hexanion", "screw", "cga_rotor"] {
        assert!(hi.get(key).is_some(), "{key} missing at mpfr:256");
    }
    // the unit quaternion at 256 bits: (3/5, 0, 0, 4/5) to 1e-70
    let q: Vec<Q> = hi["quaternion"].as_array().unwrap().iter().map(exact).collect();
    let want_q =
        [Q::new(3.into(), 5.into()), Q::from_integer(0.into()), Q::from_integer(0.into()), Q::new(4.into(), 5.into())];
    for (a, b) in q.iter().zip(&want_q) {
        assert!(rational_to_f64(&(a - b)).abs() < 1e-70);
    }
    let e = fails(&["pose", "--scalar", "rational", r#"{"hexanion": {"omega": [0, 0, 1], "m": [0, 0, 0]}}"#], 2);
    assert!(e.contains("`pose.hexanion`") && e.contains("exp"), "{e}");
}

#[test]
fn sample_and_hermite_in_every_precision() {
    let case = &cases()[1];
    let mut spec = case["spec"].clone();
    spec["body_points"] = serde_json::json!([[0.5, -1, 2]]);
    let file = TempFile::new("precision-sample.json", &spec.to_string());
    // t = 0, 2/3, 4/3, 2: exact poses and positions, no speeds
    let out: Value =
        serde_json::from_str(&ok(&["sample", "--json", "--samples", "4", "--scalar", "rational", file.path()]))
            .unwrap();
    let samples = out["samples"].as_array().unwrap();
    assert_eq!(samples[1]["t"], "2/3");
    assert!(samples.iter().all(|s| s.get("linear_speed").is_none() && s.get("angular_speed").is_none()));
    let x = [Q::new(1.into(), 2.into()), Q::from_integer((-1).into()), Q::from_integer(2.into())];
    let last: Vec<Q> = samples[3]["position"].as_array().unwrap().iter().map(exact).collect();
    assert_eq!(last, key_images(case, &x)[3].to_vec());
    // the text table of the exact samples has no speed columns
    let text = ok(&["sample", "--samples", "4", "--scalar", "rational", file.path()]);
    assert!(!text.contains("speed") && text.contains("2/3"), "{text}");
    // mpfr:256 against f64: positions and speeds agree to 1e-12
    let hi: Value =
        serde_json::from_str(&ok(&["sample", "--json", "--samples", "4", "--scalar", "mpfr:256", file.path()]))
            .unwrap();
    let lo: Value = serde_json::from_str(&ok(&["sample", "--json", "--samples", "4", file.path()])).unwrap();
    for (a, b) in hi["samples"].as_array().unwrap().iter().zip(lo["samples"].as_array().unwrap()) {
        for key in ["position", "linear_speed", "angular_speed"] {
            for (x, y) in numbers(&a[key]).iter().zip(numbers(&b[key])) {
                assert!((x - y).abs() < 1e-12 * (1.0 + y.abs()), "{key}: {x} vs {y}");
            }
        }
    }
    // a Hermite spec: mpfr runs (and agrees with f64), rational exits 2
    let hermite = TempFile::new("precision-hermite.json", common::CONTRACT_EXAMPLE);
    let hi: Value = serde_json::from_str(&ok(&["hermite", "--json", "--scalar", "mpfr:200", hermite.path()])).unwrap();
    let lo: Value = serde_json::from_str(&ok(&["hermite", "--json", hermite.path()])).unwrap();
    let c = |v: &Value| -> Vec<f64> {
        v["control_poses"]
            .as_array()
            .unwrap()
            .iter()
            .flat_map(|m| m.as_object().unwrap().values().map(|x| rational_to_f64(&exact(x))).collect::<Vec<_>>())
            .collect()
    };
    let (a, b) = (c(&hi), c(&lo));
    assert_eq!(a.len(), b.len());
    for (x, y) in a.iter().zip(&b) {
        assert!((x - y).abs() < 1e-12 * (1.0 + y.abs()), "{x} vs {y}");
    }
    for args in
        [["hermite", "--scalar", "rational", hermite.path()], ["sample", "--scalar", "rational", hermite.path()]]
    {
        let mut args = args.to_vec();
        if args[0] == "sample" {
            args.extend(["--samples", "3"]);
        }
        let e = fails(&args, 2);
        assert!(e.contains("axis and angle") && e.contains("mpfr:BITS"), "{e}");
    }
    ok(&["sample", "--samples", "3", "--scalar", "mpfr:100", hermite.path()]);
}

/// A surface patch of `gam surface --json` at `(u, v)`, exactly.
fn surface_at(seg: &Value, u: &Q, v: &Q) -> [Q; 3] {
    let w: Vec<Vec<Q>> =
        seg["weights"].as_array().unwrap().iter().map(|r| r.as_array().unwrap().iter().map(exact).collect()).collect();
    let p: Vec<Vec<Vec<Q>>> = seg["points"]
        .as_array()
        .unwrap()
        .iter()
        .map(|r| r.as_array().unwrap().iter().map(|q| q.as_array().unwrap().iter().map(exact).collect()).collect())
        .collect();
    let (du, dv) = (w.len() - 1, w[0].len() - 1);
    let mut den = Q::from_integer(0.into());
    let mut num = [den.clone(), den.clone(), den.clone()];
    for i in 0..=du {
        for j in 0..=dv {
            let b = bernstein(du, i, u) * bernstein(dv, j, v) * &w[i][j];
            for k in 0..3 {
                num[k] += &b * &p[i][j][k];
            }
            den += b;
        }
    }
    num.map(|x| x / &den)
}

#[test]
fn kinematic_surfaces_sweep_the_curve_through_the_key_poses() {
    // the rational segment from (1/2, -1, 2) (weight 1) to (0, 1, 1) (weight 2)
    let curve = TempFile::new("precision-curve.json", r#"{"points": [[0.5, -1, 2], [0, 1, 1]], "weights": [1, 2]}"#);
    let v = Q::new(1.into(), 3.into());
    // the curve point at v = 1/3: (w0 (1-v) p0 + w1 v p1) / (w0 (1-v) + w1 v)
    let x: [Q; 3] = {
        let (a, b) = (Q::new(2.into(), 3.into()), Q::new(2.into(), 3.into()));
        let p0 = [Q::new(1.into(), 2.into()), Q::from_integer((-1).into()), Q::from_integer(2.into())];
        let p1 = [Q::from_integer(0.into()), Q::from_integer(1.into()), Q::from_integer(1.into())];
        std::array::from_fn(|k| (&a * &p0[k] + &b * &p1[k]) / (&a + &b))
    };
    for case in cases() {
        let spec = TempFile::new("precision-surface.json", &case["spec"].to_string());
        let exact_out: Value = serde_json::from_str(&ok(&[
            "surface",
            "--json",
            "--scalar",
            "rational",
            spec.path(),
            "--curve",
            curve.path(),
        ]))
        .unwrap();
        let seg = &exact_out["segments"][0];
        assert_eq!(seg["degrees"], serde_json::json!([case["segments"][0]["degree"], 1]));
        // at each key parameter the surface is the key pose applied to the curve
        for (u, want) in key_parameters(&case).iter().zip(key_images(&case, &x)) {
            assert_eq!(surface_at(seg, u, &v), want, "{}", case["name"]);
        }
        // column 0 is the trajectory of the curve's first point (weight 1)
        let first = &case["segments"][0];
        let col0: Vec<Value> = seg["points"].as_array().unwrap().iter().map(|r| r[0].clone()).collect();
        let w0: Vec<Value> = seg["weights"].as_array().unwrap().iter().map(|r| r[0].clone()).collect();
        if case["point"] == "1/2,-1,2" {
            assert_eq!((Value::from(col0), Value::from(w0)), (first["points"].clone(), first["weights"].clone()));
        }
        // f64 agrees to 1e-12
        let f64_out: Value =
            serde_json::from_str(&ok(&["surface", "--json", spec.path(), "--curve", curve.path()])).unwrap();
        let (a, b) = (numbers(&f64_out["segments"][0]["points"]), numbers(&seg["points"]));
        let scale = b.iter().fold(1.0f64, |m, x| m.max(x.abs()));
        assert!(a.iter().zip(&b).all(|(x, y)| (x - y).abs() <= 1e-12 * scale), "{}", case["name"]);
    }
    // refusals
    let wl = TempFile::new(
        "precision-surface-wl.json",
        r#"{"method": "wl-linear", "poses": [{}, {"position": [1, 0, 0]}]}"#,
    );
    let e = fails(&["surface", wl.path(), "--curve", curve.path()], 2);
    assert!(e.contains("not rational"), "{e}");
    let bad = TempFile::new("precision-curve-bad.json", r#"{"points": [[0, 0, 0]], "weights": [1, 2]}"#);
    let spec = TempFile::new("precision-surface-ok.json", &cases()[0]["spec"].to_string());
    let e = fails(&["surface", spec.path(), "--curve", bad.path()], 2);
    assert!(e.contains("`weights` has 2 values for 1 points"), "{e}");
}

/// Exact and MPFR work is budgeted like f64 work, scaled by what an operation costs there
/// (`MotionScalar::cost_factor`): a global interpolant through 40 rational key poses, which ran
/// past two minutes, and 20 poses at 100000 bits are refused at once (exit 2), not run.
#[test]
fn exact_and_mpfr_work_is_budgeted() {
    let poses: Vec<String> = (0..40)
        .map(|i| format!(r#"{{"quaternion": [{}, 0.6, 0, 0.8], "position": [{i}, {}, 0.5]}}"#, 1 + i % 3, i % 7))
        .collect();
    let spec = TempFile::new(
        "precision-budget.json",
        &format!(r#"{{"method": "juttler-q-motion", "poses": [{}]}}"#, poses.join(", ")),
    );
    let started = std::time::Instant::now();
    let e = fails(&["interpolate", "--scalar", "rational", spec.path()], 2);
    assert!(e.contains("40 key poses (rational)") && e.contains("GAM_WORK_BUDGET"), "{e}");
    let twenty = TempFile::new(
        "precision-budget-20.json",
        &format!(r#"{{"method": "juttler-q-motion", "poses": [{}]}}"#, poses[..20].join(", ")),
    );
    let e = fails(&["trajectory", "--scalar", "mpfr:100000", twenty.path(), "--point", "0,0,0"], 2);
    assert!(e.contains("(mpfr:100000)"), "{e}");
    assert!(started.elapsed().as_secs() < 10, "refused before the work");
}

/// A literal beyond f64 is a rational like any other under `--scalar rational` (and an MPFR
/// number under `mpfr:BITS`); f64 refuses it as before.
#[test]
fn literals_beyond_f64_are_read_exactly() {
    let spec = TempFile::new(
        "precision-1e400.json",
        r#"{"method": "juttler-affine", "samples": 2, "poses": [{"position": [1e400, 0, 0]}, {"position": [1, 0, 0]}]}"#,
    );
    let out: Value =
        serde_json::from_str(&ok(&["interpolate", "--json", "--scalar", "rational", spec.path()])).unwrap();
    assert_eq!(out["samples"][0]["points"][0][0], Value::from(format!("1{}", "0".repeat(400))));
    let hi: Value = serde_json::from_str(&ok(&["interpolate", "--json", "--scalar", "mpfr:64", spec.path()])).unwrap();
    assert!(hi["samples"][0]["points"][0][0].as_str().unwrap().ends_with("e400"), "{hi}");
    assert!(fails(&["interpolate", spec.path()], 2).contains("number out of range"));
    // gam sample tells a spec of gam interpolate from one of gam hermite by the same exact read
    let sampled: Value =
        serde_json::from_str(&ok(&["sample", "--json", "--samples", "2", "--scalar", "rational", spec.path()]))
            .unwrap();
    assert_eq!(sampled["samples"][0]["position"][0], Value::from(format!("1{}", "0".repeat(400))));
}

/// `ccm-additive` over the rationals (with given velocities and key quaternions of rational
/// norm): the main paper's additive C1 Hermite motion exactly. Its samples agree with f64's to
/// 1e-12, it hits the key poses exactly (Rodrigues' images computed here), and its rational
/// trajectories (degree 6) join C1 exactly: value and derivative at the break from the printed
/// control points.
#[test]
fn ccm_additive_is_exact_with_given_velocities() {
    let spec = r#"{"method": "ccm-additive", "samples": 5, "body_points": [[0.5, -1, 2]], "parameters": [0, 0.5, 2],
        "poses": [{"position": [0, 0, 0]}, {"position": [1, 1, 0], "quaternion": [0.6, 0, 0, 0.8]},
                  {"position": [2, 0, 0.5], "quaternion": [2, 1, 2, 0]}],
        "velocities": [{"velocity": [1, 0, 0], "angular_velocity": [0, 0, 0.5]},
                       {"velocity": [0, 1, 0.5], "angular_velocity": [0.1, 0, 0.5]},
                       {"velocity": [0.5, 0, 1], "angular_velocity": [0, 0.2, 0]}],
        "shape": [1, 2, 0.5], "gamma": [0.25, 0.5]}"#;
    let file = TempFile::new("precision-ccm.json", spec);
    let ex: Value = serde_json::from_str(&ok(&["interpolate", "--json", "--scalar", "rational", file.path()])).unwrap();
    let lo: Value = serde_json::from_str(&ok(&["interpolate", "--json", file.path()])).unwrap();
    assert_eq!(ex["segments"][0]["representation"], "additive-bezier");
    for (a, b) in ex["samples"].as_array().unwrap().iter().zip(lo["samples"].as_array().unwrap()) {
        for key in ["points", "velocities", "angular_velocity", "matrix"] {
            for (x, y) in numbers(&a[key]).iter().zip(numbers(&b[key])) {
                assert!((x - y).abs() < 1e-12 * (1.0 + y.abs()), "{key}: {x} vs {y}");
            }
        }
    }
    // the key poses, exactly: sample t = 0 and t = 2, key 1 at t = 1/2
    let keys = serde_json::json!({"keys": [{"quaternion": [1, 0, 0, 0], "position": [0, 0, 0]},
        {"quaternion": ["3/5", 0, 0, "4/5"], "position": [1, 1, 0]}, {"quaternion": [2, 1, 2, 0], "position": [2, 0, "1/2"]}]});
    let x = [Q::new(1.into(), 2.into()), Q::from_integer((-1).into()), Q::from_integer(2.into())];
    let want = key_images(&keys, &x);
    for (sample, key) in [(0, 0), (1, 1), (4, 2)] {
        let p: Vec<Q> = ex["samples"][sample]["points"][0].as_array().unwrap().iter().map(exact).collect();
        assert_eq!(p, want[key].to_vec(), "key pose {key}");
    }
    // exactly C1 at the break t = 1/2
    let segs = exact_c1_segments(file.path(), "1/2,-1,2");
    assert_eq!(segs.len(), 2, "one break, at t = 1/2");
    assert!(segs.iter().all(|s| s["degree"] == 6));
}
