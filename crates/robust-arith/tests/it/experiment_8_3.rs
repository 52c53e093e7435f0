//! The experiment of section 8.3 at test size: random segment pairs in
//! `[-1, 1]^2` that the pyramid deems to intersect, their point computed by
//! Table 7.1 then Table 7.2, and the exact distance of that point from both
//! segments checked against `sqrt(153) u L` (eq. 8.17, `L = 1`).
//!
//! Intersection is decided as the 2D pyramid does it: `X11` of
//! `shadow_2d::x11` (Table 4.1). Independently, the test re-derives the
//! Table 7.2 input from `y_at_x` at the two ends of the x-overlap and checks
//! that this decides the same way and that `interpolate` gives the pyramid's
//! point bit for bit. The full 10^7 run is `cargo xtask arith-experiment`.

use crate::common::{distance_to_segment, U};
use robust_arith::{interpolate, y_at_x, INTERSECTION_ERROR_FACTOR};
use test_support::rng::SplitMix64;

/// The y of segment `p - q` (either direction, not vertical) at `x`.
fn y_on(p: [f64; 2], q: [f64; 2], x: f64) -> f64 {
    if p[0] < q[0] {
        y_at_x(p, q, x)
    } else {
        y_at_x(q, p, x)
    }
}

/// Table 7.2 input from the two ends of the x-overlap (figure 4.5): `None`
/// when the segments do not overlap in x or do not change order.
fn table_7_2_point(a: [[f64; 2]; 2], b: [[f64; 2]; 2]) -> Option<[f64; 2]> {
    let (a_lo, a_hi) = (a[0][0].min(a[1][0]), a[0][0].max(a[1][0]));
    let (b_lo, b_hi) = (b[0][0].min(b[1][0]), b[0][0].max(b[1][0]));
    let (x_l, x_r) = (a_lo.max(b_lo), a_hi.min(b_hi));
    if x_l >= x_r {
        return None; // no overlap, or (never with random data) a touch
    }
    let (yal, yar) = (y_on(a[0], a[1], x_l), y_on(a[0], a[1], x_r));
    let (ybl, ybr) = (y_on(b[0], b[1], x_l), y_on(b[0], b[1], x_r));
    // eq. 4.1: B shadows A where y_B >= y_A; the plus end is "left".
    match (ybl >= yal, ybr >= yar) {
        (true, false) => Some(interpolate(x_l, yal, ybl, x_r, yar, ybr)),
        (false, true) => Some(interpolate(x_r, yar, ybr, x_l, yal, ybl)),
        _ => None,
    }
}

#[test]
fn sqrt_153_bound_over_100k_random_intersecting_pairs() {
    const PAIRS: usize = 100_000;
    let mut rng = SplitMix64::new(0x0005_eed8);
    let bound = INTERSECTION_ERROR_FACTOR; // in units of u L, L = 1
    let (mut found, mut tried) = (0usize, 0usize);
    let (mut max_far, mut max_a, mut max_b) = (0.0f64, 0.0f64, 0.0f64);
    let mut below_1u = 0usize;
    while found < PAIRS {
        tried += 1;
        let a = [[rng.pm1(), rng.pm1()], [rng.pm1(), rng.pm1()]];
        let b = [[rng.pm1(), rng.pm1()], [rng.pm1(), rng.pm1()]];
        let hit = shadow_2d::x11(&a[0], &a[1], &b[0], &b[1]).expect("Theorem 1: X11 has partners");
        let own = table_7_2_point(a, b);
        let Some(h) = hit else {
            assert!(
                own.is_none(),
                "x11 says no crossing, Table 7.2 path says {own:?}: {a:?} {b:?}"
            );
            continue;
        };
        found += 1;
        let p = own
            .unwrap_or_else(|| panic!("x11 = {} but no Table 7.2 crossing: {a:?} {b:?}", h.value));
        assert_eq!(
            h.a.map(f64::to_bits),
            p.map(f64::to_bits),
            "x11 point != Table 7.2 point: {a:?} {b:?}"
        );
        assert_eq!(h.b, h.a);
        let da = distance_to_segment(p, a[0], a[1]) / U;
        let db = distance_to_segment(p, b[0], b[1]) / U;
        assert!(
            da <= bound && db <= bound,
            "eq. 8.17 violated: {da:.3} u and {db:.3} u (bound {bound:.3} u) for {a:?} {b:?} -> {p:?}"
        );
        max_a = max_a.max(da);
        max_b = max_b.max(db);
        max_far = max_far.max(da.max(db));
        if da.max(db) < 1.0 {
            below_1u += 1;
        }
    }
    // The dissertation observed at most 2.57 u over 10^7 pairs; report ours.
    let share = below_1u as f64 / PAIRS as f64;
    println!(
        "{PAIRS} intersecting pairs of {tried}: max distance from the farther segment {max_far:.3} u \
         (A {max_a:.3} u, B {max_b:.3} u), {:.3}% below 1 u",
        100.0 * share
    );
    assert!(
        max_far <= bound,
        "observed max {max_far:.3} u exceeds sqrt(153) u"
    );
    // A sanity check that the oracle measures something: real errors occur.
    assert!(
        max_far > 0.1,
        "observed max {max_far:.3} u: oracle suspiciously exact"
    );
}
