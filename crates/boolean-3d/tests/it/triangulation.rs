//! Section 4.8: a geometrically valid retained facet is triangulated into
//! non-overlapping triangles that all face the facet's way; an invalid
//! facet still gives a closed triangulation.

use boolean_3d::{boolean_mesh, triangulate_facet, BooleanOp};
use proptest::prelude::*;
use test_support::rng::Lcg64;
use test_support::shapes::{box_mesh, icosphere, uv_sphere};
use topology::PolygonMesh;

fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// For every facet: the triangles' area vectors all point along the
/// facet's (Newell) area vector, and their magnitudes add up to its
/// magnitude, i.e. no triangle is flipped and none overlaps another.
fn check_faithful(m: &PolygonMesh, rel_tol: f64) {
    for (fi, f) in m.facets.iter().enumerate() {
        let hes: Vec<(u32, u32)> = f.half_edges.iter().map(|h| (h.start, h.end)).collect();
        let mut tris = Vec::new();
        triangulate_facet(&m.vertices, &hes, &mut tris);
        let p = |i: u32| m.vertices[i as usize];
        let o = p(hes[0].0);
        let rel = |i: u32| {
            let q = p(i);
            [q[0] - o[0], q[1] - o[1], q[2] - o[2]]
        };
        let mut facet_area = [0.0; 3];
        for &(s, e) in &hes {
            let c = cross(rel(s), rel(e));
            for k in 0..3 {
                facet_area[k] += c[k] / 2.0;
            }
        }
        let fa = (facet_area[0].powi(2) + facet_area[1].powi(2) + facet_area[2].powi(2)).sqrt();
        let mut sum_abs = 0.0;
        for t in &tris {
            let (a, b, c) = (rel(t[0]), rel(t[1]), rel(t[2]));
            let n = cross(
                [b[0] - a[0], b[1] - a[1], b[2] - a[2]],
                [c[0] - a[0], c[1] - a[1], c[2] - a[2]],
            );
            let area = (n[0].powi(2) + n[1].powi(2) + n[2].powi(2)).sqrt() / 2.0;
            let along = (n[0] * facet_area[0] + n[1] * facet_area[1] + n[2] * facet_area[2]) / 2.0;
            assert!(
                along >= -rel_tol * fa * fa,
                "facet {fi}: triangle {t:?} is flipped"
            );
            sum_abs += area;
        }
        assert!(
            (sum_abs - fa).abs() <= rel_tol * fa.max(1e-300),
            "facet {fi}: triangles cover {sum_abs}, facet area {fa}"
        );
    }
}

#[test]
fn box_and_sphere_results_triangulate_faithfully() {
    let a = box_mesh([0.0; 3], [2.0; 3]);
    for b in [
        box_mesh([0.5, 0.5, -1.0], [1.5, 1.5, 3.0]),
        box_mesh([1.0, 0.5, 0.25], [3.0, 1.5, 1.75]),
        box_mesh([0.5, 0.5, 0.5], [1.5, 1.5, 1.5]),
    ] {
        for op in BooleanOp::BASIC {
            check_faithful(&boolean_mesh(&a, &b, op).unwrap().mesh, 1e-12);
            check_faithful(&boolean_mesh(&b, &a, op).unwrap().mesh, 1e-12);
        }
    }
    let s = icosphere([0.0; 3], 1.0, 2).to_polygon_mesh();
    let t = uv_sphere([0.4, 0.1, 0.05], 0.8, 20, 10).to_polygon_mesh();
    for op in BooleanOp::BASIC {
        check_faithful(&boolean_mesh(&s, &t, op).unwrap().mesh, 1e-9);
        check_faithful(&boolean_mesh(&a, &s, op).unwrap().mesh, 1e-9);
    }
}

/// A star-shaped polygon with holes is triangulated faithfully.
#[test]
fn polygons_with_holes_triangulate_faithfully() {
    let mut v = Vec::new();
    let n = 24;
    for i in 0..n {
        let ang = 2.0 * std::f64::consts::PI * f64::from(i) / f64::from(n);
        let r = if i % 2 == 0 { 3.0 } else { 1.8 };
        v.push([r * ang.cos(), r * ang.sin(), 0.25 * ang.cos()]);
    }
    let mut loops = vec![(0..n as u32).collect::<Vec<_>>()];
    for (cx, cy) in [(0.0, 0.0), (1.6, 0.0), (-0.5, 1.1)] {
        let base = v.len() as u32;
        for k in 0..5 {
            let ang = -2.0 * std::f64::consts::PI * f64::from(k) / 5.0;
            v.push([
                cx + 0.3 * ang.cos(),
                cy + 0.3 * ang.sin(),
                0.25 * (cx + 0.3 * ang.cos()) / 3.0,
            ]);
        }
        loops.push((base..base + 5).collect());
    }
    // A planar facet z = x / 12 (the outer loop's z is on the same plane
    // only approximately; tolerance accordingly).
    for p in &mut v {
        p[2] = p[0] / 12.0;
    }
    let m = PolygonMesh::new(v, vec![topology::Facet::from_loops(&loops)]);
    check_faithful(&m, 1e-12);
}

#[test]
fn facets_touching_themselves_at_a_vertex_triangulate_faithfully() {
    // Two regions sharing vertex 0, and a hole touching the outer boundary
    // at vertex 5.
    let v = vec![
        [0.0, 0.0, 0.0],
        [1.0, 1.0, 0.0],
        [-1.0, 1.0, 0.0],
        [1.0, -1.0, 0.0],
        [-1.0, -1.0, 0.0],
        [3.0, 0.0, 0.0],
        [6.0, -2.0, 0.0],
        [6.0, 2.0, 0.0],
        [4.0, 0.5, 0.0],
        [4.0, -0.5, 0.0],
    ];
    for order in 0..4 {
        let mut loops = vec![vec![2, 0, 1], vec![3, 0, 4], vec![5, 6, 7], vec![5, 8, 9]];
        loops.rotate_left(order);
        let m = PolygonMesh::new(v.clone(), vec![topology::Facet::from_loops(&loops)]);
        check_faithful(&m, 1e-12);
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: test_support::cases(64), .. ProptestConfig::default() })]

    /// Any facet, valid or not, gives a closed set of triangles: the
    /// triangles' half-edges minus the facet's cancel in opposite pairs.
    #[test]
    fn any_facet_gives_a_closed_triangulation(seed in any::<u64>(), n in 3usize..12, holes in 0usize..3) {
        let mut rng = Lcg64::new(seed);
        let nv = n + 3 * holes;
        let v: Vec<[f64; 3]> = (0..nv)
            .map(|_| [rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0)])
            .collect();
        let mut hes: Vec<(u32, u32)> = (0..n as u32).map(|i| (i, (i + 1) % n as u32)).collect();
        for h in 0..holes as u32 {
            let b = n as u32 + 3 * h;
            hes.extend([(b, b + 2), (b + 2, b + 1), (b + 1, b)]);
        }
        let mut tris = Vec::new();
        triangulate_facet(&v, &hes, &mut tris);
        // At least one triangle per loop, at most one per vertex plus two
        // per bridge.
        prop_assert!(tris.len() > holes && tris.len() <= nv + 2 * holes);
        let mut count = std::collections::HashMap::new();
        for t in &tris {
            for (s, e) in [(t[0], t[1]), (t[1], t[2]), (t[2], t[0])] {
                *count.entry((s, e)).or_insert(0i32) += 1;
            }
        }
        for &(s, e) in &hes {
            *count.entry((s, e)).or_insert(0) -= 1;
        }
        for (&(s, e), &c) in &count {
            prop_assert!(s == e || c == count.get(&(e, s)).copied().unwrap_or(0));
        }
    }
}
