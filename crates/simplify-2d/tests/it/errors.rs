//! Bad input gets a clear error; garbage that satisfies closure never makes
//! the sweep panic and always gives a valid cell structure.

use crate::common;
use proptest::prelude::*;
use simplify_2d::*;
use topology::{Edge2, PolygonSet2, TopologyError};

#[test]
fn non_finite_and_out_of_range_coordinates_are_rejected() {
    for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY, f64::MAX] {
        let mut s = PolygonSet2::new();
        s.add_loop(&[[0.0, 0.0], [1.0, bad], [0.0, 1.0]]);
        let err = simplify(&s, FillRule::Positive).unwrap_err();
        assert!(
            matches!(
                err,
                SimplifyError::InvalidInput {
                    operand: 0,
                    source: TopologyError::BadCoordinate {
                        vertex: 1,
                        axis: 1,
                        ..
                    }
                }
            ),
            "{err}"
        );
        assert!(err.to_string().contains("vertex 1"));
        let ok = common::polygon(&[[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]);
        assert!(matches!(
            boolean(&ok, &s, BooleanOp::Union),
            Err(SimplifyError::InvalidInput { operand: 1, .. })
        ));
    }
}

#[test]
fn open_and_dangling_input_is_rejected() {
    let open = PolygonSet2::from_parts(
        vec![[0.0, 0.0], [1.0, 0.0]],
        vec![Edge2 {
            start: 0,
            end: 1,
            mult: 1,
        }],
    );
    assert!(matches!(
        cell_structure(&open),
        Err(SimplifyError::InvalidInput {
            source: TopologyError::ShapeClosure2 { .. },
            ..
        })
    ));
    let dangling = PolygonSet2::from_parts(
        vec![[0.0, 0.0]],
        vec![Edge2 {
            start: 0,
            end: 7,
            mult: 1,
        }],
    );
    assert!(matches!(
        union_all(&[dangling]),
        Err(SimplifyError::InvalidInput {
            source: TopologyError::DanglingIndex { .. },
            ..
        })
    ));
}

#[test]
fn empty_and_degenerate_input() {
    let empty = PolygonSet2::new();
    let out = simplify(&empty, FillRule::Positive).unwrap();
    assert!(out.shape.is_empty());
    assert_eq!(out.k_max, 0);
    // A loop of coincident points and a zero-area sliver.
    let s = common::polygon(&[[1.0, 1.0], [1.0, 1.0], [1.0, 1.0]]);
    assert!(simplify(&s, FillRule::NonZero).unwrap().shape.is_empty());
    let s = common::polygon(&[[0.0, 0.0], [1.0, 1.0], [2.0, 2.0]]);
    let c = cell_structure(&s).unwrap();
    c.check_cells().unwrap();
    // The long edge is split at (1, 1) (section 6.5); the identical parts
    // co-exist on the sweep line (section 7.4.2) and cancel on output.
    assert!(c.arrangement().is_empty());
    // Extreme magnitudes side by side.
    let s = common::polygon(&[
        [-1e300, 0.0],
        [1e300, 1e-300],
        [0.0, 1e300],
        [5e-324, -1e300],
    ]);
    let c = cell_structure(&s).unwrap();
    c.check_cells().unwrap();
    assert!(c.epsilon().is_finite());
}

fn coord() -> impl Strategy<Value = f64> {
    prop_oneof![
        (-4i32..4).prop_map(f64::from),
        any::<f64>().prop_filter("finite", |v| v.is_finite() && v.abs() <= f64::MAX / 4.0),
        (-1.0f64..1.0),
        (-1.0f64..1.0).prop_map(|v| v * 1e-300),
        (-1.0f64..1.0).prop_map(|v| 1.5 * 562_949_953_421_312.0 + v * 8.0),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig { cases: test_support::cases(256), ..ProptestConfig::default() })]

    /// Random coordinates of any magnitude, repeated vertices, zero-length
    /// edges, multiplicities of any sign: closure holds by construction, so
    /// the result must be a valid cell structure and valid shapes.
    #[test]
    fn garbage_never_panics(
        loops in proptest::collection::vec(
            (proptest::collection::vec((coord(), coord()), 1..=8), -3i32..=3),
            1..=4,
        )
    ) {
        let mut s = PolygonSet2::new();
        for (pts, mult) in &loops {
            let first = s.vertex_count() as u32;
            let k = pts.len() as u32;
            for &(x, y) in pts {
                s.add_vertex([x, y]);
            }
            for i in 0..k {
                s.add_edge_mult(first + i, first + (i + 1) % k, *mult);
            }
        }
        let c = cell_structure(&s).unwrap();
        c.check_cells().unwrap();
        for rule in [FillRule::Positive, FillRule::EvenOdd, FillRule::Custom(|w| w == -2 || w == 3)] {
            let out = c.shape_with(|w| rule.contains(*w));
            prop_assert!(out.check_topology().is_ok());
            prop_assert!(out.validate_coordinates().is_ok());
        }
        let half = s.clone();
        for op in [BooleanOp::Union, BooleanOp::Xor] {
            prop_assert!(boolean(&s, &half.reversed(), op).unwrap().shape.check_topology().is_ok());
        }
    }
}
