//! Differences of nearly identical cubes (issue 10, chapter 5): a cube
//! minus itself and minus a copy offset by 1e-10 leave nothing after
//! smoothing; a cube minus a slightly smaller cube sharing faces leaves
//! no sliver (no facet thinner than the tolerance); a cube with a
//! through-hole whose caps coincide up to 1e-9 keeps its exact volume.

use crate::mesh_common::{check_result, facet_width, min_edge, poly, shells};
use boolean_3d::{boolean_mesh, boolean_triangles, BooleanOp};
use smooth::{sanity_check_triangles, smooth_mesh, smooth_triangles, SmoothOptions};
use test_support::shapes::{box_mesh, box_triangles};
use topology::PolygonMesh;

const DELTA: f64 = 1e-5;

fn difference(a: ([f64; 3], [f64; 3]), b: ([f64; 3], [f64; 3])) -> PolygonMesh {
    let raw = boolean_mesh(
        &box_mesh(a.0, a.1),
        &box_mesh(b.0, b.1),
        BooleanOp::Difference,
    )
    .unwrap()
    .mesh;
    let out = smooth_mesh(&raw, &SmoothOptions::new(DELTA)).unwrap();
    check_result(&out.shape, &out.report, DELTA);
    // The triangle variant agrees on emptiness and validity.
    let traw = boolean_triangles(
        &box_triangles(a.0, a.1),
        &box_triangles(b.0, b.1),
        BooleanOp::Difference,
    )
    .unwrap()
    .mesh;
    let t = smooth_triangles(&traw, &SmoothOptions::new(DELTA)).unwrap();
    sanity_check_triangles(&t.shape, DELTA).unwrap();
    assert_eq!(t.shape.triangles.is_empty(), out.shape.facets.is_empty());
    if !t.shape.triangles.is_empty() {
        let tv = poly(&t.shape).signed_volume();
        assert!((tv - out.shape.signed_volume()).abs() < 1e-6, "{tv}");
    }
    out.shape
}

fn assert_no_sliver(m: &PolygonMesh) {
    for fi in 0..m.facets.len() {
        let w = facet_width(m, fi);
        assert!(w > DELTA, "facet {fi} is a sliver of width {w:e}");
    }
    assert!(m.facets.is_empty() || min_edge(m) > DELTA);
}

const UNIT: ([f64; 3], [f64; 3]) = ([0.0; 3], [1.0; 3]);

#[test]
fn cube_minus_identical_cube_is_empty() {
    let m = difference(UNIT, UNIT);
    assert!(m.facets.is_empty() && m.vertices.is_empty(), "{m:?}");
}

#[test]
fn cube_minus_offset_cube_is_empty() {
    for d in [1e-10, -1e-10, 1e-12, 3e-7] {
        let m = difference(UNIT, ([d; 3], [1.0 + d; 3]));
        assert!(
            m.facets.is_empty(),
            "offset {d:e}: {} facets left",
            m.facets.len()
        );
    }
}

#[test]
fn cube_minus_slightly_smaller_cube_leaves_no_sliver() {
    for e in [1e-7, 1e-9, 5e-6] {
        // Shares the bottom face: a cup of thickness e is all that is left.
        let m = difference(UNIT, ([e, e, 0.0], [1.0 - e, 1.0 - e, 1.0 - e]));
        assert_no_sliver(&m);
        assert!(
            m.facets.is_empty(),
            "thickness {e:e}: {} facets",
            m.facets.len()
        );
        // Shares five faces: a slab of thickness e.
        let m = difference(UNIT, ([0.0; 3], [1.0, 1.0, 1.0 - e]));
        assert_no_sliver(&m);
        assert!(m.facets.is_empty());
    }
}

#[test]
fn through_hole_with_nearly_coincident_caps() {
    for e in [0.0, 1e-9, -1e-9, 1e-12] {
        let m = difference(UNIT, ([0.25, 0.25, e], [0.75, 0.75, 1.0 + e]));
        assert_no_sliver(&m);
        let r = m.manifold_report().unwrap();
        assert!(r.is_two_manifold(), "{e:e}: {r:?}");
        assert_eq!(shells(&m), 1);
        let v = m.signed_volume();
        assert!((v - 0.75).abs() <= 1e-9 + e.abs(), "{e:e}: volume {v}");
    }
}
