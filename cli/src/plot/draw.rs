//! Drawing the [`Series`] of `gam plot` into an SVG string with `plotters`: the speed panel
//! (every body point's `|v|` as a thick line and each series' `|Ω|` as a thin one, the
//! joins as vertical grey lines) and the path panel (the paths of the body points projected on
//! a coordinate plane, or a 3-D view; the key points as dots; the body frames as red, green,
//! blue segments along the moved `e1, e2, e3`).
//!
//! Every data line is one SVG `<polyline>` and every legend mark a `<rect>`, so a test can
//! count the series of a figure (the polylines not in black, which are the axes): per series, one speed line and one path per body point, one
//! angular speed line, one line per join and three per frame (twelve with `--body cube`).
//! Filled faces (the L-shaped block's two L faces, the filled face markings of
//! [`Series::marks`]) are SVG `<polygon>`s; each mark's outline is one more polyline, a dashed
//! `arc` one per dash.

use super::data::{Mark, Series, moved};
use super::raster::{Format, Picture, encode};
use crate::error::CliError;
use crate::scalar::format_f64;
use plotters::coord::Shift;
use plotters::prelude::*;

/// How the moved body is drawn at the frame parameters.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum Body {
    /// Its coordinate frame: `e1` red, `e2` green, `e3` blue, a tenth of the paths' extent.
    Frames,
    /// The unit cube `[0, 1]³` (Jüttler's figures), its 12 edges in grey.
    Cube,
    /// The L-shaped block of the main paper's Figs. 6-10, in grey: an L of legs 2 (along `e2`)
    /// and 1 (along `e3`), 0.5 wide, 0.5 deep (along `e1`), its corner at the body origin.
    LBlock,
}

/// The L-shaped block's profile in the body's `e2 e3` plane (counter-clockwise, the corner of
/// the L at the origin), extruded along `e1` from `x = 0` to `x = 0.5` (so the L is seen face
/// on in the `y-z` view of a motion turning about `e1`, as in Figs. 8 and 9).
pub(crate) const L_BLOCK: [[f64; 2]; 6] = [[0.0, 0.0], [2.0, 0.0], [2.0, 0.5], [0.5, 0.5], [0.5, 1.0], [0.0, 1.0]];

/// The L-shaped block's depth along `e1`.
const L_DEPTH: f64 = 0.5;

/// The L-shaped block moved by frame `f`: the 6 corners of its face `x = 0` then the 6 of its
/// face `x = 0.5`. A rigid pose is affine, so body point `x` goes to `o + Σ x_k (a_k - o)`
/// with `o` the moved origin and `a_k` the moved `e_k`.
pub(crate) fn l_block(f: &super::data::Frame) -> [[f64; 3]; 12] {
    std::array::from_fn(|c| {
        let [y, z] = L_BLOCK[c % 6];
        moved(f, [if c < 6 { 0.0 } else { L_DEPTH }, y, z])
    })
}

/// The shading of the L-shaped block's two L faces (the paper's shaded blocks).
const SHADE: RGBColor = RGBColor(190, 190, 190);

/// The faces of `body` at frame `f` drawn filled in [`SHADE`]: the L-shaped block's two L
/// faces (each one SVG `<polygon>`); none for the frames and the cube.
fn body_faces(f: &super::data::Frame, body: Body) -> Vec<Vec<[f64; 3]>> {
    match body {
        Body::LBlock => {
            let b = l_block(f);
            vec![b[..6].to_vec(), b[6..].to_vec()]
        }
        Body::Frames | Body::Cube => vec![],
    }
}

/// The colour of the face markings and moved body curves.
const MARK: RGBColor = RGBColor(40, 40, 40);

/// The colour of a control pose's path (dashed).
const ARC: RGBColor = RGBColor(100, 100, 100);

/// Points per dash and per gap of a dashed [`Mark`] (`arc`): dash `i` is the polyline through
/// points `3i ..= 3i + 2`.
pub(crate) const DASH: usize = 3;

/// The filled polygons and the polylines (with their colours) drawing `m`.
#[allow(clippy::type_complexity)]
fn mark_shapes(m: &Mark) -> (Option<Vec<[f64; 3]>>, Vec<(Vec<[f64; 3]>, RGBColor, u32)>) {
    match m.kind {
        "square" | "triangle" => (Some(m.points.clone()), vec![(m.points.clone(), MARK, 1)]),
        "arc" => {
            let dashes = (0..m.points.len().saturating_sub(1) / DASH)
                .map(|i| (m.points[DASH * i..(DASH * i + DASH).min(m.points.len())].to_vec(), ARC, 1));
            (None, dashes.collect())
        }
        "curve" => (None, vec![(m.points.clone(), MARK, 2)]),
        _ => (None, vec![(m.points.clone(), MARK, 1)]),
    }
}

/// Draws the shaded faces of `body` at the frames of `s` and the marks of `s` on a chart,
/// `to` mapping a world point to the chart's coordinates.
fn draw_extras<DB: DrawingBackend, CT: CoordTranslate>(
    chart: &mut ChartContext<DB, CT>,
    s: &Series,
    body: Body,
    to: impl Fn(&[f64; 3]) -> CT::From,
) -> Result<(), CliError>
where
    CT::From: Clone + 'static,
{
    let shade =
        |ps: &Vec<[f64; 3]>, c: RGBColor| Polygon::new(ps.iter().map(&to).collect::<Vec<_>>(), c.mix(0.6).filled());
    let faces: Vec<_> = s.frames.iter().flat_map(|f| body_faces(f, body)).collect();
    chart.draw_series(faces.iter().map(|ps| shade(ps, SHADE))).map_err(draw_error)?;
    for m in &s.marks {
        let (fill, lines) = mark_shapes(m);
        chart.draw_series(fill.iter().map(|ps| shade(ps, MARK))).map_err(draw_error)?;
        let lines = lines
            .into_iter()
            .map(|(ps, c, w)| PathElement::new(ps.iter().map(&to).collect::<Vec<_>>(), c.stroke_width(w)));
        chart.draw_series(lines).map_err(draw_error)?;
    }
    Ok(())
}

/// The colour of the cube's edges.
const CUBE: RGBColor = RGBColor(90, 90, 90);

/// The 12 edges of the unit cube as pairs of corner indices `i + 2j + 4k`.
const EDGES: [(usize, usize); 12] =
    [(0, 1), (2, 3), (4, 5), (6, 7), (0, 2), (1, 3), (4, 6), (5, 7), (0, 4), (1, 5), (2, 6), (3, 7)];

/// The polylines drawing frame `f` as `body` (frame axes of length `l`). The L-shaped block is
/// three: the outlines of its two L faces and a zigzag to and fro along its six edges between them.
fn body_lines(f: &super::data::Frame, body: Body, l: f64) -> Vec<(Vec<[f64; 3]>, RGBColor)> {
    match body {
        Body::Frames => (0..3).map(|k| (vec![f.origin, tip(f, k, l)], AXIS_COLOURS[k])).collect(),
        Body::Cube => EDGES.iter().map(|(a, b)| (vec![f.cube[*a], f.cube[*b]], CUBE)).collect(),
        Body::LBlock => {
            let b = l_block(f);
            let outline = |o: usize| (0..=6).map(|c| b[o + c % 6]).collect();
            let zigzag = [0, 6, 7, 1, 2, 8, 9, 3, 4, 10, 11, 5].iter().map(|c| b[*c]).collect();
            vec![(outline(0), CUBE), (outline(6), CUBE), (zigzag, CUBE)]
        }
    }
}

/// The points the path panel must show: the paths, and the cubes when they are drawn.
fn shown_points(all: &[Series], body: Body) -> Vec<[f64; 3]> {
    let paths = all.iter().flat_map(|s| s.paths.iter().flatten().copied());
    let cubes = all.iter().flat_map(|s| s.frames.iter().flat_map(|f| f.cube)).filter(|_| body == Body::Cube);
    let blocks = all.iter().flat_map(|s| s.frames.iter().flat_map(l_block)).filter(|_| body == Body::LBlock);
    let marks = all.iter().flat_map(|s| s.marks.iter().flat_map(|m| m.points.iter().copied()));
    paths.chain(cubes).chain(blocks).chain(marks).collect()
}

/// The path panel's view: a projection on a coordinate plane or a 3-D view.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum View {
    /// The x-y plane.
    Xy,
    /// The x-z plane.
    Xz,
    /// The y-z plane.
    Yz,
    /// A 3-D view (z up).
    #[value(name = "3d")]
    ThreeD,
}

impl View {
    /// The two coordinates of a projection (None for 3-D).
    fn axes(self) -> Option<(usize, usize)> {
        match self {
            View::Xy => Some((0, 1)),
            View::Xz => Some((0, 2)),
            View::Yz => Some((1, 2)),
            View::ThreeD => None,
        }
    }
}

fn draw_error<E: std::fmt::Display>(e: E) -> CliError {
    CliError::math(format!("cannot draw the plot: {e}"))
}

/// `[lo, hi]` covering `values`, padded by 5% (and widened when all values are equal).
pub(crate) fn range(values: impl Iterator<Item = f64>) -> (f64, f64) {
    let (lo, hi) = values.fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), x| (l.min(x), h.max(x)));
    if !lo.is_finite() || !hi.is_finite() {
        return (0.0, 1.0);
    }
    let span = hi - lo;
    let pad = if span > 0.0 { 0.05 * span } else { 0.5 * lo.abs().max(1.0) };
    (lo - pad, hi + pad)
}

/// The colour of line `i`.
fn colour(i: usize) -> RGBColor {
    const C: [RGBColor; 10] = [
        RGBColor(31, 119, 180),
        RGBColor(214, 39, 40),
        RGBColor(44, 160, 44),
        RGBColor(148, 103, 189),
        RGBColor(255, 127, 14),
        RGBColor(140, 86, 75),
        RGBColor(227, 119, 194),
        RGBColor(23, 190, 207),
        RGBColor(188, 189, 34),
        RGBColor(255, 187, 120),
    ];
    C[i % C.len()]
}

/// The colour index of body point `j` of series `si`; `j = body_points.len()` is the
/// series' angular speed.
fn colour_of(all: &[Series], si: usize, j: usize) -> RGBColor {
    colour(all[..si].iter().map(|s| s.body_points.len() + 1).sum::<usize>() + j)
}

/// A legend mark (a `<rect>`, not counted as a series).
fn mark(c: RGBColor) -> impl Fn((i32, i32)) -> Rectangle<(i32, i32)> {
    move |(x, y)| Rectangle::new([(x, y - 2), (x + 20, y + 2)], c.filled())
}

/// The legend text of body point `j` of series `s` (short when the figure has one line).
fn point_label(all: &[Series], s: &Series, j: usize, what: &str) -> String {
    if all.len() == 1 && s.body_points.len() == 1 {
        return what.to_string();
    }
    let p = s.body_points[j].map(format_f64).join(", ");
    if all.len() == 1 { format!("{what} of [{p}]") } else { format!("{}: {what} of [{p}]", s.label) }
}

/// The frames' axis length: a tenth of the largest extent of the paths.
fn frame_scale(series: &[Series]) -> f64 {
    let pts = || series.iter().flat_map(|s| s.paths.iter().flatten());
    let extent = (0..3)
        .map(|k| {
            let (lo, hi) = range(pts().map(|p| p[k]));
            hi - lo
        })
        .fold(0.0, f64::max);
    0.1 * extent
}

/// The tip of axis `k` of a frame drawn with length `l`.
fn tip(f: &super::data::Frame, k: usize, l: f64) -> [f64; 3] {
    std::array::from_fn(|i| f.origin[i] + l * (f.axes[k][i] - f.origin[i]))
}

/// The colour of the join lines.
const JOIN: RGBColor = RGBColor(128, 128, 128);

const AXIS_COLOURS: [RGBColor; 3] = [RGBColor(220, 0, 0), RGBColor(0, 160, 0), RGBColor(0, 0, 220)];

/// The speed panel.
fn speeds<DB: DrawingBackend>(area: &DrawingArea<DB, Shift>, all: &[Series]) -> Result<(), CliError> {
    let (t_lo, t_hi) = range(all.iter().flat_map(|s| s.t.iter().copied()));
    let values = all.iter().flat_map(|s| s.speeds.iter().flatten().chain(&s.angular_speed).copied());
    let (_, hi) = range(values.chain(std::iter::once(0.0)));
    let mut chart = ChartBuilder::on(area)
        .caption("linear and angular speed", ("sans-serif", 18))
        .margin(15)
        .x_label_area_size(40)
        .y_label_area_size(60)
        .build_cartesian_2d(t_lo..t_hi, 0.0..hi)
        .map_err(draw_error)?;
    chart.configure_mesh().x_desc("t").y_desc("speed (per unit t)").draw().map_err(draw_error)?;
    for (si, s) in all.iter().enumerate() {
        for (j, v) in s.speeds.iter().enumerate() {
            let c = colour_of(all, si, j);
            let pts = s.t.iter().copied().zip(v.iter().copied());
            chart
                .draw_series(LineSeries::new(pts, c.stroke_width(2)))
                .map_err(draw_error)?
                .label(point_label(all, s, j, "linear speed |v|"))
                .legend(mark(c));
        }
        let c = colour_of(all, si, s.body_points.len());
        let label =
            if all.len() == 1 { "angular speed |Omega|".into() } else { format!("{}: angular speed |Omega|", s.label) };
        chart
            .draw_series(LineSeries::new(s.t.iter().copied().zip(s.angular_speed.iter().copied()), c.stroke_width(1)))
            .map_err(draw_error)?
            .label(label)
            .legend(mark(c));
        let joins = s.joins.iter().map(|t| PathElement::new(vec![(*t, 0.0), (*t, hi)], JOIN.stroke_width(1)));
        chart.draw_series(joins).map_err(draw_error)?;
    }
    chart
        .configure_series_labels()
        .background_style(WHITE.mix(0.8))
        .border_style(BLACK)
        .position(SeriesLabelPosition::UpperRight)
        .draw()
        .map_err(draw_error)
}

/// The path panel projected on the coordinates `(a, b)`.
fn paths_2d<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    all: &[Series],
    body: Body,
    a: usize,
    b: usize,
) -> Result<(), CliError> {
    let names = ["x", "y", "z"];
    let shown = shown_points(all, body);
    let pts = || shown.iter();
    let (a_lo, a_hi) = range(pts().map(|p| p[a]));
    let (b_lo, b_hi) = range(pts().map(|p| p[b]));
    let mut chart = ChartBuilder::on(area)
        .caption(format!("path of the body points ({}-{} projection)", names[a], names[b]), ("sans-serif", 18))
        .margin(15)
        .x_label_area_size(40)
        .y_label_area_size(60)
        .build_cartesian_2d(a_lo..a_hi, b_lo..b_hi)
        .map_err(draw_error)?;
    chart.configure_mesh().x_desc(names[a]).y_desc(names[b]).draw().map_err(draw_error)?;
    let l = frame_scale(all);
    for (si, s) in all.iter().enumerate() {
        for (j, path) in s.paths.iter().enumerate() {
            let c = colour_of(all, si, j);
            let series = chart.draw_series(LineSeries::new(path.iter().map(|p| (p[a], p[b])), c.stroke_width(2)));
            let series = series.map_err(draw_error)?;
            if all.len() > 1 && j == 0 {
                series.label(s.label.clone()).legend(mark(c));
            }
        }
        let dots = s.key_points.iter().flatten().map(|p| Circle::new((p[a], p[b]), 4, BLACK.filled()));
        chart.draw_series(dots).map_err(draw_error)?;
        for f in &s.frames {
            let lines = body_lines(f, body, l).into_iter();
            let lines = lines.map(|(ps, c)| {
                PathElement::new(ps.iter().map(|p| (p[a], p[b])).collect::<Vec<_>>(), c.stroke_width(2))
            });
            chart.draw_series(lines).map_err(draw_error)?;
        }
        draw_extras(&mut chart, s, body, |p| (p[a], p[b]))?;
    }
    if all.len() > 1 {
        let mut labels = chart.configure_series_labels();
        labels.background_style(WHITE.mix(0.8)).border_style(BLACK).draw().map_err(draw_error)?;
    }
    Ok(())
}

/// The path panel as a 3-D view (z up: plotters' vertical axis is its second).
fn paths_3d<DB: DrawingBackend>(area: &DrawingArea<DB, Shift>, all: &[Series], body: Body) -> Result<(), CliError> {
    let shown = shown_points(all, body);
    let pts = || shown.iter();
    let (x, y, z) = (range(pts().map(|p| p[0])), range(pts().map(|p| p[1])), range(pts().map(|p| p[2])));
    let mut chart = ChartBuilder::on(area)
        .caption("path of the body points (3-D view, z up)", ("sans-serif", 18))
        .margin(15)
        .build_cartesian_3d(x.0..x.1, z.0..z.1, y.0..y.1)
        .map_err(draw_error)?;
    chart.configure_axes().draw().map_err(draw_error)?;
    let to = |p: &[f64; 3]| (p[0], p[2], p[1]);
    let l = frame_scale(all);
    for (si, s) in all.iter().enumerate() {
        for (j, path) in s.paths.iter().enumerate() {
            let c = colour_of(all, si, j);
            let series = chart.draw_series(LineSeries::new(path.iter().map(to), c.stroke_width(2)));
            let series = series.map_err(draw_error)?;
            if all.len() > 1 && j == 0 {
                series.label(s.label.clone()).legend(mark(c));
            }
        }
        let dots = s.key_points.iter().flatten().map(|p| Circle::new(to(p), 4, BLACK.filled()));
        chart.draw_series(dots).map_err(draw_error)?;
        for f in &s.frames {
            let lines = body_lines(f, body, l).into_iter();
            let lines = lines.map(|(ps, c)| PathElement::new(ps.iter().map(to).collect::<Vec<_>>(), c.stroke_width(2)));
            chart.draw_series(lines).map_err(draw_error)?;
        }
        draw_extras(&mut chart, s, body, to)?;
    }
    if all.len() > 1 {
        let mut labels = chart.configure_series_labels();
        labels.background_style(WHITE.mix(0.8)).border_style(BLACK).draw().map_err(draw_error)?;
    }
    Ok(())
}

/// The figure of `all` (one or more series) titled `title`, the body drawn as `body` at the
/// frames, in the view `view` (1200 x 560 pixels).
pub(crate) struct Figure<'a> {
    /// The series.
    pub all: &'a [Series],
    /// The path panel's view.
    pub view: View,
    /// How the body is drawn.
    pub body: Body,
    /// The title.
    pub title: &'a str,
}

impl Picture for Figure<'_> {
    fn size(&self) -> (u32, u32) {
        (1200, 560)
    }

    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Result<(), CliError> {
        let root = root.titled(self.title, ("sans-serif", 22)).map_err(draw_error)?;
        let (left, right) = root.split_horizontally(600);
        speeds(&left, self.all)?;
        match self.view.axes() {
            Some((a, b)) => paths_2d(&right, self.all, self.body, a, b),
            None => paths_3d(&right, self.all, self.body),
        }
    }
}

/// The file bytes of the figure of `all` (see [`Figure`]) in `format`.
pub(crate) fn render(all: &[Series], view: View, body: Body, title: &str, format: Format) -> Result<Vec<u8>, CliError> {
    encode(&Figure { all, view, body, title }, format)
}

#[cfg(test)]
mod tests {
    use super::{L_BLOCK, L_DEPTH, l_block};
    use crate::plot::data::Frame;

    #[test]
    fn the_l_block_moves_rigidly_with_its_frame() {
        // The frame of x ↦ R x + p, R the quarter turn about e3 (e1 → e2, e2 → -e1, e3 → e3),
        // p = (1, 2, 3): body point (x, y, z) goes to (1 - y, 2 + x, 3 + z).
        let p = [1.0, 2.0, 3.0];
        let f = Frame { t: 0.0, origin: p, axes: [[1.0, 3.0, 3.0], [0.0, 2.0, 3.0], [1.0, 2.0, 4.0]], cube: [p; 8] };
        let b = l_block(&f);
        for (c, got) in b.iter().enumerate() {
            let [y, z] = L_BLOCK[c % 6];
            let x = if c < 6 { 0.0 } else { L_DEPTH };
            assert_eq!(*got, [1.0 - y, 2.0 + x, 3.0 + z], "corner {c}");
        }
        // An L: six distinct corners per face, two legs of lengths 2 and 1 from the corner.
        assert_eq!(L_BLOCK[1], [2.0, 0.0]);
        assert_eq!(L_BLOCK[5], [0.0, 1.0]);
    }
}
