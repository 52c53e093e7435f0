//! Coordinates near the top of the f64 range (a fuzz find): a unit cube
//! and a tetrahedron whose coordinates reach about 1e306, smoothed at
//! `size * 2^-48`, where squared distances and the squared tolerance
//! overflow. The result must be valid, idempotent, and no vertex may move
//! farther than the reported distortion bound. Also a property-test find:
//! a vertex created on edges `1e300` long, which only the bound's rounding
//! allowance covers.

use boolean_3d::{boolean_mesh, BooleanOp};
use smooth::{sanity_check_mesh, smooth_mesh, smooth_triangles, SmoothOptions};
use test_support::shapes::push_box;
use topology::{Facet, PolygonMesh};

fn fuzz_mesh() -> PolygonMesh {
    let b = f64::from_bits;
    let (h, g, w, s) = (
        b(0x3fe6ff8000000000),
        b(0xff00be10f7e00010),
        b(0xefefefefefefefef),
        b(0xc4),
    );
    let vertices = vec![
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [0.0, 1.0, 0.0],
        [1.0, 1.0, 0.0],
        [0.0, 0.0, 1.0],
        [1.0, 0.0, 1.0],
        [0.0, 1.0, 1.0],
        [1.0, 1.0, 1.0],
        [h, g, w],
        [s, h, g],
        [w, s, h],
        [g, w, s],
    ];
    let loops: [&[u32]; 10] = [
        &[1, 3, 2, 0],
        &[6, 7, 5, 4],
        &[4, 5, 1, 0],
        &[3, 7, 6, 2],
        &[2, 6, 4, 0],
        &[5, 7, 3, 1],
        &[8, 10, 9],
        &[8, 9, 11],
        &[9, 10, 11],
        &[8, 11, 10],
    ];
    PolygonMesh::new(
        vertices,
        loops.iter().map(|l| Facet::from_loop(l)).collect(),
    )
}

/// The distance from `p` to `q`, without overflow.
fn dist(p: [f64; 3], q: [f64; 3]) -> f64 {
    let d = [p[0] - q[0], p[1] - q[1], p[2] - q[2]];
    d[0].hypot(d[1]).hypot(d[2])
}

#[test]
fn huge_coordinates_stay_within_the_distortion_bound() {
    let a = fuzz_mesh();
    let empty = PolygonMesh::new(Vec::new(), Vec::new());
    let mesh = boolean_mesh(&a, &empty, BooleanOp::Union).map_or(a.clone(), |o| o.mesh);
    let size = mesh
        .vertices
        .iter()
        .flatten()
        .fold(0.0f64, |m, x| m.max(x.abs()));
    for exp in [-48, -60, -20, 0, 10] {
        let opts = SmoothOptions::new(size * 2f64.powi(exp));
        let out = smooth_mesh(&mesh, &opts).unwrap();
        out.shape.check_topology().unwrap();
        sanity_check_mesh(&out.shape, opts.tolerance).unwrap();
        assert!(!out.report.budget_hit);
        assert!(
            out.report.max_displacement <= out.report.distortion_bound,
            "exp {exp}: {:?}",
            out.report
        );
        // The bound is a true one: every surviving input vertex (here
        // none is created, so every output vertex is an input vertex
        // moved) lies within it of some input vertex.
        for &p in &out.shape.vertices {
            let near = mesh
                .vertices
                .iter()
                .map(|&q| dist(p, q))
                .fold(f64::INFINITY, f64::min);
            assert!(near <= out.report.distortion_bound, "exp {exp}: {near}");
        }
        let again = smooth_mesh(&out.shape, &opts).unwrap();
        assert_eq!(again.shape.vertices, out.shape.vertices, "exp {exp}");
        assert_eq!(again.shape.facets.len(), out.shape.facets.len());
    }
}

#[test]
fn huge_coordinates_in_the_triangle_variant_stay_within_the_bound() {
    let t = topology::triangulate_mesh(&fuzz_mesh());
    let size = t
        .vertices
        .iter()
        .flatten()
        .fold(0.0f64, |m, x| m.max(x.abs()));
    let opts = SmoothOptions::new(size * 2f64.powi(-48));
    let out = smooth_triangles(&t, &opts).unwrap();
    out.shape.check_topology().unwrap();
    assert!(out.report.max_displacement <= out.report.distortion_bound);
}

#[test]
fn huge_planar_coordinates_stay_within_the_distortion_bound() {
    use topology::PolygonSet2;
    let b = f64::from_bits;
    let (g, w) = (b(0xff00be10f7e00010), b(0xefefefefefefefef));
    let mut s = PolygonSet2::new();
    s.add_loop(&[[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]);
    s.add_loop(&[[g, w], [-g, w], [-g, -w * 1e-10], [0.5, g * 1e-300]]);
    let size = s.max_abs_coordinate();
    for exp in [-48, -20, 0] {
        let opts = SmoothOptions::new(size * 2f64.powi(exp));
        let out = smooth::smooth_polygon_set(&s, &opts).unwrap();
        out.shape.check_topology().unwrap();
        assert!(
            out.report.max_displacement <= out.report.distortion_bound,
            "exp {exp}: {:?}",
            out.report
        );
    }
}

/// A property-test find: a box whose corners were replaced by garbage up
/// to `1e300`, smoothed at tolerance 0 (so at the scaled floor `2^-500`,
/// about `3e89` here). Two of its edges, in the plane `x = 1`, cross: one
/// along y at `z = 1`, one from `z = 1e300` to `z = -1e300`, and the vertex
/// created at their crossing can only be placed within the coordinates'
/// resolution (about `1e284`) of the steep edge. The bound must cover that
/// rounding (it reported `2.5` times the tolerance alone, below the
/// measured `1.8e252`), and stay within it.
#[test]
fn a_vertex_created_on_edges_1e300_long_stays_within_the_bound() {
    let corners = [
        [1.0, 1.0, 1.0],
        [2.5462949704181076e89, 0.0, 1.0],
        [1.0, 1e300, 0.0],
        [1.0, 1.0, 1e300],
        [1.0, 1.0, 1.0],
        [1.0, 8.257250981989829e283, 1.0],
        [1.0, 1.0, 1.0],
        [1.0, 3.05887055934763e268, -1e300],
    ];
    // A box's corners and facets (`push_box`), the corners replaced.
    let (mut vertices, mut facets) = (Vec::new(), Vec::new());
    push_box(&mut vertices, &mut facets, [0.0; 3], [0.25; 3], false);
    assert_eq!(vertices.len(), corners.len());
    let m = PolygonMesh::new(corners.to_vec(), facets);
    let out = smooth_mesh(&m, &SmoothOptions::new(0.0)).unwrap();
    sanity_check_mesh(&out.shape, 0.0).unwrap();
    let r = &out.report;
    assert!(r.counts.vertices_created >= 1, "{r:?}");
    assert!(r.max_displacement > 1e200, "the crossing's rounding: {r:?}");
    assert!(r.max_displacement <= r.distortion_bound, "{r:?}");
    // 2.5 times the tolerance used plus 64 units of roundoff of 1e300.
    assert!(
        r.distortion_bound <= 1e90 + 64.0 * (f64::EPSILON / 2.0) * 1e300,
        "{r:?}"
    );
}
