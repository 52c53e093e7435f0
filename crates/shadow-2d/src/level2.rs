//! The level-2 intersection and shadow functions (Table 4.1).

use crate::{Partners, ShadowError};
use shadow_1d::{x01, x10, Hit};

fn finish<const N: usize>(
    value: i32,
    partners: &Partners<N>,
    function: &'static str,
) -> Result<Option<Hit<N>>, ShadowError> {
    if value == 0 {
        return Ok(None);
    }
    match partners.interpolate() {
        Some((a, b)) => Ok(Some(Hit { value, a, b })),
        None => {
            debug_assert!(false, "Theorem 1 violated in {function}");
            Err(ShadowError::MissingPartner { function })
        }
    }
}

/// `X02(v_A, f_B) = -sum_{h in f_B} S01(v_A, h)` (Table 4.1) for a facet
/// given as its half-edges `(start, end)`: the winding number of `v_A` in
/// the facet's projection on the (x, y) plane. The pair is `v_A` and the
/// point of the facet above or below it (for `N = 2`, `v_A` twice).
pub fn x02<const N: usize>(
    va: &[f64; N],
    facet: impl IntoIterator<Item = ([f64; N], [f64; N])>,
) -> Result<Option<Hit<N>>, ShadowError> {
    x02_weighted(va, facet.into_iter().map(|(s, e)| (s, e, 1)))
}

/// [`x02`] for half-edges with multiplicities `(start, end, mult)`.
pub fn x02_weighted<const N: usize>(
    va: &[f64; N],
    facet: impl IntoIterator<Item = ([f64; N], [f64; N], i32)>,
) -> Result<Option<Hit<N>>, ShadowError> {
    let mut partners = Partners::new(1);
    let mut value = 0;
    for (s, e, m) in facet {
        if m == 0 {
            continue;
        }
        if let Some(h) = x01(va, &s, &e) {
            let h = Hit {
                value: h.value * m,
                ..h
            };
            value -= partners.offer(h);
        }
    }
    finish(value, &partners, "X02")
}

/// `X20(f_A, v_B) = sum_{h in f_A} S10(h, v_B)` (Table 4.1) for a facet
/// given as its half-edges `(start, end)`.
pub fn x20<const N: usize>(
    facet: impl IntoIterator<Item = ([f64; N], [f64; N])>,
    vb: &[f64; N],
) -> Result<Option<Hit<N>>, ShadowError> {
    x20_weighted(facet.into_iter().map(|(s, e)| (s, e, 1)), vb)
}

/// [`x20`] for half-edges with multiplicities `(start, end, mult)`.
pub fn x20_weighted<const N: usize>(
    facet: impl IntoIterator<Item = ([f64; N], [f64; N], i32)>,
    vb: &[f64; N],
) -> Result<Option<Hit<N>>, ShadowError> {
    let mut partners = Partners::new(1);
    let mut value = 0;
    for (s, e, m) in facet {
        if m == 0 {
            continue;
        }
        if let Some(h) = x10(&s, &e, vb) {
            let h = Hit {
                value: h.value * m,
                ..h
            };
            value += partners.offer(h);
        }
    }
    finish(value, &partners, "X20")
}

/// `X11(e_A, e_B) = S01(v_e(e_A), e_B) - S01(v_s(e_A), e_B)
/// + S10(e_A, v_e(e_B)) - S10(e_A, v_s(e_B))` (Table 4.1): `+1` when the
/// (half-)edge `as_ -> ae` crosses `bs -> be` from left to right in (x, y).
/// The pair shares x and y (Table 7.2 for `N = 2`).
pub fn x11<const N: usize>(
    as_: &[f64; N],
    ae: &[f64; N],
    bs: &[f64; N],
    be: &[f64; N],
) -> Result<Option<Hit<N>>, ShadowError> {
    let mut partners = Partners::new(1);
    let mut value = 0;
    if let Some(h) = x01(ae, bs, be) {
        value += partners.offer(h);
    }
    if let Some(h) = x01(as_, bs, be) {
        value += partners.offer(h.negated());
    }
    if let Some(h) = x10(as_, ae, be) {
        value += partners.offer(h);
    }
    if let Some(h) = x10(as_, ae, bs) {
        value += partners.offer(h.negated());
    }
    finish(value, &partners, "X11")
}

/// `S02(v_A, f_B)`: `X02` when the facet's z at the vertex is `>=` the
/// vertex's z (eq. 4.1). Meaningful for `N >= 3`.
pub fn s02<const N: usize>(
    va: &[f64; N],
    facet: impl IntoIterator<Item = ([f64; N], [f64; N])>,
) -> Result<i32, ShadowError> {
    Ok(x02(va, facet)?.map_or(0, |h| h.shadow(2)))
}

/// `S11(e_A, e_B)`: `X11` when `e_B`'s z at the crossing is `>=` `e_A`'s
/// (eq. 4.1). Meaningful for `N >= 3`.
pub fn s11<const N: usize>(
    as_: &[f64; N],
    ae: &[f64; N],
    bs: &[f64; N],
    be: &[f64; N],
) -> Result<i32, ShadowError> {
    Ok(x11(as_, ae, bs, be)?.map_or(0, |h| h.shadow(2)))
}

/// `S20(f_A, v_B)`: `X20` when the vertex's z is `>=` the facet's z below or
/// above it (eq. 4.1). Meaningful for `N >= 3`.
pub fn s20<const N: usize>(
    facet: impl IntoIterator<Item = ([f64; N], [f64; N])>,
    vb: &[f64; N],
) -> Result<i32, ShadowError> {
    Ok(x20(facet, vb)?.map_or(0, |h| h.shadow(2)))
}

#[cfg(test)]
mod tests {
    use super::*;
    use robust_arith::interpolate;

    fn ring(points: &[[f64; 2]]) -> Vec<([f64; 2], [f64; 2])> {
        (0..points.len())
            .map(|i| (points[i], points[(i + 1) % points.len()]))
            .collect()
    }

    #[test]
    fn winding_numbers_of_a_square() {
        let sq = ring(&[[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]]);
        let w = |p: [f64; 2]| x02(&p, sq.iter().copied()).unwrap().map_or(0, |h| h.value);
        assert_eq!(w([1.0, 1.0]), 1);
        assert_eq!(w([3.0, 1.0]), 0);
        assert_eq!(w([1.0, 3.0]), 0);
        assert_eq!(w([1.0, -1.0]), 0);
        // Clockwise square: -1.
        let cw: Vec<_> = sq.iter().map(|&(s, e)| (e, s)).collect();
        assert_eq!(
            x02(&[1.0, 1.0], cw.iter().copied()).unwrap().unwrap().value,
            -1
        );
        // X20 of the same square and vertex agrees in the interior.
        assert_eq!(
            x20(sq.iter().copied(), &[1.0, 1.0]).unwrap().unwrap().value,
            1
        );
    }

    #[test]
    fn x11_is_antisymmetric_under_reversal() {
        // e_B runs from (1,0) to (0,1): its left side is towards the origin,
        // so e_A from (0,0) to (1,1) crosses it from left to right.
        let (a0, a1, b0, b1) = ([0.0, 0.0], [1.0, 1.0], [1.0, 0.0], [0.0, 1.0]);
        let h = x11(&a0, &a1, &b0, &b1).unwrap().unwrap();
        assert_eq!(h.value, 1);
        assert_eq!(x11(&a1, &a0, &b0, &b1).unwrap().unwrap().value, -1);
        assert_eq!(x11(&a0, &a1, &b1, &b0).unwrap().unwrap().value, -1);
        assert_eq!(x11(&a1, &a0, &b1, &b0).unwrap().unwrap().value, 1);
        // The point is the Table 7.2 point.
        let p = interpolate(1.0, 1.0, 0.0, 0.0, 0.0, 1.0);
        assert_eq!(h.a, p);
        assert_eq!(h.b, p);
    }

    #[test]
    fn x11_in_3d_gives_separate_z_and_shadow() {
        let h = x11(
            &[0.0, 0.0, 0.0],
            &[1.0, 1.0, 0.0],
            &[1.0, 0.0, 1.0],
            &[0.0, 1.0, 1.0],
        )
        .unwrap()
        .unwrap();
        assert_eq!(h.a, [0.5, 0.5, 0.0]);
        assert_eq!(h.b, [0.5, 0.5, 1.0]);
        assert_eq!(h.shadow(2), 1);
    }

    #[test]
    fn x02_in_3d_interpolates_the_facet_height() {
        let tri = [[0.0, 0.0, 1.0], [4.0, 0.0, 1.0], [0.0, 4.0, 3.0]];
        let facet: Vec<_> = (0..3).map(|i| (tri[i], tri[(i + 1) % 3])).collect();
        let h = x02(&[1.0, 1.0, 0.0], facet.iter().copied())
            .unwrap()
            .unwrap();
        assert_eq!(h.value, 1);
        assert_eq!(h.a, [1.0, 1.0, 0.0]);
        assert_eq!([h.b[0], h.b[1]], [1.0, 1.0]);
        assert!((h.b[2] - 1.5).abs() < 1e-15);
        assert_eq!(s02(&[1.0, 1.0, 0.0], facet.iter().copied()).unwrap(), 1);
        assert_eq!(s02(&[1.0, 1.0, 2.0], facet.iter().copied()).unwrap(), 0);
    }

    #[test]
    fn open_facet_is_reported_not_panicked_in_release() {
        // A single half-edge is not a closed facet: X02 may be non-zero
        // without a partner below.
        let facet = [([0.0, 1.0], [1.0, 1.0])];
        let r = std::panic::catch_unwind(|| x02(&[0.5, 0.0], facet.iter().copied()));
        if let Ok(r) = r {
            assert_eq!(r, Err(ShadowError::MissingPartner { function: "X02" }));
        }
    }
}
