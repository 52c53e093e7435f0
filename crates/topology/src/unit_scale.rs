//! Areas and volumes without spurious overflow. The shoelace and
//! divergence sums multiply coordinates: beyond `sqrt(f64::MAX)` (about
//! 1.3e154) a product overflows and `inf - inf` makes the sum NaN, although
//! every coordinate is valid (up to `f64::MAX / 4`). Such a sum is then
//! redone on coordinates scaled axis by axis by powers of two (exact, but
//! for bits of coordinates far smaller than their axis's largest, which
//! become subnormal) and scaled back: every term of both sums is a product
//! of one coordinate per axis, so it scales by the product of the axis
//! factors. That gives the area or volume, or an infinity of the right
//! sign when the value itself exceeds `f64::MAX`.

/// Per axis, powers of two `(down, up)` with `m * down <= 1` and
/// `down * up == 1`, `m` the largest magnitude of that coordinate over
/// `points` (NaN passed over; an axis of zeros keeps factor 1); `None` when
/// a magnitude is not finite (nothing to rescue).
pub(crate) fn axis_scales<const N: usize>(
    points: impl Iterator<Item = [f64; N]>,
) -> Option<([f64; N], [f64; N])> {
    let mut m = [0.0f64; N];
    for p in points {
        for k in 0..N {
            m[k] = m[k].max(p[k].abs());
        }
    }
    let mut down = [1.0; N];
    let mut up = [1.0; N];
    for k in 0..N {
        if !m[k].is_finite() {
            return None;
        }
        if m[k] > 0.0 {
            up[k] = robust_arith::power_of_two_bound(m[k]);
            if !up[k].is_finite() {
                return None;
            }
            down[k] = 1.0 / up[k];
        }
    }
    Some((down, up))
}

/// `x` times the product of the powers of two `ups`, without overflow or
/// underflow in between: the exponents are summed and applied in steps
/// that move `x` monotonically towards the result.
pub(crate) fn scaled_back(x: f64, ups: &[f64]) -> f64 {
    // Exact: each factor is a power of two within f64's range.
    let mut e: i32 = ups.iter().map(|u| u.log2() as i32).sum();
    let mut x = x;
    while e != 0 {
        let step = e.clamp(-1000, 1000);
        x *= 2f64.powi(step);
        e -= step;
    }
    x
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn scales_are_reciprocal_powers_of_two() {
        for m in [1e-300, 0.3, 1.0, 3.0, 1e154, 1e300, f64::MAX / 2.0] {
            let (down, up) = axis_scales([[m, -m], [0.0, 0.0]].into_iter()).unwrap();
            for k in 0..2 {
                assert!(m * down[k] <= 1.0 && m * down[k] > 0.5, "{m}");
                assert_eq!(down[k] * up[k], 1.0);
                assert_eq!(up[k].log2().fract(), 0.0);
            }
        }
        assert_eq!(
            axis_scales([[0.0, 0.0]].into_iter()),
            Some(([1.0; 2], [1.0; 2]))
        );
        assert_eq!(axis_scales([[f64::INFINITY, 0.0]].into_iter()), None);
        assert_eq!(
            axis_scales([[f64::NAN, 2.0]].into_iter()),
            Some(([1.0, 0.5], [1.0, 2.0]))
        );
    }

    /// The box `[0, x] x [0, y] x [0, z]` as a triangle mesh, outward.
    fn cuboid(x: f64, y: f64, z: f64) -> crate::TriangleMesh {
        let v = (0..8)
            .map(|i| {
                let pick = |bit: usize, s: f64| if i & bit != 0 { s } else { 0.0 };
                [pick(1, x), pick(2, y), pick(4, z)]
            })
            .collect();
        let t = vec![
            [0, 2, 1],
            [1, 2, 3],
            [4, 5, 6],
            [5, 7, 6],
            [0, 1, 4],
            [1, 5, 4],
            [2, 6, 3],
            [3, 6, 7],
            [0, 4, 2],
            [2, 4, 6],
            [1, 3, 5],
            [3, 7, 5],
        ];
        crate::TriangleMesh::new(v, t)
    }

    #[test]
    fn areas_and_volumes_of_huge_valid_shapes_are_not_nan() {
        // Products of 1e200 coordinates overflow; the values do not.
        let s = 1e200;
        let ring = [[0.0, 0.0], [s, 0.0], [s, 1e-200], [0.0, 1e-200]];
        assert_eq!(crate::ring_signed_area(&ring), 1.0);
        let mut set = crate::PolygonSet2::new();
        set.add_loop(&ring);
        assert_eq!(set.signed_area(), 1.0);
        let reversed: Vec<_> = ring.iter().rev().copied().collect();
        assert_eq!(crate::ring_signed_area(&reversed), -1.0);
        let slab = cuboid(s, s, 1e-200);
        // (The scaled sums round differently from exact arithmetic.)
        let close = |v: f64, want: f64| (v - want).abs() <= 4.0 * f64::EPSILON * want;
        assert!(
            close(slab.signed_volume(), 1e200),
            "{}",
            slab.signed_volume()
        );
        let poly = crate::mesh_signed_volume(&slab.to_polygon_mesh());
        assert!(close(poly, 1e200), "{poly}");
        // Beyond f64::MAX: an infinity of the right sign, never NaN.
        let big = cuboid(1e150, 1e150, 1e150);
        assert_eq!(big.signed_volume(), f64::INFINITY);
        let square = [[0.0, 0.0], [0.0, 1e155], [1e155, 1e155], [1e155, 0.0]];
        assert_eq!(crate::ring_signed_area(&square), f64::NEG_INFINITY);
        // Unvalidated coordinates beyond 2^1023 (no power of two bounds
        // them): the plain sum's infinity, returned (this never ended).
        let m = f64::MAX;
        assert_eq!(
            crate::ring_signed_area(&[[0.0, 0.0], [m, 0.0], [0.0, m]]),
            f64::INFINITY
        );
        assert!(!cuboid(m, m, m).signed_volume().is_finite());
        // Ordinary shapes keep their plain sums bit for bit.
        let unit = cuboid(1.0, 2.0, 3.0);
        assert_eq!(unit.signed_volume(), 6.0);
    }
}
