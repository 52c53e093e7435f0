//! Property tests of levels 0-1 (Table 4.1, eq. 4.1) over three input
//! generators: random floats in `[-1, 1]`, a small integer grid (exact ties
//! everywhere: shared x, vertices on edges, vertical and degenerate edges)
//! and garbage (mixed magnitudes from `1e-300` to `1e300`, repeated values).
//!
//! - Theorem 1 at level 1: a non-zero `X01`/`X10` always has one level-0
//!   pair where B shadows A and one where A shadows B.
//! - Half-edge reversal negates every function and keeps the points.
//! - On the integer grid every function equals its exact definition
//!   (evaluated in `i128`, ties to B, eq. 4.1).
//! - The level-1 point lies on the edge's end exactly when it shares that
//!   end's x, inside the edge's bounding box otherwise, and the 2D and 3D
//!   forms agree.

use proptest::prelude::*;
use shadow_1d::{s00, s01, s10, x00, x01, x10};
use test_support::strategies::{float_coord, garbage_coord, grid_coord};

type P = [f64; 2];

fn point(c: BoxedStrategy<f64>) -> impl Strategy<Value = P> {
    [c.clone(), c]
}

/// A vertex and an edge from one generator.
fn vertex_edge(c: BoxedStrategy<f64>) -> impl Strategy<Value = (P, P, P)> {
    (point(c.clone()), point(c.clone()), point(c))
}

fn any_vertex_edge() -> impl Strategy<Value = (P, P, P)> {
    prop_oneof![
        vertex_edge(float_coord()),
        vertex_edge(grid_coord(4)),
        vertex_edge(garbage_coord()),
        // A vertex sharing x with an end of the edge.
        (point(grid_coord(4)), point(float_coord()), 0usize..2).prop_map(|(s, e, k)| {
            let v = [if k == 0 { s[0] } else { e[0] }, e[1]];
            (v, s, e)
        }),
    ]
}

/// Theorem 1 at level 1: the level-0 pairs of `X01(v, e)` are `(v, v_e)`
/// and `(v, v_s)`, and B shadows A in x when `S00 = 1`.
fn check_theorem_1(v: P, s: P, e: P) -> Result<(), TestCaseError> {
    for (value, name) in [
        (x01(&v, &s, &e).map(|h| h.value), "X01"),
        (x10(&s, &e, &v).map(|h| h.value), "X10"),
    ] {
        if let Some(value) = value {
            prop_assert!(value != 0);
            // The lower pairs are (v, s) and (v, e) in one role order or
            // the other; in X10 the edge is A, so "B shadows A" is
            // x_v >= x_end.
            let (b_shadows_a, a_shadows_b) = if name == "X01" {
                (
                    s00(&v, &s) == 1 || s00(&v, &e) == 1,
                    s00(&v, &s) == 0 || s00(&v, &e) == 0,
                )
            } else {
                (
                    s00(&s, &v) == 1 || s00(&e, &v) == 1,
                    s00(&s, &v) == 0 || s00(&e, &v) == 0,
                )
            };
            prop_assert!(
                b_shadows_a && a_shadows_b,
                "{} = {} without both partners: {:?} {:?} {:?}",
                name,
                value,
                v,
                s,
                e
            );
            prop_assert!(value.abs() == 1);
        }
    }
    Ok(())
}

/// Exact integers of a grid point.
fn gi(p: P) -> [i128; 2] {
    [p[0] as i128, p[1] as i128]
}

/// Exact `X01` on integer coordinates (Table 4.1 with `S00 = [x_B >= x_A]`).
fn exact_x01(v: [i128; 2], s: [i128; 2], e: [i128; 2]) -> i32 {
    i32::from(e[0] >= v[0]) - i32::from(s[0] >= v[0])
}

/// Exact `X10`.
fn exact_x10(s: [i128; 2], e: [i128; 2], v: [i128; 2]) -> i32 {
    -i32::from(v[0] >= e[0]) + i32::from(v[0] >= s[0])
}

/// Exact comparison of the edge's y at `x = v.x` with `v.y`: sign of
/// `y_edge(x_v) - y_v` (the edge is not vertical).
fn exact_edge_minus_vertex(v: [i128; 2], s: [i128; 2], e: [i128; 2]) -> i128 {
    // y_edge = y_s + (x_v - x_s)(y_e - y_s)/(x_e - x_s); multiply through
    // by (x_e - x_s) and correct the sign.
    let dx = e[0] - s[0];
    let num = (s[1] - v[1]) * dx + (v[0] - s[0]) * (e[1] - s[1]);
    num.signum() * dx.signum()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(test_support::cases(1024)))]

    #[test]
    fn theorem_1_at_level_1((v, s, e) in any_vertex_edge()) {
        check_theorem_1(v, s, e)?;
        prop_assert_eq!(x00(&v, &s), 1);
    }

    /// Section 4.5: a backward half-edge negates every function; the
    /// intersection points are identical.
    #[test]
    fn reversal_negates_and_keeps_points((v, s, e) in any_vertex_edge()) {
        let (f, r) = (x01(&v, &s, &e), x01(&v, &e, &s));
        prop_assert_eq!(f.map(|h| h.value), r.map(|h| -h.value));
        prop_assert_eq!(f.map(|h| (h.a, h.b)), r.map(|h| (h.a, h.b)));
        let (f, r) = (x10(&s, &e, &v), x10(&e, &s, &v));
        prop_assert_eq!(f.map(|h| h.value), r.map(|h| -h.value));
        prop_assert_eq!(f.map(|h| (h.a, h.b)), r.map(|h| (h.a, h.b)));
        prop_assert_eq!(s01(&v, &s, &e), -s01(&v, &e, &s));
        prop_assert_eq!(s10(&s, &e, &v), -s10(&e, &s, &v));
    }

    /// The level-1 point: `a` is the vertex (X01) or `b` is (X10), the
    /// other shares its x exactly, lies in the edge's bounding box, and is
    /// the edge's end point when it shares that end's x. The 3D form of the
    /// same data gives the same x and y.
    #[test]
    fn level_1_points((v, s, e) in any_vertex_edge(), zs in -1.0f64..1.0, ze in -1.0f64..1.0) {
        if let Some(h) = x01(&v, &s, &e) {
            prop_assert_eq!(h.a, v);
            prop_assert_eq!(h.b[0], v[0]);
            prop_assert!(h.b[1] >= s[1].min(e[1]) && h.b[1] <= s[1].max(e[1]));
            for end in [s, e] {
                if end[0] == v[0] {
                    prop_assert_eq!(h.b, end);
                }
            }
            let h3 = x01(&[v[0], v[1], 0.5], &[s[0], s[1], zs], &[e[0], e[1], ze]).unwrap();
            prop_assert_eq!((h3.value, [h3.b[0], h3.b[1]]), (h.value, h.b));
            prop_assert!(h3.b[2] >= zs.min(ze) && h3.b[2] <= zs.max(ze));
            // The shadow is eq. 4.1 on the computed y, ties to B.
            prop_assert_eq!(s01(&v, &s, &e), if h.b[1] >= v[1] { h.value } else { 0 });
        } else {
            prop_assert_eq!(s01(&v, &s, &e), 0);
        }
        if let Some(h) = x10(&s, &e, &v) {
            prop_assert_eq!(h.b, v);
            prop_assert_eq!(h.a[0], v[0]);
            prop_assert!(h.a[1] >= s[1].min(e[1]) && h.a[1] <= s[1].max(e[1]));
            for end in [s, e] {
                if end[0] == v[0] {
                    prop_assert_eq!(h.a, end);
                }
            }
            prop_assert_eq!(s10(&s, &e, &v), if v[1] >= h.a[1] { h.value } else { 0 });
        } else {
            prop_assert_eq!(s10(&s, &e, &v), 0);
        }
    }

    /// Eq. 4.1 on the integer grid: every function equals its exact
    /// definition, ties (vertex on the edge, shared x) going to B.
    #[test]
    fn exact_definitions_on_the_grid(v in point(grid_coord(4)), s in point(grid_coord(4)), e in point(grid_coord(4))) {
        let (iv, is, ie) = (gi(v), gi(s), gi(e));
        prop_assert_eq!(s00(&v, &s), i32::from(is[0] >= iv[0]));
        let x = exact_x01(iv, is, ie);
        prop_assert_eq!(x01(&v, &s, &e).map_or(0, |h| h.value), x);
        let want = if x != 0 && exact_edge_minus_vertex(iv, is, ie) >= 0 { x } else { 0 };
        prop_assert_eq!(s01(&v, &s, &e), want, "S01({:?}, {:?} -> {:?})", v, s, e);
        let x = exact_x10(is, ie, iv);
        prop_assert_eq!(x10(&s, &e, &v).map_or(0, |h| h.value), x);
        let want = if x != 0 && exact_edge_minus_vertex(iv, is, ie) <= 0 { x } else { 0 };
        prop_assert_eq!(s10(&s, &e, &v), want, "S10({:?} -> {:?}, {:?})", s, e, v);
    }
}

/// Every vertex-edge configuration of a 5x5 grid, exhaustively: the exact
/// definitions of eq. 4.1 (this is where rounding in Table 7.1 could break
/// a tie; it must not for small integers).
#[test]
fn exhaustive_small_grid() {
    let pts: Vec<P> = (-2..=2)
        .flat_map(|x| (-2..=2).map(move |y| [f64::from(x), f64::from(y)]))
        .collect();
    let mut ties = 0;
    for &v in &pts {
        for &s in &pts {
            for &e in &pts {
                let (iv, is, ie) = (gi(v), gi(s), gi(e));
                let x = exact_x01(iv, is, ie);
                let d = if x != 0 {
                    exact_edge_minus_vertex(iv, is, ie)
                } else {
                    1
                };
                if x != 0 && d == 0 {
                    ties += 1;
                }
                assert_eq!(
                    s01(&v, &s, &e),
                    if d >= 0 { x } else { 0 },
                    "S01 {v:?} {s:?} {e:?}"
                );
                let x = exact_x10(is, ie, iv);
                let d = if x != 0 {
                    exact_edge_minus_vertex(iv, is, ie)
                } else {
                    -1
                };
                assert_eq!(
                    s10(&s, &e, &v),
                    if d <= 0 { x } else { 0 },
                    "S10 {s:?} {e:?} {v:?}"
                );
            }
        }
    }
    assert!(ties > 100, "the grid must exercise ties ({ties})");
}
