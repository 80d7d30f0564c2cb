//! numpy arrays in and out: inputs are checked (shape, a real dtype, finite entries) before
//! any work, so a bad array is a `GamError`, never a crash or a silent NaN; and
//! `gam.transform_points`, the bulk map of points by rigid poses.

use crate::gam_error;
use crate::pose::PyPose;
use gam_cli::api::CliError;
use numpy::ndarray::Array;
use numpy::{PyArray, PyArrayDyn, PyArrayMethods, PyReadonlyArrayDyn, PyUntypedArrayMethods};
use pyo3::prelude::*;
use pyo3::types::{PyList, PyTuple};
use rayon::prelude::*;

/// Above this many items the Rust loops run in parallel (rayon).
pub(crate) const PARALLEL_ABOVE: usize = 4096;

/// The orthonormality tolerance of a rigid matrix: the command line's (`{"matrix": ...}` poses).
pub(crate) const RIGID_TOL: f64 = 1e-9;

/// An array of float64 with its shape: `obj` itself when it is one (no copy), otherwise
/// `numpy.asarray(obj)` converted when its dtype is an integer or float type.
pub(crate) fn floats<'py>(obj: &Bound<'py, PyAny>, what: &str) -> PyResult<PyReadonlyArrayDyn<'py, f64>> {
    if let Ok(a) = obj.cast::<PyArrayDyn<f64>>() {
        return Ok(a.readonly());
    }
    let np = obj.py().import("numpy")?;
    let arr = np
        .call_method1("asarray", (obj,))
        .map_err(|e| gam_error(format!("`{what}` is not an array of numbers ({e})")))?;
    let dtype = arr.getattr("dtype")?;
    let kind: String = dtype.getattr("kind")?.extract()?;
    if !matches!(kind.as_str(), "f" | "i" | "u") {
        return Err(gam_error(format!("`{what}` must hold real numbers (got dtype {})", dtype.str()?)));
    }
    let arr = arr.call_method1("astype", ("float64",))?;
    Ok(arr
        .cast_into::<PyArrayDyn<f64>>()
        .map_err(|_| gam_error(format!("`{what}` is not a float64 array")))?
        .readonly())
}

/// The shape as text, `(2, 3)`.
pub(crate) fn shape_text(shape: &[usize]) -> String {
    match shape {
        [n] => format!("({n},)"),
        _ => format!("({})", shape.iter().map(usize::to_string).collect::<Vec<_>>().join(", ")),
    }
}

/// The entries in C order (borrowed when the array is contiguous), refusing NaN and infinity.
pub(crate) fn finite_entries<'a>(
    a: &'a PyReadonlyArrayDyn<'_, f64>,
    what: &str,
) -> PyResult<std::borrow::Cow<'a, [f64]>> {
    let data: std::borrow::Cow<'a, [f64]> = match a.as_slice() {
        Ok(s) => s.into(),
        Err(_) => a.as_array().iter().copied().collect::<Vec<f64>>().into(),
    };
    if let Some(i) = data.iter().position(|x| !x.is_finite()) {
        let shape = a.shape();
        let mut index = Vec::with_capacity(shape.len());
        let mut rest = i;
        for d in shape.iter().rev() {
            index.push(rest % d);
            rest /= d;
        }
        index.reverse();
        let index: Vec<String> = index.iter().map(usize::to_string).collect();
        return Err(gam_error(format!("`{what}[{}]` is {}: entries must be finite", index.join(", "), data[i])));
    }
    Ok(data)
}

/// A (rows x cols) float64 result from its C-order entries.
pub(crate) fn array2<'py>(py: Python<'py>, rows: usize, cols: usize, data: Vec<f64>) -> PyResult<Bound<'py, PyAny>> {
    let a = Array::from_shape_vec((rows, cols), data).map_err(|e| gam_error(format!("internal: {e}")))?;
    Ok(PyArray::from_owned_array(py, a).into_any())
}

/// A (n x a x b) float64 result from its C-order entries.
pub(crate) fn array3<'py>(py: Python<'py>, shape: [usize; 3], data: Vec<f64>) -> PyResult<Bound<'py, PyAny>> {
    let a = Array::from_shape_vec(shape, data).map_err(|e| gam_error(format!("internal: {e}")))?;
    Ok(PyArray::from_owned_array(py, a).into_any())
}

/// The 3x4 rigid part of a 4x4 matrix (16 entries, row-major) when it is a rigid motion within
/// [`RIGID_TOL`] (the checks of `Pose::from_matrix`); otherwise the reason, from `Pose::from_matrix`.
fn rigid(m: &[f64]) -> Result<(), String> {
    let close = |x: f64, y: f64| (x - y).abs() <= RIGID_TOL;
    let col = |j: usize| [m[j], m[4 + j], m[8 + j]];
    let dot = |a: [f64; 3], b: [f64; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    let (c0, c1, c2) = (col(0), col(1), col(2));
    let det = c0[0] * (c1[1] * c2[2] - c2[1] * c1[2]) - c1[0] * (c0[1] * c2[2] - c2[1] * c0[2])
        + c2[0] * (c0[1] * c1[2] - c1[1] * c0[2]);
    let ok = close(m[12], 0.0)
        && close(m[13], 0.0)
        && close(m[14], 0.0)
        && close(m[15], 1.0)
        && close(dot(c0, c0), 1.0)
        && close(dot(c1, c1), 1.0)
        && close(dot(c2, c2), 1.0)
        && close(dot(c0, c1), 0.0)
        && close(dot(c0, c2), 0.0)
        && close(dot(c1, c2), 0.0)
        && det > 0.0;
    if ok {
        return Ok(());
    }
    let rows: [[f64; 4]; 4] = std::array::from_fn(|i| std::array::from_fn(|j| m[4 * i + j]));
    match motion::Pose::from_matrix(&rows, &RIGID_TOL) {
        Err(e) => Err(e.to_string()),
        Ok(_) => Ok(()),
    }
}

/// `R p + v` for a rigid matrix (16 entries, row-major): the last row is `[0, 0, 0, 1]`.
#[inline]
fn apply(m: &[f64], p: &[f64]) -> [f64; 3] {
    std::array::from_fn(|i| m[4 * i] * p[0] + m[4 * i + 1] * p[1] + m[4 * i + 2] * p[2] + m[4 * i + 3])
}

/// The matrices of `matrices_or_poses` when they are `Pose`s (one, or a list): their entries
/// and their count (`None`: one pose for every point); `None` when it is not made of poses.
fn pose_matrices(obj: &Bound<'_, PyAny>) -> PyResult<Option<(Vec<f64>, Option<usize>)>> {
    if let Ok(p) = obj.cast::<PyPose>() {
        return Ok(Some((p.get().matrix_entries()?.to_vec(), None)));
    }
    let is_seq = obj.cast::<PyList>().is_ok() || obj.cast::<PyTuple>().is_ok();
    if !(is_seq && obj.len()? > 0 && obj.get_item(0)?.cast::<PyPose>().is_ok()) {
        return Ok(None);
    }
    let mut out = Vec::with_capacity(16 * obj.len()?);
    for (i, item) in obj.try_iter()?.enumerate() {
        let item = item?;
        let p = item
            .cast::<PyPose>()
            .map_err(|_| gam_error(format!("`matrices_or_poses[{i}]` is not a Pose (a list must hold only Poses)")))?;
        out.extend_from_slice(&p.get().matrix_entries()?);
    }
    let n = out.len() / 16;
    Ok(Some((out, Some(n))))
}

/// `gam.transform_points(matrices_or_poses, points)`: the images of N points under N rigid poses
/// (`R p + v` for each pair), an (N, 3) array. `matrices_or_poses` is an (N, 4, 4) array of
/// rigid matrices, a list of N `Pose`s, or one (4, 4) matrix or `Pose` for all the points;
/// `points` is (N, 3), or (3,) for one point under every pose. Matrices must be rigid (as
/// the command line's `{"matrix": ...}` poses: rotation block orthonormal to 1e-9, last row
/// `[0, 0, 0, 1]`). The loop runs in Rust, in parallel for large N, with the interpreter detached.
#[pyfunction]
pub(crate) fn transform_points<'py>(
    py: Python<'py>,
    matrices_or_poses: &Bound<'py, PyAny>,
    points: &Bound<'py, PyAny>,
) -> PyResult<Bound<'py, PyAny>> {
    let poses = pose_matrices(matrices_or_poses)?;
    let array = match poses {
        Some(_) => None,
        None => Some(floats(matrices_or_poses, "matrices_or_poses")?),
    };
    let (m, m_count): (std::borrow::Cow<'_, [f64]>, Option<usize>) = match (&poses, &array) {
        (Some((m, count)), _) => (m.as_slice().into(), *count),
        (None, Some(a)) => {
            let count = match a.shape() {
                [4, 4] => None,
                [n, 4, 4] => Some(*n),
                shape => {
                    return Err(gam_error(format!(
                        "`matrices_or_poses` must have shape (N, 4, 4) or (4, 4), or be Poses (got shape {})",
                        shape_text(shape)
                    )));
                }
            };
            // entries are checked finite with the rigidity, in the one pass below
            let data: std::borrow::Cow<'_, [f64]> = match a.as_slice() {
                Ok(m) => m.into(),
                Err(_) => a.as_array().iter().copied().collect::<Vec<f64>>().into(),
            };
            (data, count)
        }
        (None, None) => return Err(gam_error("internal: no matrices")),
    };
    let pa = floats(points, "points")?;
    let pshape = pa.shape().to_vec();
    let p_count = match pshape[..] {
        [3] => None,
        [n, 3] => Some(n),
        _ => {
            return Err(gam_error(format!(
                "`points` must have shape (N, 3) or (3,) (got shape {})",
                shape_text(&pshape)
            )));
        }
    };
    let n = match (m_count, p_count) {
        (Some(a), Some(b)) if a != b => {
            return Err(gam_error(format!("{a} poses for {b} points: give one pose per point, or one pose for all")));
        }
        (Some(a), _) => a,
        (None, Some(b)) => b,
        (None, None) => 1,
    };
    gam_cli::api::check_budget(&format!("transforming {n} points"), n as f64).map_err(crate::gam_error)?;
    let p = finite_entries(&pa, "points")?;
    let (m, p): (&[f64], &[f64]) = (&m, &p);
    let (m_step, p_step) = (if m_count.is_some() { 16 } else { 0 }, if p_count.is_some() { 3 } else { 0 });
    let out = crate::run_detached(py, || {
        let check = |i: usize| {
            let at = || if m_count.is_some() { format!("[{i}]") } else { String::new() };
            let mi = &m[i * 16..i * 16 + 16];
            if let Some(x) = mi.iter().find(|x| !x.is_finite()) {
                let at = at();
                return Err(CliError::usage(format!(
                    "`matrices_or_poses{at}` has the entry {x}: entries must be finite"
                )));
            }
            rigid(mi).map_err(|why| {
                CliError::usage(format!("`matrices_or_poses{} is not a rigid motion: {why}", at() + "`"))
            })
        };
        // one pass: check the pose (once per pose) and map the point
        let one = |i: usize, o: &mut [f64]| -> Result<(), CliError> {
            if m_step > 0 || i == 0 {
                check(i * m_step / 16)?;
            }
            o.copy_from_slice(&apply(&m[i * m_step..i * m_step + 16], &p[i * p_step..i * p_step + 3]));
            Ok(())
        };
        let mut out = vec![0.0; 3 * n];
        let done = if n > PARALLEL_ABOVE {
            out.par_chunks_mut(3).enumerate().with_min_len(1024).try_for_each(|(i, o)| one(i, o))
        } else {
            out.chunks_mut(3).enumerate().try_for_each(|(i, o)| one(i, o))
        };
        match done {
            // the first bad pose in index order (a parallel pass stops at any)
            Err(_) => Err((0..if m_step > 0 { n } else { 1 })
                .find_map(|i| check(i).err())
                .unwrap_or_else(|| CliError::usage("`matrices_or_poses`: a pose is not a rigid motion".to_string()))),
            Ok(()) => Ok(out),
        }
    })?;
    array2(py, n, 3, out)
}
