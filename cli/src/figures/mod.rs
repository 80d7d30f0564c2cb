//! `gam figures --out DIR [--format svg|png] [--json]`: the papers' figures redrawn from the library's
//! constructions by the drawing of `gam plot` ([`crate::plot::draw::render`]), listed with what
//! to look for in docs/figures.md. This file: the main paper's Figs. 3-5 (Sec. 4): the
//! two-segment additive motion (a quadrant, then a line) of Fig. 3, its variants with
//! `V_1 = V_0 [1 + (Ψ + γ)/6]` for real `γ = 0, ±5, ±10` (Fig. 4, planar) and for
//! `γ = 0, ±20ω, ±40ω` with `ω = e123inf` (Fig. 5, out of the plane, viewed along the y-axis);
//! the body point is the body origin (the block's centre). [`cross2022`]: Figs. 6-10;
//! [`wareham_lasenby`]: W-L Figs. 5 and 7; [`juttler`]: Jüttler's Figs. 1-6.

mod juttler;

use crate::error::CliError;
use crate::plot::data::{Series, Shape, of_motion};
use crate::plot::draw::{Body, Panel, View, render, render_panel};
use crate::plot::raster::Format;
use motion::paper::sec_4;
use motion::{AdditiveBezier, Piecewise, Pose};
use serde_json::{Value, json};

mod cross2022;
mod wareham_lasenby;

/// Samples per curve.
pub(crate) const SAMPLES: usize = 401;

/// The Sec. 4 motion over `[0, 2]` with the line's `V_1` replaced by `V_0 [1 + (Ψ + γ)/6]`
/// (`γ = g + w ω`) when `gamma` is given, as a series labelled `label`.
fn sec4(label: &str, gamma: Option<[f64; 2]>, frames: usize) -> Result<Series, CliError> {
    let mut line = sec_4::printed_line();
    if let Some([g, w]) = gamma {
        let psi = sec_4::PRINTED_PSI_END_OF_ARC;
        let step = Pose::new(1.0 + (psi[0] + g) / 6.0, psi[1] / 6.0, 0.0, 0.0, 0.0, psi[2] / 6.0, 0.0, w / 6.0);
        line[1] = line[0].then(&step);
    }
    let bad = |e: motion::CurveError| CliError::math(format!("the Sec. 4 motion: {e}"));
    let segments =
        vec![AdditiveBezier::new(sec_4::printed_arc()).map_err(bad)?, AdditiveBezier::new(line).map_err(bad)?];
    let motion = Piecewise::new(vec![0.0, 1.0, 2.0], segments).map_err(bad)?;
    let shape = Shape {
        label: label.to_string(),
        method: label.to_string(),
        segments: 2,
        degree: 3,
        tableau: crate::budget::Tableau::Linear,
        key_times: vec![0.0, 1.0, 2.0],
        joins: vec![1.0],
    };
    of_motion(shape, &motion, vec![[0.0; 3]], SAMPLES, frames)
}

/// One figure: file name, title, view, series.
pub(crate) type Figure = (&'static str, String, View, Vec<Series>);

/// The figures.
fn all() -> Result<Vec<Figure>, CliError> {
    let fig3 = vec![sec4("quadrant then line", None, 9)?];
    let fig4 = [0.0, 5.0, -5.0, 10.0, -10.0]
        .iter()
        .map(|g| sec4(&format!("γ = {g}"), Some([*g, 0.0]), 0))
        .collect::<Result<Vec<_>, _>>()?;
    let fig5 = [0.0, 20.0, -20.0, 40.0, -40.0]
        .iter()
        .map(|w| sec4(&format!("γ = {w}ω"), Some([0.0, *w]), 0))
        .collect::<Result<Vec<_>, _>>()?;
    Ok([
        (
            "fig3.svg",
            "Fig. 3: quadrant and straight line (additive cubics), speeds jump at the join".into(),
            View::Xy,
            fig3,
        ),
        ("fig4.svg", "Fig. 4: V₁ = V₀[1 + (Ψ + γ)/6], γ real: planar".into(), View::Xy, fig4),
        ("fig5.svg", "Fig. 5: γ a multiple of ω = e123∞: out of the plane (x-z view)".into(), View::Xz, fig5),
    ]
    .into_iter()
    .chain(cross2022::figures()?)
    .chain(wareham_lasenby::figures()?)
    .collect())
}

/// The companion of Fig. 10: its motions' errors against the exact motion.
const FIG10_ERROR: &str = "fig10_error.svg";

/// The companion of Fig. 5: its speeds as increases over `γ = 0`.
const FIG5_INCREASE: &str = "fig5_increase.svg";

/// `100 (a - b) / b`, and 0 where both are 0.
fn percent(a: f64, b: f64) -> f64 {
    if a == b { 0.0 } else { 100.0 * (a - b) / b }
}

/// The companion of Fig. 5: every series with its linear and angular speeds as increases in
/// per cent over the first one's (`γ = 0`, the same samples), its title and the base's label. The ±γ motions mirror each other, so their
/// speeds coincide and are drawn over each other, and the increase is a few per cent: at the
/// scale of the speeds the paper's "this increases the linear speed" is hard to see.
fn increases(series: &[Series]) -> Result<(Vec<Series>, String, String), CliError> {
    let base = series.first().ok_or_else(|| CliError::math("Fig. 5 has no series"))?;
    let mut out = Vec::new();
    for s in series {
        let mut c = s.clone();
        c.speeds = s
            .speeds
            .iter()
            .zip(&base.speeds)
            .map(|(v, v0)| v.iter().zip(v0).map(|(a, b)| percent(*a, *b)).collect())
            .collect();
        c.angular_speed = s.angular_speed.iter().zip(&base.angular_speed).map(|(a, b)| percent(*a, *b)).collect();
        if c.speeds.iter().flatten().chain(&c.angular_speed).any(|x| !x.is_finite()) {
            return Err(CliError::math(format!("{}: a speed increase over a zero speed", s.label)));
        }
        c.frames.clear();
        out.push(c);
    }
    let title = "Fig. 5 (companion): the speeds of Fig. 5 as increases over γ = 0, in per cent".to_string();
    Ok((out, title, base.label.clone()))
}

/// How the body is drawn in figure `file`: the cuboid in the main paper's Fig. 3, the
/// L-shaped block in its Figs. 6-10.
fn body_of(file: &str) -> Body {
    match file {
        "fig3.svg" => Body::Cuboid,
        _ if cross2022::L_BLOCK_FILES.contains(&file) => Body::LBlock,
        _ => Body::Frames,
    }
}

/// `file` (named `NAME.svg`) with the extension of `format`.
fn named(file: &str, format: Format) -> String {
    format!("{}.{}", file.strip_suffix(".svg").unwrap_or(file), format.extension())
}

/// Writes one figure's file into `dir` and says so.
fn write(dir: &str, file: &str, title: &str, bytes: Vec<u8>) -> Result<String, CliError> {
    let path = std::path::Path::new(dir).join(file);
    let shown = path.display().to_string();
    std::fs::write(&path, bytes).map_err(|e| CliError::usage(format!("cannot write `{shown}`: {e}")))?;
    Ok(format!("wrote {shown}: {title}"))
}

/// Runs `gam figures`: writes the figures into `dir` in `format` (their names end in `.svg`
/// or `.png`) and reports them (or prints their data, keyed by the file names).
pub fn figures(dir: &str, format: Format, json: bool) -> Result<String, CliError> {
    let mut lines = Vec::new();
    let mut data = serde_json::Map::new();
    for (file, title, view, series) in all()? {
        let (body, fig5) = (body_of(file), file == "fig5.svg");
        let bytes = render(&series, view, body, &title, format)?;
        let file = named(file, format);
        lines.push(write(dir, &file, &title, bytes)?);
        let body = serde_json::to_value(body).map_err(|e| CliError::math(format!("cannot print the body: {e}")))?;
        data.insert(file, json!({"title": title, "body": body, "series": series}));
        if fig5 {
            let (companion, title, base) = increases(&series)?;
            let bytes = render_panel(&companion, (view, Body::Frames), (&title, Panel::Increase(&base)), format)?;
            let file = named(FIG5_INCREASE, format);
            lines.push(write(dir, &file, &title, bytes)?);
            data.insert(file, json!({"title": title, "relative_to": base, "series": companion}));
        }
    }
    let (errors, title) = cross2022::fig10_error()?;
    let panel = Panel::Error(cross2022::EXACT);
    let bytes = render_panel(&errors, (View::ThreeD, Body::Frames), (&title, panel), format)?;
    let file = named(FIG10_ERROR, format);
    lines.push(write(dir, &file, &title, bytes)?);
    data.insert(file, json!({"title": title, "error_against": cross2022::EXACT, "series": errors}));
    for (file, title, bytes, value) in juttler::all(format)? {
        let file = named(file, format);
        lines.push(write(dir, &file, &title, bytes)?);
        data.insert(file, value);
    }
    if json {
        return serde_json::to_string(&Value::Object(data))
            .map_err(|e| CliError::math(format!("cannot print the figure data: {e}")));
    }
    Ok(lines.join("\n"))
}
