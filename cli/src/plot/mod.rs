//! `gam plot SPEC.json --out FILE.svg [--samples N]`: an SVG of the sampled segment (see
//! [`crate::sample`]) with two panels, like the paper's Figs. 3-5: the linear speed of the body
//! point and the angular speed against `t`, and the path of the body point projected on the
//! x-y plane. Drawn with `plotters` into a string, then written to FILE (so an unwritable
//! path is one `error:` line, exit 2, and nothing is left half written by the backend).

use crate::error::CliError;
use crate::sample::{Sampled, sample_spec};
use crate::scalar::format_f64;
use plotters::prelude::*;

/// The default number of samples of `gam plot`.
pub const DEFAULT_SAMPLES: usize = 201;

/// `[lo, hi]` covering `values`, padded by 5% (and widened when all values are equal).
fn range(values: impl Iterator<Item = f64>) -> (f64, f64) {
    let (mut lo, mut hi) = values.fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), x| (l.min(x), h.max(x)));
    if !lo.is_finite() || !hi.is_finite() {
        return (0.0, 1.0);
    }
    let span = hi - lo;
    let pad = if span > 0.0 { 0.05 * span } else { 0.5 * lo.abs().max(1.0) };
    lo -= pad;
    hi += pad;
    (lo, hi)
}

/// The title of the figure.
pub(crate) fn title(s: &Sampled) -> String {
    let p = s.body_point.map(format_f64);
    let what = if s.segments == 1 {
        format!("{} segment of degree {}", s.kind, s.degree)
    } else {
        format!("{} motion of {} segments of degree {}", s.kind, s.segments, s.degree)
    };
    format!("{what}, body point [{}, {}, {}]", p[0], p[1], p[2])
}

fn draw_error<E: std::fmt::Display>(e: E) -> CliError {
    CliError::math(format!("cannot draw the plot: {e}"))
}

/// Renders the SVG text of a sampled segment.
pub(crate) fn render(s: &Sampled) -> Result<String, CliError> {
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (1200, 560)).into_drawing_area();
        root.fill(&WHITE).map_err(draw_error)?;
        let root = root.titled(&title(s), ("sans-serif", 22)).map_err(draw_error)?;
        let (left, right) = root.split_horizontally(600);

        // Panel 1: speeds against t.
        let t_range = match (s.samples.first(), s.samples.last()) {
            (Some(a), Some(b)) if b.t > a.t => (a.t, b.t),
            _ => (0.0, 1.0),
        };
        let (_, speed_hi) =
            range(s.samples.iter().flat_map(|x| [x.linear_speed, x.angular_speed]).chain(std::iter::once(0.0)));
        let mut chart = ChartBuilder::on(&left)
            .caption("linear and angular speed", ("sans-serif", 18))
            .margin(15)
            .x_label_area_size(40)
            .y_label_area_size(60)
            .build_cartesian_2d(t_range.0..t_range.1, 0.0..speed_hi)
            .map_err(draw_error)?;
        chart.configure_mesh().x_desc("t").y_desc("speed (per unit t)").draw().map_err(draw_error)?;
        chart
            .draw_series(LineSeries::new(s.samples.iter().map(|x| (x.t, x.linear_speed)), BLUE.stroke_width(2)))
            .map_err(draw_error)?
            .label("linear speed |v|")
            .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], BLUE.stroke_width(2)));
        chart
            .draw_series(LineSeries::new(s.samples.iter().map(|x| (x.t, x.angular_speed)), RED.stroke_width(2)))
            .map_err(draw_error)?
            .label("angular speed |Omega|")
            .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], RED.stroke_width(2)));
        chart
            .configure_series_labels()
            .background_style(WHITE.mix(0.8))
            .border_style(BLACK)
            .position(SeriesLabelPosition::UpperRight)
            .draw()
            .map_err(draw_error)?;

        // Panel 2: the path of the body point, x-y projection.
        let (x_lo, x_hi) = range(s.samples.iter().map(|x| x.position[0]));
        let (y_lo, y_hi) = range(s.samples.iter().map(|x| x.position[1]));
        let mut path = ChartBuilder::on(&right)
            .caption("path of the body point (x-y projection)", ("sans-serif", 18))
            .margin(15)
            .x_label_area_size(40)
            .y_label_area_size(60)
            .build_cartesian_2d(x_lo..x_hi, y_lo..y_hi)
            .map_err(draw_error)?;
        path.configure_mesh().x_desc("x").y_desc("y").draw().map_err(draw_error)?;
        path.draw_series(LineSeries::new(
            s.samples.iter().map(|x| (x.position[0], x.position[1])),
            BLUE.stroke_width(2),
        ))
        .map_err(draw_error)?;
        let ends = [s.samples.first(), s.samples.last()];
        path.draw_series(
            ends.into_iter().flatten().map(|x| Circle::new((x.position[0], x.position[1]), 4, BLACK.filled())),
        )
        .map_err(draw_error)?;
        root.present().map_err(draw_error)?;
    }
    Ok(svg)
}

/// Runs `gam plot`: writes the SVG to `out` and reports what was written.
pub fn plot(path: &str, out: &str, n: usize) -> Result<String, CliError> {
    let sampled = sample_spec(path, n)?;
    let svg = render(&sampled)?;
    std::fs::write(out, svg).map_err(|e| CliError::usage(format!("cannot write `{out}`: {e}")))?;
    Ok(format!("wrote {out}: {} ({} samples)", title(&sampled), sampled.samples.len()))
}
