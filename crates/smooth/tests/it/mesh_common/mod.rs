//! Shared measures for the 3D smoothing tests: shells by edge
//! connectivity, facet areas and widths, edge lengths, the full result
//! check (sanity checker, closure, displacement within the bound), and the
//! strategies of the Boolean-chain property tests.

#![allow(dead_code)]

use boolean_3d::BooleanOp;
use proptest::prelude::*;
use smooth::{sanity_check_mesh, SmoothReport};
use std::collections::HashMap;
use topology::{PolygonMesh, TriangleMesh};

fn find(p: &mut [usize], mut i: usize) -> usize {
    while p[i] != i {
        p[i] = p[p[i]];
        i = p[i];
    }
    i
}

/// The number of shells: facets joined through shared edges.
pub fn shells(m: &PolygonMesh) -> usize {
    let mut parent: Vec<usize> = (0..m.facets.len()).collect();
    let mut first: HashMap<(u32, u32), usize> = HashMap::new();
    for (fi, f) in m.facets.iter().enumerate() {
        for h in &f.half_edges {
            let key = (h.start.min(h.end), h.start.max(h.end));
            match first.get(&key) {
                Some(&g) => {
                    let (a, b) = (find(&mut parent, fi), find(&mut parent, g));
                    parent[a] = b;
                }
                None => {
                    first.insert(key, fi);
                }
            }
        }
    }
    (0..m.facets.len())
        .filter(|&i| find(&mut parent, i) == i)
        .count()
}

fn newell(m: &PolygonMesh, fi: usize) -> [f64; 3] {
    let f = &m.facets[fi];
    let o = m.vertices[f.half_edges[0].start as usize];
    let mut n = [0.0; 3];
    for h in &f.half_edges {
        let p = m.vertices[h.start as usize];
        let q = m.vertices[h.end as usize];
        let (p, q) = (
            [p[0] - o[0], p[1] - o[1], p[2] - o[2]],
            [q[0] - o[0], q[1] - o[1], q[2] - o[2]],
        );
        n[0] += (p[1] - q[1]) * (p[2] + q[2]);
        n[1] += (p[2] - q[2]) * (p[0] + q[0]);
        n[2] += (p[0] - q[0]) * (p[1] + q[1]);
    }
    n
}

/// The area of a facet (half the length of Newell's vector).
pub fn facet_area(m: &PolygonMesh, fi: usize) -> f64 {
    let n = newell(m, fi);
    0.5 * (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt()
}

fn len(m: &PolygonMesh, a: u32, b: u32) -> f64 {
    let (p, q) = (m.vertices[a as usize], m.vertices[b as usize]);
    ((p[0] - q[0]).powi(2) + (p[1] - q[1]).powi(2) + (p[2] - q[2]).powi(2)).sqrt()
}

/// A facet's width measure `2 * area / perimeter` (the inradius for a
/// triangle; half the thickness of a thin strip).
pub fn facet_width(m: &PolygonMesh, fi: usize) -> f64 {
    let perimeter: f64 = m.facets[fi]
        .half_edges
        .iter()
        .map(|h| len(m, h.start, h.end))
        .sum();
    2.0 * facet_area(m, fi) / perimeter
}

/// The shortest edge.
pub fn min_edge(m: &PolygonMesh) -> f64 {
    m.facets
        .iter()
        .flat_map(|f| &f.half_edges)
        .map(|h| len(m, h.start, h.end))
        .fold(f64::INFINITY, f64::min)
}

/// The largest coordinate magnitude of the inputs given to [`check_result`].
pub const TEST_COORDINATE_BOUND: f64 = 100.0;

/// The checks every smoothing result must pass.
pub fn check_result(m: &PolygonMesh, r: &SmoothReport, delta: f64) {
    sanity_check_mesh(m, delta).unwrap();
    assert!(!r.budget_hit, "budget hit: {r:?}");
    assert!(
        r.max_displacement <= r.distortion_bound,
        "displacement {} beyond the bound {}",
        r.max_displacement,
        r.distortion_bound
    );
    // 2.5 delta, plus the rounding allowance of created vertices: 64 units
    // of roundoff of the largest coordinate of the edges they were made on,
    // which may have cancelled since: bounded by the inputs of these tests.
    let largest = m
        .vertices
        .iter()
        .flatten()
        .fold(0.0f64, |a, x| a.max(x.abs()));
    assert!(
        largest <= TEST_COORDINATE_BOUND,
        "a coordinate beyond the tests' bound: {largest}"
    );
    let allowance = 64.0 * (f64::EPSILON / 2.0) * TEST_COORDINATE_BOUND;
    assert!(
        r.distortion_bound <= 2.5 * delta + allowance,
        "bound {} beyond 2.5 delta + {allowance}",
        r.distortion_bound
    );
}

/// A polygon mesh's signed volume.
pub fn volume(m: &PolygonMesh) -> f64 {
    m.signed_volume()
}

/// A triangle mesh as a polygon mesh (for the measures above).
pub fn poly(t: &TriangleMesh) -> PolygonMesh {
    t.to_polygon_mesh()
}

/// A grid box (unit 0.25) moved by a jitter of magnitude `10^e`, `e` from
/// -12 to `max_exp`.
pub fn grid_box(max_exp: i32) -> impl Strategy<Value = ([f64; 3], [f64; 3])> {
    (
        prop::array::uniform3(0i32..4),
        prop::array::uniform3(1i32..4),
        -12i32..=max_exp,
        prop::array::uniform3(-1i32..=1),
    )
        .prop_map(|(lo, size, e, dir)| {
            let j = 10f64.powi(e);
            let lo: [f64; 3] =
                std::array::from_fn(|k| 0.25 * f64::from(lo[k]) + j * f64::from(dir[k]));
            let hi: [f64; 3] = std::array::from_fn(|k| lo[k] + 0.25 * f64::from(size[k]));
            (lo, hi)
        })
}

/// Union, difference or intersection.
pub fn op() -> impl Strategy<Value = BooleanOp> {
    prop::sample::select(vec![
        BooleanOp::Union,
        BooleanOp::Difference,
        BooleanOp::Intersection,
    ])
}
