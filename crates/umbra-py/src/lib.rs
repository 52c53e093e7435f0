//! The native part of the `umbra` Python package (`umbra._umbra`): the
//! facade's meshes, Booleans, simplification, CSG trees and file formats
//! behind a small PyO3 API, with numpy arrays in and out. The pure-Python
//! layer (`python/umbra/__init__.py`) adds the shapely and trimesh
//! conversions and re-exports everything here.
//!
//! Every operation copies its inputs out of Python objects, then releases
//! the GIL (`run`) while the facade computes, so two Python threads run
//! two Booleans on two cores at once. The work runs on a rayon pool of
//! this process (rebuilt in a child after `fork`, whose inherited pool has
//! no threads): one shared pool, or one single-worker pool per Python
//! thread under `RAYON_NUM_THREADS=1`. A panic never crosses into Python: it
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
use std::cell::RefCell;
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::sync::{Arc, Mutex, PoisonError};

// Registered under `umbra` (the package re-exports it there), so pickle
// finds it by that name: an error raised in a worker process reaches its
// caller as an `UmbraError`.
create_exception!(
    umbra,
    UmbraError,
    PyValueError,
    "An error of umbra: bad input (a NaN coordinate, a dangling index, an open mesh, an unknown operation, an unreadable file) or, for messages starting with 'internal error', a bug to report. The message is one line, as the command-line tool prints it."
);

/// An `UmbraError` with `message`.
pub(crate) fn error(message: impl Into<String>) -> PyErr {
    UmbraError::new_err(message.into())
}

/// A rayon pool and the process that built it. After `fork` the child
/// inherits a pool's memory but not its worker threads, so a job installed
/// on it would wait forever: a pool built by another process is never
/// used again (it is leaked, as dropping it would signal threads that do
/// not exist) and a new one is built.
struct ProcessPool {
    pid: u32,
    pool: Arc<rayon::ThreadPool>,
}

impl ProcessPool {
    /// This process's pool in `slot`, built (or rebuilt after a fork) with
    /// `threads` workers; `None` when the system refuses threads.
    fn current(slot: &mut Option<ProcessPool>, threads: usize) -> Option<Arc<rayon::ThreadPool>> {
        let pid = std::process::id();
        if slot.as_ref().is_none_or(|p| p.pid != pid) {
            if let Some(inherited) = slot.take() {
                std::mem::forget(inherited);
            }
            *slot = rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .ok()
                .map(|pool| ProcessPool {
                    pid,
                    pool: Arc::new(pool),
                });
        }
        slot.as_ref().map(|p| Arc::clone(&p.pool))
    }
}

/// The worker threads per operation: `RAYON_NUM_THREADS` when it is a
/// positive number, else the available cores (rayon's own rule, read here
/// so that rayon's global pool, which nothing uses, is never started).
fn configured_threads() -> usize {
    std::env::var("RAYON_NUM_THREADS")
        .ok()
        .and_then(|v| v.trim().parse::<usize>().ok())
        .filter(|&n| n > 0)
        .unwrap_or_else(|| std::thread::available_parallelism().map_or(1, |n| n.get()))
}

/// The pool shared by every Python thread when operations run on several
/// workers: concurrent calls share its workers, so the process never holds
/// more than one pool's threads however many Python threads call.
static SHARED: Mutex<Option<ProcessPool>> = Mutex::new(None);

thread_local! {
    /// This Python thread's own one-worker pool, when operations run on
    /// one worker (`RAYON_NUM_THREADS=1`): calls of different Python
    /// threads then still run side by side, one core each, instead of
    /// queueing for one shared worker.
    static OWN: RefCell<Option<ProcessPool>> = const { RefCell::new(None) };
}

/// The pool the calling thread's operation runs on.
fn pool() -> Option<Arc<rayon::ThreadPool>> {
    let threads = configured_threads();
    if threads == 1 {
        OWN.with(|own| ProcessPool::current(&mut own.borrow_mut(), 1))
    } else {
        // The lock is held only to look up or build the pool, never while
        // an operation runs.
        let mut shared = SHARED.lock().unwrap_or_else(PoisonError::into_inner);
        ProcessPool::current(&mut shared, threads)
    }
}

/// Raises a `UserWarning` with `message` in the caller's frame (a
/// message with a NUL byte is cut there).
pub(crate) fn warn_user(py: Python<'_>, message: &str) -> PyResult<()> {
    let text = message.split('\0').next().unwrap_or_default();
    let message = std::ffi::CString::new(text).unwrap_or_default();
    let category = py.get_type::<pyo3::exceptions::PyUserWarning>();
    PyErr::warn(py, category.as_any(), &message, 1)
}

/// Runs `work` with the GIL released, on this process's pool (`pool`),
/// and any panic caught: the result, or an `UmbraError` (the
/// work's own error as its one-line message, a panic as an internal error).
pub(crate) fn run<T, E, F>(py: Python<'_>, work: F) -> PyResult<T>
where
    F: FnOnce() -> Result<T, E> + Send,
    T: Send,
    E: std::fmt::Display + Send,
{
    let caught = move || catch_unwind(AssertUnwindSafe(work));
    let on_pool = move || match pool() {
        Some(pool) => pool.install(caught),
        None => caught(),
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
    m.add_function(wrap_pyfunction!(ops::difference_all, m)?)?;
    m.add_function(wrap_pyfunction!(ops::smooth, m)?)?;
    m.add_function(wrap_pyfunction!(ops::csg, m)?)?;
    m.add_function(wrap_pyfunction!(planar::boolean_2d, m)?)?;
    m.add_function(wrap_pyfunction!(planar::boolean_2d_all, m)?)?;
    m.add_function(wrap_pyfunction!(planar::simplify, m)?)?;
    m.add_function(wrap_pyfunction!(files::read, m)?)?;
    m.add_function(wrap_pyfunction!(files::write_mesh, m)?)?;
    m.add_function(wrap_pyfunction!(files::write_polygons, m)?)?;
    m.add_function(wrap_pyfunction!(ops::panic_for_tests, m)?)?;
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    Ok(())
}
