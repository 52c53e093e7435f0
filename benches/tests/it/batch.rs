//! Tests of the n-ary 3D rows: every peer carves the slab and unites the spheres alike.

use umbra::MeshVariant;
use umbra_benches::batch::*;
use umbra_benches::solid::SolidStats;

fn run<P: BatchPeer>(peer: &P, case: &BatchCase) -> SolidStats {
    let input = peer
        .prepare(case)
        .unwrap_or_else(|| panic!("{} refused {}", peer.name(), case.label));
    peer.stats(&peer.run(&input))
}

#[test]
fn every_peer_carves_the_slab_exactly() {
    let case = slab_case(4, 3);
    let want = 12.0 * 0.75;
    assert_eq!(case.exact_volume, Some(want));
    for s in [
        run(&UmbraBatch(MeshVariant::PolygonMesh), &case),
        run(&UmbraBatch(MeshVariant::TriangleMesh), &case),
        run(&ManifoldRustBatch { fold: false }, &case),
        run(&BoolmeshBatch, &case),
    ] {
        assert!(s.valid, "{s:?}");
        assert!((s.volume - want).abs() < 1e-9, "{s:?}");
    }
}

#[test]
fn every_peer_unites_the_spheres_alike() {
    let case = sphere_union_case(8, 8);
    assert_eq!(case.operands.len(), 8);
    let u = run(&UmbraBatch(MeshVariant::PolygonMesh), &case);
    assert!(u.valid);
    // Eight spheres of volume at most 4/3 pi 0.6^3 that overlap.
    let one = umbra_benches::solid::triangle_volume(&case.operands[0]);
    assert!(u.volume > one && u.volume < 8.0 * one, "{u:?}");
    for s in [
        run(&UmbraBatch(MeshVariant::TriangleMesh), &case),
        run(&ManifoldRustBatch { fold: false }, &case),
        run(&ManifoldRustBatch { fold: true }, &case),
        run(&BoolmeshBatch, &case),
    ] {
        assert!(s.valid, "{s:?}");
        assert!(
            (s.volume - u.volume).abs() < 1e-9 * u.volume,
            "{s:?} vs {u:?}"
        );
    }
}
