//! `gam plot SPEC.json... --out FILE.svg|FILE.png|FILE.html [--format svg|png] [--samples N]
//! [--view xy|xz|yz|3d] [--frames K] [--body frames|cube|l-block|cuboid] [--acceleration] [--animate]
//! [--json]`: an
//! SVG (or a PNG, [`raster`]; or, with `--animate`, an animated SVG or HTML page, [`animate`])
//! of one or more specs, like the paper's
//! Figs. 3-5, with two panels: the linear speed of every body point and the angular speed
//! against `t` with the joins marked, and the paths of the body points (projected on a
//! coordinate plane, or in a 3-D view) with the key points and, with `--frames K`, the moved
//! body's coordinate frames (or, with `--body cube`, the unit cube; with `--body l-block`, the
//! L-shaped block) at `K` evenly spaced parameters. Several specs are overlaid in one figure
//! with a legend.
//!
//! A spec is a `gam interpolate` spec (it has a `method` key: every segment over the whole
//! parameter range, every `body_points` entry) or a `gam hermite` spec (one segment over
//! `[0, 1]`, its `body_point`), or explicit control data: a `segments` list as
//! `gam interpolate --json` prints it ([`control`]). The data are computed first ([`data::Series`], printed by
//! `--json`), then drawn ([`draw::render`]) into a string, then written to FILE (so an
//! unwritable path is one `error:` line, exit 2, and nothing is left half written).

pub(crate) mod animate;
pub(crate) mod axes3d;
pub(crate) mod control;
pub(crate) mod data;
pub(crate) mod draw;
pub(crate) mod font;
pub(crate) mod legend;
pub(crate) mod raster;
pub(crate) mod style;
pub(crate) mod surface;
pub(crate) mod svg;

use crate::error::CliError;
use crate::sample::Sampler;
use crate::scalar::format_f64;
use data::Series;
pub use draw::{Body, View};
pub use raster::Format;

/// The default number of samples of `gam plot`.
pub const DEFAULT_SAMPLES: usize = 201;

/// The most body frames `--frames` draws.
pub const MAX_FRAMES: usize = 1000;

/// The title of a sampled Hermite segment (also `gam sample`, in any scalar).
pub(crate) fn title<T: crate::precision::OutScalar>(s: &Sampler<T>) -> String {
    let point = s.body_point.iter().map(crate::precision::OutScalar::text).collect::<Vec<_>>();
    titled(&s.kind.to_string(), s.segments, s.degree, &[format!("[{}]", point.join(", "))])
}

/// "KIND segment of degree D" or "KIND motion of N segments of degree D", and the body points.
fn one_title(method: &str, segments: usize, degree: usize, points: &[[f64; 3]]) -> String {
    let p: Vec<String> = points.iter().map(|p| format!("[{}]", p.map(format_f64).join(", "))).collect();
    titled(method, segments, degree, &p)
}

/// [`one_title`] with the body points already written.
fn titled(method: &str, segments: usize, degree: usize, p: &[String]) -> String {
    let what = if segments == 1 {
        format!("{method} segment of degree {degree}")
    } else {
        format!("{method} motion of {segments} segments of degree {degree}")
    };
    let noun = if p.len() == 1 { "body point" } else { "body points" };
    format!("{what}, {noun} {}", p.join(" "))
}

/// The title of a figure of `all`.
fn figure_title(all: &[Series]) -> String {
    match all {
        [s] => one_title(&s.method, s.segments, s.degree, &s.body_points),
        _ => format!("{} motions: {}", all.len(), all.iter().map(|s| s.method.as_str()).collect::<Vec<_>>().join(", ")),
    }
}

/// What `gam plot` draws.
pub struct PlotArgs<'a> {
    /// The spec files (at least one).
    pub specs: &'a [String],
    /// The file to write.
    pub out: &'a str,
    /// The file format (`None`: PNG for an `out` ending in `.png`, SVG otherwise).
    pub format: Option<Format>,
    /// Samples per spec (at least 2).
    pub samples: usize,
    /// The path panel's view.
    pub view: View,
    /// Body frames per spec.
    pub frames: usize,
    /// How the body is drawn at the frames.
    pub body: Body,
    /// Print the data of the figure as JSON instead of the one-line report.
    pub json: bool,
    /// Write an animation ([`animate`]): an animated SVG, or an HTML page for an `out` ending
    /// in `.html`.
    pub animate: bool,
    /// Draw the accelerations `|a|`, `|Ω'|` instead of the speeds in the left panel.
    pub acceleration: bool,
}

/// Runs `gam plot`: writes the SVG or PNG to `out` and reports what was written (or prints the data).
pub fn plot(a: &PlotArgs) -> Result<String, CliError> {
    if a.specs.is_empty() {
        return Err(CliError::usage("`gam plot` needs at least one SPEC.json"));
    }
    if a.frames > MAX_FRAMES {
        return Err(CliError::usage(format!("`--frames` must be at most {MAX_FRAMES} (got {})", a.frames)));
    }
    if a.samples < 2 || a.samples > crate::sample::MAX_SAMPLES {
        let max = crate::sample::MAX_SAMPLES;
        return Err(CliError::usage(format!("`--samples` must be an integer from 2 to {max} (got {})", a.samples)));
    }
    let format = Format::of(a.format, a.out);
    if a.animate && format == Format::Png {
        return Err(CliError::usage("`--animate` writes an SVG or an HTML page (FILE.svg or FILE.html), not a PNG"));
    }
    let all = a.specs.iter().map(|p| data::series(p, a.samples, a.frames)).collect::<Result<Vec<_>, _>>()?;
    let title = figure_title(&all);
    let out = a.out;
    let bytes = if a.animate {
        let n = animate::FRAMES;
        let frames = a.specs.iter().map(|p| data::series(p, n, n)).collect::<Result<Vec<_>, _>>()?;
        animate::render((&all, a.view, a.body, &title), &frames, animate::Kind::of(out))?
    } else {
        let panel = if a.acceleration { draw::Panel::Acceleration } else { draw::Panel::Speeds };
        draw::render_panel(&all, (a.view, a.body), (&title, panel), format)?
    };
    std::fs::write(out, bytes).map_err(|e| CliError::usage(format!("cannot write `{out}`: {e}")))?;
    if a.json {
        return serde_json::to_string(&serde_json::json!({"title": title, "series": all}))
            .map_err(|e| CliError::math(format!("cannot print the plot data: {e}")));
    }
    Ok(format!("wrote {out}: {title} ({} samples)", a.samples))
}
