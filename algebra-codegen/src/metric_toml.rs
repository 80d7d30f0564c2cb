//! Algebra descriptions in TOML (the CLI's `--algebra file.toml`): the metric parser and the
//! "built-in name or path" resolution. Lives here, not in algebra-core, so a kernel user's
//! build does not contain `toml`/`serde`; enabled by this crate's `toml` feature.

use algebra_core::rational::{Q, parse_rational, q};
use algebra_core::{Algebra, Metric, MetricError};
use num_traits::Zero;
use std::collections::HashMap;
use std::sync::Arc;

/// Reads an algebra description in TOML. Either a full matrix
///
/// ```toml
/// name = "plane"            # optional
/// generators = ["x", "y"]
/// gram = [[1, 0], [0, "-1/2"]]
/// ```
///
/// or the non-zero entries by label pair (unlisted pairs are 0; `(a, b)` sets both
/// `B(a, b)` and `B(b, a)`):
///
/// ```toml
/// generators = ["0", "1", "2", "3", "inf"]
/// metric = { "1,1" = 1, "2,2" = 1, "3,3" = 1, "0,inf" = -1 }
/// ```
///
/// Entries are integers or rational strings (`"p/q"`, exact decimals). Returns the
/// optional name and the metric.
///
/// ```
/// let (name, m) = algebra_codegen::metric_toml::metric_from_toml_str(
///     "name = \"h\"\ngenerators = [\"a\", \"b\"]\nmetric = { \"a,b\" = \"1/2\" }",
///     "<string>",
/// ).unwrap();
/// assert_eq!(name.as_deref(), Some("h"));
/// assert_eq!(m.gram(1, 0).unwrap(), &algebra_core::rational::ratio(1, 2));
/// ```
pub fn metric_from_toml_str(text: &str, path: &str) -> Result<(Option<String>, Metric), MetricError> {
    let err = |message: String| MetricError::Toml { path: path.to_string(), message };
    let doc: toml::Table = text.parse().map_err(|e: toml::de::Error| {
        // "TOML parse error at line L, column C" ... "reason": keep both, on one line
        let msg = e.to_string();
        let mut lines = msg.lines().map(str::trim).filter(|l| !l.is_empty());
        let first = lines.next().unwrap_or("parse error").to_string();
        match lines.rfind(|l| !l.contains('|') && !l.starts_with('^')) {
            Some(reason) => err(format!("{first}: {reason}")),
            None => err(first),
        }
    })?;
    for key in doc.keys() {
        if !["name", "generators", "gram", "metric"].contains(&key.as_str()) {
            return Err(err(format!("unknown key `{key}` (expected name, generators, gram or metric)")));
        }
    }
    let name = match doc.get("name") {
        None => None,
        Some(toml::Value::String(s)) => Some(s.clone()),
        Some(_) => return Err(err("`name` must be a string".into())),
    };
    let labels: Vec<String> = match doc.get("generators") {
        Some(toml::Value::Array(a)) => a
            .iter()
            .map(|v| match v {
                toml::Value::String(s) => Ok(s.clone()),
                toml::Value::Integer(i) => Ok(i.to_string()),
                _ => Err(err("`generators` must be a list of labels".into())),
            })
            .collect::<Result<_, _>>()?,
        _ => return Err(err("missing `generators = [...]`".into())),
    };
    let n = labels.len();
    let entry = |v: &toml::Value, at: &str| -> Result<Q, MetricError> {
        match v {
            toml::Value::Integer(i) => Ok(q(*i)),
            toml::Value::String(s) => parse_rational(s).map_err(|e| err(format!("{at}: {e}"))),
            _ => Err(err(format!(
                "{at}: entries must be integers or rational strings like \"1/2\" (floats are not exact)"
            ))),
        }
    };
    let gram = match (doc.get("gram"), doc.get("metric")) {
        (Some(_), Some(_)) => return Err(err("give either `gram` or `metric`, not both".into())),
        (None, None) => return Err(err("missing `gram = [[...]]` or `metric = { \"a,b\" = value }`".into())),
        (Some(toml::Value::Array(rows)), None) => rows
            .iter()
            .enumerate()
            .map(|(i, row)| match row {
                toml::Value::Array(r) => r
                    .iter()
                    .enumerate()
                    .map(|(j, v)| entry(v, &format!("gram[{i}][{j}]")))
                    .collect::<Result<Vec<_>, _>>(),
                _ => Err(err("`gram` must be a list of rows".into())),
            })
            .collect::<Result<Vec<_>, _>>()?,
        (None, Some(toml::Value::Table(t))) => {
            let mut gram = vec![vec![Q::zero(); n]; n];
            let index: HashMap<&str, usize> = labels.iter().enumerate().map(|(i, l)| (l.as_str(), i)).collect();
            let mut set: HashMap<(usize, usize), Q> = HashMap::new();
            for (key, v) in t {
                let (a, b) = key.split_once(',').ok_or_else(|| err(format!("metric key `{key}` must be \"a,b\"")))?;
                let ia = *index.get(a.trim()).ok_or_else(|| MetricError::UnknownLabel(a.trim().into()))?;
                let ib = *index.get(b.trim()).ok_or_else(|| MetricError::UnknownLabel(b.trim().into()))?;
                let value = entry(v, &format!("metric \"{key}\""))?;
                // "a,b" and "b,a" name one entry: contradictory values are an error, not "last wins"
                if let Some(first) = set.insert((ia.min(ib), ia.max(ib)), value.clone())
                    && first != value
                {
                    return Err(err(format!(
                        "metric \"{key}\" = {value} contradicts an earlier entry for the same pair ({first}); B is symmetric"
                    )));
                }
                gram[ia][ib] = value.clone();
                gram[ib][ia] = value;
            }
            gram
        }
        _ => return Err(err("`gram` must be a matrix and `metric` a table".into())),
    };
    Ok((name, Metric::new(labels, gram)?))
}

/// A built-in name (see [`algebra_core::algebra::BUILTINS`]), or else a path to a TOML
/// description (see [`metric_from_toml_str`]); the CLI's `--algebra` argument.
///
/// ```
/// let alg = algebra_codegen::metric_toml::algebra_from_name_or_path("pga3").unwrap();
/// assert!(alg.metric().is_degenerate());
/// assert!(algebra_codegen::metric_toml::algebra_from_name_or_path("nope").is_err());
/// ```
///
/// A file whose `name` is a built-in's (`name = "pga3"`) is refused: its algebra would
/// otherwise be printed and generated under the built-in's identity.
pub fn algebra_from_name_or_path(arg: &str) -> Result<Arc<Algebra>, MetricError> {
    if let Ok(alg) = Algebra::builtin(arg) {
        return Ok(alg);
    }
    if !arg.ends_with(".toml") && !std::path::Path::new(arg).exists() {
        return Err(MetricError::UnknownAlgebra(arg.to_string()));
    }
    let text = std::fs::read_to_string(arg)
        .map_err(|e| MetricError::Toml { path: arg.to_string(), message: e.to_string() })?;
    let (name, metric) = metric_from_toml_str(&text, arg)?;
    // a built-in's name would make the file's algebra print, describe and generate under the
    // built-in's identity (its description, its module name): refused, not shadowed
    if let Some(n) = &name
        && Algebra::builtin(n).is_ok()
    {
        return Err(MetricError::Toml {
            path: arg.to_string(),
            message: format!("`name = \"{n}\"` is a built-in algebra's name; give the file's algebra another name"),
        });
    }
    Ok(Algebra::new(name.unwrap_or_else(|| arg.to_string()), metric))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn toml_forms_agree() {
        let (_, a) =
            metric_from_toml_str("generators = [\"0\",\"1\",\"inf\"]\nmetric = { \"1,1\" = 1, \"0,inf\" = -1 }", "a")
                .unwrap();
        let (_, b) =
            metric_from_toml_str("generators = [\"0\",\"1\",\"inf\"]\ngram = [[0,0,-1],[0,1,0],[-1,0,0]]", "b")
                .unwrap();
        assert_eq!(a, b);
        assert!(!a.is_degenerate());
        assert!(metric_from_toml_str("generators = [\"a\"]\ngram = [[1.5]]", "c").is_err());
        assert!(metric_from_toml_str("generators = [\"a\"]\nmetric = { \"a,z\" = 1 }", "c").is_err());
        let Err(MetricError::Toml { message, .. }) = metric_from_toml_str("generators = [\"a\"", "c") else {
            panic!("broken TOML must be rejected")
        };
        assert!(message.contains("line 1") && message.contains(": "), "{message}");
    }
}
