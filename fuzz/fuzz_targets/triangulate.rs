//! Fuzz target: `topology::triangulate_facet` never panics, and its
//! triangles always have the facet's boundary (section 4.8: only internal
//! edges are added, each in both directions, so for every pair of distinct
//! vertices the triangles' half-edges minus the facet's run as often one
//! way as the other); on a valid plate (a rectangle with square holes) it
//! gives exactly `V + 2H - 2` triangles, none reversed, covering the
//! plate's area.
#![no_main]

use libfuzzer_sys::fuzz_target;
use robust_arith::orient2d;
use std::cmp::Ordering;
use std::collections::HashMap;
use topology::triangulate_facet;
use umbra_fuzz::FacetInput;

/// Asserts that `triangles` have the boundary of `half_edges`.
fn assert_same_boundary(half_edges: &[(u32, u32)], triangles: &[[u32; 3]], n: usize) {
    let mut net: HashMap<(u32, u32), i64> = HashMap::new();
    for t in triangles {
        assert!(
            t.iter().all(|&v| (v as usize) < n),
            "triangle {t:?} beyond {n} vertices"
        );
        for k in 0..3 {
            *net.entry((t[k], t[(k + 1) % 3])).or_default() += 1;
        }
    }
    for &(s, e) in half_edges {
        *net.entry((s, e)).or_default() -= 1;
    }
    for (&(s, e), &c) in &net {
        if s != e {
            let back = net.get(&(e, s)).copied().unwrap_or(0);
            assert_eq!(c, back, "edge {s}-{e}: {c} one way, {back} the other");
        }
    }
}

fuzz_target!(|input: FacetInput| {
    let (positions, half_edges) = input.loops_facet();
    let mut out = Vec::new();
    triangulate_facet(&positions, &half_edges, &mut out);
    assert_same_boundary(&half_edges, &out, positions.len());

    let (positions, half_edges, plane, holes) = input.plate_facet();
    let mut out = Vec::new();
    triangulate_facet(&positions, &half_edges, &mut out);
    assert_same_boundary(&half_edges, &out, positions.len());
    // At most the bridged polygon's ear count: zero-area ears over a
    // repeated vertex (a spike along a bridge) are dropped, never emitted.
    assert!(
        out.len() <= plane.len() + 2 * holes - 2,
        "triangle count of a plate"
    );
    assert!(
        out.iter()
            .all(|t| t[0] != t[1] && t[1] != t[2] && t[2] != t[0]),
        "a triangle repeats a vertex"
    );
    let mut twice_area = 0.0;
    for t in &out {
        let [a, b, c] = t.map(|v| plane[v as usize]);
        assert_eq!(
            orient2d(a, b, c),
            Ordering::Greater,
            "reversed or flat triangle {t:?}"
        );
        twice_area += (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
    }
    // Small integers: every term and sum is exact.
    let outer = 2.0 * plane[2][0] * plane[2][1];
    assert_eq!(twice_area, outer - 8.0 * holes as f64, "area of a plate");
});
