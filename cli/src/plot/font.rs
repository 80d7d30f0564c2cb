//! The font of `gam plot`'s PNG output ([`super::raster`]): DejaVu Sans (bundled in the
//! binary by the `dejavu` crate, so a PNG needs no font on the machine and has the same pixels
//! on every machine), rasterised by `ab_glyph` into coverage values (anti-aliased text).
//!
//! The glyphs are drawn at the em the SVG gives the text ([`super::raster::drawn_em`]) with
//! their own advances and kerning. A text wider than the box plotters' layout gives it
//! ([`super::raster::text_box`], `0.7 em` of its estimate per character; a run of capitals such
//! as `WWW`) is narrowed to the box's width, so the figure lays out the same in both formats
//! and no text leaves its box.

use ab_glyph::{Font, FontRef, GlyphId, PxScale, ScaleFont, point};
use std::sync::OnceLock;

/// DejaVu Sans' x-height in em (1120 of 2048 units): the `ex` of the SVG's baseline offsets.
pub(crate) const EX: f64 = 0.547;

/// DejaVu Sans, parsed once.
fn font() -> Result<&'static FontRef<'static>, ab_glyph::InvalidFont> {
    static FONT: OnceLock<Result<FontRef<'static>, ab_glyph::InvalidFont>> = OnceLock::new();
    FONT.get_or_init(|| FontRef::try_from_slice(dejavu::sans::regular())).as_ref().map_err(|e| *e)
}

/// A pixel `(x, y)` of a drawn text and its coverage in `(0, 1]`.
pub(crate) type Coverage = (i32, i32, f32);

/// The pixels of `text` drawn at `em` pixels to the em, relative to the start of its baseline
/// (y down), each with its coverage in `(0, 1]`, sorted by row then column, each pixel once;
/// narrowed horizontally to at most `max_width` pixels. Returns the pixels and the text's
/// width (its advances, after narrowing).
pub(crate) fn coverage(text: &str, em: f64, max_width: f64) -> Result<(Vec<Coverage>, f64), ab_glyph::InvalidFont> {
    let font = font()?;
    let upem = f64::from(font.units_per_em().unwrap_or(2048.0));
    // ab_glyph's scale is the pixel height of ascent - descent, not of the em.
    let height = em * f64::from(font.height_unscaled()) / upem;
    let scaled = font.as_scaled(PxScale::from(height as f32));
    let ids: Vec<GlyphId> = text.chars().map(|c| scaled.glyph_id(c)).collect();
    let advances = |scaled: &ab_glyph::PxScaleFont<&FontRef<'static>>| {
        let mut x = 0.0f32;
        let mut at = Vec::with_capacity(ids.len());
        for (i, id) in ids.iter().enumerate() {
            if i > 0 {
                x += scaled.kern(ids[i - 1], *id);
            }
            at.push(x);
            x += scaled.h_advance(*id);
        }
        (at, f64::from(x))
    };
    let (_, natural) = advances(&scaled);
    let narrow = if natural > max_width && natural > 0.0 { max_width / natural } else { 1.0 };
    let scaled = font.as_scaled(PxScale { x: (height * narrow) as f32, y: height as f32 });
    let (at, width) = advances(&scaled);
    let mut px = Vec::new();
    for (id, x) in ids.iter().zip(at) {
        let glyph = id.with_scale_and_position(scaled.scale(), point(x, 0.0));
        if let Some(outline) = font.outline_glyph(glyph) {
            let b = outline.px_bounds();
            let (x0, y0) = (b.min.x as i32, b.min.y as i32);
            outline.draw(|gx, gy, c| {
                if c > 0.0 {
                    px.push((x0 + gx as i32, y0 + gy as i32, c));
                }
            });
        }
    }
    // Glyphs that touch share pixels: add their coverage, at most full.
    px.sort_by_key(|&(x, y, _)| (y, x));
    let mut out: Vec<Coverage> = Vec::with_capacity(px.len());
    for (x, y, c) in px {
        match out.last_mut() {
            Some(last) if (last.0, last.1) == (x, y) => last.2 = (last.2 + c).min(1.0),
            _ => out.push((x, y, c.min(1.0))),
        }
    }
    Ok((out, width))
}

#[cfg(test)]
mod tests {
    use super::coverage;

    #[test]
    fn glyphs_are_proportional_and_anti_aliased() {
        let em = 20.0;
        let (_, narrow) = coverage("iiii", em, 1e9).expect("the bundled font");
        let (_, wide) = coverage("WWWW", em, 1e9).expect("the bundled font");
        // DejaVu Sans' advances: i 569, W 2025 units of 2048 to the em (the font's hmtx).
        assert!((narrow - 4.0 * em * 569.0 / 2048.0).abs() < 0.01, "{narrow}");
        assert!((wide - 4.0 * em * 2025.0 / 2048.0).abs() < 0.01, "{wide}");
        let (px, _) = coverage("Ag", em, 1e9).expect("the bundled font");
        assert!(px.iter().any(|p| p.2 < 0.9) && px.iter().any(|p| p.2 > 0.99), "partial and full coverage");
        assert!(px.windows(2).all(|w| (w[0].1, w[0].0) < (w[1].1, w[1].0)), "each pixel once, in order");
        // The capital stands on the baseline, below which only g's descender goes (to 0.2 em,
        // inside the box's 0.24 em).
        let bottom = px.iter().map(|p| p.1).max().expect("pixels");
        assert!((3..=4).contains(&bottom), "{bottom}");
    }

    #[test]
    fn a_text_wider_than_its_box_is_narrowed_to_it() {
        let (px, width) = coverage("WWWW", 20.0, 40.0).expect("the bundled font");
        assert!((width - 40.0).abs() < 0.01, "{width}");
        assert!(px.iter().all(|p| (0..=40).contains(&p.0)), "inside the box");
    }

    #[test]
    fn characters_beyond_ascii_have_glyphs() {
        // Greek and the parallel sign of the papers' captions: not the empty notdef glyph.
        for text in ["λ", "γ", "ω", "∥"] {
            let (px, width) = coverage(text, 20.0, 1e9).expect("the bundled font");
            assert!(px.len() > 10 && width > 5.0, "{text}: {} pixels, width {width}", px.len());
        }
    }
}
