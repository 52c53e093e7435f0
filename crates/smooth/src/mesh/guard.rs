//! The guard of 3D smoothing ([`crate::SmoothOptions::guard`]): smoothing
//! is kept only where it leaves no more defects than the input had. The
//! operations of Appendix A move vertices by up to the tolerance and
//! split edges at created vertices; where two surfaces lie within the
//! tolerance of each other at an angle (a solid minus a copy of itself
//! turned by a few degrees), a merge or a crack on one surface can push a
//! facet through the other, which the raw Boolean (Theorem 2: exact
//! topology, no such pair where its operands had none) did not do. The
//! guard counts intersecting facet pairs, non-manifold edges and
//! vertices, and open edges near the facets smoothing changed, in the
//! result and, only when the result has some, in the input near the
//! facets they replaced; a result worse by
//! [`crate::MeshDefects::worse_than`] (more pairs, or as many and more
//! manifold defects) is dropped for the input. Outside the focus both
//! meshes are the same, so the comparison near it is the comparison of
//! the whole meshes.

use crate::{MeshDefects, Reverted, SmoothReport};
use topology::{ManifoldReport, PolygonMesh, TriangleMesh};

/// The counts of a manifold report and a pair list.
fn defects(pairs: Option<Vec<[u32; 2]>>, manifold: Option<ManifoldReport>) -> MeshDefects {
    let m = manifold.unwrap_or_default();
    MeshDefects {
        intersecting_pairs: pairs.map_or(0, |p| p.len()),
        non_manifold_edges: m.non_manifold_edges.len(),
        non_manifold_vertices: m.non_manifold_vertices.len(),
        open_edges: m.open_edges.len(),
    }
}

/// The defects of a polygon mesh near the facets `f` with `focus[f]`.
pub(crate) fn defects_near_mesh(mesh: &PolygonMesh, focus: &[bool]) -> MeshDefects {
    defects(
        topology::self_intersecting_pairs_near(mesh, focus),
        mesh.manifold_report_near(focus),
    )
}

/// The defects of a triangle mesh near the triangles `t` with `focus[t]`.
pub(crate) fn defects_near_triangles(mesh: &TriangleMesh, focus: &[bool]) -> MeshDefects {
    defects(
        topology::self_intersecting_triangle_pairs_near(mesh, focus),
        mesh.manifold_report_near(focus),
    )
}

/// The guard's decision on a smoothing run: `Some` (the report of the
/// input handed back) when the result's defects near what changed
/// (`smoothed`) are worse than the input's there (`input`, computed only
/// when the result has any).
pub(crate) fn judge(
    report: &SmoothReport,
    smoothed: impl FnOnce() -> MeshDefects,
    input: impl FnOnce() -> MeshDefects,
) -> Option<SmoothReport> {
    let smoothed = smoothed();
    if !smoothed.any() {
        return None;
    }
    let input = input();
    smoothed.worse_than(&input).then(|| SmoothReport {
        tolerance: report.tolerance,
        reverted: Some(Reverted {
            smoothed,
            input,
            counts: report.counts,
        }),
        ..SmoothReport::default()
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::SmoothCounts;

    #[test]
    fn a_clean_result_is_kept_without_looking_at_the_input() {
        let r = SmoothReport::default();
        let kept = judge(&r, MeshDefects::default, || {
            panic!("the input is not inspected when the result is clean")
        });
        assert_eq!(kept, None);
    }

    #[test]
    fn a_worse_result_is_reverted() {
        let r = SmoothReport {
            tolerance: 1e-9,
            counts: SmoothCounts {
                vertices_merged: 4,
                ..SmoothCounts::default()
            },
            distortion_bound: 1e-9,
            ..SmoothReport::default()
        };
        let pinch = MeshDefects {
            non_manifold_vertices: 1,
            ..MeshDefects::default()
        };
        let pairs = MeshDefects {
            intersecting_pairs: 2,
            ..MeshDefects::default()
        };
        // Fewer pairs than the input had: kept, also at the price of a
        // pinch.
        assert_eq!(
            judge(
                &r,
                || pairs,
                || MeshDefects {
                    intersecting_pairs: 5,
                    ..pairs
                }
            ),
            None
        );
        assert_eq!(judge(&r, || pinch, || pairs), None);
        // A pinch the clean input did not have: reverted.
        let back = judge(&r, || pinch, MeshDefects::default).unwrap();
        assert_eq!(back.tolerance, 1e-9);
        assert_eq!(back.counts, SmoothCounts::default());
        assert_eq!(back.distortion_bound, 0.0);
        let undone = back.reverted.unwrap();
        assert_eq!(
            (undone.smoothed, undone.input),
            (pinch, MeshDefects::default())
        );
        // More pairs: reverted even if the input had a pinch.
        let more = MeshDefects {
            intersecting_pairs: 1,
            ..MeshDefects::default()
        };
        assert!(judge(&r, || more, || pinch).is_some());
        assert_eq!(undone.counts.vertices_merged, 4);
    }
}
