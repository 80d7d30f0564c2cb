//! The output formats of `gam plot` and `gam figures`: SVG (plotters' SVG backend) or PNG
//! (plotters' `BitMapBackend` into memory, encoded by the `png` crate). plotters draws text
//! into a bitmap only through a font rasteriser and a system font; [`Raster`] instead draws
//! every text with the built-in bitmap font of [`super::font`] and hands everything else to
//! the `BitMapBackend`, so a PNG needs no font on the machine and has the same pixels
//! everywhere.
//!
//! A text occupies the box plotters' layout estimates for it (the box the SVG output's layout
//! uses too): per character `0.7 em` wide, `em` above the baseline and `0.24 em` below, with
//! `em = size / 1.24²`. A glyph's 5 x 9 pixels fill its character cell (6 columns with the
//! spacing, 8 rows above the baseline with one of space, 2 below), so the figure lays out the
//! same in both formats.

use super::font::{ABOVE, COLUMNS, glyph};
use crate::error::CliError;
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters_backend::text_anchor::{HPos, VPos};
use plotters_backend::{BackendColor, BackendCoord, BackendStyle, BackendTextStyle, DrawingErrorKind};

/// The file format of a figure.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum Format {
    /// Scalable vector graphics (the default).
    Svg,
    /// A PNG image (RGB, 8 bits per channel), text in the built-in bitmap font.
    Png,
}

impl Format {
    /// The format of `path` unless `given`: PNG for a name ending in `.png` (any case), SVG
    /// otherwise.
    pub fn of(given: Option<Format>, path: &str) -> Format {
        given.unwrap_or(if path.to_ascii_lowercase().ends_with(".png") { Format::Png } else { Format::Svg })
    }

    /// The file extension, without the dot.
    pub fn extension(self) -> &'static str {
        match self {
            Format::Svg => "svg",
            Format::Png => "png",
        }
    }
}

/// Something drawn on a drawing area of any backend (the figure is drawn once, whatever the
/// format).
pub(crate) trait Picture {
    /// The image size in pixels.
    fn size(&self) -> (u32, u32);
    /// Draws the picture on `root` (already filled white).
    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Result<(), CliError>;
}

fn draw_error<E: std::fmt::Display>(e: E) -> CliError {
    CliError::math(format!("cannot draw the plot: {e}"))
}

/// Draws `picture` on a white background, fills and presents it.
fn paint<DB: DrawingBackend>(picture: &impl Picture, backend: DB) -> Result<(), CliError> {
    let root = backend.into_drawing_area();
    root.fill(&WHITE).map_err(draw_error)?;
    picture.draw(&root)?;
    root.present().map_err(draw_error)
}

/// The bytes of the file of `picture` in `format` (drawn in memory, so nothing is written
/// when drawing fails).
pub(crate) fn encode(picture: &impl Picture, format: Format) -> Result<Vec<u8>, CliError> {
    let (w, h) = picture.size();
    match format {
        Format::Svg => {
            let mut svg = String::new();
            paint(picture, SVGBackend::with_string(&mut svg, (w, h)))?;
            Ok(svg.into_bytes())
        }
        Format::Png => {
            let mut rgb = vec![0u8; 3 * w as usize * h as usize];
            paint(picture, Raster { inner: BitMapBackend::with_buffer(&mut rgb, (w, h)) })?;
            let mut file = Vec::new();
            let mut encoder = png::Encoder::new(&mut file, w, h);
            encoder.set_color(png::ColorType::Rgb);
            encoder.set_depth(png::BitDepth::Eight);
            let png_error = |e: png::EncodingError| CliError::math(format!("cannot encode the PNG: {e}"));
            let mut writer = encoder.write_header().map_err(png_error)?;
            writer.write_image_data(&rgb).map_err(png_error)?;
            writer.finish().map_err(png_error)?;
            Ok(file)
        }
    }
}

/// A `BitMapBackend` that draws text with the built-in bitmap font (see the module doc).
pub(crate) struct Raster<'a> {
    inner: BitMapBackend<'a>,
}

type Error<'a> = DrawingErrorKind<<BitMapBackend<'a> as DrawingBackend>::ErrorType>;

impl<'a> DrawingBackend for Raster<'a> {
    type ErrorType = <BitMapBackend<'a> as DrawingBackend>::ErrorType;

    fn get_size(&self) -> (u32, u32) {
        self.inner.get_size()
    }

    fn ensure_prepared(&mut self) -> Result<(), Error<'a>> {
        self.inner.ensure_prepared()
    }

    fn present(&mut self) -> Result<(), Error<'a>> {
        self.inner.present()
    }

    fn draw_pixel(&mut self, point: BackendCoord, color: BackendColor) -> Result<(), Error<'a>> {
        self.inner.draw_pixel(point, color)
    }

    fn draw_line<S: BackendStyle>(&mut self, from: BackendCoord, to: BackendCoord, style: &S) -> Result<(), Error<'a>> {
        self.inner.draw_line(from, to, style)
    }

    fn draw_rect<S: BackendStyle>(
        &mut self,
        upper_left: BackendCoord,
        bottom_right: BackendCoord,
        style: &S,
        fill: bool,
    ) -> Result<(), Error<'a>> {
        self.inner.draw_rect(upper_left, bottom_right, style, fill)
    }

    fn draw_path<S: BackendStyle, I: IntoIterator<Item = BackendCoord>>(
        &mut self,
        path: I,
        style: &S,
    ) -> Result<(), Error<'a>> {
        self.inner.draw_path(path, style)
    }

    fn draw_circle<S: BackendStyle>(
        &mut self,
        center: BackendCoord,
        radius: u32,
        style: &S,
        fill: bool,
    ) -> Result<(), Error<'a>> {
        self.inner.draw_circle(center, radius, style, fill)
    }

    fn fill_polygon<S: BackendStyle, I: IntoIterator<Item = BackendCoord>>(
        &mut self,
        vert: I,
        style: &S,
    ) -> Result<(), Error<'a>> {
        self.inner.fill_polygon(vert, style)
    }

    fn blit_bitmap(&mut self, pos: BackendCoord, size: (u32, u32), src: &[u8]) -> Result<(), Error<'a>> {
        self.inner.blit_bitmap(pos, size, src)
    }

    fn draw_text<T: BackendTextStyle>(&mut self, text: &str, style: &T, pos: BackendCoord) -> Result<(), Error<'a>> {
        let color = style.color();
        if color.alpha == 0.0 {
            return Ok(());
        }
        let ((x0, y0), (x1, y1)) = text_box(text, style.size());
        let (width, height) = (x1 - x0, y1 - y0);
        let dx = match style.anchor().h_pos {
            HPos::Left => 0,
            HPos::Right => -width,
            HPos::Center => -width / 2,
        };
        let dy = match style.anchor().v_pos {
            VPos::Top => 0,
            VPos::Center => -height / 2,
            VPos::Bottom => -height,
        };
        let trans = style.transform();
        let (w, h) = self.get_size();
        for (x, y) in text_pixels(text, style.size()) {
            let (x, y) = trans.transform(x + dx - x0, y + dy - y0);
            let (x, y) = (pos.0 + x, pos.1 + y);
            if x >= 0 && x < w as i32 && y >= 0 && y < h as i32 {
                self.inner.draw_pixel((x, y), color)?;
            }
        }
        Ok(())
    }

    fn estimate_text_size<T: BackendTextStyle>(&self, text: &str, style: &T) -> Result<(u32, u32), Error<'a>> {
        let ((x0, y0), (x1, y1)) = text_box(text, style.size());
        Ok(((x1 - x0) as u32, (y1 - y0) as u32))
    }
}

/// `em` of a font of `size` (plotters' estimate).
fn em(size: f64) -> f64 {
    size / 1.24 / 1.24
}

/// The box of `text` at `size` relative to the start of its baseline, `((x0, y0), (x1, y1))`
/// (y down): the layout plotters estimates without a font, per character.
pub(crate) fn text_box(text: &str, size: f64) -> ((i32, i32), (i32, i32)) {
    let em = em(size);
    let n = text.chars().count() as f64;
    ((0, -em.round() as i32), ((em * 0.7 * n).round() as i32, (em * 0.24).round() as i32))
}

/// The pixels of `text` at `size` relative to the start of its baseline: every set glyph pixel
/// scaled to its share of the character cell (see the module doc).
pub(crate) fn text_pixels(text: &str, size: f64) -> Vec<(i32, i32)> {
    let em = em(size);
    let (cw, rh) = (0.7 * em / (COLUMNS + 1) as f64, em / (ABOVE + 1) as f64);
    let mut out = Vec::new();
    for (i, c) in text.chars().enumerate() {
        let left = 0.7 * em * i as f64;
        for (r, bits) in glyph(c).iter().enumerate() {
            // row r's top, with the baseline at y = 0 below row ABOVE - 1
            let top = (r as f64 - ABOVE as f64) * rh;
            let (ya, yb) = (top.round() as i32, (top + rh).round() as i32);
            for col in 0..COLUMNS {
                if bits >> (COLUMNS - 1 - col) & 1 == 0 {
                    continue;
                }
                let x = left + col as f64 * cw;
                let (xa, xb) = (x.round() as i32, (x + cw).round() as i32);
                for y in ya..yb.max(ya + 1) {
                    for x in xa..xb.max(xa + 1) {
                        out.push((x, y));
                    }
                }
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::{Format, text_box, text_pixels};

    #[test]
    fn the_format_follows_the_flag_then_the_extension() {
        assert_eq!(Format::of(None, "a/b.png"), Format::Png);
        assert_eq!(Format::of(None, "B.PNG"), Format::Png);
        assert_eq!(Format::of(None, "b.svg"), Format::Svg);
        assert_eq!(Format::of(None, "b"), Format::Svg);
        assert_eq!(Format::of(Some(Format::Png), "b.svg"), Format::Png);
        assert_eq!(Format::of(Some(Format::Svg), "b.png"), Format::Svg);
    }

    #[test]
    fn text_stays_in_its_box_and_scales_the_glyphs() {
        for size in [10.0, 12.0, 18.0, 22.0, 40.0] {
            let text = "Agy|_~";
            let ((x0, y0), (x1, y1)) = text_box(text, size);
            let px = text_pixels(text, size);
            assert!(!px.is_empty());
            for (x, y) in &px {
                assert!((x0..=x1).contains(x) && (y0..=y1).contains(y), "{size}: ({x}, {y}) outside");
            }
        }
        // At em = 8 (size 8 * 1.24²) a glyph pixel is one row high and 0.7 * 8 / 6 wide: the
        // capital I's 7 rows of pixels stand on the baseline, rows -7..-1.
        let px = text_pixels("I", 8.0 * 1.24 * 1.24);
        let rows: std::collections::BTreeSet<i32> = px.iter().map(|p| p.1).collect();
        assert_eq!(rows.into_iter().collect::<Vec<_>>(), vec![-7, -6, -5, -4, -3, -2, -1]);
    }
}
