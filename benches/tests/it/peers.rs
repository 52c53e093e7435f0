//! Tests of the 2D Boolean peers: counts, exact union areas, ring statistics.

use umbra_benches::*;

fn check<P: Peer>(peer: &P, n: usize, alpha_deg: f64) -> RingStats {
    let (a, b) = rotated_ngon_pair(n, alpha_deg);
    let input = peer.prepare(&[a], &[b]);
    let out = peer.union(&input);
    match peer.stats(&out) {
        Ok(stats) => stats,
        Err(e) => panic!("{}: {e}", peer.name()),
    }
}

#[test]
fn every_peer_gets_one_ring_of_4n_vertices() {
    let n = 100;
    let expected = 4 * n;
    let stats = [
        ("umbra", check(&Umbra, n, 1.0e-2)),
        ("i_overlay", check(&IOverlay, n, 1.0e-2)),
        ("i_overlay-i64", check(&IOverlay64, n, 1.0e-2)),
        ("geo", check(&Geo, n, 1.0e-2)),
        ("clipper2", check(&Clipper2, n, 1.0e-2)),
        ("clipper2-rust", check(&Clipper2Rust, n, 1.0e-2)),
    ];
    for (name, s) in stats {
        assert!(s.is_single_ring_with(expected), "{name}: {s:?}");
    }
}

#[test]
fn the_exact_union_area_is_the_shoelace_area_of_umbras_ring() {
    for (n, alpha) in [
        (3, 30.0),
        (4, 10.0),
        (100, 1.0e-2),
        (1000, 1.0e-4),
        (20000, 9.88e-7),
    ] {
        let (a, b) = rotated_ngon_pair(n, alpha);
        let out = Umbra.union(&Umbra.prepare(&[a], &[b]));
        let s = Umbra.stats(&out).unwrap_or_default();
        let want = exact_union_area(n, alpha);
        assert!(
            (s.area - want).abs() <= 1e-12 * want,
            "n={n}: {} vs {want}",
            s.area
        );
        assert!(
            s.is_exact_union(&umbra_benches::Case {
                n,
                alpha_deg: alpha
            }),
            "n={n}"
        );
    }
    // Two squares rotated by 45 degrees: the octagram of area
    // 2 * 2 - (the regular octagon of apothem sqrt(1/2)) = 4 - 4 (sqrt 2 - 1).
    let want = 4.0 - 4.0 * (2f64.sqrt() - 1.0);
    assert!((exact_union_area(4, 45.0) - want).abs() < 1e-12);
    // A result of the right counts but the wrong area is not exact.
    let wrong = RingStats {
        rings: 1,
        vertices: 400,
        zero_length_edges: 0,
        area: 1.0,
    };
    assert!(!wrong.is_exact_union(&umbra_benches::Case {
        n: 100,
        alpha_deg: 1.0e-2
    }));
}

#[test]
fn ring_stats_count_zero_length_edges() {
    let rings = vec![vec![[0.0, 0.0], [1.0, 0.0], [1.0, 0.0], [0.0, 1.0]]];
    let s = RingStats::of(&rings);
    assert_eq!(s.rings, 1);
    assert_eq!(s.vertices, 4);
    assert_eq!(s.zero_length_edges, 1);
    assert!(!s.is_single_ring_with(4));
    let closed = vec![vec![[0.0, 0.0], [1.0, 0.0], [0.0, 1.0], [0.0, 0.0]]];
    assert_eq!(RingStats::of(&closed).zero_length_edges, 1);
}

#[test]
fn geo_rings_drop_the_closing_point() {
    // The union of a decagon with itself is the decagon, which `geo`
    // closes with a repeat of its first point.
    let (a, b) = rotated_ngon_pair(10, 0.0);
    let mp = Geo.union(&Geo.prepare(&[a], &[b]));
    assert_eq!(mp.0.len(), 1);
    assert_eq!(mp.0[0].exterior().0.len(), 11);
    let rings = Geo.rings(&mp).unwrap_or_default();
    assert_eq!(rings.len(), 1);
    assert_eq!(rings[0].len(), 10);
}
