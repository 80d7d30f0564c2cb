//! `gam.build(spec) -> Motion`: the motion of a `gam interpolate` spec, built once, sampled at
//! any parameters into numpy arrays. A sample is the one of `gam interpolate` at that `t`
//! (the same Rust function: `gam_cli::api::Motion::sample`).

use crate::arrays::{PARALLEL_ABOVE, array2, array3, finite_entries, floats, shape_text};
use crate::convert::to_json;
use crate::{gam_error, run_detached};
use gam_cli::api::{CliError, Motion, Sample};
use numpy::{PyArray1, PyUntypedArrayMethods};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use rayon::prelude::*;

/// The motion of an interpolate spec: `motion.sample(t, body_points=None)`.
#[pyclass(module = "gam", name = "Motion", frozen)]
pub(crate) struct PyMotion {
    motion: Motion,
}

/// `gam.build(spec)`: the motion of a `gam interpolate` spec (its `samples` are ignored).
#[pyfunction]
pub(crate) fn build(py: Python<'_>, spec: &Bound<'_, PyAny>) -> PyResult<PyMotion> {
    let v = to_json(spec, "spec")?;
    let motion = run_detached(py, || Motion::build(&v, "spec"))?;
    Ok(PyMotion { motion })
}

/// The samples at every `t` (in parallel when there are many); the first failure in `t` order.
fn sample_all(m: &Motion, ts: &[f64], points: &[[f64; 3]]) -> Result<Vec<Sample>, CliError> {
    if ts.len() > PARALLEL_ABOVE / 16 {
        let all: Vec<Result<Sample, CliError>> = ts.par_iter().with_min_len(64).map(|t| m.sample(*t, points)).collect();
        all.into_iter().collect()
    } else {
        ts.iter().map(|t| m.sample(*t, points)).collect()
    }
}

/// The checked parameters and body points of a `sample` call.
fn inputs(
    m: &Motion,
    t: &Bound<'_, PyAny>,
    body_points: Option<&Bound<'_, PyAny>>,
) -> PyResult<(Vec<f64>, Vec<[f64; 3]>)> {
    let ta = floats(t, "t")?;
    if ta.ndim() != 1 {
        return Err(gam_error(format!("`t` must be a 1-D array (got shape {})", shape_text(ta.shape()))));
    }
    let ts = finite_entries(&ta, "t")?.into_owned();
    let points: Vec<[f64; 3]> = match body_points {
        None => m.body_points().to_vec(),
        Some(b) => {
            let a = floats(b, "body_points")?;
            if a.ndim() != 2 || a.shape()[1] != 3 {
                return Err(gam_error(format!(
                    "`body_points` must have shape (P, 3) (got shape {})",
                    shape_text(a.shape())
                )));
            }
            finite_entries(&a, "body_points")?.chunks(3).map(|c| [c[0], c[1], c[2]]).collect()
        }
    };
    m.check_work(ts.len(), points.len()).map_err(gam_error)?;
    Ok((ts, points))
}

#[pymethods]
impl PyMotion {
    /// The samples at the parameters `t` (a 1-D array within `[t_0, t_m]`) of the spec's body
    /// points or of `body_points` ((P, 3), body coordinates): a dict of arrays `t` (N,),
    /// `matrix` (N, 4, 4), `points` (N, P, 3), `velocities` (N, P, 3) (d/dt), `angular_velocity`
    /// (N, 3) (fixed frame), equal to `gam.interpolate`'s samples at the same `t`.
    #[pyo3(signature = (t, body_points = None))]
    fn sample<'py>(
        &self,
        py: Python<'py>,
        t: &Bound<'py, PyAny>,
        body_points: Option<&Bound<'py, PyAny>>,
    ) -> PyResult<Bound<'py, PyDict>> {
        let (ts, points) = inputs(&self.motion, t, body_points)?;
        let m = &self.motion;
        let samples = run_detached(py, || sample_all(m, &ts, &points))?;
        let (n, p) = (samples.len(), points.len());
        let mut matrix = Vec::with_capacity(16 * n);
        let mut positions = Vec::with_capacity(3 * n * p);
        let mut velocities = Vec::with_capacity(3 * n * p);
        let mut angular = Vec::with_capacity(3 * n);
        for s in &samples {
            matrix.extend(s.matrix.iter().flatten());
            positions.extend(s.points.iter().flatten());
            velocities.extend(s.velocities.iter().flatten());
            angular.extend(s.angular_velocity);
        }
        let out = PyDict::new(py);
        out.set_item("t", PyArray1::from_vec(py, ts))?;
        out.set_item("matrix", array3(py, [n, 4, 4], matrix)?)?;
        out.set_item("points", array3(py, [n, p, 3], positions)?)?;
        out.set_item("velocities", array3(py, [n, p, 3], velocities)?)?;
        out.set_item("angular_velocity", array2(py, n, 3, angular)?)?;
        Ok(out)
    }

    /// The parameters `t_0 < ... < t_m` of the key poses.
    #[getter]
    fn parameters(&self) -> Vec<f64> {
        self.motion.times().to_vec()
    }

    /// The spec's body points (P, 3).
    #[getter]
    fn body_points<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let pts = self.motion.body_points();
        array2(py, pts.len(), 3, pts.iter().flatten().copied().collect())
    }
}

/// For the benchmark (python/bench/bench.py): the seconds the Rust sampler takes for the
/// samples of `motion.sample(t, body_points)`, the same loop without the numpy arrays.
#[pyfunction]
#[pyo3(name = "_rust_sample_seconds", signature = (motion, t, body_points = None))]
pub(crate) fn rust_sample_seconds(
    py: Python<'_>,
    motion: &PyMotion,
    t: &Bound<'_, PyAny>,
    body_points: Option<&Bound<'_, PyAny>>,
) -> PyResult<f64> {
    let (ts, points) = inputs(&motion.motion, t, body_points)?;
    let m = &motion.motion;
    run_detached(py, || {
        let start = std::time::Instant::now();
        drop(sample_all(m, &ts, &points)?);
        Ok(start.elapsed().as_secs_f64())
    })
}
