//! The SVG output of `gam plot` and `gam figures`: a plotters backend that is drawn at
//! [`SVG_SCALE`] times the picture's size (plotters places everything on an integer grid) and
//! writes every coordinate, width and font size divided by it, so the file is the picture's
//! size in pixels with coordinates to a quarter pixel.
//!
//! Elements: data lines are `<polyline>`s (a line drawn with [`super::style::dashed`] gets a
//! `stroke-dasharray`), filled areas `<polygon>`s, rectangles `<rect>`, dots `<circle>`, text
//! `<text>` with `text-anchor` and a `dy` for its vertical anchor (as plotters' own SVG
//! backend writes them). A text's box is the one plotters' layout estimates
//! ([`super::raster::text_box`]), so the layout is the same in SVG and PNG.

use super::style::{DASH_OPACITY, DASH_PATTERN, SVG_SCALE};
use plotters_backend::text_anchor::{HPos, VPos};
use plotters_backend::{
    BackendColor, BackendCoord, BackendStyle, BackendTextStyle, DrawingBackend, DrawingErrorKind, FontTransform,
};
use std::cell::RefCell;
use std::fmt::Write as _;
use std::rc::Rc;

/// The layers of an animated picture: while `current` is `Some(k)`, what is drawn goes into
/// `frames[k]` instead of the picture ([`super::animate`]).
#[derive(Debug, Default)]
pub(crate) struct Layers {
    /// The layer being drawn, if any.
    pub current: Option<usize>,
    /// The elements of each layer.
    pub frames: Vec<String>,
}

/// The layers shared by the drawing code (which switches them) and the backend (which writes
/// into them).
pub(crate) type SharedLayers = Rc<RefCell<Layers>>;

/// Draws into layer `k` of `layers` (if any) while `draw` runs.
pub(crate) fn in_layer<T>(layers: Option<&SharedLayers>, k: usize, draw: impl FnOnce() -> T) -> T {
    if let Some(l) = layers {
        let mut l = l.borrow_mut();
        if l.frames.len() <= k {
            l.frames.resize(k + 1, String::new());
        }
        l.current = Some(k);
    }
    let out = draw();
    if let Some(l) = layers {
        l.borrow_mut().current = None;
    }
    out
}

/// An SVG document being drawn (see the module doc).
pub(crate) struct Svg<'a> {
    out: &'a mut String,
    /// The picture's size in pixels.
    size: (u32, u32),
    /// The animation layers, if the picture has any.
    layers: Option<SharedLayers>,
}

impl<'a> Svg<'a> {
    /// Starts a picture of `size` pixels written into `out`, drawing into `layers` while one
    /// is switched on.
    pub fn new(out: &'a mut String, size: (u32, u32), layers: Option<SharedLayers>) -> Self {
        let _ = writeln!(
            out,
            r#"<svg width="{w}" height="{h}" viewBox="0 0 {w} {h}" xmlns="http://www.w3.org/2000/svg">"#,
            w = size.0,
            h = size.1
        );
        Svg { out, size, layers }
    }

    /// Writes one element line into the current layer or the picture.
    fn emit(&mut self, line: String) {
        if let Some(layers) = &self.layers {
            let mut l = layers.borrow_mut();
            if let Some(k) = l.current {
                l.frames[k].push_str(&line);
                l.frames[k].push('\n');
                return;
            }
        }
        self.out.push_str(&line);
        self.out.push('\n');
    }
}

/// A drawing-unit length as SVG pixels, with at most two decimals.
fn n(v: f64) -> String {
    let v = (v / SVG_SCALE * 100.0).round() / 100.0;
    if v == v.trunc() { format!("{}", v as i64) } else { format!("{v}") }
}

fn colour(c: BackendColor) -> String {
    format!("#{:02X}{:02X}{:02X}", c.rgb.0, c.rgb.1, c.rgb.2)
}

/// ` opacity="a"` unless opaque (or the dash marker).
fn opacity(c: BackendColor) -> String {
    if c.alpha >= 1.0 || c.alpha == DASH_OPACITY { String::new() } else { format!(r#" opacity="{}""#, c.alpha) }
}

fn points(path: impl IntoIterator<Item = BackendCoord>) -> String {
    let all: Vec<String> = path.into_iter().map(|(x, y)| format!("{},{}", n(x.into()), n(y.into()))).collect();
    all.join(" ")
}

fn escape(text: &str) -> String {
    text.chars()
        .map(|c| match c {
            '<' => "&lt;".to_string(),
            '>' => "&gt;".to_string(),
            '&' => "&amp;".to_string(),
            '"' => "&quot;".to_string(),
            '\'' => "&apos;".to_string(),
            c => c.to_string(),
        })
        .collect()
}

type Error = DrawingErrorKind<std::convert::Infallible>;

impl DrawingBackend for Svg<'_> {
    type ErrorType = std::convert::Infallible;

    fn get_size(&self) -> (u32, u32) {
        let s = |v: u32| (f64::from(v) * SVG_SCALE) as u32;
        (s(self.size.0), s(self.size.1))
    }

    fn ensure_prepared(&mut self) -> Result<(), Error> {
        Ok(())
    }

    fn present(&mut self) -> Result<(), Error> {
        if !self.out.ends_with("</svg>\n") {
            self.out.push_str("</svg>\n");
        }
        Ok(())
    }

    fn draw_pixel(&mut self, p: BackendCoord, c: BackendColor) -> Result<(), Error> {
        if c.alpha > 0.0 {
            let one = n(1.0);
            let (x, y, f, o) = (n(p.0.into()), n(p.1.into()), colour(c), opacity(c));
            self.emit(format!(r#"<rect x="{x}" y="{y}" width="{one}" height="{one}" fill="{f}"{o}/>"#));
        }
        Ok(())
    }

    fn draw_line<S: BackendStyle>(&mut self, from: BackendCoord, to: BackendCoord, style: &S) -> Result<(), Error> {
        self.draw_path([from, to], style)
    }

    fn draw_rect<S: BackendStyle>(
        &mut self,
        a: BackendCoord,
        b: BackendCoord,
        style: &S,
        fill: bool,
    ) -> Result<(), Error> {
        let c = style.color();
        if c.alpha == 0.0 {
            return Ok(());
        }
        let (x, y, w, h) = (n(a.0.into()), n(a.1.into()), n((b.0 - a.0).into()), n((b.1 - a.1).into()));
        let paint = if fill {
            format!(r#"fill="{}" stroke="none""#, colour(c))
        } else {
            format!(r#"fill="none" stroke="{}" stroke-width="{}""#, colour(c), n(style.stroke_width().into()))
        };
        let o = opacity(c);
        self.emit(format!(r#"<rect x="{x}" y="{y}" width="{w}" height="{h}" {paint}{o}/>"#));
        Ok(())
    }

    fn draw_path<S: BackendStyle, I: IntoIterator<Item = BackendCoord>>(
        &mut self,
        path: I,
        style: &S,
    ) -> Result<(), Error> {
        let c = style.color();
        if c.alpha == 0.0 {
            return Ok(());
        }
        let w = f64::from(style.stroke_width());
        let dash = if c.alpha == DASH_OPACITY {
            let unit = w + SVG_SCALE;
            format!(r#" stroke-dasharray="{} {}""#, n(DASH_PATTERN[0] * unit), n(DASH_PATTERN[1] * unit))
        } else {
            String::new()
        };
        let (p, s, o, w) = (points(path), colour(c), opacity(c), n(w));
        self.emit(format!(
            r#"<polyline fill="none" stroke="{s}" stroke-width="{w}"{dash}{o} stroke-linejoin="round" points="{p}"/>"#
        ));
        Ok(())
    }

    fn draw_circle<S: BackendStyle>(&mut self, c0: BackendCoord, r: u32, style: &S, fill: bool) -> Result<(), Error> {
        let c = style.color();
        if c.alpha == 0.0 {
            return Ok(());
        }
        let paint = if fill {
            format!(r#"fill="{}" stroke="none""#, colour(c))
        } else {
            format!(r#"fill="none" stroke="{}""#, colour(c))
        };
        let (x, y, r, o) = (n(c0.0.into()), n(c0.1.into()), n(r.into()), opacity(c));
        self.emit(format!(r#"<circle cx="{x}" cy="{y}" r="{r}" {paint}{o}/>"#));
        Ok(())
    }

    fn fill_polygon<S: BackendStyle, I: IntoIterator<Item = BackendCoord>>(
        &mut self,
        vert: I,
        style: &S,
    ) -> Result<(), Error> {
        let c = style.color();
        if c.alpha > 0.0 {
            let (p, f, o) = (points(vert), colour(c), opacity(c));
            self.emit(format!(r#"<polygon points="{p}" fill="{f}"{o}/>"#));
        }
        Ok(())
    }

    fn draw_text<T: BackendTextStyle>(&mut self, text: &str, style: &T, pos: BackendCoord) -> Result<(), Error> {
        let c = style.color();
        if c.alpha == 0.0 {
            return Ok(());
        }
        let anchor = match style.anchor().h_pos {
            HPos::Left => "start",
            HPos::Right => "end",
            HPos::Center => "middle",
        };
        let dy = match style.anchor().v_pos {
            VPos::Top => "0.76em",
            VPos::Center => "0.5ex",
            VPos::Bottom => "-0.5ex",
        };
        let (x, y) = (n(pos.0.into()), n(pos.1.into()));
        let rotate = match style.transform() {
            FontTransform::Rotate90 => format!(r#" transform="rotate(90, {x}, {y})""#),
            FontTransform::Rotate180 => format!(r#" transform="rotate(180, {x}, {y})""#),
            FontTransform::Rotate270 => format!(r#" transform="rotate(270, {x}, {y})""#),
            _ => String::new(),
        };
        let (size, f, o, t) = (n(super::raster::drawn_em(style.size())), colour(c), opacity(c), escape(text));
        let family = escape(style.family().as_str());
        self.emit(format!(r#"<text x="{x}" y="{y}" dy="{dy}" text-anchor="{anchor}" font-family="{family}" font-size="{size}" fill="{f}"{o}{rotate}>{t}</text>"#
        ));
        Ok(())
    }

    fn estimate_text_size<T: BackendTextStyle>(&self, text: &str, style: &T) -> Result<(u32, u32), Error> {
        let ((x0, y0), (x1, y1)) = super::raster::text_box(text, style.size());
        Ok(((x1 - x0) as u32, (y1 - y0) as u32))
    }

    fn blit_bitmap(&mut self, _: BackendCoord, _: (u32, u32), _: &[u8]) -> Result<(), Error> {
        Ok(())
    }
}
