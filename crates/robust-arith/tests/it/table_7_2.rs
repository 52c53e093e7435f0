//! Table 7.2 (`interpolate`) against its specification: it is the `N = 2,
//! k = 1` case of eq. 4.2-4.6 (`interpolate_pair`) bit for bit, its point
//! lies in both segment bounding boxes (eq. 8.18-8.19), it is exact where
//! the segments meet at an end of the overlap, and a horizontal segment
//! gives its own y exactly (section 7.1.1).

use crate::common::{coord, distance_to_segment, pow2_at_least, U};
use proptest::prelude::*;
use robust_arith::{interpolate, interpolate_pair, INTERSECTION_ERROR_FACTOR};

/// Inputs satisfying the precondition of Table 7.2: `y_AL <= y_BL`,
/// `y_BR <= y_AR`, one strict. `x_L` and `x_R` in either order (the
/// pyramid passes the B-shadows-A end as "left", wherever it is), possibly
/// equal (a vertical segment). The mode forces meeting ends and horizontal
/// segments.
#[derive(Clone, Copy, Debug)]
struct Input {
    x_l: f64,
    y_al: f64,
    y_bl: f64,
    x_r: f64,
    y_ar: f64,
    y_br: f64,
}

fn input() -> impl Strategy<Value = Input> {
    (-200i32..200, -200i32..200)
        .prop_flat_map(|(ex, ey)| {
            (
                coord(ex),
                coord(ex),
                [coord(ey), coord(ey), coord(ey), coord(ey)],
                0u8..8,
            )
        })
        .prop_filter_map("precondition of Table 7.2", |(x_l, x_r, y, mode)| {
            let [mut y_al, mut y_bl, mut y_ar, mut y_br] = y;
            if y_al > y_bl {
                std::mem::swap(&mut y_al, &mut y_bl);
            }
            if y_br > y_ar {
                std::mem::swap(&mut y_br, &mut y_ar);
            }
            match mode {
                0 => y_bl = y_al, // meet at the left end
                1 => y_br = y_ar, // meet at the right end
                2 => {
                    // A horizontal: needs y_bl >= y_a >= y_br.
                    let ya = y_al.max(y_br).min(y_bl);
                    y_al = ya;
                    y_ar = ya;
                }
                3 => {
                    // B horizontal: needs y_al <= y_b <= y_ar.
                    let yb = y_bl.max(y_al).min(y_ar);
                    y_bl = yb;
                    y_br = yb;
                }
                4 => {
                    // A vertical overlap: x_L = x_R.
                    return Some(Input {
                        x_l,
                        y_al,
                        y_bl,
                        x_r: x_l,
                        y_ar,
                        y_br,
                    })
                    .filter(|_| y_al < y_bl || y_br < y_ar);
                }
                _ => {}
            }
            let ok = (y_al < y_bl || y_br < y_ar) && (y_bl - y_al) - (y_br - y_ar) > 0.0;
            let finite = [x_r - x_l, y_ar - y_al, y_br - y_bl]
                .iter()
                .all(|d| d.is_finite());
            (ok && finite).then_some(Input {
                x_l,
                y_al,
                y_bl,
                x_r,
                y_ar,
                y_br,
            })
        })
}

fn run(i: &Input) -> [f64; 2] {
    interpolate(i.x_l, i.y_al, i.y_bl, i.x_r, i.y_ar, i.y_br)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(test_support::cases(1024)))]

    /// Table 7.2 is eq. 4.2-4.6 with `k = 1`: plus pair at the left end,
    /// minus pair at the right end, both points equal bit for bit.
    #[test]
    fn interpolate_is_interpolate_pair(i in input()) {
        let p = run(&i);
        let (a, b) = interpolate_pair::<2>(
            1,
            [i.x_l, i.y_al],
            [i.x_l, i.y_bl],
            [i.x_r, i.y_ar],
            [i.x_r, i.y_br],
        );
        prop_assert_eq!(a.map(f64::to_bits), p.map(f64::to_bits));
        prop_assert_eq!(b.map(f64::to_bits), p.map(f64::to_bits));
    }

    /// Eq. 8.18-8.19: the point lies in the intersection of the bounding
    /// boxes of segment A `(x_L, y_AL) - (x_R, y_AR)` and segment B
    /// `(x_L, y_BL) - (x_R, y_BR)`.
    #[test]
    fn point_lies_in_both_bounding_boxes(i in input()) {
        let [x, y] = run(&i);
        let (x0, x1) = (i.x_l.min(i.x_r), i.x_l.max(i.x_r));
        prop_assert!(x0 <= x && x <= x1, "x_I = {:e} outside [{:e}, {:e}] for {:?}", x, x0, x1, i);
        for (ya, yb, name) in [(i.y_al, i.y_ar, "A"), (i.y_bl, i.y_br, "B")] {
            prop_assert!(ya.min(yb) <= y && y <= ya.max(yb),
                "y_I = {:e} outside segment {}'s y-range for {:?}", y, name, i);
        }
    }

    /// Exact where the segments meet at an end of the overlap (section
    /// 7.1.1: "the correct evaluation of x_I when y_BL = y_AL or
    /// y_AR = y_BR").
    #[test]
    fn exact_where_segments_meet(i in input()) {
        let p = run(&i);
        if i.y_al == i.y_bl {
            prop_assert_eq!(p, [i.x_l, i.y_al], "{:?}", i);
        } else if i.y_ar == i.y_br {
            prop_assert_eq!(p, [i.x_r, i.y_ar], "{:?}", i);
        }
    }

    /// A horizontal segment gives its y exactly (section 7.1.1).
    #[test]
    fn horizontal_segment_gives_its_y(i in input()) {
        let p = run(&i);
        if i.y_al == i.y_ar {
            prop_assert_eq!(p[1], i.y_al, "{:?}", i);
        }
        if i.y_bl == i.y_br {
            prop_assert_eq!(p[1], i.y_bl, "{:?}", i);
        }
    }

    /// Eq. 8.17 for the Table 7.2 stage alone: the point is within
    /// `sqrt(153) u L` of both segments as given (their end points are the
    /// inputs, so this holds whatever the y-values were computed from).
    #[test]
    fn within_sqrt_153_u_l_of_both_segments(i in input()) {
        let p = run(&i);
        let l = pow2_at_least(
            [i.x_l, i.x_r, i.y_al, i.y_bl, i.y_ar, i.y_br]
                .iter()
                .fold(0.0f64, |m, v| m.max(v.abs())),
        );
        let bound = INTERSECTION_ERROR_FACTOR * U * l;
        let da = distance_to_segment(p, [i.x_l, i.y_al], [i.x_r, i.y_ar]);
        let db = distance_to_segment(p, [i.x_l, i.y_bl], [i.x_r, i.y_br]);
        prop_assert!(da <= bound && db <= bound,
            "distances {:.3} u L and {:.3} u L for {:?}", da / (U * l), db / (U * l), i);
    }
}

/// The example of the crate documentation and the four branch combinations
/// of Table 7.2 on small exact cases.
#[test]
fn branch_examples() {
    // Closer to the left, A flatter.
    assert_eq!(interpolate(0.0, 0.0, 1.0, 4.0, 2.0, -5.0), [0.5, 0.25]);
    // Closer to the right, B flatter.
    assert_eq!(interpolate(0.0, -6.0, 1.0, 4.0, 1.0, 0.0), [3.5, 0.125]);
    // Reversed x order: the plus end on the right.
    assert_eq!(interpolate(4.0, 1.0, 1.0, 0.0, 3.0, 1.0), [4.0, 1.0]);
    // Vertical overlap (x_L = x_R).
    assert_eq!(interpolate(2.0, 0.0, 1.0, 2.0, 3.0, 1.0), [2.0, 1.0]);
}
