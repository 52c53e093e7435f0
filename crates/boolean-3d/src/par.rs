//! How the Boolean uses the thread pool: one entry into the pool per
//! call, and sequential work below a size threshold.
//!
//! A Boolean of a small operand against a large one (one step of a chain
//! of differences) takes a millisecond or so, made of a few dozen
//! parallel steps. Called from outside the pool, every `join` or parallel
//! iterator would hand its work to a worker thread and wait for it, and
//! every split would wake idle workers that find nothing to steal; on
//! millisecond steps that hand-over (futex waits, yields) costs as much as
//! the work. So each entry point runs its whole body on a worker
//! ([`on_pool`]), `join`s whose smaller side is below [`SEQUENTIAL_BELOW`]
//! items run one after the other ([`join`]), and parallel iterators are
//! not split below [`MIN_LEN`] items.
//!
//! None of this changes a result: every parallel step of the Boolean
//! concatenates its parts in input order (see the module headers), so the
//! output is bit for bit the same whatever the threads and thresholds
//! (tested with the thresholds forced either way).

#[cfg(test)]
use std::sync::atomic::{AtomicU8, Ordering};

/// A `join` whose smaller side has fewer items than this (facets, edges,
/// half-edges: whatever the side works on) runs sequentially.
pub(crate) const SEQUENTIAL_BELOW: usize = 4096;

/// Parallel iterators over items are split into pieces of at least this
/// many items.
pub(crate) const MIN_LEN: usize = 2048;

/// Test override: 0 = the thresholds above, 1 = always sequential, 2 =
/// always parallel. Results do not depend on it, so tests that run
/// concurrently with one that sets it are unaffected.
#[cfg(test)]
pub(crate) static FORCE: AtomicU8 = AtomicU8::new(0);

/// Whether work on `items` items (the smaller side of a `join`) is worth
/// splitting.
#[inline]
pub(crate) fn worth_splitting(items: usize) -> bool {
    #[cfg(test)]
    match FORCE.load(Ordering::Relaxed) {
        1 => return false,
        2 => return true,
        _ => {}
    }
    items >= SEQUENTIAL_BELOW
}

/// The minimum piece length for a parallel iterator over `unit`-item
/// elements (1 for plain items, the chunk size for `par_chunks`).
#[inline]
pub(crate) fn min_len(unit: usize) -> usize {
    #[cfg(test)]
    match FORCE.load(Ordering::Relaxed) {
        1 => return usize::MAX,
        2 => return 1,
        _ => {}
    }
    MIN_LEN.div_ceil(unit.max(1))
}

/// `rayon::join` when both sides are worth splitting (`items` is the size
/// of the smaller side), else `a` then `b` on the current thread.
#[inline]
pub(crate) fn join<RA: Send, RB: Send>(
    items: usize,
    a: impl FnOnce() -> RA + Send,
    b: impl FnOnce() -> RB + Send,
) -> (RA, RB) {
    if worth_splitting(items) {
        rayon::join(a, b)
    } else {
        (a(), b())
    }
}

/// Runs `f` on a worker thread of the current pool (the global one when
/// called from outside any pool), so that the parallel steps inside it do
/// not each cross from the caller's thread into the pool.
pub(crate) fn on_pool<R: Send>(f: impl FnOnce() -> R + Send) -> R {
    if rayon::current_thread_index().is_some() {
        f()
    } else {
        rayon::scope(|_| f())
    }
}
