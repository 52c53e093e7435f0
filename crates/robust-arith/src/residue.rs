//! An exact coplanarity test, [`coplanar`], with a residue filter in front
//! of the exact [`orient3d`](crate::orient3d).
//!
//! Four points that are coplanar in real numbers but rounded to `f64` (the
//! two triangles of a flat quadrilateral, say) defeat every floating-point
//! filter: their determinant is of the size of its own rounding error, so
//! the adaptive predicate runs to its exact stage. Whether the determinant
//! is *zero* needs no sign, and that has a cheap exact certificate.
//!
//! Every finite `f64` is `m * 2^e` with an integer `|m| < 2^53`. Scaled by
//! `2^-e_min`, the smallest exponent among the non-zero coordinates, all
//! twelve coordinates are integers and the determinant (a homogeneous
//! cubic in them) is multiplied by `2^(-3 e_min)`, which keeps it non-zero
//! or zero. Reduced modulo the Mersenne prime `p = 2^61 - 1` it is computed
//! exactly in 64-bit words (reduction is a ring homomorphism), and
//! `2^k mod p = 2^(k mod 61)` makes the scaling a shift. A non-zero residue
//! proves a non-zero determinant; a zero residue (every coplanar input, and
//! about one non-coplanar input in `2^61`) defers to the exact predicate.

use crate::exact::{common_exponent, decode, in_fast_range, orient3d};
use crate::{Point3, UNIT_ROUNDOFF};
use std::cmp::Ordering;

/// The Mersenne prime `2^61 - 1`.
const P: u64 = (1 << 61) - 1;

/// `x mod P` for `x < 2^122`.
#[inline]
fn reduce(x: u128) -> u64 {
    // x = hi * 2^61 + lo, and 2^61 = 1 (mod P).
    let folded = (x as u64 & P) as u128 + (x >> 61);
    let r = (folded as u64 & P) + (folded >> 61) as u64;
    if r >= P {
        r - P
    } else {
        r
    }
}

/// `a * b mod P` for `a, b < P`.
#[inline]
fn mul(a: u64, b: u64) -> u64 {
    reduce(u128::from(a) * u128::from(b))
}

/// `a + b mod P` for `a, b < P`.
#[inline]
fn add(a: u64, b: u64) -> u64 {
    let s = a + b;
    if s >= P {
        s - P
    } else {
        s
    }
}

/// `a - b mod P` for `a, b < P`.
#[inline]
fn sub(a: u64, b: u64) -> u64 {
    if a >= b {
        a - b
    } else {
        a + P - b
    }
}

/// The residues mod `P` of the coordinates scaled to integers by one
/// common power of two.
#[inline]
fn residues(values: [f64; 12]) -> [u64; 12] {
    let dec = values.map(decode);
    let low = common_exponent(&dec);
    dec.map(|(m, e)| {
        // |m| < 2^53 < P and the shift is below 61 (for a zero `m`, whose
        // exponent may be below `low`, any shift gives zero), so the
        // product is below 2^114.
        let r = reduce(u128::from(m.unsigned_abs()) << (e - low).rem_euclid(61) as u32);
        if m < 0 {
            sub(0, r)
        } else {
            r
        }
    })
}

/// Whether the four points are coplanar, exactly: `orient3d(a, b, c, d)
/// == Ordering::Equal` (so `true` for a non-finite input too), decided by
/// a residue certificate when the determinant is not zero (module docs).
///
/// ```
/// use robust_arith::coplanar;
/// let (a, b, c) = ([0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]);
/// assert!(coplanar(a, b, c, [7.0, -3.0, 0.0]));
/// assert!(!coplanar(a, b, c, [0.5, 0.5, f64::from_bits(1)]));
/// ```
pub fn coplanar(a: Point3, b: Point3, c: Point3, d: Point3) -> bool {
    let all = [
        a[0], a[1], a[2], b[0], b[1], b[2], c[0], c[1], c[2], d[0], d[1], d[2],
    ];
    if all.iter().all(|&v| in_fast_range(v)) && certainly_nonzero(a, b, c, d) {
        return false;
    }
    if all.iter().all(|v| v.is_finite()) && residue_nonzero(all) {
        return false;
    }
    orient3d(a, b, c, d) == Ordering::Equal
}

/// Shewchuk's first-stage filter of `orient3d` (his operation order and
/// error bound `(7 + 56 eps) eps` times the permanent), valid in the fast
/// path's range (`crate::exact` module docs): `true` when the determinant
/// is certainly not zero.
#[inline]
fn certainly_nonzero(a: Point3, b: Point3, c: Point3, d: Point3) -> bool {
    let (adx, bdx, cdx) = (a[0] - d[0], b[0] - d[0], c[0] - d[0]);
    let (ady, bdy, cdy) = (a[1] - d[1], b[1] - d[1], c[1] - d[1]);
    let (adz, bdz, cdz) = (a[2] - d[2], b[2] - d[2], c[2] - d[2]);
    let (bdxcdy, cdxbdy) = (bdx * cdy, cdx * bdy);
    let (cdxady, adxcdy) = (cdx * ady, adx * cdy);
    let (adxbdy, bdxady) = (adx * bdy, bdx * ady);
    let det = adz * (bdxcdy - cdxbdy) + bdz * (cdxady - adxcdy) + cdz * (adxbdy - bdxady);
    let permanent = (bdxcdy.abs() + cdxbdy.abs()) * adz.abs()
        + (cdxady.abs() + adxcdy.abs()) * bdz.abs()
        + (adxbdy.abs() + bdxady.abs()) * cdz.abs();
    let eps = UNIT_ROUNDOFF;
    det.abs() > (7.0 + 56.0 * eps) * eps * permanent
}

/// Whether the orientation determinant of the twelve finite coordinates
/// `a, b, c, d` is non-zero modulo `P` (so certainly non-zero).
#[inline]
fn residue_nonzero(all: [f64; 12]) -> bool {
    let r = residues(all);
    let (d0, d1, d2) = (r[9], r[10], r[11]);
    let (ax, ay, az) = (sub(r[0], d0), sub(r[1], d1), sub(r[2], d2));
    let (bx, by, bz) = (sub(r[3], d0), sub(r[4], d1), sub(r[5], d2));
    let (cx, cy, cz) = (sub(r[6], d0), sub(r[7], d1), sub(r[8], d2));
    let det = add(
        add(
            mul(az, sub(mul(bx, cy), mul(cx, by))),
            mul(bz, sub(mul(cx, ay), mul(ax, cy))),
        ),
        mul(cz, sub(mul(ax, by), mul(bx, ay))),
    );
    det != 0
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn modular_arithmetic_matches_big_integers() {
        let big = |v: u128| (v % u128::from(P)) as u64;
        let samples = [0u64, 1, 2, P - 1, P - 2, 1 << 60, (1 << 53) - 1, 12345];
        for &a in &samples {
            for &b in &samples {
                assert_eq!(mul(a, b), big(u128::from(a) * u128::from(b)));
                assert_eq!(add(a, b), big(u128::from(a) + u128::from(b)));
                assert_eq!(
                    sub(a, b),
                    big(u128::from(a) + u128::from(P) - u128::from(b))
                );
            }
        }
        assert_eq!(reduce((1u128 << 122) - 1), big((1u128 << 122) - 1));
    }

    #[test]
    fn decode_is_exact() {
        for v in [1.0, -0.75, 3.5e-300, f64::from_bits(1), f64::MAX, -0.0] {
            let (m, e) = decode(v);
            let back = m as f64 * 2f64.powi(e.max(-1022)) * 2f64.powi((e + 1022).min(0));
            assert_eq!(back, v);
        }
    }

    #[test]
    fn scaling_is_a_shift() {
        // 1.5 = (3 * 2^51) * 2^-52 and 2^70 = 2^52 * 2^18: scaled by 2^52
        // they are 3 * 2^51 and 2^122 = (2^61)^2 = 1 (mod P); zeros stay 0.
        let mut values = [0.0; 12];
        values[0] = 1.5;
        values[1] = 2f64.powi(70);
        let r = residues(values);
        assert_eq!(r[0], 3 << 51);
        assert_eq!(r[1], 1);
        assert_eq!(r[2], 0);
        values[0] = -1.5;
        assert_eq!(residues(values)[0], P - (3 << 51));
    }
}
