//! Chapter 5's stacked cubes (figures 5.1-5.2): two unit cubes stacked
//! face to face, touching exactly or with gaps and overlaps of 1e-12 to
//! 1e-6, united by the basic Boolean in both argument orders (both
//! variants), then smoothed at 1e-5: one closed 2-manifold shell of
//! volume 2, with no zero-area facet and no edge shorter than the
//! tolerance.

use crate::mesh_common::{check_result, facet_area, min_edge, poly, shells};
use boolean_3d::{boolean_mesh, boolean_triangles, BooleanOp};
use smooth::{sanity_check_triangles, smooth_mesh, smooth_triangles, SmoothOptions};
use test_support::shapes::{box_mesh, box_triangles};
use topology::PolygonMesh;

const DELTA: f64 = 1e-5;
const OFFSETS: [f64; 7] = [0.0, 1e-12, -1e-12, 1e-9, -1e-9, 1e-6, -1e-6];

/// One closed 2-manifold shell whose volume is the exact union's (2, less
/// an overlap) within 1e-9 plus what closing the gap or overlap by merging
/// may move (vertices move by `|gap|` over a unit square).
fn assert_one_box(m: &PolygonMesh, gap: f64, what: &str) {
    let r = m.manifold_report().unwrap();
    assert!(r.is_two_manifold(), "{what}: not a 2-manifold: {r:?}");
    assert_eq!(shells(m), 1, "{what}: shells");
    let v = m.signed_volume();
    let exact = 2.0 + gap.min(0.0);
    assert!((v - exact).abs() <= 1e-9 + gap.abs(), "{what}: volume {v}");
    for fi in 0..m.facets.len() {
        assert!(
            facet_area(m, fi) > DELTA * DELTA,
            "{what}: facet {fi} has zero area"
        );
    }
    assert!(
        min_edge(m) > DELTA,
        "{what}: an edge shorter than the tolerance"
    );
}

#[test]
fn stacked_cubes_polygon_meshes() {
    for gap in OFFSETS {
        let lower = box_mesh([0.0; 3], [1.0; 3]);
        let upper = box_mesh([0.0, 0.0, 1.0 + gap], [1.0, 1.0, 2.0 + gap]);
        for (a, b, order) in [
            (&lower, &upper, "lower first"),
            (&upper, &lower, "upper first"),
        ] {
            let what = format!("gap {gap:e}, {order}");
            let raw = boolean_mesh(a, b, BooleanOp::Union).unwrap().mesh;
            let out = smooth_mesh(&raw, &SmoothOptions::new(DELTA)).unwrap();
            check_result(&out.shape, &out.report, DELTA);
            assert_one_box(&out.shape, gap, &what);
        }
    }
}

#[test]
fn stacked_cubes_triangle_meshes() {
    for gap in OFFSETS {
        let lower = box_triangles([0.0; 3], [1.0; 3]);
        let upper = box_triangles([0.0, 0.0, 1.0 + gap], [1.0, 1.0, 2.0 + gap]);
        for (a, b, order) in [
            (&lower, &upper, "lower first"),
            (&upper, &lower, "upper first"),
        ] {
            let what = format!("triangles, gap {gap:e}, {order}");
            let raw = boolean_triangles(a, b, BooleanOp::Union).unwrap().mesh;
            let out = smooth_triangles(&raw, &SmoothOptions::new(DELTA)).unwrap();
            sanity_check_triangles(&out.shape, DELTA).unwrap();
            assert!(!out.report.budget_hit);
            assert_one_box(&poly(&out.shape), gap, &what);
        }
    }
}
