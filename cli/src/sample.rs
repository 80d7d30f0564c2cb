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
use crate::scalar::format_f64;
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

/// One sample of the motion.
pub(crate) struct Sample {
    /// The parameter value.
    pub t: f64,
    /// `S(t)`.
    pub pose: Pose<f64>,
    /// The current position of the body point.
    pub position: [f64; 3],
    /// `|v|`: the speed of the body point.
    pub linear_speed: f64,
    /// `|Ω|`.
    pub angular_speed: f64,
}

fn norm(v: &[f64; 3]) -> f64 {
    v.iter().map(|x| x * x).sum::<f64>().sqrt()
}

/// The samples of a spec, computed one at a time (streamed for the text table and for
/// `--json`, [`sample_json`]).
pub(crate) struct Sampler {
    /// Additive or multiplicative.
    pub kind: SegmentKind,
    /// The degree of the segment(s).
    pub degree: usize,
    /// The number of segments (1 for a `gam hermite` spec).
    pub segments: usize,
    /// The body point (body coordinates).
    pub body_point: [f64; 3],
    /// The number of samples.
    pub n: usize,
    /// Sample `i` of `n`, checked finite.
    pub at: Box<dyn Fn(usize) -> Result<Sample, CliError>>,
}

/// A sample with every number checked finite.
pub(crate) fn checked(sample: Sample) -> Result<Sample, CliError> {
    let m = &sample.pose;
    let coefficients = [m.scalar, m.e12, m.e13, m.e23, m.e1inf, m.e2inf, m.e3inf, m.e123inf];
    let all = coefficients.iter().chain(&sample.position).chain([&sample.linear_speed, &sample.angular_speed]);
    if all.into_iter().all(|x| x.is_finite()) {
        Ok(sample)
    } else {
        Err(CliError::math(format!("the result at t = {} is not finite (overflow)", format_f64(sample.t))))
    }
}

/// The segment of a `gam hermite` spec `label` and its body point (default the body origin;
/// an error when not finite), as `gam sample` and `gam plot` read them.
pub(crate) fn hermite_segment(label: &str, spec: &HermiteSpec) -> Result<(AnyHermiteSegment<f64>, [f64; 3]), CliError> {
    let body_point = spec.body_point.unwrap_or([0.0; 3]);
    if !body_point.iter().all(|x| x.is_finite()) {
        return Err(CliError::usage(format!("`{label}`: `body_point` must be finite")));
    }
    Ok((build_segment(spec)?, body_point))
}

/// Checks the work of `passes` passes over `n` samples of a spec (`label` names it in
/// messages) and returns its sampler.
pub(crate) fn sampler(label: &str, spec: &SampleSpec, n: usize, passes: usize) -> Result<Sampler, CliError> {
    if !(2..=MAX_SAMPLES).contains(&n) {
        return Err(CliError::usage(format!("`--samples` must be an integer from 2 to {MAX_SAMPLES} (got {n})")));
    }
    let spec = match spec {
        SampleSpec::Interpolate(spec) => return crate::interpolate::spec_sampler(label, spec, n, passes),
        SampleSpec::Hermite(spec) => spec,
    };
    let (seg, body_point) = hermite_segment(label, spec)?;
    let (kind, degree) = (seg.kind(), seg.degree());
    // building the segment is O(degree); sampling it is O(samples x degree^2)
    let work = crate::budget::sampling_work(Tableau::of_segment(kind), degree, n, passes);
    crate::budget::check(&format!("sampling degree {degree} at {n} values"), work)?;
    let curve = |e: motion::CurveError| CliError::math(e.to_string());
    let motion: AnyMotion<f64> = seg.into_motion().map_err(curve)?;
    let last = (n - 1) as f64;
    let at = move |i: usize| {
        let t = i as f64 / last;
        let vel = velocity(&motion, &t).map_err(|e| CliError::math(format!("at t = {}: {e}", format_f64(t))))?;
        let (position, v) = vel
            .body_point_velocity(&body_point)
            .map_err(|e| CliError::math(format!("at t = {}: {e}", format_f64(t))))?;
        checked(Sample {
            t,
            linear_speed: norm(&v),
            angular_speed: norm(&vel.twist().angular.to_array()),
            position,
            pose: vel.pose,
        })
    };
    Ok(Sampler { kind, degree, segments: 1, body_point, n, at: Box::new(at) })
}

/// One sample as the JSON object of `gam sample --json`.
fn one_json(x: &Sample) -> Value {
    json!({
        "t": x.t,
        "pose": mv_json(&x.pose.to_multivector()),
        "position": x.position,
        "linear_speed": x.linear_speed,
        "angular_speed": x.angular_speed,
    })
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
fn text_row(x: &Sample) -> Vec<String> {
    let mut row = vec![format_f64(x.t)];
    row.extend(x.position.iter().map(|c| format_f64(*c)));
    row.push(format_f64(x.linear_speed));
    row.push(format_f64(x.angular_speed));
    row.push(mv_human(&x.pose.to_multivector()));
    row
}

/// The text header of `gam sample`.
const HEADER: [&str; 7] = ["t", "x", "y", "z", "linear speed", "angular speed", "pose"];

/// Runs `gam sample`: `--json` and the text table are both written to standard output in
/// bounded memory (and an empty string returned). The text table's columns are aligned, so
/// the samples are computed twice: once to check them all and measure the columns (nothing
/// is printed if one fails), once to print them; a million samples no longer hold their
/// text (1.9 GB) in memory.
pub fn sample(path: &str, n: usize, json: bool) -> Result<String, CliError> {
    let spec = SampleSpec::read(path)?;
    if json {
        return sample_json(path, &spec, n)?.stream();
    }
    let s = sampler(path, &spec, n, 2)?;
    write_text(s, &mut std::io::BufWriter::new(std::io::stdout().lock())).map_err(|e| match e {
        TextError::Cli(e) => e,
        TextError::Io(e) => write_error(e),
    })?;
    Ok(String::new())
}

/// A failure while writing the text table: of a sample, or of the output.
enum TextError {
    Cli(CliError),
    Io(std::io::Error),
}

/// The text table of `gam sample` written to `out`, the samples computed twice (see
/// [`sample`]).
fn write_text(s: Sampler, out: &mut impl Write) -> Result<(), TextError> {
    let mut widths = HEADER.map(|h| h.chars().count());
    for i in 0..s.n {
        for (w, cell) in widths.iter_mut().zip(text_row(&(s.at)(i).map_err(TextError::Cli)?)) {
            *w = (*w).max(cell.chars().count());
        }
    }
    let title = crate::plot::title(&s);
    let mut line = |text: String| writeln!(out, "{text}").map_err(TextError::Io);
    line(format!("{title}, {} samples", s.n))?;
    line(table_line(&HEADER.map(str::to_string), &widths))?;
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
