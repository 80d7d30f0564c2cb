//! JSON values between Python and Rust: a spec or pose given as Python objects becomes a
//! [`serde_json::Value`] (dicts with string keys, lists/tuples, strings, numbers, booleans,
//! `None`; numpy arrays and scalars through their `tolist()`; a `fractions.Fraction` as the
//! string `"p/q"`), and a command's JSON value
//! becomes the objects `json.loads` would give (integers stay `int`, other numbers `float`).

use crate::gam_error;
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyDict, PyFloat, PyInt, PyList, PyString, PyTuple};
use serde_json::{Map, Number, Value};

/// Deeper nesting is refused (the command line's JSON reader stops at the same depth).
const MAX_DEPTH: usize = 128;

/// A Python object as a JSON value; `what` names it in messages.
pub(crate) fn to_json(obj: &Bound<'_, PyAny>, what: &str) -> PyResult<Value> {
    to_json_at(obj, what, 0)
}

fn to_json_at(obj: &Bound<'_, PyAny>, at: &str, depth: usize) -> PyResult<Value> {
    if depth > MAX_DEPTH {
        return Err(gam_error(format!("`{at}` is nested more than {MAX_DEPTH} levels deep")));
    }
    if obj.is_none() {
        return Ok(Value::Null);
    }
    if let Ok(b) = obj.cast::<PyBool>() {
        return Ok(Value::Bool(b.is_true()));
    }
    if let Ok(i) = obj.cast::<PyInt>() {
        if let Ok(x) = i.extract::<i64>() {
            return Ok(Value::from(x));
        }
        if let Ok(x) = i.extract::<u64>() {
            return Ok(Value::from(x));
        }
        return Err(gam_error(format!("`{at}`: the integer {i} does not fit in 64 bits")));
    }
    if let Ok(f) = obj.cast::<PyFloat>() {
        let x = f.value();
        return Number::from_f64(x)
            .map(Value::Number)
            .ok_or_else(|| gam_error(format!("`{at}` is {x}: numbers must be finite (JSON has no NaN or infinity)")));
    }
    if let Ok(s) = obj.cast::<PyString>() {
        return Ok(Value::String(s.to_str()?.to_string()));
    }
    if let Ok(d) = obj.cast::<PyDict>() {
        let mut map = Map::new();
        for (k, v) in d.iter() {
            let key = k
                .cast::<PyString>()
                .map_err(|_| gam_error(format!("`{at}`: keys must be strings (got {})", type_name(&k))))?
                .to_str()?
                .to_string();
            let value = to_json_at(&v, &format!("{at}.{key}"), depth + 1)?;
            map.insert(key, value);
        }
        return Ok(Value::Object(map));
    }
    if obj.cast::<PyList>().is_ok() || obj.cast::<PyTuple>().is_ok() {
        let items = obj.try_iter()?;
        let mut list = Vec::new();
        for (i, item) in items.enumerate() {
            list.push(to_json_at(&item?, &format!("{at}[{i}]"), depth + 1)?);
        }
        return Ok(Value::Array(list));
    }
    // fractions.Fraction: the string "p/q", read exactly under scalar="rational" or "mpfr:BITS"
    if type_name(obj) == "Fraction" && obj.hasattr("numerator")? && obj.hasattr("denominator")? {
        let (p, q) = (obj.getattr("numerator")?.str()?, obj.getattr("denominator")?.str()?);
        return Ok(Value::String(format!("{}/{}", p.to_str()?, q.to_str()?)));
    }
    // numpy arrays and numpy scalars (float64, int64, ...)
    if obj.hasattr("tolist")? && obj.hasattr("dtype")? {
        let plain = obj.call_method0("tolist")?;
        if !plain.hasattr("dtype")? {
            return to_json_at(&plain, at, depth);
        }
    }
    Err(gam_error(format!(
        "`{at}`: a {} is not a JSON value (use dicts, lists, strings, numbers, booleans and None)",
        type_name(obj)
    )))
}

fn type_name(obj: &Bound<'_, PyAny>) -> String {
    obj.get_type().name().map(|n| n.to_string()).unwrap_or_else(|_| "value".into())
}

/// A JSON value as the Python objects of `json.loads`.
pub(crate) fn to_py<'py>(py: Python<'py>, v: &Value) -> PyResult<Bound<'py, PyAny>> {
    Ok(match v {
        Value::Null => py.None().into_bound(py),
        Value::Bool(b) => PyBool::new(py, *b).to_owned().into_any(),
        Value::Number(n) => {
            if let Some(i) = n.as_i64() {
                i.into_pyobject(py)?.into_any()
            } else if let Some(u) = n.as_u64() {
                u.into_pyobject(py)?.into_any()
            } else {
                n.as_f64().unwrap_or(f64::NAN).into_pyobject(py)?.into_any()
            }
        }
        Value::String(s) => PyString::new(py, s).into_any(),
        Value::Array(items) => {
            let list = PyList::empty(py);
            for item in items {
                list.append(to_py(py, item)?)?;
            }
            list.into_any()
        }
        Value::Object(map) => {
            let dict = PyDict::new(py);
            for (k, item) in map {
                dict.set_item(k, to_py(py, item)?)?;
            }
            dict.into_any()
        }
    })
}

/// `assume`: a list of strings (one string is taken as a list of one).
pub(crate) fn strings(obj: &Bound<'_, PyAny>, what: &str) -> PyResult<Vec<String>> {
    if let Ok(s) = obj.cast::<PyString>() {
        return Ok(vec![s.to_str()?.to_string()]);
    }
    let bad = || gam_error(format!("`{what}` must be a list of strings"));
    let items = obj.try_iter().map_err(|_| bad())?;
    items.map(|item| item.and_then(|i| i.extract::<String>()).map_err(|_| bad())).collect()
}

/// The `--point` text of `gam trajectory`: a string as given, or `x,y,z` from a sequence of
/// numbers (each printed so that it reads back exactly).
pub(crate) fn point_text(obj: &Bound<'_, PyAny>) -> PyResult<String> {
    if let Ok(s) = obj.cast::<PyString>() {
        return Ok(s.to_str()?.to_string());
    }
    let bad = || gam_error("`point` must be [x, y, z] (three numbers) or the text \"x,y,z\"");
    let obj = if obj.hasattr("tolist")? { obj.call_method0("tolist")? } else { obj.clone() };
    let items = obj.try_iter().map_err(|_| bad())?;
    // each coordinate as the CLI's text: a Fraction as p/q, a string and an int as written
    // (exact under scalar="rational"), a float as its shortest round-trip decimal
    let coordinate = |i: Bound<'_, PyAny>| -> PyResult<String> {
        match to_json(&i, "point")? {
            Value::String(s) => Ok(s),
            Value::Number(n) => {
                Ok(n.as_f64().filter(|_| n.is_f64()).map_or_else(|| n.to_string(), |x| format!("{x:?}")))
            }
            _ => Err(bad()),
        }
    };
    let coords: Vec<String> = items.map(|i| i.map_err(|_| bad()).and_then(coordinate)).collect::<Result<_, _>>()?;
    Ok(coords.join(","))
}
