//! The native part of the `umbra` Python package (`umbra._umbra`): the
//! facade's meshes, Booleans, simplification, CSG trees and file formats
//! behind a small PyO3 API, with numpy arrays in and out. The pure-Python
//! layer (`python/umbra/__init__.py`) adds the shapely and trimesh
//! conversions and re-exports everything here.
//!
//! Every operation copies its inputs out of Python objects, then releases
//! the GIL (`run`) while the facade computes, so two Python threads run
//! two Booleans on two cores at once. A panic never crosses into Python: it
//! is caught and raised as `UmbraError("internal error ...")`. Every error
//! is an `umbra.UmbraError` (a `ValueError`) with the command-line tool's
//! one-line message.

// PyO3's macros expand to unsafe FFI code: the workspace's `forbid` would
// refuse them, so this crate only denies unsafe code of its own.
#![deny(unsafe_code)]

mod arrays;
mod files;
mod mesh;
mod ops;
mod planar;

use pyo3::create_exception;
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use std::panic::{catch_unwind, AssertUnwindSafe};

create_exception!(
    _umbra,
    UmbraError,
    PyValueError,
    "An error of umbra: bad input (a NaN coordinate, a dangling index, an open mesh, an unknown operation, an unreadable file) or, for messages starting with 'internal error', a bug to report. The message is one line, as the command-line tool prints it."
);

/// An `UmbraError` with `message`.
pub(crate) fn error(message: impl Into<String>) -> PyErr {
    UmbraError::new_err(message.into())
}

thread_local! {
    /// This Python thread's own rayon pool, as many threads as the global
    /// one (`RAYON_NUM_THREADS` or the cores), made at its first call: the
    /// calls of different Python threads never queue for one pool, so with
    /// `RAYON_NUM_THREADS=1` two threads run two Booleans on two cores (on
    /// the shared global pool of one worker they ran one after the other).
    static POOL: Option<rayon::ThreadPool> = rayon::ThreadPoolBuilder::new()
        .num_threads(rayon::current_num_threads())
        .build()
        .ok();
}

/// Runs `work` with the GIL released, on the calling thread's pool
/// ([`POOL`]), and any panic caught: the result, or an `UmbraError` (the
/// work's own error as its one-line message, a panic as an internal error).
pub(crate) fn run<T, E, F>(py: Python<'_>, work: F) -> PyResult<T>
where
    F: FnOnce() -> Result<T, E> + Send,
    T: Send,
    E: std::fmt::Display + Send,
{
    let caught = move || catch_unwind(AssertUnwindSafe(work));
    let on_pool = move || {
        POOL.with(|pool| match pool {
            Some(pool) => pool.install(caught),
            None => caught(),
        })
    };
    let outcome = py.detach(move || match on_pool() {
        Ok(Ok(value)) => Ok(value),
        Ok(Err(e)) => Err(e.to_string()),
        Err(panic) => {
            let what = panic
                .downcast_ref::<&str>()
                .map(|s| s.to_string())
                .or_else(|| panic.downcast_ref::<String>().cloned())
                .unwrap_or_else(|| "a panic".to_string());
            Err(format!(
                "internal error (this is a bug, please report it): {}",
                what.replace(['\n', '\r'], " ")
            ))
        }
    });
    outcome.map_err(error)
}

/// The module `umbra._umbra`.
#[pymodule]
fn _umbra(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("UmbraError", m.py().get_type::<UmbraError>())?;
    m.add_class::<mesh::Mesh>()?;
    m.add_function(wrap_pyfunction!(ops::boolean, m)?)?;
    m.add_function(wrap_pyfunction!(ops::union_all, m)?)?;
    m.add_function(wrap_pyfunction!(ops::smooth, m)?)?;
    m.add_function(wrap_pyfunction!(ops::csg, m)?)?;
    m.add_function(wrap_pyfunction!(planar::boolean_2d, m)?)?;
    m.add_function(wrap_pyfunction!(planar::simplify, m)?)?;
    m.add_function(wrap_pyfunction!(files::read, m)?)?;
    m.add_function(wrap_pyfunction!(files::write_mesh, m)?)?;
    m.add_function(wrap_pyfunction!(files::write_polygons, m)?)?;
    m.add_function(wrap_pyfunction!(ops::panic_for_tests, m)?)?;
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    Ok(())
}
