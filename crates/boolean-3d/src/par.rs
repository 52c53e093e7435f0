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
//! ([`on_pool`]; on the caller's thread when nothing is large enough to
//! split), `join`s whose smaller side is below [`SEQUENTIAL_BELOW`]
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

/// Runs `f`, whose largest array has `items` items, on a worker thread of
/// the current pool (the global one when called from outside any pool),
/// so that the parallel steps inside it do not each cross from the
/// caller's thread into the pool. When nothing in `f` is large enough to
/// be split, `f` runs on the caller's thread and never wakes the pool (an
/// unsplit parallel iterator runs where it is called).
pub(crate) fn on_pool<R: Send>(items: usize, f: impl FnOnce() -> R + Send) -> R {
    // A parallel iterator over `n` items splits once `n >= 2 min_len(1)`.
    if rayon::current_thread_index().is_some() || min_len(1).saturating_mul(2) > items {
        f()
    } else {
        rayon::scope(|_| f())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{boolean_mesh, boolean_triangles, triangulate_mesh, BooleanOp};
    use proptest::prelude::*;
    use test_support::shapes::{box_mesh, box_triangles, icosphere, uv_sphere};
    use topology::TriangleMesh;

    /// Runs `f` with the thresholds forced to `mode` (see [`FORCE`]).
    fn forced<R>(mode: u8, f: impl FnOnce() -> R) -> R {
        FORCE.store(mode, Ordering::Relaxed);
        let r = f();
        FORCE.store(0, Ordering::Relaxed);
        r
    }

    /// Both variants, every operation, of `a` and `b`: the triangle
    /// results and the polygon results.
    fn all_ops(a: &TriangleMesh, b: &TriangleMesh) -> Vec<String> {
        let (pa, pb) = (a.to_polygon_mesh(), b.to_polygon_mesh());
        let mut out = Vec::new();
        for op in BooleanOp::BASIC {
            out.push(format!("{:?}", boolean_triangles(a, b, op)));
            out.push(format!("{:?}", boolean_mesh(&pa, &pb, op)));
        }
        out
    }

    #[test]
    fn thresholds_and_threads_do_not_change_results() {
        // Curved operands (no coplanar merge) and a plate with boxes cut
        // out of it (merged facets, re-used triangles).
        let a = icosphere([0.0; 3], 1.0, 3);
        let b = uv_sphere([0.3, 0.2, 0.1], 0.9, 24, 12);
        let mut plate = box_triangles([0.0, 0.0, 0.0], [4.0, 3.0, 1.0]);
        for (i, j) in [(0, 0), (1, 2), (3, 1)] {
            let (x, y) = (f64::from(i) + 0.25, f64::from(j) + 0.25);
            let hole = box_triangles([x, y, -0.5], [x + 0.5, y + 0.5, 1.5]);
            plate = boolean_triangles(&plate, &hole, BooleanOp::Difference)
                .unwrap()
                .mesh;
        }
        let cutter = box_triangles([1.5, 0.5, 0.5], [3.5, 2.5, 2.0]);
        for (x, y) in [(&a, &b), (&plate, &cutter)] {
            let default = all_ops(x, y);
            assert_eq!(forced(1, || all_ops(x, y)), default, "sequential");
            assert_eq!(forced(2, || all_ops(x, y)), default, "split");
            for threads in [1, 3] {
                let pool = rayon::ThreadPoolBuilder::new()
                    .num_threads(threads)
                    .build()
                    .unwrap();
                assert_eq!(pool.install(|| all_ops(x, y)), default, "{threads} threads");
            }
        }
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(test_support::cases(12)))]

        /// Chains of boxes cut out of a plate in the triangle-mesh variant,
        /// one difference at a time, with the thresholds forced to
        /// sequential and to split-everything: the same triangles every
        /// step, the exact volume (dyadic coordinates), valid topology,
        /// and as many triangles as the polygon variant's result on
        /// quadrilateral boxes, triangulated (every triangulation of a facet with `V` vertices
        /// and `H` holes has `V + 2H - 2` triangles).
        #[test]
        fn chains_of_boxes(cells in proptest::collection::btree_set((0u8..6, 0u8..4), 1..6),
                           jitter in proptest::collection::vec((-12i8..12, -12i8..12), 6)) {
            let plate = box_triangles([0.0, 0.0, 0.0], [6.0, 4.0, 1.0]);
            let mut seq = plate.clone();
            let mut split = plate.clone();
            let mut poly = box_mesh([0.0, 0.0, 0.0], [6.0, 4.0, 1.0]);
            for (k, &(i, j)) in cells.iter().enumerate() {
                let (jx, jy) = jitter[k];
                let x = f64::from(i) + 0.25 + f64::from(jx) / 64.0;
                let y = f64::from(j) + 0.25 + f64::from(jy) / 64.0;
                let hole = box_triangles([x, y, -0.5], [x + 0.5, y + 0.5, 1.5]);
                seq = forced(1, || boolean_triangles(&seq, &hole, BooleanOp::Difference))
                    .unwrap()
                    .mesh;
                split = forced(2, || boolean_triangles(&split, &hole, BooleanOp::Difference))
                    .unwrap()
                    .mesh;
                prop_assert_eq!(&seq, &split);
                let quads = box_mesh([x, y, -0.5], [x + 0.5, y + 0.5, 1.5]);
                poly = boolean_mesh(&poly, &quads, BooleanOp::Difference)
                    .unwrap()
                    .mesh;
                prop_assert!(seq.check_topology().is_ok());
                prop_assert_eq!(seq.signed_volume(), 24.0 - 0.25 * (k + 1) as f64);
                prop_assert_eq!(seq.triangles.len(), triangulate_mesh(&poly).triangles.len());
            }
        }
    }
}
