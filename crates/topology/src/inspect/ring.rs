//! Point location in a closed ring, exact: the winding number of a ring
//! around a point or whether the point lies on the ring (used to group
//! holes into outer rings when polygon files are written), and the ring's
//! signed area.

use robust_arith::{orient2d, Point2};
use std::cmp::Ordering;

/// The signed area of a closed ring (last point joins the first; positive
/// when counter-clockwise), by the shoelace sum relative to the first point
/// (f64). Finite for every ring of valid coordinates whose area is at most
/// `f64::MAX` (beyond, an infinity of the area's sign), also where the
/// products of the plain sum overflow.
///
/// ```
/// use topology::ring_signed_area;
/// assert_eq!(ring_signed_area(&[[0.0, 0.0], [2.0, 0.0], [2.0, 1.0], [0.0, 1.0]]), 2.0);
/// let s = 1e155;
/// assert_eq!(ring_signed_area(&[[0.0, 0.0], [s, 0.0], [s, s], [0.0, s]]), f64::INFINITY);
/// assert_eq!(ring_signed_area(&[[0.0, 0.0], [s, 0.0], [s, 1.0], [0.0, 1.0]]), s);
/// ```
pub fn ring_signed_area(ring: &[Point2]) -> f64 {
    let Some(&o) = ring.first() else {
        return 0.0;
    };
    let area = ring_twice_area(ring, o, [1.0; 2]) / 2.0;
    if area.is_finite() {
        return area;
    }
    let rel = ring.iter().map(|p| [p[0] - o[0], p[1] - o[1]]);
    match crate::unit_scale::axis_scales(rel) {
        Some((down, up)) => {
            crate::unit_scale::scaled_back(ring_twice_area(ring, o, down) / 2.0, &up)
        }
        None => area,
    }
}

/// Twice the signed area of `ring` by the shoelace sum over its points
/// relative to `o`, the differences of axis `k` multiplied by `scale[k]`
/// (1, or powers of two that keep the products finite: `unit_scale.rs`).
fn ring_twice_area(ring: &[Point2], o: Point2, scale: [f64; 2]) -> f64 {
    let n = ring.len();
    let mut twice = 0.0;
    for i in 1..n.saturating_sub(1) {
        let a = [
            (ring[i][0] - o[0]) * scale[0],
            (ring[i][1] - o[1]) * scale[1],
        ];
        let b = [
            (ring[i + 1][0] - o[0]) * scale[0],
            (ring[i + 1][1] - o[1]) * scale[1],
        ];
        twice += a[0] * b[1] - a[1] * b[0];
    }
    twice
}

/// Where a point lies with respect to a closed ring.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RingSide {
    /// On an edge of the ring (exactly).
    Boundary,
    /// Off the ring, with the ring's winding number around the point.
    Off(i64),
}

/// The winding number of the closed ring `ring` (last point joins the first)
/// around `p`, or `Boundary` when `p` lies exactly on an edge. Sunday's
/// crossing rule with the exact [`orient2d`].
/// `O(n)` per query; [`RingIndex`] answers the same faster for many
/// queries on one ring.
///
/// ```
/// use topology::{ring_side, RingSide};
/// let sq = [[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]];
/// assert_eq!(ring_side(&sq, [1.0, 1.0]), RingSide::Off(1));
/// assert_eq!(ring_side(&sq, [2.0, 1.0]), RingSide::Boundary);
/// ```
pub fn ring_side(ring: &[Point2], p: Point2) -> RingSide {
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
#[derive(Clone, Debug)]
pub struct RingIndex {
    /// The lower end of the first strip.
    y0: f64,
    /// The strip height.
    height: f64,
    /// Edge ids per strip.
    strips: Vec<Vec<u32>>,
}

impl RingIndex {
    /// Builds the index; about `sqrt(n)` strips (at most 1024).
    pub fn new(ring: &[Point2]) -> RingIndex {
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

    /// [`ring_side`] of `p` with respect to `ring` (the ring this index
    /// was built from; another ring gives a meaningless answer, never a
    /// panic).
    pub fn side(&self, ring: &[Point2], p: Point2) -> RingSide {
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
