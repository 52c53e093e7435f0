//! The first stage of the intersection calculation (section 7.1.1): the
//! y-value of a non-vertical segment at a given x, exactly as Table 7.1.

/// The y-value `y_S` such that `(x_p, y_S)` lies on the segment `l -> r`,
/// computed exactly as the code of Table 7.1.
///
/// Preconditions (not checked, as in the dissertation): `l[0] < r[0]` and
/// `l[0] <= x_p <= r[0]`. The interpolation starts from the end closer in x
/// to `x_p`, so `x_p == l[0]` gives `l[1]` exactly and `x_p == r[0]` gives
/// `r[1]` exactly; a horizontal segment gives its y exactly. The result is
/// within `4 u L_Y` of the true segment (Table 8.1).
///
/// ```
/// use robust_arith::y_at_x;
/// assert_eq!(y_at_x([0.0, 1.0], [3.0, 7.0], 0.0), 1.0);
/// assert_eq!(y_at_x([0.0, 1.0], [3.0, 7.0], 3.0), 7.0);
/// assert_eq!(y_at_x([0.0, 1.0], [3.0, 7.0], 1.5), 4.0);
/// ```
#[inline]
pub fn y_at_x(l: [f64; 2], r: [f64; 2], x_p: f64) -> f64 {
    // Table 7.1, statement by statement.
    let dx_l = x_p - l[0]; // >= 0
    let dx_r = x_p - r[0]; // <= 0
    let dx_l_less = dx_l < -dx_r;
    let lambda = (if dx_l_less { dx_l } else { dx_r }) / (r[0] - l[0]);
    (if dx_l_less { l[1] } else { r[1] }) + lambda * (r[1] - l[1])
}

/// The N-dimensional form of [`y_at_x`]: the point of segment `l -> r` whose
/// first coordinate is `x_p`. Coordinate 0 of the result is `x_p` itself;
/// every further coordinate is computed exactly as the y of Table 7.1, with
/// the same `lambda`, from the end closer in x. For `N = 2` the result is
/// `[x_p, y_at_x(l, r, x_p)]` bit for bit.
///
/// Same preconditions as [`y_at_x`]. This is the level-1 intersection point
/// of a vertex with an edge (eq. 4.2-4.6 with the closer-end choice of
/// footnote 1 of section 4.5).
#[inline]
pub fn point_at_x<const N: usize>(l: [f64; N], r: [f64; N], x_p: f64) -> [f64; N] {
    let dx_l = x_p - l[0];
    let dx_r = x_p - r[0];
    let dx_l_less = dx_l < -dx_r;
    let lambda = (if dx_l_less { dx_l } else { dx_r }) / (r[0] - l[0]);
    let mut out = [0.0; N];
    out[0] = x_p;
    for c in 1..N {
        out[c] = (if dx_l_less { l[c] } else { r[c] }) + lambda * (r[c] - l[c]);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn end_points_are_exact() {
        let l = [0.1, 0.3];
        let r = [0.7, -0.9];
        assert_eq!(y_at_x(l, r, l[0]), l[1]);
        assert_eq!(y_at_x(l, r, r[0]), r[1]);
    }

    #[test]
    fn horizontal_segment_is_exact() {
        for i in 0..100 {
            let x = -1.0 + 0.0173 * i as f64;
            assert_eq!(y_at_x([-1.0, 0.3], [1.0, 0.3], x), 0.3);
        }
    }

    #[test]
    fn point_at_x_matches_y_at_x_in_2d() {
        let l = [-0.25, 0.125];
        let r = [0.75, 0.6];
        for i in 0..=100 {
            let x = -0.25 + 0.01 * i as f64;
            let x = x.min(0.75);
            let p = point_at_x(l, r, x);
            assert_eq!(p, [x, y_at_x(l, r, x)]);
        }
    }

    #[test]
    fn point_at_x_interpolates_z_with_the_same_lambda() {
        let p = point_at_x([0.0, 0.0, 0.0], [4.0, 8.0, -4.0], 1.0);
        assert_eq!(p, [1.0, 2.0, -1.0]);
        let p = point_at_x([0.0, 0.0, 0.0], [4.0, 8.0, -4.0], 4.0);
        assert_eq!(p, [4.0, 8.0, -4.0]);
    }
}
