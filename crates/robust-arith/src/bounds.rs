//! The error-bound constants of chapter 8 and the power-of-two scale `L`
//! they are expressed in.

/// The unit roundoff `u = 2^-53` of IEEE 754 double precision (section 8.1):
/// half the spacing of representable numbers in `[1, 2)`, so that the
/// spacing in `[L/2, L]` is `uL`.
pub const UNIT_ROUNDOFF: f64 = f64::EPSILON / 2.0;

/// The bound of Table 8.1: a value computed by [`crate::y_at_x`] lies within
/// `4 u L_Y` of the true segment, where `L_Y` is a power of two bounding the
/// y-coordinates.
pub const Y_AT_X_ERROR_FACTOR: f64 = 4.0;

/// The bound of eq. 8.17: a point computed by [`crate::interpolate`] lies
/// within `sqrt(153) u L` (about `12.37 u L`) of both segments, where `L` is
/// a power of two bounding every coordinate of both segments.
pub const INTERSECTION_ERROR_FACTOR: f64 = 12.369_316_876_852_98; // sqrt(153)

/// The largest coordinate magnitude accepted: `f64::MAX / 4`, so that no
/// subtraction of coordinates overflows (section 8.5).
pub const MAX_COORDINATE: f64 = f64::MAX / 4.0;

/// The smallest power of two `L >= max_abs` (and at least the smallest
/// positive normal number), the scale in which the chapter 8 bounds are
/// stated. Returns infinity for non-finite input and above `2^1023`, the
/// largest power of two an `f64` holds.
///
/// ```
/// use robust_arith::power_of_two_bound;
/// assert_eq!(power_of_two_bound(1.0), 1.0);
/// assert_eq!(power_of_two_bound(3.0), 4.0);
/// assert_eq!(power_of_two_bound(0.3), 0.5);
/// assert_eq!(power_of_two_bound(f64::MAX), f64::INFINITY);
/// ```
pub fn power_of_two_bound(max_abs: f64) -> f64 {
    let m = max_abs.abs();
    if !m.is_finite() {
        return f64::INFINITY;
    }
    let mut l = f64::MIN_POSITIVE;
    if m <= l {
        return l;
    }
    // Start from the binary exponent of m and correct by at most one step.
    let exp = m.log2().floor() as i32;
    l = 2f64.powi(exp.clamp(-1022, 1023));
    while l < m {
        l *= 2.0;
    }
    if l.is_infinite() {
        // m > 2^1023: no finite power of two bounds it (halving an
        // infinity below would never end).
        return l;
    }
    while l / 2.0 >= m && l / 2.0 >= f64::MIN_POSITIVE {
        l /= 2.0;
    }
    l
}

/// `4 u L`: the bound on the error of [`crate::y_at_x`] for coordinates
/// bounded by `max_abs` (Table 8.1).
pub fn y_at_x_error_bound(max_abs: f64) -> f64 {
    Y_AT_X_ERROR_FACTOR * UNIT_ROUNDOFF * power_of_two_bound(max_abs)
}

/// `sqrt(153) u L`: the bound on the distance of a computed intersection
/// point from either segment, for coordinates bounded by `max_abs`
/// (eq. 8.17). This is the `alpha` of section 8.4 and so the epsilon of the
/// 2D basic Boolean.
pub fn intersection_error_bound(max_abs: f64) -> f64 {
    INTERSECTION_ERROR_FACTOR * UNIT_ROUNDOFF * power_of_two_bound(max_abs)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sqrt_153_constant_is_correctly_rounded() {
        assert_eq!(INTERSECTION_ERROR_FACTOR, 153f64.sqrt());
        assert_eq!(UNIT_ROUNDOFF, 2f64.powi(-53));
    }

    #[test]
    fn power_of_two_bound_is_tight() {
        for &(m, l) in &[
            (1.0, 1.0),
            (1.0000001, 2.0),
            (0.5, 0.5),
            (0.50001, 1.0),
            (1e300, 2f64.powi(997)),
            (0.0, f64::MIN_POSITIVE),
            (2f64.powi(1023), 2f64.powi(1023)),
            (MAX_COORDINATE * 2.0, 2f64.powi(1023)),
            // Above 2^1023 no finite power of two bounds m (this looped
            // forever on an infinity before).
            (1.5 * 2f64.powi(1023), f64::INFINITY),
            (f64::MAX, f64::INFINITY),
            (f64::NAN, f64::INFINITY),
        ] {
            assert_eq!(power_of_two_bound(m), l, "m = {m}");
        }
        for i in -1000..1000 {
            let m = 1.37f64 * 2f64.powi(i);
            let l = power_of_two_bound(m);
            assert!(l >= m && l / 2.0 < m, "m = {m}, l = {l}");
        }
    }
}
