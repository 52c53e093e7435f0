//! Shared test support for the robust-arith integration tests: exact
//! oracles (rational and scaled-integer arithmetic, on `test-support`'s
//! exact scaling and orientation) and input generators.
//!
//! The oracles are independent of the code under test: they never call
//! `y_at_x` or `interpolate`, and they evaluate every formula exactly, so a
//! test that compares a computed value against them can fail.

#![allow(dead_code)]

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{Signed, ToPrimitive, Zero};
use proptest::prelude::*;
use test_support::exact::scaled;

/// The unit roundoff `u = 2^-53` (section 8.1), written out independently
/// of the crate's constant.
pub const U: f64 = 1.0 / 9_007_199_254_740_992.0;

/// An f64 as an exact rational.
pub fn q(x: f64) -> BigRational {
    BigRational::from_float(x).expect("finite test input")
}

/// A rational rounded to f64 (for reporting only; comparisons stay exact).
pub fn f(x: &BigRational) -> f64 {
    x.to_f64().unwrap_or(f64::NAN)
}

/// The exact y of the line through `l` and `r` at `x` (the "true segment"
/// of Table 8.1): `y_L + (x - x_L) (y_R - y_L) / (x_R - x_L)`.
pub fn exact_y_at_x(l: [f64; 2], r: [f64; 2], x: f64) -> BigRational {
    let (xl, yl, xr, yr) = (q(l[0]), q(l[1]), q(r[0]), q(r[1]));
    &yl + (q(x) - &xl) * (&yr - &yl) / (&xr - &xl)
}

/// The smallest power of two `>= m` (independent of
/// `robust_arith::power_of_two_bound`), at least the smallest normal.
pub fn pow2_at_least(m: f64) -> f64 {
    let mut l = f64::MIN_POSITIVE;
    while l < m.abs() {
        l *= 2.0;
    }
    l
}

/// `v * 2^e` as f64 for a big integer `v` (accurate to a few ulps, which is
/// all the reporting needs).
pub fn big_to_f64(v: &BigInt, e: i32) -> f64 {
    let bits = v.bits() as i32;
    let shift = (bits - 60).max(0);
    let top = (v >> (shift as usize)).to_f64().unwrap_or(f64::NAN);
    top * 2f64.powi(shift + e)
}

/// The exact Euclidean distance (rounded to f64 at the end only) from point
/// `p` to the closed segment `s0 - s1`.
pub fn distance_to_segment(p: [f64; 2], s0: [f64; 2], s1: [f64; 2]) -> f64 {
    let (ints, scale) = scaled(&[p[0], p[1], s0[0], s0[1], s1[0], s1[1]]);
    let [px, py, ax, ay, bx, by] = [&ints[0], &ints[1], &ints[2], &ints[3], &ints[4], &ints[5]];
    let (dx, dy) = (bx - ax, by - ay);
    let (wx, wy) = (px - ax, py - ay);
    let len2 = &dx * &dx + &dy * &dy;
    let dot = &dx * &wx + &dy * &wy;
    let e = scale as i32;
    let norm = |x: &BigInt, y: &BigInt| {
        let (x, y) = (big_to_f64(x, e), big_to_f64(y, e));
        (x * x + y * y).sqrt()
    };
    if len2.is_zero() || dot.is_negative() {
        norm(&wx, &wy)
    } else if dot > len2 {
        norm(&(px - bx), &(py - by))
    } else {
        let cross = &dx * &wy - &dy * &wx;
        big_to_f64(&cross.abs(), 2 * e) / big_to_f64(&len2, 2 * e).sqrt()
    }
}

/// Distance from `p` to the exact intersection point of the lines through
/// segments `a0-a1` and `b0-b1` (which must not be parallel).
pub fn distance_to_true_intersection(
    p: [f64; 2],
    a0: [f64; 2],
    a1: [f64; 2],
    b0: [f64; 2],
    b1: [f64; 2],
) -> f64 {
    let (i, scale) = scaled(&[
        p[0], p[1], a0[0], a0[1], a1[0], a1[1], b0[0], b0[1], b1[0], b1[1],
    ]);
    let (px, py, ax, ay) = (&i[0], &i[1], &i[2], &i[3]);
    let (dax, day) = (&i[4] - ax, &i[5] - ay);
    let (dbx, dby) = (&i[8] - &i[6], &i[9] - &i[7]);
    let den = &dax * &dby - &day * &dbx;
    let num = (&i[6] - ax) * &dby - (&i[7] - ay) * &dbx;
    // true point = a0 + num/den * da; p - true = ((p - a0) den - num da) / den
    let ex = (px - ax) * &den - &num * &dax;
    let ey = (py - ay) * &den - &num * &day;
    let e = scale as i32;
    let d = big_to_f64(&den, 2 * e);
    let (x, y) = (big_to_f64(&ex, 3 * e) / d, big_to_f64(&ey, 3 * e) / d);
    (x * x + y * y).sqrt()
}

/// A finite f64 of random sign, mantissa and binary exponent in
/// `[lo, hi]` (both kept well inside the normal range by the callers).
pub fn any_magnitude(lo: i32, hi: i32) -> impl Strategy<Value = f64> {
    (any::<bool>(), 0u64..(1 << 52), lo..=hi).prop_map(|(neg, frac, e)| {
        let m = 1.0 + frac as f64 / 4_503_599_627_370_496.0;
        let v = m * 2f64.powi(e);
        if neg {
            -v
        } else {
            v
        }
    })
}

/// A coordinate: mostly of the scale `2^e` with full random mantissa bits,
/// sometimes a small integer or zero (exact ties and simple values).
pub fn coord(e: i32) -> impl Strategy<Value = f64> {
    prop_oneof![
        6 => any_magnitude(e - 40, e),
        1 => (-4i32..=4).prop_map(f64::from),
        1 => Just(0.0),
    ]
}
