//! Small vector helpers for 3D smoothing (Appendix A): distances from a
//! point to a segment and between two segments, in plain f64.

use topology::Point3;

pub(crate) fn sub(a: Point3, b: Point3) -> Point3 {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

pub(crate) fn dot(a: Point3, b: Point3) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

pub(crate) fn cross(a: Point3, b: Point3) -> Point3 {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

pub(crate) fn dist2(a: Point3, b: Point3) -> f64 {
    let d = sub(a, b);
    dot(d, d)
}

/// `a + t (b - a)`.
pub(crate) fn lerp(a: Point3, b: Point3, t: f64) -> Point3 {
    [
        a[0] + t * (b[0] - a[0]),
        a[1] + t * (b[1] - a[1]),
        a[2] + t * (b[2] - a[2]),
    ]
}

/// The parameter `t` of the point of segment `a b` closest to `p`
/// (clamped to `[0, 1]`) and the squared distance to it. A degenerate
/// segment gives `t = 0`.
pub(crate) fn point_segment(p: Point3, a: Point3, b: Point3) -> (f64, f64) {
    let d = sub(b, a);
    let l2 = dot(d, d);
    let t = if l2 > 0.0 {
        (dot(sub(p, a), d) / l2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    (t, dist2(p, lerp(a, b, t)))
}

/// The unclamped projection parameter of `p` on the line `a b` (0 for a
/// degenerate segment).
pub(crate) fn projection(p: Point3, a: Point3, b: Point3) -> f64 {
    let d = sub(b, a);
    let l2 = dot(d, d);
    if l2 > 0.0 {
        dot(sub(p, a), d) / l2
    } else {
        0.0
    }
}

/// The closest points of segments `p1 q1` and `p2 q2`: parameters `(s, t)`
/// in `[0, 1]` and the points themselves (Ericson, "Real-Time Collision
/// Detection", 5.1.9). Parallel segments get `s` from the first end.
pub(crate) fn segment_segment(
    p1: Point3,
    q1: Point3,
    p2: Point3,
    q2: Point3,
) -> (f64, f64, Point3, Point3) {
    let d1 = sub(q1, p1);
    let d2 = sub(q2, p2);
    let r = sub(p1, p2);
    let a = dot(d1, d1);
    let e = dot(d2, d2);
    let f = dot(d2, r);
    let (s, t);
    if a <= 0.0 && e <= 0.0 {
        s = 0.0;
        t = 0.0;
    } else if a <= 0.0 {
        s = 0.0;
        t = (f / e).clamp(0.0, 1.0);
    } else {
        let c = dot(d1, r);
        if e <= 0.0 {
            t = 0.0;
            s = (-c / a).clamp(0.0, 1.0);
        } else {
            let b = dot(d1, d2);
            let denom = a * e - b * b;
            let s0 = if denom > 0.0 {
                ((b * f - c * e) / denom).clamp(0.0, 1.0)
            } else {
                0.0
            };
            let t0 = (b * s0 + f) / e;
            if t0 < 0.0 {
                t = 0.0;
                s = (-c / a).clamp(0.0, 1.0);
            } else if t0 > 1.0 {
                t = 1.0;
                s = ((b - c) / a).clamp(0.0, 1.0);
            } else {
                t = t0;
                s = s0;
            }
        }
    }
    (s, t, lerp(p1, q1, s), lerp(p2, q2, t))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn crossing_segments_meet_in_the_middle() {
        let (s, t, c1, c2) = segment_segment(
            [0.0, 0.0, 0.0],
            [2.0, 0.0, 0.0],
            [1.0, -1.0, 1.0],
            [1.0, 1.0, 1.0],
        );
        assert_eq!((s, t), (0.5, 0.5));
        assert_eq!(c1, [1.0, 0.0, 0.0]);
        assert_eq!(c2, [1.0, 0.0, 1.0]);
    }

    #[test]
    fn point_segment_clamps() {
        let (t, d2) = point_segment([3.0, 1.0, 0.0], [0.0; 3], [2.0, 0.0, 0.0]);
        assert_eq!(t, 1.0);
        assert_eq!(d2, 2.0);
        let (t, d2) = point_segment([1.0, 1.0, 0.0], [0.0; 3], [2.0, 0.0, 0.0]);
        assert_eq!((t, d2), (0.5, 1.0));
    }
}
