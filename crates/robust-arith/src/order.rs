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
