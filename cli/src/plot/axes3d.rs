//! The 3-D view of `gam plot` and `gam figures` (z up): a chart whose three axes have the same
//! scale (the box drawn is proportional to the data's extents, so a unit cube looks like a
//! cube), the box's edges, a floor grid, and the axes drawn here rather than by plotters: each
//! on the box edge nearest the viewer's bottom left, with its name (`x`, `y`, `z`) and tick
//! labels set outward from the box, a label left out where it would overlap one already set.
//! The box, grid and axes are drawn in black (translucent for the box and grid), like the
//! axes and grid of the 2-D panels, so they are never taken for data.

use super::raster::text_box;
use super::style::Px;
use crate::error::CliError;
use plotters::coord::Shift;
use plotters::coord::ranged3d::Cartesian3d;
use plotters::coord::types::RangedCoordf64;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

/// A box in world coordinates `x, y, z`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Bounds {
    /// The smallest coordinates.
    pub lo: [f64; 3],
    /// The largest coordinates.
    pub hi: [f64; 3],
}

impl Bounds {
    /// The box of `points`, each range padded by 5% of the largest extent (so all three are
    /// padded alike), a degenerate range widened to a tenth of the largest.
    pub fn of<'p>(points: impl Iterator<Item = &'p [f64; 3]>) -> Bounds {
        let (mut lo, mut hi) = ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]);
        for p in points.filter(|p| p.iter().all(|v| v.is_finite())) {
            for k in 0..3 {
                lo[k] = lo[k].min(p[k]);
                hi[k] = hi[k].max(p[k]);
            }
        }
        if !lo[0].is_finite() {
            return Bounds { lo: [0.0; 3], hi: [1.0; 3] };
        }
        let largest = (0..3).map(|k| hi[k] - lo[k]).fold(0.0, f64::max);
        let largest = if largest > 0.0 { largest } else { 1.0 };
        for k in 0..3 {
            let short = (0.1 * largest - (hi[k] - lo[k])).max(0.0) / 2.0;
            lo[k] -= short + 0.05 * largest;
            hi[k] += short + 0.05 * largest;
        }
        Bounds { lo, hi }
    }

    /// The extents.
    pub fn span(&self) -> [f64; 3] {
        std::array::from_fn(|k| self.hi[k] - self.lo[k])
    }
}

/// A 3-D chart (plotters' axes: `x`, then `z` up, then `y`).
pub(crate) type Chart3<'a, DB> = ChartContext<'a, DB, Cartesian3d<RangedCoordf64, RangedCoordf64, RangedCoordf64>>;

/// World point `p` in the chart's coordinates.
pub(crate) fn to(p: &[f64; 3]) -> (f64, f64, f64) {
    (p[0], p[2], p[1])
}

fn draw_error<E: std::fmt::Display>(e: E) -> CliError {
    CliError::math(format!("cannot draw the 3-D view: {e}"))
}

/// The pixel lengths of the box's `x, z, y` edges (plotters' order): proportional to the
/// extents, the largest `size`.
pub(crate) fn edge_pixels(b: &Bounds, size: i32) -> (i32, i32, i32) {
    let s = b.span();
    let largest = s.iter().copied().fold(0.0, f64::max);
    let len = |v: f64| ((f64::from(size) * v / largest).round() as i32).max(1);
    (len(s[0]), len(s[2]), len(s[1]))
}

/// The view's pitch (radians above the horizon) and yaw.
const PITCH: f64 = 0.35;
const YAW: f64 = 0.55;

/// A 3-D chart of `b` on `area` with equal scales on the three axes, the box as large as fits.
pub(crate) fn chart<'a, DB: DrawingBackend>(
    area: &'a DrawingArea<DB, Shift>,
    b: &Bounds,
    px: Px,
) -> Result<Chart3<'a, DB>, CliError> {
    let mut chart = ChartBuilder::on(area)
        .margin(px.u(36.0))
        .build_cartesian_3d(b.lo[0]..b.hi[0], b.lo[2]..b.hi[2], b.lo[1]..b.hi[1])
        .map_err(draw_error)?;
    let (w, h) = chart.plotting_area().dim_in_pixel();
    let size = (f64::from(w.min(h)) * 0.7) as i32;
    chart.set_3d_pixel_range(edge_pixels(b, size));
    let view = |scale: f64| {
        move |mut pb: plotters::coord::ranged3d::ProjectionMatrixBuilder| {
            (pb.pitch, pb.yaw, pb.scale) = (PITCH, YAW, scale);
            pb.into_matrix()
        }
    };
    chart.with_projection(view(1.0));
    // The projected box at scale 1, then the scale that makes it fill 92% of the area.
    let corners: Vec<_> = (0..8).map(|i| chart.plotting_area().map_coordinate(&to(&corner(b, i)))).collect();
    let extent = |k: fn(&(i32, i32)) -> i32| {
        let v = corners.iter().map(k);
        f64::from(v.clone().max().unwrap_or(1) - v.min().unwrap_or(0)).max(1.0)
    };
    let scale = (0.92 * f64::from(w) / extent(|p| p.0)).min(0.92 * f64::from(h) / extent(|p| p.1));
    chart.with_projection(view(scale));
    Ok(chart)
}

/// About `n` round tick values in `[lo, hi]` and the step between them.
pub(crate) fn ticks(lo: f64, hi: f64, n: usize) -> (Vec<f64>, f64) {
    let raw = (hi - lo) / n as f64;
    if !(raw > 0.0 && raw.is_finite()) {
        return (vec![], 1.0);
    }
    let p = 10f64.powf(raw.log10().floor());
    let step = [1.0, 2.0, 5.0, 10.0].iter().map(|m| m * p).find(|s| *s >= raw).unwrap_or(10.0 * p);
    let first = (lo / step).ceil() as i64;
    let last = (hi / step).floor() as i64;
    ((first..=last).map(|i| i as f64 * step).collect(), step)
}

/// `v` printed with as many decimals as `step` needs.
pub(crate) fn tick_text(v: f64, step: f64) -> String {
    let decimals = (-step.log10().floor()).max(0.0) as usize;
    let s = format!("{v:.decimals$}");
    if s.trim_start_matches('-').chars().all(|c| c == '0' || c == '.') { format!("{:.decimals$}", 0.0) } else { s }
}

/// A text box in pixels `(x0, y0, x1, y1)`.
type TextBox = (f64, f64, f64, f64);

fn overlaps(a: &TextBox, b: &TextBox) -> bool {
    a.0 < b.2 + 2.0 && b.0 < a.2 + 2.0 && a.1 < b.3 + 2.0 && b.1 < a.3 + 2.0
}

/// The anchor of a label set in direction `d` from its point, and its box at pixel `(x, y)`.
fn placed(text: &str, size: f64, (x, y): (f64, f64), d: (f64, f64)) -> (Pos, TextBox) {
    let ((_, y0), (w, y1)) = text_box(text, size);
    let (w, h) = (f64::from(w), f64::from(y1 - y0));
    let (pos, x0, top) = if d.0.abs() > d.1.abs() {
        if d.0 > 0.0 {
            (Pos::new(HPos::Left, VPos::Center), x, y - h / 2.0)
        } else {
            (Pos::new(HPos::Right, VPos::Center), x - w, y - h / 2.0)
        }
    } else if d.1 > 0.0 {
        (Pos::new(HPos::Center, VPos::Top), x - w / 2.0, y)
    } else {
        (Pos::new(HPos::Center, VPos::Bottom), x - w / 2.0, y - h)
    };
    (pos, (x0, top, x0 + w, top + h))
}

/// The box's corner `i` (bit `k` of `i` set: the high end of axis `k`).
fn corner(b: &Bounds, i: usize) -> [f64; 3] {
    std::array::from_fn(|k| if i >> k & 1 == 1 { b.hi[k] } else { b.lo[k] })
}

/// Draws the box edges, the floor grid and the labelled axes of `b` on `chart`, built on
/// `panel` (the labels are drawn on `panel`, which holds the chart's margins: plotters would
/// push a text outside the plotting area back inside it).
pub(crate) fn draw_axes<DB: DrawingBackend>(
    chart: &mut Chart3<'_, DB>,
    panel: &DrawingArea<DB, Shift>,
    b: &Bounds,
    px: Px,
) -> Result<(), CliError> {
    let area = chart.plotting_area().clone();
    let base = panel.get_base_pixel();
    let (pw, ph) = panel.dim_in_pixel();
    let within = |t: &TextBox| t.0 >= 0.0 && t.1 >= 0.0 && t.2 <= f64::from(pw) / px.0 && t.3 <= f64::from(ph) / px.0;
    let screen = |p: &[f64; 3]| {
        let (x, y) = area.map_coordinate(&to(p));
        (f64::from(x - base.0) / px.0, f64::from(y - base.1) / px.0)
    };
    let centre = {
        let all: Vec<_> = (0..8).map(|i| screen(&corner(b, i))).collect();
        (all.iter().map(|p| p.0).sum::<f64>() / 8.0, all.iter().map(|p| p.1).sum::<f64>() / 8.0)
    };
    // The floor grid and the box's edges.
    let grid = BLACK.mix(0.12).stroke_width(px.u(1.0));
    let mut lines: Vec<[[f64; 3]; 2]> = Vec::new();
    for k in 0..2 {
        for v in ticks(b.lo[k], b.hi[k], 6).0 {
            let (mut a, mut e) = (b.lo, b.lo);
            a[k] = v;
            e[k] = v;
            e[1 - k] = b.hi[1 - k];
            lines.push([a, e]);
        }
    }
    chart.draw_series(lines.iter().map(|[a, e]| PathElement::new(vec![to(a), to(e)], grid))).map_err(draw_error)?;
    let edge = BLACK.mix(0.35).stroke_width(px.u(1.0));
    let mut edges = Vec::new();
    for i in 0..8 {
        for k in 0..3 {
            if i >> k & 1 == 0 {
                edges.push([corner(b, i), corner(b, i | 1 << k)]);
            }
        }
    }
    chart.draw_series(edges.iter().map(|[a, e]| PathElement::new(vec![to(a), to(e)], edge))).map_err(draw_error)?;
    // Each axis on the edge lowest on the screen (x, y) or leftmost (z).
    let axis_edge = |k: usize| {
        let parallel = edges.iter().filter(|[a, e]| (0..3).all(|j| (j == k) != (a[j] == e[j])));
        let key = |[a, e]: &&[[f64; 3]; 2]| {
            let (pa, pe) = (screen(a), screen(e));
            if k == 2 { -(pa.0 + pe.0) } else { pa.1 + pe.1 }
        };
        *parallel.max_by(|p, q| key(p).total_cmp(&key(q))).expect("four parallel edges")
    };
    let (size, name_size) = (px.font(12.0), px.font(15.0));
    let mut taken: Vec<TextBox> = Vec::new();
    let mut texts: Vec<(String, (f64, f64), Pos, f64)> = Vec::new();
    let axes: Vec<_> = (0..3).map(axis_edge).collect();
    let outward = |p: (f64, f64)| {
        let d = (p.0 - centre.0, p.1 - centre.1);
        let l = d.0.hypot(d.1).max(1e-9);
        (d.0 / l, d.1 / l)
    };
    let black = BLACK.stroke_width(px.u(1.0));
    for (k, [a, e]) in axes.iter().enumerate() {
        chart.draw_series(std::iter::once(PathElement::new(vec![to(a), to(e)], black))).map_err(draw_error)?;
        let mid: [f64; 3] = std::array::from_fn(|j| (a[j] + e[j]) / 2.0);
        let d = outward(screen(&mid));
        let m = screen(&mid);
        let at = (m.0 + 34.0 * d.0, m.1 + 34.0 * d.1);
        let name = ["x", "y", "z"][k];
        let (pos, bx) = placed(name, name_size / px.0, at, d);
        taken.push(bx);
        texts.push((name.to_string(), at, pos, name_size));
    }
    for (k, [a, _]) in axes.iter().enumerate() {
        let (values, step) = ticks(b.lo[k], b.hi[k], 6);
        for v in values {
            let mut p = *a;
            p[k] = v;
            let s = screen(&p);
            let d = outward(s);
            let tick = [(s.0, s.1), (s.0 + 5.0 * d.0, s.1 + 5.0 * d.1)].map(|(x, y)| (px.i(x), px.i(y)));
            let text = tick_text(v, step);
            let at = (s.0 + 8.0 * d.0, s.1 + 8.0 * d.1);
            let (pos, bx) = placed(&text, size / px.0, at, d);
            panel.draw(&PathElement::new(tick.to_vec(), black)).map_err(draw_error)?;
            if within(&bx) && taken.iter().all(|t| !overlaps(t, &bx)) {
                taken.push(bx);
                texts.push((text, at, pos, size));
            }
        }
    }
    for (text, (x, y), pos, size) in texts {
        let style = ("sans-serif", size).into_font().color(&BLACK).pos(pos);
        panel.draw(&Text::new(text, (px.i(x), px.i(y)), style)).map_err(draw_error)?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::{Bounds, edge_pixels, tick_text, ticks};

    #[test]
    fn the_box_keeps_the_data_proportions() {
        // A 2 x 1 x 0.5 slab: padded by 5% of 2 on every side, so its box edges are in the
        // ratio 2.2 : 1.2 : 0.7 (x : y : z), the largest drawn at the full size.
        let b = Bounds::of([[0.0, 0.0, 0.0], [2.0, 1.0, 0.5]].iter());
        let s = b.span();
        assert!((s[0] - 2.2).abs() < 1e-12 && (s[1] - 1.2).abs() < 1e-12 && (s[2] - 0.7).abs() < 1e-12, "{s:?}");
        assert_eq!(edge_pixels(&b, 440), (440, 140, 240));
        // A flat path still gets a box a tenth as high as it is wide (plus the padding).
        let flat = Bounds::of([[0.0, 0.0, 1.0], [10.0, 4.0, 1.0]].iter());
        assert!((flat.span()[2] - 2.0).abs() < 1e-12, "{:?}", flat.span());
    }

    #[test]
    fn the_view_looks_down_and_depth_grows_away_from_the_viewer() {
        // The painter's algorithm of Jüttler's Fig. 5b (surface.rs) draws the largest
        // projected depth first, taking plotters' depth as the distance from the screen. In our
        // view (pitched 0.35 rad above the horizon) a point above another is nearer the viewer:
        // its depth must be smaller, and it must be drawn higher on the screen.
        use super::{Bounds, chart, to};
        use crate::plot::style::Px;
        use crate::plot::svg::Svg;
        use plotters::prelude::IntoDrawingArea;
        let mut out = String::new();
        let area = Svg::new(&mut out, (400, 400), None).into_drawing_area();
        let b = Bounds::of([[0.0, 0.0, 0.0], [1.0, 1.0, 1.0]].iter());
        let c = chart(&area, &b, Px(1.0)).expect("a chart");
        let depth = |p: [f64; 3]| {
            let (x, y, z) = to(&p);
            c.as_coord_spec().projected_depth(&x, &y, &z)
        };
        let screen_y = |p: [f64; 3]| c.plotting_area().map_coordinate(&to(&p)).1;
        for (x, y) in [(0.0, 0.0), (1.0, 0.0), (0.0, 1.0), (0.5, 0.5)] {
            let (low, high) = ([x, y, 0.0], [x, y, 1.0]);
            assert!(depth(high) < depth(low), "({x}, {y}): {} vs {}", depth(high), depth(low));
            assert!(screen_y(high) < screen_y(low));
        }
    }

    #[test]
    fn ticks_are_round_and_inside() {
        assert_eq!(ticks(-0.3, 2.3, 5), (vec![0.0, 1.0, 2.0], 1.0));
        assert_eq!(ticks(-0.3, 2.3, 8), (vec![0.0, 0.5, 1.0, 1.5, 2.0], 0.5));
        assert_eq!(ticks(0.0, 14.0, 5).0, vec![0.0, 5.0, 10.0]);
        assert_eq!(tick_text(1.5, 0.5), "1.5");
        assert_eq!(tick_text(10.0, 5.0), "10");
        assert_eq!(tick_text(-0.0, 0.2), "0.0");
        assert!(ticks(1.0, 1.0, 5).0.is_empty());
    }
}
