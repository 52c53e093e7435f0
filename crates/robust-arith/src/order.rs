//! The lexicographic point order of section 7.1.2: by x first, then by y
//! (then by z). A vertical segment's "leftmost" point is its lowest.

use std::cmp::Ordering;

/// Compares two points lexicographically. `-0.0` and `+0.0` compare equal;
/// NaN (which validated data never holds) falls back to the IEEE total order
/// so the comparison is still a total order.
///
/// ```
/// use robust_arith::lex_cmp;
/// use std::cmp::Ordering;
/// assert_eq!(lex_cmp(&[0.0, 5.0], &[1.0, 0.0]), Ordering::Less);
/// assert_eq!(lex_cmp(&[1.0, 5.0], &[1.0, 0.0]), Ordering::Greater);
/// assert_eq!(lex_cmp(&[-0.0, 1.0], &[0.0, 1.0]), Ordering::Equal);
/// ```
#[inline]
pub fn lex_cmp<const N: usize>(a: &[f64; N], b: &[f64; N]) -> Ordering {
    for i in 0..N {
        let o = a[i]
            .partial_cmp(&b[i])
            .unwrap_or_else(|| a[i].total_cmp(&b[i]));
        if o != Ordering::Equal {
            return o;
        }
    }
    Ordering::Equal
}

/// `true` when `a` precedes `b` in the lexicographic order.
#[inline]
pub fn lex_less<const N: usize>(a: &[f64; N], b: &[f64; N]) -> bool {
    lex_cmp(a, b) == Ordering::Less
}

/// The integer image of `f64::total_cmp`: `total_order_key(a) <
/// total_order_key(b)` exactly when `a.total_cmp(&b)` is `Less`, so sorts
/// and heaps over coordinates can compare integers. On finite values with
/// `-0.0` normalised to `+0.0` (what validated data holds) it is the order
/// of [`lex_cmp`] per coordinate.
///
/// ```
/// use robust_arith::{from_total_order_key, total_order_key};
/// assert!(total_order_key(-1.0) < total_order_key(0.5));
/// assert_eq!(from_total_order_key(total_order_key(-2.5)), -2.5);
/// ```
#[inline]
pub fn total_order_key(x: f64) -> u64 {
    let bits = x.to_bits();
    if bits >> 63 == 1 {
        !bits
    } else {
        bits | (1 << 63)
    }
}

/// The inverse of [`total_order_key`], bit for bit.
#[inline]
pub fn from_total_order_key(key: u64) -> f64 {
    f64::from_bits(if key >> 63 == 1 {
        key & !(1 << 63)
    } else {
        !key
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn total_order_key_is_total_cmp_and_invertible() {
        let values = [
            f64::NEG_INFINITY,
            -f64::MAX,
            -1.5,
            -f64::MIN_POSITIVE,
            -5e-324,
            -0.0,
            0.0,
            5e-324,
            f64::MIN_POSITIVE,
            1.0,
            1.5,
            f64::MAX,
            f64::INFINITY,
        ];
        for a in values {
            assert_eq!(
                from_total_order_key(total_order_key(a)).to_bits(),
                a.to_bits()
            );
            for b in values {
                assert_eq!(
                    total_order_key(a).cmp(&total_order_key(b)),
                    a.total_cmp(&b),
                    "{a} vs {b}"
                );
            }
        }
    }
}
