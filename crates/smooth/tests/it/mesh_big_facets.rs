//! Two prisms over a regular n-gon stacked cap to cap (n up to 2,000):
//! their union's coincident caps are two large opposing facets, cancelled
//! in full by one swap, without any quadratic loop search; the result is
//! one closed 2-manifold shell.

use boolean_3d::{boolean_mesh, BooleanOp};
use smooth::{sanity_check_mesh, smooth_mesh, SmoothOptions};
use topology::{Facet, PolygonMesh};

/// A prism over the regular `n`-gon of radius 1 between heights `z0` and
/// `z1`, facets facing out.
fn prism(n: usize, z0: f64, z1: f64) -> PolygonMesh {
    let mut v = Vec::new();
    for z in [z0, z1] {
        for i in 0..n {
            let a = std::f64::consts::TAU * i as f64 / n as f64;
            v.push([a.cos(), a.sin(), z]);
        }
    }
    let n32 = n as u32;
    let mut f = vec![
        Facet::from_loop(&(0..n32).rev().collect::<Vec<_>>()),
        Facet::from_loop(&(n32..2 * n32).collect::<Vec<_>>()),
    ];
    for i in 0..n32 {
        let j = (i + 1) % n32;
        f.push(Facet::from_loop(&[i, j, j + n32, i + n32]));
    }
    PolygonMesh::new(v, f)
}

#[test]
fn stacked_prisms_with_large_caps() {
    for (n, gap) in [(12, 0.0), (300, 1e-9), (2000, 0.0)] {
        let a = prism(n, 0.0, 1.0);
        let b = prism(n, 1.0 + gap, 2.0);
        let raw = boolean_mesh(&a, &b, BooleanOp::Union).unwrap().mesh;
        let out = smooth_mesh(&raw, &SmoothOptions::new(1e-6)).unwrap();
        sanity_check_mesh(&out.shape, 1e-6).unwrap();
        assert!(
            out.shape.manifold_report().unwrap().is_two_manifold(),
            "n {n}"
        );
        assert_eq!(
            out.shape.facets.len(),
            2 + 2 * n,
            "n {n}: the caps cancelled"
        );
        let exact = 2.0 * (n as f64 / 2.0) * (std::f64::consts::TAU / n as f64).sin();
        let v = out.shape.signed_volume();
        assert!(
            (v - exact).abs() < 1e-9 + 4.0 * gap,
            "n {n}: {v} vs {exact}"
        );
    }
}

#[test]
fn large_retriangulated_facet_stays_valid() {
    // The triangle variant: a 48-gon prism's side is cracked by the other
    // prism's vertices (offset by half a step), so the quads become
    // polygons to re-triangulate, flipped towards Delaunay.
    let n = 48;
    let a = topology::triangulate_mesh(&prism(n, 0.0, 1.0));
    let mut b = prism(n, 1.0, 2.0);
    for p in &mut b.vertices {
        let a = std::f64::consts::PI / n as f64;
        let (s, c) = a.sin_cos();
        *p = [c * p[0] - s * p[1], s * p[0] + c * p[1], p[2]];
    }
    let b = topology::triangulate_mesh(&b);
    let raw = boolean_3d::boolean_triangles(&a, &b, BooleanOp::Union)
        .unwrap()
        .mesh;
    let out = smooth::smooth_triangles(&raw, &SmoothOptions::new(1e-6)).unwrap();
    smooth::sanity_check_triangles(&out.shape, 1e-6).unwrap();
    assert!(!out.report.budget_hit);
    let v = out.shape.signed_volume();
    assert!((v - raw.signed_volume()).abs() < 1e-6, "{v}");
}
