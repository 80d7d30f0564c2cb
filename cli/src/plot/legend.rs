//! The legend of a `gam plot` figure: a band under both panels, outside every plotting area,
//! so no entry can hide data. Entries are laid out in as many columns as the longest one
//! allows; each has a swatch drawn as `<rect>`s (one for a solid line or a dot, three for a
//! dashed one),
//! so the swatches are never taken for data. The band is one `<rect>` filled with
//! [`FILL`], which is how a reader (or a test) finds it.

use super::raster::text_box;
use super::style::Px;
use crate::error::CliError;
use plotters::coord::Shift;
use plotters::prelude::*;

/// The legend band's background (no other element has it).
pub(crate) const FILL: RGBColor = RGBColor(250, 250, 250);

/// How an entry's swatch is drawn.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Swatch {
    /// A thick solid line.
    Solid,
    /// A thin dashed line.
    Dashed,
    /// A dot (the key points), drawn as a small square (a `<rect>` like every swatch).
    Dot,
    /// A thick solid line, then a thin dashed one (a spec's linear and angular speed).
    Pair,
}

/// One legend entry.
#[derive(Debug, Clone)]
pub(crate) struct Entry {
    /// The text.
    pub text: String,
    /// The colour.
    pub colour: RGBColor,
    /// The swatch.
    pub swatch: Swatch,
}

/// The legend text size, the swatch length, the row height and the padding, in pixels.
const FONT: f64 = 13.0;
const SWATCH: f64 = 28.0;
const ROW: f64 = 19.0;
const PAD: f64 = 8.0;

/// The columns and the column width (pixels) of `entries` in a band `width` pixels wide.
fn columns(entries: &[Entry], width: f64) -> (usize, f64) {
    let widest = entries.iter().map(|e| f64::from(text_box(&e.text, FONT).1.0)).fold(0.0, f64::max);
    let column = SWATCH + 8.0 + widest + 18.0;
    let n = ((width - 2.0 * PAD) / column).floor().clamp(1.0, entries.len().max(1) as f64) as usize;
    (n, column)
}

/// The band's height in pixels for `entries` in a band `width` pixels wide (0 without entries).
pub(crate) fn height(entries: &[Entry], width: f64) -> u32 {
    if entries.is_empty() {
        return 0;
    }
    let (n, _) = columns(entries, width);
    let rows = entries.len().div_ceil(n);
    (2.0 * PAD + rows as f64 * ROW + 6.0).ceil() as u32
}

fn draw_error<E: std::fmt::Display>(e: E) -> CliError {
    CliError::math(format!("cannot draw the legend: {e}"))
}

/// Draws `entries` in `band` (its top inset by 3 pixels, the box 6 pixels from each side).
pub(crate) fn draw<DB: DrawingBackend>(
    band: &DrawingArea<DB, Shift>,
    entries: &[Entry],
    px: Px,
) -> Result<(), CliError> {
    if entries.is_empty() {
        return Ok(());
    }
    let (w, h) = band.dim_in_pixel();
    let width = f64::from(w) / px.0;
    let (n, column) = columns(entries, width);
    let box_ = Rectangle::new([(px.i(6.0), px.i(3.0)), (w as i32 - px.i(6.0), h as i32 - px.i(3.0))], FILL.filled());
    band.draw(&box_).map_err(draw_error)?;
    let border = Rectangle::new(
        [(px.i(6.0), px.i(3.0)), (w as i32 - px.i(6.0), h as i32 - px.i(3.0))],
        RGBColor(160, 160, 160).stroke_width(px.u(1.0)),
    );
    band.draw(&border).map_err(draw_error)?;
    let font = ("sans-serif", px.font(FONT)).into_font().color(&BLACK).pos(plotters::style::text_anchor::Pos::new(
        plotters::style::text_anchor::HPos::Left,
        plotters::style::text_anchor::VPos::Center,
    ));
    for (i, e) in entries.iter().enumerate() {
        let (row, col) = (i / n, i % n);
        let x = PAD + 6.0 + col as f64 * column;
        let y = PAD + 3.0 + (row as f64 + 0.5) * ROW;
        let bar = |a: f64, b: f64, half: f64| {
            Rectangle::new([(px.i(x + a), px.i(y - half)), (px.i(x + b), px.i(y + half))], e.colour.filled())
        };
        match e.swatch {
            Swatch::Solid => band.draw(&bar(0.0, SWATCH, 1.5)).map_err(draw_error)?,
            Swatch::Dashed => {
                for k in 0..3 {
                    let a = k as f64 * SWATCH / 3.0;
                    band.draw(&bar(a, a + SWATCH / 3.0 - 3.0, 0.75)).map_err(draw_error)?;
                }
            }
            Swatch::Pair => {
                band.draw(&bar(0.0, SWATCH / 2.0 - 2.0, 1.5)).map_err(draw_error)?;
                for k in 0..2 {
                    let a = SWATCH / 2.0 + 2.0 + k as f64 * SWATCH / 4.0;
                    band.draw(&bar(a, a + SWATCH / 4.0 - 2.5, 0.75)).map_err(draw_error)?;
                }
            }
            Swatch::Dot => band.draw(&bar(SWATCH / 2.0 - 3.5, SWATCH / 2.0 + 3.5, 3.5)).map_err(draw_error)?,
        }
        band.draw(&Text::new(e.text.clone(), (px.i(x + SWATCH + 8.0), px.i(y)), font.clone())).map_err(draw_error)?;
    }
    Ok(())
}
