//! Fuzz target: rounding a mesh to `f32` coordinates for the formats that
//! store them (`umbra::round_to_f32`) never panics, on Boolean results of
//! any coordinates (both variants) and on the operands themselves: every
//! finite coordinate in the `f32` range comes out an `f32` value, a closed
//! mesh stays closed, and when the report says no pair is left, a mesh
//! whose `f64` form had no intersecting facet pair has none after
//! rounding either (the exact test, `umbra::check_mesh`).
#![no_main]

use libfuzzer_sys::fuzz_target;
use umbra::{
    boolean_solid, check_mesh, round_to_f32, triangulate_mesh, BooleanOp, MeshVariant, PolygonMesh,
};
use umbra_fuzz::SolidInput;

/// Rounds `mesh` and checks what the rounding promises.
fn round_and_check(mesh: &PolygonMesh) {
    let closed = mesh.check_topology().is_ok();
    // Judged on the triangles rounding starts from (the exact test of a
    // polygon mesh may triangulate a facet otherwise).
    let triangles = triangulate_mesh(mesh).to_polygon_mesh();
    let clean_before = check_mesh(&triangles).self_intersecting_facet_pairs == Some(0);
    let rounded = round_to_f32(mesh);
    for &x in rounded.mesh.vertices.iter().flatten() {
        let in_range = x.is_finite() && x.abs() <= f64::from(f32::MAX);
        assert!(
            !in_range || f64::from(x as f32) == x,
            "coordinate {x:e} is not an f32 value"
        );
    }
    let out = rounded.mesh.to_polygon_mesh();
    if closed {
        out.check_topology().expect("rounding opened a closed mesh");
    }
    if closed && clean_before && rounded.report.pairs_left == 0 {
        assert_eq!(
            check_mesh(&out).self_intersecting_facet_pairs,
            Some(0),
            "report {:?} says no pair is left",
            rounded.report
        );
    }
}

fuzz_target!(|input: SolidInput| {
    let (a, b) = (input.a.to_mesh(), input.b.to_mesh());
    let op = match input.op % 3 {
        0 => BooleanOp::Union,
        1 => BooleanOp::Intersection,
        _ => BooleanOp::Difference,
    };
    round_and_check(&a);
    for variant in [MeshVariant::PolygonMesh, MeshVariant::TriangleMesh] {
        if let Ok(out) = boolean_solid(&a, &b, op, variant) {
            round_and_check(&out.mesh);
        }
    }
});
