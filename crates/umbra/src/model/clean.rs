//! The exact clean-up of a Boolean's result before it feeds the next
//! Boolean of a CSG tree.
//!
//! Where the operands of a Boolean meet in a degenerate way (a vertex on
//! the other's facet, an edge through the other's edge, coplanar facets:
//! the common case of parts placed on each other's corners, faces or
//! axes), symbolic perturbation (eq. 4.1) makes the coincident points
//! distinct, so the raw output holds several vertices at one position
//! joined by zero-length edges, and in the triangle variant zero-area
//! triangles between them. The output is topologically valid and encloses
//! the right region, but fed to the next Boolean that structure is cut
//! and re-triangulated again, and over a chain it grows with every step
//! (a cube whose corners are carved by 40 spheres, one at a time: 1,866
//! triangles against the 524 of the shape).
//!
//! The clean-up is data smoothing (Appendix A) at tolerance 0, only near
//! the Boolean's contacts: vertices at one position are merged, edges are
//! cracked at vertices exactly on them, zero-length edges, empty and
//! opposite coincident facets are removed. No point moves (the distortion
//! bound is 0), so the shape is the same point set, and smoothing keeps
//! the closure constraints of section 4.2. It runs only when the result
//! has a zero-length edge, which a Boolean without such coincidences never
//! leaves; the check is one pass over the facets.

use super::eval::Solid;
use crate::{smooth_mesh_near, smooth_triangles_near, SmoothOptions};
use robust_arith::Point3;
use topology::{PolygonMesh, TriangleMesh};

/// Whether vertices `a` and `b` of `vertices` lie at one position (an
/// index past the vertices is at none).
fn same_position(vertices: &[Point3], a: u32, b: u32) -> bool {
    match (vertices.get(a as usize), vertices.get(b as usize)) {
        (Some(p), Some(q)) => p == q,
        _ => false,
    }
}

/// Whether a triangle has two corners at one position.
fn triangles_have_zero_length_edge(mesh: &TriangleMesh) -> bool {
    let same = |a, b| same_position(&mesh.vertices, a, b);
    mesh.triangles
        .iter()
        .any(|&[a, b, c]| same(a, b) || same(b, c) || same(c, a))
}

/// Whether a half-edge runs between two vertices at one position.
fn polygons_have_zero_length_edge(mesh: &PolygonMesh) -> bool {
    mesh.facets
        .iter()
        .flat_map(|f| f.half_edges.iter())
        .any(|h| same_position(&mesh.vertices, h.start, h.end))
}

/// Whether `solid` has an edge of length zero: what the clean-up removes.
pub(super) fn needs_cleaning(solid: &Solid) -> bool {
    match solid {
        Solid::Poly(m) => polygons_have_zero_length_edge(m),
        Solid::Tri(m) => triangles_have_zero_length_edge(m),
    }
}

/// `solid` smoothed at tolerance 0 near `contacts` (module docs), or
/// `None` when smoothing refused it (the raw result then goes on: it is a
/// valid operand as it is).
pub(super) fn cleaned(solid: &Solid, contacts: &[[Point3; 2]]) -> Option<Solid> {
    let exact = SmoothOptions::new(0.0);
    match solid {
        Solid::Poly(m) => smooth_mesh_near(m, &exact, contacts)
            .ok()
            .map(|s| Solid::Poly(s.shape)),
        Solid::Tri(m) => smooth_triangles_near(m, &exact, contacts)
            .ok()
            .map(|s| Solid::Tri(s.shape)),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use topology::Facet;

    #[test]
    fn zero_length_edges_are_found_by_position_not_by_index() {
        let mut t = TriangleMesh {
            vertices: vec![[0.0; 3], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [1.0, 0.0, 0.0]],
            triangles: vec![[0, 1, 2]],
        };
        assert!(!triangles_have_zero_length_edge(&t));
        t.triangles.push([1, 3, 2]);
        assert!(triangles_have_zero_length_edge(&t));
        // An index past the vertices is no edge of length zero.
        t.triangles = vec![[0, 9, 10]];
        assert!(!triangles_have_zero_length_edge(&t));
        let mut p = PolygonMesh {
            vertices: t.vertices.clone(),
            facets: vec![Facet::from_loop(&[0, 1, 2])],
        };
        assert!(!polygons_have_zero_length_edge(&p));
        p.facets.push(Facet::from_loop(&[0, 1, 3, 2]));
        assert!(polygons_have_zero_length_edge(&p));
    }
}
