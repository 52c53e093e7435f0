//! Smoothing near contacts (`smooth_mesh_near`, `smooth_triangles_near`)
//! against whole-mesh smoothing as the oracle: on Boolean results of
//! operands that need no smoothing themselves, with the Boolean's own
//! contacts, both give the same facets (as sets of coordinates), the
//! same counts and a valid shape; elsewhere (no contacts, contacts over
//! everything, garbage boxes, bad input) the documented behaviour.

use crate::mesh_common::{grid_box, op, shells};
use boolean_3d::{boolean_mesh_with_contacts, boolean_triangles_with_contacts, BooleanOp};
use proptest::prelude::*;
use smooth::{
    sanity_check_mesh, sanity_check_triangles, smooth_mesh, smooth_mesh_near, smooth_triangles,
    smooth_triangles_near, SmoothError, SmoothOptions,
};
use test_support::canonical;
use test_support::shapes::{box_mesh, box_triangles, icosphere, uv_sphere};
use topology::{Facet, Point3, PolygonMesh};

const DELTA: f64 = 1e-5;

proptest! {
    #![proptest_config(ProptestConfig {
        cases: test_support::cases(120),
        max_global_rejects: test_support::cases(1024),
        ..ProptestConfig::default()
    })]

    /// A chain of Booleans, each result smoothed before the next (so both
    /// operands are clean): near and whole smoothing agree at every step.
    #[test]
    fn near_smoothing_equals_whole_smoothing_on_box_chains(
        first in grid_box(-6),
        rest in prop::collection::vec((op(), grid_box(-6)), 1..4),
    ) {
        let opts = SmoothOptions::new(DELTA);
        let mut m = box_mesh(first.0, first.1);
        for (o, b) in &rest {
            let (out, c) = boolean_mesh_with_contacts(&m, &box_mesh(b.0, b.1), *o, DELTA).unwrap();
            let whole = smooth_mesh(&out.mesh, &opts).unwrap();
            let near = smooth_mesh_near(&out.mesh, &opts, &c.boxes).unwrap();
            sanity_check_mesh(&near.shape, DELTA).unwrap();
            prop_assert_eq!(canonical::mesh_facets(&near.shape), canonical::mesh_facets(&whole.shape));
            prop_assert_eq!(near.report.counts, whole.report.counts);
            let settled = settle(whole.shape, |m| smooth_mesh(m, &opts).unwrap());
            prop_assume!(settled.is_some(), "smoothing did not settle");
            m = settled.unwrap();
        }
    }

    #[test]
    fn near_smoothing_equals_whole_smoothing_on_triangle_chains(
        first in grid_box(-6),
        rest in prop::collection::vec((op(), grid_box(-6)), 1..3),
    ) {
        let opts = SmoothOptions::new(DELTA);
        let mut m = box_triangles(first.0, first.1);
        for (o, b) in &rest {
            let other = box_triangles(b.0, b.1);
            let (out, c) = boolean_triangles_with_contacts(&m, &other, *o, DELTA).unwrap();
            let whole = smooth_triangles(&out.mesh, &opts).unwrap();
            let near = smooth_triangles_near(&out.mesh, &opts, &c.boxes).unwrap();
            sanity_check_triangles(&near.shape, DELTA).unwrap();
            prop_assert_eq!(canonical::triangles(&near.shape), canonical::triangles(&whole.shape));
            let settled = settle(whole.shape, |m| smooth_triangles(m, &opts).unwrap());
            prop_assume!(settled.is_some(), "smoothing did not settle");
            m = settled.unwrap();
        }
    }
}

/// The next operand of a chain: `m` smoothed again until a run changes
/// nothing (at most four runs; `None` if it does not settle). The
/// comparison needs operands that need no smoothing, and one run does not
/// always leave a fixpoint: in the triangle variant re-triangulation may
/// add an internal edge within `delta` of a vertex in a cluster a few
/// `delta` wide, which a second run cracks (the documented limit of
/// idempotence).
fn settle<M>(mut m: M, mut smooth: impl FnMut(&M) -> smooth::Smoothed<M>) -> Option<M> {
    for _ in 0..4 {
        let again = smooth(&m);
        if again.report.counts == smooth::SmoothCounts::default() {
            return Some(m);
        }
        m = again.shape;
    }
    None
}

#[test]
fn stacked_cubes_come_out_as_one_box_through_the_contacts() {
    for gap in [0.0, 1e-12, -1e-12, 1e-7, -1e-7, 1e-6] {
        for swap in [false, true] {
            let a = box_mesh([0.0; 3], [1.0; 3]);
            let b = box_mesh([0.0, 0.0, 1.0 + gap], [1.0, 1.0, 2.0]);
            let (a, b) = if swap { (b, a) } else { (a, b) };
            let (out, c) = boolean_mesh_with_contacts(&a, &b, BooleanOp::Union, DELTA).unwrap();
            let s = smooth_mesh_near(&out.mesh, &SmoothOptions::new(DELTA), &c.boxes).unwrap();
            sanity_check_mesh(&s.shape, DELTA).unwrap();
            assert_eq!(shells(&s.shape), 1, "gap {gap}, swap {swap}");
            assert!((s.shape.signed_volume() - 2.0).abs() <= 1e-9 + gap.abs() * 2.0);
        }
    }
}

#[test]
fn spheres_agree_with_whole_smoothing_at_several_tolerances() {
    let a = icosphere([0.0; 3], 1.0, 3);
    let b = icosphere([0.3, 0.2, 0.1], 1.0, 3);
    for op in [
        BooleanOp::Union,
        BooleanOp::Intersection,
        BooleanOp::Difference,
    ] {
        for tol in [1e-9, 1e-4, 1e-3, 2e-2] {
            let opts = SmoothOptions::new(tol);
            let (out, c) = boolean_triangles_with_contacts(&a, &b, op, tol).unwrap();
            let whole = smooth_triangles(&out.mesh, &opts).unwrap();
            let near = smooth_triangles_near(&out.mesh, &opts, &c.boxes).unwrap();
            assert_eq!(
                canonical::triangles(&near.shape),
                canonical::triangles(&whole.shape),
                "{op:?} at {tol}"
            );
            assert_eq!(near.report.counts, whole.report.counts, "{op:?} at {tol}");
        }
    }
}

/// Exact clean-up (tolerance 0) of Booleans that meet in degenerate ways:
/// spheres centred on a cube's corners, their poles on its edges and
/// their meridians in its faces, so the raw outputs hold coincident
/// vertices, which the region path merges and puts back (one of them
/// stays, the one on the cut if any) instead of handing the mesh to whole
/// smoothing. The result is whole smoothing's, with no point moved.
#[test]
fn coincident_vertices_at_degenerate_contacts_are_merged_near_them() {
    let exact = SmoothOptions::new(0.0);
    let mut a = box_triangles([-1.0; 3], [1.0; 3]);
    let mut merged_somewhere = false;
    for (k, r) in [0.3, 0.45, 0.3].into_iter().enumerate() {
        let c = [if k % 2 == 0 { 1.0 } else { -1.0 }, 1.0, -1.0];
        let sphere = uv_sphere(c, r, 16, 8);
        let (out, contacts) =
            boolean_triangles_with_contacts(&a, &sphere, BooleanOp::Difference, 0.0).unwrap();
        let whole = smooth_triangles(&out.mesh, &exact).unwrap();
        let near = smooth_triangles_near(&out.mesh, &exact, &contacts.boxes).unwrap();
        sanity_check_triangles(&near.shape, 0.0).unwrap();
        assert_eq!(
            canonical::triangles(&near.shape),
            canonical::triangles(&whole.shape),
            "step {k}"
        );
        assert_eq!(near.report.counts, whole.report.counts, "step {k}");
        assert_eq!(near.report.distortion_bound, 0.0);
        let volume = |m: &topology::TriangleMesh| m.signed_volume();
        assert!((volume(&near.shape) - volume(&out.mesh)).abs() <= 1e-12 * volume(&out.mesh));
        merged_somewhere |= near.report.counts.vertices_merged > 0;
        a = near.shape;
    }
    assert!(merged_somewhere, "the contacts were not degenerate");
}

#[test]
fn no_contact_keeps_the_mesh_and_a_box_over_everything_is_whole_smoothing() {
    // The doc example of `smooth_mesh`: a sliver pair beside a corner.
    let v = vec![
        [0.0; 3],
        [1.0, 0.0, 0.0],
        [0.0, 1.0, 0.0],
        [0.0, 0.0, 1.0],
        [1e-9, 0.0, 0.0],
    ];
    let mut facets: Vec<Facet> = [[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2]]
        .iter()
        .map(|l| Facet::from_loop(l))
        .collect();
    facets.push(Facet::from_loop(&[0, 4, 1]));
    facets.push(Facet::from_loop(&[1, 4, 0]));
    let mesh = PolygonMesh::new(v, facets);
    let opts = SmoothOptions::new(1e-6);
    let none = smooth_mesh_near(&mesh, &opts, &[]).unwrap();
    assert_eq!(none.shape, mesh);
    assert_eq!(none.report.counts.adjustments(), 0);
    // Garbage boxes (inverted, NaN, far away) meet nothing.
    let garbage: [[Point3; 2]; 3] = [
        [[1.0; 3], [0.0; 3]],
        [[f64::NAN; 3], [f64::NAN; 3]],
        [[10.0; 3], [11.0; 3]],
    ];
    assert_eq!(
        smooth_mesh_near(&mesh, &opts, &garbage).unwrap().shape,
        mesh
    );
    let whole = smooth_mesh(&mesh, &opts).unwrap();
    let everything = [[[-1.0; 3], [2.0; 3]]];
    let near = smooth_mesh_near(&mesh, &opts, &everything).unwrap();
    assert_eq!(
        canonical::mesh_facets(&near.shape),
        canonical::mesh_facets(&whole.shape)
    );
    // Infinite boxes, alone or among others, meet everything.
    let inf = [
        [[f64::NEG_INFINITY; 3], [f64::INFINITY; 3]],
        [[0.5; 3], [0.6; 3]],
        [[f64::NEG_INFINITY, 0.0, 0.0], [0.0, 0.0, 0.0]],
    ];
    for k in 1..=3 {
        let near = smooth_mesh_near(&mesh, &opts, &inf[..k]).unwrap();
        assert_eq!(
            canonical::mesh_facets(&near.shape),
            canonical::mesh_facets(&whole.shape)
        );
    }
    // A box at the sliver alone: the region grows to what smoothing needs.
    let at_sliver = [[[0.0; 3], [1e-9, 0.0, 0.0]]];
    let near = smooth_mesh_near(&mesh, &opts, &at_sliver).unwrap();
    assert_eq!(
        canonical::mesh_facets(&near.shape),
        canonical::mesh_facets(&whole.shape)
    );
    assert_eq!(near.shape.facets.len(), 4);
}

#[test]
fn bad_input_is_refused_and_left_untouched() {
    let good = box_triangles([0.0; 3], [1.0; 3]);
    let boxes = [[[-1.0; 3], [2.0; 3]]];
    let mut dangling = good.clone();
    dangling.triangles[3][1] = 99;
    let copy = dangling.clone();
    let e = smooth_triangles_near(&dangling, &SmoothOptions::new(1e-6), &boxes).unwrap_err();
    assert!(matches!(e, SmoothError::InvalidInput(_)), "{e}");
    assert_eq!(dangling, copy);
    let mut nan = good.clone();
    nan.vertices[2][0] = f64::NAN;
    assert!(matches!(
        smooth_triangles_near(&nan, &SmoothOptions::new(1e-6), &boxes),
        Err(SmoothError::InvalidInput(_))
    ));
    assert!(matches!(
        smooth_triangles_near(&good, &SmoothOptions::new(-1.0), &boxes),
        Err(SmoothError::InvalidTolerance(_))
    ));
    // Open topology inside the region is refused, not returned broken.
    let mut open = good.to_polygon_mesh();
    open.facets.pop();
    let r = smooth_mesh_near(&open, &SmoothOptions::new(1e-6), &boxes);
    assert!(matches!(r, Err(SmoothError::InvalidInput(_))), "{r:?}");
}

#[test]
fn a_dangling_end_alone_is_refused() {
    // The last half-edge of a facet ends at a vertex that does not exist
    // while every start is in range.
    let mut m = box_mesh([0.0; 3], [1.0; 3]);
    let last = m.facets[2].half_edges.len() - 1;
    m.facets[2].half_edges[last].end = 1000;
    let r = smooth_mesh_near(&m, &SmoothOptions::new(1e-6), &[[[-1.0; 3], [2.0; 3]]]);
    assert!(matches!(r, Err(SmoothError::InvalidInput(_))), "{r:?}");
}
