//! Plane geometry of 2D smoothing: squared lengths, point-segment
//! distance, the exact crossing and touching tests (signs from the
//! workspace's one exact orientation predicate) and the crossing point by
//! the interpolation of Tables 7.1 and 7.2.
//!
//! The point-segment distance is dimension-generic so that the 3D
//! smoothing can share it.

use robust_arith::{interpolate, lex_cmp, orient2d, y_at_x, Point2};
use std::cmp::Ordering;

/// The squared Euclidean distance `|a - b|^2` in f64 (may overflow to
/// infinity for coordinates near `f64::MAX / 4`; every caller compares it
/// with `<`/`<=`, where infinity and NaN are never "close").
#[inline]
pub fn dist2<const N: usize>(a: &[f64; N], b: &[f64; N]) -> f64 {
    let mut d = 0.0;
    for k in 0..N {
        let t = a[k] - b[k];
        d += t * t;
    }
    d
}

/// The squared distance from `p` to the closed segment `a b`, and the
/// parameter `t` in `[0, 1]` of the nearest point `a + t (b - a)`. A
/// zero-length segment gives the distance to `a` and `t = 0`. NaN when an
/// intermediate overflows (treated as "far" by every caller).
pub fn point_segment_dist2<const N: usize>(p: &[f64; N], a: &[f64; N], b: &[f64; N]) -> (f64, f64) {
    let mut ab2 = 0.0;
    let mut dot = 0.0;
    for k in 0..N {
        let d = b[k] - a[k];
        ab2 += d * d;
        dot += (p[k] - a[k]) * d;
    }
    let t = if ab2 > 0.0 {
        (dot / ab2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    let mut d2 = 0.0;
    for k in 0..N {
        let q = a[k] + t * (b[k] - a[k]);
        let e = p[k] - q;
        d2 += e * e;
    }
    (d2, t)
}

/// Appendix A's rule for cracking the edge `a -> b` at the vertex `v`:
/// `v` lies within the tolerance of the segment (`tol2` is its square) or
/// exactly on its open segment, and both parts are strictly shorter than
/// the edge. Edge cracking by vertex, the removal of straight-through
/// vertices and the checker all decide by it.
pub fn cracks_at(v: Point2, a: Point2, b: Point2, tol2: f64) -> bool {
    let len2 = dist2(&a, &b);
    let (d2, _) = point_segment_dist2(&v, &a, &b);
    (d2 <= tol2 || on_open_segment(v, a, b)) && dist2(&a, &v) < len2 && dist2(&v, &b) < len2
}

/// `true` when `p` lies exactly on the open segment `a b` (exact
/// orientation, then strictly between the ends in the lexicographic order
/// of the segment's direction).
pub fn on_open_segment(p: Point2, a: Point2, b: Point2) -> bool {
    if orient2d(a, b, p) != Ordering::Equal || a == b {
        return false;
    }
    let (lo, hi) = if lex_cmp(&a, &b) == Ordering::Less {
        (a, b)
    } else {
        (b, a)
    };
    lex_cmp(&lo, &p) == Ordering::Less && lex_cmp(&p, &hi) == Ordering::Less
}

/// `true` when the open segments `a b` and `c d` cross at one point
/// interior to both (exact: each segment's ends lie strictly on opposite
/// sides of the other's line).
pub fn properly_cross(a: Point2, b: Point2, c: Point2, d: Point2) -> bool {
    let opp = |x: Ordering, y: Ordering| {
        matches!(
            (x, y),
            (Ordering::Less, Ordering::Greater) | (Ordering::Greater, Ordering::Less)
        )
    };
    opp(orient2d(a, b, c), orient2d(a, b, d)) && opp(orient2d(c, d, a), orient2d(c, d, b))
}

/// `true` when two edges of a polygon set meet anywhere other than at a
/// vertex they share (exact): a proper crossing, an end of one on the
/// interior of the other, or a collinear overlap. Edges that share one
/// vertex conflict only when they overlap along a common direction from
/// it; the same vertex pair in both orders always conflicts (the caller
/// has cancelled such pairs).
pub fn edges_conflict(e: [u32; 2], f: [u32; 2], pts: &[Point2]) -> bool {
    let p = |v: u32| pts[v as usize];
    let shared = [e[0] == f[0], e[0] == f[1], e[1] == f[0], e[1] == f[1]];
    let n_shared = shared.iter().filter(|&&s| s).count();
    if n_shared >= 2 {
        return true;
    }
    let (a, b, c, d) = (p(e[0]), p(e[1]), p(f[0]), p(f[1]));
    if n_shared == 1 {
        // The shared vertex s and the two far ends x (of e) and y (of f).
        let (s, x, y) = match shared {
            [true, ..] => (a, b, d),
            [_, true, ..] => (a, b, c),
            [_, _, true, _] => (b, a, d),
            _ => (b, a, c),
        };
        if orient2d(s, x, y) != Ordering::Equal {
            return false;
        }
        // Collinear: they overlap when x and y lie on the same side of s.
        let dir = |q: Point2| lex_cmp(&s, &q);
        return dir(x) == dir(y);
    }
    properly_cross(a, b, c, d)
        || on_open_segment(c, a, b)
        || on_open_segment(d, a, b)
        || on_open_segment(a, c, d)
        || on_open_segment(b, c, d)
        || (c == a || c == b || d == a || d == b)
}

/// The crossing point of two properly crossing segments (see
/// [`properly_cross`]), by Tables 7.1 and 7.2 on the axis along which
/// both segments' spans overlap: within `sqrt(153) u L` of both segments
/// (section 8.2) and inside both bounding boxes.
pub fn crossing_point(a: Point2, b: Point2, c: Point2, d: Point2) -> Point2 {
    if let Some(p) = crossing_on_axis(a, b, c, d, false) {
        return p;
    }
    if let Some(p) = crossing_on_axis(a, b, c, d, true) {
        return p;
    }
    // Both spans degenerate on both axes: the overlap of the boxes is a
    // single point, which is the crossing.
    [
        a[0].min(b[0]).max(c[0].min(d[0])),
        a[1].min(b[1]).max(c[1].min(d[1])),
    ]
}

fn crossing_on_axis(a: Point2, b: Point2, c: Point2, d: Point2, swap: bool) -> Option<Point2> {
    let s = |p: Point2| if swap { [p[1], p[0]] } else { p };
    let order = |p: Point2, q: Point2| if p[0] <= q[0] { (p, q) } else { (q, p) };
    let (al, ar) = order(s(a), s(b));
    let (bl, br) = order(s(c), s(d));
    let x_l = al[0].max(bl[0]);
    let x_r = ar[0].min(br[0]);
    if x_l >= x_r || al[0] == ar[0] || bl[0] == br[0] {
        return None;
    }
    let (y_al, y_bl) = (y_at_x(al, ar, x_l), y_at_x(bl, br, x_l));
    let (y_ar, y_br) = (y_at_x(al, ar, x_r), y_at_x(bl, br, x_r));
    // Table 7.2's precondition: B at or above A on the left, below on the
    // right (one strict); otherwise exchange the roles of A and B.
    let p = if y_al <= y_bl && y_br <= y_ar && (y_al < y_bl || y_br < y_ar) {
        interpolate(x_l, y_al, y_bl, x_r, y_ar, y_br)
    } else if y_bl <= y_al && y_ar <= y_br && (y_bl < y_al || y_ar < y_br) {
        interpolate(x_l, y_bl, y_al, x_r, y_br, y_ar)
    } else {
        // Rounding hid the crossing at both ends: the middle of the span
        // on segment A (still inside both boxes up to the span).
        let xm = x_l + (x_r - x_l) / 2.0;
        [xm, y_at_x(al, ar, xm)]
    };
    Some(s(p))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn distance_and_parameter() {
        let (d2, t) = point_segment_dist2(&[1.0, 1.0], &[0.0, 0.0], &[2.0, 0.0]);
        assert_eq!((d2, t), (1.0, 0.5));
        let (d2, t) = point_segment_dist2(&[-3.0, 4.0], &[0.0, 0.0], &[2.0, 0.0]);
        assert_eq!((d2, t), (25.0, 0.0));
        let (d2, _) = point_segment_dist2(&[1.0, 1.0, 1.0], &[0.0; 3], &[0.0; 3]);
        assert_eq!(d2, 3.0);
    }

    #[test]
    fn conflicts() {
        let pts = [
            [0.0, 0.0],
            [2.0, 0.0],
            [1.0, -1.0],
            [1.0, 1.0],
            [1.0, 0.0],
            [3.0, 0.0],
        ];
        assert!(edges_conflict([0, 1], [2, 3], &pts)); // proper crossing
        assert!(edges_conflict([0, 1], [4, 3], &pts)); // T-junction
        assert!(!edges_conflict([0, 2], [2, 3], &pts)); // chain
        assert!(edges_conflict([0, 1], [0, 4], &pts)); // collinear overlap from a shared end
        assert!(!edges_conflict([0, 4], [4, 1], &pts)); // collinear chain
        assert!(edges_conflict([4, 5], [0, 1], &pts)); // overlap, no shared vertex
        assert!(edges_conflict([0, 1], [1, 0], &pts));
    }

    #[test]
    fn crossing_points_are_exact_where_representable() {
        let p = crossing_point([0.0, 0.0], [2.0, 2.0], [0.0, 2.0], [2.0, 0.0]);
        assert_eq!(p, [1.0, 1.0]);
        let p = crossing_point([1.0, -1.0], [1.0, 3.0], [0.0, 0.5], [4.0, 0.5]);
        assert_eq!(p, [1.0, 0.5]);
        let p = crossing_point([0.0, 0.0], [1.0, 3.0], [0.0, 1.0], [1.0, 0.0]);
        assert!((p[0] - 0.25).abs() < 1e-15 && (p[1] - 0.75).abs() < 1e-15);
    }
}
