//! Named cases: a cube against a copy rotated by 10^-k radians (section
//! 2.3.3), cubes touching face to face in both argument orders (figures
//! 5.1-5.2), coincident and coplanar faces, edge-on-edge and vertex-on-face
//! contact, A op A, two cubes sharing one edge as a single non-manifold
//! input, and a shape with an inside-out region (the 3D analogue of figure
//! 4.9). Every case checks Theorems 1-4 through the audit, topological
//! validity of both variants, and the volume against an exact value.

use crate::common::{rotate, volume};
use boolean_3d::{boolean_mesh_audit, boolean_triangles_audit, triangulate_mesh, BooleanOp};
use test_support::exact::triangle_mesh_volume as exact_volume;
use test_support::shapes::{box_mesh, box_triangles, icosphere, tetra};
use topology::{PolygonMesh, TriangleMesh};

/// Runs `op` in both variants, checks every theorem and returns the exact
/// volume of the (triangulated) polygon result and of the triangle result.
fn run(a: &PolygonMesh, b: &PolygonMesh, op: BooleanOp) -> (f64, f64) {
    let (out, audit) = boolean_mesh_audit(a, b, op).unwrap();
    audit.verify().unwrap();
    assert_eq!(out.mesh.check_topology(), Ok(()));
    let tri = triangulate_mesh(&out.mesh);
    assert_eq!(tri.check_topology(), Ok(()));
    let (ta, tb) = (triangulate_mesh(a), triangulate_mesh(b));
    let (tout, audit) = boolean_triangles_audit(&ta, &tb, op).unwrap();
    audit.verify().unwrap();
    assert_eq!(tout.mesh.check_topology(), Ok(()));
    (exact_volume(&tri), exact_volume(&tout.mesh))
}

fn expect_volumes(a: &PolygonMesh, b: &PolygonMesh, want: [f64; 3], tol: f64, what: &str) {
    for (op, w) in BooleanOp::BASIC.into_iter().zip(want) {
        let (vp, vt) = run(a, b, op);
        assert!((vp - w).abs() <= tol, "{what} {op:?} polygon: {vp} vs {w}");
        assert!(
            (vt - w).abs() <= tol,
            "{what} {op:?} triangles: {vt} vs {w}"
        );
    }
}

fn merge(a: &PolygonMesh, b: &PolygonMesh) -> PolygonMesh {
    let mut m = a.clone();
    let off = m.vertices.len() as u32;
    m.vertices.extend(b.vertices.iter());
    for f in &b.facets {
        let mut f = f.clone();
        for h in &mut f.half_edges {
            h.start += off;
            h.end += off;
        }
        m.facets.push(f);
    }
    m
}

fn reversed(m: &PolygonMesh) -> PolygonMesh {
    let mut r = m.clone();
    for f in &mut r.facets {
        for h in &mut f.half_edges {
            std::mem::swap(&mut h.start, &mut h.end);
        }
    }
    r
}

#[test]
fn cube_against_copy_rotated_by_ten_to_the_minus_k() {
    let a = box_mesh([-0.5; 3], [0.5; 3]);
    for k in 1..=15 {
        let ang = 10f64.powi(-k);
        let mut b = a.clone();
        for p in &mut b.vertices {
            *p = rotate(*p, [0.0; 3], ang);
        }
        // The symmetric difference of the cubes has volume O(angle).
        let tol = 4.0 * ang + 1e-14;
        expect_volumes(&a, &b, [1.0, 1.0, 0.0], tol, &format!("k = {k}"));
        // Triangle meshes of the same cubes (each face split in two).
        let (ta, tb) = (box_triangles([-0.5; 3], [0.5; 3]), {
            let mut t = box_triangles([-0.5; 3], [0.5; 3]);
            for p in &mut t.vertices {
                *p = rotate(*p, [0.0; 3], ang);
            }
            t
        });
        for op in BooleanOp::BASIC {
            let (out, audit) = boolean_triangles_audit(&ta, &tb, op).unwrap();
            audit.verify().unwrap();
            assert_eq!(out.mesh.check_topology(), Ok(()));
        }
    }
}

#[test]
fn cubes_touching_face_to_face_in_both_orders() {
    let a = box_mesh([0.0; 3], [1.0; 3]);
    for b in [
        box_mesh([1.0, 0.0, 0.0], [2.0, 1.0, 1.0]),
        box_mesh([1.0, 0.5, 0.25], [2.0, 1.5, 1.25]),
    ] {
        expect_volumes(&a, &b, [2.0, 0.0, 1.0], 0.0, "A touches B");
        expect_volumes(&b, &a, [2.0, 0.0, 1.0], 0.0, "B touches A");
    }
    // Touching from below in z (the shadow direction of level 3).
    let b = box_mesh([0.25, 0.25, 1.0], [0.75, 0.75, 2.0]);
    expect_volumes(&a, &b, [1.25, 0.0, 1.0], 0.0, "A under B");
    expect_volumes(&b, &a, [1.25, 0.0, 0.25], 0.0, "B on A");
}

#[test]
fn coincident_and_coplanar_faces() {
    let a = box_mesh([0.0; 3], [1.0; 3]);
    // Shares the planes z = 0 and z = 1 and x = 1 partly.
    let b = box_mesh([0.5, 0.25, 0.0], [1.5, 0.75, 1.0]);
    // |A| = 1, |B| = 0.5, overlap 0.25.
    expect_volumes(&a, &b, [1.25, 0.25, 0.75], 0.0, "coplanar");
    expect_volumes(&b, &a, [1.25, 0.25, 0.25], 0.0, "coplanar reversed");
    // A box inside sharing three faces with the corner of A.
    let c = box_mesh([0.0; 3], [0.5; 3]);
    expect_volumes(&a, &c, [1.0, 0.125, 0.875], 0.0, "corner");
    expect_volumes(&c, &a, [1.0, 0.125, 0.0], 0.0, "corner reversed");
}

#[test]
fn edge_on_edge_and_vertex_on_face_contact() {
    let a = box_mesh([0.0; 3], [1.0; 3]);
    let b = box_mesh([1.0, 1.0, 0.0], [2.0, 2.0, 1.0]);
    expect_volumes(&a, &b, [2.0, 0.0, 1.0], 0.0, "edge on edge");
    let b = box_mesh([1.0, 1.0, 0.5], [2.0, 2.0, 1.5]);
    expect_volumes(&a, &b, [2.0, 0.0, 1.0], 0.0, "edge on edge, offset");
    // Crossing edges: B's edge along y at x = 1, z = 1 crosses A's... the
    // box rotated 45 degrees about y touches A's top edge at one line.
    let t = tetra([
        [0.5, 0.5, 1.0],
        [0.0, 0.0, 2.0],
        [1.0, 0.0, 2.0],
        [0.5, 1.0, 2.0],
    ])
    .to_polygon_mesh();
    // Tetrahedron above A with its apex on A's top face (orientation fixed
    // below by the sign of the volume).
    let t = if volume(&t) < 0.0 { reversed(&t) } else { t };
    let vt = exact_volume(&triangulate_mesh(&t));
    expect_volumes(
        &a,
        &t,
        [1.0 + vt, 0.0, 1.0],
        1e-15,
        "vertex on face from outside",
    );
    // A tetrahedron inside A with a vertex on A's face.
    let t = tetra([
        [0.5, 0.5, 1.0],
        [0.1, 0.1, 0.2],
        [0.9, 0.1, 0.2],
        [0.5, 0.9, 0.2],
    ])
    .to_polygon_mesh();
    let t = if volume(&t) < 0.0 { reversed(&t) } else { t };
    let vt = exact_volume(&triangulate_mesh(&t));
    expect_volumes(
        &a,
        &t,
        [1.0, vt, 1.0 - vt],
        1e-15,
        "vertex on face from inside",
    );
}

#[test]
fn a_op_a_for_every_op() {
    let cube = box_mesh([0.0; 3], [1.0; 3]);
    expect_volumes(&cube, &cube, [1.0, 1.0, 0.0], 0.0, "cube");
    let s: TriangleMesh = icosphere([0.1, 0.2, 0.3], 1.0, 2);
    let vs = exact_volume(&s);
    let sp = s.to_polygon_mesh();
    expect_volumes(&sp, &sp, [vs, vs, 0.0], 1e-12, "sphere");
}

#[test]
fn two_cubes_sharing_one_edge_as_one_non_manifold_input() {
    let a = merge(
        &box_mesh([0.0; 3], [1.0; 3]),
        &box_mesh([1.0, 1.0, 0.0], [2.0, 2.0, 1.0]),
    );
    // Weld the shared edge so the input is non-manifold: vertices 3 and 7
    // of the first cube are (1,1,0) and (1,1,1), vertices 8 and 12 of the
    // second.
    let mut a = a;
    for f in &mut a.facets {
        for h in &mut f.half_edges {
            for v in [&mut h.start, &mut h.end] {
                if *v == 8 {
                    *v = 3;
                } else if *v == 12 {
                    *v = 7;
                }
            }
        }
    }
    assert_eq!(a.check_topology(), Ok(()));
    let b = box_mesh([0.5, 0.5, 0.25], [1.5, 1.5, 0.75]);
    expect_volumes(&a, &b, [2.25, 0.25, 1.75], 0.0, "non-manifold A");
    expect_volumes(&b, &a, [2.25, 0.25, 0.25], 0.0, "non-manifold B");
    expect_volumes(&a, &a, [2.0, 2.0, 0.0], 0.0, "non-manifold A op A");
}

#[test]
fn shape_with_an_inside_out_region() {
    // A: a unit cube plus a separate inside-out cube (winding -1 there).
    let a = merge(
        &box_mesh([0.0; 3], [1.0; 3]),
        &reversed(&box_mesh([2.0, 0.0, 0.0], [3.0, 1.0, 1.0])),
    );
    let b = box_mesh([0.5, 0.25, 0.25], [2.5, 0.75, 0.75]);
    // Signed volumes are integrals of the winding number of eq. 4.20:
    // int a = 0, int b = 0.5, int ab = 0.125 - 0.125 = 0.
    expect_volumes(&a, &b, [0.5, 0.0, 0.0], 0.0, "inside-out A");
    // With B first: int b = 0 ... the roles of c_A and c_B swap.
    expect_volumes(&b, &a, [0.5, 0.0, 0.5], 0.0, "inside-out B");
    // A doubly enclosed region: two overlapping cubes in one mesh
    // (winding 2 in the overlap), against a box crossing it.
    let d = merge(
        &box_mesh([0.0; 3], [1.0; 3]),
        &box_mesh([0.5, 0.0, 0.0], [1.5, 1.0, 1.0]),
    );
    let b = box_mesh([0.25, 0.25, 0.25], [1.25, 0.75, 0.75]);
    // int a = 2, int b = 0.25, int ab = 0.25 * (1 on [0.25,0.5] ... ) by
    // slabs in x: [0.25,0.5] a=1, [0.5,1] a=2, [1,1.25] a=1, cross section
    // 0.25: int ab = 0.25 * (0.25 + 2 * 0.5 + 0.25) = 0.375.
    expect_volumes(
        &d,
        &b,
        [2.0 + 0.25 - 0.375, 0.375, 2.0 - 0.375],
        0.0,
        "doubly enclosed",
    );
}

#[test]
fn sphere_against_copy_rotated_by_tiny_angles() {
    let a = icosphere([0.0; 3], 1.0, 1);
    let va = exact_volume(&a);
    for k in [3, 8, 15] {
        let ang = 10f64.powi(-k);
        let mut b = a.clone();
        for p in &mut b.vertices {
            *p = rotate(*p, [0.0; 3], ang);
        }
        for op in BooleanOp::BASIC {
            let (out, audit) = boolean_triangles_audit(&a, &b, op).unwrap();
            audit.verify().unwrap();
            assert_eq!(out.mesh.check_topology(), Ok(()));
            let v = exact_volume(&out.mesh);
            let want = if op == BooleanOp::Difference { 0.0 } else { va };
            assert!(
                (v - want).abs() <= 10.0 * ang + 1e-13,
                "k = {k} {op:?}: {v} vs {want}"
            );
        }
    }
}
