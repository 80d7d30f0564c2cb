//! The output formats of `gam plot` and `gam figures`: SVG ([`super::svg::Svg`], drawn at
//! [`SVG_SCALE`]) or PNG (plotters' `BitMapBackend` into memory at [`PNG_SCALE`] times the
//! size, averaged down to the size, so lines are anti-aliased; encoded by the `png` crate).
//! plotters draws text into a bitmap only through a system font; [`Raster`] instead draws
//! every text with the bundled font of [`super::font`] (anti-aliased coverage) and hands
//! everything else to the `BitMapBackend`, so a PNG needs no font on the machine and has the
//! same pixels everywhere.
//!
//! Both formats lay texts out in the box plotters estimates without a font ([`text_box`]: per
//! character `0.7 em` wide, `em = size / 1.24²`) and draw them at [`drawn_em`] with the same
//! anchors and baselines, so the figure lays out the same in both.

use super::font;
use super::style::{DASH_OPACITY, DASH_PATTERN, Px, SVG_SCALE};
use super::svg::Svg;
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
    /// A PNG image (RGB, 8 bits per channel), text in the bundled DejaVu Sans.
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
    /// Draws the picture on `root` (already filled white) at the scale `px` (`root` is
    /// `px` times [`Picture::size`]).
    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>, px: Px) -> Result<(), CliError>;
}

/// A plotters drawing error as the one `error:` line of `gam plot` and `gam figures`.
pub(crate) fn draw_error<E: std::fmt::Display>(e: E) -> CliError {
    CliError::math(format!("cannot draw the plot: {e}"))
}

/// Draws `picture` on a white background, fills and presents it.
pub(crate) fn paint<DB: DrawingBackend>(picture: &impl Picture, backend: DB, px: Px) -> Result<(), CliError> {
    let root = backend.into_drawing_area();
    root.fill(&WHITE).map_err(draw_error)?;
    picture.draw(&root, px)?;
    root.present().map_err(draw_error)
}

/// The bytes of the file of `picture` in `format` (drawn in memory, so nothing is written
/// when drawing fails).
pub(crate) fn encode(picture: &impl Picture, format: Format) -> Result<Vec<u8>, CliError> {
    let (w, h) = picture.size();
    match format {
        Format::Svg => {
            let mut svg = String::new();
            paint(picture, Svg::new(&mut svg, (w, h), None), Px(SVG_SCALE))?;
            Ok(svg.into_bytes())
        }
        Format::Png => {
            let (sw, sh) = (w * PNG_SCALE, h * PNG_SCALE);
            let mut big = vec![0u8; 3 * sw as usize * sh as usize];
            paint(picture, Raster { inner: BitMapBackend::with_buffer(&mut big, (sw, sh)) }, Px(f64::from(PNG_SCALE)))?;
            let rgb = shrink(&big, (w, h));
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

/// PNGs are drawn at this multiple of their size and averaged down.
pub(crate) const PNG_SCALE: u32 = 2;

/// The `(w, h)` RGB image whose pixels are the means of the `PNG_SCALE`² pixels of `big`
/// (rounded to nearest). Written over rows and pixel chunks rather than per-byte index
/// arithmetic: the tests run the `gam` binary unoptimised, where this was a quarter of
/// `gam figures --format png`.
fn shrink(big: &[u8], (w, h): (u32, u32)) -> Vec<u8> {
    let (s, (w, h)) = (PNG_SCALE as usize, (w as usize, h as usize));
    let (count, half) = ((s * s) as u32, (s * s / 2) as u32);
    let mut out = Vec::with_capacity(3 * w * h);
    let mut sums = vec![0u32; 3 * w];
    // one band of `s` input rows per output row
    for band in big.chunks_exact(3 * w * s * s).take(h) {
        sums.fill(half);
        for row in band.chunks_exact(3 * w * s) {
            for (sum, block) in sums.chunks_exact_mut(3).zip(row.chunks_exact(3 * s)) {
                for px in block.chunks_exact(3) {
                    sum[0] += u32::from(px[0]);
                    sum[1] += u32::from(px[1]);
                    sum[2] += u32::from(px[2]);
                }
            }
        }
        out.extend(sums.iter().map(|&v| (v / count) as u8));
    }
    out
}

/// The dashes of the polyline `path`: pieces of [`DASH_PATTERN`]`[0] unit` drawn, then
/// `[1] unit` skipped (`unit`: the line width plus one pixel, in drawing units).
fn dashes(path: &[BackendCoord], unit: f64) -> Vec<Vec<BackendCoord>> {
    let (on, off) = (DASH_PATTERN[0] * unit, DASH_PATTERN[1] * unit);
    let (mut out, mut cur, mut drawing, mut left) = (Vec::new(), Vec::new(), true, on);
    for seg in path.windows(2) {
        let (a, b) = ((f64::from(seg[0].0), f64::from(seg[0].1)), (f64::from(seg[1].0), f64::from(seg[1].1)));
        let len = (b.0 - a.0).hypot(b.1 - a.1);
        let at = |s: f64| {
            let u = if len > 0.0 { s / len } else { 0.0 };
            ((a.0 + u * (b.0 - a.0)).round() as i32, (a.1 + u * (b.1 - a.1)).round() as i32)
        };
        let mut s = 0.0;
        if drawing && cur.is_empty() {
            cur.push(at(0.0));
        }
        while len - s > left {
            s += left;
            if drawing {
                cur.push(at(s));
                out.push(std::mem::take(&mut cur));
            } else {
                cur = vec![at(s)];
            }
            drawing = !drawing;
            left = if drawing { on } else { off };
        }
        left -= len - s;
        if drawing {
            cur.push(at(len));
        }
    }
    if cur.len() > 1 {
        out.push(cur);
    }
    out
}

/// The pixel spans `(y, x0, x1)` inside the polygon `vert` (even-odd rule, pixel centres).
fn spans(vert: &[BackendCoord]) -> Vec<(i32, i32, i32)> {
    let n = vert.len();
    if n < 3 {
        return vec![];
    }
    let (lo, hi) = vert.iter().fold((i32::MAX, i32::MIN), |(l, h), p| (l.min(p.1), h.max(p.1)));
    let mut out = Vec::new();
    let mut xs = Vec::new();
    for y in lo..=hi {
        let yc = f64::from(y) + 0.5;
        xs.clear();
        for i in 0..n {
            let (a, b) = (vert[i], vert[(i + 1) % n]);
            let (ya, yb) = (f64::from(a.1), f64::from(b.1));
            if (ya <= yc) != (yb <= yc) {
                xs.push(f64::from(a.0) + (yc - ya) / (yb - ya) * f64::from(b.0 - a.0));
            }
        }
        xs.sort_by(f64::total_cmp);
        for pair in xs.chunks_exact(2) {
            let (x0, x1) = ((pair[0] - 0.5).ceil() as i32, (pair[1] - 0.5).floor() as i32);
            if x0 <= x1 {
                out.push((y, x0, x1));
            }
        }
    }
    out
}

/// A `BitMapBackend` that draws text with the bundled font (see the module doc).
pub(crate) struct Raster<'a> {
    inner: BitMapBackend<'a>,
}

type Error<'a> = DrawingErrorKind<<BitMapBackend<'a> as DrawingBackend>::ErrorType>;

impl<'a> Raster<'a> {
    /// Draws a polyline segment by segment with round joins: plotters joins the segments of a
    /// wide polyline with mitres, which shoot far out where the line turns back on itself (the
    /// L-shaped block's zigzag along its edges).
    fn wide_path<S: BackendStyle>(&mut self, path: &[BackendCoord], style: &S) -> Result<(), Error<'a>> {
        let w = style.stroke_width();
        if w <= 1 {
            return self.inner.draw_path(path.iter().copied(), style);
        }
        for seg in path.windows(2) {
            self.inner.draw_path(seg.iter().copied(), style)?;
        }
        if style.color().alpha >= 1.0 {
            for p in path.iter().skip(1).take(path.len().saturating_sub(2)) {
                self.inner.draw_circle(*p, w / 2, &style.color(), true)?;
            }
        }
        Ok(())
    }
}

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
        let c = style.color();
        let path: Vec<_> = path.into_iter().collect();
        if c.alpha != DASH_OPACITY {
            return self.wide_path(&path, style);
        }
        let solid = ShapeStyle {
            color: RGBAColor(c.rgb.0, c.rgb.1, c.rgb.2, 1.0),
            filled: false,
            stroke_width: style.stroke_width(),
        };
        for dash in dashes(&path, f64::from(style.stroke_width() + PNG_SCALE)) {
            self.wide_path(&dash, &solid)?;
        }
        Ok(())
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
        // plotters' own polygon fill draws stray spans for polygons seen almost edge on (the
        // L-shaped block's faces in a 3-D view); this is a plain even-odd scanline fill.
        let c = style.color();
        let vert: Vec<BackendCoord> = vert.into_iter().collect();
        for (y, x0, x1) in spans(&vert) {
            for x in x0..=x1 {
                self.inner.draw_pixel((x, y), c)?;
            }
        }
        Ok(())
    }

    fn blit_bitmap(&mut self, pos: BackendCoord, size: (u32, u32), src: &[u8]) -> Result<(), Error<'a>> {
        self.inner.blit_bitmap(pos, size, src)
    }

    fn draw_text<T: BackendTextStyle>(&mut self, text: &str, style: &T, pos: BackendCoord) -> Result<(), Error<'a>> {
        let color = style.color();
        if color.alpha == 0.0 {
            return Ok(());
        }
        let ((x0, _), (x1, _)) = text_box(text, style.size());
        let em = drawn_em(style.size());
        let (pixels, width) =
            font::coverage(text, em, f64::from(x1 - x0)).map_err(|e| DrawingErrorKind::FontError(Box::new(e)))?;
        // Anchored by the drawn width and the baseline offsets of the SVG output
        // (`text-anchor`, and `dy` of 0.76 em, 0.5 ex or -0.5 ex).
        let width = width.round() as i32;
        let dx = match style.anchor().h_pos {
            HPos::Left => 0,
            HPos::Right => -width,
            HPos::Center => -width / 2,
        };
        let dy = (em
            * match style.anchor().v_pos {
                VPos::Top => 0.76,
                VPos::Center => 0.5 * font::EX,
                VPos::Bottom => -0.5 * font::EX,
            })
        .round() as i32;
        let trans = style.transform();
        for (x, y, c) in pixels {
            let (x, y) = trans.transform(x + dx, y + dy);
            let alpha = color.alpha * f64::from(c);
            self.inner.draw_pixel((pos.0 + x, pos.1 + y), BackendColor { alpha, rgb: color.rgb })?;
        }
        Ok(())
    }

    fn estimate_text_size<T: BackendTextStyle>(&self, text: &str, style: &T) -> Result<(u32, u32), Error<'a>> {
        let ((x0, y0), (x1, y1)) = text_box(text, style.size());
        Ok(((x1 - x0) as u32, (y1 - y0) as u32))
    }
}

/// `em` of a font of `size` in plotters' layout estimate (smaller than the drawn em,
/// [`drawn_em`]).
fn em(size: f64) -> f64 {
    size / 1.24 / 1.24
}

/// The em a text of `size` is drawn at, in both formats: the SVG's `font-size` and the PNG's
/// glyphs.
pub(crate) fn drawn_em(size: f64) -> f64 {
    size / 1.24
}

/// The box of `text` at `size` relative to the start of its baseline, `((x0, y0), (x1, y1))`
/// (y down): the layout plotters estimates without a font, per character.
pub(crate) fn text_box(text: &str, size: f64) -> ((i32, i32), (i32, i32)) {
    let em = em(size);
    let n = text.chars().count() as f64;
    ((0, -em.round() as i32), ((em * 0.7 * n).round() as i32, (em * 0.24).round() as i32))
}

#[cfg(test)]
mod tests {
    use super::{Format, text_box};

    #[test]
    fn polygons_fill_their_inside_only() {
        // A 4 x 2 rectangle: pixel centres (x + 0.5, y + 0.5) inside for x in 0..4, y in 0..2.
        let rect = super::spans(&[(0, 0), (4, 0), (4, 2), (0, 2)]);
        assert_eq!(rect, vec![(0, 0, 3), (1, 0, 3)]);
        // A sliver seen edge on (all corners within half a pixel of one row) fills at most
        // that row, never a long stray span.
        let sliver = super::spans(&[(0, 10), (300, 10), (300, 11), (150, 10), (0, 11)]);
        assert!(sliver.iter().all(|(y, x0, x1)| *y == 10 && *x0 >= 0 && *x1 < 300), "{sliver:?}");
        // A triangle: the row through y = 4.5 of (0, 0), (10, 0), (0, 10) covers x + 0.5 <= 5.5.
        let tri = super::spans(&[(0, 0), (10, 0), (0, 10)]);
        assert!(tri.contains(&(4, 0, 5)), "{tri:?}");
        assert!(super::spans(&[(0, 0), (1, 1)]).is_empty());
    }

    #[test]
    fn shrinking_averages_each_block_of_pixels_rounded_to_nearest() {
        let (w, h, s) = (5usize, 3usize, super::PNG_SCALE as usize);
        // a pseudo-random RGB image at PNG_SCALE times (w, h)
        let mut x = 0x2545_f491_u32;
        let big: Vec<u8> = (0..3 * w * s * h * s)
            .map(|_| {
                x ^= x << 13;
                x ^= x >> 17;
                x ^= x << 5;
                (x >> 24) as u8
            })
            .collect();
        let small = super::shrink(&big, (w as u32, h as u32));
        assert_eq!(small.len(), 3 * w * h);
        // each output byte, by the definition: the block's mean, rounded half up
        for (y, xx, c) in (0..h).flat_map(|y| (0..w).flat_map(move |xx| (0..3).map(move |c| (y, xx, c)))) {
            let sum: u32 = (0..s)
                .flat_map(|dy| (0..s).map(move |dx| (dy, dx)))
                .map(|(dy, dx)| u32::from(big[3 * ((y * s + dy) * w * s + xx * s + dx) + c]))
                .sum();
            let n = (s * s) as f64;
            assert_eq!(f64::from(small[3 * (y * w + xx) + c]), (f64::from(sum) / n + 0.5).floor(), "({y}, {xx}, {c})");
        }
        // a flat image stays flat
        assert!(super::shrink(&vec![200; 3 * w * s * h * s], (w as u32, h as u32)).iter().all(|&v| v == 200));
    }

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
    fn text_stays_in_its_box() {
        // The box an SVG reader gives a text (cli/tests/figures_reader.rs): at most 0.7 em of
        // plotters' estimate per character wide, 0.76 drawn em above the baseline and 0.24
        // below (one pixel more for anti-aliasing).
        for size in [10.0, 12.0, 18.0, 22.0, 40.0] {
            let em = super::drawn_em(size);
            for text in ["Agy|_~", "WWWWMM", "t∥ λ = 1.5", "iiii", "(Ψ)"] {
                let ((x0, _), (x1, _)) = text_box(text, size);
                let (px, width) = super::font::coverage(text, em, f64::from(x1 - x0)).expect("the font");
                assert!(!px.is_empty() && width <= f64::from(x1 - x0) + 0.01, "{text} at {size}: width {width}");
                let (top, bottom) = ((-0.76 * em).floor() as i32 - 1, (0.24 * em).ceil() as i32 + 1);
                for (x, y, _) in &px {
                    assert!(
                        (x0 - 1..=x1 + 1).contains(x) && (top..=bottom).contains(y),
                        "{text} at {size}: ({x}, {y}) outside"
                    );
                }
            }
        }
        // The capital I stands on the baseline and is 0.73 em high (DejaVu Sans' cap height,
        // 1493 of 2048 units): at em = 20 its rows are -15..-1.
        let (px, _) = super::font::coverage("I", 20.0, 100.0).expect("the font");
        let full: std::collections::BTreeSet<i32> = px.iter().filter(|p| p.2 > 0.99).map(|p| p.1).collect();
        assert_eq!(full.first().copied(), Some(-14));
        assert_eq!(full.last().copied(), Some(-1));
    }
}
