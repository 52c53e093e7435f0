//! A facet whose hole touches the outer boundary at a vertex (the residual
//! a chain of box holes left on a slab's face, found by the random chain
//! test of `boolean-3d`): the polygon visits the vertex twice, and ear
//! clipping there used to emit zero-area triangles that repeat it. The
//! triangulation must hold no such triangle, keep the facet's half-edges
//! up to opposite pairs, and cover exactly the region's area.

use std::collections::HashMap;
use topology::triangulate_facet;

#[test]
fn a_hole_touching_the_boundary_at_a_vertex_gives_no_degenerate_triangle() {
    let mut pos = vec![[0.0f64; 3]; 12];
    let xy = [
        (0.0, 0.0),    // 0: the shared vertex
        (8.0, 0.0),    // 1
        (8.0, 4.0),    // 2
        (1.75, 1.25),  // 3
        (2.25, 0.125), // 4
        (2.25, 0.625), // 5
        (2.75, 0.625), // 6
        (2.75, 0.125), // 7
        (4.75, 0.125), // 8
        (4.25, 0.125), // 9
        (4.25, 0.625), // 10
        (4.75, 0.625), // 11
    ];
    for (p, &(x, y)) in pos.iter_mut().zip(&xy) {
        *p = [x, y, 1.0];
    }
    // Outer 0-1-2-3, the pinched notch 0-5-6-7-4 (clockwise, through 0),
    // and a free hole 9-10-11-8, in the order the Boolean listed them.
    let hes = [
        (0, 1),
        (4, 0),
        (0, 5),
        (3, 0),
        (1, 2),
        (2, 3),
        (7, 4),
        (6, 7),
        (5, 6),
        (8, 9),
        (9, 10),
        (11, 8),
        (10, 11),
    ];
    let mut out = Vec::new();
    triangulate_facet(&pos, &hes, &mut out);
    assert!(
        out.iter()
            .all(|t| t[0] != t[1] && t[1] != t[2] && t[2] != t[0]),
        "{out:?}"
    );
    // The triangles' half-edges net to the facet's (internal edges cancel).
    let mut net: HashMap<(u32, u32), i32> = HashMap::new();
    let mut add = |a: u32, b: u32, k: i32| {
        if a < b {
            *net.entry((a, b)).or_default() += k;
        } else {
            *net.entry((b, a)).or_default() -= k;
        }
    };
    for t in &out {
        for (a, b) in [(t[0], t[1]), (t[1], t[2]), (t[2], t[0])] {
            add(a, b, 1);
        }
    }
    for &(a, b) in &hes {
        add(a, b, -1);
    }
    assert!(net.values().all(|&v| v == 0), "{net:?}");
    // Exact area: the shoelace of every loop (dyadic coordinates, exact).
    let shoelace = |ring: &[usize]| {
        (0..ring.len())
            .map(|i| {
                let (p, q) = (xy[ring[i]], xy[ring[(i + 1) % ring.len()]]);
                p.0 * q.1 - q.0 * p.1
            })
            .sum::<f64>()
            / 2.0
    };
    let region = shoelace(&[0, 1, 2, 3]) + shoelace(&[0, 5, 6, 7, 4]) + shoelace(&[9, 10, 11, 8]);
    let covered: f64 = out
        .iter()
        .map(|t| {
            let [a, b, c] = t.map(|i| xy[i as usize]);
            ((b.0 - a.0) * (c.1 - a.1) - (c.0 - a.0) * (b.1 - a.1)) / 2.0
        })
        .sum();
    assert_eq!(covered, region);
}
