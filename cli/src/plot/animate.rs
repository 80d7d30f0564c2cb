//! `gam plot --animate`: the figure with the moving body. The static figure is drawn as
//! always; then, for each of [`FRAMES`] parameters evenly spaced over every spec's range, the
//! body (as `--body` draws it), a dot on every body point and a cursor on the speed panel are
//! drawn into a layer of their own ([`super::svg::Layers`]), through the same charts, so they
//! sit exactly on the figure. The file is self-contained (no network, no external script):
//!
//! - `--out FILE.svg`: an animated SVG. Each layer is a `<g>` hidden but during its share of
//!   the loop (a SMIL `<animate>` of `visibility`, discrete, [`SECONDS`] per loop); it plays in
//!   a browser, also as an `<img>`.
//! - `--out FILE.html`: an HTML page with the SVG inline, a play/pause button and a slider,
//!   and a short inline script that shows one layer at a time. `FILE.html#frame=K` opens it
//!   paused at frame `K` (how the tests take two frames in headless Chromium).

use super::data::Series;
use super::draw::{Animation, Body, Figure, View};
use super::raster::{Picture, paint};
use super::style::{Px, SVG_SCALE};
use super::svg::{Layers, Svg};
use crate::error::CliError;
use std::cell::RefCell;
use std::fmt::Write as _;
use std::rc::Rc;

/// The frames of an animation.
pub const FRAMES: usize = 120;

/// The length of one loop in seconds.
pub const SECONDS: f64 = 6.0;

/// How an animation is written.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Kind {
    /// An SVG animated by SMIL.
    Svg,
    /// An HTML page with the SVG inline and controls.
    Html,
}

impl Kind {
    /// The kind for `path`: HTML for a name ending in `.html` or `.htm` (any case), SVG otherwise.
    pub fn of(path: &str) -> Kind {
        let lower = path.to_ascii_lowercase();
        if lower.ends_with(".html") || lower.ends_with(".htm") { Kind::Html } else { Kind::Svg }
    }
}

/// The static SVG of the figure and the elements of each frame's layer.
fn layers(figure: (&[Series], View, Body, &str), frames: &[Series]) -> Result<(String, Vec<String>), CliError> {
    let (all, view, body, title) = figure;
    let shared = Rc::new(RefCell::new(Layers::default()));
    let animation = Animation { series: frames, frames: FRAMES, layers: shared.clone() };
    let picture = Figure { all, view, body, title, animation: Some(animation), panel: super::draw::Panel::Speeds };
    let (w, h) = picture.size();
    let mut svg = String::new();
    paint(&picture, Svg::new(&mut svg, (w, h), Some(shared.clone())), Px(SVG_SCALE))?;
    drop(picture);
    let layers = std::mem::take(&mut shared.borrow_mut().frames);
    Ok((svg, layers))
}

/// The SVG `svg` with `groups` inserted before its closing tag.
fn with_groups(svg: &str, groups: &str) -> String {
    let end = svg.rfind("</svg>").unwrap_or(svg.len());
    format!("{}{groups}{}", &svg[..end], &svg[end..])
}

/// The animated SVG: layer `k` visible during `[k, k + 1) / n` of each loop.
fn smil(svg: &str, frames: &[String]) -> String {
    let n = frames.len() as f64;
    let mut groups = String::new();
    for (k, elements) in frames.iter().enumerate() {
        let (a, b) = (k as f64 / n, (k + 1) as f64 / n);
        let (values, times) = if k == 0 {
            ("visible;hidden".to_string(), format!("0;{b}"))
        } else {
            ("hidden;visible;hidden".to_string(), format!("0;{a};{b}"))
        };
        let _ = write!(
            groups,
            "<g class=\"gam-frame\" visibility=\"hidden\">\n<animate attributeName=\"visibility\" values=\"{values}\" keyTimes=\"{times}\" dur=\"{SECONDS}s\" calcMode=\"discrete\" repeatCount=\"indefinite\"/>\n{elements}</g>\n"
        );
    }
    with_groups(svg, &groups)
}

/// The script of the HTML page: one layer visible at a time, advanced by a timer; the
/// slider shows and sets the frame; `#frame=K` starts paused at `K`.
const SCRIPT: &str = r#"(function () {
  var frames = document.querySelectorAll('g.gam-frame');
  var slider = document.getElementById('gam-slider');
  var button = document.getElementById('gam-play');
  var n = frames.length, k = 0, playing = true;
  function show(i) {
    frames[k].setAttribute('visibility', 'hidden');
    k = ((i % n) + n) % n;
    frames[k].setAttribute('visibility', 'visible');
    slider.value = k;
    document.body.setAttribute('data-frame', k);
  }
  var m = /frame=(\d+)/.exec(location.hash);
  if (m) { playing = false; button.textContent = 'play'; }
  show(m ? parseInt(m[1], 10) : 0);
  slider.addEventListener('input', function () { playing = false; button.textContent = 'play'; show(parseInt(slider.value, 10)); });
  button.addEventListener('click', function () { playing = !playing; button.textContent = playing ? 'pause' : 'play'; });
  setInterval(function () { if (playing) { show(k + 1); } }, INTERVAL);
})();"#;

/// The HTML page of the figure titled `title`.
fn html(svg: &str, frames: &[String], title: &str) -> String {
    let mut groups = String::new();
    for elements in frames {
        let _ = write!(groups, "<g class=\"gam-frame\" visibility=\"hidden\">\n{elements}</g>\n");
    }
    let svg = with_groups(svg, &groups);
    let escaped = title.replace('&', "&amp;").replace('<', "&lt;").replace('>', "&gt;");
    let interval = format!("{:.0}", SECONDS * 1000.0 / frames.len().max(1) as f64);
    let script = SCRIPT.replace("INTERVAL", &interval);
    format!(
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>{escaped}</title>\n\
         <style>body {{ margin: 0; font-family: sans-serif; }} #gam-controls {{ padding: 4px 12px; }} \
         #gam-slider {{ width: 600px; vertical-align: middle; }}</style>\n</head>\n<body>\n{svg}\
         <div id=\"gam-controls\"><button id=\"gam-play\">pause</button> \
         <input id=\"gam-slider\" type=\"range\" min=\"0\" max=\"{}\" step=\"1\" value=\"0\"></div>\n\
         <script>\n{script}\n</script>\n</body>\n</html>\n",
        frames.len().saturating_sub(1)
    )
}

/// The animated figure of `all` (with `frames`: per spec, the series sampled at the
/// animation's [`FRAMES`] parameters) as the bytes of `kind`.
pub(crate) fn render(
    figure: (&[Series], View, Body, &str),
    frames: &[Series],
    kind: Kind,
) -> Result<Vec<u8>, CliError> {
    let (svg, layers) = layers(figure, frames)?;
    Ok(match kind {
        Kind::Svg => smil(&svg, &layers),
        Kind::Html => html(&svg, &layers, figure.3),
    }
    .into_bytes())
}
