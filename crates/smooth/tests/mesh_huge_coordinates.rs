//! Coordinates near the top of the f64 range (a fuzz find): a unit cube
//! and a tetrahedron whose coordinates reach about 1e306, smoothed at
//! `size * 2^-48`, where squared distances and the squared tolerance
//! overflow. The result must be valid, idempotent, and no vertex may move
//! farther than the reported distortion bound.

use boolean_3d::{boolean_mesh, BooleanOp};
use smooth::{sanity_check_mesh, smooth_mesh, smooth_triangles, SmoothOptions};
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
