//! A closed plate pierced by 1,000 rectangular holes, as a polygon mesh
//! whose top and bottom facets are rectangles with 1,000 holes each (the
//! shape of the n-ary difference "slab minus 1,000 boxes"), triangulated
//! by `triangulate_mesh` (section 4.8): the result is closed, has the
//! plate's exact volume, `E + 2H - 2` triangles per cap (`E` half-edges,
//! `H` holes) and no cap triangle reversed (exact orientation). The
//! timing of the same triangulation is a criterion bench
//! (`benches/benches/triangulate.rs`); here the invariants only.

use robust_arith::orient2d;
use std::cmp::Ordering;
use topology::{triangulate_mesh, Facet, PolygonMesh};

/// A `w x h` plate of unit cells, thickness 1, with a hole of
/// `0.5 x 0.5` (shifted by multiples of 1/32 from cell to cell, so that
/// holes share coordinates with their neighbours) through every cell.
fn plate(w: u32, h: u32) -> (PolygonMesh, f64) {
    let (fw, fh) = (f64::from(w), f64::from(h));
    let mut v: Vec<[f64; 3]> = Vec::new();
    for z in [0.0, 1.0] {
        v.extend([[0.0, 0.0, z], [fw, 0.0, z], [fw, fh, z], [0.0, fh, z]]);
    }
    let mut bottom = vec![vec![3, 2, 1, 0]];
    let mut top = vec![vec![4, 5, 6, 7]];
    let mut facets = Vec::new();
    for i in 0..4u32 {
        let j = (i + 1) % 4;
        facets.push(Facet::from_loop(&[i, j, 4 + j, 4 + i]));
    }
    let mut hole_area = 0.0;
    for i in 0..w {
        for j in 0..h {
            let x = f64::from(i) + 0.25 + f64::from((i * 7 + j * 3) % 5) / 32.0 - 2.0 / 32.0;
            let y = f64::from(j) + 0.25 + f64::from((i * 3 + j * 5) % 5) / 32.0 - 2.0 / 32.0;
            let b = v.len() as u32;
            for z in [0.0, 1.0] {
                v.extend([
                    [x, y, z],
                    [x + 0.5, y, z],
                    [x + 0.5, y + 0.5, z],
                    [x, y + 0.5, z],
                ]);
            }
            hole_area += 0.25;
            // The caps' holes run against the caps' outer loops; the
            // hole's walls face into the hole.
            bottom.push(vec![b, b + 1, b + 2, b + 3]);
            top.push(vec![b + 7, b + 6, b + 5, b + 4]);
            for k in 0..4u32 {
                let l = (k + 1) % 4;
                facets.push(Facet::from_loop(&[b + l, b + k, b + 4 + k, b + 4 + l]));
            }
        }
    }
    facets.push(Facet::from_loops(&bottom));
    facets.push(Facet::from_loops(&top));
    (PolygonMesh::new(v, facets), fw * fh - hole_area)
}

#[test]
fn a_plate_of_1000_holes_triangulates_closed_and_exact() {
    let (mesh, volume) = plate(40, 25);
    mesh.check_topology().unwrap();
    let t = triangulate_mesh(&mesh);
    t.check_topology().unwrap();
    // Dyadic coordinates: every product and sum of the volume is exact.
    assert_eq!(t.signed_volume(), volume);
    let holes = 1000;
    let walls = 4 + 4 * holes;
    let cap = 4 * (holes + 1) + 2 * holes - 2;
    assert_eq!(t.triangles.len(), 2 * walls + 2 * cap);
    // The caps' triangles (those with all three corners at z = 0 or all
    // at z = 1) face down, resp. up.
    let mut caps = 0;
    for tri in &t.triangles {
        let p = tri.map(|i| t.vertices[i as usize]);
        let z = p[0][2];
        if p.iter().all(|q| q[2] == z) {
            caps += 1;
            let o = orient2d([p[0][0], p[0][1]], [p[1][0], p[1][1]], [p[2][0], p[2][1]]);
            let way = if z == 0.0 {
                Ordering::Less
            } else {
                Ordering::Greater
            };
            assert_eq!(o, way, "{tri:?}");
        }
    }
    assert_eq!(caps, 2 * cap);
}
