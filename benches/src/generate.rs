//! Deterministic input generators: regular n-gons (Table 7.4 of the
//! dissertation) and seeded random star-shaped polygons.

use test_support::rng::SplitMix64;
pub use test_support::shapes::{regular_ngon, Ring};

/// One row of Table 7.4: `n` vertices, rotation `alpha` in degrees.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Case {
    /// The number of vertices of each regular polygon.
    pub n: usize,
    /// The rotation of the second polygon, in degrees.
    pub alpha_deg: f64,
}

impl Case {
    /// The number of vertices of the exact union (one ring): `4n`.
    pub fn expected_vertices(&self) -> usize {
        4 * self.n
    }

    /// A short label, `n=1000,alpha=1e-4`.
    pub fn label(&self) -> String {
        format!("n={},alpha={:e}", self.n, self.alpha_deg)
    }
}

/// The rows of the dissertation's Table 7.4 (section 7.6, repeating Table
/// 1.1 from \[MY04\]) in the order printed there: the union of a regular
/// n-gon with a copy rotated by `alpha_deg` degrees.
pub const TABLE_7_4: [Case; 10] = [
    Case {
        n: 1000,
        alpha_deg: 1.0e-4,
    },
    Case {
        n: 1000,
        alpha_deg: 1.0e-5,
    },
    Case {
        n: 1000,
        alpha_deg: 1.0e-6,
    },
    Case {
        n: 100,
        alpha_deg: 1.0e-2,
    },
    Case {
        n: 100,
        alpha_deg: 0.5e-2,
    },
    Case {
        n: 200,
        alpha_deg: 1.0e-2,
    },
    Case {
        n: 400,
        alpha_deg: 1.0e-2,
    },
    Case {
        n: 5000,
        alpha_deg: 6.175e-6,
    },
    Case {
        n: 5000,
        alpha_deg: 1.581e-9,
    },
    Case {
        n: 20000,
        alpha_deg: 9.88e-7,
    },
];

/// The two operands of a Table 7.4 row: the unit regular `n`-gon and the
/// same polygon rotated by `alpha_deg` degrees about the origin.
pub fn rotated_ngon_pair(n: usize, alpha_deg: f64) -> (Ring, Ring) {
    (regular_ngon(n, 1.0, 0.0), regular_ngon(n, 1.0, alpha_deg))
}

/// A seeded random simple polygon with `n` vertices, counter clockwise and
/// star-shaped about `center`: vertex `k` at angle `2 pi k / n` and a radius
/// drawn uniformly from `[0.5, 1] * radius`. The same `seed` always gives
/// the same ring. Fewer than three vertices give an empty ring.
pub fn random_star_polygon(seed: u64, n: usize, center: [f64; 2], radius: f64) -> Ring {
    if n < 3 {
        return Vec::new();
    }
    let mut rng = SplitMix64::new(seed);
    (0..n)
        .map(|k| {
            let theta = std::f64::consts::TAU * (k as f64) / (n as f64);
            let r = radius * (0.5 + 0.5 * rng.unit());
            [center[0] + r * theta.cos(), center[1] + r * theta.sin()]
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

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
}
