//! The flat internal form of an operand: half-edges grouped by facet and by
//! edge (section 4.2: an edge groups the half-edges joining the same two
//! vertices in either order), with the bounding boxes of the broad phase.

use crate::bvh::Aabb;
use rayon::prelude::*;
use robust_arith::Point3;
use std::sync::OnceLock;
use topology::{PolygonMesh, TopologyError, TriangleMesh};

/// Half-edges facet by facet and the facets' offsets into them.
pub(crate) type FacetHalfEdges = (Vec<(u32, u32)>, Vec<u32>);

/// The half-edges of a flat form, facet by facet.
#[derive(Debug, PartialEq)]
enum HalfEdges<'a> {
    /// Owned half-edges (polygon meshes, merged facets):
    /// `facet_off[f]..facet_off[f + 1]` are the half-edges of facet `f`.
    Owned {
        he: Vec<(u32, u32)>,
        facet_off: Vec<u32>,
    },
    /// A triangle mesh's triangles, read in place (the caller's array, so
    /// a triangle operand's half-edges cost no memory): triangle `[a, b,
    /// c]` is facet `t` with half-edges `3t, 3t + 1, 3t + 2` =
    /// `a->b, b->c, c->a`.
    Triangles(&'a [[u32; 3]]),
}

impl HalfEdges<'_> {
    /// The number of half-edges.
    #[inline]
    fn len(&self) -> usize {
        match self {
            HalfEdges::Owned { he, .. } => he.len(),
            HalfEdges::Triangles(t) => 3 * t.len(),
        }
    }

    /// Half-edge `h` as `(start, end)`.
    #[inline]
    fn get(&self, h: usize) -> (u32, u32) {
        match self {
            HalfEdges::Owned { he, .. } => he[h],
            HalfEdges::Triangles(t) => {
                let tri = &t[h / 3];
                match h % 3 {
                    0 => (tri[0], tri[1]),
                    1 => (tri[1], tri[2]),
                    _ => (tri[2], tri[0]),
                }
            }
        }
    }

    /// Calls `f(h, start, end)` for every half-edge in order (triangles
    /// read without dividing the index).
    #[inline]
    fn for_each(&self, mut f: impl FnMut(usize, u32, u32)) {
        match self {
            HalfEdges::Owned { he, .. } => {
                for (h, &(s, e)) in he.iter().enumerate() {
                    f(h, s, e);
                }
            }
            HalfEdges::Triangles(t) => {
                for (i, tri) in t.iter().enumerate() {
                    f(3 * i, tri[0], tri[1]);
                    f(3 * i + 1, tri[1], tri[2]);
                    f(3 * i + 2, tri[2], tri[0]);
                }
            }
        }
    }

    /// The facet holding half-edge `h`.
    #[inline]
    fn facet_of(&self, h: usize) -> usize {
        match self {
            HalfEdges::Owned { facet_off, .. } => {
                facet_off.partition_point(|&o| o as usize <= h) - 1
            }
            HalfEdges::Triangles(_) => h / 3,
        }
    }
}

/// One operand in compressed-row form. Indices are `u32` as in `topology`.
#[derive(Debug, PartialEq)]
pub(crate) struct Flat<'a> {
    /// Vertex positions (borrowed from the caller's mesh).
    pub pos: &'a [Point3],
    /// Half-edges `(start, end)`, facet by facet ([`Flat::he`]).
    half_edges: HalfEdges<'a>,
    /// The edge of each half-edge.
    pub he_edge: Vec<u32>,
    /// Whether each vertex is referenced by some half-edge.
    pub referenced: Vec<bool>,
    /// The edges `(start, end)` with `start <= end` (vertex indices): the
    /// forward direction of an edge runs from the lower index to the higher.
    pub edges: Vec<(u32, u32)>,
    /// `edge_off[e]..edge_off[e + 1]` index `edge_he`: the half-edges of
    /// `e`; `None` when every edge has exactly two (those of `e` are then
    /// `2e, 2e + 1`: a closed two-manifold, the usual operand), which
    /// saves the array.
    edge_off: Option<Vec<u32>>,
    /// Half-edge indices grouped by edge.
    pub edge_he: Vec<u32>,
    /// The largest coordinate magnitude of `pos`, computed on first use
    /// ([`Flat::max_abs`]).
    max_abs: Cached,
}

/// A value derived from the flat form's points, computed on first use. It
/// takes no part in comparisons: two flat forms with equal points derive
/// equal values, whether computed yet or not.
#[derive(Clone, Debug, Default)]
struct Cached(OnceLock<f64>);

impl PartialEq for Cached {
    fn eq(&self, _: &Cached) -> bool {
        true
    }
}

/// The largest coordinate magnitude of the points (0 for none): three
/// independent running maxima by plain comparisons (a NaN is never taken,
/// as with `f64::max`).
pub(crate) fn max_abs(points: &[Point3]) -> f64 {
    let mut m = [0.0f64; 3];
    for p in points {
        for c in 0..3 {
            let a = p[c].abs();
            if a > m[c] {
                m[c] = a;
            }
        }
    }
    m[0].max(m[1]).max(m[2])
}

/// The direction bit of a half-edge running from its edge's lower vertex
/// to its higher (`dirs` in [`Flat::build`]; the next bit is the other
/// way).
const FORWARD: u8 = 1;

/// Sorts one bucket of `(higher << 32 | half-edge)` keys, carrying each
/// key's direction byte along: an insertion sort, the buckets being a
/// vertex's few edges (a general sort beyond 32).
fn sort_bucket(keys: &mut [u64], dirs: &mut [u8]) {
    if keys.len() > 32 {
        let mut both: Vec<(u64, u8)> = keys.iter().copied().zip(dirs.iter().copied()).collect();
        both.sort_unstable_by_key(|&(k, _)| k);
        for (i, (k, d)) in both.into_iter().enumerate() {
            keys[i] = k;
            dirs[i] = d;
        }
        return;
    }
    for i in 1..keys.len() {
        let (k, d) = (keys[i], dirs[i]);
        let mut j = i;
        while j > 0 && keys[j - 1] > k {
            keys[j] = keys[j - 1];
            dirs[j] = dirs[j - 1];
            j -= 1;
        }
        keys[j] = k;
        dirs[j] = d;
    }
}

/// `Some(edge_off)` unless every edge has exactly two half-edges.
fn edge_offsets(edge_off: Vec<u32>) -> Option<Vec<u32>> {
    let pairs = edge_off
        .iter()
        .enumerate()
        .all(|(e, &o)| o as usize == 2 * e);
    (!pairs).then_some(edge_off)
}

impl<'a> Flat<'a> {
    /// The flat form of a polygon mesh, checking the data definitions and
    /// topological constraints of section 4.2 on the way (the same checks,
    /// and the same first violation reported, as
    /// `PolygonMesh::check_topology`, in linear time).
    pub fn from_polygon_mesh(m: &'a PolygonMesh) -> Result<Self, TopologyError> {
        let mut he = Vec::with_capacity(m.half_edge_count());
        let mut facet_off = Vec::with_capacity(m.facets.len() + 1);
        facet_off.push(0u32);
        // The caller has checked that the counts fit in u32.
        for f in &m.facets {
            he.extend(f.half_edges.iter().map(|h| (h.start, h.end)));
            facet_off.push(he.len() as u32);
        }
        Self::build(&m.vertices, HalfEdges::Owned { he, facet_off }, "facet")
    }

    /// The flat form of a triangle mesh, checked like
    /// `TriangleMesh::check_topology`: triangle `[a, b, c]` has half-edges
    /// `a->b, b->c, c->a`, read from the mesh in place.
    pub fn from_triangle_mesh(m: &'a TriangleMesh) -> Result<Self, TopologyError> {
        Self::build(&m.vertices, HalfEdges::Triangles(&m.triangles), "triangle")
    }

    /// The flat form of facets built by the coplanar merge from a
    /// validated triangle mesh (closed by construction, see `merge`).
    pub fn from_merged(
        pos: &'a [Point3],
        he: Vec<(u32, u32)>,
        facet_off: Vec<u32>,
    ) -> Result<Self, TopologyError> {
        Self::build(pos, HalfEdges::Owned { he, facet_off }, "merged facet")
    }

    /// The flat form of a subset of `parent`'s half-edges (`old[i]` is the
    /// parent index of half-edge `i`) in which every edge of `parent`
    /// keeps all of its half-edges or none (the coplanar merge removes
    /// whole edges). The edge grouping is derived from the parent's
    /// without sorting again, and equals what [`Flat::from_merged`]
    /// builds: edges in (lower, higher) order, an edge's half-edges by
    /// index. When some edge keeps only part of its half-edges, the
    /// half-edges and offsets are handed back.
    pub fn from_subset(
        parent: &Flat<'a>,
        he: Vec<(u32, u32)>,
        facet_off: Vec<u32>,
        old: &[u32],
    ) -> Result<Self, FacetHalfEdges> {
        let mut new_of = vec![u32::MAX; parent.he_count()];
        for (i, &o) in old.iter().enumerate() {
            new_of[o as usize] = i as u32;
        }
        // A vertex is referenced when some kept edge ends at it.
        let mut referenced = vec![false; parent.pos.len()];
        let mut edges = Vec::with_capacity(he.len() / 2 + 1);
        let mut edge_off = Vec::with_capacity(he.len() / 2 + 2);
        let mut edge_he: Vec<u32> = Vec::with_capacity(he.len());
        let mut he_edge = vec![0u32; he.len()];
        for (e, &key) in parent.edges.iter().enumerate() {
            let hs = parent.edge_half_edges(e as u32);
            let kept = hs
                .iter()
                .filter(|&&h| new_of[h as usize] != u32::MAX)
                .count();
            if kept == 0 {
                continue;
            }
            if kept != hs.len() {
                return Err((he, facet_off));
            }
            let ne = edges.len() as u32;
            edges.push(key);
            referenced[key.0 as usize] = true;
            referenced[key.1 as usize] = true;
            let start = edge_he.len();
            edge_off.push(start as u32);
            for &h in hs {
                let n = new_of[h as usize];
                he_edge[n as usize] = ne;
                edge_he.push(n);
            }
            let group = &mut edge_he[start..];
            if group.len() == 2 {
                if group[0] > group[1] {
                    group.swap(0, 1);
                }
            } else {
                group.sort_unstable();
            }
        }
        edge_off.push(edge_he.len() as u32);
        if edge_he.len() != he.len() {
            return Err((he, facet_off));
        }
        Ok(Flat {
            pos: parent.pos,
            half_edges: HalfEdges::Owned { he, facet_off },
            he_edge,
            referenced,
            edges,
            edge_off: edge_offsets(edge_off),
            edge_he,
            max_abs: parent.max_abs.clone(),
        })
    }

    fn build(
        pos: &'a [Point3],
        half_edges: HalfEdges<'a>,
        entity: &'static str,
    ) -> Result<Self, TopologyError> {
        let n_he = half_edges.len();
        let n_v = pos.len();
        let he = |h: usize| half_edges.get(h);
        // Data definitions: every index refers to a vertex.
        let vertex_count = n_v as u32;
        let mut max_index = 0u32;
        half_edges.for_each(|_, s, e| max_index = max_index.max(s).max(e));
        // The first half-edge in facet order with a dangling index names
        // the facet; its start is checked before its end.
        if n_he > 0 && max_index as usize >= n_v {
            if let Some(h) = (0..n_he).position(|h| {
                let (s, e) = he(h);
                s as usize >= n_v || e as usize >= n_v
            }) {
                let f = half_edges.facet_of(h);
                let (s, e) = he(h);
                return Err(TopologyError::DanglingIndex {
                    entity,
                    entity_index: f as u32,
                    vertex: if s as usize >= n_v { s } else { e },
                    vertex_count,
                });
            }
        }
        // Facet boundary closure (triangles satisfy it by construction).
        if let HalfEdges::Owned { he, facet_off } = &half_edges {
            if entity == "facet" {
                check_facet_closure(he, facet_off)?;
            }
        }
        // Group half-edges into edges by their unordered vertex pair: a
        // counting sort by the lower vertex, then a sort of each (small)
        // bucket by the higher vertex and half-edge index (one u64 key,
        // `higher << 32 | half-edge`, whose order is that pair's). The edge
        // numbering, by (lower, higher), is independent of thread count.
        let mut referenced = vec![false; n_v];
        let mut bucket = vec![0u32; n_v + 1];
        half_edges.for_each(|_, s, e| {
            referenced[s as usize] = true;
            referenced[e as usize] = true;
            bucket[s.min(e) as usize + 1] += 1;
        });
        for v in 0..n_v {
            bucket[v + 1] += bucket[v];
        }
        let mut fill = bucket.clone();
        // (higher vertex, half-edge) scattered by lower vertex, with each
        // half-edge's direction beside it (`FORWARD` from the lower vertex,
        // `BACKWARD`, or neither for a loop), so that the grouping below
        // reads no half-edge again.
        let mut pairs = vec![0u64; n_he];
        let mut dirs = vec![0u8; n_he];
        half_edges.for_each(|h, s, e| {
            let (lo, hi) = if s <= e { (s, e) } else { (e, s) };
            let k = fill[lo as usize] as usize;
            pairs[k] = (u64::from(hi) << 32) | h as u64;
            dirs[k] = u8::from(s < e) | (u8::from(s > e) << 1);
            fill[lo as usize] += 1;
        });
        drop(fill);
        let mut edges = Vec::with_capacity(n_he / 2 + 1);
        // Edge offsets only from the first edge without exactly two
        // half-edges on (every earlier edge `i` starts at `2 i`).
        let mut edge_off: Option<Vec<u32>> = None;
        let mut he_edge = vec![0u32; n_he];
        for v in 0..n_v {
            let (b0, b1) = (bucket[v] as usize, bucket[v + 1] as usize);
            sort_bucket(&mut pairs[b0..b1], &mut dirs[b0..b1]);
            let mut k = b0;
            while k < b1 {
                let hi = (pairs[k] >> 32) as u32;
                let e = edges.len() as u32;
                edges.push((v as u32, hi));
                let start = k;
                // Shape boundary closure: as many half-edges each way.
                let (mut forward, mut backward) = (0u32, 0u32);
                while k < b1 && (pairs[k] >> 32) as u32 == hi {
                    he_edge[pairs[k] as u32 as usize] = e;
                    forward += u32::from(dirs[k] & FORWARD);
                    backward += u32::from(dirs[k] >> 1);
                    k += 1;
                }
                check_shape_closure((v as u32, hi), (forward, backward))?;
                match edge_off.as_mut() {
                    Some(off) => off.push(start as u32),
                    None if k - start != 2 => {
                        let mut off = Vec::with_capacity(n_he / 2 + 2);
                        off.extend((0..=e).map(|i| 2 * i));
                        edge_off = Some(off);
                    }
                    None => {}
                }
            }
        }
        drop(dirs);
        if let Some(off) = edge_off.as_mut() {
            off.push(n_he as u32);
        }
        // A fresh allocation: collecting in place would keep the pairs'
        // buffer, twice the size needed, alive for the whole Boolean.
        let edge_he: Vec<u32> = pairs.iter().map(|&p| p as u32).collect();
        drop(pairs);
        Ok(Flat {
            pos,
            half_edges,
            he_edge,
            referenced,
            edges,
            edge_off,
            edge_he,
            max_abs: Cached::default(),
        })
    }

    /// The largest coordinate magnitude of the points (of all of `pos`,
    /// referenced or not), computed once.
    pub fn max_abs(&self) -> f64 {
        *self.max_abs.0.get_or_init(|| max_abs(self.pos))
    }

    /// The number of half-edges.
    #[inline]
    pub fn he_count(&self) -> usize {
        self.half_edges.len()
    }

    /// Half-edge `h` as `(start, end)`.
    #[inline]
    pub fn he(&self, h: u32) -> (u32, u32) {
        self.half_edges.get(h as usize)
    }

    /// Every half-edge, facet by facet.
    pub fn half_edges(&self) -> impl Iterator<Item = (u32, u32)> + '_ {
        (0..self.he_count() as u32).map(|h| self.he(h))
    }

    /// The half-edges and facet offsets as arrays (a triangle operand's
    /// are built from its triangles).
    pub fn to_parts(&self) -> FacetHalfEdges {
        let mut off: Vec<u32> = (0..self.facet_count() as u32)
            .map(|f| self.facet_range(f).start as u32)
            .collect();
        off.push(self.he_count() as u32);
        (self.half_edges().collect(), off)
    }

    /// The number of facets.
    pub fn facet_count(&self) -> usize {
        match &self.half_edges {
            HalfEdges::Owned { facet_off, .. } => facet_off.len() - 1,
            HalfEdges::Triangles(t) => t.len(),
        }
    }

    /// The half-edge index range of facet `f`.
    #[inline]
    pub fn facet_range(&self, f: u32) -> std::ops::Range<usize> {
        match &self.half_edges {
            HalfEdges::Owned { facet_off, .. } => {
                facet_off[f as usize] as usize..facet_off[f as usize + 1] as usize
            }
            HalfEdges::Triangles(_) => 3 * f as usize..3 * f as usize + 3,
        }
    }

    /// The half-edges of facet `f`.
    #[inline]
    pub fn facet_half_edges(&self, f: u32) -> impl Iterator<Item = (u32, u32)> + Clone + '_ {
        self.facet_range(f).map(|h| self.half_edges.get(h))
    }

    /// The half-edges of facet `f` as point pairs (the form the level-2
    /// functions of `shadow-2d` take).
    #[inline]
    pub fn facet_points(&self, f: u32) -> impl Iterator<Item = (Point3, Point3)> + Clone + '_ {
        self.facet_half_edges(f)
            .map(|(s, e)| (self.pos[s as usize], self.pos[e as usize]))
    }

    /// The half-edges of edge `e`.
    #[inline]
    pub fn edge_half_edges(&self, e: u32) -> &[u32] {
        let e = e as usize;
        match &self.edge_off {
            Some(off) => &self.edge_he[off[e] as usize..off[e + 1] as usize],
            None => &self.edge_he[2 * e..2 * e + 2],
        }
    }

    /// The end points of edge `e` (start, end).
    #[inline]
    pub fn edge_points(&self, e: u32) -> (Point3, Point3) {
        let (s, t) = self.edges[e as usize];
        (self.pos[s as usize], self.pos[t as usize])
    }

    /// The facet holding half-edge `h`.
    #[inline]
    pub fn he_facet(&self, h: u32) -> u32 {
        self.half_edges.facet_of(h as usize) as u32
    }

    /// Whether half-edge `h` is a forward half-edge of its edge (section
    /// 4.2); zero-length half-edges count as forward.
    #[inline]
    pub fn he_fwd(&self, h: u32) -> bool {
        let (s, e) = self.he(h);
        s <= e
    }

    /// The closed bounding box of every facet, widened by `margin` in y and
    /// z.
    pub fn facet_boxes(&self, margin: f64) -> Vec<Aabb> {
        // Exact bounds first (by facet closure every end is also a start),
        // widened, then rounded outwards once.
        fn bound(pos: &[Point3], starts: impl Iterator<Item = u32>, margin: f64) -> Aabb {
            let mut lo = [f64::INFINITY; 3];
            let mut hi = [f64::NEG_INFINITY; 3];
            for s in starts {
                let p = &pos[s as usize];
                // Plain comparisons: the coordinates are finite.
                for c in 0..3 {
                    if p[c] < lo[c] {
                        lo[c] = p[c];
                    }
                    if p[c] > hi[c] {
                        hi[c] = p[c];
                    }
                }
            }
            if lo[0] > hi[0] {
                Aabb::EMPTY
            } else {
                // The safety margin in y and z (see `level3`).
                for c in 1..3 {
                    lo[c] -= margin;
                    hi[c] += margin;
                }
                Aabb::new(lo, hi)
            }
        }
        if let HalfEdges::Triangles(t) = &self.half_edges {
            // A triangle's corners straight from the caller's array: no
            // half-edge to decode, no offsets to read.
            return t
                .par_iter()
                .with_min_len(crate::par::min_len(1))
                .map(|t| bound(self.pos, t.iter().copied(), margin))
                .collect();
        }
        (0..self.facet_count() as u32)
            .into_par_iter()
            .with_min_len(crate::par::min_len(1))
            .map(|f| bound(self.pos, self.facet_half_edges(f).map(|h| h.0), margin))
            .collect()
    }
}

/// Shape boundary closure for one edge: as many half-edges each way.
fn check_shape_closure(
    key: (u32, u32),
    (forward, backward): (u32, u32),
) -> Result<(), TopologyError> {
    if key.0 != key.1 && forward != backward {
        return Err(TopologyError::ShapeClosure3 {
            start: key.0,
            end: key.1,
            forward,
            backward,
        });
    }
    Ok(())
}

/// Facet boundary closure of every facet: each vertex ends as many of the
/// facet's half-edges as it starts. Reports the first facet and, in it,
/// the lowest vertex that fails.
fn check_facet_closure(he: &[(u32, u32)], facet_off: &[u32]) -> Result<(), TopologyError> {
    let mut scratch: Vec<(u32, bool)> = Vec::new();
    for (f, w) in facet_off.windows(2).enumerate() {
        let hes = &he[w[0] as usize..w[1] as usize];
        if hes.len() == 3 && hes[0].1 == hes[1].0 && hes[1].1 == hes[2].0 && hes[2].1 == hes[0].0 {
            continue; // a triangle loop is closed
        }
        scratch.clear();
        for &(s, e) in hes {
            scratch.push((e, true));
            scratch.push((s, false));
        }
        scratch.sort_unstable();
        let mut i = 0;
        while i < scratch.len() {
            let v = scratch[i].0;
            let (mut ending, mut starting) = (0u32, 0u32);
            while i < scratch.len() && scratch[i].0 == v {
                if scratch[i].1 {
                    ending += 1;
                } else {
                    starting += 1;
                }
                i += 1;
            }
            if ending != starting {
                return Err(TopologyError::FacetClosure {
                    facet: f as u32,
                    vertex: v,
                    ending,
                    starting,
                });
            }
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;
    use topology::Facet;

    /// Every observable of two flat forms of the same half-edges.
    fn assert_same(a: &Flat<'_>, b: &Flat<'_>) {
        assert_eq!(a.to_parts(), b.to_parts());
        assert_eq!(a.facet_count(), b.facet_count());
        assert_eq!(a.he_edge, b.he_edge);
        assert_eq!(a.referenced, b.referenced);
        assert_eq!(a.edges, b.edges);
        assert_eq!(a.edge_he, b.edge_he);
        assert_eq!(a.edge_off, b.edge_off);
        for e in 0..a.edges.len() as u32 {
            assert_eq!(a.edge_half_edges(e), b.edge_half_edges(e));
        }
        for h in 0..a.he_count() as u32 {
            assert_eq!(a.he(h), b.he(h));
            assert_eq!(a.he_facet(h), b.he_facet(h));
            assert_eq!(a.he_fwd(h), b.he_fwd(h));
        }
        for f in 0..a.facet_count() as u32 {
            assert_eq!(a.facet_range(f), b.facet_range(f));
            assert!(a.facet_points(f).eq(b.facet_points(f)));
        }
    }

    /// The edge grouping's definition, checked directly: edges in strictly
    /// increasing (lower, higher) order, each edge's half-edges in
    /// increasing index order with that unordered vertex pair, every
    /// half-edge in exactly one edge, and `referenced` exactly the vertices
    /// some half-edge touches.
    fn assert_grouping(flat: &Flat<'_>) {
        assert!(flat.edges.windows(2).all(|w| w[0] < w[1]));
        let mut seen = vec![false; flat.he_count()];
        for (e, &(lo, hi)) in flat.edges.iter().enumerate() {
            assert!(lo <= hi);
            let hs = flat.edge_half_edges(e as u32);
            assert!(!hs.is_empty() && hs.windows(2).all(|w| w[0] < w[1]));
            for &h in hs {
                let (s, t) = flat.he(h);
                assert_eq!((s.min(t), s.max(t)), (lo, hi));
                assert_eq!(flat.he_edge[h as usize], e as u32);
                assert!(!std::mem::replace(&mut seen[h as usize], true));
            }
        }
        assert!(seen.iter().all(|&s| s));
        let mut touched = vec![false; flat.pos.len()];
        for (s, t) in flat.half_edges() {
            touched[s as usize] = true;
            touched[t as usize] = true;
        }
        assert_eq!(touched, flat.referenced);
    }

    #[test]
    fn a_vertex_of_high_valence_groups_its_edges() {
        // A closed double cone over a 70-gon: the apexes have 70 edges
        // each (the general sort of a bucket), the rim vertices 4.
        let n = 70u32;
        let mut v: Vec<Point3> = (0..n)
            .map(|i| {
                let a = f64::from(i) * std::f64::consts::TAU / f64::from(n);
                [a.cos(), a.sin(), 0.0]
            })
            .collect();
        v.push([0.0, 0.0, 1.0]);
        v.push([0.0, 0.0, -1.0]);
        // Triangles in a scrambled order, so the buckets arrive unsorted.
        let mut t: Vec<[u32; 3]> = (0..n)
            .flat_map(|i| [[i, (i + 1) % n, n], [(i + 1) % n, i, n + 1]])
            .collect();
        t.reverse();
        t.swap(3, 90);
        let m = TriangleMesh::new(v, t);
        let flat = Flat::from_triangle_mesh(&m).unwrap();
        assert_grouping(&flat);
        assert_eq!(flat.edges.len(), 3 * n as usize);
        assert!(flat.edge_off.is_none());
        assert_eq!(m.check_topology(), Ok(()));
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(test_support::cases(256)))]

        /// The running maxima equal the plain fold of `f64::max` over
        /// every coordinate's magnitude, and the cached value is that.
        #[test]
        fn max_abs_is_the_largest_magnitude(
            pts in prop::collection::vec([-1e6f64..1e6, -1e300f64..1e300, -1e-300f64..1e-300], 0..40),
        ) {
            let fold = pts.iter().flatten().fold(0.0f64, |m, &c| m.max(c.abs()));
            prop_assert_eq!(max_abs(&pts), fold);
            let m = TriangleMesh::new(pts.clone(), Vec::new());
            let flat = Flat::from_triangle_mesh(&m).unwrap();
            prop_assert_eq!(flat.max_abs(), fold);
            prop_assert_eq!(flat.max_abs(), fold);
        }

        /// The bucket sort carries each key's direction along and orders
        /// like a plain sort, below and above the insertion-sort length.
        #[test]
        fn sort_bucket_is_a_sort(keys in prop::collection::vec(0u64..40, 0..80)) {
            let mut k = keys.clone();
            let mut d: Vec<u8> = keys.iter().map(|&x| (x % 3) as u8).collect();
            sort_bucket(&mut k, &mut d);
            let mut expect = keys.clone();
            expect.sort_unstable();
            prop_assert_eq!(&k, &expect);
            prop_assert!(k.iter().zip(&d).all(|(&x, &y)| (x % 3) as u8 == y));
        }
    }

    fn as_polygons(m: &TriangleMesh) -> PolygonMesh {
        let facets = m.triangles.iter().map(|t| Facet::from_loop(t)).collect();
        PolygonMesh::new(m.vertices.clone(), facets)
    }

    #[test]
    fn a_closed_two_manifold_needs_no_edge_offsets() {
        let m = test_support::shapes::box_triangles([0.0; 3], [1.0; 3]);
        let flat = Flat::from_triangle_mesh(&m).unwrap();
        assert!(flat.edge_off.is_none());
        assert_eq!(flat.edges.len(), 18);
        assert_same(&flat, &Flat::from_polygon_mesh(&as_polygons(&m)).unwrap());
        // Two boxes sharing an edge: four half-edges on it.
        let mut t = m.triangles.clone();
        let mut v = m.vertices.clone();
        let shifted = test_support::shapes::box_triangles([1.0, 1.0, 0.0], [2.0, 2.0, 1.0]);
        v.extend(&shifted.vertices);
        t.extend(shifted.triangles.iter().map(|t| t.map(|i| i + 8)));
        let mut two = TriangleMesh::new(v, t);
        // Weld the shared edge (x = y = 1).
        let weld: Vec<u32> = (0..two.vertices.len() as u32)
            .map(|i| {
                (0..i)
                    .find(|&j| two.vertices[j as usize] == two.vertices[i as usize])
                    .unwrap_or(i)
            })
            .collect();
        for t in &mut two.triangles {
            *t = t.map(|i| weld[i as usize]);
        }
        let flat = Flat::from_triangle_mesh(&two).unwrap();
        assert!(flat.edge_off.is_some());
        assert!((0..flat.edges.len() as u32).any(|e| flat.edge_half_edges(e).len() == 4));
        assert_same(&flat, &Flat::from_polygon_mesh(&as_polygons(&two)).unwrap());
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(test_support::cases(256)))]

        /// A triangle operand read in place gives the same flat form as
        /// the same triangles copied as polygon facets, and the same first
        /// violation, on random soups (degenerate, non-manifold, open).
        #[test]
        fn triangles_in_place_equal_copied_facets(
            n_v in 1u32..7,
            tris in prop::collection::vec([0u32..7, 0u32..7, 0u32..7], 0..14),
            closed in any::<bool>(),
        ) {
            let tris: Vec<[u32; 3]> = tris.into_iter().map(|t| t.map(|i| i % n_v)).collect();
            // Half of the cases closed by adding every triangle reversed.
            let tris: Vec<[u32; 3]> = if closed {
                tris.iter().flat_map(|&[a, b, c]| [[a, b, c], [a, c, b]]).collect()
            } else {
                tris
            };
            let vertices = (0..n_v).map(|i| [f64::from(i), f64::from(i * i), 1.0]).collect();
            let m = TriangleMesh::new(vertices, tris);
            let poly = as_polygons(&m);
            match (Flat::from_triangle_mesh(&m), Flat::from_polygon_mesh(&poly)) {
                (Ok(a), Ok(b)) => {
                    assert_grouping(&a);
                    assert_same(&a, &b);
                    prop_assert_eq!(m.check_topology(), Ok(()));
                }
                (Err(a), Err(b)) => {
                    prop_assert_eq!(m.check_topology(), Err(a.clone()));
                    prop_assert_eq!(a, b);
                }
                (a, b) => prop_assert!(false, "{:?} against {:?}", a.err(), b.err()),
            }
        }
    }
}
