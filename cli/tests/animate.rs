//! `gam plot --animate`: an animated SVG (SMIL) or an HTML page with the body moving along its
//! path and a cursor on the speed panel.
//!
//! The structure is checked on the text: 120 frame layers, each with its cursor at the frame's
//! parameter (from `--json`'s range, mapped by the speed panel's tick labels) and the body point's
//! dot where the path is at that parameter; nothing loaded from outside the file. The page is
//! also loaded in headless Chromium (`played_in_chromium`, ignored by default; `.ci/run`
//! installs Debian's `chromium` and runs it): two frames differ where the body moved and on
//! the speed panel, and agree on the title.

use crate::common;

use common::{TempFile, fails, ok};

const SPEC: &str = r#"{"method": "ccm-additive",
  "poses": [{"position": [0, 0, 0], "axis": [0, 0, 1], "angle": 0},
            {"position": [2, 1, 0], "axis": [0, 0, 1], "angle": 1},
            {"position": [4, 0, 0], "axis": [0, 0, 1], "angle": 2}]}"#;

/// The numbers of attribute `name` in `tag`.
fn attr(tag: &str, name: &str) -> f64 {
    let key = format!(" {name}=\"");
    let at = tag.find(&key).unwrap_or_else(|| panic!("no {name} in {tag}")) + key.len();
    tag[at..at + tag[at..].find('"').unwrap()].parse().expect("a number")
}

/// The layers (`<g class="gam-frame">` bodies) of an animated file.
fn layers(text: &str) -> Vec<&str> {
    text.split("<g class=\"gam-frame\"").skip(1).map(|g| &g[..g.find("</g>").expect("closed")]).collect()
}

/// The x pixel of tick label `value` on the speed panel's t axis, from the static figure.
fn t_ticks(svg: &str) -> Vec<(f64, f64)> {
    svg.lines()
        .filter(|l| l.starts_with("<text") && l.contains(r#"dy="0.76em" text-anchor="middle""#) && attr(l, "x") < 600.0)
        .filter_map(|l| {
            let text = &l[l.find('>').unwrap() + 1..l.rfind("</text>").unwrap()];
            text.parse::<f64>().ok().map(|v| (v, attr(l, "x")))
        })
        .collect()
}

#[test]
fn an_animated_svg_has_a_layer_per_frame_in_order() {
    let spec = TempFile::new("animate-spec.json", SPEC);
    let out = TempFile::empty("animate.svg");
    let json = ok(&["plot", spec.path(), "--out", out.path(), "--animate", "--json"]);
    let data: serde_json::Value = serde_json::from_str(&json).expect("JSON");
    let svg = std::fs::read_to_string(out.path()).expect("written");
    let frames = layers(&svg);
    assert_eq!(frames.len(), 120);
    // Each layer is shown during its share of a 6 s loop.
    for (k, g) in frames.iter().enumerate() {
        assert!(g.contains(r#"attributeName="visibility""#) && g.contains(r#"dur="6s""#), "frame {k}");
        let (a, b) = (k as f64 / 120.0, (k + 1) as f64 / 120.0);
        let times = if k == 0 { format!(r#"keyTimes="0;{b}""#) } else { format!(r#"keyTimes="0;{a};{b}""#) };
        assert!(g.contains(&times), "frame {k}: {times}");
    }
    // The cursor (the black vertical line) of frame k is at t = k/119 of [0, 2], read off the
    // speed panel's axis through its tick labels.
    let ticks = t_ticks(&svg);
    let (first, last) = (ticks.first().expect("ticks"), ticks.last().expect("ticks"));
    let to_t = |x: f64| first.0 + (x - first.1) * (last.0 - first.0) / (last.1 - first.1);
    let t = data["series"][0]["t"].as_array().expect("t");
    let (t0, t1) = (t[0].as_f64().unwrap(), t[t.len() - 1].as_f64().unwrap());
    for (k, g) in frames.iter().enumerate() {
        let cursor = g.lines().find(|l| l.starts_with("<polyline") && l.contains(r##"stroke="#000000""##));
        let cursor = cursor.unwrap_or_else(|| panic!("frame {k}: no cursor"));
        let pts = &cursor[cursor.find("points=\"").unwrap() + 8..];
        let x: f64 = pts.split(',').next().unwrap().parse().unwrap();
        let want = t0 + (t1 - t0) * k as f64 / 119.0;
        assert!((to_t(x) - want).abs() < 0.01, "frame {k}: cursor at t = {}, want {want}", to_t(x));
    }
    // The body point's dot moves: its centre in the first and the last frame is where the
    // path starts and ends (the path's first and last vertices in the static figure).
    let dot = |g: &str| {
        let c = g.lines().find(|l| l.starts_with("<circle")).expect("a dot");
        (attr(c, "cx"), attr(c, "cy"))
    };
    let points = |l: &str| -> Vec<(f64, f64)> {
        let p = l.split("points=\"").nth(1).expect("points");
        p[..p.find('"').unwrap()]
            .split_whitespace()
            .map(|xy| {
                let (x, y) = xy.split_once(',').unwrap();
                (x.parse().unwrap(), y.parse().unwrap())
            })
            .collect()
    };
    let path = svg
        .lines()
        .filter(|l| l.starts_with("<polyline") && l.contains(r##"stroke="#0088FF" stroke-width="2""##))
        .map(points)
        .find(|p| p[0].0 > 600.0)
        .expect("the path in the right panel");
    let (a, b) = (path[0], path[path.len() - 1]);
    let (d0, d1) = (dot(frames[0]), dot(frames[119]));
    assert!((d0.0 - a.0).abs() < 1.0 && (d0.1 - a.1).abs() < 1.0, "first dot {d0:?}, path starts at {a:?}");
    assert!((d1.0 - b.0).abs() < 1.0 && (d1.1 - b.1).abs() < 1.0, "last dot {d1:?}, path ends at {b:?}");
    assert_ne!(dot(frames[0]), dot(frames[60]));
}

#[test]
fn an_animated_page_is_self_contained() {
    let spec = TempFile::new("animate-page.json", SPEC);
    let out = TempFile::empty("animate.html");
    ok(&["plot", spec.path(), "--out", out.path(), "--animate", "--view", "3d", "--body", "cube"]);
    let html = std::fs::read_to_string(out.path()).expect("written");
    assert!(html.starts_with("<!DOCTYPE html>"));
    assert_eq!(layers(&html).len(), 120);
    assert!(html.contains("<script>") && html.contains("gam-slider") && html.contains("gam-play"));
    let page = html.replace(r#"xmlns="http://www.w3.org/2000/svg""#, "");
    for external in ["src=", "href=", "http:", "https:", "@import", "url("] {
        assert!(!page.contains(external), "the page loads something from outside: {external}");
    }
    // Each layer draws the cube's 12 edges.
    for g in layers(&html) {
        assert_eq!(g.matches(r##"stroke="#5A5A5A""##).count(), 12);
    }
}

#[test]
fn animate_refuses_png() {
    let spec = TempFile::new("animate-png.json", SPEC);
    let line = fails(&["plot", spec.path(), "--out", "x.png", "--animate"], 2);
    assert!(line.contains("--animate") && line.contains("PNG"), "{line}");
}

/// A screenshot of `url` by headless Chromium, decoded: (width, height, RGB).
fn screenshot(url: &str, name: &str) -> (usize, usize, Vec<u8>) {
    let shot = TempFile::empty(name);
    let status = std::process::Command::new("chromium")
        .args(["--headless", "--no-sandbox", "--disable-gpu", "--hide-scrollbars", "--window-size=1200,700"])
        .arg(format!("--screenshot={}", shot.path()))
        .arg(url)
        .output()
        .expect("chromium runs (apt-get install chromium; .ci/run installs it)");
    assert!(status.status.success(), "chromium: {}", String::from_utf8_lossy(&status.stderr));
    let bytes = std::fs::read(shot.path()).expect("a screenshot");
    let decoder = png::Decoder::new(std::io::Cursor::new(bytes));
    let mut reader = decoder.read_info().expect("a PNG");
    let mut buf = vec![0; reader.output_buffer_size().expect("a size")];
    let info = reader.next_frame(&mut buf).expect("a frame");
    let channels = info.color_type.samples();
    let rgb = buf[..info.buffer_size()].chunks(channels).flat_map(|p| [p[0], p[1], p[2]]).collect();
    (info.width as usize, info.height as usize, rgb)
}

#[test]
#[ignore = "needs Debian's chromium; .ci/run installs it and runs this test"]
fn played_in_chromium() {
    let spec = TempFile::new("animate-chromium.json", SPEC);
    let out = TempFile::empty("animate-chromium.html");
    ok(&["plot", spec.path(), "--out", out.path(), "--animate", "--frames", "0"]);
    let url = |k: usize| format!("file://{}#frame={k}", out.path());
    let (w, h, a) = screenshot(&url(10), "animate-10.png");
    let (w2, h2, b) = screenshot(&url(100), "animate-100.png");
    assert_eq!((w, h), (w2, h2));
    let differ = |xs: std::ops::Range<usize>, ys: std::ops::Range<usize>| {
        ys.flat_map(|y| xs.clone().map(move |x| (x, y)))
            .filter(|(x, y)| a[3 * (y * w + x)..][..3] != b[3 * (y * w + x)..][..3])
            .count()
    };
    // The path panel: the body (its frame and dot) moved; the speed panel: the cursor moved.
    assert!(differ(600..w, 40..540) > 100, "the body did not move");
    assert!(differ(0..600, 40..540) > 100, "the cursor did not move");
    // The title band is the same in both.
    assert_eq!(differ(0..w, 0..24), 0, "the static figure changed");
}
