//! `TriangleMesh`: a polyhedral shape of triangular facets (section 4.2,
//! "Triangle mesh").

use crate::mesh::check_shape_closure;
use crate::{validate_points, Facet, PolygonMesh, TopologyError};
use robust_arith::Point3;

/// A polyhedral shape as vertices and triangles. Each triangle `[a, b, c]`
/// has the half-edges `a->b`, `b->c`, `c->a` and faces the side from which
/// they run anticlockwise.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct TriangleMesh {
    /// The vertex positions.
    pub vertices: Vec<Point3>,
    /// The triangles, as vertex indices.
    pub triangles: Vec<[u32; 3]>,
}

impl TriangleMesh {
    /// A mesh from vertices and triangles (unchecked).
    pub fn new(vertices: Vec<Point3>, triangles: Vec<[u32; 3]>) -> Self {
        TriangleMesh {
            vertices,
            triangles,
        }
    }

    /// Checks the data definitions and shape boundary closure (section 4.2).
    /// The triangular facet loop constraint holds by construction.
    pub fn check_topology(&self) -> Result<(), TopologyError> {
        let n = self.vertices.len() as u32;
        for (ti, t) in self.triangles.iter().enumerate() {
            for &v in t {
                if v >= n {
                    return Err(TopologyError::DanglingIndex {
                        entity: "triangle",
                        entity_index: ti as u32,
                        vertex: v,
                        vertex_count: n,
                    });
                }
            }
        }
        check_shape_closure(
            self.triangles
                .iter()
                .flat_map(|t| [(t[0], t[1]), (t[1], t[2]), (t[2], t[0])]),
        )
    }

    /// Checks every coordinate (finite, at most `f64::MAX / 4`).
    pub fn validate_coordinates(&self) -> Result<(), TopologyError> {
        validate_points(&self.vertices)
    }

    /// The same shape as a polygon mesh with one facet per triangle.
    pub fn to_polygon_mesh(&self) -> PolygonMesh {
        PolygonMesh::new(
            self.vertices.clone(),
            self.triangles.iter().map(|t| Facet::from_loop(t)).collect(),
        )
    }

    /// The signed volume (divergence theorem, f64; positive for a closed
    /// outward-facing shape). Triangles with a dangling index are skipped.
    pub fn signed_volume(&self) -> f64 {
        let volume = self.six_times_volume([1.0; 3]) / 6.0;
        if volume.is_finite() {
            return volume;
        }
        // The products overflowed: the same sum on exactly scaled
        // coordinates, scaled back (`unit_scale.rs`).
        match crate::unit_scale::axis_scales(self.vertices.iter().copied()) {
            Some((down, up)) => {
                crate::unit_scale::scaled_back(self.six_times_volume(down) / 6.0, &up)
            }
            None => volume,
        }
    }

    /// Six times the signed volume, coordinate `k` multiplied by
    /// `scale[k]` (1, or powers of two).
    fn six_times_volume(&self, scale: [f64; 3]) -> f64 {
        let mut six = 0.0;
        for t in &self.triangles {
            let (Some(&a), Some(&b), Some(&c)) = (
                self.vertices.get(t[0] as usize),
                self.vertices.get(t[1] as usize),
                self.vertices.get(t[2] as usize),
            ) else {
                continue;
            };
            let [a, b, c] = [a, b, c].map(|p| [p[0] * scale[0], p[1] * scale[1], p[2] * scale[2]]);
            six += a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0])
                + a[2] * (b[0] * c[1] - b[1] * c[0]);
        }
        six
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The unit tetrahedron. A local copy of `test_support::shapes::tetra`:
    /// `test-support` depends on this crate, so here its meshes would be a
    /// second, foreign `TriangleMesh` type.
    fn tetra() -> TriangleMesh {
        TriangleMesh::new(
            vec![[0., 0., 0.], [1., 0., 0.], [0., 1., 0.], [0., 0., 1.]],
            vec![[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2]],
        )
    }

    #[test]
    fn tetrahedron_is_closed_with_volume_one_sixth() {
        let t = tetra();
        assert_eq!(t.check_topology(), Ok(()));
        assert_eq!(t.signed_volume(), 1.0 / 6.0);
        assert_eq!(t.to_polygon_mesh().check_topology(), Ok(()));
    }

    #[test]
    fn flipped_triangle_is_rejected() {
        let mut t = tetra();
        t.triangles[0] = [0, 1, 2];
        assert!(matches!(
            t.check_topology(),
            Err(TopologyError::ShapeClosure3 { .. })
        ));
    }

    #[test]
    fn dangling_triangle_index_is_named() {
        let mut t = tetra();
        t.triangles[3][1] = 9;
        // Measures skip it rather than panic.
        assert!(t.signed_volume().is_finite());
        assert!(!t.check().is_valid());
        assert!(matches!(
            t.check_topology(),
            Err(TopologyError::DanglingIndex {
                entity: "triangle",
                entity_index: 3,
                vertex: 9,
                ..
            })
        ));
    }
}
