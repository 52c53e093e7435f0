//! Shared test helpers: input generators of section 7.7 (random topological
//! polygons, polygonal stars, displacements), exact rational oracles
//! (signed area, point-segment distance; the generator, orientation and
//! winding number come from `test-support`) and structural checks.
#![allow(dead_code)]

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{Signed, Zero};
use robust_arith::y_at_x;
use simplify_2d::CellStructure;
use test_support::exact::orient;
use test_support::rng::Xorshift64Star;
use topology::PolygonSet2;

/// The random topological polygon of section 7.7: a cyclic sequence of `n`
/// random points in the unit disc.
pub fn random_polygon(n: usize, seed: u64) -> Vec<[f64; 2]> {
    let mut r = Xorshift64Star::new(seed);
    (0..n).map(|_| r.in_disc()).collect()
}

/// The polygonal star of section 7.7: `n` evenly spaced points on the unit
/// circle joined every `step`-th (default `n/2 - 1` for even `n`, `(n-1)/2`
/// for odd).
pub fn star(n: usize) -> Vec<[f64; 2]> {
    let step = if n.is_multiple_of(2) {
        n / 2 - 1
    } else {
        (n - 1) / 2
    };
    let step = step.max(1);
    (0..n)
        .map(|i| {
            let a = std::f64::consts::TAU * ((i * step) % n) as f64 / n as f64;
            [a.cos(), a.sin()]
        })
        .collect()
}

/// Displaces points by `(dx, dy)` (figures 7.12-7.14), rounding to the
/// coarse grid of the displaced magnitude.
pub fn displace(pts: &[[f64; 2]], dx: f64, dy: f64) -> Vec<[f64; 2]> {
    pts.iter().map(|p| [p[0] + dx, p[1] + dy]).collect()
}

pub fn polygon(pts: &[[f64; 2]]) -> PolygonSet2 {
    let mut s = PolygonSet2::new();
    s.add_loop(pts);
    s
}

pub fn q(v: f64) -> BigRational {
    BigRational::from_float(v).expect("finite")
}

/// Exact winding number of point `p` with respect to a polygon set
/// (crossing rule with half-open edges, exact orientation). `p` must not
/// lie on an edge.
pub fn winding_exact(set: &PolygonSet2, p: [f64; 2]) -> i32 {
    test_support::exact::winding(p, set) as i32
}

/// f64 winding number (for points far from every edge).
pub fn winding_f64(set: &PolygonSet2, p: [f64; 2]) -> i32 {
    let mut w = 0i32;
    for e in set.edges() {
        let (a, b) = set.edge_points(e);
        let cross = (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]);
        if a[1] <= p[1] && b[1] > p[1] {
            if cross > 0.0 {
                w += e.mult;
            }
        } else if a[1] > p[1] && b[1] <= p[1] && cross < 0.0 {
            w -= e.mult;
        }
    }
    w
}

/// Exact twice-signed-area of a polygon set.
pub fn twice_area_exact(set: &PolygonSet2) -> BigRational {
    let mut s = BigRational::zero();
    for e in set.edges() {
        let (a, b) = set.edge_points(e);
        let t = q(a[0]) * q(b[1]) - q(b[0]) * q(a[1]);
        s += t * BigRational::from_integer(BigInt::from(e.mult));
    }
    s
}

/// f64 distance from `p` to segment `a b` (for sampling filters only).
pub fn dist_f64(p: [f64; 2], a: [f64; 2], b: [f64; 2]) -> f64 {
    let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
    let l2 = dx * dx + dy * dy;
    let t = if l2 > 0.0 {
        (((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / l2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    let (cx, cy) = (a[0] + t * dx - p[0], a[1] + t * dy - p[1]);
    (cx * cx + cy * cy).sqrt()
}

/// Exact test: is the distance from `p` to segment `a b` at most `eps`?
pub fn within_exact(p: [f64; 2], a: [f64; 2], b: [f64; 2], eps: f64) -> bool {
    let (px, py, ax, ay, bx, by) = (q(p[0]), q(p[1]), q(a[0]), q(a[1]), q(b[0]), q(b[1]));
    let dx = &bx - &ax;
    let dy = &by - &ay;
    let l2 = &dx * &dx + &dy * &dy;
    let e2 = q(eps) * q(eps);
    let dot = (&px - &ax) * &dx + (&py - &ay) * &dy;
    let d2 = if l2.is_zero() || !dot.is_positive() {
        (&px - &ax) * (&px - &ax) + (&py - &ay) * (&py - &ay)
    } else if dot >= l2 {
        (&px - &bx) * (&px - &bx) + (&py - &by) * (&py - &by)
    } else {
        // |cross|^2 / l2
        let c = (&px - &ax) * &dy - (&py - &ay) * &dx;
        &c * &c / &l2
    };
    d2 <= e2
}

/// Number of pairs of segments that properly cross (exact), a measure of
/// geometric invalidity.
pub fn proper_crossings(segs: &[([f64; 2], [f64; 2])]) -> usize {
    let mut n = 0;
    for i in 0..segs.len() {
        for j in i + 1..segs.len() {
            let (a, b) = segs[i];
            let (c, d) = segs[j];
            if a[0].max(b[0]) < c[0].min(d[0])
                || c[0].max(d[0]) < a[0].min(b[0])
                || a[1].max(b[1]) < c[1].min(d[1])
                || c[1].max(d[1]) < a[1].min(b[1])
            {
                continue;
            }
            let o1 = orient(a, b, c);
            let o2 = orient(a, b, d);
            let o3 = orient(c, d, a);
            let o4 = orient(c, d, b);
            if o1 * o2 < 0 && o3 * o4 < 0 {
                n += 1;
            }
        }
    }
    n
}

/// The segments of a cell structure (non-degenerate ones).
pub fn cell_segments<W: simplify_2d::Winding>(c: &CellStructure<W>) -> Vec<([f64; 2], [f64; 2])> {
    let v = c.vertices();
    c.edges()
        .iter()
        .filter(|e| e.start != e.end)
        .map(|e| (v[e.start as usize], v[e.end as usize]))
        .collect()
}

/// `true` when the output of a sweep is "clean" under the sweep's own
/// predicates: no vertex lies on another edge by the rule of section 6.5,
/// and no two edges are computed to swap order over their common x-range.
pub fn computationally_clean(set: &PolygonSet2) -> bool {
    let segs: Vec<([f64; 2], [f64; 2])> = set
        .edges()
        .iter()
        .map(|e| {
            let (a, b) = set.edge_points(e);
            if (a[0], a[1]) < (b[0], b[1]) {
                (a, b)
            } else {
                (b, a)
            }
        })
        .collect();
    for &(l, r) in &segs {
        if l[0] == r[0] {
            return false; // keep the check simple: no vertical edges
        }
        for v in set.vertices() {
            if *v != l && *v != r && l[0] <= v[0] && v[0] <= r[0] && y_at_x(l, r, v[0]) == v[1] {
                return false;
            }
        }
    }
    for i in 0..segs.len() {
        for j in i + 1..segs.len() {
            let (a, b) = (segs[i], segs[j]);
            let xl = a.0[0].max(b.0[0]);
            let xr = a.1[0].min(b.1[0]);
            if xl > xr {
                continue;
            }
            let dl = y_at_x(a.0, a.1, xl) - y_at_x(b.0, b.1, xl);
            let dr = y_at_x(a.0, a.1, xr) - y_at_x(b.0, b.1, xr);
            if (dl < 0.0 && dr > 0.0) || (dl > 0.0 && dr < 0.0) {
                return false;
            }
            if xl < xr && (dl == 0.0) != (dr == 0.0) && a.0 != b.0 && a.1 != b.1 {
                return false;
            }
        }
    }
    true
}
