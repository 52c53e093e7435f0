//! Reports describe what they say they describe: a 3D result is counted as
//! the file written holds it (the triangles of 3MF and ASCII STL, checked
//! against the files read back and counted by hand), and the CSG report's
//! 2-manifoldness is `check_mesh`'s (one census), on clean and
//! non-manifold results.

use umbra::{
    boolean_solid, check_mesh, cuboid, encode_mesh_with, evaluate_csg, parse_3mf, parse_csg,
    parse_obj, parse_stl, transform_mesh, Boolean3Report, BooleanOp, CsgOptions, DMat4, DVec3,
    FileKind, MeshCounts, MeshVariant, MeshWriteOptions, Operands, WrittenMeshReport,
};

/// The union of two 2-cubes overlapping in a unit cube, by the polygon
/// variant: 6 squares and 6 L-shaped hexagons, 36 triangles once split
/// (two per square, four per hexagon), volume 15.
#[test]
fn a_polygon_result_is_counted_as_the_file_holds_it() {
    let a = cuboid(DVec3::splat(2.0), false).unwrap();
    let b = transform_mesh(&a, &DMat4::from_translation(DVec3::splat(1.0))).unwrap();
    let out = boolean_solid(&a, &b, BooleanOp::Union, MeshVariant::PolygonMesh).unwrap();
    assert_eq!(out.mesh.facets.len(), 12);
    let inputs = Operands {
        a: MeshCounts::of_mesh("a", &a),
        b: MeshCounts::of_mesh("b", &b),
    };
    let text = MeshWriteOptions { text: true };
    for (kind, options) in [
        (FileKind::ThreeMf, MeshWriteOptions::default()),
        (FileKind::Stl, text),
        (FileKind::Obj, text),
    ] {
        let e = encode_mesh_with(kind, &out.mesh, options, "out").unwrap();
        let r = Boolean3Report::new(BooleanOp::Union, inputs.clone(), "out", &out).written_as(&e);
        // What the file holds, by its reader and by hand.
        let (vertices, facets) = match kind {
            FileKind::ThreeMf => {
                let m = parse_3mf(&e.bytes, "out.3mf").unwrap();
                (m.vertices.len(), m.triangles.len())
            }
            FileKind::Stl => {
                let text = String::from_utf8(e.bytes.clone()).unwrap();
                let by_hand = text.matches("facet normal").count();
                let m = parse_stl(&e.bytes, "out.stl").unwrap();
                assert_eq!(m.triangles.len(), by_hand);
                (m.vertices.len(), by_hand)
            }
            _ => {
                let text = String::from_utf8(e.bytes.clone()).unwrap();
                let m = parse_obj(&text, "out.obj").unwrap();
                (
                    m.vertices.len(),
                    text.lines().filter(|l| l.starts_with("f ")).count(),
                )
            }
        };
        let want_facets = if kind == FileKind::Obj { 12 } else { 36 };
        assert_eq!(facets, want_facets, "{kind:?}");
        assert_eq!(r.output.facets, facets, "{kind:?}");
        assert_eq!(r.output.vertices, vertices, "{kind:?}");
        assert_eq!(
            r.output.half_edges,
            if kind == FileKind::Obj { 60 } else { 108 }
        );
        assert_eq!(r.output.signed_volume, 15.0, "{kind:?}");
        assert!(r.topologically_valid, "{kind:?}");
        assert_eq!(e.counts("out", &out.mesh), r.output, "{kind:?}");
    }
}

/// The CSG report states `check_mesh`'s 2-manifoldness of the result: on
/// a clean difference (a closed 2-manifold), on two cubes sharing an edge
/// (two shells, coincident vertices kept apart by the raw Boolean), and on
/// touching parts whose raw triangle result has non-manifold edges (where
/// the report's own counter said 1 and `check` 3).
#[test]
fn the_csg_report_states_the_checks_manifold_counts() {
    let cases = [
        (
            r#"{"op": "difference", "children": [
                {"box": {"size": [2, 2, 2], "center": true}},
                {"cylinder": {"radius": 0.5, "height": 3, "segments": 8, "center": true}}]}"#,
            false,
            Some(true),
        ),
        (
            r#"{"op": "union", "children": [
                {"box": {"size": [1, 1, 1]}},
                {"box": {"size": [1, 1, 1]}, "translate": [1, 1, 0]}]}"#,
            false,
            Some(true),
        ),
        (
            r#"{"op": "union", "children": [
                {"box": {"size": [1, 1.5, 1.5]}, "translate": [0, 2, 2]},
                {"cylinder": {"radius": 1, "height": 1, "segments": 8}, "translate": [2, 2, 0]},
                {"cylinder": {"radius": 0.5, "height": 1, "segments": 8}, "translate": [0.5, 2, 1.5]},
                {"box": {"size": [0.5, 0.5, 0.5]}, "translate": [1, 2, 0]}]}"#,
            true,
            Some(false),
        ),
    ];
    for (script, triangulate, manifold) in cases {
        let tree = parse_csg(script).unwrap();
        let options = CsgOptions {
            triangulate,
            ..CsgOptions::default()
        };
        let out = evaluate_csg(&tree, options).unwrap();
        let r = &out.report;
        let c = check_mesh(&out.mesh);
        assert_eq!(r.two_manifold, manifold, "{script}");
        assert_eq!(r.two_manifold, c.two_manifold, "{script}");
        assert_eq!(r.open_edges, c.open_edges, "{script}");
        assert_eq!(r.non_manifold_edges, c.non_manifold_edges, "{script}");
        assert_eq!(r.non_manifold_vertices, c.non_manifold_vertices, "{script}");
        assert_eq!((r.vertices, r.facets), (c.vertices, c.facets), "{script}");
        if manifold == Some(false) {
            assert!(r.non_manifold_edges > Some(1), "{script}: {r:?}");
        } else {
            assert_eq!((r.open_edges, r.non_manifold_edges), (Some(0), Some(0)));
        }
    }
}
