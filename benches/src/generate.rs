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
