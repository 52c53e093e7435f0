//! Bad input: every operand is validated first, the error names the operand
//! and the violated constraint exactly as `topology`'s checks do, and
//! nothing panics.

use boolean_3d::{boolean_mesh, boolean_triangles, Boolean3Error, BooleanOp, Operand};
use proptest::prelude::*;
use test_support::rng::Lcg64;
use test_support::shapes::{box_mesh, icosphere};
use topology::{Facet, HalfEdge, PolygonMesh, TopologyError};

#[test]
fn nan_and_huge_coordinates_are_rejected_with_the_vertex_named() {
    let good = box_mesh([0.0; 3], [1.0; 3]);
    let mut bad = good.clone();
    bad.vertices[3][1] = f64::NAN;
    let err = boolean_mesh(&good, &bad, BooleanOp::Union).unwrap_err();
    assert!(matches!(
        err,
        Boolean3Error::InvalidInput {
            operand: Operand::B,
            source: TopologyError::BadCoordinate {
                vertex: 3,
                axis: 1,
                ..
            }
        }
    ));
    assert!(err.to_string().contains("operand B"));
    bad.vertices[3][1] = f64::MAX;
    assert!(boolean_mesh(&bad, &good, BooleanOp::Union).is_err());
}

#[test]
fn open_mesh_and_dangling_index_are_rejected() {
    let good = box_mesh([0.0; 3], [1.0; 3]);
    let mut open = good.clone();
    open.facets.pop();
    let err = boolean_mesh(&open, &good, BooleanOp::Difference).unwrap_err();
    assert_eq!(
        err,
        Boolean3Error::InvalidInput {
            operand: Operand::A,
            source: open.check_topology().unwrap_err()
        }
    );
    let mut dangling = good.clone();
    dangling.facets[2].half_edges[1].end = 99;
    let err = boolean_mesh(&good, &dangling, BooleanOp::Difference).unwrap_err();
    assert!(err.to_string().contains("dangling"), "{err}");
    let mut t = icosphere([0.0; 3], 1.0, 1);
    t.triangles[5][2] = 1000;
    let err = boolean_triangles(&t, &t, BooleanOp::Union).unwrap_err();
    assert_eq!(
        err,
        Boolean3Error::InvalidInput {
            operand: Operand::A,
            source: t.check_topology().unwrap_err()
        }
    );
}

/// Random damage to a valid mesh: remove, reverse, redirect or add a
/// half-edge, or make an index dangle.
fn damage(m: &mut PolygonMesh, rng: &mut Lcg64) {
    let nf = m.facets.len() as u64;
    let f = rng.below(nf) as usize;
    let nh = m.facets[f].half_edges.len() as u64;
    let h = rng.below(nh.max(1)) as usize;
    match rng.below(5) {
        0 => {
            m.facets[f].half_edges.remove(h);
        }
        1 => {
            let e = &mut m.facets[f].half_edges[h];
            std::mem::swap(&mut e.start, &mut e.end);
        }
        2 => m.facets[f].half_edges[h].end = rng.below(m.vertices.len() as u64) as u32,
        3 => m.facets[f].half_edges.push(HalfEdge {
            start: rng.below(m.vertices.len() as u64) as u32,
            end: rng.below(m.vertices.len() as u64) as u32,
        }),
        _ => m.facets[f].half_edges[h].start = m.vertices.len() as u32 + rng.below(3) as u32,
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: test_support::cases(64), .. ProptestConfig::default() })]

    /// The Boolean accepts exactly the meshes `check_topology` accepts and
    /// reports the same first violation.
    #[test]
    fn validation_agrees_with_check_topology(seed in any::<u64>(), which in 0u32..3) {
        let mut rng = Lcg64::new(seed);
        let mut m = match which {
            0 => box_mesh([0.0; 3], [1.0; 3]),
            1 => icosphere([0.0; 3], 1.0, 1).to_polygon_mesh(),
            _ => PolygonMesh::new(
                box_mesh([0.0; 3], [1.0; 3]).vertices,
                vec![Facet::from_loop(&[0, 1, 3, 2]), Facet::from_loop(&[0, 2, 3, 1])],
            ),
        };
        damage(&mut m, &mut rng);
        let good = box_mesh([0.5; 3], [2.0; 3]);
        let r = boolean_mesh(&good, &m, BooleanOp::Intersection);
        match m.check_topology() {
            Ok(()) => {
                let out = r.unwrap();
                prop_assert_eq!(out.mesh.check_topology(), Ok(()));
            }
            Err(e) => prop_assert_eq!(
                r.unwrap_err(),
                Boolean3Error::InvalidInput { operand: Operand::B, source: e }
            ),
        }
        let t = boolean_3d::triangulate_mesh(&m);
        if t.check_topology().is_err() {
            let r = boolean_triangles(&t, &t, BooleanOp::Union);
            prop_assert_eq!(
                r.unwrap_err(),
                Boolean3Error::InvalidInput { operand: Operand::A, source: t.check_topology().unwrap_err() }
            );
        }
    }
}

#[test]
fn empty_operands_are_fine() {
    let empty = PolygonMesh::default();
    let a = box_mesh([0.0; 3], [1.0; 3]);
    for op in BooleanOp::BASIC {
        let out = boolean_mesh(&a, &empty, op).unwrap();
        assert_eq!(out.mesh.check_topology(), Ok(()));
        let expect = if op == BooleanOp::Intersection { 0 } else { 6 };
        assert_eq!(out.mesh.facets.len(), expect, "{op:?}");
        let out = boolean_mesh(&empty, &a, op).unwrap();
        let expect = if op == BooleanOp::Union { 6 } else { 0 };
        assert_eq!(out.mesh.facets.len(), expect, "{op:?}");
    }
    let out = boolean_mesh(&empty, &empty, BooleanOp::Union).unwrap();
    assert!(out.mesh.facets.is_empty());
    // A facet without half-edges and an unreferenced vertex are valid.
    let mut odd = box_mesh([0.5; 3], [1.5; 3]);
    odd.facets.insert(2, Facet::default());
    odd.vertices.push([0.75; 3]);
    assert_eq!(odd.check_topology(), Ok(()));
    for op in BooleanOp::BASIC {
        let (out, audit) = boolean_3d::boolean_mesh_audit(&a, &odd, op).unwrap();
        audit.verify().unwrap();
        assert_eq!(out.mesh.check_topology(), Ok(()));
    }
}

/// `Audit::verify` can fail: each theorem check rejects tampered data.
#[test]
fn audit_verify_detects_each_violation() {
    let a = box_mesh([0.0; 3], [2.0; 3]);
    let b = box_mesh([1.0, 0.5, 0.25], [3.0, 1.5, 1.75]);
    let (_, audit) = boolean_3d::boolean_mesh_audit(&a, &b, BooleanOp::Union).unwrap();
    audit.verify().unwrap();
    let mut t = audit.clone();
    t.x03_per_vertex[0] += 1;
    assert!(t.verify().unwrap_err().contains("X03"));
    let mut t = audit.clone();
    t.composites[0].ends += 1;
    assert!(t.verify().unwrap_err().contains("Theorem 2"));
    let mut t = audit.clone();
    t.net_counts[0].1 = 1;
    assert!(t.verify().unwrap_err().contains("Theorem 2"));
    let mut t = audit.clone();
    t.facets[0].closed = false;
    assert!(t.verify().unwrap_err().contains("Theorem 3"));
    let mut t = audit.clone();
    t.shape_closure = Err(TopologyError::ShapeClosure3 {
        start: 0,
        end: 1,
        forward: 1,
        backward: 0,
    });
    assert!(t.verify().unwrap_err().contains("Theorem 4"));
    let mut t = audit.clone();
    assert!(!t.level3.x21.is_empty());
    t.level3.x21[0].point[0] = f64::NAN;
    assert!(t.verify().unwrap_err().contains("Theorem 1"));
}

#[test]
fn xor_is_refused_before_any_work() {
    let a = boolean_3d_cube();
    let err = boolean_3d::boolean_mesh(&a, &a, boolean_3d::BooleanOp::Xor).unwrap_err();
    assert_eq!(
        err,
        boolean_3d::Boolean3Error::UnsupportedOperation(boolean_3d::BooleanOp::Xor)
    );
    assert!(err.to_string().contains("not xor"), "{err}");
    let t = boolean_3d::triangulate_mesh(&a);
    assert!(boolean_3d::boolean_triangles(&t, &t, boolean_3d::BooleanOp::Xor).is_err());
}

fn boolean_3d_cube() -> topology::PolygonMesh {
    box_mesh([0.0; 3], [1.0; 3])
}
