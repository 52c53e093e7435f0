//! Bad input to 2D smoothing: the right `SmoothError`, never a panic, and
//! the caller's set untouched.

use smooth::{smooth_polygon_set, SmoothError, SmoothOptions};
use topology::{Edge2, PolygonSet2, TopologyError};

fn triangle() -> PolygonSet2 {
    let mut s = PolygonSet2::new();
    s.add_loop(&[[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]);
    s
}

fn refused(s: &PolygonSet2, tol: f64) -> SmoothError {
    // Bit patterns (NaN is not equal to itself).
    let bits = |s: &PolygonSet2| {
        let v: Vec<[u64; 2]> = s.vertices().iter().map(|p| p.map(f64::to_bits)).collect();
        (v, s.edges().to_vec())
    };
    let before = bits(s);
    let e = smooth_polygon_set(s, &SmoothOptions::new(tol)).expect_err("refused");
    assert_eq!(bits(s), before, "input untouched");
    assert!(!e.to_string().is_empty());
    e
}

#[test]
fn non_finite_and_too_large_coordinates() {
    for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY, f64::MAX / 2.0] {
        let mut pts = triangle().vertices().to_vec();
        pts[1][1] = bad;
        let s = PolygonSet2::from_parts(pts, triangle().edges().to_vec());
        let e = refused(&s, 1e-6);
        assert!(matches!(e, SmoothError::InvalidInput(_)), "{e:?}");
        assert!(std::error::Error::source(&e).is_some());
    }
}

#[test]
fn dangling_index_and_open_set() {
    let t = triangle();
    let mut edges = t.edges().to_vec();
    edges.push(Edge2 {
        start: 2,
        end: 9,
        mult: 1,
    });
    let s = PolygonSet2::from_parts(t.vertices().to_vec(), edges);
    assert!(matches!(
        refused(&s, 1e-6),
        SmoothError::InvalidInput(TopologyError::DanglingIndex { vertex: 9, .. })
    ));
    let mut open = PolygonSet2::from_parts(t.vertices().to_vec(), t.edges()[..2].to_vec());
    assert!(matches!(
        refused(&open, 1e-6),
        SmoothError::InvalidInput(TopologyError::ShapeClosure2 { .. })
    ));
    // Multiplicities that do not balance.
    open = PolygonSet2::from_parts(
        t.vertices().to_vec(),
        vec![
            Edge2 {
                start: 0,
                end: 1,
                mult: 2,
            },
            Edge2 {
                start: 1,
                end: 2,
                mult: 1,
            },
            Edge2 {
                start: 2,
                end: 0,
                mult: 1,
            },
        ],
    );
    assert!(matches!(refused(&open, 1e-6), SmoothError::InvalidInput(_)));
}

#[test]
fn bad_tolerances() {
    let t = triangle();
    for tol in [f64::NAN, -1e-9, f64::INFINITY, f64::NEG_INFINITY] {
        assert!(matches!(refused(&t, tol), SmoothError::InvalidTolerance(_)));
    }
}

#[test]
fn bad_tolerance_is_reported_before_bad_coordinates() {
    let mut pts = triangle().vertices().to_vec();
    pts[0][0] = f64::NAN;
    let s = PolygonSet2::from_parts(pts, triangle().edges().to_vec());
    assert!(matches!(
        refused(&s, -1.0),
        SmoothError::InvalidTolerance(_)
    ));
}

#[test]
fn empty_and_degenerate_valid_sets_are_fine() {
    let opts = SmoothOptions::new(1e-6);
    let empty = smooth_polygon_set(&PolygonSet2::new(), &opts).unwrap();
    assert!(empty.shape.is_empty());
    // A loop of one vertex (a zero-length edge) and unreferenced vertices.
    let mut s = PolygonSet2::new();
    let v = s.add_vertex([1.0, 2.0]);
    s.add_vertex([5.0, 5.0]);
    s.add_edge(v, v);
    let out = smooth_polygon_set(&s, &opts).unwrap();
    assert!(out.shape.is_empty() && out.shape.vertex_count() == 0);
    assert_eq!(out.report.counts.zero_length_edges_removed, 1);
    assert_eq!(out.report.counts.unreferenced_vertices_removed, 2);
}

#[test]
fn a_budget_of_zero_is_reported_and_the_result_stays_valid() {
    let mut s = triangle();
    s.add_loop(&[[1e-9, 0.0], [0.0, 1.0], [1.0, 0.0]]); // nearly the reverse
    let opts = SmoothOptions {
        tolerance: 1e-6,
        budget: Some(0),
        guard: false,
    };
    let out = smooth_polygon_set(&s, &opts).unwrap();
    assert!(out.report.budget_hit);
    out.shape.check_topology().unwrap();
}
