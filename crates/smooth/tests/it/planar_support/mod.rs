//! Shared checks of the 2D smoothing tests: every guarantee of
//! `smooth_polygon_set` tested against independent oracles (exact
//! big-integer orientation over all edge pairs, exact winding numbers at
//! sample points, the shoelace area, brute-force distances).

#![allow(dead_code)]

use smooth::{sanity_check_polygon_set, smooth_polygon_set, SmoothOptions, Smoothed};
use test_support::exact::{orient, winding};
use test_support::shapes::Ring;
use topology::PolygonSet2;

/// A polygon set of the given rings (each anticlockwise ring a region).
pub fn set_of(rings: &[Ring]) -> PolygonSet2 {
    let mut s = PolygonSet2::new();
    for r in rings {
        s.add_loop(r);
    }
    s
}

/// The total length of the edges, multiplicity-weighted.
pub fn perimeter(s: &PolygonSet2) -> f64 {
    s.edges()
        .iter()
        .map(|e| {
            let (p, q) = s.edge_points(e);
            f64::from(e.mult.abs()) * ((p[0] - q[0]).powi(2) + (p[1] - q[1]).powi(2)).sqrt()
        })
        .sum()
}

/// The distance from `p` to segment `a b` (plain f64, brute force).
pub fn seg_dist(p: [f64; 2], a: [f64; 2], b: [f64; 2]) -> f64 {
    let d = [b[0] - a[0], b[1] - a[1]];
    let l2 = d[0] * d[0] + d[1] * d[1];
    let t = if l2 > 0.0 {
        (((p[0] - a[0]) * d[0] + (p[1] - a[1]) * d[1]) / l2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    let q = [a[0] + t * d[0], a[1] + t * d[1]];
    ((p[0] - q[0]).powi(2) + (p[1] - q[1]).powi(2)).sqrt()
}

/// All pairs, exact (big integers): edges that meet other than at a
/// shared vertex. The oracle of the crate's broad-phase crossing test.
pub fn exact_conflicts(s: &PolygonSet2) -> usize {
    let e = s.edges();
    let mut n = 0;
    for i in 0..e.len() {
        for j in i + 1..e.len() {
            let (a, b) = s.edge_points(&e[i]);
            let (c, d) = s.edge_points(&e[j]);
            let ids = [e[i].start, e[i].end];
            let shared = [e[j].start, e[j].end]
                .iter()
                .filter(|v| ids.contains(v))
                .count();
            let (o1, o2, o3, o4) = (
                orient(a, b, c),
                orient(a, b, d),
                orient(c, d, a),
                orient(c, d, b),
            );
            let between = |p: [f64; 2], q: [f64; 2], r: [f64; 2]| {
                // r strictly inside segment p q, given collinear
                let lo = [p[0].min(q[0]), p[1].min(q[1])];
                let hi = [p[0].max(q[0]), p[1].max(q[1])];
                r != p && r != q && lo[0] <= r[0] && r[0] <= hi[0] && lo[1] <= r[1] && r[1] <= hi[1]
            };
            let bad = match shared {
                0 => {
                    (o1 * o2 < 0 && o3 * o4 < 0)
                        || (o1 == 0 && between(a, b, c))
                        || (o2 == 0 && between(a, b, d))
                        || (o3 == 0 && between(c, d, a))
                        || (o4 == 0 && between(c, d, b))
                        || a == c
                        || a == d
                        || b == c
                        || b == d
                }
                1 => {
                    // collinear and overlapping from the shared vertex
                    o1 == 0
                        && o2 == 0
                        && (between(a, b, c)
                            || between(a, b, d)
                            || between(c, d, a)
                            || between(c, d, b))
                }
                _ => true,
            };
            if bad {
                n += 1;
            }
        }
    }
    n
}

/// Sample points of a grid over the box of `s` (and a margin), skipping
/// points on an edge (exact): their exact winding numbers.
pub fn sampled_windings(s: &PolygonSet2, per_axis: usize) -> Vec<i64> {
    let Some([lo, hi]) = s.bounding_box() else {
        return Vec::new();
    };
    let mut out = Vec::new();
    for i in 0..per_axis {
        for j in 0..per_axis {
            let fx = (i as f64 + 0.37) / per_axis as f64;
            let fy = (j as f64 + 0.61) / per_axis as f64;
            let p = [lo[0] + (hi[0] - lo[0]) * fx, lo[1] + (hi[1] - lo[1]) * fy];
            let on_edge = s.edges().iter().any(|e| {
                let (a, b) = s.edge_points(e);
                orient(a, b, p) == 0
                    && p[0] >= a[0].min(b[0])
                    && p[0] <= a[0].max(b[0])
                    && p[1] >= a[1].min(b[1])
                    && p[1] <= a[1].max(b[1])
            });
            if !on_edge {
                out.push(winding(p, s));
            }
        }
    }
    out
}

/// Smooths and checks every guarantee that holds for any valid input:
/// topology, the checker, idempotence, the report's consistency.
/// Returns the result.
pub fn smooth_checked(input: &PolygonSet2, tol: f64) -> Smoothed<PolygonSet2> {
    let before = input.clone();
    let out = smooth_polygon_set(input, &SmoothOptions::new(tol)).expect("valid input smooths");
    assert_eq!(input, &before, "input untouched");
    out.shape.check_topology().expect("closure");
    let r = &out.report;
    assert!(!r.budget_hit, "budget hit: {r:?}");
    assert!(
        r.passes < smooth::MAX_PLANAR_PASSES,
        "ended on the pass limit: {r:?}"
    );
    assert!(r.max_displacement <= r.distortion_bound, "{r:?}");
    assert!(r.epsilon >= r.distortion_bound);
    if let Err(d) = sanity_check_polygon_set(&out.shape, tol) {
        panic!("not clean at {tol}: {d}; report {r:?}\nout {:?}", out.shape);
    }
    let again = smooth_polygon_set(&out.shape, &SmoothOptions::new(tol)).unwrap();
    assert_eq!(again.shape, out.shape, "idempotent");
    assert_eq!(again.report.counts.adjustments(), 0, "{:?}", again.report);
    // Winding numbers of the result in {0, 1}.
    for w in sampled_windings(&out.shape, 23) {
        assert!(w == 0 || w == 1, "winding {w}");
    }
    if out.shape.edge_count() <= 400 {
        assert_eq!(exact_conflicts(&out.shape), 0);
        assert_spacing_brute_force(&out.shape, tol);
        // Every result vertex within the distortion bound of the input's
        // boundary.
        for &p in out.shape.vertices() {
            let d = input
                .edges()
                .iter()
                .filter(|e| e.mult != 0)
                .map(|e| {
                    let (a, b) = input.edge_points(e);
                    seg_dist(p, a, b)
                })
                .fold(f64::INFINITY, f64::min);
            assert!(
                d <= r.distortion_bound * (1.0 + 1e-9) + 1e-300,
                "vertex {p:?} {d} from the input, bound {}",
                r.distortion_bound
            );
        }
    }
    out
}

/// [`smooth_checked`], and the area within `perimeter x tol` of the
/// input's (for inputs whose winding numbers are already 0 or 1).
pub fn smooth_checked_area(input: &PolygonSet2, tol: f64) -> Smoothed<PolygonSet2> {
    let out = smooth_checked(input, tol);
    let (a0, a1) = (input.signed_area(), out.shape.signed_area());
    let bound = perimeter(input) * tol + 1e-12 * (1.0 + a0.abs());
    assert!((a1 - a0).abs() <= bound, "area {a0} -> {a1}, bound {bound}");
    out
}

/// All pairs, plain f64 with a relative slack for rounding: no two
/// vertices within `tol`, no edge `tol` long or shorter, and no vertex
/// within `tol` of an edge's interior where a crack would make both parts
/// shorter (Appendix A's condition).
pub fn assert_spacing_brute_force(s: &PolygonSet2, tol: f64) {
    let v = s.vertices();
    let d = |p: [f64; 2], q: [f64; 2]| ((p[0] - q[0]).powi(2) + (p[1] - q[1]).powi(2)).sqrt();
    let slack = 1.0 - 1e-9;
    for i in 0..v.len() {
        for j in i + 1..v.len() {
            assert!(
                d(v[i], v[j]) > tol * slack,
                "vertices {i} and {j} within {tol}"
            );
        }
    }
    for e in s.edges() {
        let (a, b) = s.edge_points(e);
        let len = d(a, b);
        assert!(len > tol * slack, "edge {e:?} of length {len}");
        for (k, &p) in v.iter().enumerate() {
            if k as u32 == e.start || k as u32 == e.end {
                continue;
            }
            let near = seg_dist(p, a, b) < tol * slack;
            let shorter = d(a, p) < len * slack && d(p, b) < len * slack;
            assert!(!(near && shorter), "vertex {k} within {tol} of edge {e:?}");
        }
    }
}
