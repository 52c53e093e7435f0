//! The 2D Boolean against independent oracles: the winding-number identity
//! of eq. 4.20 at sample points away from every input edge (windings by an
//! exact rational orientation test), exact areas of integer rectilinear
//! inputs (against a unit-cell count of eq. 4.20), touching and coincident
//! edges in both argument orders, `A op A`, figure 4.9 (an inside-out
//! region), the rotated n-gon of Table 7.4 (one ring of `4n` vertices) and
//! bad input.

use boolean_2d::{boolean, boolean_audit, BooleanError, BooleanOp, Operand};
use proptest::prelude::*;
use test_support::exact::winding;
use test_support::shapes::{regular_ngon, square};
use topology::{Edge2, PolygonSet2, TopologyError};

fn set_from(loops: &[Vec<[f64; 2]>]) -> PolygonSet2 {
    let mut set = PolygonSet2::new();
    for l in loops {
        set.add_loop(l);
    }
    set
}

/// Distance from `p` to the segment `s t` (f64; only used to keep sample
/// points clear of edges).
fn distance(p: [f64; 2], s: [f64; 2], t: [f64; 2]) -> f64 {
    let (dx, dy) = (t[0] - s[0], t[1] - s[1]);
    let len2 = dx * dx + dy * dy;
    let u = if len2 > 0.0 {
        (((p[0] - s[0]) * dx + (p[1] - s[1]) * dy) / len2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    let (cx, cy) = (s[0] + u * dx - p[0], s[1] + u * dy - p[1]);
    (cx * cx + cy * cy).sqrt()
}

fn clear_of(set: &PolygonSet2, p: [f64; 2], gap: f64) -> bool {
    set.edges().iter().all(|e| {
        let (s, t) = set.edge_points(e);
        distance(p, s, t) > gap
    })
}

/// Asserts eq. 4.20 at every sample point clear of both operands' edges.
fn check_identity(
    a: &PolygonSet2,
    b: &PolygonSet2,
    samples: &[[f64; 2]],
) -> Result<usize, TestCaseError> {
    let mut checked = 0;
    for op in BooleanOp::ALL {
        let out = boolean(a, b, op).expect("valid input");
        prop_assert!(out.shape.check_topology().is_ok());
        for &p in samples {
            if !(clear_of(a, p, 1e-9) && clear_of(b, p, 1e-9)) {
                continue;
            }
            let (wa, wb) = (winding(p, a), winding(p, b));
            let want = op.result_winding(wa, wb);
            let got = winding(p, &out.shape);
            prop_assert_eq!(got, want, "{:?} at {:?}: w_A = {}, w_B = {}", op, p, wa, wb);
            checked += 1;
        }
    }
    Ok(checked)
}

fn unit_loops() -> impl Strategy<Value = Vec<Vec<[f64; 2]>>> {
    proptest::collection::vec(
        proptest::collection::vec(
            (-1.0f64..1.0, -1.0f64..1.0).prop_map(|(x, y)| [x, y]),
            3..10,
        ),
        1..3,
    )
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(test_support::cases(48)))]

    /// eq. 4.20 on random (mostly self-intersecting) polygons, whose
    /// winding numbers range well outside {0, 1} (section 4.7).
    #[test]
    fn winding_identity_on_random_polygons(
        a in unit_loops(),
        b in unit_loops(),
        samples in proptest::collection::vec((-1.1f64..1.1, -1.1f64..1.1).prop_map(|(x, y)| [x, y]), 40),
    ) {
        check_identity(&set_from(&a), &set_from(&b), &samples)?;
    }

    /// Exact areas of integer rectangles (every crossing of axis-parallel
    /// edges is exact in Table 7.2): the signed area of the result equals
    /// the sum over unit cells of eq. 4.20's winding number, computed from
    /// the operands alone.
    #[test]
    fn exact_areas_of_integer_rectangles(
        ra in proptest::collection::vec((0i32..8, 0i32..8, 1i32..5, 1i32..5, any::<bool>()), 1..4),
        rb in proptest::collection::vec((0i32..8, 0i32..8, 1i32..5, 1i32..5, any::<bool>()), 1..4),
    ) {
        let rects = |r: &[(i32, i32, i32, i32, bool)]| {
            let loops: Vec<Vec<[f64; 2]>> = r
                .iter()
                .map(|&(x, y, w, h, ccw)| {
                    let (x0, y0, x1, y1) = (f64::from(x), f64::from(y), f64::from(x + w), f64::from(y + h));
                    let mut l = vec![[x0, y0], [x1, y0], [x1, y1], [x0, y1]];
                    if !ccw {
                        l.reverse();
                    }
                    l
                })
                .collect();
            set_from(&loops)
        };
        let (a, b) = (rects(&ra), rects(&rb));
        for op in BooleanOp::ALL {
            for (p, q) in [(&a, &b), (&b, &a)] {
                let out = boolean(p, q, op).expect("valid input");
                prop_assert!(out.shape.check_topology().is_ok());
                let mut want = 0i64;
                for i in 0..13 {
                    for j in 0..13 {
                        let c = [f64::from(i) + 0.5, f64::from(j) + 0.5];
                        want += op.result_winding(winding(c, p), winding(c, q));
                    }
                }
                prop_assert_eq!(out.shape.signed_area(), want as f64, "{:?}", op);
            }
        }
    }
}

#[test]
fn touching_squares_in_both_orders() {
    // Side by side (a shared edge), corner to corner, and one inside the
    // other sharing two sides.
    let cases = [
        (
            square(0.0, 0.0, 1.0),
            square(1.0, 0.0, 1.0),
            [2.0, 0.0, 1.0],
        ),
        (
            square(0.0, 0.0, 1.0),
            square(1.0, 1.0, 1.0),
            [2.0, 0.0, 1.0],
        ),
        (
            square(0.0, 0.0, 2.0),
            square(0.0, 0.0, 1.0),
            [4.0, 1.0, 3.0],
        ),
    ];
    for (sa, sb, [union, inter, diff]) in cases {
        let (a, b) = (set_from(&[sa]), set_from(&[sb]));
        for (p, q, forward) in [(&a, &b, true), (&b, &a, false)] {
            let (out, data) = boolean_audit(p, q, BooleanOp::Union).unwrap();
            assert!(out.shape.check_topology().is_ok());
            assert!(data.composite_counts.iter().all(|(s, e)| s == e));
            assert_eq!(out.shape.signed_area(), union);
            let out = boolean(p, q, BooleanOp::Intersection).unwrap();
            assert_eq!(out.shape.signed_area(), inter);
            let out = boolean(p, q, BooleanOp::Difference).unwrap();
            let d = if forward {
                diff
            } else {
                p.signed_area() - inter
            };
            assert_eq!(out.shape.signed_area(), d);
            assert!(out.shape.check_topology().is_ok());
        }
    }
    // The union of side-by-side squares keeps no net part of the shared
    // edge: the basic Boolean may retain both copies (A's upward, B's
    // downward; section 4.6 decides each by symbolic perturbation), but
    // their multiplicities cancel, so the winding number is continuous
    // across x = 1.
    let out = boolean(
        &set_from(&[square(0.0, 0.0, 1.0)]),
        &set_from(&[square(1.0, 0.0, 1.0)]),
        BooleanOp::Union,
    )
    .unwrap();
    let net: i32 = out
        .shape
        .edges()
        .iter()
        .filter_map(|e| {
            let (s, t) = out.shape.edge_points(e);
            (s[0] == 1.0 && t[0] == 1.0 && s[1].min(t[1]) < 0.5 && s[1].max(t[1]) > 0.5)
                .then(|| if t[1] > s[1] { e.mult } else { -e.mult })
        })
        .sum();
    assert_eq!(net, 0);
    assert_eq!(winding([0.9, 0.5], &out.shape), 1);
    assert_eq!(winding([1.1, 0.5], &out.shape), 1);
}

#[test]
fn a_op_a_and_its_reverse() {
    let a = set_from(&[
        vec![[0.0, 0.0], [3.0, 0.5], [2.0, 2.0], [0.5, 3.0]],
        square(5.0, 5.0, 1.0),
    ]);
    let area = a.signed_area();
    let union = boolean(&a, &a, BooleanOp::Union).unwrap();
    assert_eq!(union.shape.signed_area(), area);
    let inter = boolean(&a, &a, BooleanOp::Intersection).unwrap();
    assert_eq!(inter.shape.signed_area(), area);
    let diff = boolean(&a, &a, BooleanOp::Difference).unwrap();
    assert_eq!(diff.shape.signed_area(), 0.0);
    for out in [&union, &inter, &diff] {
        assert!(out.shape.check_topology().is_ok());
    }
    // A and its reverse: union is the plane's winding a + (-a) - a(-a) ...
    // checked by eq. 4.20 at samples.
    let r = a.reversed();
    let samples: Vec<[f64; 2]> = (0..30)
        .flat_map(|i| (0..30).map(move |j| [f64::from(i) * 0.23 - 0.1, f64::from(j) * 0.23 - 0.1]))
        .collect();
    assert!(check_identity(&a, &r, &samples).unwrap() > 0);
}

/// Figure 4.9: the union of a rectangle with a shape that has an inside-out
/// region across the rectangle's bottom edge keeps that part of the edge
/// twice (winding -1 below it, +1 above it).
#[test]
fn figure_4_9_inside_out_region() {
    let a = set_from(&[vec![[0.0, 0.0], [4.0, 0.0], [4.0, 2.0], [0.0, 2.0]]]);
    // A figure-8 crossing itself at (4.5, 0): the left lobe (over A's bottom
    // edge) is clockwise, i.e. inside out; the right lobe counter-clockwise.
    let b = set_from(&[vec![[1.0, -1.0], [1.0, 1.0], [8.0, -1.0], [8.0, 1.0]]]);
    assert_eq!(winding([2.0, 0.5], &b), -1);
    assert_eq!(winding([7.0, 0.0], &b), 1);
    let (out, data) = boolean_audit(&a, &b, BooleanOp::Union).unwrap();
    assert!(out.shape.check_topology().is_ok());
    assert!(data.composite_counts.iter().all(|(s, e)| s == e));
    assert_eq!(winding([2.0, -0.2], &out.shape), -1);
    assert_eq!(winding([2.0, 0.2], &out.shape), 1);
    // The retained part of the bottom edge is represented twice: the
    // multiplicities of result edges on y = 0 covering x = 2 add up to 2.
    let covering: i32 = out
        .shape
        .edges()
        .iter()
        .filter_map(|e| {
            let (s, t) = out.shape.edge_points(e);
            (s[1] == 0.0 && t[1] == 0.0 && s[0].min(t[0]) < 2.0 && s[0].max(t[0]) > 2.0)
                .then(|| if t[0] > s[0] { e.mult } else { -e.mult })
        })
        .sum();
    assert_eq!(covering, 2);
    let samples: Vec<[f64; 2]> = (0..40)
        .flat_map(|i| (0..20).map(move |j| [f64::from(i) * 0.23 - 0.3, f64::from(j) * 0.23 - 1.6]))
        .collect();
    assert!(check_identity(&a, &b, &samples).unwrap() > 0);
}

fn ngon(n: usize, alpha_degrees: f64) -> PolygonSet2 {
    set_from(&[regular_ngon(n, 1.0, alpha_degrees)])
}

/// Table 7.4: the union of a regular n-gon with a copy rotated by a tiny
/// angle is one ring of exactly `4n` vertices, for every alpha.
#[test]
fn table_7_4_rotated_ngon_union() {
    let n = 1000;
    for alpha in [1.0, 1e-1, 1e-3, 1e-5, 1e-7, 1.581e-9] {
        let out = boolean(&ngon(n, 0.0), &ngon(n, alpha), BooleanOp::Union).unwrap();
        assert!(out.shape.check_topology().is_ok());
        let loops = out.shape.loops();
        assert_eq!(loops.len(), 1, "alpha = {alpha}");
        assert_eq!(loops[0].len(), 4 * n, "alpha = {alpha}");
        assert_eq!(out.intersections, 2 * n, "alpha = {alpha}");
    }
}

#[test]
fn bad_input_names_the_operand_and_constraint() {
    let good = set_from(&[square(0.0, 0.0, 1.0)]);
    let mut nan = set_from(&[square(0.0, 0.0, 1.0)]);
    nan.add_vertex([f64::NAN, 0.0]);
    let inf = set_from(&[vec![[0.0, 0.0], [f64::INFINITY, 0.0], [1.0, 1.0]]]);
    let huge = set_from(&[vec![[0.0, 0.0], [f64::MAX, 0.0], [1.0, 1.0]]]);
    let dangling = PolygonSet2::from_parts(
        vec![[0.0, 0.0], [1.0, 0.0]],
        vec![
            Edge2 {
                start: 0,
                end: 1,
                mult: 1,
            },
            Edge2 {
                start: 1,
                end: 7,
                mult: 1,
            },
        ],
    );
    let open = PolygonSet2::from_parts(
        vec![[0.0, 0.0], [1.0, 0.0], [1.0, 1.0]],
        vec![
            Edge2 {
                start: 0,
                end: 1,
                mult: 1,
            },
            Edge2 {
                start: 1,
                end: 2,
                mult: 1,
            },
        ],
    );
    for bad in [&nan, &inf, &huge, &dangling, &open] {
        for op in BooleanOp::BASIC {
            for (p, q, which) in [(bad, &good, Operand::A), (&good, bad, Operand::B)] {
                let before = (p.clone(), q.clone());
                match boolean(p, q, op) {
                    Err(BooleanError::InvalidInput { operand, source }) => {
                        assert_eq!(operand, which);
                        let text = source.to_string();
                        assert!(!text.is_empty());
                        match source {
                            TopologyError::DanglingIndex { vertex, .. } => assert_eq!(vertex, 7),
                            TopologyError::ShapeClosure2 { .. } => {
                                assert!(std::ptr::eq(bad, &open))
                            }
                            TopologyError::BadCoordinate { .. } => {}
                            other => panic!("unexpected error {other:?}"),
                        }
                    }
                    other => panic!("expected InvalidInput, got {other:?}"),
                }
                let bits = |s: &PolygonSet2| -> Vec<[u64; 2]> {
                    s.vertices()
                        .iter()
                        .map(|v| [v[0].to_bits(), v[1].to_bits()])
                        .collect()
                };
                assert_eq!(bits(p), bits(&before.0), "caller's data untouched");
                assert_eq!(bits(q), bits(&before.1));
                assert_eq!(p.edges(), before.0.edges());
                assert_eq!(q.edges(), before.1.edges());
            }
        }
    }
}
