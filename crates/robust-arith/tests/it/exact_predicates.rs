//! `orient2d` and `orient3d` against an independent exact oracle (the
//! determinant in `BigRational`, from `BigRational::from_float`) over
//! random inputs of every magnitude from subnormal to `f64::MAX / 4`, mixed
//! magnitudes, and degenerate (collinear and coplanar) configurations at
//! every scale, where a plain float determinant or the adaptive predicates
//! alone would overflow or underflow.

use num_rational::BigRational;
use num_traits::{Signed, Zero};
use proptest::prelude::*;
use robust_arith::{coplanar, orient2d, orient3d, FAST_MAX, FAST_MIN};
use std::cmp::Ordering;

fn q(v: f64) -> BigRational {
    BigRational::from_float(v).expect("finite test input")
}

fn q_sign(v: &BigRational) -> Ordering {
    if v.is_zero() {
        Ordering::Equal
    } else if v.is_positive() {
        Ordering::Greater
    } else {
        Ordering::Less
    }
}

/// The oracle of `orient2d`: `(a - c) x (b - c)` exactly.
fn oracle2(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> Ordering {
    let (acx, acy) = (q(a[0]) - q(c[0]), q(a[1]) - q(c[1]));
    let (bcx, bcy) = (q(b[0]) - q(c[0]), q(b[1]) - q(c[1]));
    q_sign(&(acx * bcy - acy * bcx))
}

/// The oracle of `orient3d`: `det(a - d, b - d, c - d)` exactly, expanded
/// along the last column (another order than the library's).
fn oracle3(a: [f64; 3], b: [f64; 3], c: [f64; 3], d: [f64; 3]) -> Ordering {
    let r = |p: [f64; 3]| [0, 1, 2].map(|k| q(p[k]) - q(d[k]));
    let (u, v, w) = (r(a), r(b), r(c));
    let m = |i: usize, j: usize, x: &[BigRational; 3], y: &[BigRational; 3]| {
        &x[i] * &y[j] - &x[j] * &y[i]
    };
    let det = &u[2] * m(0, 1, &v, &w) - &v[2] * m(0, 1, &u, &w) + &w[2] * m(0, 1, &u, &v);
    q_sign(&det)
}

/// Any finite f64 with a uniformly random exponent (subnormals included)
/// up to `f64::MAX / 4`, either sign, sometimes exactly zero.
fn any_magnitude() -> impl Strategy<Value = f64> {
    prop_oneof![
        1 => Just(0.0),
        1 => (any::<bool>(), 0u64..(1 << 52)).prop_map(|(s, m)| {
            let v = f64::from_bits(m.max(1));
            if s { -v } else { v }
        }),
        8 => (any::<bool>(), 1u64..2045, 0u64..(1 << 52)).prop_map(|(s, e, m)| {
            let v = f64::from_bits((e << 52) | m);
            if s { -v } else { v }
        }),
    ]
}

/// Small integers, scaled by a power of two from deep in the subnormals to
/// near `f64::MAX / 4` (exactly: the products stay representable).
fn grid_scaled() -> impl Strategy<Value = (Vec<i32>, i32)> {
    (proptest::collection::vec(-8i32..=8, 12), -1060i32..=1010)
}

fn scale(v: i32, k: i32) -> f64 {
    // 2^k without overflowing the power itself.
    let mut x = f64::from(v);
    let mut k = k;
    while k > 500 {
        x *= 2f64.powi(500);
        k -= 500;
    }
    while k < -500 {
        x *= 2f64.powi(-500);
        k += 500;
    }
    x * 2f64.powi(k)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(test_support::cases(3000)))]

    #[test]
    fn orient2d_is_exact_at_any_magnitude(c in proptest::collection::vec(any_magnitude(), 6)) {
        let (a, b, p) = ([c[0], c[1]], [c[2], c[3]], [c[4], c[5]]);
        prop_assert_eq!(orient2d(a, b, p), oracle2(a, b, p), "{:?}", c);
    }

    #[test]
    fn orient3d_is_exact_at_any_magnitude(c in proptest::collection::vec(any_magnitude(), 12)) {
        let p = |i: usize| [c[3 * i], c[3 * i + 1], c[3 * i + 2]];
        prop_assert_eq!(orient3d(p(0), p(1), p(2), p(3)), oracle3(p(0), p(1), p(2), p(3)), "{:?}", c);
        prop_assert_eq!(coplanar(p(0), p(1), p(2), p(3)), oracle3(p(0), p(1), p(2), p(3)) == Ordering::Equal, "{:?}", c);
    }

    /// Collinear and coplanar configurations (a small grid is full of them)
    /// at every scale, both sides of the fast path's range.
    #[test]
    fn degenerate_grids_at_every_scale((g, k) in grid_scaled()) {
        let v: Vec<f64> = g.iter().map(|&x| scale(x, k)).collect();
        let (a, b, c) = ([v[0], v[1]], [v[2], v[3]], [v[4], v[5]]);
        prop_assert_eq!(orient2d(a, b, c), oracle2(a, b, c));
        // Force collinearity: c on the line through a and b (integer steps).
        let c2 = [scale(2 * g[2] - g[0], k), scale(2 * g[3] - g[1], k)];
        prop_assert_eq!(orient2d(a, b, c2), Ordering::Equal);
        let p = |i: usize| [v[3 * i], v[3 * i + 1], v[3 * i + 2]];
        prop_assert_eq!(orient3d(p(0), p(1), p(2), p(3)), oracle3(p(0), p(1), p(2), p(3)));
        // Force coplanarity: d = a + (b - a) + (c - a) in integers.
        let d: [f64; 3] = [0, 1, 2].map(|j| scale(g[3 + j] + g[6 + j] - g[j], k));
        prop_assert_eq!(orient3d(p(0), p(1), p(2), d), Ordering::Equal);
        prop_assert!(coplanar(p(0), p(1), p(2), d));
        prop_assert!(coplanar(d, p(2), p(0), p(1)));
        prop_assert_eq!(
            coplanar(p(0), p(1), p(2), p(3)),
            oracle3(p(0), p(1), p(2), p(3)) == Ordering::Equal
        );
    }

    /// Near-degenerate: the last point one to a few ulps off a coplanar or
    /// collinear position, at mixed magnitudes (one coordinate huge, the
    /// others tiny, and so on).
    #[test]
    fn near_degenerate_mixed_magnitudes(
        (g, k) in grid_scaled(),
        shift in -3i64..=3,
        huge in any::<bool>(),
        axis in 0usize..3,
    ) {
        let mut v: Vec<f64> = g.iter().map(|&x| scale(x, k)).collect();
        if huge {
            v[axis] = scale(g[axis].max(1), 1000);
        }
        let nudge = |x: f64| {
            if x == 0.0 || shift == 0 {
                x
            } else {
                f64::from_bits((x.to_bits() as i64 + shift) as u64)
            }
        };
        let (a, b) = ([v[0], v[1]], [v[2], v[3]]);
        let c = [scale(2 * g[2] - g[0], k), nudge(scale(2 * g[3] - g[1], k))];
        prop_assert_eq!(orient2d(a, b, c), oracle2(a, b, c));
        let p = |i: usize| [v[3 * i], v[3 * i + 1], v[3 * i + 2]];
        let mut d: [f64; 3] = [0, 1, 2].map(|j| scale(g[3 + j] + g[6 + j] - g[j], k));
        d[axis] = nudge(d[axis]);
        prop_assert_eq!(orient3d(p(0), p(1), p(2), d), oracle3(p(0), p(1), p(2), d));
        prop_assert_eq!(coplanar(p(0), p(1), p(2), d), oracle3(p(0), p(1), p(2), d) == Ordering::Equal);
    }

    /// Points coplanar in real numbers and rounded to `f64` (the two
    /// triangles of a flat quadrilateral on a sphere's latitude band, and
    /// points of a slanted plane with random mantissas): the determinant is
    /// of the size of its rounding, zero or not, and `coplanar` must say
    /// exactly which.
    #[test]
    fn rounded_coplanar_points(
        t in proptest::collection::vec(0.0f64..1.0, 8),
        k in -60i32..=60,
        slope in proptest::collection::vec(-4.0f64..4.0, 2),
    ) {
        let s = 2f64.powi(k);
        // A latitude band quadrilateral: exactly planar in reals.
        let (th0, th1) = (t[0] * 6.2, t[0] * 6.2 + 0.001 + t[1] * 0.01);
        let (ph0, ph1) = (t[2] * 3.1, t[2] * 3.1 + 0.001 + t[3] * 0.01);
        let sph = |th: f64, ph: f64| [s * ph.sin() * th.cos(), s * ph.sin() * th.sin(), s * ph.cos()];
        let quad = [sph(th0, ph0), sph(th1, ph0), sph(th1, ph1), sph(th0, ph1)];
        prop_assert_eq!(
            coplanar(quad[0], quad[1], quad[2], quad[3]),
            oracle3(quad[0], quad[1], quad[2], quad[3]) == Ordering::Equal
        );
        // The plane z = slope0 x + slope1 y, rounded.
        let on = |x: f64, y: f64| [s * x, s * y, s * (slope[0] * x + slope[1] * y)];
        let p = [on(t[4], t[5]), on(t[6], t[7]), on(t[5], t[4]), on(t[7] * 0.5, t[6])];
        prop_assert_eq!(coplanar(p[0], p[1], p[2], p[3]), oracle3(p[0], p[1], p[2], p[3]) == Ordering::Equal);
    }
}

#[test]
fn coplanar_on_non_finite_input_is_orient3d_equal() {
    let (a, b, c) = ([0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]);
    for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        assert!(coplanar(a, b, c, [bad, 0.5, 1.0]));
        assert_eq!(orient3d(a, b, c, [bad, 0.5, 1.0]), Ordering::Equal);
    }
    // Subnormal and huge coordinates together: exact either way.
    let tiny = f64::from_bits(3);
    assert!(!coplanar(a, b, c, [0.5, 0.5, tiny]));
    assert!(coplanar(
        [f64::MAX / 8.0, 0.0, 0.0],
        [0.0, f64::MAX / 8.0, 0.0],
        [tiny, tiny, 0.0],
        [0.0, 0.0, 0.0]
    ));
}

#[test]
fn the_range_edges_of_the_fast_path() {
    // Points exactly at and just beyond the fast path's bounds, where the
    // answer must not change with the path taken.
    for base in [FAST_MIN, FAST_MAX] {
        for step in [-1i64, 0, 1] {
            let s = f64::from_bits((base.to_bits() as i64 + step) as u64);
            let (a, b) = ([0.0, 0.0], [s, s]);
            for c in [[2.0 * s, 2.0 * s], [s, 2.0 * s], [2.0 * s, s]] {
                assert_eq!(orient2d(a, b, c), oracle2(a, b, c), "{s:e} {c:?}");
            }
            let t = [[0.0; 3], [s, 0.0, 0.0], [0.0, s, 0.0]];
            for d in [[s, s, 0.0], [s, s, s], [s, s, -s]] {
                assert_eq!(orient3d(t[0], t[1], t[2], d), oracle3(t[0], t[1], t[2], d));
            }
        }
    }
    // Beyond the adaptive predicates: the full valid coordinate range.
    let h = f64::MAX / 4.0;
    assert_eq!(orient2d([-h, -h], [h, -h], [h, h]), Ordering::Greater);
    assert_eq!(
        orient3d([-h, -h, 0.0], [h, -h, 0.0], [h, h, 0.0], [0.0, 0.0, -h]),
        Ordering::Greater
    );
    // The smallest subnormal differences.
    let e = f64::from_bits(1);
    assert_eq!(orient2d([0.0, 0.0], [e, 0.0], [0.0, e]), Ordering::Greater);
    assert_eq!(
        orient3d([0.0; 3], [e, 0.0, 0.0], [0.0, e, 0.0], [0.0, 0.0, e]),
        Ordering::Less
    );
}
