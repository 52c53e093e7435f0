//! The operands' contacts (`boolean_*_with_contacts`): the result is the
//! Boolean's own bit for bit, every facet pair within the proximity is
//! found (brute force over exact boxes as the oracle), facets far apart
//! are not, and every vertex the Boolean created lies in a contact box.

use boolean_3d::{
    boolean_mesh, boolean_mesh_with_contacts, boolean_triangles, boolean_triangles_with_contacts,
    Boolean3Error, BooleanOp, Contacts,
};
use proptest::prelude::*;
use std::collections::HashSet;
use test_support::shapes::{box_mesh, box_triangles, icosphere};
use topology::{Point3, TriangleMesh};

fn inside(p: &Point3, b: &[Point3; 2]) -> bool {
    (0..3).all(|c| b[0][c] <= p[c] && p[c] <= b[1][c])
}

fn exact_box(m: &TriangleMesh, t: usize) -> [Point3; 2] {
    let mut lo = [f64::INFINITY; 3];
    let mut hi = [f64::NEG_INFINITY; 3];
    for &v in &m.triangles[t] {
        for c in 0..3 {
            lo[c] = lo[c].min(m.vertices[v as usize][c]);
            hi[c] = hi[c].max(m.vertices[v as usize][c]);
        }
    }
    [lo, hi]
}

/// The largest per-axis gap between two boxes (0 when they overlap).
fn gap(a: &[Point3; 2], b: &[Point3; 2]) -> f64 {
    (0..3)
        .map(|c| (b[0][c] - a[1][c]).max(a[0][c] - b[1][c]).max(0.0))
        .fold(0.0, f64::max)
}

/// Points spread over triangle `t` of `m` (a barycentric grid).
fn samples(m: &TriangleMesh, t: usize) -> Vec<Point3> {
    let [a, b, c] = m.triangles[t].map(|i| m.vertices[i as usize]);
    let k = 6;
    let mut out = Vec::new();
    for i in 0..=k {
        for j in 0..=k - i {
            let (u, v) = (f64::from(i) / f64::from(k), f64::from(j) / f64::from(k));
            let w = 1.0 - u - v;
            out.push(std::array::from_fn(|d| u * a[d] + v * b[d] + w * c[d]));
        }
    }
    out
}

/// Every triangle of `m` with a point within `p` of a point of a triangle
/// of `other` (sampled: the sampled distance is never below the true one,
/// so these pairs do come that close) lies, grown by `p`, inside a
/// contact box (the contacts of the triangle variant are boxes of merged
/// coplanar facets, which hold their triangles).
fn assert_covers(m: &TriangleMesh, other: &TriangleMesh, c: &Contacts, p: f64) {
    for t in 0..m.triangles.len() {
        let bt = exact_box(m, t);
        let st = samples(m, t);
        let near = (0..other.triangles.len()).any(|u| {
            gap(&bt, &exact_box(other, u)) <= p
                && samples(other, u).iter().any(|q| {
                    st.iter().any(|s| {
                        let d: f64 = (0..3).map(|k| (s[k] - q[k]) * (s[k] - q[k])).sum();
                        d.sqrt() <= p
                    })
                })
        });
        if near {
            let g = [bt[0].map(|x| x - p), bt[1].map(|x| x + p)];
            let held = c.boxes.iter().any(|b| inside(&g[0], b) && inside(&g[1], b));
            assert!(
                held,
                "triangle {t} comes within {p} of the other operand but no box holds it"
            );
        }
    }
}

#[test]
fn stacked_cubes_touch_within_the_proximity_and_not_beyond() {
    for gap_z in [0.0, 1e-12, 5e-10] {
        let a = box_triangles([0.0; 3], [1.0; 3]);
        let b = box_triangles([0.0, 0.0, 1.0 + gap_z], [1.0, 1.0, 2.0]);
        let (out, c) = boolean_triangles_with_contacts(&a, &b, BooleanOp::Union, 1e-9).unwrap();
        assert_eq!(out, boolean_triangles(&a, &b, BooleanOp::Union).unwrap());
        assert!(!c.boxes.is_empty(), "gap {gap_z}");
        // The top face of A and the bottom face of B are among them.
        let top = c
            .boxes
            .iter()
            .any(|b| b[0][2] <= 1.0 && b[1][2] >= 1.0 && b[1][2] < 1.0 + 1e-6);
        assert!(top, "gap {gap_z}: {:?}", c.boxes);
    }
    // Far apart: no contact at all.
    let a = box_triangles([0.0; 3], [1.0; 3]);
    let b = box_triangles([0.0, 0.0, 1.001], [1.0, 1.0, 2.0]);
    let (_, c) = boolean_triangles_with_contacts(&a, &b, BooleanOp::Union, 1e-9).unwrap();
    assert!(c.boxes.is_empty(), "{:?}", c.boxes);
}

#[test]
fn bad_proximity_is_refused() {
    let a = box_mesh([0.0; 3], [1.0; 3]);
    for p in [-1.0, f64::NAN, f64::INFINITY] {
        let e = boolean_mesh_with_contacts(&a, &a, BooleanOp::Union, p).unwrap_err();
        assert!(matches!(e, Boolean3Error::InvalidProximity(_)), "{e}");
        assert!(e.to_string().contains("proximity"));
    }
}

#[test]
fn created_vertices_lie_in_contact_boxes_and_results_are_unchanged() {
    let a = icosphere([0.0; 3], 1.0, 1);
    let b = icosphere([0.3, 0.2, 0.1], 1.0, 1);
    let inputs: HashSet<[u64; 3]> = a
        .vertices
        .iter()
        .chain(&b.vertices)
        .map(|p| p.map(f64::to_bits))
        .collect();
    for op in [
        BooleanOp::Union,
        BooleanOp::Intersection,
        BooleanOp::Difference,
    ] {
        let (out, c) = boolean_triangles_with_contacts(&a, &b, op, 1e-9).unwrap();
        assert_eq!(out, boolean_triangles(&a, &b, op).unwrap());
        for p in &out.mesh.vertices {
            if !inputs.contains(&p.map(f64::to_bits)) {
                assert!(c.boxes.iter().any(|b| inside(p, b)), "{op:?}: {p:?}");
            }
        }
        assert_covers(&a, &b, &c, 1e-9);
        let pa = a.to_polygon_mesh();
        let pb = b.to_polygon_mesh();
        let (m, _) = boolean_mesh_with_contacts(&pa, &pb, op, 1e-9).unwrap();
        assert_eq!(m, boolean_mesh(&pa, &pb, op).unwrap());
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]
    /// Two boxes placed at random near each other, at random proximities:
    /// every pair of triangles within the proximity by their exact boxes
    /// is covered (the brute-force oracle).
    #[test]
    fn near_triangle_pairs_are_all_found(
        dx in -1.2f64..1.2, dy in -1.2f64..1.2, dz in -1.2f64..1.2,
        e in -14i32..-1,
    ) {
        let p = 10f64.powi(e);
        let a = box_triangles([0.0; 3], [1.0; 3]);
        let b = box_triangles([1.0 + dx, dy, dz], [2.0 + dx, 1.0 + dy, 1.0 + dz]);
        if let Ok((_, c)) = boolean_triangles_with_contacts(&a, &b, BooleanOp::Union, p) {
            assert_covers(&a, &b, &c, p);
        }
    }
}
