//! The facade's inspection on Boolean results: every result of the 3D
//! Boolean on overlapping cubes is valid, has the analytic volume and no
//! self-intersecting facet pair, also with every triangle as a facet of its
//! own (coplanar neighbours, corners on other facets' edges).

use umbra::{boolean_mesh, check_mesh, triangulate_mesh, BooleanOp, Facet, PolygonMesh};

/// A polygon mesh from coordinates and facet loops.
fn mesh(v: &[[f64; 3]], loops: &[&[u32]]) -> PolygonMesh {
    PolygonMesh::new(
        v.to_vec(),
        loops.iter().map(|l| Facet::from_loop(l)).collect(),
    )
}

fn cube_at(o: f64, s: f64) -> PolygonMesh {
    let v: Vec<[f64; 3]> = (0..8)
        .map(|i| {
            [
                o + s * f64::from(i & 1),
                o + s * f64::from((i >> 1) & 1),
                o + s * f64::from((i >> 2) & 1),
            ]
        })
        .collect();
    mesh(
        &v,
        &[
            &[0, 2, 3, 1],
            &[4, 5, 7, 6],
            &[0, 1, 5, 4],
            &[2, 6, 7, 3],
            &[0, 4, 6, 2],
            &[1, 3, 7, 5],
        ],
    )
}

#[test]
fn boolean_results_of_overlapping_cubes_do_not_self_intersect() {
    let (a, b) = (cube_at(0.0, 2.0), cube_at(1.0, 2.0));
    for (op, volume) in [
        (BooleanOp::Union, 15.0),
        (BooleanOp::Intersection, 1.0),
        (BooleanOp::Difference, 7.0),
    ] {
        let out = boolean_mesh(&a, &b, op).unwrap().mesh;
        let r = check_mesh(&out);
        assert!(r.is_valid(), "{op:?}: {r:?}");
        assert_eq!(r.signed_volume, Some(volume), "{op:?}");
        assert_eq!(r.self_intersecting_facet_pairs, Some(0), "{op:?}");
        // Every triangle of the result as a facet of its own: coplanar
        // neighbours, corners on other facets' edges.
        let tri = triangulate_mesh(&out).to_polygon_mesh();
        let r = check_mesh(&tri);
        assert!(r.is_valid(), "{op:?}: {r:?}");
        assert_eq!(r.self_intersecting_facet_pairs, Some(0), "{op:?} triangles");
    }
}
