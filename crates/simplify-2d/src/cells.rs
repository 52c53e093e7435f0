//! The cell structure computed by the sweep (the boundary self-intersection
//! of section 7.7 with winding numbers, section 7.4.3), its validity check,
//! and the simplified shape for a rule.

use crate::collection::EdgeCollection;
use crate::winding::Winding;
use crate::SimplifyError;
use robust_arith::intersection_error_bound;
use topology::PolygonSet2;

/// One edge of the cell structure, directed from `start` to `end` (the
/// logical leftmost and rightmost points at which the sweep processed it).
///
/// Convention: crossing the edge from its right side to its left side adds
/// `mult` to the winding number, so **`left == right + mult`**. For every
/// edge except the rare downward vertical ones of section 7.6.1 `start`
/// precedes `end` lexicographically, and the left side is the one above.
#[derive(Clone, Debug, PartialEq)]
pub struct CellEdge<W> {
    /// Vertex index of the start point (the logical leftmost point).
    pub start: u32,
    /// Vertex index of the end point (the logical rightmost point).
    pub end: u32,
    /// Multiplicity in the direction `start -> end` (section 6.5).
    pub mult: W,
    /// Winding number of the cell on the left (above).
    pub left: W,
    /// Winding number of the cell on the right (below).
    pub right: W,
    /// Adjustment count (section 8.4): the edge lies within `k * alpha` of
    /// the input edge it originates from.
    pub k: u32,
    /// Index of an input edge it originates from (for Booleans, edges of
    /// the first operand come first, then those of the second, and so on).
    pub origin: u32,
}

/// The rotation of the edges around one processed event point, as recorded
/// by the sweep: the edges that ended there (bottom to top, arriving from
/// the left) and those that started there (bottom to top, leaving to the
/// right), with the winding numbers of the cells below and above the point.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Fan<W> {
    pub(crate) vertex: u32,
    pub(crate) below: W,
    pub(crate) above: W,
    pub(crate) start: u32,
    pub(crate) mid: u32,
    pub(crate) end: u32,
}

/// Counters of one sweep run.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct SweepStats {
    /// Edges handed to the sweep (before merging identical ones).
    pub input_edges: usize,
    /// Distinct input segments after merging (section 7.1.2).
    pub merged_input_edges: usize,
    /// Event points processed (a point may be processed more than once).
    pub events: u64,
    /// Computed edge-edge intersections (Table 7.2 calls).
    pub intersections: u64,
    /// Edges split at a vertex found on their interior (section 6.5).
    pub vertex_on_edge_splits: u64,
    /// Edges split because they pass through the event point (figure 7.8).
    pub through_splits: u64,
    /// Edges split because they were incorrectly grouped (section 7.6.2).
    pub misgrouped_splits: u64,
    /// Events where the literal linear scans of section 7.6.2 were needed.
    pub full_scans: u64,
    /// The largest number of edges on the sweep line at once.
    pub max_sweep_len: usize,
}

/// The cell structure of an edge collection: every edge of the computed
/// arrangement with the winding numbers on both sides, and the adjustment
/// bound of section 8.4.
///
/// `W` is `i32` for a single input, `[i32; 2]` for a Boolean of two, and
/// `Vec<i32>` for n operands tracked separately.
#[derive(Clone, Debug)]
pub struct CellStructure<W> {
    vertices: Vec<[f64; 2]>,
    edges: Vec<CellEdge<W>>,
    fans: Vec<Fan<W>>,
    fan_edges: Vec<u32>,
    k_max: u32,
    alpha: f64,
    dims: usize,
    stats: SweepStats,
}

impl<W: Winding> CellStructure<W> {
    #[allow(clippy::too_many_arguments)]
    pub(crate) fn new(
        vertices: Vec<[f64; 2]>,
        edges: Vec<CellEdge<W>>,
        fans: Vec<Fan<W>>,
        fan_edges: Vec<u32>,
        k_max: u32,
        max_abs: f64,
        dims: usize,
        stats: SweepStats,
    ) -> Self {
        CellStructure {
            vertices,
            edges,
            fans,
            fan_edges,
            k_max,
            alpha: intersection_error_bound(max_abs),
            dims,
            stats,
        }
    }

    /// The vertex positions (every processed event point).
    pub fn vertices(&self) -> &[[f64; 2]] {
        &self.vertices
    }

    /// The edges. Exactly coincident edges may appear more than once (they
    /// co-exist on the sweep line and bound a cell of zero area, section
    /// 7.4.2). A zero-length edge (`start == end`) appears only in the
    /// degenerate inexact case where an event point is processed a second
    /// time with an edge already starting there in its group; it is kept
    /// because it is part of the rotations checked by
    /// [`Self::check_cells`], and it never reaches a simplified shape.
    pub fn edges(&self) -> &[CellEdge<W>] {
        &self.edges
    }

    /// The largest adjustment count of any edge (section 8.4).
    pub fn k_max(&self) -> u32 {
        self.k_max
    }

    /// `alpha = sqrt(153) u L` (eq. 8.17), `L` the power of two bounding
    /// the input coordinates.
    pub fn alpha(&self) -> f64 {
        self.alpha
    }

    /// `eps = (k_max + 1) * alpha`: the sweep is epsilon-tolerant with this
    /// value (section 8.4).
    pub fn epsilon(&self) -> f64 {
        (f64::from(self.k_max) + 1.0) * self.alpha
    }

    /// The counters of the sweep run.
    pub fn stats(&self) -> SweepStats {
        self.stats
    }

    /// Checks that the cell structure is valid: winding numbers consistent
    /// across every edge and around every vertex.
    ///
    /// - every edge: `left == right + mult`, vertex indices in range;
    /// - every recorded event point: going around it, the edges that ended
    ///   there (bottom to top) chain the cell below the point to the cell
    ///   above it (`right` of the first is the cell below, `left` of each is
    ///   `right` of the next, `left` of the last is the cell above), and so
    ///   do the edges that start there; each such edge ends (starts) at that
    ///   vertex;
    /// - every edge ends at exactly one recorded event and starts at exactly
    ///   one (so the rotations cover the structure);
    /// - the first and last events see the unbounded cell (winding zero)
    ///   both below and above.
    ///
    /// Together these make the edges and rotations a cell structure on
    /// which every face has one winding number (section 6.3: the condition
    /// simplification needs beyond shape boundary closure).
    pub fn check_cells(&self) -> Result<(), SimplifyError> {
        let bad = |m: String| {
            Err(SimplifyError::Internal(format!(
                "invalid cell structure: {m}"
            )))
        };
        let nv = self.vertices.len() as u32;
        for (i, e) in self.edges.iter().enumerate() {
            if e.start >= nv || e.end >= nv {
                return bad(format!("edge {i} refers to a missing vertex"));
            }
            let mut l = e.right.clone();
            l.add_assign(&e.mult);
            if l != e.left {
                return bad(format!(
                    "edge {i}: left {:?} != right {:?} + mult {:?}",
                    e.left, e.right, e.mult
                ));
            }
        }
        let mut ended = vec![0u32; self.edges.len()];
        let mut started = vec![0u32; self.edges.len()];
        for (f_i, f) in self.fans.iter().enumerate() {
            let (s, m, t) = (f.start as usize, f.mid as usize, f.end as usize);
            let (Some(ending), Some(starting)) =
                (self.fan_edges.get(s..m), self.fan_edges.get(m..t))
            else {
                return bad(format!("fan {f_i} out of range"));
            };
            for (list, is_end) in [(ending, true), (starting, false)] {
                let mut w = f.below.clone();
                for &ei in list {
                    let Some(e) = self.edges.get(ei as usize) else {
                        return bad(format!("fan {f_i} refers to missing edge {ei}"));
                    };
                    let at = if is_end { e.end } else { e.start };
                    if at != f.vertex {
                        return bad(format!(
                            "edge {ei} listed at vertex {} but not incident",
                            f.vertex
                        ));
                    }
                    if e.right != w {
                        return bad(format!(
                            "around vertex {} (event {f_i}): edge {ei} has {:?} on its right, the cell there has {:?}",
                            f.vertex, e.right, w
                        ));
                    }
                    w = e.left.clone();
                    if is_end {
                        ended[ei as usize] += 1;
                    } else {
                        started[ei as usize] += 1;
                    }
                }
                if w != f.above {
                    return bad(format!(
                        "around vertex {} (event {f_i}): edges reach {:?}, the cell above has {:?}",
                        f.vertex, w, f.above
                    ));
                }
            }
        }
        for i in 0..self.edges.len() {
            if ended[i] != 1 || started[i] != 1 {
                return bad(format!(
                    "edge {i} ends at {} and starts at {} recorded events",
                    ended[i], started[i]
                ));
            }
        }
        let zero = W::zero(self.dims);
        for f in [self.fans.first(), self.fans.last()].into_iter().flatten() {
            if f.below != zero || f.above != zero {
                return bad("the outermost events do not see the unbounded cell".into());
            }
        }
        Ok(())
    }

    /// The simplified shape: every edge separating a retained cell from a
    /// discarded one, directed with the retained cell on its left (section
    /// 7.4.3, figure 6.2). Identical edges are merged (section 7.1.2) and
    /// the vertical edges of each x are merged by 1D simplification (section
    /// 7.6.1). The result always satisfies shape boundary closure.
    pub fn shape_with(&self, keep: impl Fn(&W) -> bool) -> PolygonSet2 {
        let mut c = EdgeCollection::new();
        for e in &self.edges {
            if e.start == e.end {
                continue;
            }
            let (Some(&a), Some(&b)) = (
                self.vertices.get(e.start as usize),
                self.vertices.get(e.end as usize),
            ) else {
                continue;
            };
            let l = keep(&e.left);
            let r = keep(&e.right);
            if l && !r {
                c.add_edge(a, b, 1);
            } else if r && !l {
                c.add_edge(b, a, 1);
            }
        }
        c.merge_vertical_edges();
        c.to_polygon_set()
    }

    /// The whole arrangement as a polygon set: every edge with its
    /// total multiplicity over the operands (identical edges merged, zero
    /// cancelled). Its winding numbers are the summed winding numbers of
    /// the input.
    pub fn arrangement(&self) -> EdgeCollection {
        let mut c = EdgeCollection::new();
        for e in &self.edges {
            if let (Some(&a), Some(&b)) = (
                self.vertices.get(e.start as usize),
                self.vertices.get(e.end as usize),
            ) {
                c.add_edge(a, b, e.mult.total());
            }
        }
        c
    }
}
