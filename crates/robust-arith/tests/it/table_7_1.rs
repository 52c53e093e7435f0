//! Table 7.1 (`y_at_x`) against its specification: exact end points and
//! horizontal segments (section 7.1.1), the bounding box of the segment,
//! and the `4 u L_Y` error bound of Table 8.1 against an exact rational
//! oracle over inputs of many magnitudes.

use crate::common::{coord, exact_y_at_x, f, pow2_at_least, q, U};
use num_traits::Signed;
use proptest::prelude::*;
use robust_arith::{point_at_x, y_at_x, Y_AT_X_ERROR_FACTOR};
use test_support::rng::Xorshift64;

/// A segment `l -> r` with `x_L < x_R` and an `x_P` in `[x_L, x_R]`, the x
/// and y coordinates drawn at independent scales `2^ex`, `2^ey`.
fn segment_and_x() -> impl Strategy<Value = ([f64; 2], [f64; 2], f64)> {
    (-300i32..300, -300i32..300)
        .prop_flat_map(|(ex, ey)| {
            (
                coord(ex),
                coord(ey),
                coord(ex),
                coord(ey),
                0u64..=(1 << 20),
                0u8..4,
            )
        })
        .prop_filter_map("x_L < x_R", |(x0, y0, x1, y1, t, mode)| {
            if x0 == x1 {
                return None;
            }
            let (l, r) = if x0 < x1 {
                ([x0, y0], [x1, y1])
            } else {
                ([x1, y1], [x0, y0])
            };
            // x_P: an end, or a point in between (clamped: the sum may
            // round outside the interval).
            let xp = match mode {
                0 => l[0],
                1 => r[0],
                _ => {
                    let s = t as f64 / (1u64 << 20) as f64;
                    (l[0] + s * (r[0] - l[0])).clamp(l[0], r[0])
                }
            };
            if !(r[0] - l[0]).is_finite() {
                return None;
            }
            Some((l, r, xp))
        })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(test_support::cases(512)))]

    /// Section 7.1.1: `x_P = x_L` gives `y_L` and `x_P = x_R` gives `y_R`
    /// exactly, bit for bit.
    #[test]
    fn end_points_are_exact((l, r, _xp) in segment_and_x()) {
        prop_assert_eq!(y_at_x(l, r, l[0]).to_bits(), l[1].to_bits());
        prop_assert_eq!(y_at_x(l, r, r[0]).to_bits(), r[1].to_bits());
    }

    /// A horizontal segment gives its y exactly at every x in range.
    #[test]
    fn horizontal_segments_are_exact((l, r, xp) in segment_and_x()) {
        let y = l[1];
        prop_assert_eq!(y_at_x([l[0], y], [r[0], y], xp), y);
    }

    /// The result lies in the bounding box of the segment.
    #[test]
    fn result_lies_in_the_bounding_box((l, r, xp) in segment_and_x()) {
        let y = y_at_x(l, r, xp);
        prop_assert!(y >= l[1].min(r[1]) && y <= l[1].max(r[1]),
            "y_at_x({:?}, {:?}, {:e}) = {:e} outside [{:e}, {:e}]", l, r, xp, y, l[1].min(r[1]), l[1].max(r[1]));
    }

    /// Table 8.1: `|y_S - y_true| <= 4 u L_Y` with `L_Y` the power of two
    /// bounding the y-coordinates, against the exact rational value at the
    /// (exact) `x_P`.
    #[test]
    fn within_4_u_l_of_the_true_segment((l, r, xp) in segment_and_x()) {
        let y = y_at_x(l, r, xp);
        let exact = exact_y_at_x(l, r, xp);
        let err = (q(y) - &exact).abs();
        let ly = pow2_at_least(l[1].abs().max(r[1].abs()));
        let bound = q(Y_AT_X_ERROR_FACTOR * U * ly);
        prop_assert!(err <= bound,
            "y_at_x({:?}, {:?}, {:e}) = {:e}, exact {:e}, error {:.3} u L_Y",
            l, r, xp, y, f(&exact), f(&err) / (U * ly));
    }

    /// `point_at_x` in 2D is `[x_P, y_at_x]` bit for bit, and in 3D its z
    /// obeys the same bound with `L_Z`.
    #[test]
    fn point_at_x_agrees((l, r, xp) in segment_and_x(), z0 in coord(0), z1 in coord(0)) {
        let p = point_at_x(l, r, xp);
        prop_assert_eq!(p[0].to_bits(), xp.to_bits());
        prop_assert_eq!(p[1].to_bits(), y_at_x(l, r, xp).to_bits());
        let p3 = point_at_x([l[0], l[1], z0], [r[0], r[1], z1], xp);
        prop_assert_eq!(p3[1].to_bits(), p[1].to_bits());
        let exact_z = exact_y_at_x([l[0], z0], [r[0], z1], xp);
        let lz = pow2_at_least(z0.abs().max(z1.abs()));
        prop_assert!((q(p3[2]) - exact_z).abs() <= q(4.0 * U * lz));
    }
}

/// A dense sweep of `x_P` across one segment of awkward slope, through the
/// switch between the two reference ends: every value within `4 u L_Y`.
#[test]
fn dense_sweep_is_bounded() {
    let l = [-0.7312, 0.912_345_678_9];
    let r = [0.6543, -0.333_333_333_333_333_3];
    let ly = pow2_at_least(0.912_345_678_9);
    for i in 0..=20_000 {
        let xp = (l[0] + (r[0] - l[0]) * (i as f64 / 20_000.0)).clamp(l[0], r[0]);
        let y = y_at_x(l, r, xp);
        let err = (q(y) - exact_y_at_x(l, r, xp)).abs();
        assert!(
            err <= q(4.0 * U * ly),
            "x_P = {xp:e}: error {:.3} u",
            f(&err) / U
        );
    }
}

/// The bounding-box property again where rounding is coarsest: segments
/// displaced onto the grids of section 7.7 (`1.5 * 2^49` and `1.5 * 2^47`,
/// spacing 1/8 and 1/32) and segments near the `f64::MAX / 4` limit of
/// section 8.5. The simplification sweep relies on it to classify edges
/// whose y-range excludes the event point without evaluating Table 7.1.
/// It holds because each branch interpolates from the closer end, so
/// `|lambda| <= (1 + 3u) / 2` and the rounded step never reaches the far
/// end's y.
#[test]
fn bounding_box_holds_on_coarse_grids_and_huge_magnitudes() {
    let mut rng = Xorshift64::new(0x2545_F491_4F6C_DD1D);
    let mut next = move || rng.next_u64();
    let offsets = [1.5 * 2f64.powi(49), 1.5 * 2f64.powi(47), f64::MAX / 8.0];
    let mut checked = 0;
    for i in 0..300_000 {
        let off = offsets[i % offsets.len()];
        let scale = if off > 1e300 { off / 4.0 } else { 8.0 };
        let mut c = || off + ((next() % 2001) as f64 - 1000.0) / 1000.0 * scale;
        let (x0, y0, x1, y1) = (c(), c(), c(), c());
        if x0 == x1 {
            continue;
        }
        let (l, r) = if x0 < x1 {
            ([x0, y0], [x1, y1])
        } else {
            ([x1, y1], [x0, y0])
        };
        let t = (next() % 1025) as f64 / 1024.0;
        let xp = (l[0] + t * (r[0] - l[0])).clamp(l[0], r[0]);
        let y = y_at_x(l, r, xp);
        assert!(
            y >= l[1].min(r[1]) && y <= l[1].max(r[1]),
            "y_at_x({l:?}, {r:?}, {xp:e}) = {y:e} outside the y-range"
        );
        checked += 1;
    }
    assert!(checked > 250_000);
}
