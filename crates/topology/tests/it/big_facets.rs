//! Inspection of meshes with huge facets: a 30,000-sided cylinder (two
//! 30,000-gon caps and 30,000 quadrilaterals) is checked in about linear
//! time and memory. With every candidate pair stored, or with its caps
//! triangulated as fans, this took minutes and gigabytes; no time is
//! asserted here, the test would simply not finish in reasonable time.

use std::f64::consts::TAU;
use topology::{check_mesh, Facet, PolygonMesh};

/// An n-sided prism around the z-axis (radius `r`, from `z = 0` to `h`),
/// caps as single facets, sides as quadrilaterals, facing outwards.
fn cylinder(n: u32, r: f64, h: f64) -> PolygonMesh {
    let mut v = Vec::with_capacity(2 * n as usize);
    for z in [0.0, h] {
        for i in 0..n {
            let t = TAU * f64::from(i) / f64::from(n);
            v.push([r * t.cos(), r * t.sin(), z]);
        }
    }
    let bottom: Vec<u32> = (0..n).rev().collect();
    let top: Vec<u32> = (n..2 * n).collect();
    let mut f = vec![Facet::from_loop(&bottom), Facet::from_loop(&top)];
    for i in 0..n {
        let j = (i + 1) % n;
        f.push(Facet::from_loop(&[i, j, n + j, n + i]));
    }
    PolygonMesh::new(v, f)
}

/// The volume of the prism by the polyhedral formula, `n/2 sin(2 pi / n)
/// r^2 h`.
fn prism_volume(n: u32, r: f64, h: f64) -> f64 {
    f64::from(n) / 2.0 * (TAU / f64::from(n)).sin() * r * r * h
}

#[test]
fn a_30000_sided_cylinder_is_valid_and_checked_quickly() {
    let n = 30_000;
    let m = cylinder(n, 1.0, 2.0);
    let r = check_mesh(&m);
    assert!(r.is_valid(), "{r:?}");
    assert_eq!(r.two_manifold, Some(true));
    assert_eq!(r.facets, n as usize + 2);
    assert_eq!(r.edges, 3 * n as usize);
    assert_eq!(r.self_intersecting_facet_pairs, Some(0));
    let v = r.signed_volume.unwrap();
    let want = prism_volume(n, 1.0, 2.0);
    assert!((v - want).abs() <= 1e-9 * want, "{v} vs {want}");
    assert_eq!(r.bounding_box.map(|b| [b[0][2], b[1][2]]), Some([0.0, 2.0]));
}

#[test]
fn a_big_cylinder_with_a_dent_through_the_far_side_is_found() {
    // Vertex 0 of the bottom rim pushed across the whole cylinder (to
    // x = -1.5): its two side quadrilaterals now cross the far side, the
    // bottom cap is no longer convex (so it takes section 4.8's
    // triangulation), and the top cap (still convex, by halving) is not
    // touched.
    let n = 1000;
    let mut m = cylinder(n, 1.0, 2.0);
    m.vertices[0] = [-1.5, 0.0, 0.0];
    let r = check_mesh(&m);
    assert!(r.is_valid());
    let pairs = m.self_intersections().unwrap();
    assert_eq!(r.self_intersecting_facet_pairs, Some(pairs.len()));
    assert!(!pairs.is_empty());
    // Facet ids: 0 bottom, 1 top, 2 + i the side quad from vertex i. The
    // dented quads are 2 (0 -> 1) and 2 + n - 1 (n-1 -> 0).
    let dented = [2, n + 1];
    assert!(
        pairs
            .iter()
            .all(|p| p.iter().any(|f| dented.contains(f)) || p.contains(&0)),
        "{pairs:?}"
    );
    assert!(pairs.iter().all(|p| !p.contains(&1)), "{pairs:?}");
    // The far side around x = -1 is crossed: the side quad at angle pi.
    let far = 2 + n / 2;
    assert!(pairs.iter().any(|p| p.contains(&far)), "{pairs:?}");
}

#[test]
fn a_big_cap_pierced_by_a_second_cylinder() {
    // Two big cylinders, the second shifted up by half the height and
    // sideways: each one's caps cross the other's sides, convex caps of
    // 2,000 vertices triangulated by halving.
    let n = 2000;
    let a = cylinder(n, 1.0, 2.0);
    let b = cylinder(n, 1.0, 2.0);
    let mut v = a.vertices.clone();
    let off = v.len() as u32;
    v.extend(b.vertices.iter().map(|p| [p[0] + 0.5, p[1], p[2] + 1.0]));
    let mut f = a.facets.clone();
    f.extend(b.facets.iter().map(|fa| {
        let mut g = fa.clone();
        for h in &mut g.half_edges {
            h.start += off;
            h.end += off;
        }
        g
    }));
    let m = PolygonMesh::new(v, f);
    let pairs = m.self_intersections().unwrap();
    let second = |x: u32| x >= n + 2;
    // Only pairs across the two solids.
    assert!(pairs.iter().all(|p| second(p[0]) != second(p[1])));
    // A's top cap (facet 1) crosses B's sides; B's bottom cap (facet
    // n + 2) crosses A's sides.
    assert!(pairs.iter().any(|p| p[0] == 1 && second(p[1])));
    assert!(pairs.iter().any(|p| p[1] == n + 2 && !second(p[0])));
    // The caps are parallel planes a distance 1 apart: they never meet.
    assert!(!pairs.contains(&[1, n + 2]) && !pairs.contains(&[0, n + 3]));
}
