//! The working copy of a polygon set during smoothing: vertex positions
//! with their adjustment records, and the edges in a canonical form (one
//! entry per unordered vertex pair, a signed multiplicity), so that the
//! cancellation of opposing edges (Appendix A's half-edge cancellation,
//! in 2D) and the removal of zero-length edges are one normalisation.

use crate::SmoothCounts;
use rayon::prelude::*;
use robust_arith::{lex_cmp, Point2};
use topology::{Edge2, PolygonSet2};

/// What is known about a vertex of the working copy.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct VertexRecord {
    /// Adjustments that touched this vertex (merges into it, cracks at it,
    /// its creation), counted along the chain of adjustments that led here
    /// (the k of section 8.4).
    pub k: u32,
}

/// An edge between `a < b`: `m > 0` is `a -> b` counted `m` times,
/// `m < 0` is `b -> a` counted `-m` times.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub struct WEdge {
    /// The smaller vertex id.
    pub a: u32,
    /// The larger vertex id (equal to `a` only before normalisation).
    pub b: u32,
    /// The signed multiplicity.
    pub m: i64,
}

impl WEdge {
    /// The edge `start -> end` counted `mult` times, canonical.
    pub fn directed(start: u32, end: u32, mult: i64) -> WEdge {
        if start <= end {
            WEdge {
                a: start,
                b: end,
                m: mult,
            }
        } else {
            WEdge {
                a: end,
                b: start,
                m: -mult,
            }
        }
    }
}

/// The working copy.
#[derive(Clone, Debug, Default)]
pub struct Work {
    /// Vertex positions.
    pub pts: Vec<Point2>,
    /// One record per vertex.
    pub rec: Vec<VertexRecord>,
    /// The edges, canonical after [`Work::normalize`].
    pub edges: Vec<WEdge>,
    /// For every input vertex, the vertex of the working copy it became
    /// (`None` once it has been removed with the edges that used it).
    pub tracked: Vec<Option<u32>>,
}

impl Work {
    /// A copy of a validated set (edges of multiplicity zero are dropped;
    /// every vertex starts with `k = 0`).
    pub fn from_set(set: &PolygonSet2) -> Work {
        let pts = set.vertices().to_vec();
        let n = pts.len();
        let edges = set
            .edges()
            .iter()
            .filter(|e| e.mult != 0)
            .map(|e| WEdge::directed(e.start, e.end, i64::from(e.mult)))
            .collect();
        Work {
            pts,
            rec: vec![VertexRecord { k: 0 }; n],
            edges,
            tracked: (0..n as u32).map(Some).collect(),
        }
    }

    /// Renames every vertex `v` to `map[v]`, then normalises.
    pub fn remap(&mut self, map: &[u32], counts: &mut SmoothCounts) {
        for e in &mut self.edges {
            *e = WEdge::directed(map[e.a as usize], map[e.b as usize], e.m);
        }
        for t in self.tracked.iter_mut().flatten() {
            *t = map[*t as usize];
        }
        self.normalize(counts);
    }

    /// Removes zero-length edges (same start and end vertex), then merges
    /// the entries of each vertex pair, cancelling opposing multiplicities
    /// (`a -> b` against `b -> a`), and drops what cancels to zero. Sorted,
    /// so the result is deterministic.
    pub fn normalize(&mut self, counts: &mut SmoothCounts) {
        let before = self.edges.len();
        self.edges.retain(|e| e.a != e.b);
        counts.zero_length_edges_removed += (before - self.edges.len()) as u64;
        self.edges.sort_unstable_by_key(|e| (e.a, e.b));
        let mut out: Vec<WEdge> = Vec::with_capacity(self.edges.len());
        let mut i = 0;
        while i < self.edges.len() {
            let (a, b) = (self.edges[i].a, self.edges[i].b);
            let (mut pos, mut neg) = (0i64, 0i64);
            while i < self.edges.len() && self.edges[i].a == a && self.edges[i].b == b {
                let m = self.edges[i].m;
                if m > 0 {
                    pos = pos.saturating_add(m);
                } else {
                    neg = neg.saturating_add(-m);
                }
                i += 1;
            }
            counts.half_edges_cancelled += pos.min(neg) as u64;
            if pos != neg {
                out.push(WEdge { a, b, m: pos - neg });
            }
        }
        self.edges = out;
    }

    /// Removes the vertices no edge refers to and renumbers the rest in
    /// their order.
    pub fn remove_unreferenced(&mut self, counts: &mut SmoothCounts) {
        let n = self.pts.len();
        let mut used = vec![false; n];
        for e in &self.edges {
            used[e.a as usize] = true;
            used[e.b as usize] = true;
        }
        let mut map = vec![u32::MAX; n];
        let mut next = 0u32;
        for v in 0..n {
            if used[v] {
                map[v] = next;
                self.pts[next as usize] = self.pts[v];
                self.rec[next as usize] = self.rec[v];
                next += 1;
            }
        }
        counts.unreferenced_vertices_removed += (n - next as usize) as u64;
        self.pts.truncate(next as usize);
        self.rec.truncate(next as usize);
        for e in &mut self.edges {
            e.a = map[e.a as usize];
            e.b = map[e.b as usize];
        }
        for t in &mut self.tracked {
            *t = t.and_then(|v| (map[v as usize] != u32::MAX).then_some(map[v as usize]));
        }
    }

    /// The largest `|m|` of an edge (0 when there are none).
    pub fn max_multiplicity(&self) -> i64 {
        self.edges.iter().map(|e| e.m.abs()).max().unwrap_or(0)
    }

    /// The largest adjustment count of a vertex.
    pub fn k_max(&self) -> u32 {
        self.rec.iter().map(|r| r.k).max().unwrap_or(0)
    }

    /// The working copy as a polygon set, vertices in their current order.
    pub fn to_set(&self) -> PolygonSet2 {
        PolygonSet2::from_parts(self.pts.clone(), self.directed_edges(|v| v))
    }

    /// The canonical output: vertices sorted lexicographically by
    /// position, edges directed by multiplicity sign, sorted by (start,
    /// end). Smoothing a canonical clean set returns it bit for bit.
    pub fn into_canonical(mut self, counts: &mut SmoothCounts) -> (PolygonSet2, Vec<Option<u32>>) {
        self.remove_unreferenced(counts);
        // Parallel sorts: the one step of smoothing near contacts whose
        // cost is the whole result's size besides the check's sweep. The
        // index breaks ties, so the order is that of any sort.
        let mut order: Vec<u32> = (0..self.pts.len() as u32).collect();
        order.par_sort_unstable_by(|&x, &y| {
            lex_cmp(&self.pts[x as usize], &self.pts[y as usize]).then(x.cmp(&y))
        });
        let mut rank = vec![0u32; self.pts.len()];
        for (r, &v) in order.iter().enumerate() {
            rank[v as usize] = r as u32;
        }
        let pts: Vec<Point2> = order.iter().map(|&v| self.pts[v as usize]).collect();
        let mut edges = self.directed_edges(|v| rank[v as usize]);
        edges.par_sort_unstable_by_key(|e| (e.start, e.end, e.mult));
        let tracked = self
            .tracked
            .iter()
            .map(|t| t.map(|v| rank[v as usize]))
            .collect();
        (PolygonSet2::from_parts(pts, edges), tracked)
    }

    /// The edges as directed `Edge2` entries with positive multiplicity
    /// (split into several entries where it exceeds `i32::MAX`), vertex
    /// ids renamed by `rename`.
    fn directed_edges(&self, rename: impl Fn(u32) -> u32) -> Vec<Edge2> {
        let mut out = Vec::with_capacity(self.edges.len());
        for e in &self.edges {
            let (start, end) = if e.m > 0 { (e.a, e.b) } else { (e.b, e.a) };
            let (start, end) = (rename(start), rename(end));
            let mut left = e.m.unsigned_abs();
            while left > 0 {
                let take = left.min(i32::MAX as u64);
                out.push(Edge2 {
                    start,
                    end,
                    mult: take as i32,
                });
                left -= take;
            }
        }
        out
    }
}
