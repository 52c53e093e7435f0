//! Exact oracles, independent of the code under test: every f64 is an
//! integer times a power of two, so a set of them scaled to a common
//! exponent turns the orientation, distance and intersection formulas into
//! exact integer arithmetic, rounded to f64 only when a figure is reported;
//! rational arithmetic where a quotient is needed (volumes).

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{Signed, ToPrimitive, Zero};
use topology::{PolygonSet2, TriangleMesh};

/// A 2D point.
pub type P = [f64; 2];

/// `(mantissa, exponent)` with `x = mantissa * 2^exponent` exactly (for
/// finite `x`).
pub fn decode(x: f64) -> (i64, i32) {
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

/// The values as exact big integers times `2^scale` (the returned scale).
pub fn scaled(values: &[f64]) -> (Vec<BigInt>, i64) {
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
    (ints, i64::from(scale))
}

/// `x * 2^e` without overflow or underflow of the power of two itself.
pub fn ldexp(mut x: f64, mut e: i64) -> f64 {
    while e > 1000 {
        x *= 2f64.powi(1000);
        e -= 1000;
    }
    while e < -1000 {
        x *= 2f64.powi(-1000);
        e += 1000;
    }
    x * 2f64.powi(e as i32)
}

/// A big integer as `(top, shift)`, `v ~= top * 2^shift`, `|top| < 2^61`.
pub fn split(v: &BigInt) -> (f64, i64) {
    let shift = (v.bits() as i64 - 60).max(0);
    ((v >> (shift as usize)).to_f64().unwrap_or(f64::NAN), shift)
}

/// `v * 2^e` as f64.
pub fn to_f64(v: &BigInt, e: i64) -> f64 {
    let (t, s) = split(v);
    ldexp(t, s + e)
}

/// The exact sign of the orientation of `(p, q, r)`: +1 when `r` lies left
/// of `p -> q` (anticlockwise), -1 right, 0 collinear.
pub fn orient(p: P, q: P, r: P) -> i32 {
    let (i, _) = scaled(&[p[0], p[1], q[0], q[1], r[0], r[1]]);
    let v = (&i[2] - &i[0]) * (&i[5] - &i[1]) - (&i[3] - &i[1]) * (&i[4] - &i[0]);
    sign(&v)
}

/// The sign of `v` as -1, 0 or +1.
pub fn sign(v: &BigInt) -> i32 {
    if v.is_positive() {
        1
    } else if v.is_negative() {
        -1
    } else {
        0
    }
}

/// The exact distance from `p` to the closed segment `s0 - s1`, divided by
/// `2^unit_exp` and rounded to f64 at the end.
pub fn distance_to_segment(p: P, s0: P, s1: P, unit_exp: i64) -> f64 {
    let (i, e) = scaled(&[p[0], p[1], s0[0], s0[1], s1[0], s1[1]]);
    let (dx, dy) = (&i[4] - &i[2], &i[5] - &i[3]);
    let (wx, wy) = (&i[0] - &i[2], &i[1] - &i[3]);
    let len2 = &dx * &dx + &dy * &dy;
    let dot = &dx * &wx + &dy * &wy;
    let norm = |x: &BigInt, y: &BigInt| to_f64(x, e - unit_exp).hypot(to_f64(y, e - unit_exp));
    if len2.is_zero() || dot.is_negative() {
        norm(&wx, &wy)
    } else if dot > len2 {
        norm(&(&i[0] - &i[4]), &(&i[1] - &i[5]))
    } else {
        let cross = (&dx * &wy - &dy * &wx).abs();
        let (ct, cs) = split(&cross);
        let (mut lt, mut ls) = split(&len2);
        if ls % 2 != 0 {
            lt *= 2.0;
            ls -= 1;
        }
        ldexp(ct / lt.sqrt(), cs - ls / 2 + e - unit_exp)
    }
}

/// The distance from `p` to the exact intersection point of the lines
/// through `a0-a1` and `b0-b1`, divided by `2^unit_exp`; infinite when the
/// lines are parallel.
pub fn distance_to_line_intersection(p: P, a0: P, a1: P, b0: P, b1: P, unit_exp: i64) -> f64 {
    let (i, e) = scaled(&[
        p[0], p[1], a0[0], a0[1], a1[0], a1[1], b0[0], b0[1], b1[0], b1[1],
    ]);
    let (ax, ay) = (&i[2], &i[3]);
    let (dax, day) = (&i[4] - ax, &i[5] - ay);
    let (dbx, dby) = (&i[8] - &i[6], &i[9] - &i[7]);
    let den = &dax * &dby - &day * &dbx;
    if den.is_zero() {
        return f64::INFINITY;
    }
    let num = (&i[6] - ax) * &dby - (&i[7] - ay) * &dbx;
    // true = a0 + num/den * da, so (p - true) den = (p - a0) den - num da.
    let ex = (&i[0] - ax) * &den - &num * &dax;
    let ey = (&i[1] - ay) * &den - &num * &day;
    let (dt, ds) = split(&den.abs());
    let (xt, xs) = split(&ex);
    let (yt, ys) = split(&ey);
    let x = ldexp(xt / dt, xs - ds + e - unit_exp);
    let y = ldexp(yt / dt, ys - ds + e - unit_exp);
    x.hypot(y)
}

/// The exact winding number of `p` (which must not lie on an edge) with
/// respect to a polygon set, multiplicity-weighted, by the crossing rule
/// with a horizontal ray (upward edges with `p` strictly left count +1,
/// downward edges with `p` strictly right count -1).
pub fn winding(p: P, set: &PolygonSet2) -> i64 {
    let mut w = 0i64;
    for e in set.edges() {
        if e.mult == 0 {
            continue;
        }
        let (s, t) = set.edge_points(e);
        if s[1] <= p[1] && p[1] < t[1] && orient(s, t, p) > 0 {
            w += i64::from(e.mult);
        } else if t[1] <= p[1] && p[1] < s[1] && orient(s, t, p) < 0 {
            w -= i64::from(e.mult);
        }
    }
    w
}

/// The binary exponent of the power of two `L` bounding `max_abs` (the
/// scale of the chapter 8 bounds).
pub fn l_exp(max_abs: f64) -> i64 {
    let l = robust_arith::power_of_two_bound(max_abs);
    i64::from(l.log2().round() as i32)
}

/// An f64 as an exact rational (`None` for NaN and infinities).
pub fn rational(x: f64) -> Option<BigRational> {
    BigRational::from_float(x)
}

/// The signed volume of a triangle mesh in exact rational arithmetic
/// (divergence theorem), rounded to the nearest f64 once at the end; a
/// non-finite coordinate counts as 0.
pub fn triangle_mesh_volume(m: &TriangleMesh) -> f64 {
    let q = |x: f64| rational(x).unwrap_or_else(BigRational::zero);
    let mut six = BigRational::zero();
    for t in &m.triangles {
        let [a, b, c] = t.map(|i| m.vertices[i as usize].map(q));
        let cross = [
            &b[1] * &c[2] - &b[2] * &c[1],
            &b[2] * &c[0] - &b[0] * &c[2],
            &b[0] * &c[1] - &b[1] * &c[0],
        ];
        six += &a[0] * &cross[0] + &a[1] * &cross[1] + &a[2] * &cross[2];
    }
    (six / BigRational::from_integer(6.into()))
        .to_f64()
        .unwrap_or(f64::NAN)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn oracles_on_simple_cases() {
        assert_eq!(orient([0.0, 0.0], [1.0, 0.0], [0.0, 1.0]), 1);
        assert_eq!(orient([0.0, 0.0], [1.0, 0.0], [2.0, 0.0]), 0);
        assert_eq!(orient([0.0, 0.0], [1.0, 1e-300], [2.0, 0.0]), -1);
        assert_eq!(
            distance_to_segment([0.0, 3.0], [-1.0, 0.0], [1.0, 0.0], 0),
            3.0
        );
        assert_eq!(
            distance_to_segment([5.0, 4.0], [-1.0, 0.0], [2.0, 0.0], 0),
            5.0
        );
        assert_eq!(
            distance_to_segment([0.0, 3.0], [-1.0, 0.0], [1.0, 0.0], 1),
            1.5
        );
        let d = distance_to_line_intersection(
            [1.0, 1.0],
            [0.0, 0.0],
            [2.0, 2.0],
            [0.0, 2.0],
            [2.0, 0.0],
            0,
        );
        assert_eq!(d, 0.0);
        let d = distance_to_line_intersection(
            [1.0, 2.0],
            [0.0, 0.0],
            [2.0, 2.0],
            [0.0, 2.0],
            [2.0, 0.0],
            0,
        );
        assert_eq!(d, 1.0);
        let mut sq = PolygonSet2::new();
        sq.add_loop(&[[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]]);
        assert_eq!(winding([1.0, 1.0], &sq), 1);
        assert_eq!(winding([3.0, 1.0], &sq), 0);
        assert_eq!(winding([1.0, 1.0], &sq.reversed()), -1);
        assert_eq!(decode(0.75), (3 << 51, -53));
        assert_eq!(decode(-0.0), (0, -1074));
    }

    #[test]
    fn exact_volume_of_a_unit_tetrahedron() {
        let t = TriangleMesh::new(
            vec![
                [0.0, 0.0, 0.0],
                [1.0, 0.0, 0.0],
                [0.0, 1.0, 0.0],
                [0.0, 0.0, 1.0],
            ],
            vec![[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2]],
        );
        assert_eq!(triangle_mesh_volume(&t), 1.0 / 6.0);
    }
}
