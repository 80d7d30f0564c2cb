//! `gam figures`: the data behind the main paper's Figs. 6-10 and Wareham–Lasenby's Figs. 5
//! and 7 checked against the papers' statements with independently computed references (the
//! end conditions of Sec. 5.1/5.2, the Jaklič path `c(t)` and its derivative, the helix
//! geometry of W-L Sec. 4.1), and the committed SVGs equal to what `gam figures` writes.

use crate::common;

use common::ok;
use serde_json::Value;
use std::sync::OnceLock;

/// The files this test covers.
const FILES: [&str; 7] = ["fig6.svg", "fig7.svg", "fig8.svg", "fig9.svg", "fig10.svg", "wl_fig5.svg", "wl_fig7.svg"];

/// `gam figures --json` once for all tests: the data and the written SVGs.
fn run() -> &'static (Value, Vec<(String, String)>) {
    static RUN: OnceLock<(Value, Vec<(String, String)>)> = OnceLock::new();
    RUN.get_or_init(|| {
        let dir = std::env::temp_dir().join(format!("gam-cli-test-{}-figures-more", std::process::id()));
        std::fs::create_dir_all(&dir).expect("a temp directory");
        let data: Value = serde_json::from_str(&ok(&["figures", "--json", "--out", dir.to_str().unwrap()])).unwrap();
        let svgs =
            FILES.iter().map(|f| (f.to_string(), std::fs::read_to_string(dir.join(f)).expect("written"))).collect();
        let _ = std::fs::remove_dir_all(&dir);
        (data, svgs)
    })
}

/// The series of figure `file`.
fn series(file: &str) -> Vec<Value> {
    run().0[file]["series"].as_array().unwrap_or_else(|| panic!("no {file}")).clone()
}

fn nums(v: &Value) -> Vec<f64> {
    v.as_array().expect("a list").iter().map(|x| x.as_f64().expect("a number")).collect()
}

fn point(v: &Value) -> [f64; 3] {
    serde_json::from_value(v.clone()).expect("[x, y, z]")
}

fn path(s: &Value) -> Vec<[f64; 3]> {
    s["paths"][0].as_array().expect("a path").iter().map(|p| nums(p).try_into().expect("3 coordinates")).collect()
}

fn sub(a: &[f64; 3], b: &[f64; 3]) -> [f64; 3] {
    std::array::from_fn(|i| a[i] - b[i])
}

fn norm(a: &[f64; 3]) -> f64 {
    a.iter().map(|x| x * x).sum::<f64>().sqrt()
}

/// The left and right one-sided second-order difference velocities at sample `i` (step `h`).
fn one_sided(p: &[[f64; 3]], i: usize, h: f64) -> ([f64; 3], [f64; 3]) {
    let left = std::array::from_fn(|k| (3.0 * p[i][k] - 4.0 * p[i - 1][k] + p[i - 2][k]) / (2.0 * h));
    let right = std::array::from_fn(|k| (-3.0 * p[i][k] + 4.0 * p[i + 1][k] - p[i + 2][k]) / (2.0 * h));
    (left, right)
}

#[test]
fn committed_svgs_are_what_gam_figures_writes() {
    for (file, svg) in &run().1 {
        let committed = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../docs/figures").join(file);
        let committed = std::fs::read_to_string(&committed).expect("the gallery has the figure");
        assert!(&committed == svg, "docs/figures/{file} is stale: run `gam figures --out docs/figures`");
        // The L-shaped block is three grey polylines per frame.
        if file.starts_with("fig") {
            let frames: usize = series(file).iter().map(|s| s["frames"].as_array().unwrap().len()).sum();
            assert_eq!(svg.matches(r##"stroke="#5A5A5A""##).count(), 3 * frames, "{file}");
        }
    }
}

#[test]
fn figs_6_and_7_meet_the_sec_5_1_end_conditions() {
    // r0 = 0, r3 = (8, 10, 12); |v0| = |(1, 1, 1)|, |v3| = |(1, 5, 3)|; |Ω0| = |(1, 2, 3)|,
    // |Ω3| = |(2, 1, 1)|: both kinds, the body drawn at t = 0, 0.2, ..., 1.
    for (file, method) in [("fig6.svg", "multiplicative"), ("fig7.svg", "additive")] {
        let s = &series(file)[0];
        assert_eq!(s["method"], method);
        let (p, v, w) = (path(s), nums(&s["speeds"][0]), nums(&s["angular_speed"]));
        assert!(norm(&p[0]) < 1e-12 && norm(&sub(&p[400], &[8.0, 10.0, 12.0])) < 1e-12, "{file}");
        for (got, want) in [(v[0], 3f64), (v[400], 35.0), (w[0], 14.0), (w[400], 6.0)] {
            assert!((got - want.sqrt()).abs() < 1e-9, "{file}: {got} vs sqrt({want})");
        }
        let t: Vec<f64> = s["frames"].as_array().unwrap().iter().map(|f| f["t"].as_f64().unwrap()).collect();
        assert_eq!(t.len(), 6);
        assert!(t.iter().enumerate().all(|(i, ti)| (ti - 0.2 * i as f64).abs() < 1e-15), "{t:?}");
    }
}

#[test]
fn figs_8_and_9_scale_the_end_speeds_by_the_shape_factors() {
    // Ψ0 = λ0 (ν0 + γ0), Ψ3 = λ3 (ν3 + γ3): the end speeds are λ0 |v0| = 8 λ0 and λ3 |v3| = 4 λ3,
    // the angular speeds λ0 π/4 and λ3 π/8, the end tangents keep their directions (e3 at the
    // start, e2 at the end), the end points are r0 = 0 and r3 = (0, 10, 0).
    use std::f64::consts::PI;
    for file in ["fig8.svg", "fig9.svg"] {
        let all = series(file);
        let shapes: Vec<[f64; 2]> = all
            .iter()
            .map(|s| {
                let l = s["label"].as_str().unwrap();
                let n: Vec<f64> = l.split(", ").map(|x| x.rsplit(" = ").next().unwrap().parse().unwrap()).collect();
                [n[0], n[1]]
            })
            .collect();
        assert_eq!(shapes, [[1.0, 1.0], [4.0, 1.0], [1.0, 4.0], [4.0, 4.0]]);
        for (s, [l0, l3]) in all.iter().zip(&shapes) {
            let (p, v, w) = (path(s), nums(&s["speeds"][0]), nums(&s["angular_speed"]));
            assert!(norm(&p[0]) < 1e-12 && norm(&sub(&p[400], &[0.0, 10.0, 0.0])) < 1e-12);
            for (got, want) in [(v[0], 8.0 * l0), (v[400], 4.0 * l3), (w[0], l0 * PI / 4.0), (w[400], l3 * PI / 8.0)] {
                assert!((got - want).abs() < 1e-9, "{file} {}: {got} vs {want}", s["label"]);
            }
            let (d0, d1) = (sub(&p[1], &p[0]), sub(&p[400], &p[399]));
            assert!(d0[2] / norm(&d0) > 0.999 && d1[1] / norm(&d1) > 0.999, "{file}: {d0:?} {d1:?}");
        }
    }
    // The multiplicative motion is planar (x = 0); the additive one with γ's ω parts is not.
    let x = |s: &Value| path(s).iter().map(|p| p[0].abs()).fold(0.0, f64::max);
    assert!(series("fig8.svg").iter().all(|s| x(s) < 1e-12));
    assert!(series("fig9.svg").iter().all(|s| x(s) > 1e-3));
}

/// The Jaklič reference-point path `c(t)` and its derivative (Sec. 5.3).
fn jaklic(t: f64) -> ([f64; 3], [f64; 3]) {
    let (l, dl) = (3.0 * (t + 1.0).ln(), 3.0 / (t + 1.0));
    let c = [l * t.cos(), l * t.sin(), 3.0 * (t + 1.0)];
    let d = [dl * t.cos() - l * t.sin(), dl * t.sin() + l * t.cos(), 3.0];
    (c, d)
}

#[test]
fn fig_10_passes_through_the_nine_poses_c1() {
    // Samples every 0.02 over [1, 9]: t = k at sample 50 (k - 1). Every common shape factor:
    // through c(k); at each join the velocity from the left equals that from the right and is
    // λ c'(k) (the precision velocity scaled by the shape factor); blocks at t = 1..9 on λ = 1.
    let all = series("fig10.svg");
    assert_eq!(all.iter().map(|s| s["label"].as_str().unwrap()).collect::<Vec<_>>(), ["λ = 1", "λ = 0.5", "λ = 1.5"]);
    for (s, lambda) in all.iter().zip([1.0, 0.5, 1.5]) {
        assert_eq!(nums(&s["joins"]), [2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0]);
        let (p, v) = (path(s), nums(&s["speeds"][0]));
        for k in 1..=9 {
            let (c, d) = jaklic(f64::from(k));
            let i = 50 * (k as usize - 1);
            assert!(norm(&sub(&p[i], &c)) < 1e-12, "lambda {lambda}, t = {k}: {:?} vs {c:?}", p[i]);
            assert!((v[i] - lambda * norm(&d)).abs() < 1e-9, "lambda {lambda}, t = {k}: {} vs {}", v[i], norm(&d));
            if (2..=8).contains(&k) {
                let (left, right) = one_sided(&p, i, 0.02);
                let want = d.map(|x| lambda * x);
                for side in [left, right] {
                    assert!(
                        norm(&sub(&side, &want)) < 0.02 * norm(&want),
                        "lambda {lambda}, t = {k}: {side:?} vs {want:?}"
                    );
                }
            }
        }
        let frames = s["frames"].as_array().unwrap();
        let t: Vec<f64> = frames.iter().map(|f| f["t"].as_f64().unwrap()).collect();
        assert_eq!(t, if lambda == 1.0 { (1..=9).map(f64::from).collect() } else { vec![] });
    }
}

#[test]
fn wl_fig_5_linear_has_corners_quadratic_does_not() {
    // Samples every 0.005 over [0, 2]: the middle key pose at sample 200. Both pass through the
    // three key positions; the piecewise-linear path turns by a finite angle there (a corner),
    // the quadratic one is smooth.
    let all = series("wl_fig5.svg");
    let angle = |a: [f64; 3], b: [f64; 3]| {
        let dot: f64 = (0..3).map(|k| a[k] * b[k]).sum();
        (dot / (norm(&a) * norm(&b))).clamp(-1.0, 1.0).acos()
    };
    let mut corners = Vec::new();
    for s in &all {
        let p = path(s);
        for (i, want) in [(0, [0.0, 0.0, 0.0]), (200, [4.0, 3.0, 0.0]), (400, [8.0, 0.0, 1.0])] {
            assert!(norm(&sub(&p[i], &want)) < 1e-12, "{}: {:?} vs {want:?}", s["label"], p[i]);
        }
        let (left, right) = one_sided(&p, 200, 0.005);
        corners.push(angle(left, right));
    }
    assert!(corners[0] > 0.5, "piecewise linear: a corner of {} rad", corners[0]);
    assert!(corners[1] < 1e-3, "quadratic: {} rad", corners[1]);
}

#[test]
fn wl_fig_7_is_the_helix_of_t_par_and_psi() {
    // ψ = 9π, t∥ = 4a + 6b, |t⊥| = 1 (W-L Sec. 4.1): a helix of radius α/ψ (α = |t∥| = √52)
    // about an axis along t⊥ (e3), 9π/2π = 4.5 turns over λ ∈ [0, 1], rising |t⊥| = 1 in all:
    // the pitch is 1/4.5 = 2/9 per turn. Its speed is √(α² + |t⊥|²) = √53 and its angular
    // speed ψ throughout. Samples every 1/400.
    use std::f64::consts::PI;
    let s = &series("wl_fig7.svg")[0];
    let p = path(s);
    let (alpha, psi) = (52f64.sqrt(), 9.0 * PI);
    let radius = alpha / psi;
    // The height falls linearly: z(λ) = -λ |t⊥| (W-L's exp(tn/2) translates by -t).
    for (i, q) in p.iter().enumerate() {
        assert!((q[2] + i as f64 / 400.0).abs() < 1e-12, "z at {i}: {}", q[2]);
    }
    // Half a turn (Δλ = 1/9) apart the points are diametrically opposite: 2 α/ψ apart in x-y.
    for l in [0.0, 0.1, 0.37, 0.8] {
        let (a, b) = (l, l + 1.0 / 9.0);
        let at = |x: f64| {
            let i = x * 400.0;
            let (i0, f) = (i.floor() as usize, i - i.floor());
            let (q0, q1) = (p[i0], p[(i0 + 1).min(400)]);
            [q0[0] + f * (q1[0] - q0[0]), q0[1] + f * (q1[1] - q0[1])]
        };
        let (pa, pb) = (at(a), at(b));
        let d = ((pa[0] - pb[0]).powi(2) + (pa[1] - pb[1]).powi(2)).sqrt();
        assert!((d - 2.0 * radius).abs() < 2e-3, "λ = {l}: {d} vs {}", 2.0 * radius);
    }
    // The end point: |t'∥| = (2α/ψ)|sin(ψ/2)| = 2α/ψ in the plane, z = -1.
    let end = p[400];
    assert!(((end[0].hypot(end[1])) - 2.0 * radius).abs() < 1e-12 && (end[2] + 1.0).abs() < 1e-12, "{end:?}");
    // 4.5 turns: the x-y direction of the velocity turns by ψ = 9π in all.
    let dirs: Vec<f64> = p.windows(2).map(|w| (w[1][1] - w[0][1]).atan2(w[1][0] - w[0][0])).collect();
    let turned: f64 = dirs.windows(2).map(|w| (w[1] - w[0] + PI).rem_euclid(2.0 * PI) - PI).sum();
    assert!((turned.abs() - psi * 399.0 / 400.0).abs() < 1e-9, "turned {turned} vs 9π");
    for (v, w) in nums(&s["speeds"][0]).iter().zip(nums(&s["angular_speed"])) {
        assert!((v - 53f64.sqrt()).abs() < 1e-9 && (w - psi).abs() < 1e-9, "{v} {w}");
    }
    assert!(nums(&s["joins"]).is_empty());
    // The vectors drawn: -t⊥ = -e3 from the origin, then the paper's t'∥ at λ = 1 (Sec. 4.1)
    // by hand: c = cos(9π/2) = 0, s = sin(9π/2) = 1, so t'∥ = -(2/ψ)(a tᵇ - b tᵃ) =
    // (2/(9π)) (-6, 4, 0). It ends where the library's path ends: the paper's formula and
    // the library's exp(λB) agree on the end of the helix.
    let marks = s["marks"].as_array().expect("marks");
    let arrow = |label: &str| {
        let m = marks.iter().find(|m| m["label"] == label).unwrap_or_else(|| panic!("no {label}"));
        assert_eq!(m["kind"], "arrow");
        (point(&m["points"][0]), point(&m["points"][1]))
    };
    let (o, down) = arrow("-t⊥");
    assert_eq!((o, down), ([0.0; 3], [0.0, 0.0, -1.0]));
    let (from, to) = arrow("t'∥");
    let k = 2.0 / (9.0 * PI);
    assert_eq!(from, down);
    let want = [-6.0 * k, 4.0 * k, -1.0];
    for i in 0..3 {
        assert!((to[i] - want[i]).abs() < 1e-15, "t'_par ends at {to:?}, want {want:?}");
        assert!((end[i] - want[i]).abs() < 1e-12, "the path ends at {end:?}, t'_par at {want:?}");
    }
    assert_eq!(arrow("t∥ / 8"), ([0.0; 3], [0.5, 0.75, 0.0]));
}

#[test]
fn gam_plot_draws_the_l_block() {
    // `--body l-block` on an interpolate spec: per frame three grey polylines, the outlines of
    // the two L faces (7 points each, closed) and the zigzag along the 6 edges between them
    // (12 points).
    let spec = r#"{"method": "ccm-multiplicative", "poses": [
        {"position": [0, 0, 0], "axis": [0, 0, 1], "angle": 0},
        {"position": [5, 2, 1], "axis": [0, 1, 0], "angle": 1}]}"#;
    let file = common::TempFile::new("figures-more-l-block.json", spec);
    let out = common::TempFile::empty("figures-more-l-block.svg");
    ok(&["plot", "--out", out.path(), file.path(), "--frames", "4", "--body", "l-block", "--view", "3d"]);
    let svg = std::fs::read_to_string(out.path()).expect("written");
    let grey: Vec<usize> = svg
        .split("<polyline")
        .skip(1)
        .filter(|e| e.contains(r##"stroke="#5A5A5A""##))
        .map(|e| e.split("points=\"").nth(1).expect("points").split('"').next().unwrap().split_whitespace().count())
        .collect();
    assert_eq!(grey, [7, 7, 12].repeat(4));
}

#[test]
fn fig_10s_companion_measures_the_error_against_the_paper_s_path() {
    // The reference point's path of Jaklič et al. as the paper prints it (Sec. 5.3):
    // c(t) = (3 log(t+1) cos t, 3 log(t+1) sin t, 3 (t+1)).
    let c = |t: f64| [3.0 * (t + 1.0).ln() * t.cos(), 3.0 * (t + 1.0).ln() * t.sin(), 3.0 * (t + 1.0)];
    let (hermite, errors) = (series("fig10.svg"), series("fig10_error.svg"));
    assert_eq!(run().0["fig10_error.svg"]["error_against"], "the motion of Jaklic et al.");
    assert_eq!(errors.len(), 4, "three shape factors and the exact motion");
    for (h, e) in hermite.iter().zip(&errors) {
        assert_eq!(h["label"], e["label"]);
        let (t, p, d, w) = (nums(&h["t"]), path(h), nums(&e["speeds"][0]), nums(&e["angular_speed"]));
        for i in 0..t.len() {
            let want = norm(&sub(&p[i], &c(t[i])));
            assert!((d[i] - want).abs() < 1e-9, "{} t = {}: {} vs {want}", h["label"], t[i], d[i]);
            // the Hermite motion interpolates the precision poses at t = 1, ..., 9
            if (t[i] - t[i].round()).abs() < 1e-12 {
                assert!(
                    d[i] < 1e-9 && w[i] < 1e-7,
                    "{} at the precision pose t = {}: {} {}",
                    h["label"],
                    t[i],
                    d[i],
                    w[i]
                );
            }
        }
        let (dmax, wmax) = (d.iter().fold(0.0, |a: f64, b| a.max(*b)), w.iter().fold(0.0, |a: f64, b| a.max(*b)));
        assert!(dmax > 0.01 && wmax > 1e-3, "{}: an interpolant, not the motion itself", h["label"]);
    }
    // λ = 1 follows the exact motion most closely: its largest position error is ten times
    // smaller than with λ = 0.5 or 1.5.
    let dmax = |s: &Value| nums(&s["speeds"][0]).into_iter().fold(0.0, f64::max);
    assert!(10.0 * dmax(&errors[0]) < dmax(&errors[1]).min(dmax(&errors[2])));
    // The exact motion's path is c(t), its error zero.
    let exact = &errors[3];
    for (ti, q) in nums(&exact["t"]).iter().zip(path(exact)) {
        assert!(norm(&sub(&q, &c(*ti))) < 1e-12);
    }
    assert!(nums(&exact["speeds"][0]).iter().chain(&nums(&exact["angular_speed"])).all(|x| *x == 0.0));
}
