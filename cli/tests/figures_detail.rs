//! The details of the gallery beyond paths and speeds (docs/figures.md): the main paper's
//! Fig. 8 dashed arcs (the paths of the middle control poses as a shape factor varies: circular
//! arcs in this planar example), the shaded L faces of the blocks of Figs. 6-10, Jüttler's
//! face markings (squares, triangles, crosses on the three pairs of opposite faces of the unit
//! cube) and Fig. 5a's parabola drawn as the moving body, each checked in the data
//! (`gam figures --json`) against Rodrigues matrices of the key poses, and counted in the SVGs.

use crate::common;

use common::{ok, rodrigues};
use serde_json::Value;
use std::sync::OnceLock;

/// `gam figures --json` once: the data and every SVG by file name.
fn run() -> &'static (Value, Vec<(String, String)>) {
    static RUN: OnceLock<(Value, Vec<(String, String)>)> = OnceLock::new();
    RUN.get_or_init(|| {
        let dir = std::env::temp_dir().join(format!("gam-cli-test-{}-figures-detail", std::process::id()));
        std::fs::create_dir_all(&dir).expect("a temp directory");
        let data: Value = serde_json::from_str(&ok(&["figures", "--json", "--out", dir.to_str().unwrap()])).unwrap();
        let files: Vec<String> = data.as_object().unwrap().keys().cloned().collect();
        let svgs = files.iter().map(|f| (f.clone(), std::fs::read_to_string(dir.join(f)).expect("written"))).collect();
        let _ = std::fs::remove_dir_all(&dir);
        (data, svgs)
    })
}

fn svg(file: &str) -> &'static str {
    &run().1.iter().find(|(f, _)| f == file).unwrap_or_else(|| panic!("no {file}")).1
}

fn point(v: &Value) -> [f64; 3] {
    serde_json::from_value(v.clone()).expect("[x, y, z]")
}

fn points(v: &Value) -> Vec<[f64; 3]> {
    v.as_array().expect("a list").iter().map(point).collect()
}

fn sub(a: &[f64; 3], b: &[f64; 3]) -> [f64; 3] {
    std::array::from_fn(|i| a[i] - b[i])
}

fn dist(a: &[f64; 3], b: &[f64; 3]) -> f64 {
    sub(a, b).iter().map(|x| x * x).sum::<f64>().sqrt()
}

fn cross(a: &[f64; 3], b: &[f64; 3]) -> [f64; 3] {
    [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
}

/// The marks of `kind` in series 0 of `file`.
fn marks(file: &str, kind: &str) -> Vec<(f64, Vec<[f64; 3]>)> {
    let s = &run().0[file]["series"][0];
    let all = s["marks"].as_array().map(|a| a.as_slice()).unwrap_or_default();
    all.iter().filter(|m| m["kind"] == kind).map(|m| (m["t"].as_f64().unwrap(), points(&m["points"]))).collect()
}

/// `M x` for the 4x4 matrix `m`.
fn apply(m: &[[f64; 4]; 4], x: &[f64; 3]) -> [f64; 3] {
    std::array::from_fn(|i| m[i][0] * x[0] + m[i][1] * x[1] + m[i][2] * x[2] + m[i][3])
}

/// The Rodrigues matrices of the key poses of a Jüttler figure and their parameters.
fn key_matrices(file: &str) -> Vec<(f64, [[f64; 4]; 4])> {
    let fig = &run().0[file];
    let keys: Vec<([f64; 3], f64, [f64; 3])> = serde_json::from_value(fig["keys"].clone()).unwrap();
    let times = fig["series"][0]["key_times"].as_array().unwrap().iter().map(|t| t.as_f64().unwrap());
    times.zip(keys.iter().map(|(a, phi, t)| rodrigues(*a, *phi, *t))).collect()
}

#[test]
fn fig_8_draws_the_middle_control_poses_paths_as_dashed_circular_arcs() {
    let arcs = marks("fig8.svg", "arc");
    assert_eq!(arcs.len(), 2, "the paths of S_1 (lambda0) and S_2 (lambda3)");
    for (t, p) in &arcs {
        assert_eq!(p.len(), 61, "t = {t}");
        // Planar (x = 0) and on one circle: the centre from three points, every point at
        // the same distance (a straight or elliptic path would fail).
        assert!(p.iter().all(|q| q[0].abs() < 1e-12), "t = {t}: not in the y-z plane");
        let [a, b, c] = [p[0], p[30], p[60]].map(|q| [q[1], q[2]]);
        let d = 2.0 * (a[0] * (b[1] - c[1]) + b[0] * (c[1] - a[1]) + c[0] * (a[1] - b[1]));
        let n = |q: [f64; 2]| q[0] * q[0] + q[1] * q[1];
        let ux = (n(a) * (b[1] - c[1]) + n(b) * (c[1] - a[1]) + n(c) * (a[1] - b[1])) / d;
        let uy = (n(a) * (c[0] - b[0]) + n(b) * (a[0] - c[0]) + n(c) * (b[0] - a[0])) / d;
        let centre = [0.0, ux, uy];
        let r = dist(&p[0], &centre);
        assert!(r.is_finite() && r > 0.1 && r < 100.0, "t = {t}: radius {r}");
        for q in p {
            assert!((dist(q, &centre) - r).abs() < 1e-9 * r, "t = {t}: {q:?} off the circle of radius {r}");
        }
        assert!(dist(&p[0], &p[60]) > 0.5, "t = {t}: the arc has length");
    }
    // Dashed: 20 dashes of 3 points per arc, in the arcs' grey; no arc in Fig. 9.
    let dashes = svg("fig8.svg").matches(r##"stroke="#646464""##).count();
    assert_eq!(dashes, 40);
    assert!(marks("fig9.svg", "arc").is_empty());
    assert_eq!(svg("fig9.svg").matches(r##"stroke="#646464""##).count(), 0);
}

#[test]
fn the_l_blocks_are_shaded() {
    for file in ["fig6.svg", "fig7.svg", "fig8.svg", "fig9.svg", "fig10.svg"] {
        let frames: usize =
            run().0[file]["series"].as_array().unwrap().iter().map(|s| s["frames"].as_array().unwrap().len()).sum();
        // the two L faces of every block, one filled polygon each (the 3-D view's three
        // translucent black back panels are polygons too)
        let shaded = svg(file).matches(r##"fill="#BEBEBE" opacity="0.6""##).count();
        assert_eq!(shaded, 2 * frames, "{file}");
        assert_eq!(svg(file).matches(r##"fill="#BEBEBE""##).count(), 2 * frames, "{file}");
    }
}

#[test]
fn juttlers_face_markings_move_with_the_cube() {
    let square = [[0.3, 0.3], [0.7, 0.3], [0.7, 0.7], [0.3, 0.7], [0.3, 0.3]];
    let triangle = [[0.3, 0.3], [0.7, 0.3], [0.5, 0.7], [0.3, 0.3]];
    for file in ["juttler_fig1.svg", "juttler_fig2.svg", "juttler_fig3.svg", "juttler_fig4.svg", "juttler_fig6.svg"] {
        let frames = run().0[file]["series"][0]["frames"].as_array().unwrap().len();
        let (sq, tr, cr) = (marks(file, "square"), marks(file, "triangle"), marks(file, "cross"));
        assert_eq!((sq.len(), tr.len(), cr.len()), (2 * frames, 2 * frames, 4 * frames), "{file}");
        // squares and triangles filled: four polygons per cube
        let filled = svg(file).matches(r##"fill="#282828" opacity="0.6""##).count();
        assert_eq!(filled, 4 * frames, "{file}");
        for (t, m) in key_matrices(file) {
            for (k, shapes, pattern) in [(0, &sq, &square[..]), (1, &tr, &triangle[..])] {
                let at_t: Vec<_> = shapes.iter().filter(|(tm, _)| *tm == t).collect();
                assert_eq!(at_t.len(), 2, "{file} t = {t}");
                for (side, (_, got)) in at_t.iter().enumerate() {
                    // the pattern on the face x_k = side, in the face coordinates (x_{k+1}, x_{k+2})
                    for (q, [a, b]) in got.iter().zip(pattern) {
                        let mut x = [0.0; 3];
                        (x[k], x[(k + 1) % 3], x[(k + 2) % 3]) = (side as f64, *a, *b);
                        assert!(dist(q, &apply(&m, &x)) < 1e-9, "{file} t = {t}: face {k}/{side}");
                    }
                    // its normal is the key rotation's image of e_k
                    let n = cross(&sub(&got[1], &got[0]), &sub(&got[2], &got[1]));
                    let len = n.iter().map(|c| c * c).sum::<f64>().sqrt();
                    let want: [f64; 3] = std::array::from_fn(|i| m[i][k]);
                    assert!(dist(&n.map(|c| c / len), &want) < 1e-9, "{file} t = {t}: normal of face {k}");
                }
            }
            // crosses on z = 0 and z = 1: their strokes' midpoints are the face centres
            let mids: Vec<[f64; 3]> = cr
                .iter()
                .filter(|(tm, _)| *tm == t)
                .map(|(_, p)| std::array::from_fn(|i| 0.5 * (p[0][i] + p[1][i])))
                .collect();
            assert_eq!(mids.len(), 4);
            for (j, mid) in mids.iter().enumerate() {
                let centre = apply(&m, &[0.5, 0.5, (j / 2) as f64]);
                assert!(dist(mid, &centre) < 1e-9, "{file} t = {t}: cross {j}");
            }
        }
    }
}

#[test]
fn fig_5a_draws_the_parabola_at_the_cubes() {
    let file = "juttler_fig5a.svg";
    let curves = marks(file, "curve");
    let frames = run().0[file]["series"][0]["frames"].as_array().unwrap().len();
    assert_eq!(curves.len(), frames);
    // x(v) = (v, 0, 2v(1 - v)): the quadratic Bézier curve of (0,0,0), (1/2,0,1), (1,0,0)
    for (t, m) in key_matrices(file) {
        let (_, p) = curves.iter().find(|(tc, _)| *tc == t).expect("a parabola at every key pose");
        assert_eq!(p.len(), 33);
        for (j, q) in p.iter().enumerate() {
            let v = j as f64 / 32.0;
            assert!(dist(q, &apply(&m, &[v, 0.0, 2.0 * v * (1.0 - v)])) < 1e-9, "t = {t}, v = {v}");
        }
    }
    // one thick dark polyline per parabola
    let thick = svg(file).match_indices("<polyline").filter(|(i, _)| {
        let tag = svg(file)[*i..].split('>').next().unwrap();
        tag.contains(r##"stroke="#282828""##) && tag.contains(r#"stroke-width="2""#)
    });
    assert_eq!(thick.count(), frames);
}
