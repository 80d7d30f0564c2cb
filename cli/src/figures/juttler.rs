//! Jüttler's Figs. 1-6 (Sec. 6 of "Visualization of moving objects using dual quaternion
//! curves") redrawn from the library's constructions: unit cubes `[0, 1]³` of the moving space
//! at the key poses and midway between them, the trajectories of the origin and of
//! `(0, 0, 1)`, in a 3-D view (z up). The cubes' three pairs of opposite faces are marked by
//! squares, triangles and crosses as in the paper ([`face_marks`]), and Fig. 5a also draws the
//! parabola moved with the body ([`parabola_marks`]). The paper does not print its positions; the ones here
//! ([`FIVE`], [`FOUR`], [`THREE`], [`SIX`]) are chosen to show what each figure shows (docs/figures.md).
//!
//! - Fig. 1: elliptic rotations (23)-(25) composed with the TR translation (Algorithm 1),
//!   equidistant parameters (`Method::JuttlerQMotion`).
//! - Fig. 2: the projective rotations (28) (degree 3 through 5 positions) with the same TR
//!   translation (`juttler::projective::projective`, `juttler::tr::tr_method`): a somersault.
//! - Fig. 3: Algorithm 1 with `Δt_i ~ √dist` (centripetal).
//! - Fig. 4: TRT with `l1 = 3, l2 = 0` and `Δt_i ~ dist + ∠` (`Method::JuttlerTrt`).
//! - Fig. 5a/5b: the minimal rational motion of order 4 through 3 positions (`juttler-minimal`)
//!   moving the parabola [`parabola`], and the kinematic surface it sweeps
//!   (`juttler::surface::RationalBezierSurface::kinematic`), shaded, with its iso-curves.
//! - Fig. 6: the C¹ spline Q-motion of Algorithm 2 through 6 positions (`juttler-spline`).

use crate::error::CliError;
use crate::plot::data::{Frame, Mark, Series, Shape, evenly, frame, moved, of_motion};
use crate::plot::draw::{Body, View, render};
use crate::plot::raster::Format;
use crate::plot::surface::wireframe;
use motion::juttler::surface::RationalBezierSurface;
use motion::juttler::{Parametrisation, QMotion, RationalBezier, minimal, projective, tr};
use motion::method::{Method, MethodInput, Parameters};
use motion::trajectory::{align_signs, sample_motion};
use motion::{MapScalar, Pose, algebra_core::Jet};
use serde_json::{Value, json};

/// Samples per curve.
const SAMPLES: usize = 201;

/// The body points whose trajectories are drawn: the origin and `(0, 0, 1)`.
const POINTS: [[f64; 3]; 2] = [[0.0; 3], [0.0, 0.0, 1.0]];

/// A key pose: rotation axis, angle (radians), translation (the rotation first).
type Key = ([f64; 3], f64, [f64; 3]);

/// The five positions of Figs. 1-4: along x, turning about changing axes.
pub(crate) const FIVE: [Key; 5] = [
    ([0.0, 0.0, 1.0], 0.0, [0.0, 0.0, 0.0]),
    ([0.0, 0.0, 1.0], 0.8, [3.0, 1.0, 0.0]),
    ([1.0, 0.0, 0.0], 1.2, [6.0, 0.0, 1.0]),
    ([0.0, 1.0, 1.0], 1.6, [8.0, 2.0, 0.0]),
    ([1.0, 1.0, 0.0], 2.0, [12.0, 0.0, 0.0]),
];

/// The five positions of Fig. 4. With [`FIVE`] the TRT system (34) is nearly singular: the
/// motion swings out to `y = 34` at speeds up to 1167 (per unit `t`) between key poses 12
/// apart. These (found by a search over random positions marching along x, then rounded)
/// give a motion that stays within 0.03 of the key poses' bounding box, speeds up to 21.
pub(crate) const FOUR: [Key; 5] = [
    ([0.0, 0.0, 1.0], 0.0, [0.0, 0.0, 0.0]),
    ([-0.4, -0.6, 0.6], 1.0, [2.6, -0.9, 0.0]),
    ([-1.0, 0.7, -0.6], 0.6, [5.9, 0.5, 0.1]),
    ([0.3, 0.3, -0.1], 0.4, [9.5, 1.1, -0.4]),
    ([-0.1, 0.5, 1.0], 0.4, [11.5, 0.4, 0.1]),
];

/// The three positions of Fig. 5.
pub(crate) const THREE: [Key; 3] = [
    ([0.0, 0.0, 1.0], 0.0, [0.0, 0.0, 0.0]),
    ([1.0, 0.0, 0.0], 1.0, [3.0, 1.0, 1.0]),
    ([0.0, 1.0, 0.0], 1.5, [6.0, 0.0, 0.0]),
];

/// The six positions of Fig. 6.
pub(crate) const SIX: [Key; 6] = [
    ([0.0, 0.0, 1.0], 0.0, [0.0, 0.0, 0.0]),
    ([0.0, 0.0, 1.0], 1.0, [2.5, 1.5, 0.0]),
    ([1.0, 0.0, 0.0], 1.0, [5.0, 0.0, 1.0]),
    ([0.0, 1.0, 0.0], 1.0, [7.5, 1.5, 0.0]),
    ([1.0, 1.0, 1.0], 1.5, [10.0, 0.0, 1.0]),
    ([0.0, 0.0, 1.0], 0.5, [12.5, 1.5, 0.0]),
];

/// The parabola `x(v)` of the moving space swept in Fig. 5: the quadratic Bézier curve with
/// control points `(0, 0, 0), (1/2, 0, 1), (1, 0, 0)`, unit weights (homogeneous, weight first).
pub(crate) fn parabola() -> Result<RationalBezier<f64>, CliError> {
    RationalBezier::new(vec![[1.0, 0.0, 0.0, 0.0], [1.0, 0.5, 0.0, 1.0], [1.0, 1.0, 0.0, 0.0]])
        .map_err(|e| CliError::math(format!("the parabola of Fig. 5: {e}")))
}

/// The points `x(0), x(1/2), x(1)` of the [`parabola`] (the body points of Fig. 5a).
fn on_parabola() -> Result<Vec<[f64; 3]>, CliError> {
    let x = parabola()?;
    [0.0, 0.5, 1.0].iter().map(|v| x.point(v).map_err(bad("Fig. 5"))).collect()
}

fn poses(keys: &[Key]) -> Result<Vec<Pose<f64>>, CliError> {
    let mut p = keys
        .iter()
        .map(|(axis, angle, t)| Pose::from_axis_angle_translation(axis, angle, t))
        .collect::<Result<Vec<_>, _>>()
        .map_err(|e| CliError::math(format!("a key pose of Jüttler's figures: {e}")))?;
    align_signs(&mut p);
    Ok(p)
}

fn bad<E: std::fmt::Display>(what: &'static str) -> impl Fn(E) -> CliError {
    move |e| CliError::math(format!("{what}: {e}"))
}

/// The face markings of the unit cube at frame `f`, as Jüttler marks "the three pairs of
/// opposite faces": the faces `x = 0, 1` by squares, `y = 0, 1` by triangles and `z = 0, 1`
/// by crosses (two strokes each), inside `[0.3, 0.7]²` of the face's other two coordinates
/// `(x_{k+1}, x_{k+2})` (indices mod 3), moved with the body.
pub(crate) fn face_marks(f: &Frame) -> Vec<Mark> {
    const SQUARE: [[f64; 2]; 5] = [[0.3, 0.3], [0.7, 0.3], [0.7, 0.7], [0.3, 0.7], [0.3, 0.3]];
    const TRIANGLE: [[f64; 2]; 4] = [[0.3, 0.3], [0.7, 0.3], [0.5, 0.7], [0.3, 0.3]];
    const CROSS: [[[f64; 2]; 2]; 2] = [[[0.3, 0.3], [0.7, 0.7]], [[0.3, 0.7], [0.7, 0.3]]];
    let mut out = Vec::new();
    for k in 0..3 {
        for side in [0.0, 1.0] {
            let on = |[a, b]: [f64; 2]| {
                let mut x = [0.0; 3];
                (x[k], x[(k + 1) % 3], x[(k + 2) % 3]) = (side, a, b);
                moved(f, x)
            };
            let shapes: Vec<(&'static str, &[[f64; 2]])> = match k {
                0 => vec![("square", &SQUARE)],
                1 => vec![("triangle", &TRIANGLE)],
                _ => CROSS.iter().map(|c| ("cross", &c[..])).collect(),
            };
            for (kind, pts) in shapes {
                out.push(Mark { t: f.t, kind, points: pts.iter().copied().map(on).collect(), label: None });
            }
        }
    }
    out
}

/// The series of `motion` over `key_times`: the trajectories of `points`, the unit cube at
/// the key parameters and midway between them, its faces marked ([`face_marks`]).
fn series<M: MapScalar<f64, Jet<Jet<f64>>>>(
    shape: Shape,
    motion: &M,
    points: Vec<[f64; 3]>,
) -> Result<Series, CliError> {
    let keys = shape.key_times.clone();
    let mut s = of_motion(shape, motion, points, SAMPLES, 0)?;
    let mut times: Vec<f64> = keys.windows(2).flat_map(|w| [w[0], 0.5 * (w[0] + w[1])]).collect();
    times.extend(keys.last());
    s.frames = times
        .into_iter()
        .map(|t| {
            let pose = sample_motion(motion, &t, &[]).map_err(bad("Jüttler's figures"))?.pose;
            frame(t, &pose)
        })
        .collect::<Result<Vec<_>, _>>()?;
    s.marks = s.frames.iter().flat_map(face_marks).collect();
    Ok(s)
}

/// The parabola moved with the body at every frame of `s` (Fig. 5a's moving body), 33 points each.
fn parabola_marks(s: &Series) -> Result<Vec<Mark>, CliError> {
    let x = parabola()?;
    let points: Vec<[f64; 3]> =
        evenly(0.0, 1.0, 33).iter().map(|v| x.point(v).map_err(bad("Fig. 5a"))).collect::<Result<_, _>>()?;
    Ok(s.frames
        .iter()
        .map(|f| Mark { t: f.t, kind: "curve", points: points.iter().map(|p| moved(f, *p)).collect(), label: None })
        .collect())
}

/// The series of `method` through `keys` with `parameters` (and `l1`).
fn built(
    label: &str,
    method: Method,
    keys: &[Key],
    parameters: Parameters<f64>,
    l1: Option<usize>,
    points: Vec<[f64; 3]>,
) -> Result<Series, CliError> {
    let input = MethodInput { parameters, l1, ..MethodInput::new(poses(keys)?) };
    let m = method.build(&input).map_err(bad("Jüttler's figures"))?;
    let shape = Shape {
        label: label.to_string(),
        method: method.name().to_string(),
        segments: m.segments().len(),
        degree: m.max_degree(),
        tableau: crate::budget::Tableau::of_method(m.method()),
        key_times: m.times().to_vec(),
        joins: m.segments().iter().skip(1).map(|s| s.t0).collect(),
    };
    series(shape, m.motion(), points)
}

/// Fig. 2's motion: the projective rotations through [`FIVE`] composed with the TR
/// translation, equidistant parameters.
fn projective_motion() -> Result<(QMotion<f64>, Vec<f64>), CliError> {
    let p = poses(&FIVE)?;
    let t = evenly(0.0, 1.0, p.len());
    let rots = p.iter().map(|x| Ok(tr::rotation_translation(x)?.0)).collect::<Result<Vec<_>, _>>();
    let rots = rots.map_err(bad::<motion::juttler::JuttlerError>("Fig. 2"))?;
    let rot = projective::projective(&rots, &t).map_err(bad("Fig. 2, the projective method"))?;
    Ok((tr::tr_method(&rot, &p, &t).map_err(bad("Fig. 2, the TR method"))?, t))
}

/// The kinematic surface of Fig. 5b sampled as its iso-parameter curves: `[v fixed, t fixed]`
/// at `v, t = 0, 1/8, ..., 1`, each curve at [`SAMPLES`] values of the other parameter.
fn surface_curves() -> Result<[Vec<Vec<[f64; 3]>>; 2], CliError> {
    let m = minimal::minimal(&poses(&THREE)?, &[0.0, 0.5, 1.0]).map_err(bad("Fig. 5"))?;
    let s = RationalBezierSurface::kinematic(&m, &parabola()?).map_err(bad("Fig. 5b"))?;
    let at = |t: f64, v: f64| s.point(&t, &v).map_err(bad("Fig. 5b"));
    let grid = evenly(0.0, 1.0, 9);
    let fine = evenly(0.0, 1.0, SAMPLES);
    let iso_v = grid.iter().map(|v| fine.iter().map(|t| at(*t, *v)).collect()).collect::<Result<_, _>>()?;
    let iso_t = grid.iter().map(|t| fine.iter().map(|v| at(*t, *v)).collect()).collect::<Result<_, _>>()?;
    Ok([iso_v, iso_t])
}

/// One drawn figure: file name (`.svg`), title, file bytes and JSON data.
pub(crate) type Drawn = (&'static str, String, Vec<u8>, Value);

/// The file name, title, file bytes (in `format`) and JSON data of each figure.
pub(crate) fn all(format: Format) -> Result<Vec<Drawn>, CliError> {
    let uniform = || Parameters::Uniform;
    let pts = || POINTS.to_vec();
    let (proj, t) = projective_motion()?;
    let proj_shape = Shape {
        label: "projective".into(),
        method: "projective + TR".into(),
        segments: 1,
        degree: proj.degree(),
        tableau: crate::budget::Tableau::Rational,
        key_times: t,
        joins: vec![],
    };
    let figs: Vec<(&'static str, &str, Series)> = vec![
        (
            "juttler_fig1.svg",
            "Jüttler Fig. 1: elliptic rotations + TR translation, equidistant",
            built("elliptic", Method::JuttlerQMotion, &FIVE, uniform(), None, pts())?,
        ),
        (
            "juttler_fig2.svg",
            "Jüttler Fig. 2: projective rotations (degree 3) + TR translation: a somersault",
            series(proj_shape, &proj, pts())?,
        ),
        (
            "juttler_fig3.svg",
            "Jüttler Fig. 3: TR method (Algorithm 1), Δt ~ √dist",
            built("TR", Method::JuttlerQMotion, &FIVE, Parameters::Rule(Parametrisation::Centripetal), None, pts())?,
        ),
        (
            "juttler_fig4.svg",
            "Jüttler Fig. 4: TRT method (l₁ = 3, l₂ = 0), Δt ~ dist + angle",
            built("TRT", Method::JuttlerTrt, &FOUR, Parameters::Rule(Parametrisation::AngleDistance), Some(3), pts())?,
        ),
        (
            "juttler_fig5a.svg",
            "Jüttler Fig. 5a: rational motion of order 4 through 3 positions, parabola points",
            built("minimal", Method::JuttlerMinimal, &THREE, uniform(), None, on_parabola()?)?,
        ),
        (
            "juttler_fig6.svg",
            "Jüttler Fig. 6: C1 spline Q-motion (Algorithm 2) through 6 positions",
            built("spline", Method::JuttlerSpline, &SIX, uniform(), None, pts())?,
        ),
    ];
    let mut out = Vec::new();
    for (file, title, mut s) in figs {
        if file == "juttler_fig5a.svg" {
            s.marks.extend(parabola_marks(&s)?);
        }
        let svg = render(std::slice::from_ref(&s), View::ThreeD, Body::Cube, title, format)?;
        // the key poses as [axis, angle, translation], for the reader (and the test)
        let keys: &[Key] = match file {
            "juttler_fig5a.svg" => &THREE,
            "juttler_fig6.svg" => &SIX,
            "juttler_fig4.svg" => &FOUR,
            _ => &FIVE,
        };
        out.push((file, title.to_string(), svg, json!({"title": title, "keys": keys, "series": [s]})));
    }
    let [iso_v, iso_t] = surface_curves()?;
    let title = "Jüttler Fig. 5b: the kinematic surface swept by the parabola (v = const thick, t = const thin)";
    let svg = wireframe([&iso_v, &iso_t], title, format)?;
    let grid = evenly(0.0, 1.0, 9);
    let data = json!({"title": title, "grid": grid, "t": evenly(0.0, 1.0, SAMPLES), "iso_v": iso_v, "iso_t": iso_t});
    out.insert(5, ("juttler_fig5b.svg", title.to_string(), svg, data));
    Ok(out)
}
