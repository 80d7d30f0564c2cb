//! `gam plot` on `gam interpolate` specs: the data behind the figure (`--json`) checked
//! numerically against independent references (key poses by Rodrigues' formula, speeds by
//! central differences of the path), every SVG checked well-formed with the expected number
//! of series, every method of `gam interpolate` plotted in every view, overlays, and the
//! error rules.

mod common;

use common::{TempFile, fails, ok};
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
    let n = (a[0] * a[0] + a[1] * a[1] + a[2] * a[2]).sqrt();
    let u = a.map(|c| c / n);
    let (c, s) = (phi.cos(), phi.sin());
    let dot = u[0] * x[0] + u[1] * x[1] + u[2] * x[2];
    let cross = [u[1] * x[2] - u[2] * x[1], u[2] * x[0] - u[0] * x[2], u[0] * x[1] - u[1] * x[0]];
    std::array::from_fn(|i| x[i] * c + cross[i] * s + u[i] * dot * (1.0 - c) + p[i])
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
fn every_method_plots_in_every_view() {
    let methods = [
        "ccm-additive",
        "ccm-multiplicative",
        "wl-linear",
        "wl-quadratic",
        "hexanion-linear",
        "juttler-q-motion",
        "juttler-trt",
        "juttler-minimal",
        "juttler-spline",
    ];
    for method in methods {
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
