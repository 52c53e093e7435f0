//! Exact orientation predicate for the validity hints of `check` and for
//! grouping holes into outer rings when writing files.
//!
//! A floating-point filter answers most calls; when it cannot certify the
//! sign the determinant is evaluated exactly in rational arithmetic. These
//! are not the dissertation's predicates (the Booleans never call them): they
//! only describe shapes, they never decide topology.

use num_rational::BigRational;
use num_traits::{Signed, Zero};
use robust_arith::{Point2, UNIT_ROUNDOFF};
use std::cmp::Ordering;

/// The relative error bound of the filter, `(3 + 16u) u` (the orientation
/// filter of Shewchuk's `orient2d`, differences taken in floating point).
const FILTER: f64 = (3.0 + 16.0 * UNIT_ROUNDOFF) * UNIT_ROUNDOFF;

/// Below this magnitude of `|l| + |r|` products may have underflowed and the
/// filter's relative bound no longer holds; the exact path decides.
const UNDERFLOW_GUARD: f64 = 1.0e-280;

/// The sign of the determinant `(a - c) x (b - c)`: `Greater` when `a, b, c`
/// turn counter-clockwise, `Less` when clockwise, `Equal` when collinear.
/// Exact for finite inputs; a non-finite input gives `Equal`.
pub(crate) fn orient2d(a: Point2, b: Point2, c: Point2) -> Ordering {
    let acx = a[0] - c[0];
    let bcx = b[0] - c[0];
    let acy = a[1] - c[1];
    let bcy = b[1] - c[1];
    let left = acx * bcy;
    let right = acy * bcx;
    let det = left - right;
    let sum = left.abs() + right.abs();
    if det.is_finite() && sum.is_finite() && sum > UNDERFLOW_GUARD && det.abs() > FILTER * sum {
        return det.partial_cmp(&0.0).unwrap_or(Ordering::Equal);
    }
    orient2d_exact(a, b, c)
}

/// The exact sign of the orientation determinant in rational arithmetic.
fn orient2d_exact(a: Point2, b: Point2, c: Point2) -> Ordering {
    let r = |v: f64| BigRational::from_float(v);
    let (Some(ax), Some(ay), Some(bx), Some(by), Some(cx), Some(cy)) =
        (r(a[0]), r(a[1]), r(b[0]), r(b[1]), r(c[0]), r(c[1]))
    else {
        return Ordering::Equal;
    };
    let det = (&ax - &cx) * (&by - &cy) - (&ay - &cy) * (&bx - &cx);
    if det.is_zero() {
        Ordering::Equal
    } else if det.is_positive() {
        Ordering::Greater
    } else {
        Ordering::Less
    }
}

/// Where a point lies with respect to a closed ring.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum RingSide {
    /// On an edge of the ring (exactly).
    Boundary,
    /// Off the ring, with the ring's winding number around the point.
    Off(i64),
}

/// The winding number of the closed ring `ring` (last point joins the first)
/// around `p`, or `Boundary` when `p` lies exactly on an edge. Sunday's
/// crossing rule with the exact [`orient2d`].
/// (The plain form is the oracle the tests hold [`RingIndex`] to.)
#[cfg(test)]
pub(crate) fn ring_side(ring: &[Point2], p: Point2) -> RingSide {
    ring_side_of_edges(ring, 0..ring.len() as u32, p)
}

/// [`ring_side`] summed over the edges `i -> i + 1` of `ring` listed in
/// `edges`; exact when `edges` holds every edge whose closed y-range
/// contains `p`'s y (the others contribute nothing).
fn ring_side_of_edges(ring: &[Point2], edges: impl Iterator<Item = u32>, p: Point2) -> RingSide {
    let n = ring.len();
    let mut wn = 0i64;
    for i in edges {
        let i = i as usize;
        let (Some(&a), Some(&b)) = (ring.get(i), ring.get((i + 1) % n)) else {
            continue;
        };
        let o = orient2d(a, b, p);
        if o == Ordering::Equal && within_box(a, b, p) {
            return RingSide::Boundary;
        }
        if a[1] <= p[1] {
            if b[1] > p[1] && o == Ordering::Greater {
                wn += 1;
            }
        } else if b[1] <= p[1] && o == Ordering::Less {
            wn -= 1;
        }
    }
    RingSide::Off(wn)
}

/// A point-location index over one ring: the ring's y-range cut into
/// horizontal strips, each listing the edges whose closed y-range meets it,
/// so a query visits only the edges near the point's y.
pub(crate) struct RingIndex {
    /// The lower end of the first strip.
    y0: f64,
    /// The strip height.
    height: f64,
    /// Edge ids per strip.
    strips: Vec<Vec<u32>>,
}

impl RingIndex {
    /// Builds the index; about `sqrt(n)` strips (at most 1024).
    pub(crate) fn new(ring: &[Point2]) -> RingIndex {
        let n = ring.len();
        let (lo, hi) = ring
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), p| {
                (lo.min(p[1]), hi.max(p[1]))
            });
        let count = ((n as f64).sqrt() as usize).clamp(1, 1024);
        let height = (hi - lo) / count as f64;
        let mut index = RingIndex {
            y0: lo,
            height,
            strips: vec![Vec::new(); count],
        };
        if !(height.is_finite() && height > 0.0) {
            // Flat or non-finite: one strip with every edge.
            index.strips = vec![(0..n as u32).collect()];
            index.height = f64::INFINITY;
            return index;
        }
        for i in 0..n {
            let a = ring[i][1];
            let b = ring[(i + 1) % n][1];
            let (s, t) = (index.strip(a.min(b)), index.strip(a.max(b)));
            for strip in &mut index.strips[s..=t] {
                strip.push(i as u32);
            }
        }
        index
    }

    /// The strip holding height `y` (clamped; neighbouring strips overlap
    /// at their shared boundary through the edges' closed ranges, and the
    /// clamp keeps rounding at a boundary conservative).
    fn strip(&self, y: f64) -> usize {
        let last = self.strips.len().saturating_sub(1);
        let k = ((y - self.y0) / self.height).floor();
        if k.is_nan() || k < 0.0 {
            0
        } else {
            (k as usize).min(last)
        }
    }

    /// [`ring_side`] of `p` with respect to `ring` (the ring indexed).
    pub(crate) fn side(&self, ring: &[Point2], p: Point2) -> RingSide {
        // An edge whose range ends exactly at a strip boundary may be filed
        // only in the neighbouring strip after rounding: visit the strips
        // either side of p too, skipping duplicates.
        let k = self.strip(p[1]);
        let lo = k.saturating_sub(1);
        let hi = (k + 1).min(self.strips.len().saturating_sub(1));
        let mut edges: Vec<u32> = self.strips[lo..=hi].iter().flatten().copied().collect();
        edges.sort_unstable();
        edges.dedup();
        ring_side_of_edges(ring, edges.into_iter(), p)
    }
}

/// `true` when `p` is inside the closed bounding box of segment `a b`.
fn within_box(a: Point2, b: Point2, p: Point2) -> bool {
    (0..2).all(|k| a[k].min(b[k]) <= p[k] && p[k] <= a[k].max(b[k]))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn orientation_is_exact_near_degeneracy() {
        // Points on the line y = x with tiny offsets the filter cannot see.
        let a = [0.5, 0.5];
        let b = [12.0, 12.0];
        let c = [24.0, 24.0];
        assert_eq!(orient2d(a, b, c), Ordering::Equal);
        let c_up = [24.0, f64::from_bits(24.0f64.to_bits() + 1)];
        assert_eq!(orient2d(a, b, c_up), Ordering::Greater);
        let c_down = [24.0, f64::from_bits(24.0f64.to_bits() - 1)];
        assert_eq!(orient2d(a, b, c_down), Ordering::Less);
        // Huge coordinates overflow the filter; the exact path answers.
        let h = f64::MAX / 4.0;
        assert_eq!(orient2d([-h, -h], [h, -h], [h, h]), Ordering::Greater);
    }

    #[test]
    fn ring_side_counts_winding() {
        let sq = [[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]];
        assert_eq!(ring_side(&sq, [1.0, 1.0]), RingSide::Off(1));
        assert_eq!(ring_side(&sq, [3.0, 1.0]), RingSide::Off(0));
        assert_eq!(ring_side(&sq, [2.0, 1.0]), RingSide::Boundary);
        assert_eq!(ring_side(&sq, [0.0, 0.0]), RingSide::Boundary);
        let rev: Vec<Point2> = sq.iter().rev().copied().collect();
        assert_eq!(ring_side(&rev, [1.0, 1.0]), RingSide::Off(-1));
    }

    #[test]
    fn ring_index_agrees_with_the_plain_test() {
        // A comb-like ring with 400 vertices and points on a grid that hits
        // vertices, edges and strip boundaries.
        let mut ring: Vec<Point2> = Vec::new();
        for i in 0..100 {
            let x = f64::from(i);
            ring.push([x, 0.0]);
            ring.push([x, 10.0 + f64::from(i % 7)]);
            ring.push([x + 0.5, 10.0 + f64::from(i % 7)]);
            ring.push([x + 0.5, 1.0]);
        }
        ring.push([100.0, 0.0]);
        ring.push([100.0, -3.0]);
        ring.push([0.0, -3.0]);
        let index = RingIndex::new(&ring);
        for i in -4..=408 {
            for j in -16..=80 {
                let p = [f64::from(i) / 4.0, f64::from(j) / 4.0];
                assert_eq!(index.side(&ring, p), ring_side(&ring, p), "{p:?}");
            }
        }
    }
}
