//! The `gam` Python package (the contract: shared/python.md; the guide: docs/python.md).
//!
//! - The mirror functions (`eval`, `table`, `prove`, `verify`, `pose`, `hermite`,
//!   `interpolate`, `trajectory`) call the command line's own code (`gam_cli::api`) and return
//!   its `--json` value as Python objects (module `convert`).
//! - `Pose` (module `pose`), `build(spec) -> Motion` (module `motion`) and `transform_points`
//!   (module `arrays`) work on numpy arrays.
//!
//! Every failure is a `gam.GamError` (a `ValueError`) carrying the command's `error:` message;
//! long calls run with the interpreter detached (other Python threads go on).

mod arrays;
mod convert;
mod motion;
mod pose;

use gam_cli::api::{self, CliError};
use pyo3::prelude::*;
use serde_json::Value;

pyo3::create_exception!(
    gam,
    GamError,
    pyo3::exceptions::PyValueError,
    "A failure of a gam function: the message is the `gam` command's `error:` line (without the prefix)."
);

/// The Python error of a CLI error.
pub(crate) fn gam_error(message: impl std::fmt::Display) -> PyErr {
    GamError::new_err(message.to_string())
}

fn cli_error(e: CliError) -> PyErr {
    gam_error(e)
}

/// Runs `f` with the interpreter detached, a panic turned into a `GamError` (never a crash).
pub(crate) fn run_detached<T: Send>(py: Python<'_>, f: impl FnOnce() -> Result<T, CliError> + Send) -> PyResult<T> {
    let result = py.detach(|| std::panic::catch_unwind(std::panic::AssertUnwindSafe(f)));
    match result {
        Ok(r) => r.map_err(cli_error),
        Err(panic) => {
            let why = panic
                .downcast_ref::<String>()
                .cloned()
                .or_else(|| panic.downcast_ref::<&str>().map(|s| s.to_string()))
                .unwrap_or_default();
            Err(gam_error(format!("internal error (please report): {why}")))
        }
    }
}

/// Runs a mirror function detached and converts its JSON value.
fn mirror<'py>(py: Python<'py>, f: impl FnOnce() -> Result<Value, CliError> + Send) -> PyResult<Bound<'py, PyAny>> {
    let v = run_detached(py, f)?;
    convert::to_py(py, &v)
}

/// `gam eval --json`: the value of a multivector expression, `{basis name: coefficient string}`
/// (`{"value": bool}` for a relation `==` / `!=`).
#[pyfunction]
#[pyo3(signature = (expr, algebra = "cga-null", basis = "blade", scalar = "rational"))]
fn eval<'py>(py: Python<'py>, expr: &str, algebra: &str, basis: &str, scalar: &str) -> PyResult<Bound<'py, PyAny>> {
    mirror(py, || api::eval(expr, algebra, basis, scalar))
}

/// `gam table --json`: a list of `{"a", "b", "result"}` for every ordered pair of basis elements.
#[pyfunction]
#[pyo3(signature = (algebra = "cga-null", basis = "blade", product = "gp"))]
fn table<'py>(py: Python<'py>, algebra: &str, basis: &str, product: &str) -> PyResult<Bound<'py, PyAny>> {
    mirror(py, || api::table(algebra, basis, product))
}

/// `gam prove --json`: `{"holds", "method", "basis_size", "time_ms", "witness", ...}`; a claim
/// that does not hold is returned with `holds` false, not raised.
#[pyfunction]
#[pyo3(signature = (claim, algebra = "cga-null", basis = "blade", assume = None, timeout = 10.0))]
fn prove<'py>(
    py: Python<'py>,
    claim: &str,
    algebra: &str,
    basis: &str,
    assume: Option<&Bound<'py, PyAny>>,
    timeout: f64,
) -> PyResult<Bound<'py, PyAny>> {
    let assume = match assume {
        None => Vec::new(),
        Some(a) => convert::strings(a, "assume")?,
    };
    mirror(py, || api::prove(claim, algebra, basis, &assume, timeout))
}

/// `gam verify --json`: the report on the papers' statements (all, or those matching `filter`);
/// with `list=True` (`gam verify --json --list`) the selected statements, not run.
#[pyfunction]
#[pyo3(signature = (filter = None, list = false))]
fn verify<'py>(py: Python<'py>, filter: Option<&str>, list: bool) -> PyResult<Bound<'py, PyAny>> {
    if list { mirror(py, || api::verify_list(filter)) } else { mirror(py, || api::verify(filter)) }
}

/// `gam pose --json [--scalar S]`: one pose object (any form of the contract) in every
/// representation; `scalar` is `"f64"` (default), `"rational"` or `"mpfr:BITS"`.
#[pyfunction]
#[pyo3(name = "pose", signature = (pose, scalar = "f64"))]
fn pose_fn<'py>(py: Python<'py>, pose: &Bound<'py, PyAny>, scalar: &str) -> PyResult<Bound<'py, PyAny>> {
    let v = convert::to_json(pose, "pose")?;
    mirror(py, || api::pose_with(&v, scalar))
}

/// `gam hermite --json [--scalar S]`: the control poses of a segment from its end conditions.
#[pyfunction]
#[pyo3(signature = (spec, scalar = "f64"))]
fn hermite<'py>(py: Python<'py>, spec: &Bound<'py, PyAny>, scalar: &str) -> PyResult<Bound<'py, PyAny>> {
    let v = convert::to_json(spec, "spec")?;
    mirror(py, || api::hermite_with(&v, "spec", scalar))
}

/// `gam interpolate --json [--scalar S]`: a motion through key poses, its segments and samples.
#[pyfunction]
#[pyo3(signature = (spec, scalar = "f64"))]
fn interpolate<'py>(py: Python<'py>, spec: &Bound<'py, PyAny>, scalar: &str) -> PyResult<Bound<'py, PyAny>> {
    let v = convert::to_json(spec, "spec")?;
    mirror(py, || api::interpolate_with(&v, "spec", scalar))
}

/// `gam trajectory --json --point x,y,z [--scalar S]`: the trajectory of a body point as
/// rational Bézier curves; `point` is `[x, y, z]` or the text `"x,y,z"`.
#[pyfunction]
#[pyo3(signature = (spec, point, scalar = "f64"))]
fn trajectory<'py>(
    py: Python<'py>,
    spec: &Bound<'py, PyAny>,
    point: &Bound<'py, PyAny>,
    scalar: &str,
) -> PyResult<Bound<'py, PyAny>> {
    let v = convert::to_json(spec, "spec")?;
    let point = convert::point_text(point)?;
    mirror(py, || api::trajectory_with(&v, "spec", &point, scalar))
}

/// `gam surface --json --curve CURVE.json [--scalar S]`: the kinematic surface of a rational
/// curve (`{"points": [[x, y, z], ...], "weights": [...]}`) under the spec's motion.
#[pyfunction]
#[pyo3(signature = (spec, curve, scalar = "f64"))]
fn surface<'py>(
    py: Python<'py>,
    spec: &Bound<'py, PyAny>,
    curve: &Bound<'py, PyAny>,
    scalar: &str,
) -> PyResult<Bound<'py, PyAny>> {
    let (v, c) = (convert::to_json(spec, "spec")?, convert::to_json(curve, "curve")?);
    mirror(py, || api::surface(&v, "spec", &c, scalar))
}

/// The Python module `gam`.
#[pymodule]
fn gam(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("GamError", m.py().get_type::<GamError>())?;
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    m.add_function(wrap_pyfunction!(eval, m)?)?;
    m.add_function(wrap_pyfunction!(table, m)?)?;
    m.add_function(wrap_pyfunction!(prove, m)?)?;
    m.add_function(wrap_pyfunction!(verify, m)?)?;
    m.add_function(wrap_pyfunction!(pose_fn, m)?)?;
    m.add_function(wrap_pyfunction!(hermite, m)?)?;
    m.add_function(wrap_pyfunction!(interpolate, m)?)?;
    m.add_function(wrap_pyfunction!(trajectory, m)?)?;
    m.add_function(wrap_pyfunction!(surface, m)?)?;
    m.add_class::<pose::PyPose>()?;
    m.add_class::<motion::PyMotion>()?;
    m.add_function(wrap_pyfunction!(motion::build, m)?)?;
    m.add_function(wrap_pyfunction!(motion::rust_sample_seconds, m)?)?;
    m.add_function(wrap_pyfunction!(arrays::transform_points, m)?)?;
    Ok(())
}
