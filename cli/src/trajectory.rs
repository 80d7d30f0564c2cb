//! `gam trajectory [--json] SPEC.json --point x,y,z`: the trajectory of one body point under
//! the motion of a `gam interpolate` spec, as exact rational Bézier curves, one per segment in
//! the segment's local parameter `u ∈ [0, 1]` (Wave 2 contract, shared/cli.md). The spec is
//! built by the one build path of `gam interpolate` (`motion::method::Method::build`); the
//! curves come from `motion::method::BuiltMotion::rational_trajectories`, i.e. the
//! `motion::juttler::RationalMotion` trait. Methods whose motions are not rational
//! (multiplicative, W-L, hexanion) exit 2 with one `error:` line saying so.

use crate::error::CliError;
use crate::interpolate::{build, read_spec, usage};
use crate::scalar::format_f64;
use motion::method::{BuildError, Method};
use motion::schema::InterpolateSpec;
use serde_json::{Value, json};

/// `x,y,z` of `--point`: three finite numbers.
pub(crate) fn point(text: &str) -> Result<[f64; 3], CliError> {
    let bad = || CliError::usage(format!("`--point {text}`: expected three finite numbers `x,y,z`"));
    let v: Vec<f64> = text.split(',').map(|s| s.trim().parse::<f64>().map_err(|_| bad())).collect::<Result<_, _>>()?;
    match v[..] {
        [x, y, z] if v.iter().all(|c| c.is_finite()) => Ok([x, y, z]),
        _ => Err(bad()),
    }
}

/// One segment's curve: `t0`, `t1`, degree, weights, affine control points.
type Curve = (f64, f64, usize, Vec<f64>, Vec<[f64; 3]>);

/// The rational Bézier curves of body point `x` under the motion of a spec (`label` names it
/// in messages), checked finite.
fn curves(label: &str, spec: &InterpolateSpec, x: &[f64; 3]) -> Result<(Method, Vec<Curve>), CliError> {
    let b = build(label, spec)?;
    let method = b.motion.method();
    let segments = b.motion.rational_trajectories(x).map_err(|e| match e {
        BuildError::NotRational { .. } => usage(label, e),
        e => CliError::math(format!("{method}: {e}")),
    })?;
    let mut out = Vec::with_capacity(segments.len());
    for s in &segments {
        let weights = s.curve.weights();
        let points = s.curve.points().map_err(|e| CliError::math(format!("{method}: the trajectory of {x:?}: {e}")))?;
        let finite = weights.iter().chain(points.iter().flatten()).all(|c| c.is_finite());
        if !finite {
            return Err(CliError::math(format!("{method}: the trajectory of {x:?} is not finite (overflow)")));
        }
        out.push((s.t0, s.t1, s.curve.degree(), weights, points));
    }
    Ok((method, out))
}

/// `gam trajectory --json` of a spec (`label` names it in messages) and body point `x`.
pub fn trajectory_json(label: &str, spec: &InterpolateSpec, x: &[f64; 3]) -> Result<Value, CliError> {
    let z = |c: f64| c + 0.0;
    let segs: Vec<_> = curves(label, spec, x)?
        .1
        .iter()
        .map(|(t0, t1, d, w, p)| {
            json!({"t0": t0, "t1": t1, "degree": d, "weights": w.iter().map(|c| z(*c)).collect::<Vec<_>>(),
                "points": p.iter().map(|q| q.map(z)).collect::<Vec<_>>()})
        })
        .collect();
    Ok(json!({ "segments": segs }))
}

/// Runs `gam trajectory` on the spec file at `path`.
pub fn trajectory(path: &str, point_text: &str, json: bool) -> Result<String, CliError> {
    let x = point(point_text)?;
    let spec = read_spec(path)?;
    if json {
        return Ok(trajectory_json(path, &spec, &x)?.to_string());
    }
    let (method, out) = curves(path, &spec, &x)?;
    let f = |c: &f64| format_f64(*c);
    let mut lines = vec![format!(
        "{method}: trajectory of [{}] as {} rational Bézier curves (local parameter u in [0, 1])",
        x.iter().map(f).collect::<Vec<_>>().join(", "),
        out.len()
    )];
    for (k, (t0, t1, d, w, p)) in out.iter().enumerate() {
        lines.push(format!("segment {k} (t = {} .. {}): degree {d}", f(t0), f(t1)));
        for (j, (wj, pj)) in w.iter().zip(p).enumerate() {
            lines.push(format!("  w{j} = {}, P{j} = [{}]", f(wj), pj.iter().map(f).collect::<Vec<_>>().join(", ")));
        }
    }
    Ok(lines.join("\n"))
}
