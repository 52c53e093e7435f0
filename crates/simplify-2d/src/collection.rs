//! The edge collection with multiplicity of section 7.1.2 (the `PolySet2`
//! class of Table 7.3): edges keyed by their lexicographically ordered end
//! points, identical edges merged, multiplicities added, zero cancelled.

use crate::point::Pt;
use std::collections::{BTreeMap, HashMap};
use topology::{Edge2, PolygonSet2};

/// A collection of directed edges with integer multiplicity, exactly as the
/// `PolySet2` class of Table 7.3 (section 7.1.2).
///
/// Each edge is stored once, keyed by its *leftmost* and *rightmost* point in
/// lexicographic order (for a vertical edge: lowest, then highest). An edge
/// going from rightmost to leftmost point is held with a negative
/// multiplicity. Adding an edge with the same two points merges it with the
/// stored one (multiplicities add, with the sign of the direction); an edge
/// whose multiplicity reaches zero is removed; a zero-length edge is ignored.
/// Iteration visits the edges in lexicographic order of (leftmost,
/// rightmost), the order a left-to-right sweep wants.
///
/// Multiplicities use wrapping `i32` arithmetic, so no input can make the
/// collection panic; the sums are exact unless the true total exceeds
/// `i32::MAX` in magnitude.
///
/// ```
/// use simplify_2d::EdgeCollection;
///
/// let mut c = EdgeCollection::new();
/// assert_eq!(c.add_edge([0.0, 0.0], [1.0, 0.0], 1), 1);
/// // The same segment the other way round cancels it (figure 6.7(b)).
/// assert_eq!(c.add_edge([1.0, 0.0], [0.0, 0.0], 1), 0);
/// assert!(c.is_empty());
/// // The same direction twice gives multiplicity 2 (figure 6.7(c)).
/// c.add_edge([0.0, 0.0], [0.0, 1.0], 1);
/// assert_eq!(c.add_edge([0.0, 0.0], [0.0, 1.0], 1), 2);
/// ```
#[derive(Clone, Debug, Default, PartialEq)]
pub struct EdgeCollection {
    edges: BTreeMap<(Pt, Pt), i32>,
}

impl EdgeCollection {
    /// An empty collection.
    pub fn new() -> Self {
        Self::default()
    }

    /// Adds the edge `start -> end` with multiplicity `mult` and returns the
    /// resulting multiplicity of that segment *in the direction
    /// `start -> end`* (Table 7.3, `addEdge`). A zero-length edge is not
    /// processed and returns 0.
    pub fn add_edge(&mut self, start: [f64; 2], end: [f64; 2], mult: i32) -> i32 {
        let s = Pt::new(start);
        let e = Pt::new(end);
        if s < e {
            self.add_ordered(s, e, mult)
        } else if s != e {
            self.add_ordered(e, s, mult.wrapping_neg()).wrapping_neg()
        } else {
            0
        }
    }

    fn add_ordered(&mut self, l: Pt, r: Pt, mult: i32) -> i32 {
        let slot = self.edges.entry((l, r)).or_insert(0);
        *slot = slot.wrapping_add(mult);
        let result = *slot;
        if result == 0 {
            self.edges.remove(&(l, r));
        }
        result
    }

    /// The number of stored (non-cancelled) segments.
    pub fn len(&self) -> usize {
        self.edges.len()
    }

    /// `true` when every edge has cancelled.
    pub fn is_empty(&self) -> bool {
        self.edges.is_empty()
    }

    /// The stored edges in lexicographic order as `(leftmost, rightmost,
    /// multiplicity)`; a negative multiplicity means the edge runs from the
    /// rightmost to the leftmost point.
    pub fn iter(&self) -> impl Iterator<Item = ([f64; 2], [f64; 2], i32)> + '_ {
        self.edges.iter().map(|(&(l, r), &m)| (l.arr(), r.arr(), m))
    }

    /// Merges the vertical edges of every x-coordinate by 1D simplification
    /// (section 7.6.1, footnote 9): the overlapping vertical edges at one x
    /// are replaced by the elementary intervals between their end points,
    /// each carrying the summed multiplicity, and intervals whose sum is zero
    /// are dropped. The break points are existing end points, so no new
    /// coordinate is introduced, and since the 1D multiplicity density is
    /// unchanged the shape boundary closure constraint still holds at every
    /// point.
    pub fn merge_vertical_edges(&mut self) {
        let mut vertical: Vec<(Pt, Pt, i32)> = self
            .edges
            .iter()
            .filter(|(&(l, r), _)| l.x == r.x)
            .map(|(&(l, r), &m)| (l, r, m))
            .collect();
        if vertical.len() < 2 {
            return;
        }
        vertical.sort_by(|a, b| a.0.x.total_cmp(&b.0.x));
        let mut i = 0;
        while i < vertical.len() {
            let x = vertical[i].0.x;
            let mut j = i;
            while j < vertical.len() && vertical[j].0.x == x {
                j += 1;
            }
            if j - i >= 2 {
                let mut marks: Vec<(f64, f64, i32)> = Vec::with_capacity(2 * (j - i));
                for &(l, r, m) in &vertical[i..j] {
                    self.edges.remove(&(l, r));
                    marks.push((l.y, l.y, m));
                    marks.push((r.y, r.y, m.wrapping_neg()));
                }
                elementary_intervals(&mut marks, |y, y_next, run| {
                    self.add_ordered(Pt::new([x, y]), Pt::new([x, y_next]), run);
                });
            }
            i = j;
        }
    }

    /// The collection as a [`PolygonSet2`]: one vertex per distinct end point
    /// (in lexicographic order) and one edge per stored segment, directed so
    /// that its multiplicity is positive.
    pub fn to_polygon_set(&self) -> PolygonSet2 {
        let mut ids: HashMap<Pt, u32> = HashMap::with_capacity(self.edges.len() * 2);
        let mut points: Vec<Pt> = Vec::with_capacity(self.edges.len() * 2);
        for &(l, r) in self.edges.keys() {
            points.push(l);
            points.push(r);
        }
        points.sort();
        points.dedup();
        let vertices: Vec<[f64; 2]> = points.iter().map(|p| p.arr()).collect();
        for (i, p) in points.iter().enumerate() {
            ids.insert(*p, i as u32);
        }
        let mut edges = Vec::with_capacity(self.edges.len());
        for (&(l, r), &m) in &self.edges {
            let (Some(&a), Some(&b)) = (ids.get(&l), ids.get(&r)) else {
                continue;
            };
            if m > 0 {
                edges.push(Edge2 {
                    start: a,
                    end: b,
                    mult: m,
                });
            } else if m != i32::MIN {
                edges.push(Edge2 {
                    start: b,
                    end: a,
                    mult: -m,
                });
            } else {
                edges.push(Edge2 {
                    start: a,
                    end: b,
                    mult: m,
                });
            }
        }
        PolygonSet2::from_parts(vertices, edges)
    }

    /// Builds a collection from every edge of a polygon set (vertices
    /// referred to by out-of-range indices are skipped; validate first).
    pub fn from_polygon_set(set: &PolygonSet2) -> Self {
        let mut c = EdgeCollection::new();
        let v = set.vertices();
        for e in set.edges() {
            if let (Some(&a), Some(&b)) = (v.get(e.start as usize), v.get(e.end as usize)) {
                c.add_edge(a, b, e.mult);
            }
        }
        c
    }
}

/// The 1D simplification of section 7.6.1 (footnote 9) for the vertical
/// edges at one x: each edge leaves a mark `(y, end, m)` at its lower end
/// and `(y, end, -m)` at its upper end, and every elementary interval
/// between consecutive break points with a non-zero running sum is passed
/// to `emit(from, to, sum)`, `from` and `to` being the ends at those break
/// points. Marks at equal y belong to one point and are summed, so their
/// order does not matter.
pub(crate) fn elementary_intervals<T: Copy>(
    marks: &mut [(f64, T, i32)],
    mut emit: impl FnMut(T, T, i32),
) {
    marks.sort_unstable_by(|a, b| a.0.total_cmp(&b.0));
    let mut run = 0i32;
    let mut k = 0;
    while k < marks.len() {
        let (y, at) = (marks[k].0, marks[k].1);
        while k < marks.len() && marks[k].0 == y {
            run = run.wrapping_add(marks[k].2);
            k += 1;
        }
        if let Some(next) = marks.get(k) {
            if run != 0 {
                emit(at, next.1, run);
            }
        }
    }
}
