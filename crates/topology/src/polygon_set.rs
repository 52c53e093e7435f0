//! `PolygonSet2`: a 2D polygonal set as a collection of directed edges with
//! multiplicity (section 4.2, "Polygonal shape").

use crate::{validate_points, TopologyError};
use robust_arith::Point2;

/// A directed edge of a [`PolygonSet2`]: from vertex `start` to vertex `end`,
/// counted `mult` times. A negative multiplicity is the same as the reversed
/// edge counted `-mult` times; zero contributes nothing.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Edge2 {
    /// The start-vertex index.
    pub start: u32,
    /// The end-vertex index.
    pub end: u32,
    /// The multiplicity.
    pub mult: i32,
}

/// A polygonal set in the plane: vertices and directed edges, the interior
/// lying to the left of each edge (section 4.2).
///
/// The topological constraint (shape boundary closure) is that at every
/// vertex the multiplicity-weighted number of edges ending there equals the
/// number starting there. Coincident vertices and zero-length edges are
/// allowed. Geometric validity (no crossings, interior on the left) is not
/// required: the Booleans accept geometrically invalid sets (section 4.7).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct PolygonSet2 {
    vertices: Vec<Point2>,
    edges: Vec<Edge2>,
}

impl PolygonSet2 {
    /// An empty set (the empty region).
    pub fn new() -> Self {
        Self::default()
    }

    /// An empty set with room for `vertices` vertices and `edges` edges.
    pub fn with_capacity(vertices: usize, edges: usize) -> Self {
        PolygonSet2 {
            vertices: Vec::with_capacity(vertices),
            edges: Vec::with_capacity(edges),
        }
    }

    /// A set from raw parts, unchecked: call [`Self::check_topology`] and
    /// [`Self::validate_coordinates`] before handing user data to an
    /// algorithm.
    pub fn from_parts(vertices: Vec<Point2>, edges: Vec<Edge2>) -> Self {
        PolygonSet2 { vertices, edges }
    }

    /// Splits the set into its vertices and edges.
    pub fn into_parts(self) -> (Vec<Point2>, Vec<Edge2>) {
        (self.vertices, self.edges)
    }

    /// The vertex positions.
    pub fn vertices(&self) -> &[Point2] {
        &self.vertices
    }

    /// The directed edges.
    pub fn edges(&self) -> &[Edge2] {
        &self.edges
    }

    /// The position of vertex `v`.
    ///
    /// # Panics
    /// If `v` is out of range; validated sets never hold such an index.
    pub fn vertex(&self, v: u32) -> Point2 {
        self.vertices[v as usize]
    }

    /// The start and end positions of edge `e`.
    pub fn edge_points(&self, e: &Edge2) -> (Point2, Point2) {
        (self.vertex(e.start), self.vertex(e.end))
    }

    /// Adds a vertex and returns its index.
    pub fn add_vertex(&mut self, p: Point2) -> u32 {
        self.vertices.push(p);
        (self.vertices.len() - 1) as u32
    }

    /// Adds the edge `start -> end` with multiplicity one.
    pub fn add_edge(&mut self, start: u32, end: u32) {
        self.add_edge_mult(start, end, 1);
    }

    /// Adds the edge `start -> end` with multiplicity `mult`.
    pub fn add_edge_mult(&mut self, start: u32, end: u32, mult: i32) {
        self.edges.push(Edge2 { start, end, mult });
    }

    /// Adds a closed loop through the given points, in order (the last point
    /// joins back to the first). A loop of fewer than one point adds nothing.
    /// Returns the index of the loop's first vertex.
    pub fn add_loop(&mut self, points: &[Point2]) -> u32 {
        let first = self.vertices.len() as u32;
        let n = points.len() as u32;
        for &p in points {
            self.add_vertex(p);
        }
        for i in 0..n {
            self.add_edge(first + i, first + (i + 1) % n);
        }
        first
    }

    /// Appends every vertex and edge of `other` (a disjoint union of the edge
    /// collections: winding numbers add).
    pub fn append(&mut self, other: &PolygonSet2) {
        let off = self.vertices.len() as u32;
        self.vertices.extend_from_slice(&other.vertices);
        self.edges.extend(other.edges.iter().map(|e| Edge2 {
            start: e.start + off,
            end: e.end + off,
            mult: e.mult,
        }));
    }

    /// The same set with every edge reversed (winding numbers negated).
    pub fn reversed(&self) -> PolygonSet2 {
        PolygonSet2 {
            vertices: self.vertices.clone(),
            edges: self
                .edges
                .iter()
                .map(|e| Edge2 {
                    start: e.end,
                    end: e.start,
                    mult: e.mult,
                })
                .collect(),
        }
    }

    /// The number of vertices.
    pub fn vertex_count(&self) -> usize {
        self.vertices.len()
    }

    /// The number of edges (entries, whatever their multiplicity).
    pub fn edge_count(&self) -> usize {
        self.edges.len()
    }

    /// `true` when the set has no edge with non-zero multiplicity.
    pub fn is_empty(&self) -> bool {
        self.edges.iter().all(|e| e.mult == 0)
    }

    /// Checks the data definitions and the shape boundary closure constraint
    /// of section 4.2. On failure names the first offending edge or vertex.
    pub fn check_topology(&self) -> Result<(), TopologyError> {
        let n = self.vertices.len();
        let mut balance = vec![(0i64, 0i64); n];
        for (i, e) in self.edges.iter().enumerate() {
            for v in [e.start, e.end] {
                if v as usize >= n {
                    return Err(TopologyError::DanglingIndex {
                        entity: "edge",
                        entity_index: i as u32,
                        vertex: v,
                        vertex_count: n as u32,
                    });
                }
            }
            let m = i64::from(e.mult);
            balance[e.start as usize].1 += m;
            balance[e.end as usize].0 += m;
        }
        for (v, &(ending, starting)) in balance.iter().enumerate() {
            if ending != starting {
                return Err(TopologyError::ShapeClosure2 {
                    vertex: v as u32,
                    ending,
                    starting,
                });
            }
        }
        Ok(())
    }

    /// Checks that every coordinate is finite and at most `f64::MAX / 4` in
    /// magnitude (section 8.5).
    pub fn validate_coordinates(&self) -> Result<(), TopologyError> {
        validate_points(&self.vertices)
    }

    /// The largest coordinate magnitude (0 for an empty set).
    pub fn max_abs_coordinate(&self) -> f64 {
        self.vertices
            .iter()
            .flat_map(|p| p.iter())
            .fold(0.0f64, |m, &c| m.max(c.abs()))
    }

    /// The multiplicity-weighted signed area, the integral of the winding
    /// number over the plane (shoelace formula in f64; an estimate, not an
    /// exact value). Where the formula's products overflow (coordinates
    /// beyond about 1.3e154), the sum is taken on coordinates scaled by a
    /// power of two and scaled back: the area, or an infinity of its sign
    /// when it exceeds `f64::MAX`.
    pub fn signed_area(&self) -> f64 {
        let area = self.twice_area([1.0; 2]) / 2.0;
        if area.is_finite() {
            return area;
        }
        match crate::unit_scale::axis_scales(self.vertices.iter().copied()) {
            Some((down, up)) => crate::unit_scale::scaled_back(self.twice_area(down) / 2.0, &up),
            None => area,
        }
    }

    /// Twice [`PolygonSet2::signed_area`], coordinate `k` multiplied by
    /// `scale[k]` (1, or powers of two).
    fn twice_area(&self, scale: [f64; 2]) -> f64 {
        let mut twice = 0.0;
        for e in &self.edges {
            let (a, b) = self.edge_points(e);
            let s = |p: Point2| [p[0] * scale[0], p[1] * scale[1]];
            let (a, b) = (s(a), s(b));
            twice += f64::from(e.mult) * (a[0] * b[1] - b[0] * a[1]);
        }
        twice
    }

    /// The axis-aligned bounding box `[min, max]` of the vertices of edges
    /// with non-zero multiplicity, or `None` when there are none.
    pub fn bounding_box(&self) -> Option<[Point2; 2]> {
        let mut bb: Option<[Point2; 2]> = None;
        for e in self.edges.iter().filter(|e| e.mult != 0) {
            for v in [e.start, e.end] {
                let p = self.vertex(v);
                let b = bb.get_or_insert([p, p]);
                for c in 0..2 {
                    b[0][c] = b[0][c].min(p[c]);
                    b[1][c] = b[1][c].max(p[c]);
                }
            }
        }
        bb
    }

    /// Splits the edges into closed loops of unit edges (multiplicity `m`
    /// edges become `|m|` copies, reversed when negative). Each loop is a
    /// list of vertex indices, the last joining back to the first.
    ///
    /// At a vertex where several loops meet, the outgoing edge is the first
    /// one clockwise from the reversed incoming edge, so the walk follows
    /// the region on its left around one corner of it; a walk that comes
    /// back to a vertex it passed (a hole touching its outer ring, two
    /// holes touching) is then cut there into closed loops. So no loop
    /// passes a vertex twice: loops that touch at a vertex come out as
    /// separate rings, which is what ring formats (the simple rings of
    /// OGC Simple Features) need. Requires [`Self::check_topology`] to
    /// pass; otherwise the unmatched edges are left out.
    pub fn loops(&self) -> Vec<Vec<u32>> {
        crate::polygon_set::trace::trace_loops(self)
    }
}

mod trace {
    //! Loop tracing for [`super::PolygonSet2::loops`].
    use super::PolygonSet2;

    /// The pseudo-angle of direction `d` in `[0, 4)`, monotone in the true
    /// angle measured anticlockwise from +x; exact comparisons are not
    /// needed here (any pairing keeps the topology, section 4.6).
    fn pseudo_angle(d: [f64; 2]) -> f64 {
        let s = d[0].abs() + d[1].abs();
        if s == 0.0 {
            return 0.0;
        }
        let p = d[0] / s;
        if d[1] >= 0.0 {
            1.0 - p
        } else {
            3.0 + p
        }
    }

    pub(super) fn trace_loops(set: &PolygonSet2) -> Vec<Vec<u32>> {
        let n = set.vertices.len();
        // Unit edges, outgoing lists per vertex.
        let mut unit: Vec<(u32, u32)> = Vec::new();
        for e in &set.edges {
            if (e.start as usize) >= n || (e.end as usize) >= n {
                continue;
            }
            let (s, t) = if e.mult >= 0 {
                (e.start, e.end)
            } else {
                (e.end, e.start)
            };
            for _ in 0..e.mult.unsigned_abs() {
                unit.push((s, t));
            }
        }
        let mut out_start = vec![0usize; n + 1];
        for &(s, _) in &unit {
            out_start[s as usize + 1] += 1;
        }
        for i in 0..n {
            out_start[i + 1] += out_start[i];
        }
        let mut fill = out_start.clone();
        let mut out_edges = vec![0usize; unit.len()];
        for (i, &(s, _)) in unit.iter().enumerate() {
            out_edges[fill[s as usize]] = i;
            fill[s as usize] += 1;
        }
        let mut used = vec![false; unit.len()];
        let mut loops = Vec::new();
        let mut at = vec![u32::MAX; n];
        for first in 0..unit.len() {
            if used[first] {
                continue;
            }
            used[first] = true;
            let start_vertex = unit[first].0;
            let mut ring = vec![start_vertex];
            let mut cur = first;
            loop {
                let (s, t) = unit[cur];
                if t == start_vertex {
                    break;
                }
                // Choose the unused outgoing edge at t turning furthest right.
                let pt = set.vertices[t as usize];
                let ps = set.vertices[s as usize];
                let back = pseudo_angle([ps[0] - pt[0], ps[1] - pt[1]]);
                let mut best: Option<(f64, usize)> = None;
                for &cand in &out_edges[out_start[t as usize]..out_start[t as usize + 1]] {
                    if used[cand] {
                        continue;
                    }
                    let q = set.vertices[unit[cand].1 as usize];
                    let a = pseudo_angle([q[0] - pt[0], q[1] - pt[1]]);
                    // The clockwise angle from the backward direction to the
                    // candidate; the smallest wins.
                    let mut turn = back - a;
                    if turn <= 0.0 {
                        turn += 4.0;
                    }
                    if best.is_none_or(|(b, _)| turn < b) {
                        best = Some((turn, cand));
                    }
                }
                match best {
                    Some((_, next)) => {
                        used[next] = true;
                        ring.push(t);
                        cur = next;
                    }
                    None => break,
                }
            }
            split_at_repeats(&ring, &mut at, &mut loops);
        }
        loops
    }

    /// Cuts the closed walk `walk` into loops that pass no vertex twice and
    /// appends them to `out`: a stack of the walk's vertices, and on
    /// meeting a vertex already on it, everything above that vertex (with
    /// it) closes a loop. Each edge of the walk lands in exactly one loop,
    /// in its direction, so the edges and every winding number stay the
    /// same. `at` holds each vertex's stack position, `u32::MAX` when not
    /// on the stack (and is left so).
    fn split_at_repeats(walk: &[u32], at: &mut Vec<u32>, out: &mut Vec<Vec<u32>>) {
        let mut stack: Vec<u32> = Vec::with_capacity(walk.len());
        for &v in walk {
            if at.len() <= v as usize {
                at.resize(v as usize + 1, u32::MAX);
            }
            let pos = at[v as usize];
            if pos == u32::MAX {
                at[v as usize] = stack.len() as u32;
                stack.push(v);
                continue;
            }
            // The walk came back to `v`: the part since closes a loop.
            let piece: Vec<u32> = stack.drain(pos as usize..).collect();
            for &w in &piece[1..] {
                at[w as usize] = u32::MAX;
            }
            out.push(piece);
            stack.push(v);
        }
        for &w in &stack {
            at[w as usize] = u32::MAX;
        }
        if !stack.is_empty() {
            out.push(stack);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn closure_counts_multiplicity() {
        let mut s = PolygonSet2::new();
        let a = s.add_vertex([0.0, 0.0]);
        let b = s.add_vertex([1.0, 0.0]);
        let c = s.add_vertex([0.0, 1.0]);
        s.add_edge_mult(a, b, 2);
        s.add_edge_mult(b, c, 2);
        s.add_edge(c, a);
        assert_eq!(
            s.check_topology(),
            Err(TopologyError::ShapeClosure2 {
                vertex: 0,
                ending: 1,
                starting: 2
            })
        );
        s.add_edge_mult(a, c, -1);
        assert!(s.check_topology().is_ok());
        assert_eq!(s.signed_area(), 1.0);
    }

    #[test]
    fn dangling_index_is_named() {
        let s = PolygonSet2::from_parts(
            vec![[0.0, 0.0]],
            vec![Edge2 {
                start: 0,
                end: 3,
                mult: 1,
            }],
        );
        assert!(matches!(
            s.check_topology(),
            Err(TopologyError::DanglingIndex { vertex: 3, .. })
        ));
    }

    #[test]
    fn bad_coordinates_are_named() {
        let mut s = PolygonSet2::new();
        s.add_loop(&[[0.0, 0.0], [1.0, f64::NAN], [0.0, 1.0]]);
        let err = s.validate_coordinates().unwrap_err();
        assert!(matches!(
            err,
            TopologyError::BadCoordinate {
                vertex: 1,
                axis: 1,
                ..
            }
        ));
        assert!(err.to_string().contains("vertex 1"));
    }

    /// The directed unit edges of `loops`, sorted.
    fn loop_edges(loops: &[Vec<u32>]) -> Vec<(u32, u32)> {
        let mut e: Vec<(u32, u32)> = loops
            .iter()
            .flat_map(|l| (0..l.len()).map(move |i| (l[i], l[(i + 1) % l.len()])))
            .collect();
        e.sort_unstable();
        e
    }

    /// The directed unit edges of `set` (multiplicity `m` as `|m|` copies,
    /// reversed when negative), sorted.
    fn unit_edges(set: &PolygonSet2) -> Vec<(u32, u32)> {
        let mut e = Vec::new();
        for x in set.edges() {
            let d = if x.mult > 0 {
                (x.start, x.end)
            } else {
                (x.end, x.start)
            };
            e.extend(std::iter::repeat_n(d, x.mult.unsigned_abs() as usize));
        }
        e.sort_unstable();
        e
    }

    #[test]
    fn loops_split_a_hole_touching_its_outer_ring() {
        // A square with a triangular hole touching its corner (0, 0), and a
        // second hole touching the first at (2, 5): the walk around the
        // region's corners passes (0, 0) and (2, 5) twice; the loops must
        // not (a ring through one point twice is not a simple ring).
        // The touching points are one vertex each, and the outer ring
        // starts at (0, 10), so the walk reaches (0, 0) before closing and
        // turns into the hole there.
        let mut s = PolygonSet2::new();
        let [top, o, right, corner, a, b, c, d] = [
            [0., 10.],
            [0., 0.],
            [10., 0.],
            [10., 10.],
            [2., 5.],
            [5., 2.],
            [3., 8.],
            [4., 6.],
        ]
        .map(|p| s.add_vertex(p));
        for ring in [&[top, o, right, corner][..], &[o, a, b], &[a, c, d]] {
            for i in 0..ring.len() {
                s.add_edge(ring[i], ring[(i + 1) % ring.len()]);
            }
        }
        assert!(s.check_topology().is_ok());
        let loops = s.loops();
        assert_eq!(loops.len(), 3, "{loops:?}");
        for l in &loops {
            let mut v = l.clone();
            v.sort_unstable();
            v.dedup();
            assert_eq!(v.len(), l.len(), "{l:?} passes a vertex twice");
        }
        assert_eq!(loop_edges(&loops), unit_edges(&s));
        let areas: Vec<f64> = loops
            .iter()
            .map(|l| {
                let ring: Vec<Point2> = l.iter().map(|&v| s.vertex(v)).collect();
                crate::ring_signed_area(&ring)
            })
            .collect();
        assert_eq!(areas.iter().filter(|&&a| a > 0.0).count(), 1, "{areas:?}");
        assert_eq!(areas.iter().sum::<f64>(), s.signed_area());
    }

    proptest::proptest! {
        /// Closed random walks on a 4 x 4 grid (many vertices passed
        /// several times, edges repeated and reversed): every loop passes
        /// each vertex at most once, and the loops use each unit edge of
        /// the set exactly once.
        #[test]
        fn loops_are_simple_and_use_every_edge_once(
            walks in proptest::collection::vec(
                proptest::collection::vec((0u8..4, 0u8..4), 2..12), 1..5)
        ) {
            let mut s = PolygonSet2::new();
            let ids: Vec<u32> = (0..16)
                .map(|i| s.add_vertex([f64::from(i % 4), f64::from(i / 4)]))
                .collect();
            for w in &walks {
                for i in 0..w.len() {
                    let (a, b) = (w[i], w[(i + 1) % w.len()]);
                    let (a, b) = (ids[usize::from(a.0 + 4 * a.1)], ids[usize::from(b.0 + 4 * b.1)]);
                    if a != b {
                        s.add_edge(a, b);
                    }
                }
            }
            proptest::prop_assume!(s.check_topology().is_ok());
            let loops = s.loops();
            for l in &loops {
                let mut v = l.clone();
                v.sort_unstable();
                v.dedup();
                proptest::prop_assert_eq!(v.len(), l.len(), "{:?}", l);
            }
            proptest::prop_assert_eq!(loop_edges(&loops), unit_edges(&s));
        }
    }

    #[test]
    fn loops_split_a_figure_eight_at_the_touching_vertex() {
        // Two squares touching at (1,1), drawn as one closed walk.
        let mut s = PolygonSet2::new();
        let p = |x: f64, y: f64| [x, y];
        let v: Vec<u32> = [
            p(0., 0.),
            p(1., 0.),
            p(1., 1.),
            p(2., 1.),
            p(2., 2.),
            p(1., 2.),
            p(0., 1.),
        ]
        .iter()
        .map(|&q| s.add_vertex(q))
        .collect();
        for (a, b) in [
            (0, 1),
            (1, 2),
            (2, 3),
            (3, 4),
            (4, 5),
            (5, 2),
            (2, 6),
            (6, 0),
        ] {
            s.add_edge(v[a], v[b]);
        }
        assert!(s.check_topology().is_ok());
        let loops = s.loops();
        assert_eq!(loops.len(), 2, "{loops:?}");
        let total: usize = loops.iter().map(|l| l.len()).sum();
        assert_eq!(total, 8);
    }
}
