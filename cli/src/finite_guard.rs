//! The last guard before a numeric result is printed: an output holding a non-finite number
//! (`inf`, `-inf`, `NaN`, as the scalars print them) is refused with an error instead of
//! printed with exit 0. (JSON `null` is not checked: `gam pose` writes `"pitch": null` for a
//! screw without rotation, and serde writes a non-finite `f64` number as `null`, so those
//! numbers are checked where they are computed.) The computations refuse such values themselves (each with a
//! reason); this guard catches any path that missed it, so a wrong number never reaches a
//! script as a success.

/// The first non-finite token of `out`: `inf`, `infinity` or `nan` (any case) as a whole word
/// (letters, digits and `_` around it make it part of another word: `e1inf`, `is_nan`).
pub fn non_finite_token(out: &str) -> Option<&str> {
    let word = |c: char| c.is_ascii_alphanumeric() || c == '_';
    let mut start = None;
    for (i, c) in out.char_indices().chain(std::iter::once((out.len(), ' '))) {
        match (word(c), start) {
            (true, None) => start = Some(i),
            (false, Some(s)) => {
                let w = &out[s..i];
                if w.eq_ignore_ascii_case("inf") || w.eq_ignore_ascii_case("nan") || w.eq_ignore_ascii_case("infinity")
                {
                    return Some(w);
                }
                start = None;
            }
            _ => {}
        }
    }
    None
}

/// `Ok(out)` unless it holds a non-finite number (exit status 1: the computation overflowed).
pub fn finite_output(command: &str, out: String) -> Result<String, crate::error::CliError> {
    match non_finite_token(&out) {
        None => Ok(out),
        Some(w) => Err(refused(command, w)),
    }
}

/// [`finite_output`] for a JSON value (the library's door, `gam::api`): the same tokens, looked
/// for in its strings without printing it (a JSON number is always finite: serde writes a
/// non-finite `f64` as `null`).
///
/// ```
/// use serde_json::json;
/// assert!(gam::finite_guard::finite_value("pose", &json!({"e1inf": "2", "angle": 0.5})).is_ok());
/// assert!(gam::finite_guard::finite_value("pose", &json!({"motor": {"e1": "-inf"}})).is_err());
/// ```
pub fn finite_value(command: &str, v: &serde_json::Value) -> Result<(), crate::error::CliError> {
    use serde_json::Value;
    match v {
        Value::String(s) => non_finite_token(s).map_or(Ok(()), |w| Err(refused(command, w))),
        Value::Array(xs) => xs.iter().try_for_each(|x| finite_value(command, x)),
        Value::Object(m) => m.values().try_for_each(|x| finite_value(command, x)),
        Value::Null | Value::Bool(_) | Value::Number(_) => Ok(()),
    }
}

fn refused(command: &str, token: &str) -> crate::error::CliError {
    crate::error::CliError::math(format!(
        "{command}: the result holds a non-finite number (`{token}`): overflow or an undefined value in the computation; nothing printed"
    ))
}

#[cfg(test)]
mod tests {
    use super::non_finite_token;

    #[test]
    fn tokens() {
        assert_eq!(non_finite_token("1 + e1inf + e0inf - 2*e123inf"), None);
        assert_eq!(non_finite_token("{\"e1inf\":\"1\"}"), None);
        assert_eq!(non_finite_token("inf*e1inf"), Some("inf"));
        assert_eq!(non_finite_token("{\"e1\":\"-inf\"}"), Some("inf"));
        assert_eq!(non_finite_token("[1.0,NaN]"), Some("NaN"));
        assert_eq!(non_finite_token("{\"pitch\":null}"), None);
        assert_eq!(non_finite_token("Infinity"), Some("Infinity"));
        assert_eq!(non_finite_token("algebra cga-null"), None);
        assert_eq!(non_finite_token("x.is_nan() || nanometre"), None);
        assert_eq!(non_finite_token(""), None);
    }
}
