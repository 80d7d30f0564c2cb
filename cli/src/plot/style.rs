//! The look of `gam plot` and `gam figures`, in one place: the drawing scale (SVG coordinates
//! are drawn at [`SVG_SCALE`] times the pixel size, so curves are placed to a quarter pixel),
//! the palette of series colours, the frame-axis colours no series uses, and the marker that
//! asks a backend to dash a line.
//!
//! The palette: twelve colours, every two at least 40 apart in CIELAB (ΔE*ab, CIE 1976), and
//! at least 40 from the frame-axis colours, black, white and the greys of the axes, joins
//! and bodies. It was chosen greedily from a 16-level RGB grid of mid lightness (L* between 25
//! and 70), keeping the smallest distance to the colours already chosen largest; the test
//! `the_palette_is_distinct` below recomputes the distances.

use plotters::prelude::RGBColor;

/// SVG coordinates are drawn at this multiple of the picture's pixel size and written divided
/// by it (a quarter pixel); PNGs are drawn at scale 1.
pub(crate) const SVG_SCALE: f64 = 4.0;

/// Pixel lengths of a picture drawn at a scale: layout constants are written in pixels of
/// the final picture and multiplied here.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Px(pub f64);

impl Px {
    /// `n` pixels as drawing units.
    pub fn i(self, n: f64) -> i32 {
        (n * self.0).round() as i32
    }

    /// `n` pixels as drawing units (unsigned: widths, radii, label areas).
    pub fn u(self, n: f64) -> u32 {
        (n * self.0).round().max(1.0) as u32
    }

    /// A font size of `size` pixels in drawing units.
    pub fn font(self, size: f64) -> f64 {
        size * self.0
    }
}

/// `size` (pixels), shrunk so that `text` is at most `width` pixels wide (titles shrink rather
/// than clip).
pub(crate) fn fitted(text: &str, size: f64, width: f64) -> f64 {
    let w = f64::from(super::raster::text_box(text, size).1.0);
    if w > width { size * width / w } else { size }
}

/// The series colours, in the order specs (or body points) take them.
pub(crate) const PALETTE: [RGBColor; 12] = [
    RGBColor(0, 136, 255),
    RGBColor(204, 153, 0),
    RGBColor(136, 17, 51),
    RGBColor(0, 187, 153),
    RGBColor(102, 34, 136),
    RGBColor(255, 68, 187),
    RGBColor(34, 68, 0),
    RGBColor(238, 136, 102),
    RGBColor(0, 68, 119),
    RGBColor(238, 0, 255),
    RGBColor(204, 136, 204),
    RGBColor(0, 170, 221),
];

/// Series colour `i` (the palette repeats from the thirteenth on).
pub(crate) fn colour(i: usize) -> RGBColor {
    PALETTE[i % PALETTE.len()]
}

/// The colours of a body frame's axes `e1, e2, e3` (red, green, blue; no series uses them).
pub(crate) const AXIS_COLOURS: [RGBColor; 3] = [RGBColor(220, 0, 0), RGBColor(0, 150, 0), RGBColor(0, 0, 220)];

/// The grey of the joins on the speed panel.
pub(crate) const JOIN: RGBColor = RGBColor(128, 128, 128);

/// The colour of the angular speed (near black) when one spec has several body points (the angular speed
/// belongs to no body point).
pub(crate) const ANGULAR: RGBColor = RGBColor(20, 20, 20);

/// The opacity that asks a backend to draw a line dashed ([`super::svg::Svg`] writes a
/// `stroke-dasharray`, [`super::raster`] cuts the line into dashes): any other opacity is
/// drawn as given. Use [`dashed`].
pub(crate) const DASH_OPACITY: f64 = 0.999;

/// The style of a dashed line of colour `c` and width `w` (drawing units).
pub(crate) fn dashed(c: RGBColor, w: u32) -> plotters::style::ShapeStyle {
    use plotters::style::Color;
    c.mix(DASH_OPACITY).stroke_width(w)
}

/// The dash pattern: dash and gap lengths in units of the line width plus one.
pub(crate) const DASH_PATTERN: [f64; 2] = [4.0, 2.5];

#[cfg(test)]
mod tests {
    use super::{ANGULAR, AXIS_COLOURS, JOIN, PALETTE};
    use plotters::prelude::RGBColor;

    /// CIELAB of an sRGB colour (D65), from the sRGB and CIE 1976 definitions.
    fn lab(c: RGBColor) -> [f64; 3] {
        let lin = |u: u8| {
            let u = f64::from(u) / 255.0;
            if u > 0.04045 { ((u + 0.055) / 1.055).powf(2.4) } else { u / 12.92 }
        };
        let (r, g, b) = (lin(c.0), lin(c.1), lin(c.2));
        let x = (0.4124 * r + 0.3576 * g + 0.1805 * b) / 0.95047;
        let y = 0.2126 * r + 0.7152 * g + 0.0722 * b;
        let z = (0.0193 * r + 0.1192 * g + 0.9505 * b) / 1.08883;
        let f = |t: f64| if t > 0.008856 { t.cbrt() } else { 7.787 * t + 16.0 / 116.0 };
        [116.0 * f(y) - 16.0, 500.0 * (f(x) - f(y)), 200.0 * (f(y) - f(z))]
    }

    fn delta_e(a: RGBColor, b: RGBColor) -> f64 {
        let (a, b) = (lab(a), lab(b));
        ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2) + (a[2] - b[2]).powi(2)).sqrt()
    }

    #[test]
    fn the_palette_is_distinct() {
        // The textbook values: white is L* = 100, black 0, sRGB red about (53.2, 80.1, 67.2).
        let white = lab(RGBColor(255, 255, 255));
        assert!((white[0] - 100.0).abs() < 0.01 && white[1].abs() < 0.05 && white[2].abs() < 0.05);
        let red = lab(RGBColor(255, 0, 0));
        assert!((red[0] - 53.24).abs() < 0.05 && (red[1] - 80.09).abs() < 0.1 && (red[2] - 67.20).abs() < 0.1);
        for (i, a) in PALETTE.iter().enumerate() {
            for b in &PALETTE[..i] {
                assert!(delta_e(*a, *b) >= 40.0, "{a:?} and {b:?} are {} apart", delta_e(*a, *b));
            }
            let others = AXIS_COLOURS.iter().chain(&[JOIN, ANGULAR, RGBColor(0, 0, 0), RGBColor(255, 255, 255)]);
            for b in others {
                assert!(delta_e(*a, *b) >= 40.0, "{a:?} is {} from {b:?}", delta_e(*a, *b));
            }
        }
    }
}
