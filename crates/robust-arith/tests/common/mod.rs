//! Shared test support for the robust-arith integration tests: exact
//! oracles (rational and scaled-integer arithmetic) and input generators.
//!
//! The oracles are independent of the code under test: they never call
//! `y_at_x` or `interpolate`, and they evaluate every formula exactly, so a
//! test that compares a computed value against them can fail.

#![allow(dead_code)]

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{Signed, ToPrimitive, Zero};
use proptest::prelude::*;

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

/// `(mantissa, exponent)` with `x = mantissa * 2^exponent` exactly.
fn decode(x: f64) -> (i64, i32) {
    let bits = x.to_bits();
    let sign = if bits >> 63 == 0 { 1 } else { -1 };
    let exp = ((bits >> 52) & 0x7ff) as i32;
    let frac = (bits & 0xf_ffff_ffff_ffff) as i64;
    if exp == 0 {
        (sign * frac, -1074)
    } else {
        (sign * (frac | (1 << 52)), exp - 1075)
    }
}

/// A set of f64 values as exact integers on a common scale `2^scale`:
/// `values[i] = ints[i] * 2^scale`. Integer arithmetic on them is exact and
/// much faster than `BigRational` (no gcd normalisation).
pub struct Scaled {
    /// The integers.
    pub ints: Vec<BigInt>,
    /// The common binary exponent.
    pub scale: i32,
}

impl Scaled {
    /// Scales `values` to integers.
    pub fn new(values: &[f64]) -> Scaled {
        let dec: Vec<(i64, i32)> = values.iter().map(|&v| decode(v)).collect();
        let scale = dec
            .iter()
            .filter(|d| d.0 != 0)
            .map(|d| d.1)
            .min()
            .unwrap_or(0);
        let ints = dec
            .iter()
            .map(|&(m, e)| {
                if m == 0 {
                    BigInt::zero()
                } else {
                    BigInt::from(m) << ((e - scale) as usize)
                }
            })
            .collect();
        Scaled { ints, scale }
    }
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
    let sc = Scaled::new(&[p[0], p[1], s0[0], s0[1], s1[0], s1[1]]);
    let [px, py, ax, ay, bx, by] = [
        &sc.ints[0],
        &sc.ints[1],
        &sc.ints[2],
        &sc.ints[3],
        &sc.ints[4],
        &sc.ints[5],
    ];
    let (dx, dy) = (bx - ax, by - ay);
    let (wx, wy) = (px - ax, py - ay);
    let len2 = &dx * &dx + &dy * &dy;
    let dot = &dx * &wx + &dy * &wy;
    let e = sc.scale;
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

/// The exact sign of the orientation of `(p, q, r)`: positive when
/// anticlockwise.
pub fn orient(p: [f64; 2], q2: [f64; 2], r: [f64; 2]) -> i32 {
    let sc = Scaled::new(&[p[0], p[1], q2[0], q2[1], r[0], r[1]]);
    let i = &sc.ints;
    let v = (&i[2] - &i[0]) * (&i[5] - &i[1]) - (&i[3] - &i[1]) * (&i[4] - &i[0]);
    if v.is_positive() {
        1
    } else if v.is_negative() {
        -1
    } else {
        0
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
    let sc = Scaled::new(&[
        p[0], p[1], a0[0], a0[1], a1[0], a1[1], b0[0], b0[1], b1[0], b1[1],
    ]);
    let i = &sc.ints;
    let (px, py, ax, ay) = (&i[0], &i[1], &i[2], &i[3]);
    let (dax, day) = (&i[4] - ax, &i[5] - ay);
    let (dbx, dby) = (&i[8] - &i[6], &i[9] - &i[7]);
    let den = &dax * &dby - &day * &dbx;
    let num = (&i[6] - ax) * &dby - (&i[7] - ay) * &dbx;
    // true point = a0 + num/den * da; p - true = ((p - a0) den - num da) / den
    let ex = (px - ax) * &den - &num * &dax;
    let ey = (py - ay) * &den - &num * &day;
    let e = sc.scale;
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

/// A uniformly random f64 in `[-1, 1]` with full precision at every scale
/// (a random 64-bit integer scaled by `2^-64`, random sign), from 64 random
/// bits for the mantissa and one for the sign.
pub fn uniform_pm1(bits: u64, sign: bool) -> f64 {
    let v = bits as f64 * (1.0 / 18_446_744_073_709_551_616.0);
    if sign {
        -v
    } else {
        v
    }
}

/// SplitMix64: a tiny seeded generator for the large deterministic runs.
pub struct SplitMix64(pub u64);

impl SplitMix64 {
    /// The next 64 random bits.
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    /// A uniformly random f64 in `[-1, 1]` (see [`uniform_pm1`]).
    pub fn pm1(&mut self) -> f64 {
        let b = self.next_u64();
        let s = self.next_u64() & 1 == 1;
        uniform_pm1(b, s)
    }
}
