//! The general point-pair interpolation of eq. 4.2-4.6.

/// Interpolates the intersection point pair of a level-`k+1` intersection
/// from two lower-level pairs (eq. 4.2-4.6).
///
/// `(a_plus, b_plus)` is a lower-level pair where B shadows A in coordinate
/// `k` (`Delta_+ = b_plus[k] - a_plus[k] >= 0`, eq. 4.5) and
/// `(a_minus, b_minus)` one where A shadows B (`Delta_- < 0`, eq. 4.6).
/// Within each pair the coordinates `0..k` are equal (they are the
/// coordinates of the subspace the lower intersection lives in).
///
/// With `t = Delta_+ / (Delta_+ - Delta_-)` (eq. 4.4) the result is
/// `x_A = x_A+ - t (x_A+ - x_A-)` and `x_B = x_B+ - t (x_B+ - x_B-)`
/// (eq. 4.2, 4.3), evaluated as footnote 1 of section 4.5 prescribes:
///
/// - from the closer end: when `t > 1/2` (`Delta_+ >= -Delta_-`) the
///   interpolation runs from the minus pair with `1 - t`;
/// - coordinates `0..k` are computed once (from A's points) and shared;
/// - coordinate `k` is computed once, from whichever of A and B changes
///   less in it (the smaller slope), and shared, so the two points agree
///   exactly in the first `k + 1` coordinates;
/// - coordinates after `k` are interpolated for A and B separately.
///
/// For `N = 2, k = 1` this is exactly [`crate::interpolate`] (Table 7.2)
/// with the plus pair as "left" and the minus pair as "right".
///
/// Precondition (not checked): `Delta_+ >= 0 > Delta_-`, which Theorem 1
/// guarantees whenever the higher-level X is non-zero.
#[inline]
pub fn interpolate_pair<const N: usize>(
    k: usize,
    a_plus: [f64; N],
    b_plus: [f64; N],
    a_minus: [f64; N],
    b_minus: [f64; N],
) -> ([f64; N], [f64; N]) {
    let d_plus = b_plus[k] - a_plus[k]; // eq. 4.5, >= 0
    let d_minus = b_minus[k] - a_minus[k]; // eq. 4.6, < 0
    let plus_closer = d_plus < -d_minus; // t < 1/2
    let lambda = (if plus_closer { d_plus } else { d_minus }) / (d_plus - d_minus);
    let (a0, b0) = if plus_closer {
        (a_plus, b_plus)
    } else {
        (a_minus, b_minus)
    };
    let mut xa = [0.0; N];
    let mut xb = [0.0; N];
    for c in 0..k {
        let v = a0[c] + lambda * (a_minus[c] - a_plus[c]);
        xa[c] = v;
        xb[c] = v;
    }
    let dk_a = a_minus[k] - a_plus[k];
    let dk_b = b_minus[k] - b_plus[k];
    let v = if dk_a.abs() < dk_b.abs() {
        a0[k] + lambda * dk_a
    } else {
        b0[k] + lambda * dk_b
    };
    xa[k] = v;
    xb[k] = v;
    for c in k + 1..N {
        xa[c] = a0[c] + lambda * (a_minus[c] - a_plus[c]);
        xb[c] = b0[c] + lambda * (b_minus[c] - b_plus[c]);
    }
    (xa, xb)
}
