//! `gam trajectory` (Wave 2 contract, shared/cli.md): the rational Bézier curves of a body
//! point, evaluated here by the Bernstein sum `Σ B_j(u) w_j P_j / Σ B_j(u) w_j` with `u` the
//! segment's local parameter, equal `gam interpolate`'s sampled points; the exact JSON keys;
//! the degree bound 2n; and the error contract (methods whose motions are not rational, a bad
//! `--point`).

use crate::common;

use common::{TempFile, fails, ok};
use serde_json::Value;

const POSES: &str = r#"[{"position": [0, 0, 0]},
  {"position": [1, 0, 0.5], "axis": [0, 0, 2], "angle": 1.2},
  {"position": [1, 1, 0], "quaternion": [0.5, 0.5, -0.5, 0.5]},
  {"position": [2, 0, 1], "axis": [1, 1, 1], "angle": -0.7}]"#;

fn spec(method: &str, extra: &str) -> String {
    format!(r#"{{"method": "{method}", "poses": {POSES}{extra}}}"#)
}

/// `C(n, k)`.
fn binomial(n: usize, k: usize) -> f64 {
    (0..k).fold(1.0, |acc, i| acc * (n - i) as f64 / (i + 1) as f64)
}

/// The rational Bézier curve of one `segments[]` object at the local parameter `u`.
fn evaluate(seg: &Value, u: f64) -> [f64; 3] {
    let w: Vec<f64> = serde_json::from_value(seg["weights"].clone()).unwrap();
    let p: Vec<[f64; 3]> = serde_json::from_value(seg["points"].clone()).unwrap();
    let d = seg["degree"].as_u64().unwrap() as usize;
    assert_eq!((w.len(), p.len()), (d + 1, d + 1));
    let b = |j: usize| binomial(d, j) * u.powi(j as i32) * (1.0 - u).powi((d - j) as i32);
    let den: f64 = (0..=d).map(|j| b(j) * w[j]).sum();
    std::array::from_fn(|k| (0..=d).map(|j| b(j) * w[j] * p[j][k]).sum::<f64>() / den)
}

/// (method, segments, degree of the trajectories): 2n for the Q-motions (n = 2m = 6; TRT
/// n = max(l1, l2) + m = 5; the spline's n = 6), 2m for the minimal-order motion, 2n = 6 for
/// the additive cubics.
const RATIONAL: [(&str, usize, u64); 5] = [
    ("juttler-q-motion", 1, 12),
    ("juttler-trt", 1, 10),
    ("juttler-minimal", 1, 6),
    ("juttler-spline", 3, 12),
    ("ccm-additive", 3, 6),
];

#[test]
fn curves_equal_the_sampled_points() {
    for (method, nseg, degree) in RATIONAL {
        for (name, params, x) in
            [("uniform", "", [0.5, -1.0, 2.0]), ("explicit", r#", "parameters": [0, 1, 2.5, 5]"#, [-1.0, 2.0, 0.25])]
        {
            curves_equal_points(method, nseg, degree, name, params, x);
        }
    }
}

fn curves_equal_points(method: &str, nseg: usize, degree: u64, name: &str, params: &str, x: [f64; 3]) {
    {
        let text = spec(method, &format!(r#"{params}, "samples": 101, "body_points": [{x:?}]"#));
        let file = TempFile::new(&format!("traj-{method}-{name}.json"), &text);
        let point = format!("{},{},{}", x[0], x[1], x[2]);
        let curves: Value =
            serde_json::from_str(&ok(&["trajectory", "--json", file.path(), "--point", &point])).expect("JSON");
        let keys: Vec<&String> = curves.as_object().unwrap().keys().collect();
        assert_eq!(keys, ["segments"]);
        let segs = curves["segments"].as_array().unwrap();
        assert_eq!(segs.len(), nseg, "{method}");
        for s in segs {
            let keys: Vec<&String> = s.as_object().unwrap().keys().collect();
            assert_eq!(keys, ["t0", "t1", "degree", "weights", "points"]);
            assert_eq!(s["degree"].as_u64().unwrap(), degree, "{method}");
        }
        let sampled: Value = serde_json::from_str(&ok(&["interpolate", "--json", file.path()])).expect("JSON");
        for s in sampled["samples"].as_array().unwrap() {
            let t = s["t"].as_f64().unwrap();
            let seg = segs
                .iter()
                .find(|g| g["t0"].as_f64().unwrap() <= t && t <= g["t1"].as_f64().unwrap())
                .expect("a segment holds t");
            let (t0, t1) = (seg["t0"].as_f64().unwrap(), seg["t1"].as_f64().unwrap());
            let got = evaluate(seg, (t - t0) / (t1 - t0));
            let want: [f64; 3] = serde_json::from_value(s["points"][0].clone()).unwrap();
            assert!((0..3).all(|k| (got[k] - want[k]).abs() < 1e-12), "{method} {name} t = {t}: {got:?} vs {want:?}");
        }
        // the text form lists the same control points
        let text = ok(&["trajectory", file.path(), "--point", &point]);
        let count = text.lines().filter(|l| l.trim_start().starts_with('w')).count();
        assert_eq!(count, nseg * (degree as usize + 1), "{text}");
    }
}

#[test]
fn methods_whose_motions_are_not_rational_exit_2() {
    for method in ["ccm-multiplicative", "wl-linear", "wl-quadratic", "hexanion-linear"] {
        let file = TempFile::new(&format!("traj-{method}.json"), &spec(method, ""));
        for json in [false, true] {
            let mut args = vec!["trajectory", file.path(), "--point", "0,0,0"];
            if json {
                args.push("--json");
            }
            let e = fails(&args, 2);
            assert!(e.contains(method) && e.contains("not rational"), "{e}");
        }
    }
}

#[test]
fn errors() {
    let file = TempFile::new("traj-err.json", &spec("juttler-q-motion", ""));
    for bad in ["0,0", "1,2,x", "1,2,3,4", "nan,0,0", ""] {
        let e = fails(&["trajectory", file.path(), "--point", bad], 2);
        assert!(e.contains("--point"), "{bad}: {e}");
    }
    fails(&["trajectory", file.path()], 2); // --point is required
    let e = fails(&["trajectory", "/nonexistent/spec.json", "--point", "0,0,0"], 2);
    assert!(e.contains("cannot read"), "{e}");
    let unknown = TempFile::new("traj-unknown.json", &spec("juttler-slerp", ""));
    let e = fails(&["trajectory", unknown.path(), "--point", "0,0,0"], 2);
    assert!(e.contains("unknown method `juttler-slerp`"), "{e}");
}
