//! Drawing a surface as a wireframe of its iso-parameter curves in a 3-D view (z up), e.g.
//! the kinematic surface of Jüttler's Fig. 5b ([`crate::figures`]). Every curve is one SVG
//! `<polyline>` in the SVG: the curves of one family in one colour, those of the other in another.

use super::draw::range;
use super::raster::{Format, Picture, encode};
use crate::error::CliError;
use plotters::coord::Shift;
use plotters::prelude::*;

/// The colours of the two families: `v` fixed (blue), `t` fixed (grey).
const FAMILIES: [RGBColor; 2] = [RGBColor(31, 119, 180), RGBColor(120, 120, 120)];

fn draw_error<E: std::fmt::Display>(e: E) -> CliError {
    CliError::math(format!("cannot draw the surface: {e}"))
}

/// The wireframe of the curves `families[0]` (drawn thick) and `families[1]` (thin), titled
/// `title` (800 x 640 pixels).
pub(crate) struct Wireframe<'a> {
    /// The two families of curves.
    pub families: [&'a [Vec<[f64; 3]>]; 2],
    /// The title.
    pub title: &'a str,
}

impl Picture for Wireframe<'_> {
    fn size(&self) -> (u32, u32) {
        (800, 640)
    }

    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Result<(), CliError> {
        let all: Vec<&[f64; 3]> = self.families.iter().flat_map(|f| f.iter().flatten()).collect();
        let (x, y, z) =
            (range(all.iter().map(|p| p[0])), range(all.iter().map(|p| p[1])), range(all.iter().map(|p| p[2])));
        let root = root.titled(self.title, ("sans-serif", 20)).map_err(draw_error)?;
        let mut chart =
            ChartBuilder::on(&root).margin(15).build_cartesian_3d(x.0..x.1, z.0..z.1, y.0..y.1).map_err(draw_error)?;
        chart.configure_axes().draw().map_err(draw_error)?;
        for (family, colour) in self.families.iter().zip(FAMILIES) {
            let width = if colour == FAMILIES[0] { 2 } else { 1 };
            for curve in family.iter() {
                let line = LineSeries::new(curve.iter().map(|p| (p[0], p[2], p[1])), colour.stroke_width(width));
                chart.draw_series(line).map_err(draw_error)?;
            }
        }
        Ok(())
    }
}

/// The file bytes of the [`Wireframe`] of `families` titled `title` in `format`.
pub(crate) fn wireframe(families: [&[Vec<[f64; 3]>]; 2], title: &str, format: Format) -> Result<Vec<u8>, CliError> {
    encode(&Wireframe { families, title }, format)
}
