//! Tests of the input generators: n-gons, rotated pairs, random stars, Table 7.4.

use umbra_benches::*;

fn signed_area(ring: &[[f64; 2]]) -> f64 {
    let n = ring.len();
    (0..n)
        .map(|i| {
            let p = ring[i];
            let q = ring[(i + 1) % n];
            p[0] * q[1] - q[0] * p[1]
        })
        .sum::<f64>()
        / 2.0
}

#[test]
fn ngon_has_n_distinct_ccw_vertices_on_the_circle() {
    for n in [3, 4, 100, 1000] {
        let ring = regular_ngon(n, 1.0, 0.0);
        assert_eq!(ring.len(), n);
        for p in &ring {
            assert!((p[0].hypot(p[1]) - 1.0).abs() < 1e-15);
        }
        // Twice the area of a regular n-gon of circumradius 1 is
        // n sin(2 pi / n).
        let expected = (n as f64) * (std::f64::consts::TAU / n as f64).sin() / 2.0;
        assert!((signed_area(&ring) - expected).abs() < 1e-12);
    }
    assert!(regular_ngon(2, 1.0, 0.0).is_empty());
}

#[test]
fn rotated_pair_differs_by_alpha() {
    let (a, b) = rotated_ngon_pair(100, 1.0e-2);
    assert_eq!(a.len(), 100);
    assert_eq!(b.len(), 100);
    for (p, q) in a.iter().zip(&b) {
        let d = q[1].atan2(q[0]) - p[1].atan2(p[0]);
        let d = d.rem_euclid(std::f64::consts::TAU);
        assert!((d - 1.0e-2f64.to_radians()).abs() < 1e-12, "{d}");
    }
}

#[test]
fn random_star_is_seeded_and_ccw() {
    let a = random_star_polygon(7, 50, [0.0, 0.0], 1.0);
    let b = random_star_polygon(7, 50, [0.0, 0.0], 1.0);
    let c = random_star_polygon(8, 50, [0.0, 0.0], 1.0);
    assert_eq!(a, b);
    assert_ne!(a, c);
    assert_eq!(a.len(), 50);
    assert!(signed_area(&a) > 0.0);
}

#[test]
fn table_has_the_ten_rows() {
    assert_eq!(TABLE_7_4.len(), 10);
    assert_eq!(TABLE_7_4[9].n, 20000);
    assert_eq!(TABLE_7_4[8].expected_vertices(), 20000);
    assert_eq!(TABLE_7_4[0].label(), "n=1000,alpha=1e-4");
}
