//! Fuzzing that checks values (issue 30, item 5): random good inputs to `gam pose` and to
//! `gam interpolate` with every method, each run under a memory cap (`ulimit -v`, 4 GB) and
//! a timeout, and every result checked against invariants that need no oracle:
//!
//! - `gam pose`: the matrix is rigid, and every representation it prints, read back as a pose
//!   object (position + axis + angle, position + quaternion, matrix, motor, dual quaternion,
//!   hexanion), gives the same matrix;
//! - `gam interpolate --json`, every method: every sampled matrix is rigid, the motion hits
//!   every key pose at its parameter (Rodrigues' matrix of the key pose, computed here), and the
//!   body points' positions are the matrices applied to them.
//!
//! The counts of inputs and checks are printed (`--nocapture`) and in docs/robustness.md.

use crate::common;

use algebra_core::test_support::Xorshift;
use common::{TempFile, matrix, max_diff, rodrigues};
use serde_json::Value;
use std::process::Command;

/// `gam ARGS` under `ulimit -v` (4 GB) and the contract's timeout; exit 0 required.
fn gam_capped(args: &[&str]) -> Value {
    gam_try(args).unwrap_or_else(|(code, stderr)| panic!("gam {args:?}: exit {code:?}: {stderr}"))
}

/// `gam ARGS` as [`gam_capped`], or its exit code and stderr when it fails.
fn gam_try(args: &[&str]) -> Result<Value, (Option<i32>, String)> {
    let mut cmd = Command::new("sh");
    cmd.arg("-c").arg("ulimit -v 4000000 && exec \"$0\" \"$@\"").arg(env!("CARGO_BIN_EXE_gam")).args(args);
    let out = cmd.output().expect("run gam under sh");
    if !out.status.success() {
        return Err((out.status.code(), String::from_utf8_lossy(&out.stderr).into_owned()));
    }
    Ok(serde_json::from_slice(&out.stdout).unwrap_or_else(|e| panic!("gam {args:?}: not JSON ({e})")))
}

/// Methods whose papers name inputs they cannot take, with the refusals they may give on
/// random poses (one `error:` line, exit 1): the affine rotations cannot reach a half turn
/// (Jüttler: "at infinity"); the projective rotations may pass near the zero quaternion
/// (Jüttler's somersaults), where f64 loses the key poses and the build refuses; TRT's system (34) is
/// singular when the relative rotations share an axis.
const MAY_REFUSE: [(&str, &[&str]); 3] = [
    ("juttler-affine", &["at infinity", "numerically unstable"]),
    // (34) is singular when the relative rotations share an axis (the random poses include
    // several of the same orientation: angles 0 and 1e-9)
    ("juttler-trt", &["share an axis"]),
    ("juttler-projective", &["numerically unstable", "inaccessible", "not unique", "only the trivial"]),
];

fn num(v: &Value) -> f64 {
    v.as_f64().unwrap_or_else(|| v.as_str().and_then(|s| s.parse().ok()).unwrap_or_else(|| panic!("not a number: {v}")))
}

/// Orthonormal rotation block (to `1e-12`), determinant +1, bottom row `[0, 0, 0, 1]` exactly.
fn assert_rigid(m: &[[f64; 4]; 4], what: &str) {
    for i in 0..3 {
        for j in 0..3 {
            let dot: f64 = (0..3).map(|k| m[k][i] * m[k][j]).sum();
            let want = if i == j { 1.0 } else { 0.0 };
            assert!((dot - want).abs() < 1e-12, "{what}: columns {i}, {j} give {dot}");
        }
    }
    let det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
        + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    assert!((det - 1.0).abs() < 1e-12, "{what}: det {det}");
    assert_eq!(m[3], [0.0, 0.0, 0.0, 1.0], "{what}");
}

/// A random key pose: axis, angle (edges 0 and π included), position.
fn random_pose(rng: &mut Xorshift) -> ([f64; 3], f64, [f64; 3]) {
    let axis = [rng.symmetric(), rng.symmetric(), rng.symmetric() + 0.05];
    let angle = match rng.below(8) {
        0 => 0.0,
        1 => std::f64::consts::PI,
        2 => 1e-9,
        _ => 3.0 * rng.unit(),
    };
    (axis, angle, [4.0 * rng.symmetric(), 4.0 * rng.symmetric(), 4.0 * rng.symmetric()])
}

fn pose_json((axis, angle, p): &([f64; 3], f64, [f64; 3])) -> String {
    format!(r#"{{"position": {p:?}, "axis": {axis:?}, "angle": {angle:?}}}"#)
}

#[test]
fn pose_representations_round_trip() {
    let mut rng = Xorshift(0x0ddb_a11c_afe5_eed5);
    let (mut inputs, mut checks) = (0, 0);
    for _ in 0..25 {
        let key = random_pose(&mut rng);
        let out = gam_capped(&["pose", "--json", &pose_json(&key)]);
        inputs += 1;
        let m = matrix(&out["matrix"]);
        assert_rigid(&m, "gam pose");
        let want = rodrigues(key.0, key.1, key.2);
        assert!(max_diff(&m, &want) < 1e-12 * 8.0, "{key:?}: {m:?} vs {want:?}");
        let forms = [
            format!(r#"{{"position": {}, "axis": {}, "angle": {}}}"#, out["position"], out["axis"], out["angle"]),
            format!(r#"{{"position": {}, "quaternion": {}}}"#, out["position"], out["quaternion"]),
            format!(r#"{{"matrix": {}}}"#, out["matrix"]),
            format!(r#"{{"motor": {}}}"#, out["motor"]),
            format!(r#"{{"dual_quaternion": {}}}"#, out["dual_quaternion"]),
            format!(r#"{{"hexanion": {}}}"#, out["hexanion"]),
        ];
        for form in &forms {
            let back = matrix(&gam_capped(&["pose", "--json", form])["matrix"]);
            inputs += 1;
            checks += 1;
            assert!(max_diff(&back, &m) < 1e-12 * 8.0, "{form}: {back:?} vs {m:?}");
        }
    }
    eprintln!("value fuzz gam pose: {inputs} inputs, {checks} round trips, 0 mismatches");
}

#[test]
fn every_method_hits_its_key_poses_with_rigid_samples() {
    let methods = motion::method::Method::ALL.map(|m| m.name());
    let mut rng = Xorshift(0x005e_ed0f_f00d_cafe);
    let file = TempFile::empty("fuzz-values-spec.json");
    let (mut inputs, mut hits, mut rigid) = (0, 0, 0);
    let body = [[0.5, -1.0, 2.0], [0.0, 0.0, 0.0]];
    let mut succeeded = std::collections::BTreeMap::new();
    for round in 0..8 {
        for method in methods {
            let may_refuse = MAY_REFUSE.iter().find(|(m, _)| *m == method).map(|(_, why)| *why);
            if round >= 3 && may_refuse.is_none() {
                continue;
            }
            // the projective method takes m + 1 = 5, 9, ... poses
            let m = if method == "juttler-projective" { 5 } else { 4 + (round % 2) };
            let keys: Vec<_> = (0..m).map(|_| random_pose(&mut rng)).collect();
            let poses: Vec<String> = keys.iter().map(pose_json).collect();
            let n = 4 * (m - 1) + 1;
            let spec = format!(
                r#"{{"method": "{method}", "poses": [{}], "samples": {n}, "body_points": {body:?}}}"#,
                poses.join(", ")
            );
            std::fs::write(file.path(), &spec).unwrap();
            let out = match (gam_try(&["interpolate", "--json", file.path()]), may_refuse) {
                (Ok(out), _) => out,
                (Err((code, stderr)), Some(why)) => {
                    assert_eq!(code, Some(1), "{method}: {stderr}");
                    assert!(stderr.lines().count() == 1 && stderr.starts_with("error:"), "{method}: {stderr}");
                    assert!(why.iter().any(|w| stderr.contains(w)), "{method}: an undocumented refusal: {stderr}");
                    continue;
                }
                (Err((code, stderr)), None) => panic!("{method}: exit {code:?}: {stderr} ({spec})"),
            };
            *succeeded.entry(method).or_insert(0) += 1;
            inputs += 1;
            let params: Vec<f64> = out["parameters"].as_array().unwrap().iter().map(num).collect();
            for s in out["samples"].as_array().unwrap() {
                let mx = matrix(&s["matrix"]);
                assert_rigid(&mx, &format!("{method} at t = {}", s["t"]));
                rigid += 1;
                for (b, p) in body.iter().zip(s["points"].as_array().unwrap()) {
                    let image: [f64; 3] =
                        std::array::from_fn(|i| (0..3).map(|j| mx[i][j] * b[j]).sum::<f64>() + mx[i][3]);
                    for i in 0..3 {
                        assert!((image[i] - num(&p[i])).abs() < 1e-12 * 16.0, "{method}: point {b:?}");
                    }
                }
                if let Some(k) = params.iter().position(|t| *t == num(&s["t"])) {
                    let want = rodrigues(keys[k].0, keys[k].1, keys[k].2);
                    let d = max_diff(&mx, &want);
                    assert!(d < 1e-9, "{method}: key pose {k} missed by {d} ({spec})");
                    hits += 1;
                }
            }
        }
    }
    assert!(hits >= inputs * 4, "{hits} key poses checked in {inputs} runs");
    for method in methods {
        assert!(succeeded.get(method).is_some_and(|n| *n >= 1), "{method} refused every random input: {succeeded:?}");
    }
    eprintln!(
        "value fuzz gam interpolate: {inputs} inputs over {} methods, {rigid} rigid samples, {hits} key poses hit, 0 mismatches",
        methods.len()
    );
}

/// A rational rotation quaternion with a rational norm, by inverse stereographic projection of
/// a random point with two-decimal coordinates: `(1 - r², 2x, 2y, 2z)`, norm `1 + r²` (as
/// decimal literals, exact under `--scalar rational`).
fn rational_quaternion(rng: &mut Xorshift) -> [f64; 4] {
    let c = |rng: &mut Xorshift| (rng.below(201) as f64 - 100.0) / 100.0;
    let (x, y, z) = (c(rng), c(rng), c(rng));
    // two-decimal inputs give four-decimal outputs: exact as decimal literals
    let r2 = ((x * x + y * y + z * z) * 1e4).round() / 1e4;
    [((1.0 - r2) * 1e4).round() / 1e4, 2.0 * x, 2.0 * y, 2.0 * z]
}

/// Exact runs against f64 runs (issue 30's value fuzz, now that `--scalar rational` exists):
/// random rational key poses (quaternions of rational norm, two-decimal positions) through
/// every method that is exact over the rationals; the samples of the exact motion, printed as
/// fractions, and those of the f64 motion agree to 1e-9 of the motion's size wherever f64
/// builds the motion (its refusals are the documented ones, tested above).
#[test]
fn exact_runs_agree_with_f64_runs() {
    let mut rng = Xorshift(0x00e8_ac7f_0064_f00d);
    let file = TempFile::empty("fuzz-values-exact.json");
    let methods = [
        "juttler-affine",
        "juttler-q-motion",
        "juttler-trt",
        "juttler-minimal",
        "juttler-bspline",
        "juttler-projective",
    ];
    let (mut compared, mut numbers) = (0, 0);
    for round in 0..4 {
        for method in methods {
            let m = if method == "juttler-projective" { 5 } else { 3 + (round % 3) };
            let poses: Vec<String> = (0..m)
                .map(|_| {
                    let q = rational_quaternion(&mut rng);
                    let p = [0, 1, 2].map(|_| (rng.below(801) as f64 - 400.0) / 100.0);
                    format!(r#"{{"quaternion": {q:?}, "position": {p:?}}}"#)
                })
                .collect();
            let spec = format!(
                r#"{{"method": "{method}", "poses": [{}], "samples": 9, "body_points": [[0.5, -1, 2]]}}"#,
                poses.join(", ")
            );
            std::fs::write(file.path(), &spec).unwrap();
            let Ok(lo) = gam_try(&["interpolate", "--json", file.path()]) else { continue };
            let hi = gam_try(&["interpolate", "--json", "--scalar", "rational", file.path()])
                .unwrap_or_else(|e| panic!("{method}: the exact run refused what f64 built: {e:?} ({spec})"));
            let flat = |v: &Value| -> Vec<f64> {
                v["samples"]
                    .as_array()
                    .unwrap()
                    .iter()
                    .flat_map(|s| s["points"][0].as_array().unwrap().iter().map(num))
                    .collect()
            };
            let exact: Vec<f64> = hi["samples"]
                .as_array()
                .unwrap()
                .iter()
                .flat_map(|s| {
                    s["points"][0].as_array().unwrap().iter().map(|x| {
                        algebra_core::rational::rational_to_f64(
                            &algebra_core::rational::parse_rational(x.as_str().unwrap()).unwrap(),
                        )
                    })
                })
                .collect();
            let (a, b) = (flat(&lo), exact);
            let size = b.iter().fold(1.0f64, |s, x| s.max(x.abs()));
            for (x, y) in a.iter().zip(&b) {
                assert!((x - y).abs() <= 1e-9 * size, "{method}: f64 {x} vs exact {y} ({spec})");
            }
            compared += 1;
            numbers += a.len();
        }
    }
    assert!(compared >= 18, "only {compared} of 24 runs built in f64");
    eprintln!("exact against f64: {compared} motions, {numbers} coordinates, 0 mismatches beyond 1e-9");
}
