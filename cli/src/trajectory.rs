//! `gam trajectory [--json] SPEC.json --point x,y,z`: the trajectory of one body point under
//! the motion of a `gam interpolate` spec, as rational Bézier curves (exactly, with `--scalar rational`), one per segment in
//! the segment's local parameter `u ∈ [0, 1]` (Wave 2 contract, shared/cli.md). The spec is
//! built by the one build path of `gam interpolate` (`motion::method::Method::build`); the
//! curves come from `motion::method::BuiltMotion::rational_trajectories`, i.e. the
//! `motion::juttler::RationalMotion` trait. Methods whose motions are not rational
//! (multiplicative, W-L, hexanion) exit 2 with one `error:` line saying so. With
//! `--scalar rational` the curves are exact (`motion::method::Method::build_exact`), with
//! `--scalar mpfr:BITS` computed at that precision ([`crate::precision`]).

use crate::error::CliError;
use crate::interpolate::{build, read_spec, usage};
use crate::precision::{self, MotionScalar, OutScalar, json_list};
use crate::scalar::CliScalar;
use algebra_core::rational::{parse_rational, rational_to_f64};
use algebra_core::{MpFloat, Ring};
use motion::method::{BuildError, Method, RationalSegment};
use motion::schema::InterpolateSpec;
use serde_json::{Value, json};

/// `x,y,z` of `--point`: three finite numbers (decimals, or `p/q` rounded to the nearest f64).
pub(crate) fn point(text: &str) -> Result<[f64; 3], CliError> {
    let bad = || CliError::usage(format!("`--point {text}`: expected three finite numbers `x,y,z`"));
    let number = |s: &str| {
        s.trim().parse::<f64>().ok().or_else(|| parse_rational(s).ok().map(|q| rational_to_f64(&q))).ok_or_else(bad)
    };
    let v: Vec<f64> = text.split(',').map(number).collect::<Result<_, _>>()?;
    match v[..] {
        [x, y, z] if v.iter().all(|c| c.is_finite()) => Ok([x, y, z]),
        _ => Err(bad()),
    }
}

/// One segment's curve: `t0`, `t1`, degree, weights, affine control points.
type Curve<T> = (T, T, usize, Vec<T>, Vec<[T; 3]>);

/// The curves of rational segments (of `method`, for body point `x`), checked finite.
fn curves_of<T: OutScalar>(
    method: Method,
    x: &[T; 3],
    segments: Result<Vec<RationalSegment<T>>, BuildError>,
    label: &str,
) -> Result<Vec<Curve<T>>, CliError> {
    let x_text = || format!("[{}]", x.iter().map(OutScalar::text).collect::<Vec<_>>().join(", "));
    let segments = segments.map_err(|e| rational_error(method, label, e))?;
    let mut out = Vec::with_capacity(segments.len());
    for s in segments {
        let weights = s.curve.weights();
        let points =
            s.curve.points().map_err(|e| CliError::math(format!("{method}: the trajectory of {}: {e}", x_text())))?;
        if !weights.iter().chain(points.iter().flatten()).all(CliScalar::finite) {
            return Err(CliError::math(format!("{method}: the trajectory of {} is not finite (overflow)", x_text())));
        }
        out.push((s.t0, s.t1, s.curve.degree(), weights, points));
    }
    Ok(out)
}

/// A refusal of a motion's rational segments (`gam trajectory`, `gam surface`): a method whose
/// motions are not rational is bad input (exit 2, `label` names the spec), anything else a
/// mathematical failure of the method (exit 1).
pub(crate) fn rational_error(method: Method, label: &str, e: BuildError) -> CliError {
    match e {
        BuildError::NotRational { .. } => usage(label, e),
        e => CliError::math(format!("{method}: {e}")),
    }
}

/// The curves of body point `x` under the f64 motion of a spec (`label` names it in messages).
fn curves(label: &str, spec: &InterpolateSpec, x: &[f64; 3]) -> Result<(Method, Vec<Curve<f64>>), CliError> {
    let b = build(label, spec)?;
    let method = b.motion.method();
    Ok((method, curves_of(method, x, b.motion.rational_trajectories(x), label)?))
}

/// The `--json` object of curves.
fn curves_json<T: OutScalar>(curves: &[Curve<T>]) -> Value {
    let segs: Vec<_> = curves
        .iter()
        .map(|(t0, t1, d, w, p)| {
            json!({"t0": t0.json(), "t1": t1.json(), "degree": d, "weights": json_list(w),
                "points": p.iter().map(|q| json_list(q)).collect::<Vec<_>>()})
        })
        .collect();
    json!({ "segments": segs })
}

/// The human form of curves.
fn curves_text<T: OutScalar>(method: Method, x: &[T; 3], curves: &[Curve<T>]) -> String {
    let f = |c: &T| c.text();
    let list = |v: &[T]| v.iter().map(f).collect::<Vec<_>>().join(", ");
    let mut lines = vec![format!(
        "{method}: trajectory of [{}] as {} rational Bézier curves (local parameter u in [0, 1])",
        list(x),
        curves.len()
    )];
    for (k, (t0, t1, d, w, p)) in curves.iter().enumerate() {
        lines.push(format!("segment {k} (t = {} .. {}): degree {d}", f(t0), f(t1)));
        for (j, (wj, pj)) in w.iter().zip(p).enumerate() {
            lines.push(format!("  w{j} = {}, P{j} = [{}]", f(wj), list(pj)));
        }
    }
    lines.join("\n")
}

/// `gam trajectory --json` of a spec (`label` names it in messages) and body point `x`.
pub fn trajectory_json(label: &str, spec: &InterpolateSpec, x: &[f64; 3]) -> Result<Value, CliError> {
    Ok(curves_json(&curves(label, spec, x)?.1))
}

/// The output of curves, JSON or human.
fn render<T: OutScalar>(method: Method, x: &[T; 3], curves: &[Curve<T>], json: bool) -> String {
    if json { curves_json(curves).to_string() } else { curves_text(method, x, curves) }
}

/// Runs `gam trajectory` on the spec file at `path`, in the scalar of `--scalar`.
pub fn trajectory(path: &str, point_text: &str, json: bool, scalar: MotionScalar) -> Result<String, CliError> {
    if scalar == MotionScalar::F64 {
        let x = point(point_text)?;
        let (method, out) = curves(path, &read_spec(path)?, &x)?;
        return Ok(render(method, &x, &out, json));
    }
    trajectory_in(path, &precision::read_file(path)?, point_text, json, scalar)
}

/// `gam trajectory` of the spec text `text` (named `label` in messages) over exact rationals
/// or MPFR: the JSON text or the human form.
pub(crate) fn trajectory_in(
    label: &str,
    text: &str,
    point_text: &str,
    json: bool,
    scalar: MotionScalar,
) -> Result<String, CliError> {
    let x = precision::point_exact(point_text)?;
    let spec = precision::exact_spec(label, text)?;
    if scalar == MotionScalar::Rational {
        let m = precision::build_exact(label, &spec)?;
        let out = curves_of(m.method(), &x, m.rational_trajectories(&x), label)?;
        return Ok(render(m.method(), &x, &out, json));
    }
    scalar.run(|| {
        let x = x.each_ref().map(MpFloat::from_rational);
        let b = precision::build_mpfr(label, &spec)?;
        let out = curves_of(b.method(), &x, b.rational_trajectories(&x), label)?;
        Ok(render(b.method(), &x, &out, json))
    })
}
