//! Bad input to 3D smoothing: a clear error, never a panic, the input
//! untouched: NaN and huge coordinates, a dangling index, an open mesh or
//! facet, bad tolerances.

use smooth::{smooth_mesh, smooth_triangles, SmoothError, SmoothOptions};
use test_support::shapes::{box_mesh, box_triangles};
use topology::{HalfEdge, TopologyError};

#[test]
fn bad_coordinates_dangling_indices_and_open_meshes_are_refused() {
    let o = SmoothOptions::new(1e-6);
    let mut m = box_mesh([0.0; 3], [1.0; 3]);
    m.vertices[3][1] = f64::NAN;
    let before = format!("{m:?}");
    assert!(matches!(
        smooth_mesh(&m, &o),
        Err(SmoothError::InvalidInput(_))
    ));
    assert_eq!(format!("{m:?}"), before);

    let mut m = box_mesh([0.0; 3], [1.0; 3]);
    m.vertices[0][2] = f64::MAX;
    assert!(matches!(
        smooth_mesh(&m, &o),
        Err(SmoothError::InvalidInput(_))
    ));

    let mut m = box_mesh([0.0; 3], [1.0; 3]);
    m.facets[2].half_edges[0].end = 99;
    let before = m.clone();
    assert!(matches!(
        smooth_mesh(&m, &o),
        Err(SmoothError::InvalidInput(
            TopologyError::DanglingIndex { .. }
        ))
    ));
    assert_eq!(m, before);

    let mut m = box_mesh([0.0; 3], [1.0; 3]);
    m.facets.pop();
    assert!(matches!(
        smooth_mesh(&m, &o),
        Err(SmoothError::InvalidInput(
            TopologyError::ShapeClosure3 { .. }
        ))
    ));

    let mut m = box_mesh([0.0; 3], [1.0; 3]);
    m.facets[0].half_edges.push(HalfEdge { start: 0, end: 7 });
    assert!(matches!(
        smooth_mesh(&m, &o),
        Err(SmoothError::InvalidInput(
            TopologyError::FacetClosure { .. }
        ))
    ));

    let mut t = box_triangles([0.0; 3], [1.0; 3]);
    t.triangles[0][1] = 8;
    let before = t.clone();
    assert!(matches!(
        smooth_triangles(&t, &o),
        Err(SmoothError::InvalidInput(_))
    ));
    assert_eq!(t, before);
    let mut t = box_triangles([0.0; 3], [1.0; 3]);
    t.vertices[5][0] = f64::INFINITY;
    assert!(matches!(
        smooth_triangles(&t, &o),
        Err(SmoothError::InvalidInput(_))
    ));
}

#[test]
fn bad_tolerances_are_refused() {
    let m = box_mesh([0.0; 3], [1.0; 3]);
    let t = box_triangles([0.0; 3], [1.0; 3]);
    for tol in [f64::NAN, -1e-9, f64::INFINITY] {
        let o = SmoothOptions::new(tol);
        assert!(matches!(
            smooth_mesh(&m, &o),
            Err(SmoothError::InvalidTolerance(_))
        ));
        assert!(matches!(
            smooth_triangles(&t, &o),
            Err(SmoothError::InvalidTolerance(_))
        ));
    }
}

#[test]
fn empty_and_clean_meshes_pass_through() {
    let o = SmoothOptions::new(1e-6);
    let empty = topology::PolygonMesh::default();
    let out = smooth_mesh(&empty, &o).unwrap();
    assert_eq!(out.shape, empty);
    let m = box_mesh([0.0; 3], [1.0; 3]);
    let out = smooth_mesh(&m, &o).unwrap();
    assert_eq!(out.shape, m, "a clean box is left as it is");
    assert_eq!(out.report.counts.adjustments(), 0);
    assert_eq!(out.report.distortion_bound, 0.0);
    let t = box_triangles([0.0; 3], [1.0; 3]);
    let out = smooth_triangles(&t, &o).unwrap();
    assert_eq!(out.shape, t);
    assert_eq!(out.report.counts.facets_retriangulated, 0);
    // Zero tolerance keeps only the exact operations.
    let out = smooth_mesh(&m, &SmoothOptions::new(0.0)).unwrap();
    assert_eq!(out.shape, m);
}

#[test]
fn a_tiny_budget_stops_early_with_a_valid_shape_and_says_so() {
    // Two unit cubes stacked with a 1e-9 gap: merging alone is 4
    // adjustments, so a budget of 2 stops the loops that follow.
    let (mut v, mut f) = (Vec::new(), Vec::new());
    test_support::shapes::push_box(&mut v, &mut f, [0.0; 3], [1.0; 3], false);
    test_support::shapes::push_box(
        &mut v,
        &mut f,
        [0.0, 0.0, 1.0 + 1e-9],
        [1.0, 1.0, 2.0],
        false,
    );
    let m = topology::PolygonMesh::new(v, f);
    let o = SmoothOptions {
        tolerance: 1e-6,
        budget: Some(2),
        guard: false,
    };
    let out = smooth_mesh(&m, &o).unwrap();
    assert!(out.report.budget_hit);
    out.shape.check_topology().unwrap();
    // The default budget is never hit: the shared face cancels.
    let out = smooth_mesh(&m, &SmoothOptions::new(1e-6)).unwrap();
    assert!(!out.report.budget_hit);
    assert_eq!(out.report.counts.facets_cancelled, 1);
    assert!(out.shape.manifold_report().unwrap().is_two_manifold());
}
