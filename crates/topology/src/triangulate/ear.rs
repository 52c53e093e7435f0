//! Ear clipping of one polygon (section 4.8, step 4): possibly with
//! repeated vertices from bridges, possibly self-overlapping.
//!
//! The scan for an ear is the plain one (from the vertex after the last
//! ear, the first valid ear whose chord passes through no vertex, else
//! the first valid one, else the first degenerate one, else the one of smallest absolute
//! area) on every polygon. What makes it fast on big
//! polygons is the test of a valid ear's emptiness: only vertices in the
//! ear's box can lie in the ear, so on polygons of [`INDEXED`] vertices or
//! more (with finite coordinates) they are looked up in a [`Grid`] instead
//! of scanning the whole polygon. Both ways test the same vertices with the
//! same predicate, so they clip the same ears.
//!
//! Resuming the scan one vertex further on, past the last ear's neighbour
//! (as the `earcut` library does, so that ears and their boxes stay small)
//! was tried and dropped: it clipped other ears than the plain scan, which
//! changed the triangles that smoothing re-triangulates, and on the demo
//! model a second smoothing then found vertices on the new triangles'
//! edges (`crates/umbra/tests/it/model_clean.rs` asserts idempotence). The
//! plain order costs about a third more on a plate with 1,000 holes
//! (14 against 9 ms), still linear in practice.

use super::grid::{bounds, Grid};
use super::{in_box_and_triangle, orient, Search, P2};

/// Polygons of at least this many vertices have their ear tests indexed.
pub(super) const INDEXED: usize = 48;

/// The sine of the turn at an ear's tip below which the tip counts as
/// flat (about 1e-9): far above the rounding of a vertex computed on a
/// facet's side (the turns seen there are 1e-16 to 1e-14), far below a
/// corner anyone models.
const FLAT_SINE: f64 = 1.0 / (1u64 << 30) as f64;

/// Whether `p` lies on the chord `a c` to rounding: strictly between its
/// ends, with a turn at `p` (the sine of the angle between `a -> p` and
/// `p -> c`) of at most [`FLAT_SINE`]. An ear whose chord passes through
/// a vertex that way (its own tip, or a vertex of a straight side the
/// chord runs along) leaves a triangle of no area, now or when that
/// vertex is clipped, which folds against the facets meeting there;
/// section 4.8's ideal internal edge touches nothing but at its ends, so
/// such an ear is clipped only when no other valid ear is left.
fn on_chord(a: P2, c: P2, p: P2) -> bool {
    let (u, v) = ([p[0] - a[0], p[1] - a[1]], [c[0] - p[0], c[1] - p[1]]);
    let cross = u[0] * v[1] - u[1] * v[0];
    let dot = u[0] * v[0] + u[1] * v[1];
    let (lu, lv) = (u[0] * u[0] + u[1] * u[1], v[0] * v[0] + v[1] * v[1]);
    dot > 0.0 && cross * cross <= FLAT_SINE * FLAT_SINE * lu * lv
}

/// Whether `p` lies in the box of the triangle `a b c` (closed).
fn in_box(a: P2, b: P2, c: P2, p: P2) -> bool {
    p[0] >= a[0].min(b[0]).min(c[0])
        && p[0] <= a[0].max(b[0]).max(c[0])
        && p[1] >= a[1].min(b[1]).min(c[1])
        && p[1] <= a[1].max(b[1]).max(c[1])
}
/// Ear clipping of `poly`, appending triangles of positions in `poly`.
pub(super) fn ear_clip(poly: &[(u32, P2)], search: Search, out: &mut Vec<[usize; 3]>) {
    let n = poly.len();
    if n < 3 {
        return; // one or two half-edges balance by themselves
    }
    let pos = |i: usize| poly[i].1;
    let grid = match search {
        Search::Indexed
            if n >= INDEXED && poly.iter().all(|p| p.1.iter().all(|c| c.is_finite())) =>
        {
            bounds(poly.iter().map(|p| p.1)).map(|(lo, hi)| {
                let mut g = Grid::new(lo, hi, n);
                for (i, p) in poly.iter().enumerate() {
                    g.insert(p.1, p.1, i as u32);
                }
                g
            })
        }
        _ => None,
    };
    let mut next: Vec<usize> = (0..n).map(|i| (i + 1) % n).collect();
    let mut prev: Vec<usize> = (0..n).map(|i| (i + n - 1) % n).collect();
    let mut alive = vec![true; n];
    let mut remaining = n;
    let mut cur = 0;
    while remaining > 3 {
        if remaining == 4 {
            // Figure 4.10: of the two diagonals take the valid one; when
            // neither is, the one whose triangles cover less area (the
            // smaller overlap). When both are, their triangles cover the
            // quadrilateral alike (the totals differ by rounding only), so
            // the diagonal is taken whose smaller triangle is larger:
            // section 4.8's ideal internal edge touches no other edge but
            // at its ends, and at a corner that is straight to rounding
            // (a vertex the Boolean put on a facet's side) the other
            // diagonal would pass through that corner, leaving a triangle
            // of no area that folds against the neighbouring facets.
            let a = cur;
            let b = next[a];
            let c = next[b];
            let d = next[c];
            let (pa, pb, pc, pd) = (pos(a), pos(b), pos(c), pos(d));
            let (ac1, ac2) = (orient(pa, pb, pc), orient(pa, pc, pd));
            let (bd1, bd2) = (orient(pb, pc, pd), orient(pb, pd, pa));
            let ac_valid = ac1 > 0.0 && ac2 > 0.0;
            let bd_valid = bd1 > 0.0 && bd2 > 0.0;
            let use_ac = match (ac_valid, bd_valid) {
                (true, true) => ac1.min(ac2) >= bd1.min(bd2),
                (true, false) => true,
                (false, true) => false,
                (false, false) => ac1.abs() + ac2.abs() <= bd1.abs() + bd2.abs(),
            };
            let (p, q, r, s) = if use_ac { (a, b, c, d) } else { (b, c, d, a) };
            out.push([p, q, r]);
            out.push([p, r, s]);
            return;
        }
        // Pass 1: a valid ear, one whose chord passes through no vertex
        // first; pass 2: a degenerate one; pass 3: the smallest absolute
        // area.
        let mut chosen = None;
        let mut flat_ear = None;
        let mut degenerate = None;
        let mut smallest: Option<(f64, usize)> = None;
        let mut i = cur;
        for _ in 0..remaining {
            let (a, c) = (prev[i], next[i]);
            let (pa, pb, pc) = (pos(a), pos(i), pos(c));
            let area = orient(pa, pb, pc);
            if area > 0.0 {
                // Another remaining vertex, not at a corner, in the ear
                // blocks it. One met in the ear's box on its chord (to
                // rounding) does not, but the chord `c -> a` would pass
                // through it, as through a flat tip: such an ear is
                // clipped only when no other valid ear is left. Both
                // searches test the same vertices, those in the ear's box.
                let touched = std::cell::Cell::new(on_chord(pa, pc, pb));
                let blocks = |j: usize| {
                    let p = pos(j);
                    if p == pa || p == pb || p == pc {
                        return false;
                    }
                    if in_box_and_triangle(pa, pb, pc, p) {
                        return true;
                    }
                    if !touched.get() && in_box(pa, pb, pc, p) && on_chord(pa, pc, p) {
                        touched.set(true);
                    }
                    false
                };
                let blocked = match &grid {
                    Some(g) => {
                        let (lo, hi) = bounds([pa, pb, pc]).unwrap_or((pa, pa));
                        g.any_in(lo, hi, |j| {
                            let j = j as usize;
                            alive[j] && j != a && j != i && j != c && blocks(j)
                        })
                    }
                    None => {
                        let mut j = next[c];
                        let mut hit = false;
                        while j != a {
                            if blocks(j) {
                                hit = true;
                                break;
                            }
                            j = next[j];
                        }
                        hit
                    }
                };
                if !blocked {
                    if !touched.get() {
                        chosen = Some(i);
                        break;
                    }
                    flat_ear.get_or_insert(i);
                }
            } else if area == 0.0 && degenerate.is_none() {
                degenerate = Some(i);
            }
            if smallest.is_none_or(|(s, _)| area.abs() < s) {
                smallest = Some((area.abs(), i));
            }
            i = next[i];
        }
        let ear = chosen
            .or(flat_ear)
            .or(degenerate)
            .or(smallest.map(|s| s.1))
            .unwrap_or(cur);
        let (a, c) = (prev[ear], next[ear]);
        out.push([a, ear, c]);
        alive[ear] = false;
        next[a] = c;
        prev[c] = a;
        remaining -= 1;
        // The next scan starts at the ear's right neighbour (see the
        // module header for the resumed scan that was dropped).
        cur = c;
    }
    let a = cur;
    let b = next[a];
    let c = next[b];
    debug_assert!(alive[a] && alive[b] && alive[c]);
    out.push([a, b, c]);
}
