//! `gam hermite [--json] SPEC.json`: a Bezier motion segment of degree `n` from its end
//! conditions (Secs. 4-5 of the main paper), exactly as in the contract (shared/cli.md).
//!
//! The spec, its checks and the segment it describes are `motion::spec` (the library owns the
//! format); this module reads the file and prints the result.
//!
//! The file is JSON; `//` comments (outside strings) are allowed, as in the contract's example.

use crate::error::CliError;
use crate::output::{mv_human, mv_json};
use motion::AnyHermiteSegment;
use motion::Even;
pub(crate) use motion::spec::HermiteSpec as Spec;
use motion::spec::SpecError;
use serde_json::{Value, json};

/// Replaces `//` comments outside JSON strings by spaces (line and column numbers unchanged).
pub(crate) fn strip_comments(text: &str) -> String {
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
    parse_spec(path, &text)
}

/// Checks the spec `text` (named `path` in messages).
pub(crate) fn parse_spec(path: &str, text: &str) -> Result<Spec, CliError> {
    let text = strip_comments(text);
    let spec: Spec = serde_json::from_str(&text).map_err(|e| {
        let (what, message) = match e.classify() {
            serde_json::error::Category::Syntax | serde_json::error::Category::Eof => ("invalid JSON", e.to_string()),
            _ => ("invalid spec", qualify_missing_field(&e.to_string(), &text)),
        };
        CliError::usage(format!("`{path}`: {what}: {message}"))
    })?;
    spec.check().map_err(|e| spec_error(path, e))?;
    Ok(spec)
}

/// A rejected spec as a CLI error: bad input is exit 2 (prefixed by the file), a mathematical
/// failure exit 1.
fn spec_error(path: &str, e: SpecError) -> CliError {
    if e.is_input() { CliError::usage(format!("`{path}`: {e}")) } else { CliError::math(e.to_string()) }
}

/// A JSON list of multivectors in g123inf blade names.
fn mv_list<'a>(list: impl Iterator<Item = &'a Even<f64>>) -> Value {
    Value::Array(list.map(|m| mv_json(&m.to_multivector())).collect())
}

/// The segment of a checked spec (shared with `gam sample` and `gam plot`).
pub(crate) fn build_segment(spec: &Spec) -> Result<AnyHermiteSegment<f64>, CliError> {
    spec.segment()
        .map_err(|e| if e.is_input() { CliError::usage(e.to_string()) } else { CliError::math(e.to_string()) })
}

/// Runs `gam hermite`.
pub fn hermite(path: &str, json: bool) -> Result<String, CliError> {
    hermite_of(path, &read_spec(path)?, json)
}

/// `gam hermite` of a checked spec (named `path` in messages).
pub(crate) fn hermite_of(path: &str, spec: &Spec, json: bool) -> Result<String, CliError> {
    if spec.body_point.is_some() {
        return Err(CliError::usage(format!("`{path}`: `body_point` is only used by `gam sample` and `gam plot`")));
    }
    let seg = build_segment(spec)?;
    let kind = seg.kind();
    let degree = seg.degree();
    let poses: Vec<&Even<f64>> = seg.control_poses().iter().collect();
    let nus: Vec<Even<f64>> = seg.velocity_bivectors().iter().map(Even::from).collect();
    if json {
        let out = json!({
            "control_poses": mv_list(poses.iter().copied()),
            "velocity_bivectors": mv_list(nus.iter()),
            "velocity_indicatrices": mv_list(seg.velocity_indicatrices().iter()),
        });
        return Ok(out.to_string());
    }
    let n = degree;
    let mut lines = vec![format!("{kind} segment of degree {n}"), "control poses:".to_string()];
    for (i, m) in poses.iter().enumerate() {
        lines.push(format!("  S{i} = {}", mv_human(&m.to_multivector())));
    }
    lines.push("velocity bivectors (nu = Omega e123 + u einf):".to_string());
    for (i, m) in [0, n].into_iter().zip(&nus) {
        lines.push(format!("  nu{i} = {}", mv_human(&m.to_multivector())));
    }
    lines.push("velocity indicatrices (Psi = shape (nu + gamma)):".to_string());
    for (i, m) in [0, n].into_iter().zip(seg.velocity_indicatrices()) {
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
