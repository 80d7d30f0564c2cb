//! Drawing a surface as a wireframe of its iso-parameter curves in a 3-D view (z up), e.g.
//! the kinematic surface of Jüttler's Fig. 5b ([`crate::figures`]). Every curve is one SVG
//! `<polyline>` in the SVG: the curves of one family in one colour, those of the other in another.

use super::axes3d::{self, Bounds};
use super::raster::{Format, Picture, encode};
use super::style::{Px, fitted};
use crate::error::CliError;
use plotters::coord::Shift;
use plotters::prelude::*;

/// The colours of the two families: `v` fixed (blue), `t` fixed (grey).
const FAMILIES: [RGBColor; 2] = [super::style::PALETTE[0], RGBColor(120, 120, 120)];

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

    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>, px: Px) -> Result<(), CliError> {
        let bounds = Bounds::of(self.families.iter().flat_map(|f| f.iter().flatten()));
        let size = fitted(self.title, 20.0, f64::from(self.size().0) - 24.0);
        let root = root.titled(self.title, ("sans-serif", px.font(size))).map_err(draw_error)?;
        let mut chart = axes3d::chart(&root, &bounds, px)?;
        axes3d::draw_axes(&mut chart, &root, &bounds, px)?;
        for (family, colour) in self.families.iter().zip(FAMILIES) {
            let width = if colour == FAMILIES[0] { 2.0 } else { 1.0 };
            for curve in family.iter() {
                let line = LineSeries::new(curve.iter().map(axes3d::to), colour.stroke_width(px.u(width)));
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
