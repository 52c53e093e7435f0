//! Fuzz target: data smoothing (Appendix A) of 3D and 2D Boolean results
//! and of raw garbage-but-valid shapes never panics, refuses exactly the
//! bad coordinates, keeps the closure constraints, never hits its safety
//! budget, moves no vertex farther than its reported bound, and is
//! idempotent (smoothing the result again changes nothing). Smoothing only
//! near the Boolean's contacts keeps the closure constraints too, and
//! where both operands need no smoothing it gives exactly what smoothing
//! the whole result gives, in 3D and in 2D. Guarded smoothing is closed
//! and never worse than its input by the whole-mesh defect checks.
#![no_main]

use boolean_3d::{boolean_mesh, boolean_mesh_with_contacts, BooleanOp};
use libfuzzer_sys::fuzz_target;
use smooth::{
    smooth_mesh, smooth_mesh_near, smooth_polygon_set, smooth_polygon_set_near, smooth_triangles,
    SmoothCounts, SmoothError, SmoothOptions,
};
use test_support::canonical;
use topology::{PolygonMesh, PolygonSet2};
use umbra_fuzz::SmoothInput;

fn tolerance(size: f64, exp: u8) -> f64 {
    let t = size * 2f64.powi(i32::from(exp % 64) - 48);
    if t.is_finite() {
        t
    } else {
        0.0
    }
}

fuzz_target!(|input: SmoothInput| {
    let a = input.solid.a.to_mesh();
    let b = input.solid.b.to_mesh();
    let coords_ok = a.validate_coordinates().is_ok();
    let op = match input.solid.op % 3 {
        0 => BooleanOp::Union,
        1 => BooleanOp::Intersection,
        _ => BooleanOp::Difference,
    };
    let size = a
        .vertices
        .iter()
        .chain(&b.vertices)
        .flatten()
        .fold(0.0f64, |m, x| m.max(x.abs()));
    let tol = tolerance(size, input.tolerance_exp);
    let opts = SmoothOptions::new(tol);
    // Near the contacts: always closed; where both operands need no
    // smoothing, the same facets as smoothing the whole result.
    if let Ok((out, contacts)) = boolean_mesh_with_contacts(&a, &b, op, tol) {
        if let Ok(near) = smooth_mesh_near(&out.mesh, &opts, &contacts.boxes) {
            near.shape
                .check_topology()
                .expect("near smoothing not closed");
            assert!(near.report.max_displacement <= near.report.distortion_bound);
            // Needs no smoothing: nothing counted and nothing moved (beyond
            // 2^200 the scaling can flush subnormal coordinates to 0).
            let clean = |m: &PolygonMesh| {
                smooth_mesh(m, &opts)
                    .is_ok_and(|s| s.report.counts == SmoothCounts::default() && s.shape == *m)
            };
            if clean(&a) && clean(&b) {
                let whole = smooth_mesh(&out.mesh, &opts).expect("whole smoothing");
                assert_eq!(
                    canonical::mesh_facets(&near.shape),
                    canonical::mesh_facets(&whole.shape),
                    "near != whole"
                );
            }
        }
    }
    let mesh = boolean_mesh(&a, &b, op).map(|o| o.mesh).unwrap_or(a);
    // The guard (what the front ends run): a guarded result is closed and
    // never worse than its input by the whole-mesh checks (intersecting
    // facet pairs, then non-manifold and open edges and non-manifold
    // vertices); undone everywhere it is the input, undone at some places
    // it keeps smoothing's report.
    if let Ok(g) = smooth_mesh(&mesh, &opts.guarded()) {
        g.shape
            .check_topology()
            .expect("guarded smoothing not closed");
        let defects = |m: &PolygonMesh| {
            let pairs = topology::check_mesh(m).self_intersecting_facet_pairs;
            let manifold = m.manifold_report().ok().map(|r| {
                r.non_manifold_edges.len() + r.open_edges.len() + r.non_manifold_vertices.len()
            });
            pairs.zip(manifold)
        };
        if let (Some(guarded), Some(input)) = (defects(&g.shape), defects(&mesh)) {
            assert!(guarded <= input, "guarded smoothing worse than its input");
        }
        match &g.report.reverted {
            Some(r) if r.is_partial() => {
                let plain = smooth_mesh(&mesh, &opts).expect("unguarded smoothing");
                assert_eq!(g.report.counts, plain.report.counts, "partial undo's counts");
            }
            Some(_) => assert_eq!(g.shape, mesh, "undone whole, not the input"),
            None => {}
        }
    }
    match smooth_mesh(&mesh, &opts) {
        Ok(out) => {
            assert!(
                mesh.validate_coordinates().is_ok(),
                "bad coordinates accepted"
            );
            out.shape
                .check_topology()
                .expect("smoothed mesh not closed");
            assert!(!out.report.budget_hit, "safety budget hit");
            assert!(out.report.max_displacement <= out.report.distortion_bound);
            // Idempotent where the coordinates resolve the tolerance (at
            // least 2^-40 of their magnitude; docs/algorithms/smooth.md).
            let top = out
                .shape
                .vertices
                .iter()
                .flatten()
                .fold(0.0f64, |m, x| m.max(x.abs()));
            if opts.tolerance >= top * 2f64.powi(-40) {
                let again = smooth_mesh(&out.shape, &opts).expect("smoothing a smoothed mesh");
                assert_eq!(again.shape.vertices, out.shape.vertices, "not idempotent");
                assert_eq!(
                    again.shape.facets.len(),
                    out.shape.facets.len(),
                    "not idempotent"
                );
            }
            if let Some(tri) = input.solid.a.to_triangles() {
                if let Ok(t) = smooth_triangles(&tri, &opts) {
                    t.shape
                        .check_topology()
                        .expect("smoothed triangles not closed");
                }
            }
        }
        Err(SmoothError::InvalidInput(_)) => {
            assert!(
                !coords_ok || mesh.validate_coordinates().is_err(),
                "valid input refused"
            )
        }
        Err(e) => panic!("{e}"),
    }

    let p = input.planar[0].to_set();
    let q = input.planar[1].to_set();
    let set = boolean_2d::boolean(&p, &q, BooleanOp::Union)
        .map(|o| o.shape)
        .unwrap_or_else(|_| p.clone());
    let opts = SmoothOptions::new(tolerance(set.max_abs_coordinate(), input.tolerance_exp));
    // Near the 2D contacts: always closed; where both operands need no
    // smoothing, whole smoothing's set bit for bit.
    if let Ok((out, contacts)) =
        boolean_2d::boolean_with_contacts(&p, &q, BooleanOp::Union, opts.tolerance)
    {
        if let Ok(near) = smooth_polygon_set_near(&out.shape, &opts, &contacts.boxes) {
            near.shape
                .check_topology()
                .expect("2D near smoothing not closed");
            assert!(near.report.max_displacement <= near.report.distortion_bound);
            let clean = |s: &PolygonSet2| {
                smooth_polygon_set(s, &opts).is_ok_and(|o| {
                    o.report.counts == SmoothCounts::default()
                        && canonical::set_edges(&o.shape) == canonical::set_edges(s)
                })
            };
            if clean(&p) && clean(&q) {
                let whole = smooth_polygon_set(&out.shape, &opts).expect("whole 2D smoothing");
                assert!(near.shape == whole.shape, "2D near != whole");
            }
        }
    }
    match smooth_polygon_set(&set, &opts) {
        Ok(out) => {
            out.shape.check_topology().expect("smoothed set not closed");
            assert!(!out.report.budget_hit, "safety budget hit");
            assert!(out.report.max_displacement <= out.report.distortion_bound);
        }
        Err(SmoothError::InvalidInput(_)) => {
            assert!(set.validate_coordinates().is_err(), "valid set refused")
        }
        Err(e) => panic!("{e}"),
    }
});
