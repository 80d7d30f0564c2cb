//! Drawing the [`Series`] of `gam plot` with `plotters`: the speed panel (every body point's
//! `|v|` as a thick solid line and each series' `|Ω|` as a thin dashed one in the same hue, on
//! a second axis at the right when the two differ by a factor of ten or more; the joins as
//! vertical grey lines), the path panel (the paths of the body points projected on a
//! coordinate plane with equal scales on both axes, or a 3-D view with equal scales,
//! [`super::axes3d`]; the key points as dots; the body frames as red, green, blue segments
//! along the moved `e1, e2, e3`, colours no path uses) and the legend in a band under both
//! ([`super::legend`]).
//!
//! Colours ([`super::style::PALETTE`]): with one spec, one hue per body point (its speed and
//! its path); with several, one hue per spec, its further body points darker.
//!
//! Every data line is one SVG `<polyline>` and every legend mark a `<rect>` (or a `<circle>`),
//! so a test can count the series of a figure (the polylines not in black or grey, which are
//! the axes, the grid and the box): per series, one speed line and one path per body point,
//! one angular speed line, one line per join and three per frame (twelve with `--body cube`).
//! Filled faces (the L-shaped block's two L faces, the filled face markings of
//! [`Series::marks`]) are SVG `<polygon>`s; each mark's outline is one more polyline, a dashed
//! `arc` one per dash.

use super::axes3d::{self, Bounds};
use super::data::{Mark, Series, moved};
use super::legend::{self, Entry, Swatch};
use super::raster::{Format, Picture, draw_error, encode};
use super::style::{ANGULAR, AXIS_COLOURS, JOIN, Px, colour, dashed, fitted};
use super::svg::{SharedLayers, in_layer};
use crate::error::CliError;
use crate::scalar::format_f64;
use plotters::coord::Shift;
use plotters::prelude::*;

/// How the moved body is drawn at the frame parameters (`gam figures --json` prints it as
/// `body`, named as `--body` names it).
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Body {
    /// Its coordinate frame: `e1` red, `e2` green, `e3` blue, a tenth of the paths' extent.
    Frames,
    /// The unit cube `[0, 1]³` (Jüttler's figures), its 12 edges in grey.
    Cube,
    /// The L-shaped block of the main paper's Figs. 6-10, in grey: an L of legs 2 (along `e2`)
    /// and 1 (along `e3`), 0.5 wide, 0.5 deep (along `e1`), its corner at the body origin.
    LBlock,
    /// The cuboidal block of the main paper's Fig. 3, in grey: [`CUBOID`] long along `e1, e2,
    /// e3`, centred on the body origin (the paper's body point is the block's centre), its
    /// top face (`+e3`) filled.
    Cuboid,
}

/// The cuboid's edge lengths along `e1, e2, e3` (the paper prints none; its Fig. 3 shows a
/// block longer than wide, flat).
pub(crate) const CUBOID: [f64; 3] = [1.2, 0.6, 0.3];

/// The cuboid moved by frame `f`: corner `i + 2j + 4k` at `(±, ±, ±)` half lengths, the
/// minus sign for a zero bit.
pub(crate) fn cuboid(f: &super::data::Frame) -> [[f64; 3]; 8] {
    std::array::from_fn(|c| {
        moved(f, std::array::from_fn(|k| if c >> k & 1 == 1 { CUBOID[k] } else { -CUBOID[k] } / 2.0))
    })
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
        Body::Cuboid => {
            let b = cuboid(f);
            vec![vec![b[4], b[5], b[7], b[6]]]
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
fn mark_shapes(m: &Mark) -> (Option<Vec<[f64; 3]>>, Vec<(Vec<[f64; 3]>, RGBColor, f64)>) {
    match m.kind {
        "square" | "triangle" => (Some(m.points.clone()), vec![(m.points.clone(), MARK, 1.0)]),
        "arc" => {
            let dashes = (0..m.points.len().saturating_sub(1) / DASH)
                .map(|i| (m.points[DASH * i..(DASH * i + DASH).min(m.points.len())].to_vec(), ARC, 1.0));
            (None, dashes.collect())
        }
        "curve" => (None, vec![(m.points.clone(), MARK, 2.0)]),
        "arrow" => (None, vec![(m.points.clone(), MARK, 2.0), (arrow_head(&m.points), MARK, 2.0)]),
        _ => (None, vec![(m.points.clone(), MARK, 1.0)]),
    }
}

/// The head of the arrow `[tail, tip]`: a polyline through the tip, its sides 15% of the
/// arrow long, in the plane of the arrow and `e3` (or `e1` for an arrow along `e3`).
fn arrow_head(points: &[[f64; 3]]) -> Vec<[f64; 3]> {
    let (Some(a), Some(b)) = (points.first(), points.last()) else { return vec![] };
    let d: [f64; 3] = std::array::from_fn(|i| b[i] - a[i]);
    let len = d.iter().map(|x| x * x).sum::<f64>().sqrt();
    if len == 0.0 {
        return vec![];
    }
    let cross =
        |u: [f64; 3], v: [f64; 3]| [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]];
    let mut side = cross(d, [0.0, 0.0, 1.0]);
    if side.iter().map(|x| x * x).sum::<f64>() < 1e-12 * len * len {
        side = cross(d, [1.0, 0.0, 0.0]);
    }
    let s = side.iter().map(|x| x * x).sum::<f64>().sqrt();
    let h = 0.15 * len;
    let at = |sign: f64| std::array::from_fn(|i| b[i] - h * d[i] / len + sign * 0.5 * h * side[i] / s);
    vec![at(1.0), *b, at(-1.0)]
}

/// Draws the shaded faces of `body` at the frames of `s` and the marks of `s` on a chart,
/// `to` mapping a world point to the chart's coordinates.
fn draw_extras<DB: DrawingBackend, CT: CoordTranslate>(
    chart: &mut ChartContext<DB, CT>,
    s: &Series,
    body: Body,
    px: Px,
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
            .map(|(ps, c, w)| PathElement::new(ps.iter().map(&to).collect::<Vec<_>>(), c.stroke_width(px.u(w))));
        chart.draw_series(lines).map_err(draw_error)?;
        if let (Some(label), Some(tip)) = (&m.label, m.points.last()) {
            let font = ("sans-serif", px.font(13.0)).into_font().color(&MARK);
            let text = EmptyElement::at(to(tip)) + Text::new(label.clone(), (px.i(6.0), px.i(-16.0)), font);
            chart.draw_series(std::iter::once(text)).map_err(draw_error)?;
        }
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
        Body::Cuboid => {
            let c = cuboid(f);
            EDGES.iter().map(|(a, b)| (vec![c[*a], c[*b]], CUBE)).collect()
        }
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
    let cuboids = all.iter().flat_map(|s| s.frames.iter().flat_map(cuboid)).filter(|_| body == Body::Cuboid);
    let marks = all.iter().flat_map(|s| s.marks.iter().flat_map(|m| m.points.iter().copied()));
    paths.chain(cubes).chain(blocks).chain(cuboids).chain(marks).collect()
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

/// The ranges `a` and `b` widened about their centres so that one unit is as many pixels
/// along both in a plotting area `(w, h)` pixels large (equal aspect).
pub(crate) fn equal_aspect(a: (f64, f64), b: (f64, f64), (w, h): (f64, f64)) -> ((f64, f64), (f64, f64)) {
    let per_pixel = ((a.1 - a.0) / w).max((b.1 - b.0) / h);
    let widen = |(lo, hi): (f64, f64), pixels: f64| {
        let (c, half) = ((lo + hi) / 2.0, per_pixel * pixels / 2.0);
        (c - half, c + half)
    };
    (widen(a, w), widen(b, h))
}

/// The colour of body point `j` of series `si` (see the module doc).
fn colour_of(all: &[Series], si: usize, j: usize) -> RGBColor {
    if all.len() == 1 {
        return colour(j);
    }
    let c = colour(si);
    let dark = (0.3 * j as f64).min(0.6);
    let f = |v: u8| (f64::from(v) * (1.0 - dark)).round() as u8;
    RGBColor(f(c.0), f(c.1), f(c.2))
}

/// The colour of series `si`'s angular speed: its spec's hue, or, for one spec of several
/// body points, a dark grey.
fn angular_colour(all: &[Series], si: usize) -> RGBColor {
    match all {
        [s] if s.body_points.len() > 1 => ANGULAR,
        _ => colour_of(all, si, 0),
    }
}

/// The legend text of body point `j` of series `s` (short when the figure has one line).
fn point_label(all: &[Series], s: &Series, j: usize, what: &str) -> String {
    if all.len() == 1 && s.body_points.len() == 1 {
        return what.to_string();
    }
    let p = s.body_points[j].map(format_f64).join(", ");
    if all.len() == 1 { format!("{what} of [{p}]") } else { format!("{}: {what} of [{p}]", s.label) }
}

/// The legend of a figure of `all` with the body drawn as `body` (`animated`: the body moves):
/// with several specs, one entry per spec of one body point (its hue, solid and dashed),
/// otherwise one per body point and one for the angular speed.
fn entries(all: &[Series], body: Body, (animated, panel): (bool, Panel)) -> Vec<Entry> {
    let (solid, dashed) = match panel {
        Panel::Acceleration => ("linear acceleration |a| and path", "angular acceleration |Ω'|"),
        _ => ("linear speed |v| and path", "angular speed |Ω|"),
    };
    let mut out = Vec::new();
    for (si, s) in all.iter().enumerate() {
        if all.len() > 1 && s.body_points.len() == 1 {
            out.push(Entry { text: s.label.clone(), colour: colour_of(all, si, 0), swatch: Swatch::Pair });
            continue;
        }
        for j in 0..s.body_points.len() {
            let text = point_label(all, s, j, solid);
            out.push(Entry { text, colour: colour_of(all, si, j), swatch: Swatch::Solid });
        }
        let text = if all.len() == 1 { dashed.to_string() } else { format!("{}: {dashed}", s.label) };
        out.push(Entry { text, colour: angular_colour(all, si), swatch: Swatch::Dashed });
    }
    if all.iter().any(|s| !s.key_points.is_empty()) {
        out.push(Entry { text: "key poses".into(), colour: BLACK, swatch: Swatch::Dot });
    }
    if all.iter().any(|s| !s.joins.is_empty()) {
        out.push(Entry { text: "joins".into(), colour: JOIN, swatch: Swatch::Solid });
    }
    if animated {
        out.push(Entry { text: "the moving body's parameter t".into(), colour: CURSOR, swatch: Swatch::Solid });
    }
    if body == Body::Frames && (animated || all.iter().any(|s| !s.frames.is_empty())) {
        for (k, c) in AXIS_COLOURS.iter().enumerate() {
            out.push(Entry { text: format!("body frame e{}", k + 1), colour: *c, swatch: Swatch::Solid });
        }
    }
    out
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

/// Panel layout, in pixels: the margin, the x and y label areas, the caption and label sizes.
const MARGIN: f64 = 12.0;
const X_LABELS: f64 = 42.0;
const Y_LABELS: f64 = 62.0;
const CAPTION: f64 = 16.0;
const LABEL: f64 = 12.0;

/// The panel `area` with its caption drawn, the rest returned.
fn captioned<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    caption: &str,
    px: Px,
) -> Result<DrawingArea<DB, Shift>, CliError> {
    let width = f64::from(area.dim_in_pixel().0) / px.0 - 2.0 * MARGIN;
    area.titled(caption, ("sans-serif", px.font(fitted(caption, CAPTION, width)))).map_err(draw_error)
}

/// The axes, grid and label styles of a 2-D panel at the scale `px`.
fn style_mesh<DB: DrawingBackend, X: plotters::coord::ranged1d::Ranged, Y: plotters::coord::ranged1d::Ranged>(
    mesh: &mut plotters::chart::MeshStyle<'_, '_, X, Y, DB>,
    px: Px,
) {
    mesh.label_style(("sans-serif", px.font(LABEL)))
        .axis_desc_style(("sans-serif", px.font(13.0)))
        .set_all_tick_mark_size(px.i(5.0))
        .axis_style(BLACK.stroke_width(px.u(1.0)))
        .bold_line_style(BLACK.mix(0.18).stroke_width(px.u(1.0)))
        .light_line_style(BLACK.mix(0.06).stroke_width(px.u(1.0)))
        .x_labels(8)
        .y_labels(8);
}

/// The speed panel (with the animation's cursor in its layers).
fn speeds<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    all: &[Series],
    (anim, panel): (Option<&Animation>, Panel),
    px: Px,
) -> Result<(), CliError> {
    let (t_lo, t_hi) = range(all.iter().flat_map(|s| s.t.iter().copied()));
    let bounds = |values: &mut dyn Iterator<Item = f64>| range(values.chain(std::iter::once(0.0)));
    let linear = bounds(&mut all.iter().flat_map(|s| lines(s, panel).0.iter().flatten().copied()));
    let angular = bounds(&mut all.iter().flat_map(|s| lines(s, panel).1.iter().copied()));
    // Speeds are never negative (their ranges start at 0); differences in per cent may be.
    let lo = if let Panel::Increase(_) = panel { linear.0.min(angular.0).min(0.0) } else { 0.0 };
    let ratio = linear.1 / angular.1;
    let split = !matches!(panel, Panel::Increase(_)) && ratio.is_finite() && !(0.1..=10.0).contains(&ratio);
    let both = linear.1.max(angular.1);
    let (lin_hi, ang_hi) = if split { (linear.1, angular.1) } else { (both, both) };
    let caption = match panel {
        Panel::Increase(base) => format!("increase over {base} in per cent: linear (solid), angular (dashed)"),
        Panel::Error(exact) => format!("error against {exact}: position (solid), rotation (dashed)"),
        Panel::Speeds => "linear speed (solid) and angular speed (dashed)".to_string(),
        Panel::Acceleration => "linear acceleration (solid) and angular acceleration (dashed)".to_string(),
    };
    let area = captioned(area, &caption, px)?;
    let mut builder = ChartBuilder::on(&area);
    builder.margin(px.u(MARGIN)).x_label_area_size(px.u(X_LABELS)).y_label_area_size(px.u(Y_LABELS));
    if split {
        builder.right_y_label_area_size(px.u(Y_LABELS));
    }
    let chart = builder.build_cartesian_2d(t_lo..t_hi, lo..lin_hi).map_err(draw_error)?;
    let mut chart = chart.set_secondary_coord(t_lo..t_hi, lo..ang_hi);
    let y_desc = match (panel, split) {
        (Panel::Increase(_), _) => "per cent of the speed",
        (Panel::Error(_), true) => "distance of the body point",
        (Panel::Error(_), false) => "distance, angle (radians)",
        (Panel::Speeds, true) => "linear speed |v| per unit t",
        (Panel::Speeds, false) => "speed per unit t",
        (Panel::Acceleration, true) => "linear acceleration |a| per unit t²",
        (Panel::Acceleration, false) => "acceleration per unit t²",
    };
    let y2_desc = match panel {
        Panel::Error(_) => "rotation angle between the two, radians (dashed)",
        Panel::Acceleration => "angular acceleration |Ω'| per unit t² (dashed)",
        _ => "angular speed |Ω| per unit t (dashed)",
    };
    let mut mesh = chart.configure_mesh();
    style_mesh(&mut mesh, px);
    mesh.x_desc("t").y_desc(y_desc).draw().map_err(draw_error)?;
    if split {
        chart
            .configure_secondary_axes()
            .label_style(("sans-serif", px.font(LABEL)))
            .axis_desc_style(("sans-serif", px.font(13.0)))
            .set_all_tick_mark_size(px.i(5.0))
            .axis_style(BLACK.stroke_width(px.u(1.0)))
            .y_desc(y2_desc)
            .draw()
            .map_err(draw_error)?;
    }
    for (si, s) in all.iter().enumerate() {
        let joins =
            s.joins.iter().map(|t| PathElement::new(vec![(*t, lo), (*t, lin_hi)], JOIN.stroke_width(px.u(1.0))));
        chart.draw_series(joins).map_err(draw_error)?;
        for (j, v) in lines(s, panel).0.iter().enumerate() {
            let pts = s.t.iter().copied().zip(v.iter().copied());
            chart
                .draw_series(LineSeries::new(pts, colour_of(all, si, j).stroke_width(px.u(2.0))))
                .map_err(draw_error)?;
        }
        let pts = s.t.iter().copied().zip(lines(s, panel).1.iter().copied());
        let style = dashed(angular_colour(all, si), px.u(1.5));
        chart.draw_secondary_series(LineSeries::new(pts, style)).map_err(draw_error)?;
    }
    if let Some(a) = anim {
        for k in 0..a.frames {
            let cursor = |s: &Series| {
                let t = s.frames[k].t;
                PathElement::new(vec![(t, lo), (t, lin_hi)], CURSOR.stroke_width(px.u(1.5)))
            };
            let drawn = in_layer(Some(&a.layers), k, || chart.draw_series(a.series.iter().map(cursor)).map(|_| ()));
            drawn.map_err(draw_error)?;
        }
    }
    Ok(())
}

/// The colour of the animation's cursor on the speed panel.
const CURSOR: RGBColor = RGBColor(0, 0, 0);

/// An animated figure ([`super::animate`]): the body and the speed cursor at `frames`
/// parameters, each drawn into its own layer.
pub(crate) struct Animation<'a> {
    /// Per spec, the series whose `frames` are the animation's frames.
    pub series: &'a [Series],
    /// The number of frames.
    pub frames: usize,
    /// The layers the frames are drawn into.
    pub layers: SharedLayers,
}

/// Draws the paths, key points, frames and extras of `all` on a chart, `to` mapping a world
/// point to the chart's coordinates.
fn draw_paths<DB: DrawingBackend, CT: CoordTranslate>(
    chart: &mut ChartContext<DB, CT>,
    all: &[Series],
    (body, anim): (Body, Option<&Animation>),
    px: Px,
    to: impl Fn(&[f64; 3]) -> CT::From + Copy,
) -> Result<(), CliError>
where
    CT::From: Clone + 'static,
{
    let l = frame_scale(all);
    for (si, s) in all.iter().enumerate() {
        for (j, path) in s.paths.iter().enumerate() {
            let style = colour_of(all, si, j).stroke_width(px.u(2.0));
            chart.draw_series(LineSeries::new(path.iter().map(to), style)).map_err(draw_error)?;
        }
        let dots = s.key_points.iter().flatten().map(|p| Circle::new(to(p), px.u(4.0), BLACK.filled()));
        chart.draw_series(dots).map_err(draw_error)?;
        for f in &s.frames {
            let lines = body_lines(f, body, l).into_iter();
            let lines =
                lines.map(|(ps, c)| PathElement::new(ps.iter().map(to).collect::<Vec<_>>(), c.stroke_width(px.u(2.0))));
            chart.draw_series(lines).map_err(draw_error)?;
        }
        draw_extras(chart, s, body, px, to)?;
    }
    let Some(a) = anim else { return Ok(()) };
    for k in 0..a.frames {
        in_layer(Some(&a.layers), k, || -> Result<(), CliError> {
            for (si, s) in a.series.iter().enumerate() {
                let f = &s.frames[k];
                let faces = body_faces(f, body)
                    .into_iter()
                    .map(|ps| Polygon::new(ps.iter().map(to).collect::<Vec<_>>(), SHADE.mix(0.6).filled()));
                chart.draw_series(faces).map_err(draw_error)?;
                let lines = body_lines(f, body, l)
                    .into_iter()
                    .map(|(ps, c)| PathElement::new(ps.iter().map(to).collect::<Vec<_>>(), c.stroke_width(px.u(2.0))));
                chart.draw_series(lines).map_err(draw_error)?;
                let dots = s
                    .body_points
                    .iter()
                    .enumerate()
                    .map(|(j, x)| Circle::new(to(&moved(f, *x)), px.u(5.0), colour_of(all, si, j).filled()));
                chart.draw_series(dots).map_err(draw_error)?;
            }
            Ok(())
        })?;
    }
    Ok(())
}

/// The path panel projected on the coordinates `(a, b)`, with equal scales on both axes.
fn paths_2d<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    all: &[Series],
    (body, anim): (Body, Option<&Animation>),
    (a, b): (usize, usize),
    px: Px,
) -> Result<(), CliError> {
    let names = ["x", "y", "z"];
    let shown = shown_points(all, body);
    let caption = format!("path of the body points ({}-{} projection, equal scales)", names[a], names[b]);
    let area = captioned(area, &caption, px)?;
    let (w, h) = area.dim_in_pixel();
    let plot = (f64::from(w) - px.0 * (2.0 * MARGIN + Y_LABELS), f64::from(h) - px.0 * (2.0 * MARGIN + X_LABELS));
    let ((a_lo, a_hi), (b_lo, b_hi)) =
        equal_aspect(range(shown.iter().map(|p| p[a])), range(shown.iter().map(|p| p[b])), plot);
    let mut chart = ChartBuilder::on(&area)
        .margin(px.u(MARGIN))
        .x_label_area_size(px.u(X_LABELS))
        .y_label_area_size(px.u(Y_LABELS))
        .build_cartesian_2d(a_lo..a_hi, b_lo..b_hi)
        .map_err(draw_error)?;
    let mut mesh = chart.configure_mesh();
    style_mesh(&mut mesh, px);
    mesh.x_desc(names[a]).y_desc(names[b]).draw().map_err(draw_error)?;
    draw_paths(&mut chart, all, (body, anim), px, |p| (p[a], p[b]))
}

/// The path panel as a 3-D view (z up), with equal scales on the three axes.
fn paths_3d<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    all: &[Series],
    (body, anim): (Body, Option<&Animation>),
    px: Px,
) -> Result<(), CliError> {
    let shown = shown_points(all, body);
    let area = captioned(area, "path of the body points (3-D view, z up, equal scales)", px)?;
    let bounds = Bounds::of(shown.iter());
    let mut chart = axes3d::chart(&area, &bounds, px)?;
    axes3d::draw_axes(&mut chart, &area, &bounds, px)?;
    draw_paths(&mut chart, all, (body, anim), px, axes3d::to)
}

/// The height of the two panels and the title, in pixels.
const PANELS: u32 = 560;

/// The figure's width in pixels.
const WIDTH: u32 = 1200;

/// The figure of `all` (one or more series) titled `title`, the body drawn as `body` at the
/// frames, in the view `view`: 1200 pixels wide, the panels 560 high, the legend band under them.
pub(crate) struct Figure<'a> {
    /// The series.
    pub all: &'a [Series],
    /// The path panel's view.
    pub view: View,
    /// How the body is drawn.
    pub body: Body,
    /// The title.
    pub title: &'a str,
    /// The animation, if the figure is animated (SVG only).
    pub animation: Option<Animation<'a>>,
    /// What the left panel's lines are.
    pub panel: Panel<'a>,
}

/// What a figure's left panel draws from each series' `speeds` (solid) and `angular_speed`
/// (dashed).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Panel<'a> {
    /// Speeds (per unit `t`).
    Speeds,
    /// Increases in per cent over the series labelled so.
    Increase(&'a str),
    /// Errors against the motion named so: the body point's distance and the rotation angle.
    Error(&'a str),
    /// Accelerations: `|a|` of the body points and `|Ω'|` (`gam plot --acceleration`).
    Acceleration,
}

/// The lines a panel draws of series `s`: per body point (solid), and the dashed one.
fn lines<'s>(s: &'s Series, panel: Panel) -> (&'s [Vec<f64>], &'s [f64]) {
    match panel {
        Panel::Acceleration => (&s.accelerations, &s.angular_acceleration),
        _ => (&s.speeds, &s.angular_speed),
    }
}

impl Picture for Figure<'_> {
    fn size(&self) -> (u32, u32) {
        let entries = entries(self.all, self.body, (self.animation.is_some(), self.panel));
        (WIDTH, PANELS + legend::height(&entries, f64::from(WIDTH)))
    }

    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>, px: Px) -> Result<(), CliError> {
        let (top, band) = root.split_vertically(px.i(f64::from(PANELS)));
        let size = fitted(self.title, 22.0, f64::from(WIDTH) - 2.0 * MARGIN);
        let top = top.titled(self.title, ("sans-serif", px.font(size))).map_err(draw_error)?;
        let top = top.margin(px.i(6.0), 0, 0, 0);
        let (left, right) = top.split_horizontally(px.i(f64::from(WIDTH) / 2.0));
        let anim = self.animation.as_ref();
        speeds(&left, self.all, (anim, self.panel), px)?;
        match self.view.axes() {
            Some(ab) => paths_2d(&right, self.all, (self.body, anim), ab, px)?,
            None => paths_3d(&right, self.all, (self.body, anim), px)?,
        }
        legend::draw(&band, &entries(self.all, self.body, (anim.is_some(), self.panel)), px)
    }
}

/// The file bytes of the figure of `all` (see [`Figure`]) in `format`.
pub(crate) fn render(all: &[Series], view: View, body: Body, title: &str, format: Format) -> Result<Vec<u8>, CliError> {
    render_panel(all, (view, body), (title, Panel::Speeds), format)
}

/// The file bytes of the figure of `all` whose left panel draws `panel` (see [`Panel`]) in
/// `format`.
pub(crate) fn render_panel(
    all: &[Series],
    (view, body): (View, Body),
    (title, panel): (&str, Panel),
    format: Format,
) -> Result<Vec<u8>, CliError> {
    encode(&Figure { all, view, body, title, animation: None, panel }, format)
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
