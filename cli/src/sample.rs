//! `gam sample SPEC.json --samples N [--json]`: the Hermite segment of a `gam hermite` spec
//! (see [`crate::hermite`]) sampled at `N` evenly spaced parameter values `t = 0..1` (or the
//! motion of a `gam interpolate` spec over `[t_0, t_m]`, [`crate::interpolate::spec_sampler`]): the pose,
//! the position of a body point (`body_point` in the spec, body coordinates, default the
//! origin), its linear speed and the angular speed of the body.
//!
//! Speeds are derivatives with respect to the segment parameter `t`, computed by
//! `motion::velocity::velocity`, which evaluates the same motion over dual numbers (never
//! finite differences): the linear speed is `|v|` of eq. (14) at the current position of the
//! body point, the angular speed `|Ω|` of `ν = Ω e123 + u einf` (Theorem 3.2).

use crate::budget::Tableau;
use crate::error::CliError;
use crate::hermite::{build_segment, read_spec};
#[cfg(test)]
use crate::output::text_table;
use crate::output::{Streamed, mv_human, mv_json, table_line, table_rule};
use crate::precision::{self, MotionScalar, OutScalar, json_list};
use crate::scalar::CliScalar;
use algebra_core::rational::Q;
use algebra_core::{MpFloat, Real, Ring};
use motion::schema::InterpolateSpec;
use motion::spec::HermiteSpec;
use motion::velocity::velocity;
use motion::{AnyHermiteSegment, AnyMotion, Pose, SegmentKind};
use serde_json::{Value, json};
use std::io::Write;

/// The most samples accepted.
pub(crate) const MAX_SAMPLES: usize = motion::schema::MAX_SAMPLES;

/// A spec `gam sample` and `gam plot` read: a `gam hermite` spec (with an optional
/// `body_point`) or a `gam interpolate` spec (with a top-level `method`).
pub enum SampleSpec {
    /// A `gam hermite` spec.
    Hermite(HermiteSpec),
    /// A `gam interpolate` spec.
    Interpolate(InterpolateSpec),
}

impl SampleSpec {
    /// The spec of an already parsed JSON value (`label` names it in messages).
    pub fn from_value(label: &str, v: &Value) -> Result<Self, CliError> {
        if v.get("method").is_some() {
            let spec = InterpolateSpec::from_value(v).map_err(|e| crate::interpolate::schema_error(label, e))?;
            return Ok(SampleSpec::Interpolate(spec));
        }
        let spec = HermiteSpec::from_value(v).map_err(|e| crate::hermite::spec_error(label, e))?;
        Ok(SampleSpec::Hermite(spec))
    }

    /// The spec in the file at `path`.
    fn read(path: &str) -> Result<Self, CliError> {
        match crate::interpolate::read(path)? {
            Some(spec) => Ok(SampleSpec::Interpolate(spec)),
            None => Ok(SampleSpec::Hermite(read_spec(path)?)),
        }
    }
}

/// One sample of the motion (`f64` unless `--scalar` says otherwise).
pub(crate) struct Sample<T = f64> {
    /// The parameter value.
    pub t: T,
    /// `S(t)`.
    pub pose: Pose<T>,
    /// The current position of the body point.
    pub position: [T; 3],
    /// `|v|`: the speed of the body point (`None` over exact rationals: a square root).
    pub linear_speed: Option<T>,
    /// `|Ω|` (`None` over exact rationals).
    pub angular_speed: Option<T>,
}

/// `|v|`.
pub(crate) fn norm<T: Real>(v: &[T; 3]) -> T {
    Real::sqrt(&v.iter().fold(T::zero(), |acc, x| acc.add_ref(&x.mul_ref(x))))
}

/// The samples of a spec, computed one at a time (streamed for the text table and for
/// `--json`, [`sample_json`]).
pub(crate) struct Sampler<T = f64> {
    /// Additive or multiplicative.
    pub kind: SegmentKind,
    /// The degree of the segment(s).
    pub degree: usize,
    /// The number of segments (1 for a `gam hermite` spec).
    pub segments: usize,
    /// The body point (body coordinates).
    pub body_point: [T; 3],
    /// The number of samples.
    pub n: usize,
    /// Sample `i` of `n`, checked finite.
    pub at: Box<dyn Fn(usize) -> Result<Sample<T>, CliError>>,
}

/// A sample with every number checked finite.
pub(crate) fn checked<T: OutScalar>(sample: Sample<T>) -> Result<Sample<T>, CliError> {
    let all = sample.pose.components().into_iter().chain(&sample.position);
    if all.chain(sample.linear_speed.iter()).chain(sample.angular_speed.iter()).all(CliScalar::finite) {
        Ok(sample)
    } else {
        Err(CliError::math(format!("the result at t = {} is not finite (overflow)", sample.t.text())))
    }
}

/// The segment of a `gam hermite` spec `label` and its body point (default the body origin;
/// an error when not finite), as `gam sample` and `gam plot` read them.
pub(crate) fn hermite_segment<T: Real>(
    label: &str,
    spec: &HermiteSpec<T>,
) -> Result<(AnyHermiteSegment<T>, [T; 3]), CliError> {
    let body_point = spec.body_point.clone().unwrap_or_else(|| [T::zero(), T::zero(), T::zero()]);
    if !body_point.iter().all(Real::is_finite) {
        return Err(CliError::usage(format!("`{label}`: `body_point` must be finite")));
    }
    Ok((build_segment(spec)?, body_point))
}

/// Checks the work of `passes` passes over `n` samples of a spec (`label` names it in
/// messages) and returns its sampler.
pub(crate) fn sampler(label: &str, spec: &SampleSpec, n: usize, passes: usize) -> Result<Sampler, CliError> {
    check_count(n)?;
    match spec {
        SampleSpec::Interpolate(spec) => crate::interpolate::spec_sampler(label, spec, n, passes),
        SampleSpec::Hermite(spec) => hermite_sampler(label, spec, n, passes),
    }
}

/// The sampler of a `gam hermite` spec over a real scalar: `t = i/(n-1)`.
fn hermite_sampler<T: Real + OutScalar>(
    label: &str,
    spec: &HermiteSpec<T>,
    n: usize,
    passes: usize,
) -> Result<Sampler<T>, CliError> {
    let (seg, body_point) = hermite_segment(label, spec)?;
    let (kind, degree) = (seg.kind(), seg.degree());
    // building the segment is O(degree); sampling it is O(samples x degree^2)
    let work = crate::budget::sampling_work(Tableau::of_segment(kind), degree, n, passes);
    crate::budget::check(&format!("sampling degree {degree} at {n} values"), work)?;
    let curve = |e: motion::CurveError| CliError::math(e.to_string());
    let motion: AnyMotion<T> = seg.into_motion().map_err(curve)?;
    let point = body_point.clone();
    let at = move |i: usize| {
        let t = T::from_ratio(i as i64, n as i64 - 1);
        let at_t = |e: &dyn std::fmt::Display| CliError::math(format!("at t = {}: {e}", t.text()));
        let vel = velocity(&motion, &t).map_err(|e| at_t(&e))?;
        let (position, v) = vel.body_point_velocity(&point).map_err(|e| at_t(&e))?;
        let angular_speed = norm(&vel.twist().angular.to_array());
        checked(Sample {
            t,
            linear_speed: Some(norm(&v)),
            angular_speed: Some(angular_speed),
            position,
            pose: vel.pose,
        })
    };
    Ok(Sampler { kind, degree, segments: 1, body_point, n, at: Box::new(at) })
}

/// One sample as the JSON object of `gam sample --json`.
fn one_json<T: OutScalar>(x: &Sample<T>) -> Value {
    let mut v = json!({"t": x.t.json(), "pose": mv_json(&x.pose.to_multivector()), "position": json_list(&x.position)});
    for (key, speed) in [("linear_speed", &x.linear_speed), ("angular_speed", &x.angular_speed)] {
        if let Some(speed) = speed {
            v[key] = speed.json();
        }
    }
    v
}

/// `gam sample --json` of a spec (`label` names it in messages): streamed by the CLI in
/// bounded memory, or taken as one value by another front door ([`Streamed::into_value`]).
pub fn sample_json<'a>(label: &str, spec: &SampleSpec, n: usize) -> Result<Streamed<'a>, CliError> {
    let s = sampler(label, spec, n, 2)?;
    Ok(Streamed { head: json!({}), n: s.n, sample: Box::new(move |i| Ok(one_json(&(s.at)(i)?))) })
}

/// A failed write of streamed output: a closed pipe (`gam sample --json ... | head`) ends the
/// run successfully, as `main` does for buffered output; anything else is an error line.
pub(crate) fn write_error(e: std::io::Error) -> CliError {
    if e.kind() == std::io::ErrorKind::BrokenPipe {
        std::process::exit(0);
    }
    CliError::usage(format!("cannot write the output: {e}"))
}

/// The text row of a sample: `t`, `x`, `y`, `z`, the two speeds, the pose (human form).
/// (Speeds left out over exact rationals.)
fn text_row<T: OutScalar>(x: &Sample<T>) -> Vec<String> {
    let mut row = vec![x.t.text()];
    row.extend(x.position.iter().map(OutScalar::text));
    row.extend(x.linear_speed.iter().chain(&x.angular_speed).map(OutScalar::text));
    row.push(mv_human(&x.pose.to_multivector()));
    row
}

/// The text header of `gam sample`.
const HEADER: [&str; 7] = ["t", "x", "y", "z", "linear speed", "angular speed", "pose"];

/// The header of samples with (or, over exact rationals, without) the speed columns.
fn header(speeds: bool) -> Vec<String> {
    HEADER.iter().filter(|h| speeds || !h.ends_with("speed")).map(|h| h.to_string()).collect()
}

/// Runs `gam sample`: `--json` and the text table are both written to standard output in
/// bounded memory (and an empty string returned). The text table's columns are aligned, so
/// the samples are computed twice: once to check them all and measure the columns (nothing
/// is printed if one fails), once to print them; a million samples no longer hold their
/// text (1.9 GB) in memory.
pub fn sample(path: &str, n: usize, json: bool, scalar: MotionScalar) -> Result<String, CliError> {
    match scalar {
        MotionScalar::F64 => {
            let spec = SampleSpec::read(path)?;
            if json {
                return sample_json(path, &spec, n)?.stream();
            }
            output(sampler(path, &spec, n, 2)?, false)
        }
        MotionScalar::Rational => {
            check_count(n)?;
            let Some(spec) = precision::exact_spec_if_any(path, &precision::read_file(path)?)? else {
                return Err(CliError::usage(format!("`{path}`: gam sample: {}", crate::hermite::NOT_EXACT)));
            };
            output(exact_sampler(path, &spec, n)?, json)
        }
        MotionScalar::Mpfr(_) => scalar.run(|| {
            check_count(n)?;
            let to = |x: &motion::schema::Exact| MpFloat::from_rational(&x.0);
            let text = precision::read_file(path)?;
            let s = match precision::exact_spec_if_any(path, &text)? {
                Some(spec) => {
                    let b = precision::build_mpfr(path, &spec)?;
                    let body = precision::body_points(&spec).swap_remove(0).each_ref().map(MpFloat::from_rational);
                    let factor = scalar.cost_factor(b.key_poses().len());
                    crate::interpolate::motion_sampler(b, Some(body), (n, 2, factor))?
                }
                None => {
                    let spec = crate::hermite::exact_spec(path, &text)?.map(&to);
                    spec.check().map_err(|e| crate::hermite::spec_error(path, e))?;
                    hermite_sampler(path, &spec, n, 2)?
                }
            };
            output(s, json)
        }),
    }
}

/// `--samples` from 2 to [`MAX_SAMPLES`].
fn check_count(n: usize) -> Result<(), CliError> {
    if (2..=MAX_SAMPLES).contains(&n) {
        Ok(())
    } else {
        Err(CliError::usage(format!("`--samples` must be an integer from 2 to {MAX_SAMPLES} (got {n})")))
    }
}

/// The output of a sampler: `--json` streamed, or the text table (see [`sample`]).
fn output<T: OutScalar + 'static>(s: Sampler<T>, json: bool) -> Result<String, CliError> {
    if json {
        let at = s.at;
        return Streamed { head: json!({}), n: s.n, sample: Box::new(move |i| Ok(one_json(&at(i)?))) }.stream();
    }
    write_text(s, &mut std::io::BufWriter::new(std::io::stdout().lock())).map_err(|e| match e {
        TextError::Cli(e) => e,
        TextError::Io(e) => write_error(e),
    })?;
    Ok(String::new())
}

/// The sampler of a `gam interpolate` spec over exact rationals: the pose and the position of
/// the body point exactly; the speeds (square roots) are left out.
fn exact_sampler(path: &str, spec: &InterpolateSpec<motion::schema::Exact>, n: usize) -> Result<Sampler<Q>, CliError> {
    let m = precision::build_exact(path, spec)?;
    let body_point = precision::body_points(spec).swap_remove(0);
    let degree = m.segments().iter().map(|s| s.degree).max().unwrap_or(0);
    crate::interpolate::check_segments(
        m.method(),
        m.segments(),
        1,
        n,
        2,
        MotionScalar::Rational.cost_factor(m.key_poses().len()),
    )?;
    let (kind, segments, point) = (m.method().kind(), m.segments().len(), body_point.clone());
    let at = move |i: usize| {
        let times = m.times();
        let t = crate::interpolate::even(&times[0], &times[times.len() - 1], n, i);
        let math = |e: &dyn std::fmt::Display| CliError::math(format!("{}: at t = {}: {e}", m.method(), t.text()));
        let s = m.sample(&t, std::slice::from_ref(&point)).map_err(|e| math(&e))?;
        let pose = m.pose(&t).map_err(|e| math(&e))?;
        let position = s.points.into_iter().next().unwrap_or_else(|| point.clone());
        Ok(Sample { t, pose, position, linear_speed: None, angular_speed: None })
    };
    Ok(Sampler { kind, degree, segments, body_point, n, at: Box::new(at) })
}

/// A failure while writing the text table: of a sample, or of the output.
enum TextError {
    Cli(CliError),
    Io(std::io::Error),
}

/// The text table of `gam sample` written to `out`, the samples computed twice (see
/// [`sample`]).
fn write_text<T: OutScalar>(s: Sampler<T>, out: &mut impl Write) -> Result<(), TextError> {
    // the columns: with the speeds, or without them over exact rationals
    let (mut speeds, mut widths) = (true, None::<Vec<usize>>);
    for i in 0..s.n {
        let sample = (s.at)(i).map_err(TextError::Cli)?;
        let w = widths.get_or_insert_with(|| {
            speeds = sample.linear_speed.is_some();
            header(speeds).iter().map(|h| h.chars().count()).collect()
        });
        for (w, cell) in w.iter_mut().zip(text_row(&sample)) {
            *w = (*w).max(cell.chars().count());
        }
    }
    let head = header(speeds);
    let widths = widths.unwrap_or_else(|| head.iter().map(|h| h.chars().count()).collect());
    let title = crate::plot::title(&s);
    let mut line = |text: String| writeln!(out, "{text}").map_err(TextError::Io);
    line(format!("{title}, {} samples", s.n))?;
    line(table_line(&head, &widths))?;
    line(table_rule(&widths))?;
    for i in 0..s.n {
        line(table_line(&text_row(&(s.at)(i).map_err(TextError::Cli)?), &widths))?;
    }
    out.flush().map_err(TextError::Io)
}

/// All samples of a spec as `gam sample`'s text table, in memory (tests and other front
/// doors): the same text the command streams.
#[cfg(test)]
fn sample_text(path: &str, n: usize) -> Result<String, CliError> {
    let s = sampler(path, &SampleSpec::read(path)?, n, 1)?;
    let samples = (0..s.n).map(|i| (s.at)(i)).collect::<Result<Vec<_>, _>>()?;
    let mut rows = vec![HEADER.map(str::to_string).to_vec()];
    rows.extend(samples.iter().map(text_row));
    let title = format!("{}, {} samples", crate::plot::title(&s), samples.len());
    Ok(format!("{title}\n{}", text_table(&rows)))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The streamed table is the in-memory [`text_table`] of the same samples, byte for byte
    /// (plus the final newline), for a Hermite and an interpolate spec.
    #[test]
    fn streamed_text_is_the_table() {
        let dir = std::env::temp_dir();
        let hermite = dir.join("gam-sample-stream-hermite.json");
        std::fs::write(
            &hermite,
            r#"{"kind": "multiplicative", "degree": 5,
                "start": {"position": [0, 0, 0], "axis": [0, 0, 1], "angle": 0, "velocity": [1, 1, 1], "angular_velocity": [1, 2, 3]},
                "end": {"position": [8, 10, 12], "axis": [1, 2, 3], "angle": 2, "velocity": [1, 2, 5], "angular_velocity": [1, 1, 2]},
                "body_point": [0.5, -1, 2]}"#,
        )
        .unwrap();
        let interpolate = dir.join("gam-sample-stream-interpolate.json");
        std::fs::write(
            &interpolate,
            r#"{"method": "ccm-multiplicative", "poses": [{"position": [0, 0, 0]}, {"position": [1, 1, 0], "axis": [0, 0, 1], "angle": 1}, {"position": [2, 0, 1]}]}"#,
        )
        .unwrap();
        for path in [&hermite, &interpolate] {
            let path = path.to_str().unwrap();
            for n in [2, 7, 101] {
                let mut streamed = Vec::new();
                let spec = SampleSpec::read(path).unwrap();
                assert!(write_text(sampler(path, &spec, n, 2).unwrap(), &mut streamed).is_ok());
                let want = sample_text(path, n).unwrap() + "\n";
                assert_eq!(String::from_utf8(streamed).unwrap(), want, "{path}, {n} samples");
            }
        }
    }
}
