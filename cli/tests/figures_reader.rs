//! The figures looked at as a reader would (issue 25): for every figure of `gam figures` and
//! for `gam plot` overlays of twelve specs, parsed from the SVG text alone:
//! - the legend box (the one `<rect>` filled `#FAFAFA`) contains no vertex of any line and no
//!   dot (a legend never hides data);
//! - no two texts overlap (their boxes estimated as plotters lays text out: 0.7 em per
//!   character, `em = font-size / 1.24`, one `font-size` high, placed by `text-anchor`, `dy`
//!   and `transform`);
//! - a path panel in a coordinate plane has equal scales on both axes, measured from its tick
//!   labels' values and pixel positions;
//! - in an overlay of twelve specs the speed lines have twelve different colours, none a body
//!   frame's colour.
//!
//! Equal scales in the 3-D view are checked where the box is built (`plot::axes3d`'s tests).

use crate::common;

use common::{TempFile, ok};
use std::collections::BTreeMap;

/// One SVG element: its name, its attributes and its text.
#[derive(Debug)]
struct Element {
    name: String,
    attrs: BTreeMap<String, String>,
    text: String,
}

impl Element {
    fn num(&self, key: &str) -> f64 {
        self.attrs.get(key).unwrap_or_else(|| panic!("<{}> without {key}", self.name)).parse().expect("a number")
    }

    fn points(&self) -> Vec<(f64, f64)> {
        let p = &self.attrs["points"];
        p.split_whitespace()
            .map(|xy| {
                let (x, y) = xy.split_once(',').expect("x,y");
                (x.parse().expect("x"), y.parse().expect("y"))
            })
            .collect()
    }
}

/// The elements of `svg` (as our SVG writer writes them: one element per line, attributes
/// in double quotes, texts without markup inside).
fn elements(svg: &str) -> Vec<Element> {
    let mut out = Vec::new();
    let mut rest = svg;
    while let Some(open) = rest.find('<') {
        let close = rest[open..].find('>').expect("a closed tag") + open;
        let tag = &rest[open + 1..close];
        rest = &rest[close + 1..];
        if tag.starts_with('/') || tag.starts_with('?') || tag.starts_with('!') {
            continue;
        }
        let name = tag.split_whitespace().next().expect("a name").trim_end_matches('/').to_string();
        let mut attrs = BTreeMap::new();
        let mut a = tag[name.len()..].trim_end_matches('/');
        while let Some(eq) = a.find("=\"") {
            let key = a[..eq].trim().to_string();
            let end = a[eq + 2..].find('"').expect("a closing quote") + eq + 2;
            attrs.insert(key, a[eq + 2..end].replace("&amp;", "&").replace("&lt;", "<").replace("&gt;", ">"));
            a = &a[end + 1..];
        }
        let text = if name == "text" { rest[..rest.find('<').unwrap_or(0)].to_string() } else { String::new() };
        out.push(Element { name, attrs, text });
    }
    out
}

/// A box `(x0, y0, x1, y1)` in pixels.
type Box2 = (f64, f64, f64, f64);

/// The box of a `<text>`.
fn text_box(t: &Element) -> Box2 {
    let (x, y, size) = (t.num("x"), t.num("y"), t.num("font-size"));
    let n = t.text.chars().count() as f64;
    let (w, h) = (0.7 * size / 1.24 * n, size);
    let (a0, a1) = match t.attrs["text-anchor"].as_str() {
        "start" => (0.0, w),
        "middle" => (-w / 2.0, w / 2.0),
        _ => (-w, 0.0),
    };
    let (b0, b1) = match t.attrs["dy"].as_str() {
        "0.76em" => (0.0, h),
        "0.5ex" => (-h / 2.0, h / 2.0),
        _ => (-h, 0.0),
    };
    match t.attrs.get("transform").map(|s| s.split(',').next().unwrap_or("")) {
        Some("rotate(270") => (x + b0, y - a1, x + b1, y - a0),
        Some("rotate(90") => (x - b1, y + a0, x - b0, y + a1),
        _ => (x + a0, y + b0, x + a1, y + b1),
    }
}

fn overlap(a: &Box2, b: &Box2) -> f64 {
    let w = a.2.min(b.2) - a.0.max(b.0);
    let h = a.3.min(b.3) - a.1.max(b.1);
    if w > 0.0 && h > 0.0 { w.min(h) } else { 0.0 }
}

/// The reader's checks on one figure; `legend` says whether it must have a legend box.
fn read(file: &str, svg: &str, legend: bool) {
    let all = elements(svg);
    let boxes: Vec<&Element> =
        all.iter().filter(|e| e.name == "rect" && e.attrs.get("fill").map(String::as_str) == Some("#FAFAFA")).collect();
    assert_eq!(boxes.len(), usize::from(legend), "{file}: legend boxes");
    for b in boxes {
        let (x0, y0) = (b.num("x"), b.num("y"));
        let (x1, y1) = (x0 + b.num("width"), y0 + b.num("height"));
        let inside = |(x, y): (f64, f64)| x > x0 && x < x1 && y > y0 && y < y1;
        for e in &all {
            match e.name.as_str() {
                "polyline" | "polygon" => {
                    let hidden = e.points().into_iter().find(|p| inside(*p));
                    assert!(hidden.is_none(), "{file}: the legend covers {hidden:?} of a {}", e.name);
                }
                "circle" => assert!(!inside((e.num("cx"), e.num("cy"))), "{file}: the legend covers a dot"),
                _ => {}
            }
        }
    }
    let texts: Vec<(&Element, Box2)> = all.iter().filter(|e| e.name == "text").map(|t| (t, text_box(t))).collect();
    for (i, (a, ba)) in texts.iter().enumerate() {
        for (b, bb) in &texts[..i] {
            let o = overlap(ba, bb);
            assert!(o <= 0.5, "{file}: {:?} and {:?} overlap by {o:.2} px ({ba:?}, {bb:?})", a.text, b.text);
        }
    }
    let projected = texts.iter().any(|(t, _)| t.text.contains("projection, equal scales"));
    if projected {
        equal_scales(file, &texts);
    }
}

/// The path panel's (right half's) pixels per unit along x and y from its tick labels are equal.
fn equal_scales(file: &str, texts: &[(&Element, Box2)]) {
    let ticks = |anchor: &str, dy: &str| -> Vec<(f64, f64, f64)> {
        let mut v: Vec<_> = texts
            .iter()
            .filter(|(t, _)| t.attrs["text-anchor"] == anchor && t.attrs["dy"] == dy && t.num("x") > 600.0)
            .filter_map(|(t, _)| t.text.trim().parse::<f64>().ok().map(|v| (v, t.num("x"), t.num("y"))))
            .collect();
        v.sort_by(|a, b| a.0.total_cmp(&b.0));
        v
    };
    let (xs, ys) = (ticks("middle", "0.76em"), ticks("end", "0.5ex"));
    assert!(xs.len() >= 3 && ys.len() >= 3, "{file}: tick labels {xs:?} {ys:?}");
    let per_unit = |a: &(f64, f64, f64), b: &(f64, f64, f64), k: usize| {
        let d = if k == 1 { b.1 - a.1 } else { a.2 - b.2 };
        d / (b.0 - a.0)
    };
    let sx = per_unit(&xs[0], &xs[xs.len() - 1], 1);
    let sy = per_unit(&ys[0], &ys[ys.len() - 1], 2);
    assert!(sx > 0.0 && (sx / sy - 1.0).abs() < 0.01, "{file}: {sx} px per unit along x, {sy} along y");
}

#[test]
fn every_figure_reads_cleanly() {
    let dir = std::env::temp_dir().join(format!("gam-cli-test-{}-reader", std::process::id()));
    std::fs::create_dir_all(&dir).expect("a temp dir");
    let lines = ok(&["figures", "--out", dir.to_str().expect("utf-8")]);
    let mut count = 0;
    let docs = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../docs/cli.md")).expect("docs/cli.md");
    for line in lines.lines() {
        let path = line.split(": ").next().unwrap().trim_start_matches("wrote ");
        let file = std::path::Path::new(path).file_name().unwrap().to_str().unwrap();
        assert!(docs.contains(&format!("`{file}`")), "docs/cli.md does not list {file}");
        let svg = std::fs::read_to_string(path).expect("written");
        read(path, &svg, !path.ends_with("juttler_fig5b.svg"));
        count += 1;
    }
    assert_eq!(count, 21);
    let _ = std::fs::remove_dir_all(&dir);
}

/// Twelve specs: the same three key poses, the last one moved along x by `k`, by
/// ccm-additive, ccm-multiplicative and wl-linear in turn.
fn twelve_specs() -> Vec<TempFile> {
    let methods = ["ccm-additive", "ccm-multiplicative", "wl-linear"];
    (0..12)
        .map(|k| {
            let spec = format!(
                r#"{{"method": "{}", "poses": [{{"position": [0, 0, 0], "axis": [0, 0, 1], "angle": 0}},
                {{"position": [1, 1, 0], "axis": [0, 0, 1], "angle": 1}},
                {{"position": [{}, 0, 1], "axis": [1, 0, 0], "angle": 0.5}}]}}"#,
                methods[k % 3],
                2.0 + 0.25 * k as f64
            );
            TempFile::new(&format!("reader-{k}.json"), &spec)
        })
        .collect()
}

#[test]
fn twelve_overlaid_specs_read_cleanly_in_distinct_colours() {
    let specs = twelve_specs();
    for view in ["xy", "xz", "3d"] {
        let out = TempFile::empty(&format!("reader-overlay-{view}.svg"));
        let mut args = vec!["plot", "--out", out.path(), "--view", view, "--frames", "2", "--samples", "61"];
        args.extend(specs.iter().map(|s| s.path()));
        ok(&args);
        let svg = std::fs::read_to_string(out.path()).expect("written");
        read(&format!("overlay {view}"), &svg, true);
        // The speed lines: thick polylines in the left half.
        let all = elements(&svg);
        let mut colours: Vec<&str> = all
            .iter()
            .filter(|e| e.name == "polyline" && e.attrs["stroke-width"] == "2")
            .filter(|e| e.points().iter().all(|p| p.0 < 600.0))
            .map(|e| e.attrs["stroke"].as_str())
            .collect();
        colours.sort();
        colours.dedup();
        assert_eq!(colours.len(), 12, "{view}: {colours:?}");
        let rgb = |c: &str| -> [f64; 3] {
            std::array::from_fn(|i| f64::from(u8::from_str_radix(&c[1 + 2 * i..3 + 2 * i], 16).expect("hex")))
        };
        let far = |a: &str, b: &str| {
            let (a, b) = (rgb(a), rgb(b));
            (0..3).map(|i| (a[i] - b[i]).powi(2)).sum::<f64>().sqrt()
        };
        for (i, a) in colours.iter().enumerate() {
            for b in colours[..i].iter().chain(&["#DC0000", "#009600", "#0000DC"]) {
                // a coarse RGB check; the perceptual one (CIELAB, 40 apart) is the palette's unit test
                assert!(far(a, b) > 40.0, "{view}: {a} and {b} look alike");
            }
        }
    }
}
