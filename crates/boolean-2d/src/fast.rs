//! The fast evaluation of level 2 (Table 4.1): a sort-and-sweep broad phase
//! before any `X11`, `X11` in parallel on the surviving pairs, and the
//! winding numbers `X02`/`X20` by one ray cast per connected component,
//! propagated along edges by the closure identity of Theorem 2.
//!
//! The result is the same [`LevelData`] as the brute force of
//! `reference.rs`, integer for integer and point for point: a pair is skipped
//! only when its `X` is provably 0, and the propagation identity holds
//! exactly for integers.

use crate::reference::LevelData;
use crate::BooleanError;
use rayon::prelude::*;
use shadow_1d::{s01, s10};
use shadow_2d::x11;
use std::time::Instant;
use topology::{Edge2, PolygonSet2};

/// Pair counts above which `X11` runs on the rayon pool; below it the
/// thread hand-off costs more than the work. The output is the same either
/// way (hits are sorted by edge indices afterwards).
const PARALLEL_PAIRS: usize = 2048;

/// Edge counts above which the two operands' ray casts run side by side.
const PARALLEL_EDGES: usize = 16384;

/// One `X11` hit as [`LevelData::x11`] stores it: edge of A, edge of B,
/// value, intersection point.
type Hit11 = (u32, u32, i32, [f64; 2]);

/// Durations of the level-2 phases, in milliseconds.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct Level2Times {
    pub broad_phase: f64,
    pub intersections: f64,
    pub winding: f64,
}

/// The closed box of one edge with non-zero multiplicity, its y range
/// widened by the broad-phase margin.
#[derive(Clone, Copy, Debug)]
struct EdgeBox {
    x0: f64,
    x1: f64,
    y0: f64,
    y1: f64,
    index: u32,
}

/// Boxes of every edge with non-zero multiplicity, sorted by `x0`.
///
/// The y range is widened by `margin` on both sides. x is never widened:
/// `X01` and `X10` compare x coordinates exactly (`S00`, eq. 4.1), so an
/// edge whose closed x range misses a vertex's x has `X01 = X10 = 0` there.
fn edge_boxes(set: &PolygonSet2, margin: f64) -> Vec<EdgeBox> {
    let mut boxes: Vec<EdgeBox> = set
        .edges()
        .iter()
        .enumerate()
        .filter(|(_, e)| e.mult != 0)
        .map(|(i, e)| {
            let (p, q) = set.edge_points(e);
            EdgeBox {
                x0: p[0].min(q[0]),
                x1: p[0].max(q[0]),
                y0: p[1].min(q[1]) - margin,
                y1: p[1].max(q[1]) + margin,
                index: i as u32,
            }
        })
        .collect();
    boxes.sort_unstable_by(|a, b| a.x0.total_cmp(&b.x0).then(a.index.cmp(&b.index)));
    boxes
}

/// Every `(edge of A, edge of B)` pair whose boxes overlap (closed ranges).
///
/// Sort-and-sweep on x: boxes enter in order of `x0`; a box entering tests
/// the other operand's active boxes (those with `x1 >= x0`, ties kept: the
/// symbolic perturbation of eq. 4.1 decides touching ranges), dropping the
/// ones that ended to its left. Each overlapping pair is found exactly once,
/// by whichever of its two boxes enters second.
///
/// Why a pair outside this set has `X11 = 0`: if the closed x ranges are
/// disjoint, every `X01`/`X10` of the pair is 0 (Table 4.1), hence every
/// level-1 shadow. If one edge lies wholly below the other with the `8 u L`
/// margin to spare, every computed y of the lower edge (within `4 u L` of
/// the true segment, section 8.2) is below every computed y of the upper
/// one, so each `S01`/`S10` equals its `X` or is 0 for the whole pair, and
/// the X terms of `X11` cancel by the closure of the two edges' end points
/// (the argument of Theorem 1, case 2).
fn overlapping_pairs(a: &[EdgeBox], b: &[EdgeBox]) -> Vec<(u32, u32)> {
    let mut pairs = Vec::new();
    let mut active_a: Vec<EdgeBox> = Vec::new();
    let mut active_b: Vec<EdgeBox> = Vec::new();
    let (mut i, mut j) = (0, 0);
    while i < a.len() || j < b.len() {
        let take_a = j == b.len() || (i < a.len() && a[i].x0 <= b[j].x0);
        let (entering, others, own) = if take_a {
            i += 1;
            (a[i - 1], &mut active_b, &mut active_a)
        } else {
            j += 1;
            (b[j - 1], &mut active_a, &mut active_b)
        };
        let mut k = 0;
        while k < others.len() {
            let o = others[k];
            if o.x1 < entering.x0 {
                others.swap_remove(k);
                continue;
            }
            if o.y0 <= entering.y1 && entering.y0 <= o.y1 {
                pairs.push(if take_a {
                    (entering.index, o.index)
                } else {
                    (o.index, entering.index)
                });
            }
            k += 1;
        }
        own.push(entering);
    }
    pairs
}

/// `X11` on every candidate pair; the non-zero ones sorted by edge of A,
/// then edge of B (the order [`LevelData::x11`] documents).
fn intersections(
    a: &PolygonSet2,
    b: &PolygonSet2,
    pairs: &[(u32, u32)],
) -> Result<Vec<Hit11>, BooleanError> {
    let eval = |&(ia, ib): &(u32, u32)| {
        let (as_, ae) = a.edge_points(&a.edges()[ia as usize]);
        let (bs, be) = b.edge_points(&b.edges()[ib as usize]);
        x11(&as_, &ae, &bs, &be)
            .map(|hit| hit.map(|h| (ia, ib, h.value, h.a)))
            .map_err(|e| BooleanError::Internal(format!("edges {ia}, {ib}: {e}")))
    };
    let found: Vec<Option<Hit11>> = if pairs.len() >= PARALLEL_PAIRS {
        pairs.par_iter().map(eval).collect::<Result<_, _>>()?
    } else {
        pairs.iter().map(eval).collect::<Result<_, _>>()?
    };
    let mut hits: Vec<_> = found.into_iter().flatten().collect();
    hits.sort_unstable_by_key(|h| (h.0, h.1));
    Ok(hits)
}

/// How a vertex's winding number is obtained: cast, or from a neighbour
/// across an edge.
#[derive(Clone, Copy)]
enum Source {
    /// The first vertex of a connected component: one ray cast.
    Cast,
    /// `value(v) = value(from) + delta`, with `delta` read from edge
    /// `edge`, traversed forwards (`from` is its start) or backwards.
    Across { from: u32, edge: u32, forward: bool },
}

/// A breadth-first order of every vertex of `set` over its edges of
/// non-zero multiplicity, each with its [`Source`].
fn propagation_order(set: &PolygonSet2) -> Vec<(u32, Source)> {
    let n = set.vertex_count();
    // Adjacency in compressed rows: (neighbour, edge, forward).
    let mut degree = vec![0u32; n + 1];
    for e in set.edges().iter().filter(|e| e.mult != 0) {
        degree[e.start as usize] += 1;
        degree[e.end as usize] += 1;
    }
    let mut offset = vec![0u32; n + 1];
    for v in 0..n {
        offset[v + 1] = offset[v] + degree[v];
    }
    let mut fill = offset.clone();
    let mut adj = vec![(0u32, 0u32, false); offset[n] as usize];
    for (i, e) in set.edges().iter().enumerate() {
        if e.mult == 0 {
            continue;
        }
        let (s, t) = (e.start as usize, e.end as usize);
        adj[fill[s] as usize] = (e.end, i as u32, true);
        fill[s] += 1;
        adj[fill[t] as usize] = (e.start, i as u32, false);
        fill[t] += 1;
    }
    let mut seen = vec![false; n];
    let mut order = Vec::with_capacity(n);
    for root in 0..n {
        if seen[root] {
            continue;
        }
        seen[root] = true;
        let head = order.len();
        order.push((root as u32, Source::Cast));
        let mut k = head;
        while k < order.len() {
            let v = order[k].0 as usize;
            for &(w, edge, forward) in &adj[offset[v] as usize..offset[v + 1] as usize] {
                if !seen[w as usize] {
                    seen[w as usize] = true;
                    order.push((
                        w,
                        Source::Across {
                            from: v as u32,
                            edge,
                            forward,
                        },
                    ));
                }
            }
            k += 1;
        }
    }
    order
}

/// Casts one ray per query point through the other operand's edges: for a
/// query `v`, the sum of `term(v, edge)` over every edge of non-zero
/// multiplicity whose closed x range holds `v.x` (all other edges have
/// `X01 = X10 = 0` at `v`, so contribute nothing). A sweep over the
/// queries in x order keeps the edges spanning the current x active.
fn cast_rays(
    queries: &[u32],
    own: &PolygonSet2,
    boxes: &[EdgeBox],
    other: &PolygonSet2,
    term: impl Fn(&[f64; 2], &Edge2, ([f64; 2], [f64; 2])) -> i32,
) -> Vec<i32> {
    let mut by_x: Vec<usize> = (0..queries.len()).collect();
    by_x.sort_unstable_by(|&p, &q| {
        own.vertex(queries[p])[0]
            .total_cmp(&own.vertex(queries[q])[0])
            .then(p.cmp(&q))
    });
    let mut result = vec![0i32; queries.len()];
    let mut active: Vec<EdgeBox> = Vec::new();
    let mut next = 0;
    for q in by_x {
        let v = own.vertex(queries[q]);
        while next < boxes.len() && boxes[next].x0 <= v[0] {
            active.push(boxes[next]);
            next += 1;
        }
        active.retain(|b| b.x1 >= v[0]);
        let mut sum = 0i32;
        for b in &active {
            let e = &other.edges()[b.index as usize];
            sum += term(&v, e, other.edge_points(e));
        }
        result[q] = sum;
    }
    result
}

/// Sum of `weight(other edge) * X11` over the hits of each edge of one
/// operand: `per_edge[e]` for the A side (`by_a`) or the B side.
fn crossing_sums(hits: &[Hit11], edge_count: usize, by_a: bool, weights: &[Edge2]) -> Vec<i32> {
    let mut sums = vec![0i32; edge_count];
    for &(ia, ib, x, _) in hits {
        let (own, other) = if by_a { (ia, ib) } else { (ib, ia) };
        sums[own as usize] += weights[other as usize].mult * x;
    }
    sums
}

/// Fills winding numbers in propagation order: casts first, then
/// `value(to) = value(from) + sign * delta[edge]` where the sign is `+1`
/// for a forward traversal.
fn propagate(order: &[(u32, Source)], cast: &[i32], delta: &[i32], n: usize) -> Vec<i32> {
    let mut value = vec![0i32; n];
    let mut k = 0;
    for &(v, source) in order {
        value[v as usize] = match source {
            Source::Cast => {
                k += 1;
                cast[k - 1]
            }
            Source::Across {
                from,
                edge,
                forward,
            } => {
                let d = delta[edge as usize];
                value[from as usize] + if forward { d } else { -d }
            }
        };
    }
    value
}

/// Level 2 by the fast path.
///
/// Winding numbers: along an edge `e_A` of non-zero multiplicity, Theorem 2
/// for its composite edge (starts equal ends, eq. 4.14-4.16 with the counts
/// of eq. 4.7-4.8) is the identity
/// `X02(v_e, B) = X02(v_s, B) - sum_{e_B} m_B X11(e_A, e_B)`, and for an
/// edge `e_B` of B (eq. 4.9-4.10)
/// `X20(A, v_e) = X20(A, v_s) + sum_{e_A} m_A X11(e_A, e_B)`. One vertex
/// per connected component gets a ray cast (`X02 = -sum m S01`,
/// `X20 = sum m S10`, Table 4.1); the rest follow exactly.
pub(crate) fn level2_fast(
    a: &PolygonSet2,
    b: &PolygonSet2,
) -> Result<(LevelData, Level2Times), BooleanError> {
    let mut times = Level2Times::default();
    let clock = Instant::now();
    let max_abs = a.max_abs_coordinate().max(b.max_abs_coordinate());
    // Twice the y_at_x bound of section 8.2 on each side (defence in depth:
    // a wider margin only adds candidate pairs).
    let margin = 2.0 * robust_arith::y_at_x_error_bound(max_abs);
    let boxes_a = edge_boxes(a, margin);
    let boxes_b = edge_boxes(b, margin);
    let pairs = overlapping_pairs(&boxes_a, &boxes_b);
    times.broad_phase = ms(clock);

    let clock = Instant::now();
    let hits = intersections(a, b, &pairs)?;
    drop(pairs);
    times.intersections = ms(clock);

    let clock = Instant::now();
    let order_a = propagation_order(a);
    let order_b = propagation_order(b);
    let casts = |order: &[(u32, Source)]| -> Vec<u32> {
        order
            .iter()
            .filter(|(_, s)| matches!(s, Source::Cast))
            .map(|&(v, _)| v)
            .collect()
    };
    let (cast_a, cast_b) = (casts(&order_a), casts(&order_b));
    let cast_x02 = || {
        cast_rays(&cast_a, a, &boxes_b, b, |v, e, (s, t)| {
            -(e.mult * s01(v, &s, &t))
        })
    };
    let cast_x20 = || {
        cast_rays(&cast_b, b, &boxes_a, a, |v, e, (s, t)| {
            e.mult * s10(&s, &t, v)
        })
    };
    let (x02_cast, x20_cast) = if a.edge_count() + b.edge_count() >= PARALLEL_EDGES {
        rayon::join(cast_x02, cast_x20)
    } else {
        (cast_x02(), cast_x20())
    };
    let delta_a: Vec<i32> = crossing_sums(&hits, a.edge_count(), true, b.edges())
        .into_iter()
        .map(|d| -d)
        .collect();
    let delta_b = crossing_sums(&hits, b.edge_count(), false, a.edges());
    let x02 = propagate(&order_a, &x02_cast, &delta_a, a.vertex_count());
    let x20 = propagate(&order_b, &x20_cast, &delta_b, b.vertex_count());
    times.winding = ms(clock);

    Ok((
        LevelData {
            x02,
            x20,
            x11: hits,
            composite_counts: Vec::new(),
        },
        times,
    ))
}

/// Milliseconds since `start`.
pub(crate) fn ms(start: Instant) -> f64 {
    start.elapsed().as_secs_f64() * 1e3
}

#[cfg(test)]
mod tests {
    use super::*;

    fn boxes(v: &[(f64, f64, f64, f64)]) -> Vec<EdgeBox> {
        let mut b: Vec<EdgeBox> = v
            .iter()
            .enumerate()
            .map(|(i, &(x0, x1, y0, y1))| EdgeBox {
                x0,
                x1,
                y0,
                y1,
                index: i as u32,
            })
            .collect();
        b.sort_unstable_by(|p, q| p.x0.total_cmp(&q.x0));
        b
    }

    #[test]
    fn sweep_finds_exactly_the_overlapping_pairs() {
        let a = boxes(&[
            (0.0, 1.0, 0.0, 1.0),
            (1.0, 2.0, 0.0, 1.0),
            (5.0, 6.0, 0.0, 1.0),
            (0.0, 10.0, 3.0, 4.0),
        ]);
        let b = boxes(&[
            (1.0, 1.0, 0.5, 0.5), // touches A0 and A1 at x = 1
            (2.0, 5.0, 1.0, 3.0), // touches A1, A2 and A3 at corners
            (7.0, 8.0, 5.0, 6.0), // above everything
        ]);
        let mut got = overlapping_pairs(&a, &b);
        got.sort_unstable();
        let mut want = Vec::new();
        for p in &a {
            for q in &b {
                if p.x0 <= q.x1 && q.x0 <= p.x1 && p.y0 <= q.y1 && q.y0 <= p.y1 {
                    want.push((p.index, q.index));
                }
            }
        }
        want.sort_unstable();
        assert_eq!(got, want);
        assert_eq!(got, vec![(0, 0), (1, 0), (1, 1), (2, 1), (3, 1)]);
    }
}
