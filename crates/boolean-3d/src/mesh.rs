//! The flat internal form of an operand: half-edges grouped by facet and by
//! edge (section 4.2: an edge groups the half-edges joining the same two
//! vertices in either order), with the bounding boxes of the broad phase.

use crate::bvh::Aabb;
use rayon::prelude::*;
use robust_arith::Point3;
use topology::{PolygonMesh, TriangleMesh};

/// One operand in compressed-row form. Indices are `u32` as in `topology`.
pub(crate) struct Flat<'a> {
    /// Vertex positions (borrowed from the caller's mesh).
    pub pos: &'a [Point3],
    /// Half-edges `(start, end)`, facet by facet.
    pub he: Vec<(u32, u32)>,
    /// `facet_off[f]..facet_off[f + 1]` are the half-edges of facet `f`.
    pub facet_off: Vec<u32>,
    /// The facet of each half-edge.
    pub he_facet: Vec<u32>,
    /// The edge of each half-edge.
    pub he_edge: Vec<u32>,
    /// Whether each half-edge is a forward half-edge of its edge (section
    /// 4.2). Zero-length half-edges count as forward.
    pub he_fwd: Vec<bool>,
    /// The edges `(start, end)` with `start <= end` (vertex indices): the
    /// forward direction of an edge runs from the lower index to the higher.
    pub edges: Vec<(u32, u32)>,
    /// `edge_off[e]..edge_off[e + 1]` index `edge_he`: the half-edges of `e`.
    pub edge_off: Vec<u32>,
    /// Half-edge indices grouped by edge.
    pub edge_he: Vec<u32>,
}

impl<'a> Flat<'a> {
    /// The flat form of a polygon mesh (already validated).
    pub fn from_polygon_mesh(m: &'a PolygonMesh) -> Self {
        let mut he = Vec::with_capacity(m.half_edge_count());
        let mut facet_off = Vec::with_capacity(m.facets.len() + 1);
        facet_off.push(0u32);
        for f in &m.facets {
            he.extend(f.half_edges.iter().map(|h| (h.start, h.end)));
            facet_off.push(he.len() as u32);
        }
        Self::build(&m.vertices, he, facet_off)
    }

    /// The flat form of a triangle mesh (already validated): triangle
    /// `[a, b, c]` has half-edges `a->b, b->c, c->a`.
    pub fn from_triangle_mesh(m: &'a TriangleMesh) -> Self {
        let he: Vec<(u32, u32)> = m
            .triangles
            .iter()
            .flat_map(|t| [(t[0], t[1]), (t[1], t[2]), (t[2], t[0])])
            .collect();
        let facet_off = (0..=m.triangles.len() as u32).map(|i| 3 * i).collect();
        Self::build(&m.vertices, he, facet_off)
    }

    fn build(pos: &'a [Point3], he: Vec<(u32, u32)>, facet_off: Vec<u32>) -> Self {
        let n_he = he.len();
        let mut he_facet = vec![0u32; n_he];
        for (f, w) in facet_off.windows(2).enumerate() {
            for slot in &mut he_facet[w[0] as usize..w[1] as usize] {
                *slot = f as u32;
            }
        }
        // Group half-edges into edges by their unordered vertex pair; the
        // sort key makes the edge numbering independent of thread count.
        let mut keyed: Vec<(u64, u32)> = he
            .iter()
            .enumerate()
            .map(|(i, &(s, e))| {
                let (lo, hi) = if s <= e { (s, e) } else { (e, s) };
                ((u64::from(lo) << 32) | u64::from(hi), i as u32)
            })
            .collect();
        keyed.par_sort_unstable();
        let mut edges = Vec::new();
        let mut edge_off = Vec::new();
        let mut edge_he = Vec::with_capacity(n_he);
        let mut he_edge = vec![0u32; n_he];
        let mut he_fwd = vec![true; n_he];
        let mut last = u64::MAX;
        for &(key, h) in &keyed {
            if key != last {
                last = key;
                edge_off.push(edge_he.len() as u32);
                edges.push(((key >> 32) as u32, key as u32));
            }
            let e = edges.len() as u32 - 1;
            he_edge[h as usize] = e;
            he_fwd[h as usize] = he[h as usize].0 <= he[h as usize].1;
            edge_he.push(h);
        }
        edge_off.push(edge_he.len() as u32);
        Flat {
            pos,
            he,
            facet_off,
            he_facet,
            he_edge,
            he_fwd,
            edges,
            edge_off,
            edge_he,
        }
    }

    /// The number of facets.
    pub fn facet_count(&self) -> usize {
        self.facet_off.len() - 1
    }

    /// The half-edge index range of facet `f`.
    #[inline]
    pub fn facet_range(&self, f: u32) -> std::ops::Range<usize> {
        self.facet_off[f as usize] as usize..self.facet_off[f as usize + 1] as usize
    }

    /// The half-edges of facet `f` as point pairs (the form the level-2
    /// functions of `shadow-2d` take).
    #[inline]
    pub fn facet_points(&self, f: u32) -> impl Iterator<Item = (Point3, Point3)> + Clone + '_ {
        self.he[self.facet_range(f)]
            .iter()
            .map(|&(s, e)| (self.pos[s as usize], self.pos[e as usize]))
    }

    /// The half-edges of edge `e`.
    #[inline]
    pub fn edge_half_edges(&self, e: u32) -> &[u32] {
        &self.edge_he[self.edge_off[e as usize] as usize..self.edge_off[e as usize + 1] as usize]
    }

    /// The end points of edge `e` (start, end).
    #[inline]
    pub fn edge_points(&self, e: u32) -> (Point3, Point3) {
        let (s, t) = self.edges[e as usize];
        (self.pos[s as usize], self.pos[t as usize])
    }

    /// Which vertices are referenced by at least one half-edge.
    pub fn referenced(&self) -> Vec<bool> {
        let mut r = vec![false; self.pos.len()];
        for &(s, e) in &self.he {
            r[s as usize] = true;
            r[e as usize] = true;
        }
        r
    }

    /// The closed bounding box of every facet.
    pub fn facet_boxes(&self) -> Vec<Aabb> {
        (0..self.facet_count() as u32)
            .into_par_iter()
            .map(|f| {
                let mut b = Aabb::EMPTY;
                for &(s, _) in &self.he[self.facet_range(f)] {
                    b.add(&self.pos[s as usize]);
                }
                b
            })
            .collect()
    }
}
