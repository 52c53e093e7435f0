//! The working structure of 3D smoothing (Appendix A): vertices that can
//! be created and left unreferenced, and facets as collections of
//! half-edges that operations cancel, swap and split in place. An edge is
//! the unordered pair of its vertices, so merging the edges of cancelled
//! half-edges' partners (Appendix A, "half-edge cancellation") needs no
//! bookkeeping. Deleted facets are empty until the final compaction, which
//! drops them and every unreferenced vertex.

use crate::mesh::geom::projection;
use crate::SmoothError;
use rayon::prelude::*;
use std::collections::HashMap;
use topology::{Facet, HalfEdge, Point3, PolygonMesh};

/// How a vertex of the working structure came to be.
#[derive(Clone, Copy, Debug)]
pub(crate) enum Origin {
    /// An input vertex (its input position).
    Input(Point3),
    /// Created by edge-edge cracking between two edges (their end points
    /// at creation time).
    Created([Point3; 4]),
}

/// The working mesh.
#[derive(Clone, Debug)]
pub(crate) struct Work {
    /// Vertex positions; input vertices first, created ones appended.
    pub pos: Vec<Point3>,
    /// Where each vertex came from.
    pub origin: Vec<Origin>,
    /// Position adjustments that touched each vertex (the k of chapter 8).
    pub adjustments: Vec<u32>,
    /// For every input vertex, the vertex it was merged into (itself if
    /// accepted).
    pub representative: Vec<u32>,
    /// The facets' half-edges; an empty facet is deleted.
    pub facets: Vec<Vec<HalfEdge>>,
    /// Whether an operation changed the facet's half-edges.
    pub changed: Vec<bool>,
}

/// The key of an edge: its vertices in increasing order.
pub(crate) fn edge_key(h: HalfEdge) -> (u32, u32) {
    (h.start.min(h.end), h.start.max(h.end))
}

impl Work {
    pub fn from_mesh(mesh: &PolygonMesh) -> Work {
        let n = mesh.vertices.len();
        Work {
            pos: mesh.vertices.clone(),
            origin: mesh.vertices.iter().map(|&p| Origin::Input(p)).collect(),
            adjustments: vec![0; n],
            representative: (0..n as u32).collect(),
            facets: mesh.facets.iter().map(|f| f.half_edges.clone()).collect(),
            changed: vec![false; mesh.facets.len()],
        }
    }

    pub fn half_edge_count(&self) -> usize {
        self.facets.iter().map(Vec::len).sum()
    }

    /// Whether each vertex is referenced by a half-edge.
    pub fn referenced(&self) -> Vec<bool> {
        let mut r = vec![false; self.pos.len()];
        for h in self.facets.iter().flatten() {
            r[h.start as usize] = true;
            r[h.end as usize] = true;
        }
        r
    }

    /// The distinct edges of non-zero length, sorted.
    pub fn edges(&self) -> Vec<(u32, u32)> {
        // Sorted as one u64 per edge (`a << 32 | b`: the same order as the
        // pairs, cheaper to compare and move).
        let mut e: Vec<u64> = self
            .facets
            .iter()
            .flatten()
            .filter(|h| h.start != h.end)
            .map(|&h| {
                let (a, b) = edge_key(h);
                (u64::from(a) << 32) | u64::from(b)
            })
            .collect();
        e.par_sort_unstable();
        e.dedup();
        e.into_iter()
            .map(|k| ((k >> 32) as u32, k as u32))
            .collect()
    }

    /// Adds a vertex created by cracking and returns its id.
    pub fn add_vertex(&mut self, p: Point3, origin: Origin) -> u32 {
        self.pos.push(p);
        self.origin.push(origin);
        self.adjustments.push(1);
        (self.pos.len() - 1) as u32
    }

    /// Renames vertices in every half-edge (vertex merging). Facet and
    /// shape boundary closure are kept: a renaming maps balanced
    /// multisets to balanced multisets.
    pub fn rename(&mut self, map: &[u32]) {
        for f in &mut self.facets {
            for h in f.iter_mut() {
                h.start = map[h.start as usize];
                h.end = map[h.end as usize];
            }
        }
    }

    /// Splits every half-edge of each edge in `splits` at the given
    /// vertices (the edge's ends excluded, duplicates ignored), ordered
    /// along the edge: `a -> b` becomes `a -> v1 -> .. -> b` and `b -> a`
    /// the reverse chain. A chain has the ends of the half-edge it
    /// replaces, so facet closure holds, and every sub-edge gets as many
    /// half-edges each way as the edge had, so shape closure holds.
    /// Returns the chains actually applied (interior vertices, ordered
    /// from the edge's smaller vertex).
    pub fn split_edges(
        &mut self,
        splits: HashMap<(u32, u32), Vec<u32>>,
    ) -> HashMap<(u32, u32), Vec<u32>> {
        let mut chains: HashMap<(u32, u32), Vec<u32>> = HashMap::new();
        for ((a, b), mut vs) in splits {
            vs.retain(|&v| v != a && v != b);
            vs.sort_unstable();
            vs.dedup();
            if vs.is_empty() {
                continue;
            }
            let (pa, pb) = (self.pos[a as usize], self.pos[b as usize]);
            let mut keyed: Vec<(f64, u32)> = vs
                .iter()
                .map(|&v| (projection(self.pos[v as usize], pa, pb), v))
                .collect();
            keyed.sort_by(|x, y| x.0.total_cmp(&y.0).then(x.1.cmp(&y.1)));
            chains.insert((a, b), keyed.into_iter().map(|(_, v)| v).collect());
        }
        if chains.is_empty() {
            return chains;
        }
        for (f, changed) in self.facets.iter_mut().zip(self.changed.iter_mut()) {
            if !f.iter().any(|&h| chains.contains_key(&edge_key(h))) {
                continue;
            }
            *changed = true;
            let mut out = Vec::with_capacity(f.len() + 4);
            for &h in f.iter() {
                match chains.get(&edge_key(h)) {
                    None => out.push(h),
                    Some(chain) => {
                        let mut prev = h.start;
                        let mut push = |v: u32| {
                            out.push(HalfEdge {
                                start: prev,
                                end: v,
                            });
                            prev = v;
                        };
                        if h.start < h.end {
                            chain.iter().for_each(|&v| push(v));
                        } else {
                            chain.iter().rev().for_each(|&v| push(v));
                        }
                        push(h.end);
                    }
                }
            }
            *f = out;
        }
        chains
    }

    /// Facet and shape boundary closure and the index range (section 4.2):
    /// the closure check run after every pass in debug builds.
    pub fn check_closure(&self, stage: &str) -> Result<(), SmoothError> {
        let mesh = PolygonMesh::new(
            self.pos.clone(),
            self.facets
                .iter()
                .map(|f| Facet {
                    half_edges: f.clone(),
                })
                .collect(),
        );
        mesh.check_topology()
            .map_err(|e| SmoothError::Internal(format!("after {stage}: {e}")))
    }

    /// The final shape: empty facets and unreferenced vertices dropped
    /// (counted), changed facets' half-edges put in loop order. Returns the
    /// mesh and, for every working vertex, its index in the mesh.
    pub fn compact(&self) -> (PolygonMesh, Vec<Option<u32>>, u64, u64) {
        let referenced = self.referenced();
        let mut map = vec![None; self.pos.len()];
        let mut vertices = Vec::new();
        let mut unreferenced = 0;
        for (i, &r) in referenced.iter().enumerate() {
            // Created vertices are never counted as removed input.
            if r {
                map[i] = Some(vertices.len() as u32);
                vertices.push(self.pos[i]);
            } else if matches!(self.origin[i], Origin::Input(_))
                && self.representative.get(i) == Some(&(i as u32))
            {
                unreferenced += 1;
            }
        }
        let mut facets = Vec::new();
        let mut empty = 0;
        for (f, &changed) in self.facets.iter().zip(&self.changed) {
            if f.is_empty() {
                empty += 1;
                continue;
            }
            let renamed: Vec<HalfEdge> = f
                .iter()
                .map(|h| HalfEdge {
                    start: map[h.start as usize].unwrap_or(u32::MAX),
                    end: map[h.end as usize].unwrap_or(u32::MAX),
                })
                .collect();
            let facet = Facet {
                half_edges: renamed,
            };
            if changed {
                facets.push(Facet::from_loops(&facet.loops_in_plane(&vertices)));
            } else {
                facets.push(facet);
            }
        }
        (PolygonMesh::new(vertices, facets), map, unreferenced, empty)
    }
}
