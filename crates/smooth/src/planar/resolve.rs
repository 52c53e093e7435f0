//! The simplification step of 2D smoothing: where merging and cracking
//! left edges that cross, touch or overlap (exact tests over the pairs of
//! the broad phase), multiplicities above one, or winding numbers outside
//! `{0, 1}`, the modified Bentley-Ottmann sweep of chapter 7 rebuilds the
//! set as the cells of positive winding number (the standard form of
//! section 6.1: multiply enclosed regions become singly enclosed, inside-out
//! regions unenclosed), which is what a Boolean result that only rounding
//! and near-degeneracy disturbed is meant to fill.

use super::broad::edge_pairs_where;
use super::geom::edges_conflict;
use super::work::{VertexRecord, Work};
use crate::{SmoothCounts, SmoothError};
use simplify_2d::{cell_structure, simplify, CellStructure, FillRule, SweepStats};
use std::collections::HashMap;
use topology::PolygonSet2;

/// The number of edge pairs that meet other than at a shared vertex
/// (exact; the pairs come from the broad phase, never all pairs).
pub fn conflicts(w: &Work) -> u64 {
    edge_pairs_where(&w.pts, &w.edges, 0.0, |i, j| {
        let (e, f) = (w.edges[i], w.edges[j]);
        edges_conflict([e.a, e.b], [f.a, f.b], &w.pts).then_some(())
    })
    .len() as u64
}

/// What the step did.
pub enum Resolution {
    /// The set was already simple: no conflicts, every edge separates
    /// winding number 1 on its left from 0 on its right.
    Clean,
    /// The sweep rebuilt the set; its epsilon (section 8.4).
    Swept(f64),
}

fn internal(e: impl std::fmt::Display) -> SmoothError {
    SmoothError::Internal(format!(
        "the simplification sweep refused a smoothed set: {e}"
    ))
}

/// Checks the working copy and, when it is not simple, replaces it by its
/// simplification with the positive rule, in one sweep.
///
/// When every multiplicity is 1 the sweep's cell structure decides and
/// gives the shape: a sweep that split, merged and computed nothing found
/// no pair of edges that meet other than at a shared vertex (every
/// crossing, touching and overlapping pair is adjacent on its line at some
/// event and tested there exactly, and two vertices at one position are
/// one point to it), so the exact pair tests of the broad phase, which
/// count the crossings resolved, run only when it did; the set is clean
/// when, besides, every edge separates winding number 1 from 0, and
/// otherwise its cells of positive winding number replace it. A set with
/// higher multiplicities is simplified directly (the same sweep keeping
/// only the boundary).
pub fn resolve(w: &mut Work, counts: &mut SmoothCounts) -> Result<Resolution, SmoothError> {
    let set = w.to_set();
    let (shape, epsilon, sweep_k, unchanged) = if w.max_multiplicity() <= 1 {
        let cells = cell_structure(&set).map_err(internal)?;
        let unchanged = sweep_found_nothing(&cells.stats(), cells.vertices().len(), w.pts.len());
        if unchanged && simple_windings(&cells) {
            debug_assert_eq!(conflicts(w), 0, "the sweep missed a conflicting pair");
            return Ok(Resolution::Clean);
        }
        let shape = cells.shape_with(|&w| w > 0);
        (shape, cells.epsilon(), cells.k_max(), unchanged)
    } else {
        let s = simplify(&set, FillRule::Positive).map_err(internal)?;
        (s.shape, s.epsilon, s.k_max, false)
    };
    if unchanged {
        debug_assert_eq!(conflicts(w), 0, "the sweep missed a conflicting pair");
    } else {
        counts.crossings_resolved += conflicts(w);
    }
    replace(w, &shape, sweep_k);
    Ok(Resolution::Swept(epsilon))
}

/// Whether every edge of the cell structure separates winding number 1 on
/// its left from 0 on its right.
fn simple_windings(cells: &CellStructure<i32>) -> bool {
    cells.edges().iter().all(|e| {
        e.mult == 0
            || (e.left - e.right == e.mult && e.left.max(e.right) == 1 && e.left.min(e.right) == 0)
    })
}

/// Whether a set is what [`resolve`] calls clean, without a working copy:
/// every edge of multiplicity 1, and one sweep that split, merged and
/// computed nothing and met `referenced` points (the number of vertices
/// an edge uses: two at one position are one point to the sweep), each
/// edge with winding number 1 on its left and 0 on its right. A set with
/// two entries on one vertex pair is merged by the sweep, so not clean.
pub fn is_simple(set: &PolygonSet2, referenced: usize) -> Result<bool, SmoothError> {
    if set.edges().iter().any(|e| e.mult != 1) {
        return Ok(false);
    }
    let cells = cell_structure(set).map_err(internal)?;
    Ok(
        sweep_found_nothing(&cells.stats(), cells.vertices().len(), referenced)
            && simple_windings(&cells),
    )
}

/// Whether the sweep left the edges as they were: no crossing computed,
/// no edge split or merged with another, and one point (of `points` the
/// sweep met) per vertex (`vertices` of them, all referenced).
fn sweep_found_nothing(s: &SweepStats, points: usize, vertices: usize) -> bool {
    s.intersections == 0
        && s.vertex_on_edge_splits == 0
        && s.through_splits == 0
        && s.misgrouped_splits == 0
        && s.merged_input_edges == s.input_edges
        && points == vertices
}

/// Replaces the working copy by the sweep's output, keeping the records
/// (and the tracking of input vertices) of the vertices whose position
/// the sweep kept; the vertices it created carry the sweep's `k_max` on
/// top of the largest count so far.
fn replace(w: &mut Work, shape: &PolygonSet2, sweep_k: u32) {
    let key = |p: [f64; 2]| (p[0].to_bits(), p[1].to_bits());
    let mut by_pos: HashMap<(u64, u64), u32> = HashMap::new();
    for (i, &p) in shape.vertices().iter().enumerate() {
        by_pos.entry(key(p)).or_insert(i as u32);
    }
    let created_k = w.k_max().saturating_add(sweep_k.max(1));
    let mut rec = vec![VertexRecord { k: created_k }; shape.vertex_count()];
    let mut old_to_new = vec![None; w.pts.len()];
    for (v, &p) in w.pts.iter().enumerate() {
        if let Some(&i) = by_pos.get(&key(p)) {
            rec[i as usize] = w.rec[v];
            old_to_new[v] = Some(i);
        }
    }
    let tracked: Vec<Option<u32>> = w
        .tracked
        .iter()
        .map(|t| t.and_then(|v| old_to_new[v as usize]))
        .collect();
    let mut next = Work::from_set(shape);
    next.rec = rec;
    next.tracked = tracked;
    *w = next;
}

#[cfg(test)]
mod tests {
    use super::*;
    use test_support::rng::SplitMix64;

    /// Random loops on a coarse grid (crossings, touchings, overlaps,
    /// repeated points under distinct ids): whenever the sweep reports
    /// that it changed nothing, no pair of edges conflicts by the exact
    /// tests, so skipping them decides as they would. Both outcomes occur.
    #[test]
    fn a_sweep_that_changed_nothing_leaves_no_conflict() {
        let mut rng = SplitMix64::new(17);
        let (mut untouched, mut touched) = (0, 0);
        for round in 0..600 {
            let mut set = PolygonSet2::new();
            for _ in 0..1 + round % 3 {
                let n = 3 + (rng.next_u64() % 4) as usize;
                let ring: Vec<[f64; 2]> = (0..n)
                    .map(|_| [(rng.next_u64() % 5) as f64, (rng.next_u64() % 5) as f64])
                    .collect();
                set.add_loop(&ring);
            }
            let mut w = Work::from_set(&set);
            w.normalize(&mut SmoothCounts::default());
            w.remove_unreferenced(&mut SmoothCounts::default());
            let cells = cell_structure(&w.to_set()).unwrap();
            if sweep_found_nothing(&cells.stats(), cells.vertices().len(), w.pts.len()) {
                untouched += 1;
                assert_eq!(conflicts(&w), 0, "round {round}: {set:?}");
            } else {
                touched += 1;
            }
        }
        assert!(untouched > 50 && touched > 50, "{untouched} {touched}");
    }

    /// The step as it was before it swept once: the cell structure first
    /// when every multiplicity is 1, then, for a set with crossings, the
    /// simplification in a second sweep (which sweeps in strips only
    /// where sampled crossings outnumber the edges, never in these sets).
    fn resolve_in_two_sweeps(
        w: &mut Work,
        counts: &mut SmoothCounts,
    ) -> Result<Resolution, SmoothError> {
        let set = w.to_set();
        let cells = (w.max_multiplicity() <= 1).then(|| cell_structure(&set).unwrap());
        let crossing = match &cells {
            Some(c) if sweep_found_nothing(&c.stats(), c.vertices().len(), w.pts.len()) => 0,
            _ => conflicts(w),
        };
        let (shape, epsilon, sweep_k) = match cells {
            Some(cells) if crossing == 0 => {
                if simple_windings(&cells) {
                    return Ok(Resolution::Clean);
                }
                (cells.shape_with(|&w| w > 0), cells.epsilon(), cells.k_max())
            }
            _ => {
                let s = simplify(&set, FillRule::Positive).unwrap();
                (s.shape, s.epsilon, s.k_max)
            }
        };
        counts.crossings_resolved += crossing;
        replace(w, &shape, sweep_k);
        Ok(Resolution::Swept(epsilon))
    }

    /// The one-sweep step decides, replaces and counts as the two-sweep
    /// step did, bit for bit, on random loops of a coarse grid (clean
    /// sets, crossings, touchings, overlaps, repeated points, edges drawn
    /// twice, inside-out loops) and on finer random loops.
    #[test]
    fn one_sweep_resolves_as_two_sweeps_did() {
        let mut rng = SplitMix64::new(29);
        let (mut clean, mut swept) = (0, 0);
        for round in 0..800 {
            let grid = if round % 4 == 3 { 1 << 20 } else { 5 };
            let mut set = PolygonSet2::new();
            for _ in 0..1 + round % 3 {
                let n = 3 + (rng.next_u64() % 5) as usize;
                let ring: Vec<[f64; 2]> = (0..n)
                    .map(|_| {
                        let c = |r: u64| (r % grid) as f64 / grid as f64;
                        [c(rng.next_u64()), c(rng.next_u64())]
                    })
                    .collect();
                // A triangle turned counter-clockwise is a clean set.
                let mut ring = ring;
                if round % 6 == 1 {
                    ring.truncate(3);
                    if robust_arith::orient2d(ring[0], ring[1], ring[2]).is_lt() {
                        ring.swap(1, 2);
                    }
                }
                set.add_loop(&ring);
                if round % 5 == 0 {
                    set.add_loop(&ring);
                }
            }
            let mut w = Work::from_set(&set);
            w.normalize(&mut SmoothCounts::default());
            w.remove_unreferenced(&mut SmoothCounts::default());
            let (mut a, mut b) = (w.clone(), w);
            let (mut ca, mut cb) = (SmoothCounts::default(), SmoothCounts::default());
            let ra = resolve(&mut a, &mut ca).unwrap();
            let rb = resolve_in_two_sweeps(&mut b, &mut cb).unwrap();
            match (ra, rb) {
                (Resolution::Clean, Resolution::Clean) => clean += 1,
                (Resolution::Swept(x), Resolution::Swept(y)) => {
                    assert_eq!(x.to_bits(), y.to_bits(), "round {round}");
                    swept += 1;
                }
                _ => panic!("round {round}: the steps decided differently on {set:?}"),
            }
            assert_eq!(ca, cb, "round {round}");
            let bits = |w: &Work| {
                let pts: Vec<[u64; 2]> = w
                    .pts
                    .iter()
                    .map(|p| [p[0].to_bits(), p[1].to_bits()])
                    .collect();
                (
                    pts,
                    w.to_set().edges().to_vec(),
                    w.rec.clone(),
                    w.tracked.clone(),
                )
            };
            assert_eq!(bits(&a), bits(&b), "round {round}");
        }
        assert!(clean > 50 && swept > 200, "{clean} {swept}");
    }
}
