//! numpy arrays in and out: `(n, k)` float64 point arrays and integer index
//! arrays, converted by numpy itself (`numpy.asarray`) so any array-like
//! is accepted, with one-line errors naming the argument and the expected
//! shape and dtype.

use crate::error;
use numpy::{PyArray1, PyArrayMethods, PyUntypedArray, PyUntypedArrayMethods};
use pyo3::prelude::*;

/// `numpy.asarray(obj)` (or with `dtype`), any failure as an
/// `UmbraError` naming `what`.
fn as_array<'py>(
    obj: &Bound<'py, PyAny>,
    dtype: Option<&str>,
    what: &str,
    expected: &str,
) -> PyResult<Bound<'py, PyUntypedArray>> {
    let np = obj.py().import("numpy")?;
    let arr = match dtype {
        Some(d) => np.call_method1("ascontiguousarray", (obj, d)),
        None => np.call_method1("asarray", (obj,)),
    }
    .map_err(|e| error(format!("{what}: expected {expected}: {e}")))?;
    arr.cast_into::<PyUntypedArray>()
        .map_err(|_| error(format!("{what}: expected {expected}")))
}

/// The numpy dtype kind (`'f'`, `'i'`, `'u'`, `'b'`, `'O'`, ...) and name.
fn kind_of(arr: &Bound<'_, PyUntypedArray>) -> PyResult<(char, String)> {
    let dtype = arr.getattr("dtype")?;
    let kind: String = dtype.getattr("kind")?.extract()?;
    let name: String = dtype.getattr("name")?.extract()?;
    Ok((kind.chars().next().unwrap_or('?'), name))
}

/// An `(n, K)` array of numbers as points: integers and floats are
/// converted to float64 (exactly for integers up to 2^53); booleans,
/// strings, objects and other shapes are refused. NaN and infinite values
/// pass (the operations check coordinates and say where).
pub fn points<const K: usize>(obj: &Bound<'_, PyAny>, what: &str) -> PyResult<Vec<[f64; K]>> {
    let expected = format!("an (n, {K}) array of float64 coordinates");
    let raw = as_array(obj, None, what, &expected)?;
    let (kind, name) = kind_of(&raw)?;
    if !matches!(kind, 'f' | 'i' | 'u') {
        return Err(error(format!(
            "{what}: expected {expected}, got dtype {name}"
        )));
    }
    let shape = raw.shape().to_vec();
    let empty_list = shape == [0];
    if !(empty_list || shape.len() == 2 && shape[1] == K) {
        return Err(error(format!(
            "{what}: expected {expected}, got shape {}",
            shape_text(&shape)
        )));
    }
    let arr = as_array(raw.as_any(), Some("float64"), what, &expected)?;
    let arr = arr
        .cast_into::<numpy::PyArrayDyn<f64>>()
        .map_err(|_| error(format!("{what}: expected {expected}")))?;
    let ro = arr.readonly();
    let flat = ro.as_slice().map_err(|e| error(format!("{what}: {e}")))?;
    Ok(flat
        .chunks_exact(K)
        .map(|c| std::array::from_fn(|i| c[i]))
        .collect())
}

/// `(3, 4)` for messages.
pub fn shape_text(shape: &[usize]) -> String {
    match shape {
        [n] => format!("({n},)"),
        _ => format!(
            "({})",
            shape
                .iter()
                .map(usize::to_string)
                .collect::<Vec<_>>()
                .join(", ")
        ),
    }
}

/// A vertex index: an integer in `0..vertex_count`.
fn index(value: i128, vertex_count: usize, what: &str) -> PyResult<u32> {
    if value < 0 {
        return Err(error(format!("{what}: negative vertex index {value}")));
    }
    if value >= vertex_count as i128 {
        return Err(error(format!(
            "{what}: vertex index {value} out of range (the mesh has {vertex_count} vertices)"
        )));
    }
    u32::try_from(value).map_err(|_| error(format!("{what}: vertex index {value} beyond 32 bits")))
}

/// An integer numpy array (any shape) as vertex indices, row-major, each
/// checked against `vertex_count`; `None` when `arr` is not of an integer
/// dtype (the caller decides whether that is an error).
pub fn indices_of_array(
    arr: &Bound<'_, PyUntypedArray>,
    vertex_count: usize,
    what: &str,
) -> PyResult<Option<Vec<u32>>> {
    let (kind, _) = kind_of(arr)?;
    let values: Vec<i128> = match kind {
        'u' => {
            let a = as_array(arr.as_any(), Some("uint64"), what, "integers")?;
            let a = a
                .cast_into::<numpy::PyArrayDyn<u64>>()
                .map_err(|_| error(format!("{what}: expected integers")))?;
            let ro = a.readonly();
            let s = ro.as_slice().map_err(|e| error(format!("{what}: {e}")))?;
            s.iter().map(|&v| i128::from(v)).collect()
        }
        'i' => {
            let a = as_array(arr.as_any(), Some("int64"), what, "integers")?;
            let a = a
                .cast_into::<numpy::PyArrayDyn<i64>>()
                .map_err(|_| error(format!("{what}: expected integers")))?;
            let ro = a.readonly();
            let s = ro.as_slice().map_err(|e| error(format!("{what}: {e}")))?;
            s.iter().map(|&v| i128::from(v)).collect()
        }
        _ => return Ok(None),
    };
    values
        .into_iter()
        .map(|v| index(v, vertex_count, what))
        .collect::<PyResult<Vec<u32>>>()
        .map(Some)
}

/// One sequence of vertex indices (a loop): an integer array-like of one
/// dimension.
pub fn index_loop(obj: &Bound<'_, PyAny>, vertex_count: usize, what: &str) -> PyResult<Vec<u32>> {
    let expected = "a sequence of integer vertex indices";
    let arr = as_array(obj, None, what, expected)?;
    if arr.ndim() != 1 {
        return Err(error(format!(
            "{what}: expected {expected}, got shape {}",
            shape_text(arr.shape())
        )));
    }
    if arr.len() == 0 {
        return Err(error(format!("{what}: an empty loop")));
    }
    let (_, name) = kind_of(&arr)?;
    indices_of_array(&arr, vertex_count, what)?
        .ok_or_else(|| error(format!("{what}: expected {expected}, got dtype {name}")))
}

/// `true` when `obj` is a Python integer or a numpy integer scalar.
pub fn is_integer(obj: &Bound<'_, PyAny>) -> bool {
    if obj.is_instance_of::<pyo3::types::PyBool>() {
        return false;
    }
    obj.is_instance_of::<pyo3::types::PyInt>()
        || obj
            .py()
            .import("numpy")
            .and_then(|np| np.getattr("integer"))
            .and_then(|t| obj.is_instance(&t))
            .unwrap_or(false)
}

/// A float64 array of shape `(n, K)` from points.
pub fn points_array<'py, const K: usize>(
    py: Python<'py>,
    pts: &[[f64; K]],
) -> PyResult<Bound<'py, PyAny>> {
    let flat: Vec<f64> = pts.iter().flatten().copied().collect();
    Ok(PyArray1::from_vec(py, flat)
        .reshape([pts.len(), K])?
        .into_any())
}

/// An array of shape `(rows, cols)` from row-major values.
pub fn index_matrix<'py, T: numpy::Element>(
    py: Python<'py>,
    flat: Vec<T>,
    rows: usize,
    cols: usize,
) -> PyResult<Bound<'py, PyAny>> {
    Ok(PyArray1::from_vec(py, flat)
        .reshape([rows, cols])?
        .into_any())
}

/// An int64 array of one dimension from indices.
pub fn index_vector<'py>(py: Python<'py>, idx: &[u32]) -> Bound<'py, PyAny> {
    let v: Vec<i64> = idx.iter().map(|&i| i64::from(i)).collect();
    PyArray1::from_vec(py, v).into_any()
}
