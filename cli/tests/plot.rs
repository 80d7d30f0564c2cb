//! `gam plot` on `gam interpolate` specs: the data behind the figure (`--json`) checked
//! numerically against independent references (key poses by Rodrigues' formula, speeds by
//! central differences of the path), every SVG checked well-formed with the expected number
//! of series, every method of `gam interpolate` plotted in every view, overlays, and the
//! error rules.

use crate::common;

use common::{TempFile, fails, ok, rodrigues};
use serde_json::Value;

/// Three key poses at the parameters 0, 1, 3 (position, axis, angle).
const KEYS: [([f64; 3], [f64; 3], f64); 3] = [
    ([0.0, 0.0, 0.0], [0.0, 0.0, 1.0], 0.0),
    ([1.0, 1.0, 0.0], [0.0, 0.0, 1.0], 1.0),
    ([2.0, 0.0, 1.0], [1.0, 0.0, 0.0], 0.5),
];

/// The body points of the specs.
const POINTS: [[f64; 3]; 2] = [[0.0, 0.0, 0.0], [0.5, -1.0, 2.0]];

/// A spec of `method` through [`KEYS`] with [`POINTS`] (`parameters` given when `given`).
fn spec(method: &str, given: bool) -> String {
    let poses: Vec<String> =
        KEYS.iter().map(|(p, a, phi)| format!(r#"{{"position": {p:?}, "axis": {a:?}, "angle": {phi}}}"#)).collect();
    let parameters = if given { r#", "parameters": [0, 1, 3]"# } else { "" };
    format!(r#"{{"method": "{method}", "poses": [{}]{parameters}, "body_points": {POINTS:?}}}"#, poses.join(", "))
}

/// `R x + p` of a key pose, by Rodrigues' formula (independent of the `motion` crate).
fn key_point(k: usize, x: &[f64; 3]) -> [f64; 3] {
    let (p, a, phi) = KEYS[k];
    let m = rodrigues(a, phi, p);
    std::array::from_fn(|i| m[i][0] * x[0] + m[i][1] * x[1] + m[i][2] * x[2] + m[i][3])
}

fn num(v: &Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("not a number: {v}"))
}

fn nums(v: &Value) -> Vec<f64> {
    v.as_array().expect("a list").iter().map(num).collect()
}

fn point(v: &Value) -> [f64; 3] {
    let v = nums(v);
    [v[0], v[1], v[2]]
}

fn dist(a: &[f64; 3], b: &[f64; 3]) -> f64 {
    (0..3).map(|i| (a[i] - b[i]).powi(2)).sum::<f64>().sqrt()
}

/// `gam plot --json ARGS...` into a temporary SVG: the data and the SVG text.
fn plot(name: &str, args: &[&str]) -> (Value, String) {
    let out = TempFile::empty(&format!("{name}.svg"));
    let mut all = vec!["plot", "--json", "--out", out.path()];
    all.extend_from_slice(args);
    let data: Value = serde_json::from_str(&ok(&all)).expect("--json prints JSON");
    let svg = std::fs::read_to_string(out.path()).expect("the SVG was written");
    (data, svg)
}

/// Checks that `svg` is well-formed XML (every tag closed in order, attributes quoted, no
/// stray `<` or `&`) and returns the number of `<polyline>` elements not drawn in black
/// (black ones are the axes and the mesh).
fn check_svg(svg: &str) -> usize {
    let mut stack: Vec<String> = Vec::new();
    let (mut rest, mut series, mut roots) = (svg.trim(), 0, 0);
    while let Some(open) = rest.find('<') {
        let text = &rest[..open];
        assert!(!text.contains('>'), "a stray `>` in {text:?}");
        for (i, _) in text.match_indices('&') {
            let entity = &text[i..text[i..].find(';').map_or(text.len(), |e| i + e + 1)];
            assert!(["&amp;", "&lt;", "&gt;", "&quot;", "&apos;"].contains(&entity), "bad entity {entity:?}");
        }
        let close = rest[open..].find('>').expect("an unclosed tag") + open;
        let tag = &rest[open + 1..close];
        rest = &rest[close + 1..];
        if tag.starts_with('?') || tag.starts_with('!') {
            continue;
        }
        assert_eq!(tag.matches('"').count() % 2, 0, "unbalanced quotes in <{tag}>");
        if let Some(name) = tag.strip_prefix('/') {
            assert_eq!(stack.pop().as_deref(), Some(name.trim()), "</{name}> closes the wrong element");
            continue;
        }
        let name = tag.split_whitespace().next().expect("a tag name").trim_end_matches('/').to_string();
        assert!(name.chars().all(|c| c.is_ascii_alphanumeric()), "bad tag name {name:?}");
        if stack.is_empty() {
            roots += 1;
        }
        if name == "polyline" && !tag.contains(r##"stroke="#000000""##) {
            series += 1;
        }
        if !tag.ends_with('/') {
            stack.push(name);
        }
    }
    assert!(rest.trim().is_empty(), "text after the root element: {rest:?}");
    assert!(stack.is_empty(), "unclosed elements {stack:?}");
    assert_eq!(roots, 1, "one root element");
    series
}

/// The series the figure of `data` must have: per spec, a speed line and a path per body
/// point, an angular speed line, a line per join, three per frame.
fn expected_series(data: &Value) -> usize {
    let series = data["series"].as_array().expect("series");
    let len = |s: &Value, key: &str| s[key].as_array().expect(key).len();
    series.iter().map(|s| 2 * len(s, "body_points") + 1 + len(s, "joins") + 3 * len(s, "frames")).sum()
}

/// The polylines of a figure's `marks` (`gam figures` only): one per mark, but a dashed arc
/// (the main paper's Fig. 8) is one per dash of 3 of its points and an arrow two.
fn mark_lines(data: &Value) -> usize {
    let marks =
        data["series"].as_array().expect("series").iter().flat_map(|s| s["marks"].as_array().into_iter().flatten());
    let lines = |m: &Value| match m["kind"].as_str() {
        Some("arc") => (m["points"].as_array().expect("points").len() - 1) / 3,
        Some("arrow") => 2, // the shaft and the head
        _ => 1,
    };
    marks.map(lines).sum()
}

#[test]
fn two_segment_multiplicative_data() {
    let file = TempFile::new("plot-ccm.json", &spec("ccm-multiplicative", true));
    let (data, svg) = plot("plot-ccm", &[file.path(), "--samples", "31", "--frames", "4"]);
    assert_eq!(check_svg(&svg), expected_series(&data));
    assert_eq!(expected_series(&data), 2 * 2 + 1 + 1 + 3 * 4);
    let s = &data["series"][0];
    assert_eq!(s["method"], "ccm-multiplicative");
    assert_eq!((s["segments"].as_u64(), s["degree"].as_u64()), (Some(2), Some(3)));
    // The join is marked at the middle key parameter, the range is the whole [0, 3].
    assert_eq!(nums(&s["joins"]), [1.0]);
    assert_eq!(nums(&s["key_times"]), [0.0, 1.0, 3.0]);
    let t = nums(&s["t"]);
    assert_eq!(t.len(), 31);
    for (i, ti) in t.iter().enumerate() {
        assert!((ti - 0.1 * i as f64).abs() < 1e-14, "t[{i}] = {ti}");
    }
    // The path passes through the key poses' body points (sample 10 is t = 1).
    for (j, x) in POINTS.iter().enumerate() {
        for (k, i) in [(0, 0), (1, 10), (2, 30)] {
            let want = key_point(k, x);
            let got = point(&s["key_points"][k][j]);
            assert!(dist(&got, &want) < 1e-12, "key {k} point {j}: {got:?} vs {want:?}");
            let on_path = point(&s["paths"][j][i]);
            assert!(dist(&on_path, &want) < 1e-12, "path {j} at t = {}: {on_path:?} vs {want:?}", t[i]);
        }
    }
    // The frames at t = 0, 1, 2, 3: at a key pose, the images of the origin and of e1, e2, e3.
    let frames = s["frames"].as_array().expect("frames");
    assert_eq!(frames.iter().map(|f| num(&f["t"])).collect::<Vec<_>>(), [0.0, 1.0, 2.0, 3.0]);
    for (f, k) in [(0, 0), (1, 1), (3, 2)] {
        let frame = &frames[f];
        assert!(dist(&point(&frame["origin"]), &key_point(k, &[0.0; 3])) < 1e-12);
        for (a, e) in [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]].iter().enumerate() {
            let (got, want) = (point(&frame["axes"][a]), key_point(k, e));
            assert!(dist(&got, &want) < 1e-12, "frame {f} axis {a}: {got:?} vs {want:?}");
        }
    }
}

#[test]
fn speeds_match_central_differences_of_the_path() {
    // A rigid motion: |v| of each body point is |d/dt| of its path, and the frame's axes stay
    // orthonormal; checked away from the join, where the difference quotient straddles it.
    let file = TempFile::new("plot-fd.json", &spec("ccm-multiplicative", true));
    let (data, _) = plot("plot-fd", &[file.path(), "--samples", "3001"]);
    let s = &data["series"][0];
    let t = nums(&s["t"]);
    let h = t[1] - t[0];
    for j in 0..POINTS.len() {
        let speeds = nums(&s["speeds"][j]);
        let path: Vec<[f64; 3]> = s["paths"][j].as_array().unwrap().iter().map(point).collect();
        let mut worst: f64 = 0.0;
        for i in 1..t.len() - 1 {
            if (t[i] - 1.0).abs() < 2.0 * h {
                continue;
            }
            let fd = dist(&path[i + 1], &path[i - 1]) / (2.0 * h);
            worst = worst.max((fd - speeds[i]).abs() / speeds[i].max(1.0));
        }
        assert!(worst < 1e-4, "body point {j}: worst relative difference {worst}");
    }
}

#[test]
fn accelerations_match_second_differences_of_the_path() {
    // |a| of each body point is |d²/dt²| of its path (second central differences, away from
    // the join); |Ω'| bounds the rate of change of |Ω| (|d|Ω|/dt| <= |dΩ/dt|); with
    // `--acceleration` the left panel draws them.
    let file = TempFile::new("plot-acc.json", &spec("ccm-multiplicative", true));
    let (data, svg) = plot("plot-acc", &[file.path(), "--samples", "2001", "--acceleration"]);
    assert!(svg.contains("linear acceleration (solid) and angular acceleration (dashed)"));
    assert!(svg.contains("linear acceleration |a| and path") && !svg.contains("linear speed"));
    let s = &data["series"][0];
    let t = nums(&s["t"]);
    let h = t[1] - t[0];
    let inside = |i: usize| (t[i] - 1.0).abs() > 3.0 * h;
    for j in 0..POINTS.len() {
        let acc = nums(&s["accelerations"][j]);
        let path: Vec<[f64; 3]> = s["paths"][j].as_array().unwrap().iter().map(point).collect();
        let mut worst: f64 = 0.0;
        for i in (1..t.len() - 1).filter(|i| inside(*i)) {
            let fd: [f64; 3] = std::array::from_fn(|k| (path[i + 1][k] - 2.0 * path[i][k] + path[i - 1][k]) / (h * h));
            let fd = fd.iter().map(|x| x * x).sum::<f64>().sqrt();
            worst = worst.max((fd - acc[i]).abs() / acc[i].max(1.0));
        }
        assert!(worst < 1e-3, "body point {j}: worst relative difference {worst}");
    }
    let (w, dw) = (nums(&s["angular_speed"]), nums(&s["angular_acceleration"]));
    assert!(dw.iter().any(|x| *x > 0.1));
    for i in (1..t.len() - 1).filter(|i| inside(*i)) {
        let rate = (w[i + 1] - w[i - 1]).abs() / (2.0 * h);
        assert!(rate <= dw[i] * (1.0 + 1e-3) + 1e-6, "t = {}: |d|Ω|/dt| {rate} > |Ω'| {}", t[i], dw[i]);
    }
}

#[test]
fn every_method_plots_in_every_view() {
    let methods = motion::method::Method::ALL.map(|m| m.name());
    // juttler-projective takes 5, 9, ... poses, not these three: plotted in interpolate_juttler.rs
    for method in methods.into_iter().filter(|m| *m != "juttler-projective") {
        let file = TempFile::new(&format!("plot-{method}.json"), &spec(method, false));
        for view in ["xy", "xz", "yz", "3d"] {
            let (data, svg) = plot(&format!("plot-{method}-{view}"), &[file.path(), "--view", view, "--frames", "3"]);
            let s = &data["series"][0];
            assert_eq!(s["method"], method);
            let segments = s["segments"].as_u64().unwrap() as usize;
            assert_eq!(s["joins"].as_array().unwrap().len(), segments - 1, "{method}");
            assert_eq!(check_svg(&svg), expected_series(&data), "{method} {view}");
            // Every method interpolates: the path passes through the key points, which are
            // the first and last samples.
            let paths = &s["paths"][1];
            let last = paths.as_array().unwrap().len() - 1;
            assert!(dist(&point(&paths[0]), &key_point(0, &POINTS[1])) < 1e-9, "{method}");
            assert!(dist(&point(&paths[last]), &key_point(2, &POINTS[1])) < 1e-9, "{method}");
        }
    }
}

#[test]
fn overlays_have_a_legend_and_every_series() {
    let a = TempFile::new("plot-over-a.json", &spec("ccm-additive", false));
    let b = TempFile::new("plot-over-b.json", &spec("juttler-spline", false));
    let (data, svg) = plot("plot-over", &[a.path(), b.path(), "--view", "xz", "--frames", "2"]);
    let series = data["series"].as_array().unwrap();
    assert_eq!(series.len(), 2);
    assert_eq!(check_svg(&svg), expected_series(&data));
    assert_eq!(data["title"], "2 motions: ccm-additive, juttler-spline");
    for label in ["plot-over-a.json: ccm-additive", "plot-over-b.json: juttler-spline"] {
        assert!(series.iter().any(|s| s["label"].as_str().unwrap().ends_with(label)), "{label}");
        assert!(svg.contains(label), "the legend lacks {label:?}");
    }
    assert!(svg.contains("x-z projection"));
}

#[test]
fn hermite_specs_plot_with_frames() {
    let file = TempFile::new("plot-hermite.json", common::CONTRACT_EXAMPLE);
    let (data, svg) = plot("plot-hermite", &[file.path(), "--samples", "11", "--frames", "3", "--view", "3d"]);
    let s = &data["series"][0];
    assert_eq!(s["method"], "additive");
    assert_eq!(nums(&s["key_times"]), [0.0, 1.0]);
    assert!(s["joins"].as_array().unwrap().is_empty());
    // The contract example starts at the origin and ends at [8, 10, 12].
    assert!(dist(&point(&s["key_points"][1][0]), &[8.0, 10.0, 12.0]) < 1e-12);
    assert_eq!(s["frames"].as_array().unwrap().iter().map(|f| num(&f["t"])).collect::<Vec<_>>(), [0.0, 0.5, 1.0]);
    assert_eq!(check_svg(&svg), expected_series(&data));
}

#[test]
fn bad_plot_arguments_are_one_error_line() {
    let file = TempFile::new("plot-bad-args.json", &spec("ccm-additive", false));
    let out = TempFile::empty("plot-bad-args.svg");
    let line = fails(&["plot", file.path(), "--out", out.path(), "--view", "xw"], 2);
    assert!(line.contains("xw"), "{line}");
    let line = fails(&["plot", file.path(), "--out", out.path(), "--frames", "1001"], 2);
    assert!(line.contains("--frames"), "{line}");
    fails(&["plot", "--out", out.path()], 2);
    let line = fails(&["plot", file.path(), "/nonexistent/spec.json", "--out", out.path()], 2);
    assert!(line.contains("/nonexistent/spec.json"), "{line}");
    let bad = TempFile::new("plot-bad-points.json", &spec("ccm-additive", false).replace("[0.5, -1.0, 2.0]", "[1, 2]"));
    fails(&["plot", bad.path(), "--out", out.path()], 2);
}

#[test]
fn the_svg_checker_rejects_malformed_svg() {
    assert_eq!(check_svg(r##"<svg><polyline stroke="#1F77B4"/><polyline stroke="#000000"/></svg>"##), 1);
    for bad in ["<svg><g></svg></g>", "<svg><g></svg>", "<svg/><svg/>", "<svg a=\"1></svg>", "<svg>&x;</svg>"] {
        let caught = std::panic::catch_unwind(|| check_svg(bad));
        assert!(caught.is_err(), "{bad:?} was accepted");
    }
}

/// `gam figures --out DIR --json` into a temporary directory: the data of each figure, after
/// checking its SVG well-formed with one series per line of the data and equal to the one
/// committed in the gallery (docs/figures/).
fn figures() -> Vec<(String, Value)> {
    let dir = std::env::temp_dir().join(format!("gam-cli-test-{}-figures", std::process::id()));
    std::fs::create_dir_all(&dir).expect("a temp directory");
    let data: Value = serde_json::from_str(&ok(&["figures", "--json", "--out", dir.to_str().unwrap()])).unwrap();
    let mut out = Vec::new();
    for (file, fig) in data.as_object().expect("an object") {
        if file.starts_with("juttler_") {
            continue; // drawn with cubes; checked by figures_juttler.rs
        }
        let svg = std::fs::read_to_string(dir.join(file)).expect("the figure was written");
        // A body drawn as a cube or the cuboid has 12 lines per frame, not 3.
        let frames: usize =
            fig["series"].as_array().unwrap().iter().map(|s| s["frames"].as_array().unwrap().len()).sum();
        let extra = if fig["body"] == "cuboid" || fig["body"] == "cube" { 9 * frames } else { 0 };
        assert_eq!(check_svg(&svg), expected_series(fig) + mark_lines(fig) + extra, "{file}");
        if fig["body"] == "cuboid" {
            // its top face filled: one light grey polygon per frame
            assert_eq!(svg.matches(r##"fill="#BEBEBE" opacity="0.6""##).count(), frames, "{file}");
        }
        let committed = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../docs/figures").join(file);
        let committed = std::fs::read_to_string(&committed).expect("the gallery has the figure");
        assert!(committed == svg, "docs/figures/{file} is stale: run `gam figures --out docs/figures`");
        out.push((file.clone(), fig.clone()));
    }
    let _ = std::fs::remove_dir_all(&dir);
    out
}

/// The series of figure `file`.
fn figure(all: &[(String, Value)], file: &str) -> Vec<Value> {
    let fig = all.iter().find(|(f, _)| f == file).unwrap_or_else(|| panic!("no {file}"));
    fig.1["series"].as_array().unwrap().clone()
}

#[test]
#[allow(clippy::approx_constant)] // the paper's printed values
fn paper_figures_3_to_5() {
    let all = figures();
    let files: Vec<&str> = all.iter().map(|(f, _)| f.as_str()).collect();
    assert!(["fig3.svg", "fig4.svg", "fig5.svg"].iter().all(|f| files.contains(f)), "{files:?}");
    // Fig. 3: the speeds jump at the join t = 1 (samples every 0.005). Just before it, the
    // printed Ψ at the end of the arc: |v| = 5.6569, |Ω| = 1.4142 (Sec. 4); on the line, the
    // printed V_i translate by 2 (2 + 1.0472 3t): |v| = 6.2832 exactly, |Ω| = 0.
    let f3 = &figure(&all, "fig3.svg")[0];
    assert_eq!(nums(&f3["joins"]), [1.0]);
    // "The poses of a cuboidal block during the motion are shown": 9 of them, the body point
    // (the block's centre) on the path at t = 0, 0.25, ..., 2.
    let frames = f3["frames"].as_array().unwrap();
    assert_eq!(frames.len(), 9);
    for (k, f) in frames.iter().enumerate() {
        let i = 50 * k; // samples every 0.005
        assert!((num(&f["t"]) - 0.25 * k as f64).abs() < 1e-12);
        assert!(dist(&point(&f["origin"]), &point(&f3["paths"][0][i])) < 1e-9, "frame {k}");
    }
    let (v, w) = (nums(&f3["speeds"][0]), nums(&f3["angular_speed"]));
    assert!((v[199] - 5.6569).abs() < 0.03 && (w[199] - 1.4142).abs() < 0.01, "{} {}", v[199], w[199]);
    for i in 201..v.len() {
        assert!((v[i] - 6.2832).abs() < 1e-9 && w[i] == 0.0, "t = {}: {} {}", 0.005 * i as f64, v[i], w[i]);
    }
    // Fig. 4: real γ keeps the motion planar; γ = 0 makes the speed continuous at the join.
    let f4 = figure(&all, "fig4.svg");
    assert_eq!(f4.len(), 5);
    for s in &f4 {
        assert!(s["paths"][0].as_array().unwrap().iter().all(|p| point(p)[2].abs() < 1e-12), "{}", s["label"]);
    }
    let v0 = nums(&f4[0]["speeds"][0]);
    assert!((v0[199] - v0[201]).abs() < 0.05, "{} vs {}", v0[199], v0[201]);
    // Fig. 5: γ = ±20ω, ±40ω take the path out of the plane, symmetrically; seen along z it
    // is the γ = 0 path, the angular speed is that of γ = 0, the linear speed is larger.
    let f5 = figure(&all, "fig5.svg");
    let path = |s: &Value| s["paths"][0].as_array().unwrap().iter().map(point).collect::<Vec<_>>();
    let base = path(&f5[0]);
    assert!(base.iter().all(|p| p[2] == 0.0));
    for s in &f5[1..] {
        let p = path(s);
        let lift = p.iter().map(|q| q[2].abs()).fold(0.0, f64::max);
        assert!(lift > 0.25, "{}: {lift}", s["label"]);
        assert!(p.iter().zip(&base).all(|(a, b)| (a[0] - b[0]).abs() < 1e-12 && (a[1] - b[1]).abs() < 1e-12));
        assert_eq!(nums(&s["angular_speed"]), nums(&f5[0]["angular_speed"]));
        let (v, v0) = (nums(&s["speeds"][0]), nums(&f5[0]["speeds"][0]));
        assert!(v.iter().zip(&v0).all(|(a, b)| a >= &(b - 1e-12)) && v.iter().zip(&v0).any(|(a, b)| a > &(b + 0.1)));
    }
    let (plus, minus) = (path(&f5[1]), path(&f5[2]));
    assert!(plus.iter().zip(&minus).all(|(a, b)| (a[2] + b[2]).abs() < 1e-12), "±20ω mirror each other");
    // Its companion: the same speeds as increases over γ = 0 in per cent (recomputed here
    // from Fig. 5's data); the mirrored motions have equal speeds; at most about 2.9% for
    // ±20ω and 11% for ±40ω, just after the join; the angular speeds do not change.
    let inc = figure(&all, "fig5_increase.svg");
    assert_eq!(inc.len(), 5);
    for (s, c) in f5.iter().zip(&inc) {
        let (v, v0, got) = (nums(&s["speeds"][0]), nums(&f5[0]["speeds"][0]), nums(&c["speeds"][0]));
        for i in 0..v.len() {
            assert!((got[i] - 100.0 * (v[i] - v0[i]) / v0[i]).abs() < 1e-9, "{} at {i}", s["label"]);
        }
        assert!(nums(&c["angular_speed"]).iter().all(|w| *w == 0.0));
    }
    let peak = |s: &Value| nums(&s["speeds"][0]).into_iter().fold(f64::MIN, f64::max);
    assert_eq!(peak(&inc[1]), peak(&inc[2]));
    assert!(
        (2.5..3.2).contains(&peak(&inc[1])) && (10.5..11.5).contains(&peak(&inc[3])),
        "{} {}",
        peak(&inc[1]),
        peak(&inc[3])
    );
}

#[test]
fn figures_into_a_missing_directory_is_exit_2() {
    let line = fails(&["figures", "--out", "/nonexistent-dir/gam-figures"], 2);
    assert!(line.contains("cannot write `/nonexistent-dir/gam-figures/fig3.svg`"), "{line}");
    fails(&["figures"], 2);
}

#[test]
fn the_unit_cube_at_the_frames() {
    // Frames at t = 0, 1.5, 3 of the spec with parameters 0, 1, 3: at t = 3 the last key pose
    // carries the corner (i, j, k) of [0, 1]³ (index i + 2j + 4k) to R (i, j, k) + p.
    let file = TempFile::new("plot-cube.json", &spec("juttler-spline", true));
    let (data, svg) = plot("plot-cube", &[file.path(), "--frames", "3", "--body", "cube", "--view", "3d"]);
    let s = &data["series"][0];
    let last = &s["frames"][2];
    assert_eq!(num(&last["t"]), 3.0);
    for c in 0..8 {
        let corner = [(c & 1) as f64, ((c >> 1) & 1) as f64, ((c >> 2) & 1) as f64];
        let (got, want) = (point(&last["cube"][c]), key_point(2, &corner));
        assert!(dist(&got, &want) < 1e-12, "corner {c}: {got:?} vs {want:?}");
    }
    // 12 edges per frame instead of 3 axes.
    assert_eq!(check_svg(&svg), expected_series(&data) + 9 * 3);
}

/// `gam interpolate --json` of `method` with [`POINTS`] added: the control-data form.
fn control_form(method: &str) -> String {
    let s = TempFile::new(&format!("ctl-{method}.json"), &spec(method, true));
    let mut out: Value = serde_json::from_str(&ok(&["interpolate", "--json", s.path()])).unwrap();
    out["body_points"] = serde_json::json!(POINTS);
    out.to_string()
}

/// Explicit control poses (the segments `gam interpolate --json` prints) draw the same motion
/// as the spec they came from, and pass through the key poses (Rodrigues, independent).
#[test]
fn control_poses_plot_the_same_motion_as_their_spec() {
    for method in ["ccm-additive", "ccm-multiplicative", "juttler-q-motion", "juttler-spline"] {
        let from_spec = TempFile::new(&format!("cs-{method}.json"), &spec(method, true));
        let from_control = TempFile::new(&format!("cc-{method}.json"), &control_form(method));
        let (a, _) = plot(&format!("cs-{method}"), &[from_spec.path(), "--samples", "301"]);
        let (b, svg) = plot(&format!("cc-{method}"), &[from_control.path(), "--samples", "301", "--frames", "3"]);
        let (a, b) = (&a["series"][0], &b["series"][0]);
        assert_eq!(nums(&a["t"]), nums(&b["t"]), "{method}");
        for (pa, pb) in a["paths"].as_array().unwrap().iter().zip(b["paths"].as_array().unwrap()) {
            for (x, y) in pa.as_array().unwrap().iter().zip(pb.as_array().unwrap()) {
                assert!(dist(&point(x), &point(y)) < 1e-9, "{method}: {x} vs {y}");
            }
        }
        for (k, t) in [0.0, 1.0, 3.0].iter().enumerate() {
            let i = nums(&b["t"]).iter().position(|s| (s - t).abs() < 1e-9).expect("a sample at the key");
            for (j, x) in POINTS.iter().enumerate() {
                let p = point(&b["paths"][j][i]);
                assert!(dist(&p, &key_point(k, x)) < 1e-9, "{method}: key {k}, point {j}: {p:?}");
            }
        }
        assert_eq!(nums(&b["joins"]), nums(&a["joins"]), "{method}");
        assert_eq!(check_svg(&svg), expected_series(&serde_json::json!({"series": [b]})), "{method}");
    }
}

#[test]
fn control_data_errors_are_one_line() {
    // key-pose segments (W-L) cannot be redrawn from their control data
    let wl = TempFile::new("ctl-wl.json", &control_form("wl-linear"));
    let out = TempFile::empty("ctl-wl.svg");
    let msg = fails(&["plot", "--out", out.path(), wl.path()], 2);
    assert!(msg.contains("cannot be drawn from control data"), "{msg}");
    // mixed representations, and a gap between segments
    let motor = r#"{"1": 1}"#;
    let seg = |t0: f64, t1: f64, r: &str| {
        format!(r#"{{"t0": {t0}, "t1": {t1}, "representation": "{r}", "control_poses": [{motor}, {motor}]}}"#)
    };
    let mixed = format!(
        r#"{{"segments": [{}, {}]}}"#,
        seg(0.0, 1.0, "additive-bezier"),
        seg(1.0, 2.0, "multiplicative-bezier")
    );
    let mixed = TempFile::new("ctl-mixed.json", &mixed);
    assert!(fails(&["plot", "--out", out.path(), mixed.path()], 2).contains("one kind per plot"));
    let gap =
        format!(r#"{{"segments": [{}, {}]}}"#, seg(0.0, 1.0, "additive-bezier"), seg(1.5, 2.0, "additive-bezier"));
    let gap = TempFile::new("ctl-gap.json", &gap);
    assert!(fails(&["plot", "--out", out.path(), gap.path()], 2).contains("no gaps"));
    let singular =
        r#"{"segments": [{"t0": 0, "t1": 1, "representation": "additive-bezier", "control_poses": [{"e1inf": 1}]}]}"#;
    let singular = TempFile::new("ctl-singular.json", singular);
    assert!(fails(&["plot", "--out", out.path(), singular.path()], 2).contains("singular"));
}

/// Explicit multiplicative control data of high degree plot as they sample (the second-order
/// dual numbers of the plot's accelerations failed from degree about 150: "ln: the
/// pseudoscalar 0", "inverse: ... singular").
#[test]
fn high_degree_multiplicative_control_data_plot() {
    let n = 200;
    let motor = |k: usize| {
        let (half, x) = (0.45 * (k as f64 * 0.7).sin(), k as f64 / n as f64);
        format!(r#"{{"1": {}, "e12": {}, "e1inf": {}, "e2inf": 0.1}}"#, half.cos(), half.sin(), x)
    };
    let poses: Vec<String> = (0..=n).map(motor).collect();
    let data = format!(
        r#"{{"segments": [{{"t0": 0, "t1": 1, "representation": "multiplicative-bezier", "control_poses": [{}]}}], "body_points": [[1, 0, 0]]}}"#,
        poses.join(", ")
    );
    let file = TempFile::new("plot-deg200.json", &data);
    let (v, svg) = plot("plot-deg200", &[file.path(), "--samples", "5"]);
    let s = &v["series"][0];
    assert_eq!(s["degree"].as_u64(), Some(n as u64));
    let speeds = nums(&s["speeds"][0]);
    assert!(speeds.len() == 5 && speeds.iter().all(|x| x.is_finite() && *x > 0.0), "{speeds:?}");
    assert_eq!(check_svg(&svg), expected_series(&v));
}
