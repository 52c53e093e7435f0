//! `PolygonMesh`: a polyhedral shape whose facets are collections of
//! half-edges (section 4.2, "Polygon mesh").

use crate::{validate_points, TopologyError};
use robust_arith::Point3;
use std::collections::HashMap;

/// A half-edge: a directed link from vertex `start` to vertex `end`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct HalfEdge {
    /// The start-vertex index.
    pub start: u32,
    /// The end-vertex index.
    pub end: u32,
}

/// A facet: a collection of half-edges. Facet boundary closure (section 4.2)
/// requires every vertex to start as many of the facet's half-edges as it
/// ends, so the half-edges form loops: an outer boundary and holes, or
/// several regions. The facet faces the side from which its outer loops run
/// anticlockwise.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Facet {
    /// The half-edges, in no required order.
    pub half_edges: Vec<HalfEdge>,
}

impl Facet {
    /// A facet bounded by one loop through the given vertices.
    pub fn from_loop(vertices: &[u32]) -> Facet {
        let mut f = Facet::default();
        f.push_loop(vertices);
        f
    }

    /// A facet bounded by several loops (e.g. an outer loop and holes).
    pub fn from_loops(loops: &[Vec<u32>]) -> Facet {
        let mut f = Facet::default();
        for l in loops {
            f.push_loop(l);
        }
        f
    }

    /// Adds the half-edges of one closed loop.
    pub fn push_loop(&mut self, vertices: &[u32]) {
        let n = vertices.len();
        for i in 0..n {
            self.half_edges.push(HalfEdge {
                start: vertices[i],
                end: vertices[(i + 1) % n],
            });
        }
    }

    /// Chains the half-edges into closed loops of vertex indices. Valid only
    /// when the facet satisfies facet boundary closure; half-edges that
    /// cannot be chained are returned as open chains.
    pub fn loops(&self) -> Vec<Vec<u32>> {
        // The first unused half-edge leaving the vertex, until the start.
        self.trace(&self.outgoing(), |_, at, first, free| {
            (at != self.half_edges[first].start)
                .then(|| free.first().copied())
                .flatten()
        })
    }

    /// Chains the half-edges into loops: from each unused half-edge
    /// `first` in order, a loop goes on by `choose(prev, at, first, free)`
    /// at each vertex `at` it reaches from `prev`, where `free` are the
    /// unused half-edges leaving `at` in stored order; `Some(i)` takes
    /// half-edge `i`, `None` ends the loop (closed when `at` is its start).
    fn trace(
        &self,
        outgoing: &HashMap<u32, Vec<usize>>,
        mut choose: impl FnMut(u32, u32, usize, &[usize]) -> Option<usize>,
    ) -> Vec<Vec<u32>> {
        let mut used = vec![false; self.half_edges.len()];
        let mut loops = Vec::new();
        let mut free = Vec::new();
        for first in 0..self.half_edges.len() {
            if used[first] {
                continue;
            }
            used[first] = true;
            let start = self.half_edges[first].start;
            let mut ring = vec![start];
            let mut prev = start;
            let mut at = self.half_edges[first].end;
            loop {
                free.clear();
                if let Some(list) = outgoing.get(&at) {
                    free.extend(list.iter().copied().filter(|&i| !used[i]));
                }
                match choose(prev, at, first, &free) {
                    Some(i) => {
                        used[i] = true;
                        ring.push(at);
                        prev = at;
                        at = self.half_edges[i].end;
                    }
                    None => break,
                }
            }
            loops.push(ring);
        }
        loops
    }

    /// [`Facet::loops`], with the choice made by geometry where the facet
    /// passes a vertex more than once: arriving at such a vertex, a loop
    /// leaves by the unused outgoing half-edge met first turning clockwise
    /// from the edge it came by, in the facet's plane seen from the side
    /// the facet faces (the plane of its Newell normal at `positions`).
    /// That is how the boundary of a region on its left is traced, so two
    /// parts of a facet touching at a vertex come out as two loops, not
    /// as one loop through the vertex twice whose corners pair the wrong
    /// edges (which a file format of one loop per face would then carry,
    /// and which reads as a pinched surface). Without such a vertex, or
    /// with an index out of range of `positions`, the loops of
    /// [`Facet::loops`].
    ///
    /// ```
    /// use topology::Facet;
    /// // Two triangles of one facet touching at vertex 0, their
    /// // half-edges stored so that the plain tracing passes 0 twice.
    /// let p = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [1.0, 1.0, 0.0], [-1.0, 0.0, 0.0], [-1.0, -1.0, 0.0]];
    /// let f = Facet::from_loop(&[1, 2, 0, 3, 4, 0]);
    /// assert_eq!(f.loops(), vec![vec![1, 2, 0, 3, 4, 0]]);
    /// assert_eq!(f.loops_in_plane(&p), vec![vec![1, 2, 0], vec![0, 3, 4]]);
    /// ```
    pub fn loops_in_plane(&self, positions: &[Point3]) -> Vec<Vec<u32>> {
        let n = positions.len() as u32;
        let outgoing = self.outgoing();
        let in_range = self.half_edges.iter().all(|h| h.start < n && h.end < n);
        if !in_range || outgoing.values().all(|l| l.len() == 1) {
            return self.loops();
        }
        let Some((u, v)) = self.plane_axes(positions) else {
            return self.loops();
        };
        let flat = |i: u32| {
            let p = positions[i as usize];
            [p[u], p[v]]
        };
        // The clockwise angle from direction `r` to direction `d`, in
        // (0, 2 pi]: the turn of `d` past `r`.
        let clockwise = |r: [f64; 2], d: [f64; 2]| {
            let cross = r[0] * d[1] - r[1] * d[0];
            let dot = r[0] * d[0] + r[1] * d[1];
            let a = (-cross).atan2(dot);
            if a <= 0.0 {
                a + std::f64::consts::TAU
            } else {
                a
            }
        };
        self.trace(&outgoing, |prev, at, first, free| {
            // Back at the start, closing the loop (by `first`) is one of
            // the choices.
            let closing = (at == self.half_edges[first].start).then_some(first);
            let here = flat(at);
            let back = flat(prev);
            let r = [back[0] - here[0], back[1] - here[1]];
            let turn = |k: usize| {
                let e = flat(self.half_edges[k].end);
                clockwise(r, [e[0] - here[0], e[1] - here[1]])
            };
            free.iter()
                .copied()
                .chain(closing)
                .min_by(|&i, &j| turn(i).total_cmp(&turn(j)).then(i.cmp(&j)))
                .filter(|&i| Some(i) != closing)
        })
    }

    /// The half-edges leaving each vertex, by index, in stored order.
    fn outgoing(&self) -> HashMap<u32, Vec<usize>> {
        let mut outgoing: HashMap<u32, Vec<usize>> = HashMap::new();
        for (i, h) in self.half_edges.iter().enumerate() {
            outgoing.entry(h.start).or_default().push(i);
        }
        outgoing
    }

    /// The two coordinate axes of the projection that sees the facet from
    /// the side it faces: the plane orthogonal to the largest component of
    /// its Newell normal, ordered so that the loops keep their turning
    /// sense; `None` for a facet with a zero normal.
    fn plane_axes(&self, positions: &[Point3]) -> Option<(usize, usize)> {
        let mut normal = [0.0f64; 3];
        for h in &self.half_edges {
            let (a, b) = (positions[h.start as usize], positions[h.end as usize]);
            for (k, n) in normal.iter_mut().enumerate() {
                let (i, j) = ((k + 1) % 3, (k + 2) % 3);
                *n += (a[i] - b[i]) * (a[j] + b[j]);
            }
        }
        let k = (0..3).max_by(|&i, &j| normal[i].abs().total_cmp(&normal[j].abs()))?;
        if normal[k] == 0.0 || normal[k].is_nan() {
            return None;
        }
        let (i, j) = ((k + 1) % 3, (k + 2) % 3);
        Some(if normal[k] > 0.0 { (i, j) } else { (j, i) })
    }
}

/// A polyhedral shape as vertices and facets (section 4.2). Non-manifold
/// edges (several half-edge pairs), several shells, coincident vertices and
/// zero-length edges are all topologically valid.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct PolygonMesh {
    /// The vertex positions.
    pub vertices: Vec<Point3>,
    /// The facets.
    pub facets: Vec<Facet>,
}

impl PolygonMesh {
    /// A mesh from vertices and facets (unchecked).
    pub fn new(vertices: Vec<Point3>, facets: Vec<Facet>) -> Self {
        PolygonMesh { vertices, facets }
    }

    /// The total number of half-edges.
    pub fn half_edge_count(&self) -> usize {
        self.facets.iter().map(|f| f.half_edges.len()).sum()
    }

    /// Checks the data definitions, facet boundary closure for every facet
    /// and shape boundary closure (section 4.2).
    pub fn check_topology(&self) -> Result<(), TopologyError> {
        let n = self.vertices.len() as u32;
        for (fi, f) in self.facets.iter().enumerate() {
            for h in &f.half_edges {
                for v in [h.start, h.end] {
                    if v >= n {
                        return Err(TopologyError::DanglingIndex {
                            entity: "facet",
                            entity_index: fi as u32,
                            vertex: v,
                            vertex_count: n,
                        });
                    }
                }
            }
        }
        // Facet boundary closure.
        let mut balance: HashMap<u32, (u32, u32)> = HashMap::new();
        for (fi, f) in self.facets.iter().enumerate() {
            balance.clear();
            for h in &f.half_edges {
                balance.entry(h.end).or_default().0 += 1;
                balance.entry(h.start).or_default().1 += 1;
            }
            let mut bad: Vec<_> = balance
                .iter()
                .filter(|(_, (e, s))| e != s)
                .map(|(&v, &(e, s))| (v, e, s))
                .collect();
            bad.sort_unstable();
            if let Some(&(vertex, ending, starting)) = bad.first() {
                return Err(TopologyError::FacetClosure {
                    facet: fi as u32,
                    vertex,
                    ending,
                    starting,
                });
            }
        }
        check_shape_closure(
            self.facets
                .iter()
                .flat_map(|f| f.half_edges.iter().map(|h| (h.start, h.end))),
        )
    }

    /// Checks every coordinate (finite, at most `f64::MAX / 4`).
    pub fn validate_coordinates(&self) -> Result<(), TopologyError> {
        validate_points(&self.vertices)
    }

    /// The same mesh with every facet turned over: each half-edge
    /// reversed, each loop walked backwards (winding numbers negated, so
    /// inside and outside swap). Both closure constraints hold for the
    /// result exactly when they hold for `self`.
    pub fn reversed(&self) -> PolygonMesh {
        PolygonMesh {
            vertices: self.vertices.clone(),
            facets: self
                .facets
                .iter()
                .map(|f| Facet {
                    half_edges: f
                        .half_edges
                        .iter()
                        .rev()
                        .map(|h| HalfEdge {
                            start: h.end,
                            end: h.start,
                        })
                        .collect(),
                })
                .collect(),
        }
    }
}

/// Shape boundary closure over a stream of half-edges: for every vertex pair
/// the number of half-edges `P -> Q` equals the number `Q -> P`.
pub(crate) fn check_shape_closure(
    half_edges: impl Iterator<Item = (u32, u32)>,
) -> Result<(), TopologyError> {
    // Per unordered vertex pair: (half-edges low->high, half-edges high->low).
    let mut count: HashMap<(u32, u32), (u32, u32)> = HashMap::new();
    for (s, e) in half_edges {
        if s == e {
            continue; // a zero-length half-edge is its own reverse
        }
        if s < e {
            count.entry((s, e)).or_default().0 += 1;
        } else {
            count.entry((e, s)).or_default().1 += 1;
        }
    }
    let mut bad: Vec<_> = count.into_iter().filter(|(_, (f, b))| f != b).collect();
    bad.sort_unstable();
    match bad.first() {
        Some(&((start, end), (forward, backward))) => Err(TopologyError::ShapeClosure3 {
            start,
            end,
            forward,
            backward,
        }),
        None => Ok(()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The unit cube. A local copy of `test_support::shapes::box_mesh`:
    /// `test-support` depends on this crate, so here its meshes would be a
    /// second, foreign `PolygonMesh` type.
    fn cube() -> PolygonMesh {
        let mut v = Vec::new();
        for i in 0..8u32 {
            v.push([
                f64::from(i & 1),
                f64::from((i >> 1) & 1),
                f64::from((i >> 2) & 1),
            ]);
        }
        let faces: [[u32; 4]; 6] = [
            [0, 2, 3, 1],
            [4, 5, 7, 6],
            [0, 1, 5, 4],
            [2, 6, 7, 3],
            [0, 4, 6, 2],
            [1, 3, 7, 5],
        ];
        PolygonMesh::new(v, faces.iter().map(|f| Facet::from_loop(f)).collect())
    }

    #[test]
    fn cube_is_closed() {
        let c = cube();
        assert_eq!(c.check_topology(), Ok(()));
        assert_eq!(c.half_edge_count(), 24);
    }

    #[test]
    fn missing_face_breaks_shape_closure() {
        let mut c = cube();
        c.facets.pop();
        assert!(matches!(
            c.check_topology(),
            Err(TopologyError::ShapeClosure3 { .. })
        ));
    }

    #[test]
    fn open_facet_breaks_facet_closure() {
        let mut c = cube();
        c.facets[0].half_edges.pop();
        assert!(matches!(
            c.check_topology(),
            Err(TopologyError::FacetClosure { facet: 0, .. })
        ));
    }

    #[test]
    fn facet_with_hole_has_two_loops() {
        let f = Facet::from_loops(&[vec![0, 1, 2, 3], vec![4, 7, 6, 5]]);
        let loops = f.loops();
        assert_eq!(loops.len(), 2);
        assert_eq!(loops[0], vec![0, 1, 2, 3]);
    }

    proptest::proptest! {
        /// Triangles of one facet around a shared centre vertex, each
        /// anticlockwise in its plane, in a plane of any orientation and
        /// with the half-edges stored in any order: the geometric tracing
        /// gives back exactly the triangles (as rotations of their loops),
        /// where the plain tracing may run through the centre twice.
        #[test]
        fn touching_triangles_come_back_as_their_loops(
            k in 2usize..6,
            axis in proptest::array::uniform3(-1.0f64..1.0),
            angle in 0.0f64..std::f64::consts::TAU,
            flip in proptest::bool::ANY,
            order in proptest::collection::vec(0u32..1000, 18),
        ) {
            proptest::prop_assume!(axis.iter().map(|a| a * a).sum::<f64>() > 1e-3);
            let n = axis.iter().map(|a| a * a).sum::<f64>().sqrt();
            let [x, y, z] = axis.map(|a| a / n);
            let (sn, c) = angle.sin_cos();
            let t = 1.0 - c;
            let r = [
                [t * x * x + c, t * x * y - sn * z, t * x * z + sn * y],
                [t * x * y + sn * z, t * y * y + c, t * y * z - sn * x],
                [t * x * z - sn * y, t * y * z + sn * x, t * z * z + c],
            ];
            let place = |u: f64, v: f64| {
                let v = if flip { -v } else { v };
                [0, 1, 2].map(|i| r[i][0] * u + r[i][1] * v)
            };
            // Triangle j spans the angles [2 pi j / k, 2 pi (j + 0.6) / k].
            let mut p = vec![place(0.0, 0.0)];
            let mut tris = Vec::new();
            for j in 0..k {
                let a0 = std::f64::consts::TAU * j as f64 / k as f64;
                let a1 = std::f64::consts::TAU * (j as f64 + 0.6) / k as f64;
                let first = p.len() as u32;
                p.push(place(a0.cos(), a0.sin()));
                p.push(place(a1.cos(), a1.sin()));
                // Anticlockwise in (u, v); clockwise when the plane is
                // flipped, so reverse it there to keep one facet's sense.
                tris.push(if flip { [0, first + 1, first] } else { [0, first, first + 1] });
            }
            let mut half_edges: Vec<HalfEdge> = tris
                .iter()
                .flat_map(|t| (0..3).map(move |i| HalfEdge { start: t[i], end: t[(i + 1) % 3] }))
                .collect();
            let mut keyed: Vec<(u32, HalfEdge)> =
                half_edges.iter().zip(&order).map(|(h, &o)| (o, *h)).collect();
            keyed.sort_by_key(|e| e.0);
            half_edges = keyed.into_iter().map(|e| e.1).collect();
            let f = Facet { half_edges };
            let canon = |l: &[u32]| {
                let m = (0..l.len()).min_by_key(|&i| l[i]).unwrap_or(0);
                let mut r = l.to_vec();
                r.rotate_left(m);
                r
            };
            let mut got: Vec<Vec<u32>> = f.loops_in_plane(&p).iter().map(|l| canon(l)).collect();
            got.sort();
            let mut want: Vec<Vec<u32>> = tris.iter().map(|t| canon(t)).collect();
            want.sort();
            proptest::prop_assert_eq!(got, want);
        }
    }

    #[test]
    fn loops_in_plane_without_a_repeated_vertex_are_the_plain_loops() {
        let p = [
            [0.0, 0.0, 0.0],
            [4.0, 0.0, 0.0],
            [4.0, 4.0, 0.0],
            [0.0, 4.0, 0.0],
            [1.0, 1.0, 0.0],
            [1.0, 2.0, 0.0],
            [2.0, 2.0, 0.0],
        ];
        let f = Facet::from_loops(&[vec![0, 1, 2, 3], vec![4, 5, 6]]);
        assert_eq!(f.loops_in_plane(&p), f.loops());
        // An index beyond the positions: the plain loops, no panic.
        assert_eq!(f.loops_in_plane(&p[..3]), f.loops());
    }
}
