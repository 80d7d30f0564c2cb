//! `gam hermite [--json] SPEC.json`: a Bezier motion segment of degree `n` from its end
//! conditions (Secs. 4-5 of the main paper), exactly as in the contract (shared/cli.md).
//!
//! The spec gives, at each end, the position of the reference point, the rotation (axis,
//! normalised, and angle), the velocity of the reference point and the angular velocity, and
//! optionally the shape factor `shape` (λ, default 1, positive) and `gamma` (`[α, β]` for
//! `α + βω`, default `[0, 0]`). The end poses are `S = R T`; `ν = Ω e123 + u einf` with
//! `u = v - Ω × r`; `Ψ = λ(ν + γ)`; the control poses next to the ends follow eq. (22)
//! (additive) or eq. (23) (multiplicative), read as in Sec. 5.2 (`motion::joins`). Degrees
//! above 3 spread the inner control poses evenly from `S1` to `S_{n-1}`
//! (`motion::hermite::hermite_segment`).
//!
//! The file is JSON; `//` comments (outside strings) are allowed, as in the contract's example.

use crate::error::CliError;
use crate::output::{mv_human, mv_json};
use motion::HermiteSegment;
use motion::hermite::hermite_segment;
use motion::{EndCondition, Even, JoinError, MotionError, Pseudoscalar, SegmentKind, Shape};
use serde::Deserialize;
use serde_json::{Value, json};

/// The largest degree accepted (a segment of degree `n` has `n + 1` control poses).
const MAX_DEGREE: i64 = 10_000;

/// The segment kind, as spelled in the spec.
#[derive(Debug, Clone, Copy, Deserialize)]
#[serde(rename_all = "lowercase")]
enum Kind {
    Additive,
    Multiplicative,
}

/// The whole spec.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct Spec {
    kind: Kind,
    degree: i64,
    start: EndSpec,
    end: EndSpec,
    /// The body point of `gam sample` / `gam plot` (body coordinates); `gam hermite` rejects it.
    #[serde(default)]
    pub(crate) body_point: Option<[f64; 3]>,
}

/// One end condition.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct EndSpec {
    position: [f64; 3],
    axis: [f64; 3],
    angle: f64,
    velocity: [f64; 3],
    angular_velocity: [f64; 3],
    #[serde(default = "one")]
    shape: f64,
    #[serde(default)]
    gamma: [f64; 2],
}

fn one() -> f64 {
    1.0
}

/// Replaces `//` comments outside JSON strings by spaces (line and column numbers unchanged).
fn strip_comments(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    let mut chars = text.chars().peekable();
    let (mut in_string, mut escaped, mut in_comment) = (false, false, false);
    while let Some(c) = chars.next() {
        if in_comment {
            if c == '\n' {
                in_comment = false;
                out.push(c);
            } else {
                out.extend(std::iter::repeat_n(' ', c.len_utf8()));
            }
            continue;
        }
        if in_string {
            if escaped {
                escaped = false;
            } else if c == '\\' {
                escaped = true;
            } else if c == '"' {
                in_string = false;
            }
        } else if c == '"' {
            in_string = true;
        } else if c == '/' && chars.peek() == Some(&'/') {
            in_comment = true;
            out.push(' ');
            continue;
        }
        out.push(c);
    }
    out
}

/// serde reports a missing field by its name only; name the end it is missing from
/// (`missing field `start.velocity``) when that can be told.
fn qualify_missing_field(message: &str, text: &str) -> String {
    let Some(rest) = message.strip_prefix("missing field `") else { return message.to_string() };
    let Some((field, tail)) = rest.split_once('`') else { return message.to_string() };
    let Ok(value) = serde_json::from_str::<Value>(text) else { return message.to_string() };
    if value.get(field).is_some() || ["kind", "degree", "start", "end"].contains(&field) {
        return message.to_string();
    }
    for end in ["start", "end"] {
        if value.get(end).is_some_and(|v| v.is_object() && v.get(field).is_none()) {
            return format!("missing field `{end}.{field}`{tail}");
        }
    }
    message.to_string()
}

/// Reads and checks the spec file.
pub(crate) fn read_spec(path: &str) -> Result<Spec, CliError> {
    let text = std::fs::read_to_string(path).map_err(|e| CliError::usage(format!("cannot read `{path}`: {e}")))?;
    let text = strip_comments(&text);
    let spec: Spec = serde_json::from_str(&text).map_err(|e| {
        let (what, message) = match e.classify() {
            serde_json::error::Category::Syntax | serde_json::error::Category::Eof => ("invalid JSON", e.to_string()),
            _ => ("invalid spec", qualify_missing_field(&e.to_string(), &text)),
        };
        CliError::usage(format!("`{path}`: {what}: {message}"))
    })?;
    if !(3..=MAX_DEGREE).contains(&spec.degree) {
        return Err(CliError::usage(format!(
            "`{path}`: `degree` must be an integer from 3 to {MAX_DEGREE} (got {}): the end conditions fix the \
             four control poses S0, S1, S_(n-1) and Sn",
            spec.degree
        )));
    }
    for (name, end) in [("start", &spec.start), ("end", &spec.end)] {
        if end.axis.iter().all(|x| *x == 0.0) {
            return Err(CliError::usage(format!("`{path}`: `{name}.axis` has length zero")));
        }
        if end.shape <= 0.0 || end.shape.is_nan() {
            return Err(CliError::usage(format!(
                "`{path}`: `{name}.shape` must be positive (got {})",
                crate::scalar::format_f64(end.shape)
            )));
        }
    }
    Ok(spec)
}

fn end_condition(name: &str, end: &EndSpec) -> Result<(EndCondition<f64>, Shape<f64>), CliError> {
    let cond =
        EndCondition::from_axis_angle(&end.position, &end.axis, &end.angle, &end.velocity, &end.angular_velocity)
            .map_err(|e| match e {
                MotionError::ZeroAxis => CliError::usage(format!("`{name}.axis` has length zero")),
                other => CliError::math(format!("`{name}`: {other}")),
            })?;
    Ok((cond, Shape::new(end.shape, Pseudoscalar::new(end.gamma[0], end.gamma[1]))))
}

/// A JSON list of multivectors in g123inf blade names.
fn mv_list<'a>(list: impl Iterator<Item = &'a Even<f64>>) -> Value {
    Value::Array(list.map(|m| mv_json(&m.to_multivector())).collect())
}

fn finite(m: &Even<f64>) -> bool {
    [m.scalar, m.e12, m.e13, m.e23, m.e1inf, m.e2inf, m.e3inf, m.e123inf].iter().all(|x| x.is_finite())
}

/// The segment of a checked spec (shared with `gam sample` and `gam plot`).
pub(crate) fn build_segment(spec: &Spec) -> Result<HermiteSegment<f64>, CliError> {
    let kind = match spec.kind {
        Kind::Additive => SegmentKind::Additive,
        Kind::Multiplicative => SegmentKind::Multiplicative,
    };
    let degree = usize::try_from(spec.degree).map_err(|_| CliError::usage("`degree` out of range"))?;
    let (start, start_shape) = end_condition("start", &spec.start)?;
    let (end, end_shape) = end_condition("end", &spec.end)?;
    let seg = hermite_segment(kind, degree, &start, &end, &start_shape, &end_shape).map_err(|e| match e {
        JoinError::Motion(m) => CliError::math(m.to_string()),
        other => CliError::usage(other.to_string()),
    })?;
    Ok(seg)
}

/// Runs `gam hermite`.
pub fn hermite(path: &str, json: bool) -> Result<String, CliError> {
    let spec = read_spec(path)?;
    if spec.body_point.is_some() {
        return Err(CliError::usage(format!("`{path}`: `body_point` is only used by `gam sample` and `gam plot`")));
    }
    let seg = build_segment(&spec)?;
    let kind = seg.kind;
    let degree = seg.degree();
    let poses: Vec<&Even<f64>> = seg.control_poses.iter().collect();
    let nus: Vec<Even<f64>> = seg.velocity_bivectors.iter().map(Even::from).collect();
    let mut all = poses.iter().copied().chain(&nus).chain(&seg.velocity_indicatrices);
    if !all.all(finite) {
        return Err(CliError::math("the result is not finite (overflow)"));
    }
    if json {
        let out = json!({
            "control_poses": mv_list(poses.iter().copied()),
            "velocity_bivectors": mv_list(nus.iter()),
            "velocity_indicatrices": mv_list(seg.velocity_indicatrices.iter()),
        });
        return Ok(out.to_string());
    }
    let n = degree;
    let mut lines = vec![format!("{kind} segment of degree {n}"), "control poses:".to_string()];
    for (i, m) in poses.iter().enumerate() {
        lines.push(format!("  S{i} = {}", mv_human(&m.to_multivector())));
    }
    lines.push("velocity bivectors (nu = Omega e123 + u einf):".to_string());
    for (i, m) in [0, n].into_iter().zip(&seg.velocity_bivectors) {
        lines.push(format!("  nu{i} = {}", mv_human(&m.to_multivector())));
    }
    lines.push("velocity indicatrices (Psi = shape (nu + gamma)):".to_string());
    for (i, m) in [0, n].into_iter().zip(&seg.velocity_indicatrices) {
        lines.push(format!("  Psi{i} = {}", mv_human(&m.to_multivector())));
    }
    Ok(lines.join("\n"))
}

#[cfg(test)]
mod tests {
    use super::strip_comments;

    #[test]
    fn comments_are_blanked_outside_strings() {
        let text = "{\"a\": \"x//y\", // note\n \"b\": 1 // more\n}";
        let out = strip_comments(text);
        assert_eq!(out.len(), text.len());
        assert_eq!(out, "{\"a\": \"x//y\",        \n \"b\": 1        \n}");
        assert_eq!(strip_comments(r#"{"a": "q\"//"}"#), r#"{"a": "q\"//"}"#);
    }
}
