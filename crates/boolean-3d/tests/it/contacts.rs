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
    #![proptest_config(ProptestConfig::with_cases(test_support::cases(24)))]
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

/// Every triangle of the result that neither operand has (either way
/// round: B's triangles come reversed in a difference) lies in a contact
/// box, so smoothing near the contacts sees every place the result is
/// new. Besides the cut facets this covers a merged coplanar region that
/// was re-triangulated away from the other operand because the merge
/// dropped a vertex that only subdivided a straight edge (a find of
/// `smooth`'s near-versus-whole property test: boxes `1e-7` apart united,
/// then united with a disjoint box).
fn assert_new_triangles_in_contacts(
    a: &TriangleMesh,
    b: &TriangleMesh,
    op: BooleanOp,
    p: f64,
) -> TriangleMesh {
    let (out, c) = boolean_triangles_with_contacts(a, b, op, p).unwrap();
    assert_eq!(out, boolean_triangles(a, b, op).unwrap());
    let mut known: HashSet<[[u64; 3]; 3]> = HashSet::new();
    for m in [a, b] {
        for t in &m.triangles {
            let q = t.map(|v| m.vertices[v as usize].map(f64::to_bits));
            for r in [q, [q[0], q[2], q[1]]] {
                for k in 0..3 {
                    known.insert([r[k], r[(k + 1) % 3], r[(k + 2) % 3]]);
                }
            }
        }
    }
    let m = &out.mesh;
    for (i, t) in m.triangles.iter().enumerate() {
        if known.contains(&t.map(|v| m.vertices[v as usize].map(f64::to_bits))) {
            continue;
        }
        let bt = exact_box(m, i);
        assert!(
            c.boxes
                .iter()
                .any(|b| inside(&bt[0], b) && inside(&bt[1], b)),
            "{op:?}: new triangle {:?} outside every contact box",
            t.map(|v| m.vertices[v as usize])
        );
    }
    out.mesh
}

/// `m` with the edge between the vertices at `a` and `b` split at its
/// midpoint in both triangles that share it (still closed).
fn with_edge_midpoint(mut m: TriangleMesh, a: Point3, b: Point3) -> TriangleMesh {
    let at = |p: Point3| m.vertices.iter().position(|q| *q == p).unwrap() as u32;
    let (ia, ib) = (at(a), at(b));
    let mid = m.vertices.len() as u32;
    m.vertices
        .push(std::array::from_fn(|k| 0.5 * (a[k] + b[k])));
    let mut tris = Vec::new();
    for t in &m.triangles {
        match (0..3).find(|&k| {
            let (x, y) = (t[k], t[(k + 1) % 3]);
            (x, y) == (ia, ib) || (x, y) == (ib, ia)
        }) {
            Some(k) => {
                let (x, y, z) = (t[k], t[(k + 1) % 3], t[(k + 2) % 3]);
                tris.push([x, mid, z]);
                tris.push([mid, y, z]);
            }
            None => tris.push(*t),
        }
    }
    TriangleMesh::new(m.vertices, tris)
}

#[test]
fn a_region_re_triangulated_away_from_the_other_operand_is_a_contact() {
    // A cube whose top and front faces share an edge split at its
    // midpoint, which the coplanar merge hides (it only subdivides a
    // straight edge).
    let m = with_edge_midpoint(
        box_triangles([0.0; 3], [1.0; 3]),
        [0.0, 0.0, 1.0],
        [1.0, 0.0, 1.0],
    );
    m.check_topology().unwrap();
    // The other operand far away: both faces are kept as they were, the
    // midpoint with them, and nothing changed needs a contact box.
    let far = box_triangles([3.0; 3], [4.0; 3]);
    let (out, c) = boolean_triangles_with_contacts(&m, &far, BooleanOp::Union, 1e-5).unwrap();
    assert_new_triangles_in_contacts(&m, &far, BooleanOp::Union, 1e-5);
    assert!(c.boxes.is_empty(), "{:?}", c.boxes);
    assert_eq!(
        out.mesh.vertices.len(),
        m.vertices.len() + far.vertices.len()
    );
    let mut want: Vec<[Point3; 3]> = m
        .triangles
        .iter()
        .chain(far.triangles.iter())
        .zip(0..)
        .map(|(t, i)| {
            let vs = if i < m.triangles.len() {
                &m.vertices
            } else {
                &far.vertices
            };
            t.map(|v| vs[v as usize])
        })
        .collect();
    let mut got: Vec<[Point3; 3]> = out
        .mesh
        .triangles
        .iter()
        .map(|t| t.map(|v| out.mesh.vertices[v as usize]))
        .collect();
    let order = |a: &[Point3; 3], b: &[Point3; 3]| a.partial_cmp(b).unwrap();
    want.sort_by(order);
    got.sort_by(order);
    assert_eq!(got, want, "untouched triangles are the operands' own");
    // A post through the top face: the top face is cut, and the front
    // face, which shares the hidden midpoint, is re-triangulated too
    // although the post is far from it: its box is a contact.
    let post = box_triangles([0.4, 0.4, 0.5], [0.6, 0.6, 1.5]);
    let (_, c) = boolean_triangles_with_contacts(&m, &post, BooleanOp::Union, 1e-5).unwrap();
    assert_new_triangles_in_contacts(&m, &post, BooleanOp::Union, 1e-5);
    let front = [[0.0, 0.0, 0.0], [1.0, 0.0, 1.0]];
    assert!(
        c.boxes
            .iter()
            .any(|b| inside(&front[0], b) && inside(&front[1], b)),
        "{:?}",
        c.boxes
    );
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(test_support::cases(24)))]
    /// Chains of three grid boxes, each shifted by up to `1e-7`, under
    /// every operation: new triangles lie in contact boxes at each step.
    #[test]
    fn new_triangles_of_box_chains_lie_in_contact_boxes(
        boxes in prop::collection::vec(
            (prop::array::uniform3(0u8..4), prop::array::uniform3(1u8..4), prop::array::uniform3(-1i8..=1)),
            3,
        ),
        ops in prop::collection::vec(0u8..3, 2),
    ) {
        let mesh = |(o, s, j): &([u8; 3], [u8; 3], [i8; 3])| {
            let lo: Point3 = std::array::from_fn(|k| 0.25 * f64::from(o[k]) + 1e-7 * f64::from(j[k]));
            let hi: Point3 = std::array::from_fn(|k| lo[k] + 0.25 * f64::from(s[k]));
            box_triangles(lo, hi)
        };
        let mut m = mesh(&boxes[0]);
        for (b, &o) in boxes[1..].iter().zip(&ops) {
            let op = [BooleanOp::Union, BooleanOp::Intersection, BooleanOp::Difference][o as usize];
            m = assert_new_triangles_in_contacts(&m, &mesh(b), op, 1e-5);
        }
    }
}
