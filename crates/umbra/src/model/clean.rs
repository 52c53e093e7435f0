//! The clean-up of a Boolean's result before it feeds the next Boolean of
//! a CSG tree.
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
//! The clean-up is data smoothing (Appendix A) only near the Boolean's
//! contacts, at the rounding tolerance `16 u L` (`u` the unit roundoff,
//! `L` the largest coordinate magnitude): vertices at one position are
//! merged, edges are cracked at vertices on them, zero-length edges,
//! empty and opposite coincident facets (the touching faces of parts
//! united face to face) are removed. At tolerance 0 the merges alone
//! happen: the facets' fitted planes put exactly coplanar points a few
//! roundings away, so touching faces would stay, joined at merged
//! vertices into non-manifold edges. No point moves by more than that
//! tolerance, below the error bound of the Boolean's own intersection
//! points (`sqrt(153) u L`, section 8.3), so the solid is the same up to
//! the Boolean's rounding, and smoothing keeps the closure constraints of
//! section 4.2. It runs only when the result has two vertices at one
//! position, which a Boolean without such coincidences never leaves; the
//! check is one hashing pass over the vertices.

use super::eval::Solid;
use crate::round_f32::coincident_pairs;
use crate::{smooth_mesh_near, smooth_triangles_near, SmoothOptions};
use robust_arith::Point3;
use topology::{PolygonMesh, TriangleMesh};

/// Whether a triangle has a corner twice.
fn triangles_repeat_a_corner(mesh: &TriangleMesh) -> bool {
    mesh.triangles
        .iter()
        .any(|&[a, b, c]| a == b || b == c || c == a)
}

/// Whether a half-edge runs from a vertex to itself.
fn polygons_have_a_loop(mesh: &PolygonMesh) -> bool {
    mesh.facets
        .iter()
        .flat_map(|f| f.half_edges.iter())
        .any(|h| h.start == h.end)
}

/// Whether `solid` has two vertices at one position or an edge from a
/// vertex to itself: what the clean-up removes. Degenerate contacts leave
/// both: coincident vertices joined by zero-length edges where a vertex
/// lies on the other operand's edge or facet, and unjoined ones where
/// facets touch (parts sharing a face come out of a union as two shells,
/// the touching faces kept).
pub(super) fn needs_cleaning(solid: &Solid) -> bool {
    match solid {
        Solid::Poly(m) => coincident_pairs(&m.vertices) > 0 || polygons_have_a_loop(m),
        Solid::Tri(m) => coincident_pairs(&m.vertices) > 0 || triangles_repeat_a_corner(m),
    }
}

/// The clean-up's tolerance for coordinates of magnitude at most `max`:
/// `16 u max` (`u` the unit roundoff), below the error bound of the
/// Boolean's own intersection points (`sqrt(153) u L`, section 8.3) when
/// `L` is the least power of two at least `max`.
fn rounding_tolerance(max: f64) -> f64 {
    let t = 8.0 * f64::EPSILON * max;
    if t.is_finite() {
        t
    } else {
        0.0
    }
}

/// `solid` smoothed near `contacts` at the rounding tolerance
/// ([`rounding_tolerance`], module docs), or `None` when smoothing refused
/// it (the raw result then goes on: it is a valid operand as it is).
pub(super) fn cleaned(solid: &Solid, contacts: &[[Point3; 2]]) -> Option<Solid> {
    let bounds = match solid {
        Solid::Poly(m) => m.bounding_box(),
        Solid::Tri(m) => m.bounding_box(),
    };
    let max = bounds.map_or(0.0, |[lo, hi]| {
        lo.iter().chain(&hi).fold(0.0f64, |m, &x| m.max(x.abs()))
    });
    let exact = SmoothOptions::new(rounding_tolerance(max));
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
    fn coincident_vertices_and_loops_are_found() {
        let mut t = TriangleMesh {
            vertices: vec![[0.0; 3], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]],
            triangles: vec![[0, 1, 2]],
        };
        assert!(!needs_cleaning(&Solid::Tri(t.clone())));
        // A second vertex at a position, joined to nothing: found.
        t.vertices.push([1.0, 0.0, 0.0]);
        assert!(needs_cleaning(&Solid::Tri(t.clone())));
        // -0.0 and 0.0 are one coordinate.
        t.vertices[3] = [-0.0, 0.0, 0.0];
        assert!(needs_cleaning(&Solid::Tri(t.clone())));
        t.vertices[3] = [0.5, 0.5, 0.0];
        assert!(!needs_cleaning(&Solid::Tri(t.clone())));
        t.triangles.push([1, 1, 2]);
        assert!(needs_cleaning(&Solid::Tri(t.clone())));
        let mut p = PolygonMesh {
            vertices: t.vertices.clone(),
            facets: vec![Facet::from_loop(&[0, 1, 2])],
        };
        assert!(!needs_cleaning(&Solid::Poly(p.clone())));
        p.facets.push(Facet::from_loop(&[0, 3, 3, 2]));
        assert!(needs_cleaning(&Solid::Poly(p)));
    }
}
