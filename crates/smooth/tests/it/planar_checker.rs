//! The 2D sanity checker finds each defect it names (so the tests that
//! rely on it can fail), and passes clean sets.

use smooth::{sanity_check_polygon_set, PlanarDefect};
use topology::{Edge2, PolygonSet2};

fn set(rings: &[&[[f64; 2]]]) -> PolygonSet2 {
    let mut s = PolygonSet2::new();
    for r in rings {
        s.add_loop(r);
    }
    s
}

const SQ: [[f64; 2]; 4] = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
const TOL: f64 = 1e-3;

#[test]
fn clean_sets_pass() {
    sanity_check_polygon_set(&set(&[&SQ]), TOL).unwrap();
    // A square with a square hole, and an empty set.
    let hole = [[0.25, 0.25], [0.25, 0.75], [0.75, 0.75], [0.75, 0.25]];
    sanity_check_polygon_set(&set(&[&SQ, &hole]), TOL).unwrap();
    sanity_check_polygon_set(&PolygonSet2::new(), TOL).unwrap();
}

#[test]
fn each_defect_is_found() {
    let check = |s: &PolygonSet2| sanity_check_polygon_set(s, TOL).unwrap_err();
    let mut cw = SQ;
    cw.reverse();
    assert!(matches!(
        check(&set(&[&cw])),
        PlanarDefect::Winding {
            left: 0,
            right: -1,
            ..
        } | PlanarDefect::Winding {
            left: -1,
            right: 0,
            ..
        }
    ));
    let inner = [[0.25, 0.25], [0.75, 0.25], [0.75, 0.75], [0.25, 0.75]];
    assert!(matches!(
        check(&set(&[&SQ, &inner])),
        PlanarDefect::Winding { .. }
    ));
    // An edge shorter than TOL.
    let pair = [
        [0.0, 0.0],
        [1.0, 0.0],
        [1.0, 1.0],
        [1.0, 1.0 + 0.5 * TOL],
        [0.0, 1.0],
    ];
    assert!(matches!(
        check(&set(&[&pair])),
        PlanarDefect::ShortEdge { edge: 2 }
    ));
    // Corners of two squares within TOL of each other.
    let right = [
        [1.0 + 0.5 * TOL, 0.0],
        [2.0, 0.0],
        [2.0, 1.0],
        [1.0 + 0.5 * TOL, 1.0],
    ];
    assert!(matches!(
        check(&set(&[&SQ, &right])),
        PlanarDefect::CloseVertices { .. }
    ));
    // A notch whose tip lies within TOL of the opposite side's interior.
    let notch = [
        [0.0, 0.0],
        [1.0, 0.0],
        [1.0, 1.0],
        [0.6, 1.0],
        [0.5, 0.5 * TOL],
        [0.4, 1.0],
        [0.0, 1.0],
    ];
    assert!(matches!(
        check(&set(&[&notch])),
        PlanarDefect::VertexNearEdge { .. }
    ));
    let bow = [[0.0, 0.0], [1.0, 1.0], [1.0, 0.0], [0.0, 1.0]];
    assert!(matches!(
        check(&set(&[&bow])),
        PlanarDefect::Crossing { .. }
    ));
    let double = PolygonSet2::from_parts(
        SQ.to_vec(),
        (0..4)
            .map(|i| Edge2 {
                start: i,
                end: (i + 1) % 4,
                mult: 2,
            })
            .collect(),
    );
    assert!(matches!(
        check(&double),
        PlanarDefect::Multiplicity { edge: 0 }
    ));
    let open = PolygonSet2::from_parts(
        SQ.to_vec(),
        vec![Edge2 {
            start: 0,
            end: 1,
            mult: 1,
        }],
    );
    assert!(matches!(check(&open), PlanarDefect::Topology(_)));
    assert!(!check(&open).to_string().is_empty());
}
