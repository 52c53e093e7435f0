//! Smoothing near the operands' contacts (`boolean_solid_with_contacts`
//! then `smooth_solid_near`, what the command line runs) on real data
//! nobody here made: PyVista's threaded hex nut and sphere (test-support's
//! `data/`) combined with rotated and shifted copies of themselves, in
//! both variants and all three operations, give exactly what smoothing
//! the whole result gives (the oracle: same facets as sets of
//! coordinates, same counts of every operation) at the default tolerance
//! and at a coarse one where many vertices merge and edges crack.

use test_support::{canonical, data_path};
use umbra::{
    boolean_solid_with_contacts, default_mesh_tolerance, read_mesh, smooth_solid,
    smooth_solid_near, BooleanOp, MeshReadOptions, MeshVariant, PolygonMesh, SmoothOptions,
};

fn mesh(name: &str) -> PolygonMesh {
    read_mesh(
        &data_path(&format!("pyvista/{name}")),
        MeshReadOptions::default(),
        true,
    )
    .unwrap()
}

/// The mesh rotated by `deg` degrees about the z axis through the origin,
/// then moved by `shift`.
fn moved(m: &PolygonMesh, deg: f64, shift: [f64; 3]) -> PolygonMesh {
    let (s, c) = deg.to_radians().sin_cos();
    let vertices = m
        .vertices
        .iter()
        .map(|p| {
            [
                c * p[0] - s * p[1] + shift[0],
                s * p[0] + c * p[1] + shift[1],
                p[2] + shift[2],
            ]
        })
        .collect();
    PolygonMesh::new(vertices, m.facets.clone())
}

fn agree(name: &str, moves: &[(f64, [f64; 3])], coarse: f64) {
    let a = mesh(name);
    for &(deg, shift) in moves {
        let b = moved(&a, deg, shift);
        for variant in [MeshVariant::PolygonMesh, MeshVariant::TriangleMesh] {
            for op in [
                BooleanOp::Union,
                BooleanOp::Intersection,
                BooleanOp::Difference,
            ] {
                for tol in [default_mesh_tolerance(&a), coarse] {
                    let (out, contacts) =
                        boolean_solid_with_contacts(&a, &b, op, variant, tol).unwrap();
                    let opts = SmoothOptions::new(tol);
                    let whole = smooth_solid(&out.mesh, variant, &opts).unwrap();
                    let near = smooth_solid_near(&out.mesh, variant, &opts, &contacts).unwrap();
                    let what = format!("{name} {deg} {shift:?} {variant:?} {op:?} at {tol:e}");
                    assert!(near.shape.check_topology().is_ok(), "{what}");
                    assert_eq!(near.report.counts, whole.report.counts, "{what}");
                    assert_eq!(
                        canonical::mesh_facets(&near.shape),
                        canonical::mesh_facets(&whole.shape),
                        "{what}"
                    );
                }
            }
        }
    }
}

#[test]
fn the_nut_with_moved_copies_agrees_with_whole_smoothing() {
    agree(
        "nut.ply",
        &[
            (1e-2, [0.0; 3]),
            (1e-6, [0.0; 3]),
            (0.5, [0.05, -0.03, 0.1]),
        ],
        1e-3,
    );
}

#[test]
fn the_sphere_with_moved_copies_agrees_with_whole_smoothing() {
    agree(
        "sphere.ply",
        &[(1e-3, [0.0; 3]), (7.0, [0.1, 0.05, 0.0])],
        1e-3,
    );
}
