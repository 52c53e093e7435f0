//! The exact geometric predicates of the workspace: [`orient2d`] and
//! [`orient3d`], returning the exact sign of the orientation determinant for
//! every finite input.
//!
//! These are not the dissertation's predicates: the Booleans never call
//! them (their decisions are the plain-`f64` comparisons of the other
//! modules). They serve shape inspection (self-intersection, crossing
//! edges, point-in-ring), which describes shapes and never decides
//! topology, and test oracles.
//!
//! # Two paths, one answer
//!
//! The fast path is Shewchuk's adaptive-precision predicates (the `robust`
//! crate). They are exact only when no intermediate value overflows or
//! underflows, which plain IEEE inputs do not guarantee: at `f64::MAX / 4`
//! the differences and products overflow, and near the subnormals the
//! error terms of the exact products (Dekker's two-product) are lost. The
//! fast path is taken only when every coordinate is zero or of magnitude
//! in `[2^-250, 2^250]` ([`FAST_MIN`], [`FAST_MAX`]); otherwise the
//! determinant is evaluated exactly in big integers (`num-bigint`; every
//! finite `f64` is an integer times a power of two, so the inputs scaled
//! to a common exponent are integers and the determinant's sign is kept).
//!
//! Why that range is safe. Every coordinate `c` with `|c| >= 2^-250` is an
//! integer multiple of `g = 2^(-250-52)`, so every difference of
//! coordinates, and every tail of such a difference, is a multiple of `g`;
//! every exact product of at most three of them (the most any term of the
//! 3D determinant or its adaptive corrections holds) is a multiple of
//! `g^3 = 2^-906`, and so is every exact sum of such products. Each
//! floating-point operation of the predicates either is exact or rounds a
//! value that is a multiple of `2^-906` at a precision whose unit is a
//! multiple of it, so by induction every computed value is a multiple of
//! `2^-906`: a non-zero one is at least `2^-906`, far inside the normal
//! range (`2^-1022`), and even the error bounds (a constant near
//! `2^-50` times a sum of such values) stay normal, so no value underflows
//! and the relative error model behind the adaptive filters holds. Above,
//! every value is at most a small constant times a product of three
//! differences, `(2^251)^3 * 2^8 = 2^761`, and Dekker's splitter multiplies
//! by `2^27 + 1`, far below `f64::MAX` (about `2^1024`): nothing overflows.
//! The 2D predicate needs products of two differences only, so the same
//! range is safe with room to spare.
//!
//! Non-finite inputs have no orientation; both predicates answer
//! `Ordering::Equal` for them (callers validate coordinates first).

use num_bigint::BigInt;
use num_traits::{Signed, Zero};
use std::cmp::Ordering;

use crate::{Point2, Point3};

/// The smallest non-zero coordinate magnitude of the fast path, `2^-250`
/// (module docs).
pub const FAST_MIN: f64 = 5.527147875260445e-76;

/// The largest coordinate magnitude of the fast path, `2^250` (module
/// docs).
pub const FAST_MAX: f64 = 1.8092513943330656e75;

/// `true` when `c` is zero or of magnitude in `[FAST_MIN, FAST_MAX]`
/// (false for NaN and infinities).
#[inline]
pub(crate) fn in_fast_range(c: f64) -> bool {
    let a = c.abs();
    a == 0.0 || (FAST_MIN..=FAST_MAX).contains(&a)
}

/// The sign of an `f64` as an ordering against zero.
#[inline]
fn sign(v: f64) -> Ordering {
    if v > 0.0 {
        Ordering::Greater
    } else if v < 0.0 {
        Ordering::Less
    } else {
        Ordering::Equal
    }
}

/// The exact sign of the 2D orientation determinant
/// `(a - c) x (b - c) = (a.x - c.x)(b.y - c.y) - (a.y - c.y)(b.x - c.x)`:
/// `Greater` when `a, b, c` turn counter-clockwise, `Less` when clockwise,
/// `Equal` when collinear (or when an input is not finite).
///
/// ```
/// use robust_arith::orient2d;
/// use std::cmp::Ordering;
/// assert_eq!(orient2d([0.0, 0.0], [1.0, 0.0], [0.0, 1.0]), Ordering::Greater);
/// // One ulp off the line y = x: exact, where the plain determinant is 0.
/// let up = f64::from_bits(24.0f64.to_bits() + 1);
/// assert_eq!(orient2d([0.5, 0.5], [12.0, 12.0], [24.0, up]), Ordering::Greater);
/// // Far beyond Shewchuk's safe range.
/// let h = f64::MAX / 4.0;
/// assert_eq!(orient2d([-h, -h], [h, -h], [h, h]), Ordering::Greater);
/// ```
pub fn orient2d(a: Point2, b: Point2, c: Point2) -> Ordering {
    let all = [a[0], a[1], b[0], b[1], c[0], c[1]];
    if all.iter().all(|&v| in_fast_range(v)) {
        let p = |q: Point2| robust::Coord { x: q[0], y: q[1] };
        return sign(robust::orient2d(p(a), p(b), p(c)));
    }
    if !all.iter().all(|v| v.is_finite()) {
        return Ordering::Equal;
    }
    orient2d_exact(a, b, c)
}

/// The exact sign of the 3D orientation determinant of the rows
/// `a - d, b - d, c - d` (Shewchuk's convention): `Greater` when `d` lies
/// below the plane through `a, b, c`, i.e. `a, b, c` appear
/// counter-clockwise seen from above the plane on the side opposite `d`;
/// `Less` when above; `Equal` when the four points are coplanar (or when
/// an input is not finite).
///
/// ```
/// use robust_arith::orient3d;
/// use std::cmp::Ordering;
/// let (a, b, c) = ([0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]);
/// assert_eq!(orient3d(a, b, c, [0.0, 0.0, -1.0]), Ordering::Greater);
/// assert_eq!(orient3d(a, b, c, [0.0, 0.0, 1.0]), Ordering::Less);
/// assert_eq!(orient3d(a, b, c, [7.0, -3.0, 0.0]), Ordering::Equal);
/// // Subnormal heights: the plain determinant underflows to zero.
/// let tiny = f64::from_bits(1);
/// assert_eq!(orient3d(a, b, c, [0.5, 0.5, tiny]), Ordering::Less);
/// ```
pub fn orient3d(a: Point3, b: Point3, c: Point3, d: Point3) -> Ordering {
    let all = [
        a[0], a[1], a[2], b[0], b[1], b[2], c[0], c[1], c[2], d[0], d[1], d[2],
    ];
    if all.iter().all(|&v| in_fast_range(v)) {
        let p = |q: Point3| robust::Coord3D {
            x: q[0],
            y: q[1],
            z: q[2],
        };
        return sign(robust::orient3d(p(a), p(b), p(c), p(d)));
    }
    if !all.iter().all(|v| v.is_finite()) {
        return Ordering::Equal;
    }
    orient3d_exact(a, b, c, d)
}

/// `(m, e)` with `v = m * 2^e` exactly (finite `v`; `|m| < 2^53`, zero
/// only for `v = ±0`).
pub(crate) fn decode(v: f64) -> (i64, i32) {
    let bits = v.to_bits();
    let negative = bits >> 63 == 1;
    let exp = ((bits >> 52) & 0x7ff) as i32;
    let frac = (bits & 0x000f_ffff_ffff_ffff) as i64;
    let (m, e) = if exp == 0 {
        (frac, -1074)
    } else {
        (frac | (1 << 52), exp - 1075)
    };
    (if negative { -m } else { m }, e)
}

/// The smallest exponent among the decoded non-zero values (0 when all
/// are zero): scaled by `2^-low`, every value is an integer.
pub(crate) fn common_exponent(dec: &[(i64, i32)]) -> i32 {
    dec.iter()
        .filter(|d| d.0 != 0)
        .map(|d| d.1)
        .min()
        .unwrap_or(0)
}

/// The finite values as exact integers, all scaled by one common positive
/// power of two (which changes no determinant's sign).
fn scaled<const N: usize>(values: [f64; N]) -> [BigInt; N] {
    let dec = values.map(decode);
    let low = common_exponent(&dec);
    dec.map(|(m, e)| BigInt::from(m) << ((e - low) as usize))
}

/// The sign of an exact integer.
fn int_sign(v: &BigInt) -> Ordering {
    if v.is_zero() {
        Ordering::Equal
    } else if v.is_positive() {
        Ordering::Greater
    } else {
        Ordering::Less
    }
}

/// [`orient2d`] in exact integer arithmetic (finite inputs).
fn orient2d_exact(a: Point2, b: Point2, c: Point2) -> Ordering {
    let [ax, ay, bx, by, cx, cy] = scaled([a[0], a[1], b[0], b[1], c[0], c[1]]);
    int_sign(&((ax - &cx) * (by - &cy) - (ay - &cy) * (bx - &cx)))
}

/// [`orient3d`] in exact integer arithmetic (finite inputs).
fn orient3d_exact(a: Point3, b: Point3, c: Point3, d: Point3) -> Ordering {
    let [ax, ay, az, bx, by, bz, cx, cy, cz, dx, dy, dz] = scaled([
        a[0], a[1], a[2], b[0], b[1], b[2], c[0], c[1], c[2], d[0], d[1], d[2],
    ]);
    let u = [ax - &dx, ay - &dy, az - &dz];
    let v = [bx - &dx, by - &dy, bz - &dz];
    let w = [cx - &dx, cy - &dy, cz - &dz];
    let det = &u[0] * (&v[1] * &w[2] - &v[2] * &w[1]) - &u[1] * (&v[0] * &w[2] - &v[2] * &w[0])
        + &u[2] * (&v[0] * &w[1] - &v[1] * &w[0]);
    int_sign(&det)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn range_constants_are_the_stated_powers_of_two() {
        assert_eq!(FAST_MIN, 2f64.powi(-250));
        assert_eq!(FAST_MAX, 2f64.powi(250));
    }

    #[test]
    fn both_paths_agree_where_both_apply() {
        // Integer grid points: both the adaptive and the rational path are
        // exact there.
        for i in 0..5 {
            for j in 0..5 {
                let (a, b, c) = ([0.0, 0.0], [4.0, 2.0], [f64::from(i), f64::from(j)]);
                assert_eq!(orient2d(a, b, c), orient2d_exact(a, b, c));
                let d = [f64::from(i), f64::from(j), f64::from(i * j % 3) - 1.0];
                let (a, b, c) = ([0.0; 3], [3.0, 1.0, 0.0], [1.0, 3.0, 1.0]);
                assert_eq!(orient3d(a, b, c, d), orient3d_exact(a, b, c, d));
            }
        }
    }

    #[test]
    fn non_finite_inputs_are_equal() {
        assert_eq!(
            orient2d([f64::NAN, 0.0], [1.0, 0.0], [0.0, 1.0]),
            Ordering::Equal
        );
        assert_eq!(
            orient3d(
                [0.0; 3],
                [1.0, 0.0, 0.0],
                [0.0, 1.0, 0.0],
                [0.0, 0.0, f64::INFINITY]
            ),
            Ordering::Equal
        );
    }
}
