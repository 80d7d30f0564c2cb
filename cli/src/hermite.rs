//! `gam hermite [--json] SPEC.json`: a Bezier motion segment of degree `n` from its end
//! conditions (Secs. 4-5 of the main paper), exactly as in the contract (shared/cli.md).
//!
//! The spec, its checks and the segment it describes are `motion::spec` (the library owns the
//! format); this module reads the file and prints the result.
//!
//! The file is JSON; `//` comments (outside strings) are allowed, as in the contract's example.
//! `--scalar mpfr:BITS` reads the numbers exactly, rounds each once and builds the segment at
//! that precision; `--scalar rational` exits 2 ([`NOT_EXACT`]).

use crate::error::CliError;
use crate::output::{mv_human, mv_json};
use crate::precision::{MotionScalar, OutScalar};
use algebra_core::{MpFloat, Real, Ring};
use motion::AnyHermiteSegment;
use motion::Even;
use motion::schema::Exact;
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

/// Reads and checks the spec file.
pub(crate) fn read_spec(path: &str) -> Result<Spec, CliError> {
    let text = std::fs::read_to_string(path).map_err(|e| CliError::usage(format!("cannot read `{path}`: {e}")))?;
    Spec::from_json(&strip_comments(&text)).map_err(|e| spec_error(path, e))
}

/// A rejected spec as a CLI error: bad input is exit 2 (prefixed by the file), a mathematical
/// failure exit 1.
pub(crate) fn spec_error(path: &str, e: SpecError) -> CliError {
    if e.is_input() { CliError::usage(format!("`{path}`: {e}")) } else { CliError::math(e.to_string()) }
}

/// A JSON list of multivectors in g123inf blade names.
fn mv_list<'a, T: OutScalar + 'a>(list: impl Iterator<Item = &'a Even<T>>) -> Value {
    Value::Array(list.map(|m| mv_json(&m.to_multivector())).collect())
}

/// The segment of a checked spec (shared with `gam sample` and `gam plot`).
pub(crate) fn build_segment<T: Real>(spec: &Spec<T>) -> Result<AnyHermiteSegment<T>, CliError> {
    spec.segment()
        .map_err(|e| if e.is_input() { CliError::usage(e.to_string()) } else { CliError::math(e.to_string()) })
}

/// The segment of a checked `gam hermite` spec (`label` names it in messages), which has no
/// `body_point`.
fn hermite_segment<T: Real>(label: &str, spec: &Spec<T>) -> Result<AnyHermiteSegment<T>, CliError> {
    if spec.body_point.is_some() {
        return Err(CliError::usage(format!("`{label}`: `body_point` is only used by `gam sample` and `gam plot`")));
    }
    build_segment(spec)
}

/// `gam hermite --json` of a checked spec (`label` names it in messages): control poses,
/// velocity bivectors and indicatrices.
pub fn hermite_json(label: &str, spec: &Spec) -> Result<Value, CliError> {
    Ok(segment_json(&hermite_segment(label, spec)?))
}

/// The JSON object of a segment.
fn segment_json<T: OutScalar + Real>(seg: &AnyHermiteSegment<T>) -> Value {
    let nus: Vec<Even<T>> = seg.velocity_bivectors().iter().map(Even::from).collect();
    json!({
        "control_poses": mv_list(seg.control_poses().iter()),
        "velocity_bivectors": mv_list(nus.iter()),
        "velocity_indicatrices": mv_list(seg.velocity_indicatrices().iter()),
    })
}

/// A `gam hermite` spec read with every literal exact (for `--scalar mpfr:BITS`) from its
/// text (`label` names it in messages).
pub(crate) fn exact_spec(label: &str, text: &str) -> Result<Spec<Exact>, CliError> {
    Spec::<Exact>::read_json(&strip_comments(text)).map_err(|e| spec_error(label, e))
}

/// Why `gam hermite` specs are not exact.
pub(crate) const NOT_EXACT: &str = "the end conditions give rotations by axis and angle (sine and cosine) and the C1 construction of Sec. 5.3 takes unit poses: not exact over the rationals (use --scalar mpfr:BITS or f64)";

/// Runs `gam hermite` on the spec file at `path`, in the scalar of `--scalar`.
pub fn hermite(path: &str, json: bool, scalar: MotionScalar) -> Result<String, CliError> {
    match scalar {
        MotionScalar::F64 => output(path, &read_spec(path)?, json),
        _ => hermite_in(path, &crate::precision::read_file(path)?, json, scalar),
    }
}

/// `gam hermite` of the spec text `text` (named `label` in messages) in an exact or MPFR
/// scalar: the JSON text or the human form.
pub(crate) fn hermite_in(label: &str, text: &str, json: bool, scalar: MotionScalar) -> Result<String, CliError> {
    match scalar {
        MotionScalar::F64 => {
            output(label, &Spec::from_json(&strip_comments(text)).map_err(|e| spec_error(label, e))?, json)
        }
        MotionScalar::Rational => Err(CliError::usage(format!("`{label}`: gam hermite: {NOT_EXACT}"))),
        MotionScalar::Mpfr(_) => scalar.run(|| {
            let spec = exact_spec(label, text)?.map(&|x| MpFloat::from_rational(&x.0));
            spec.check().map_err(|e| spec_error(label, e))?;
            output(label, &spec, json)
        }),
    }
}

/// The output of a checked spec.
fn output<T: OutScalar + Real>(path: &str, spec: &Spec<T>, json: bool) -> Result<String, CliError> {
    let seg = hermite_segment(path, spec)?;
    if json {
        return Ok(segment_json(&seg).to_string());
    }
    let n = seg.degree();
    let nus: Vec<Even<T>> = seg.velocity_bivectors().iter().map(Even::from).collect();
    let mut lines = vec![format!("{} segment of degree {n}", seg.kind()), "control poses:".to_string()];
    for (i, m) in seg.control_poses().iter().enumerate() {
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
