//! Figure A.1 of the dissertation: facets abcd (facing up) and efgh
//! (facing down) overlapping in part, as the top of one box and the
//! bottom of another; after edge cracking (e on ab, a on ef, i where cd
//! crosses he) and facet cancellation they become ebci and afghid.

use crate::mesh_common::check_result;
use smooth::{smooth_mesh, SmoothOptions};
use test_support::shapes::push_box;
use topology::{Facet, PolygonMesh};

/// The two boxes as one two-shell mesh (no Boolean: the boxes touch).
fn two_boxes() -> PolygonMesh {
    let (mut vertices, mut facets) = (Vec::new(), Vec::new());
    push_box(
        &mut vertices,
        &mut facets,
        [0.0, 0.0, 0.0],
        [2.0, 1.0, 1.0],
        false,
    );
    push_box(
        &mut vertices,
        &mut facets,
        [-1.0, 0.0, 1.0],
        [1.0, 2.0, 2.0],
        false,
    );
    PolygonMesh::new(vertices, facets)
}

/// The facet's loop as positions, if it is one loop.
fn loop_positions(m: &PolygonMesh, f: &Facet) -> Option<Vec<[f64; 3]>> {
    let loops = f.loops();
    (loops.len() == 1).then(|| loops[0].iter().map(|&v| m.vertices[v as usize]).collect())
}

/// Whether `got` is `want` up to a cyclic rotation.
fn same_cycle(got: &[[f64; 3]], want: &[[f64; 3]]) -> bool {
    got.len() == want.len()
        && (0..want.len()).any(|r| (0..want.len()).all(|k| got[(k + r) % got.len()] == want[k]))
}

#[test]
fn figure_a1_partial_cancellation() {
    let mesh = two_boxes();
    let before = mesh.clone();
    let out = smooth_mesh(&mesh, &SmoothOptions::new(1e-6)).unwrap();
    assert_eq!(mesh, before, "input untouched");
    check_result(&out.shape, &out.report, 1e-6);
    let z = 1.0;
    let [a, b, c, d] = [[0.0, 0.0, z], [2.0, 0.0, z], [2.0, 1.0, z], [0.0, 1.0, z]];
    let [e, f, g, h] = [[1.0, 0.0, z], [-1.0, 0.0, z], [-1.0, 2.0, z], [1.0, 2.0, z]];
    let i = [1.0, 1.0, z];
    let loops: Vec<Vec<[f64; 3]>> = out
        .shape
        .facets
        .iter()
        .filter_map(|fc| loop_positions(&out.shape, fc))
        .filter(|l| l.iter().all(|p| p[2] == z))
        .collect();
    assert_eq!(loops.len(), 2, "{loops:?}");
    assert!(
        loops.iter().any(|l| same_cycle(l, &[e, b, c, i])),
        "{loops:?}"
    );
    assert!(
        loops.iter().any(|l| same_cycle(l, &[a, f, g, h, i, d])),
        "{loops:?}"
    );
    let c = out.report.counts;
    assert_eq!(c.vertices_created, 1, "i is created");
    assert_eq!(c.edges_cracked_between_edges, 1);
    assert_eq!(c.facets_partially_cancelled, 1);
    assert_eq!(c.facets_cancelled, 0);
    // One closed shell of the two boxes' volume.
    assert!(out.shape.manifold_report().unwrap().is_two_manifold());
    assert_eq!(out.shape.signed_volume(), 6.0);
}
