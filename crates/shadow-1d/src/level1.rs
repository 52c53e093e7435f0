//! Level 1: vertex against edge and edge against vertex on the x-line
//! (Table 4.1), with the level-1 intersection points and shadows.

use crate::{s00, Hit};
use robust_arith::point_at_x;

/// The point of the edge `p -> q` at `x`, interpolated from the left and
/// right ends ordered by x (Table 7.1). Requires `p[0] != q[0]`.
#[inline]
fn on_edge_at<const N: usize>(p: &[f64; N], q: &[f64; N], x: f64) -> [f64; N] {
    if p[0] < q[0] {
        point_at_x(*p, *q, x)
    } else {
        point_at_x(*q, *p, x)
    }
}

/// `X01(v_A, e_B) = S00(v_A, v_e(e_B)) - S00(v_A, v_s(e_B))` for the edge (or
/// half-edge) `e_B` from `bs` to `be` (Table 4.1). `+1` when `v_A` lies
/// within `e_B` in x with `e_B` going left to right.
///
/// Returns `None` when the value is 0, otherwise the value and the point
/// pair: `v_A` itself and the point of `e_B` at `x = x_A`.
#[inline]
pub fn x01<const N: usize>(va: &[f64; N], bs: &[f64; N], be: &[f64; N]) -> Option<Hit<N>> {
    let value = s00(va, be) - s00(va, bs);
    if value == 0 {
        return None;
    }
    // value != 0 means exactly one end has x >= x_A, so the edge is not
    // vertical and x_A lies in (min x, max x].
    // Theorem 1 at level 1: one end of B shadows v_A (S00 = 1) and v_A
    // shadows the other (S00 = 0), so both level-0 partners exist and the
    // point of B at x_A is an interpolation between them.
    debug_assert!(
        bs[0].min(be[0]) < va[0] && va[0] <= bs[0].max(be[0]),
        "Theorem 1 violated in X01"
    );
    Some(Hit {
        value,
        a: *va,
        b: on_edge_at(bs, be, va[0]),
    })
}

/// `X10(e_A, v_B) = -S00(v_e(e_A), v_B) + S00(v_s(e_A), v_B)` for the edge (or
/// half-edge) `e_A` from `as_` to `ae` (Table 4.1). `+1` when `v_B` lies
/// within `e_A` in x with `e_A` going left to right.
///
/// Returns `None` when the value is 0, otherwise the value and the point
/// pair: the point of `e_A` at `x = x_B`, and `v_B` itself.
#[inline]
pub fn x10<const N: usize>(as_: &[f64; N], ae: &[f64; N], vb: &[f64; N]) -> Option<Hit<N>> {
    let value = -s00(ae, vb) + s00(as_, vb);
    if value == 0 {
        return None;
    }
    // value != 0 means x_B lies in [min x, max x) of the edge.
    // Theorem 1 at level 1, as in `x01`: v_B shadows one end of A and the
    // other end shadows v_B.
    debug_assert!(
        as_[0].min(ae[0]) <= vb[0] && vb[0] < as_[0].max(ae[0]),
        "Theorem 1 violated in X10"
    );
    Some(Hit {
        value,
        a: on_edge_at(as_, ae, vb[0]),
        b: *vb,
    })
}

/// `S01(v_A, e_B)`: `X01(v_A, e_B)` when the y of `e_B` at `x_A` is `>= y_A`
/// (the edge shadows the vertex), else 0 (eq. 4.1).
#[inline]
pub fn s01<const N: usize>(va: &[f64; N], bs: &[f64; N], be: &[f64; N]) -> i32 {
    x01(va, bs, be).map_or(0, |h| h.shadow(1))
}

/// `S10(e_A, v_B)`: `X10(e_A, v_B)` when `y_B` is `>=` the y of `e_A` at `x_B`
/// (the vertex shadows the edge), else 0 (eq. 4.1).
#[inline]
pub fn s10<const N: usize>(as_: &[f64; N], ae: &[f64; N], vb: &[f64; N]) -> i32 {
    x10(as_, ae, vb).map_or(0, |h| h.shadow(1))
}

#[cfg(test)]
mod tests {
    use super::*;
    use robust_arith::y_at_x;

    #[test]
    fn x01_half_open_interval_ties_go_to_b() {
        let (s, e) = ([0.0, 0.0], [1.0, 0.0]);
        // x_A = x_s: S00(v, s) = 1 and S00(v, e) = 1, so X01 = 0.
        assert!(x01(&[0.0, 0.0], &s, &e).is_none());
        // x_A = x_e: S00(v, e) = 1, S00(v, s) = 0.
        assert_eq!(x01(&[1.0, 5.0], &s, &e).unwrap().value, 1);
        // Inside.
        assert_eq!(x01(&[0.5, 5.0], &s, &e).unwrap().value, 1);
        // Reversed half-edge negates, same points.
        let h = x01(&[0.5, 5.0], &e, &s).unwrap();
        assert_eq!(h.value, -1);
        assert_eq!(h.b, [0.5, 0.0]);
    }

    #[test]
    fn x10_half_open_interval() {
        let (s, e) = ([0.0, 0.0], [1.0, 0.0]);
        assert_eq!(x10(&s, &e, &[0.0, 1.0]).unwrap().value, 1);
        assert!(x10(&s, &e, &[1.0, 1.0]).is_none());
        assert_eq!(x10(&e, &s, &[0.5, 1.0]).unwrap().value, -1);
    }

    #[test]
    fn vertical_edges_never_intersect_in_x() {
        let (s, e) = ([1.0, 0.0], [1.0, 1.0]);
        for x in [0.0, 1.0, 2.0] {
            assert!(x01(&[x, 0.5], &s, &e).is_none());
            assert!(x10(&s, &e, &[x, 0.5]).is_none());
        }
    }

    #[test]
    fn shadow_ties_go_to_b_above() {
        // The vertex lies exactly on the edge: B (the edge) shadows it.
        assert_eq!(s01(&[0.5, 0.5], &[0.0, 0.0], &[1.0, 1.0]), 1);
        // The edge is A, the vertex B on it: B shadows A.
        assert_eq!(s10(&[0.0, 0.0], &[1.0, 1.0], &[0.5, 0.5]), 1);
    }

    #[test]
    fn level1_points_use_table_7_1() {
        let (p, q) = ([0.1, 0.7], [0.9, -0.3]);
        let h = x01(&[0.35, 0.0], &q, &p).unwrap();
        assert_eq!(h.b[1], y_at_x(p, q, 0.35));
        let h3 = x10(&[0.1, 0.7, 2.0], &[0.9, -0.3, 4.0], &[0.9 - 1e-9, 0.0, 0.0]).unwrap();
        assert_eq!(h3.a[0], 0.9 - 1e-9);
    }
}
