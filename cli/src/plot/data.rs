//! The data behind a `gam plot` figure, computed before anything is drawn ([`super::draw`]):
//! one [`Series`] per spec file, a plain struct of sampled values. `gam plot --json` prints
//! it, so the tests check the numbers the figure shows, not the pixels.
//!
//! A `gam interpolate` spec (it has a `method` key) is built by the one build path of `gam
//! interpolate` ([`crate::interpolate::built`]) and sampled over its whole parameter range
//! `[t_0, t_m]`, every `body_points` entry at once; a `gam hermite` spec is one segment over
//! `[0, 1]` with its `body_point`.

use crate::error::CliError;
use crate::hermite::read_spec;
use crate::hermite::strip_comments;
use crate::interpolate::{built, usage};
use crate::scalar::format_f64;
use motion::algebra_core::Jet;
use motion::trajectory::sample_motion;
use motion::{MapScalar, Pose};
use serde::Serialize;
use serde_json::Value;

/// The moved body at one parameter: where the body origin, the tips of the body's unit axes
/// `e1, e2, e3` and the corners of the unit cube `[0, 1]³` are (world coordinates).
#[derive(Debug, Clone, Serialize)]
pub(crate) struct Frame {
    /// The parameter.
    pub t: f64,
    /// The image of the body origin.
    pub origin: [f64; 3],
    /// The images of the body points `e1`, `e2`, `e3`.
    pub axes: [[f64; 3]; 3],
    /// The images of the unit cube's corners `(i, j, k) ∈ {0, 1}³`, corner `i + 2j + 4k`.
    pub cube: [[f64; 3]; 8],
}

/// A drawing attached to one figure's series besides its paths, in world coordinates: the
/// markings of the moved unit cube's faces (Jüttler's Figs. 1-4), a moved curve of the body
/// (Jüttler's Fig. 5a parabola), the path of a middle control pose (the main paper's Fig. 8).
#[derive(Debug, Clone, Serialize)]
pub(crate) struct Mark {
    /// The parameter of the body pose it is drawn at (for a control pose's path, `t0` for
    /// the one next to the start, `t1` for the one next to the end).
    pub t: f64,
    /// What it is: `square`, `triangle`, `cross` (face markings; squares and triangles
    /// filled), `curve` (a moved body curve), `arc` (a control pose's path, drawn dashed),
    /// `arrow` (a vector from `points[0]` to `points[1]`, with a head and its `label`).
    pub kind: &'static str,
    /// The polyline.
    pub points: Vec<[f64; 3]>,
    /// The text written at an arrow's tip.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub label: Option<String>,
}

/// Everything drawn for one spec.
#[derive(Debug, Clone, Serialize)]
pub(crate) struct Series {
    /// The legend label: the file name and the method (or the segment kind).
    pub label: String,
    /// `method` of a `gam interpolate` spec, or `additive`/`multiplicative` for `gam hermite`.
    pub method: String,
    /// The number of segments.
    pub segments: usize,
    /// The largest segment degree.
    pub degree: usize,
    /// The body points (body coordinates).
    pub body_points: Vec<[f64; 3]>,
    /// The parameters of the key poses (`[0, 1]` for a Hermite segment).
    pub key_times: Vec<f64>,
    /// The joins: the segment boundaries strictly inside the parameter range.
    pub joins: Vec<f64>,
    /// The sample parameters, evenly spaced over the whole range, both ends included.
    pub t: Vec<f64>,
    /// `paths[j][i]`: body point `j` at `t[i]` (world coordinates).
    pub paths: Vec<Vec<[f64; 3]>>,
    /// `speeds[j][i]`: `|v|` of body point `j` at `t[i]` (per unit of `t`).
    pub speeds: Vec<Vec<f64>>,
    /// `|Ω|` at `t[i]`.
    pub angular_speed: Vec<f64>,
    /// `accelerations[j][i]`: `|a|` of body point `j` at `t[i]` (per unit of `t` squared).
    pub accelerations: Vec<Vec<f64>>,
    /// `|Ω'|` at `t[i]`, the derivative of the space angular velocity.
    pub angular_acceleration: Vec<f64>,
    /// `key_points[k][j]`: body point `j` at the key parameter `key_times[k]`.
    pub key_points: Vec<Vec<[f64; 3]>>,
    /// The body frames at the `--frames K` evenly spaced parameters.
    pub frames: Vec<Frame>,
    /// Further drawings (`gam figures` only; not printed when empty).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub marks: Vec<Mark>,
}

/// Body point `x` moved by frame `f`: a rigid pose is affine, so `x` goes to
/// `o + Σ x_k (a_k - o)` with `o` the moved origin and `a_k` the moved `e_k`.
pub(crate) fn moved(f: &Frame, x: [f64; 3]) -> [f64; 3] {
    std::array::from_fn(|i| f.origin[i] + (0..3).map(|k| x[k] * (f.axes[k][i] - f.origin[i])).sum::<f64>())
}

fn norm(v: &[f64; 3]) -> f64 {
    v.iter().map(|x| x * x).sum::<f64>().sqrt()
}

fn finite(p: &[f64; 3]) -> bool {
    p.iter().all(|x| x.is_finite())
}

/// `k` evenly spaced parameters over `[a, b]` (both ends; the middle one for `k = 1`).
pub(crate) fn evenly(a: f64, b: f64, k: usize) -> Vec<f64> {
    match k {
        0 => vec![],
        1 => vec![0.5 * (a + b)],
        _ => (0..k).map(|i| if i + 1 == k { b } else { a + (b - a) * (i as f64 / (k - 1) as f64) }).collect(),
    }
}

/// The frame of `pose` at `t`.
pub(crate) fn frame(t: f64, pose: &Pose<f64>) -> Result<Frame, CliError> {
    let at = |p: [f64; 3]| {
        pose.transform_point(&p)
            .ok()
            .filter(finite)
            .ok_or_else(|| CliError::math(format!("the body frame at t = {} is not finite", format_f64(t))))
    };
    let mut cube = [[0.0; 3]; 8];
    for (c, corner) in cube.iter_mut().enumerate() {
        *corner = at([(c & 1) as f64, ((c >> 1) & 1) as f64, ((c >> 2) & 1) as f64])?;
    }
    let axes = [at([1.0, 0.0, 0.0])?, at([0.0, 1.0, 0.0])?, at([0.0, 0.0, 1.0])?];
    Ok(Frame { t, origin: at([0.0; 3])?, axes, cube })
}

/// The file name of `path` (for legends).
fn file_name(path: &str) -> &str {
    std::path::Path::new(path).file_name().and_then(|s| s.to_str()).unwrap_or(path)
}

/// Whether `path` holds a `gam interpolate` spec (a top-level `method` key), and its JSON.
fn read_json(path: &str) -> Result<Value, CliError> {
    let text = std::fs::read_to_string(path).map_err(|e| CliError::usage(format!("cannot read `{path}`: {e}")))?;
    motion::schema::parse_json(&strip_comments(&text)).map_err(|e| usage(path, e))
}

/// The series of the spec at `path`: `n ≥ 2` samples and `frames` body frames.
pub(crate) fn series(path: &str, n: usize, frames: usize) -> Result<Series, CliError> {
    let spec = read_json(path)?;
    if spec.get("segments").is_some() {
        super::control::series(path, &spec, file_name(path), n, frames)
    } else if spec.get("method").is_some() {
        interpolated(path, n, frames)
    } else {
        hermite(path, n, frames)
    }
}

/// A `gam interpolate` spec over `[t_0, t_m]`.
fn interpolated(path: &str, n: usize, k: usize) -> Result<Series, CliError> {
    let b = built(path)?;
    let m = &b.motion;
    let method = m.method().name().to_string();
    let shape = Shape {
        label: format!("{}: {method}", file_name(path)),
        method,
        segments: m.segments().len(),
        degree: m.max_degree(),
        tableau: crate::budget::Tableau::of_method(m.method()),
        key_times: m.times().to_vec(),
        joins: m.segments().iter().skip(1).map(|s| s.t0).collect(),
    };
    of_motion(shape, m.motion(), b.body_points, n, k)
}

/// What [`of_motion`] is told about a motion besides the motion itself.
pub(crate) struct Shape {
    /// [`Series::label`].
    pub label: String,
    /// [`Series::method`].
    pub method: String,
    /// [`Series::segments`].
    pub segments: usize,
    /// [`Series::degree`].
    pub degree: usize,
    /// What a sample evaluates (for the work estimate).
    pub tableau: crate::budget::Tableau,
    /// [`Series::key_times`] (the first and last are the parameter range).
    pub key_times: Vec<f64>,
    /// [`Series::joins`].
    pub joins: Vec<f64>,
}

/// The series of `motion` (sampled by `motion::trajectory::sample_motion`, one evaluation
/// over second-order dual numbers per parameter) at `n` evenly spaced parameters over the
/// range of `shape.key_times`, with `k` frames.
pub(crate) fn of_motion<M: MapScalar<f64, Jet<Jet<f64>>>>(
    shape: Shape,
    motion: &M,
    body_points: Vec<[f64; 3]>,
    n: usize,
    k: usize,
) -> Result<Series, CliError> {
    let degree = shape.degree;
    crate::budget::check(
        &format!("plotting {} body points of degree-{degree} segments at {n} values", body_points.len()),
        crate::budget::plotting_work(shape.tableau, degree, n + k) * body_points.len().max(1) as f64,
    )?;
    let key_times = shape.key_times;
    let (t0, t1) = (key_times[0], key_times[key_times.len() - 1]);
    let sample = |t: f64| {
        let s = sample_motion(motion, &t, &body_points).map_err(|e| CliError::math(e.to_string()))?;
        let ok = s.points.iter().all(|p| finite(&p.position) && finite(&p.velocity))
            && finite(&s.space_twist.angular.to_array());
        if !ok {
            return Err(CliError::math(format!("the motion at t = {} is not finite (overflow)", format_f64(t))));
        }
        Ok(s)
    };
    let t = evenly(t0, t1, n);
    let mut paths = vec![Vec::with_capacity(n); body_points.len()];
    let mut speeds = vec![Vec::with_capacity(n); body_points.len()];
    let mut angular_speed = Vec::with_capacity(n);
    let mut accelerations = vec![Vec::with_capacity(n); body_points.len()];
    let mut angular_acceleration = Vec::with_capacity(n);
    for ti in &t {
        let s = sample(*ti)?;
        for (j, p) in s.points.iter().enumerate() {
            paths[j].push(p.position);
            speeds[j].push(norm(&p.velocity));
            accelerations[j].push(norm(&p.acceleration));
        }
        angular_speed.push(norm(&s.space_twist.angular.to_array()));
        angular_acceleration.push(norm(&s.space_twist_derivative.angular.to_array()));
    }
    let key_points = key_times
        .iter()
        .map(|tk| Ok(sample(*tk)?.points.iter().map(|p| p.position).collect()))
        .collect::<Result<_, CliError>>()?;
    let frames = evenly(t0, t1, k).into_iter().map(|tf| frame(tf, &sample(tf)?.pose)).collect::<Result<_, _>>()?;
    Ok(Series {
        label: shape.label,
        method: shape.method,
        segments: shape.segments,
        degree,
        body_points,
        key_times,
        joins: shape.joins,
        t,
        paths,
        speeds,
        angular_speed,
        accelerations,
        angular_acceleration,
        key_points,
        frames,
        marks: vec![],
    })
}

/// A `gam hermite` spec: one segment over `[0, 1]`, read as `gam sample` reads it
/// ([`crate::sample::hermite_segment`]), sampled by [`of_motion`] like every other motion.
fn hermite(path: &str, n: usize, k: usize) -> Result<Series, CliError> {
    let (seg, body_point) = crate::sample::hermite_segment(path, &read_spec(path)?)?;
    let (kind, degree) = (seg.kind(), seg.degree());
    // of_motion checks the work of sampling it
    let motion = seg.into_motion().map_err(|e| CliError::math(e.to_string()))?;
    let method = kind.to_string();
    let shape = Shape {
        label: format!("{}: {method}", file_name(path)),
        method,
        segments: 1,
        degree,
        tableau: crate::budget::Tableau::of_segment(kind),
        key_times: vec![0.0, 1.0],
        joins: vec![],
    };
    of_motion(shape, &motion, vec![body_point], n, k)
}
