//! Tests of the 3D rows: spheres, their quadrilateral form, every peer's difference.

use umbra_benches::solid::*;

#[test]
fn spheres_are_closed_and_near_the_analytic_volume() {
    let (a, b) = sphere_pair(2000);
    assert!(a.check_topology().is_ok() && b.check_topology().is_ok());
    let v = triangle_volume(&a);
    assert!((v - 4.0 / 3.0 * std::f64::consts::PI).abs() < 0.05, "{v}");
    let (q, _) = sphere_pair_quads(2000);
    assert!(q.check_topology().is_ok());
    assert!((polygon_volume(&q) - v).abs() < 1e-12);
}

#[test]
fn merged_triangles_are_the_quad_spheres() {
    for size in [2000, 20_000] {
        let (a, b) = sphere_pair(size);
        let (qa, qb) = sphere_pair_quads(size);
        let (ma, mb) = (quads_of_uv_sphere(&a), quads_of_uv_sphere(&b));
        assert_eq!(ma.vertices, qa.vertices);
        assert_eq!(ma.facets, qa.facets);
        assert_eq!(mb.facets, qb.facets);
        let quads = ma.facets.iter().filter(|f| f.half_edges.len() == 4);
        let (s, t) = sphere_resolution(size);
        assert_eq!(quads.count(), (s * (t - 2)) as usize);
        assert_eq!(ma.facets.len(), a.triangles.len() - (s * (t - 2)) as usize);
    }
}

#[test]
fn every_peer_gets_the_same_difference() {
    let (a, b) = sphere_pair(2000);
    let want = analytic_difference_volume();
    let u = UmbraTriangles.stats(&UmbraTriangles.difference(&UmbraTriangles.prepare(&a, &b)));
    let p = UmbraPolygons.stats(&UmbraPolygons.difference(&UmbraPolygons.prepare(&a, &b)));
    let q = UmbraQuads.stats(&UmbraQuads.difference(&UmbraQuads.prepare(&a, &b)));
    let m = ManifoldRust.stats(&ManifoldRust.difference(&ManifoldRust.prepare(&a, &b)));
    let bm = Boolmesh.stats(&Boolmesh.difference(&Boolmesh.prepare(&a, &b)));
    assert!(
        u.valid && p.valid && q.valid && m.valid && bm.valid,
        "{u:?} {p:?} {q:?} {m:?} {bm:?}"
    );
    assert!((u.volume - bm.volume).abs() < 1e-9, "{u:?} {bm:?}");
    assert!((u.volume - p.volume).abs() < 1e-12, "{u:?} {p:?}");
    // The quadrilaterals are the triangle pairs' union: nearly the same
    // surface (each quadrilateral is planar up to rounding), fewer
    // facets.
    assert!((u.volume - q.volume).abs() < 1e-9, "{u:?} {q:?}");
    assert!(q.facets < p.facets, "{p:?} {q:?}");
    assert!((u.volume - m.volume).abs() < 1e-9, "{u:?} {m:?}");
    assert!((u.volume - want).abs() < 0.05 * want, "{u:?} vs {want}");
}
