//! A triangle mesh validated and indexed once for any number of Booleans:
//! the part of [`crate::boolean_triangles`] that depends on one operand
//! alone (validation, the flat form, the coplanar merge, the facet boxes
//! and their hierarchy) is done by [`PreparedTriangles::new`], and
//! [`boolean_prepared`] runs the rest.
//!
//! The result is the same as [`crate::boolean_triangles`]'s on the two
//! meshes, bit for bit: the boxes are widened by the margin of the larger
//! of the two operands' coordinate bounds (section 8.5), so an operand
//! prepared with a smaller bound than the other's has its broad phase
//! built again for the Boolean; a hierarchy stands where the one-call
//! Boolean would scan the boxes of a large operand against a small one,
//! and both report the same overlapping pairs.

use crate::api::{flat_triangles, triangle_result};
use crate::level3::{coordinate_bound, Broad};
use crate::merge::Merged;
use crate::mesh::Flat;
use crate::par;
use crate::{Boolean3Error, BooleanOp, Operand, TriangleOutput};
use topology::{TopologyError, TriangleMesh};

/// A triangle mesh prepared for [`boolean_prepared`]: validated like an
/// operand of [`crate::boolean_triangles`], with its edge grouping,
/// coplanar merge and broad phase built once.
pub struct PreparedTriangles<'a> {
    mesh: &'a TriangleMesh,
    merged: Merged,
    facets: Flat<'a>,
    broad: Broad,
}

impl std::fmt::Debug for PreparedTriangles<'_> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("PreparedTriangles")
            .field("triangles", &self.mesh.triangles.len())
            .field("facets", &self.facets.facet_count())
            .finish()
    }
}

impl<'a> PreparedTriangles<'a> {
    /// Validates and indexes `mesh` (the checks of
    /// [`crate::boolean_triangles`], with a violation reported as
    /// [`Boolean3Error::InvalidInput`] of operand A: a prepared mesh has
    /// no role yet). The mesh is borrowed, never changed.
    pub fn new(mesh: &'a TriangleMesh) -> Result<Self, Boolean3Error> {
        par::on_pool(3 * mesh.triangles.len(), || {
            let flat = flat_triangles(mesh, Operand::A)?;
            let (merged, facets) = Merged::new(flat).map_err(|e: TopologyError| {
                Boolean3Error::Internal(format!("coplanar merge broke closure: {e}"))
            })?;
            // Built for a large other operand; `boolean_prepared` builds it
            // again when the other's coordinates are larger.
            let broad = Broad::new(&facets, coordinate_bound(&facets), usize::MAX);
            Ok(PreparedTriangles {
                mesh,
                merged,
                facets,
                broad,
            })
        })
    }

    /// The mesh this was prepared from.
    pub fn mesh(&self) -> &'a TriangleMesh {
        self.mesh
    }
}

/// `p`'s broad phase built again for a Boolean with `other` when `other`'s
/// coordinates are larger (the margin grows with the larger bound);
/// `None` when `p`'s own serves.
fn rebuilt(p: &PreparedTriangles<'_>, other: &PreparedTriangles<'_>) -> Option<Broad> {
    let bound = p.broad.bound.max(other.broad.bound);
    (p.broad.bound < bound).then(|| Broad::new(&p.facets, bound, other.facets.facet_count()))
}

/// The Boolean `op` of two prepared triangle meshes: the same result as
/// [`crate::boolean_triangles`] on their meshes, without validating,
/// indexing and merging them again.
pub fn boolean_prepared(
    a: &PreparedTriangles<'_>,
    b: &PreparedTriangles<'_>,
    op: BooleanOp,
) -> Result<TriangleOutput, Boolean3Error> {
    crate::api::supported(op)?;
    let larger = 3 * a.mesh.triangles.len().max(b.mesh.triangles.len());
    par::on_pool(larger, || {
        let smaller = a.facets.facet_count().min(b.facets.facet_count());
        let (ra, rb) = par::join(smaller, || rebuilt(a, b), || rebuilt(b, a));
        let broad_a = ra.as_ref().unwrap_or(&a.broad);
        let broad_b = rb.as_ref().unwrap_or(&b.broad);
        triangle_result(
            [
                (a.mesh, &a.merged, &a.facets),
                (b.mesh, &b.merged, &b.facets),
            ],
            Some([broad_a, broad_b]),
            op,
            false,
            None,
        )
        .map(|(out, _, _)| out)
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bvh::Aabb;
    use robust_arith::UNIT_ROUNDOFF;

    /// The boxes `level3_with_contacts` builds for `m` in a Boolean whose
    /// operands' coordinates are bounded by `bound`.
    fn one_call_boxes(m: &Flat<'_>, bound: f64) -> Vec<Aabb> {
        m.facet_boxes(4.0 * UNIT_ROUNDOFF * bound)
    }

    #[test]
    fn the_broad_phase_is_built_for_the_larger_bound() {
        let small = test_support::shapes::icosphere([0.0; 3], 1.0, 2);
        let large = test_support::shapes::icosphere([100.0, 0.0, 0.0], 300.0, 1);
        let (ps, pl) = (
            PreparedTriangles::new(&small).unwrap(),
            PreparedTriangles::new(&large).unwrap(),
        );
        assert!(ps.broad.bound < pl.broad.bound);
        let bound = pl.broad.bound;
        // The small operand's boxes are built again with the wider margin,
        // and differ from its own; the large operand's serve as they are.
        let again = rebuilt(&ps, &pl).expect("built again");
        assert_eq!(again.boxes, one_call_boxes(&ps.facets, bound));
        assert_ne!(again.boxes, ps.broad.boxes);
        assert!(rebuilt(&pl, &ps).is_none());
        assert_eq!(pl.broad.boxes, one_call_boxes(&pl.facets, bound));
        // Equal bounds: nothing is built again.
        assert!(rebuilt(&ps, &ps).is_none());
    }
}
