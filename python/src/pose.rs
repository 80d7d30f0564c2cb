//! `gam.Pose`: one rigid pose (the main paper's motor `S`, acting by `F_S`), made from any pose
//! form of the command line's contract and read back in each; `a * b` applies `a` first.
//!
//! Every constructor builds the contract's pose object and reads it with the command line's
//! pose reader (`gam_cli::api::pose_of`), so it accepts and refuses exactly what `gam pose`
//! does; every property is the corresponding field of `gam pose --json`.

use crate::arrays::{array2, finite_entries, floats, shape_text};
use crate::convert::{to_json, to_py};
use crate::gam_error;
use motion::Pose;
use numpy::{PyArray1, PyUntypedArrayMethods};
use pyo3::prelude::*;
use serde_json::{Value, json};

/// A rigid pose: `Pose.from_matrix`, `from_quaternion`, `from_axis_angle`, `from_motor`,
/// `from_dual_quaternion`; read as `matrix`, `quaternion` (w first), `position`, `motor`,
/// `dual_quaternion`. `a * b` and `a.then(b)` apply `a` first, then `b`.
#[pyclass(module = "gam", name = "Pose", frozen)]
pub(crate) struct PyPose {
    pose: Pose<f64>,
}

/// A fixed-size vector argument as finite floats.
fn vector<const N: usize>(obj: &Bound<'_, PyAny>, what: &str) -> PyResult<[f64; N]> {
    let a = floats(obj, what)?;
    if a.shape() != [N] {
        return Err(gam_error(format!("`{what}` must have shape ({N},) (got shape {})", shape_text(a.shape()))));
    }
    let e = finite_entries(&a, what)?;
    Ok(std::array::from_fn(|i| e[i]))
}

/// `position` (default the origin).
fn position(obj: Option<&Bound<'_, PyAny>>) -> PyResult<[f64; 3]> {
    obj.map_or(Ok([0.0; 3]), |p| vector::<3>(p, "position"))
}

impl PyPose {
    /// Reads a pose object of the contract, as `gam pose` does (`label` names it in messages).
    fn read(object: &Value, label: &str) -> PyResult<Self> {
        gam_cli::api::pose_of(object, label).map(|pose| PyPose { pose }).map_err(gam_error)
    }

    /// The `gam pose --json` object of this pose.
    fn representations(&self) -> PyResult<Value> {
        gam_cli::api::representations(&self.pose).map_err(gam_error)
    }

    /// The 16 entries of the rigid matrix, row-major.
    pub(crate) fn matrix_entries(&self) -> PyResult<[f64; 16]> {
        let m = self.pose.unitize().and_then(|u| u.to_matrix()).map_err(gam_error)?;
        Ok(std::array::from_fn(|k| m[k / 4][k % 4] + 0.0))
    }

    fn numbers(v: &Value) -> Vec<f64> {
        v.as_array().map(|l| l.iter().filter_map(Value::as_f64).collect()).unwrap_or_default()
    }
}

#[pymethods]
impl PyPose {
    /// The identity pose.
    #[staticmethod]
    fn identity() -> Self {
        PyPose { pose: Pose::identity() }
    }

    /// The pose of a (4, 4) rigid matrix (rotation block orthonormal to 1e-9, last row
    /// `[0, 0, 0, 1]`).
    #[staticmethod]
    fn from_matrix(m: &Bound<'_, PyAny>) -> PyResult<Self> {
        let a = floats(m, "m")?;
        if a.shape() != [4, 4] {
            return Err(gam_error(format!("`m` must have shape (4, 4) (got shape {})", shape_text(a.shape()))));
        }
        let e = finite_entries(&a, "m")?;
        let rows: Vec<Vec<f64>> = e.chunks(4).map(<[f64]>::to_vec).collect();
        Self::read(&json!({ "matrix": rows }), "Pose.from_matrix")
    }

    /// The rotation of the non-zero quaternion `q = [w, x, y, z]` (normalised), then the
    /// translation to `position`.
    #[staticmethod]
    #[pyo3(signature = (q, position = None))]
    fn from_quaternion(q: &Bound<'_, PyAny>, position: Option<&Bound<'_, PyAny>>) -> PyResult<Self> {
        let q = vector::<4>(q, "q")?;
        let p = self::position(position)?;
        Self::read(&json!({ "position": p, "quaternion": q }), "Pose.from_quaternion")
    }

    /// The rotation by `angle` radians (right-handed) about `axis` through the origin, then the
    /// translation to `position`.
    #[staticmethod]
    #[pyo3(signature = (axis, angle, position = None))]
    fn from_axis_angle(axis: &Bound<'_, PyAny>, angle: f64, position: Option<&Bound<'_, PyAny>>) -> PyResult<Self> {
        let axis = vector::<3>(axis, "axis")?;
        if !angle.is_finite() {
            return Err(gam_error(format!("`angle` is {angle}: it must be finite")));
        }
        let p = self::position(position)?;
        Self::read(&json!({ "position": p, "axis": axis, "angle": angle }), "Pose.from_axis_angle")
    }

    /// The main paper's pose `S` from `{blade name: coefficient}` in g123inf names (`1`, `e12`,
    /// `e13`, `e23`, `e1inf`, `e2inf`, `e3inf`, `e123inf`), any non-singular `S`.
    #[staticmethod]
    fn from_motor(motor: &Bound<'_, PyAny>) -> PyResult<Self> {
        let m = to_json(motor, "motor")?;
        Self::read(&json!({ "motor": m }), "Pose.from_motor")
    }

    /// The pose of a dual quaternion `[w, x, y, z, dw, dx, dy, dz]` acting by Jüttler's eq. (12).
    #[staticmethod]
    fn from_dual_quaternion(dq: &Bound<'_, PyAny>) -> PyResult<Self> {
        let d = vector::<8>(dq, "dq")?;
        Self::read(&json!({ "dual_quaternion": d }), "Pose.from_dual_quaternion")
    }

    /// The rigid 4x4 matrix `[[R, t], [0, 0, 0, 1]]`.
    #[getter]
    fn matrix<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        array2(py, 4, 4, self.matrix_entries()?.to_vec())
    }

    /// The unit rotation quaternion `[w, x, y, z]`, `w >= 0` (as `gam pose`).
    #[getter]
    fn quaternion<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        Ok(PyArray1::from_vec(py, Self::numbers(&self.representations()?["quaternion"])).into_any())
    }

    /// The translation (the image of the origin).
    #[getter]
    fn position<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        Ok(PyArray1::from_vec(py, Self::numbers(&self.representations()?["position"])).into_any())
    }

    /// The unit motor `S = R T` as `{blade name: coefficient string}` (as `gam pose`).
    #[getter]
    fn motor<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        to_py(py, &self.representations()?["motor"])
    }

    /// The unit dual quaternion `[w, x, y, z, dw, dx, dy, dz]` (as `gam pose`).
    #[getter]
    fn dual_quaternion<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        Ok(PyArray1::from_vec(py, Self::numbers(&self.representations()?["dual_quaternion"])).into_any())
    }

    /// `self` first, then `next` (the main paper's product `self * next`).
    fn then(&self, next: &PyPose) -> PyPose {
        PyPose { pose: self.pose.then(&next.pose) }
    }

    /// `a * b`: `a` first, then `b` (the main paper's order; the reverse of matrices' `A @ B`).
    fn __mul__(&self, other: &PyPose) -> PyPose {
        self.then(other)
    }

    /// The inverse pose.
    fn inverse(&self) -> PyResult<PyPose> {
        self.pose.try_inverse().map(|pose| PyPose { pose }).map_err(gam_error)
    }

    /// The images of the points `p` ((N, 3), or (3,) for one point) under this pose.
    fn transform_points<'py>(slf: &Bound<'py, Self>, p: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyAny>> {
        let a = floats(p, "points")?;
        let out = crate::arrays::transform_points(slf.py(), slf.as_any(), a.as_any())?;
        if a.ndim() == 1 { out.get_item(0) } else { Ok(out) }
    }

    fn __repr__(&self) -> PyResult<String> {
        let r = self.representations()?;
        Ok(format!("gam.Pose(position={}, quaternion={})", r["position"], r["quaternion"]))
    }

    /// Pickling (Dask, multiprocessing): the pose travels as its motor.
    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<(Bound<'py, PyAny>, (Bound<'py, PyAny>,))> {
        let py = slf.py();
        let ctor = py.get_type::<PyPose>().getattr("from_motor")?;
        let motor = to_py(py, &slf.get().representations()?["motor"])?;
        Ok((ctor, (motor,)))
    }
}
