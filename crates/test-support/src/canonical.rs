//! Shapes as canonical keys, to compare two results that may number their
//! vertices and order their facets differently (smoothing near contacts
//! against whole smoothing, say): every facet as the sorted list of its
//! half-edges by coordinate bits, every triangle rotated to start at its
//! least corner, both lists sorted; a polygon set's edges by coordinates.

use topology::{PolygonMesh, PolygonSet2, TriangleMesh};

/// A half-edge as the bits of its end points' coordinates.
pub type HalfEdgeKey = [[u64; 3]; 2];

/// The facets of `m`, each the sorted list of its half-edges by
/// coordinates, sorted.
pub fn mesh_facets(m: &PolygonMesh) -> Vec<Vec<HalfEdgeKey>> {
    let bits = |v: u32| m.vertices[v as usize].map(f64::to_bits);
    let mut out: Vec<Vec<HalfEdgeKey>> = m
        .facets
        .iter()
        .map(|f| {
            let mut k: Vec<HalfEdgeKey> = f
                .half_edges
                .iter()
                .map(|h| [bits(h.start), bits(h.end)])
                .collect();
            k.sort_unstable();
            k
        })
        .collect();
    out.sort_unstable();
    out
}

/// The triangles of `m` as coordinate triples (bits), each rotated to
/// start at its least corner (the same key for the same oriented
/// triangle), sorted.
pub fn triangles(m: &TriangleMesh) -> Vec<[[u64; 3]; 3]> {
    let mut v: Vec<[[u64; 3]; 3]> = m
        .triangles
        .iter()
        .map(|t| {
            let p = t.map(|i| m.vertices[i as usize].map(f64::to_bits));
            let k = (0..3).min_by_key(|&k| p[k]).unwrap_or(0);
            [p[k], p[(k + 1) % 3], p[(k + 2) % 3]]
        })
        .collect();
    v.sort_unstable();
    v
}

/// An edge of a polygon set as the bits of its end points' coordinates
/// and its multiplicity.
pub type EdgeKey = ([[u64; 2]; 2], i32);

/// The edges of a polygon set by coordinates, sorted (the vertex
/// numbering and edge order dropped).
pub fn set_edges(s: &PolygonSet2) -> Vec<EdgeKey> {
    let mut out: Vec<EdgeKey> = s
        .edges()
        .iter()
        .map(|e| {
            let (p, q) = s.edge_points(e);
            ([p.map(f64::to_bits), q.map(f64::to_bits)], e.mult)
        })
        .collect();
    out.sort_unstable();
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use topology::Facet;

    #[test]
    fn renumbering_and_reordering_keep_the_key_and_moving_changes_it() {
        let t = TriangleMesh::new(
            vec![[0.0; 3], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]],
            vec![[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2]],
        );
        // The same shape with its vertices numbered backwards and its
        // triangles reordered and rotated.
        let same = TriangleMesh::new(
            t.vertices.iter().rev().copied().collect(),
            t.triangles
                .iter()
                .rev()
                .map(|x| x.map(|v| 3 - v))
                .map(|[a, b, c]| [b, c, a])
                .collect(),
        );
        assert_eq!(triangles(&t), triangles(&same));
        // One triangle turned over is another shape.
        let mut r = t.clone();
        r.triangles[1] = [0, 3, 1];
        assert_ne!(triangles(&t), triangles(&r));
        let p = t.to_polygon_mesh();
        let mut q = same.to_polygon_mesh();
        q.facets.reverse();
        assert_eq!(mesh_facets(&p), mesh_facets(&q));
        let mut moved = p.clone();
        moved.vertices[3][2] = 2.0;
        assert_ne!(mesh_facets(&p), mesh_facets(&moved));
        let mut flipped = p.clone();
        flipped.facets[0] = Facet::from_loop(&[0, 1, 2]);
        assert_ne!(mesh_facets(&p), mesh_facets(&flipped));
    }
}
