//! Drawing a surface in a 3-D view (z up), e.g. the kinematic surface of Jüttler's Fig. 5b
//! ([`crate::figures`]), from two families of iso-parameter curves: the curves at `v` fixed
//! (sampled along `t`; thick, blue) and at `t` fixed (sampled along `v`; thin, grey). The
//! surface is cut into quads between neighbouring `v` curves, [`STEP`] samples long along `t`,
//! each shaded by the angle between its normal and a light, and painted from the farthest to
//! the nearest with the curve pieces on its edges (painter's algorithm), so a nearer part of
//! the surface hides the farther one and its curves. Every quad is one SVG `<polygon>`, every
//! curve piece one `<polyline>`.

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

/// The samples along `t` per quad.
pub(crate) const STEP: usize = 5;

/// The direction of the light (towards it), in world coordinates.
const LIGHT: [f64; 3] = [-0.4, -0.6, 0.7];

/// The shaded surface of the curves `families[0]` (`v` fixed, each sampled at the same `t`)
/// and `families[1]` (`t` fixed at every `grid`-th sample of `t`, each sampled at the same
/// `v`, the `v` curves at every `grid`-th sample of `v`), titled `title` (800 x 640 pixels).
pub(crate) struct Wireframe<'a> {
    /// The two families of curves.
    pub families: [&'a [Vec<[f64; 3]>]; 2],
    /// The title.
    pub title: &'a str,
}

/// One quad of the surface: its corners and the curve pieces on its edges (with the family).
struct Quad {
    corners: [[f64; 3]; 4],
    pieces: Vec<(Vec<[f64; 3]>, usize)>,
}

/// The quads of `families` (see [`Wireframe`]): between `v` curves `j` and `j + 1`, samples
/// `i ..= i + STEP` along `t`; the `t` curve pieces between `v_j` and `v_{j+1}` on the edges
/// at the `t` of a `t` curve.
fn quads(families: [&[Vec<[f64; 3]>]; 2]) -> Vec<Quad> {
    let [iso_v, iso_t] = families;
    let (nv, nt) = (iso_v.len(), iso_v.first().map_or(0, Vec::len));
    let mt = iso_t.first().map_or(0, Vec::len);
    // the t curves sit every (nt - 1)/(k - 1) samples of t; the v curves every (mt - 1)/(nv - 1) of v
    let t_every = if iso_t.len() > 1 { (nt - 1) / (iso_t.len() - 1) } else { usize::MAX };
    let v_every = if nv > 1 { (mt - 1) / (nv - 1) } else { 0 };
    let mut out = Vec::new();
    for j in 0..nv.saturating_sub(1) {
        let mut i = 0;
        while i + 1 < nt {
            let e = (i + STEP).min(nt - 1);
            let corners = [iso_v[j][i], iso_v[j][e], iso_v[j + 1][e], iso_v[j + 1][i]];
            let mut pieces = vec![(iso_v[j][i..=e].to_vec(), 0), (iso_v[j + 1][i..=e].to_vec(), 0)];
            for edge in [i, e] {
                if t_every != usize::MAX && edge % t_every == 0 && v_every > 0 {
                    let k = edge / t_every;
                    pieces.push((iso_t[k][j * v_every..=(j + 1) * v_every].to_vec(), 1));
                }
            }
            out.push(Quad { corners, pieces });
            i = e;
        }
    }
    out
}

/// The grey-blue of a quad lit at `cos` (the cosine between its normal and the light).
fn shade(cos: f64) -> RGBColor {
    let k = 0.45 + 0.55 * cos.abs().min(1.0);
    RGBColor((170.0 * k) as u8, (195.0 * k) as u8, (230.0 * k) as u8)
}

/// The cosine between the normal of `q` (from its diagonals) and [`LIGHT`].
fn lit(q: &[[f64; 3]; 4]) -> f64 {
    let d1: [f64; 3] = std::array::from_fn(|i| q[2][i] - q[0][i]);
    let d2: [f64; 3] = std::array::from_fn(|i| q[3][i] - q[1][i]);
    let n = [d1[1] * d2[2] - d1[2] * d2[1], d1[2] * d2[0] - d1[0] * d2[2], d1[0] * d2[1] - d1[1] * d2[0]];
    let l = LIGHT.iter().map(|x| x * x).sum::<f64>().sqrt();
    let len = n.iter().map(|x| x * x).sum::<f64>().sqrt();
    if len == 0.0 { 1.0 } else { n.iter().zip(&LIGHT).map(|(a, b)| a * b).sum::<f64>() / (len * l) }
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
        let mut all = quads(self.families);
        let depth = |q: &Quad| {
            let c: [f64; 3] = std::array::from_fn(|i| q.corners.iter().map(|p| p[i]).sum::<f64>() / 4.0);
            chart.as_coord_spec().projected_depth(&c[0], &c[2], &c[1])
        };
        all.sort_by_key(|q| std::cmp::Reverse(depth(q)));
        for q in &all {
            let face =
                Polygon::new(q.corners.iter().map(axes3d::to).collect::<Vec<_>>(), shade(lit(&q.corners)).filled());
            chart.draw_series(std::iter::once(face)).map_err(draw_error)?;
            for (piece, family) in &q.pieces {
                let width = if *family == 0 { 2.0 } else { 1.0 };
                let style = FAMILIES[*family].stroke_width(px.u(width));
                chart
                    .draw_series(std::iter::once(PathElement::new(
                        piece.iter().map(axes3d::to).collect::<Vec<_>>(),
                        style,
                    )))
                    .map_err(draw_error)?;
            }
        }
        Ok(())
    }
}

/// The file bytes of the [`Wireframe`] of `families` titled `title` in `format`.
pub(crate) fn wireframe(families: [&[Vec<[f64; 3]>]; 2], title: &str, format: Format) -> Result<Vec<u8>, CliError> {
    encode(&Wireframe { families, title }, format)
}
