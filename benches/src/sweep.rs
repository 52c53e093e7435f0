//! Inputs and peers for simplification (the bench of issue 4): Umbra's
//! sweep (`simplify_2d`, chapters 6-7) beside `i_overlay` 9
//! (`simplify_shape`, 32- and 64-bit engines) with the matching fill rule,
//! and `geo` 0.33 where it has the operation (the union rows).
//!
//! Inputs: the rotated n-gon pair of Table 7.4 assembled into one set (its
//! nonzero simplification is the union), random topological polygons of
//! section 7.7 (cyclic sequences of random points in the unit disc, heavily
//! self-intersecting), and i_overlay's kinds of stress input: two
//! checkerboards offset by half a cell, a spiral strip against its rotated
//! copy, and nested squares of alternating orientation.

use crate::{rotated_ngon_pair, Ring};
use geo::{BooleanOps, Coord, LineString, MultiPolygon, Polygon};
use i_overlay::core::fill_rule::FillRule;
use i_overlay::float::simplify::SimplifyShape;
use simplify_2d::{simplify, FillRule as UmbraRule};
use topology::PolygonSet2;

/// A simplification row: named input rings and what a correct result is.
#[derive(Clone, Debug)]
pub struct SweepCase {
    /// Row label.
    pub label: String,
    /// The rings, all taken as directed loops (nonzero rule).
    pub rings: Vec<Ring>,
    /// The exact ring and vertex counts when known (the n-gon rows: one
    /// ring of `4n` vertices; nested squares: one ring per square).
    pub expected: Option<(usize, Option<usize>)>,
}

/// Splitmix64, for seeded inputs.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        ((z ^ (z >> 31)) >> 11) as f64 * (1.0 / (1u64 << 53) as f64)
    }
}

/// Section 7.7: `n` random points in the unit disc joined cyclically.
pub fn random_topological_polygon(seed: u64, n: usize) -> Ring {
    let mut rng = Rng(seed);
    let mut out = Vec::with_capacity(n);
    while out.len() < n {
        let (x, y) = (2.0 * rng.next() - 1.0, 2.0 * rng.next() - 1.0);
        if x * x + y * y <= 1.0 {
            out.push([x, y]);
        }
    }
    out
}

fn square(x: f64, y: f64, s: f64) -> Ring {
    vec![[x, y], [x + s, y], [x + s, y + s], [x, y + s]]
}

/// Two `k x k` checkerboards of unit squares, the second offset by half a
/// cell in x and y.
pub fn checkerboards(k: usize) -> Vec<Ring> {
    let mut rings = Vec::new();
    for off in [0.0, 0.5] {
        for i in 0..k {
            for j in 0..k {
                if (i + j) % 2 == 0 {
                    rings.push(square(i as f64 + off, j as f64 + off, 1.0));
                }
            }
        }
    }
    rings
}

/// A spiral strip of `n` vertices (a simple polygon: out along one arm of
/// an Archimedean spiral and back along a parallel one), and its copy
/// rotated by 0.1 radians.
pub fn spirals(n: usize) -> Vec<Ring> {
    let half = (n / 2).max(3);
    let strip = |rot: f64| -> Ring {
        let p = |t: f64, w: f64| {
            let r = 1.0 + 0.5 * t + w;
            [r * (t + rot).cos(), r * (t + rot).sin()]
        };
        let ts: Vec<f64> = (0..half).map(|i| 0.05 * i as f64).collect();
        let mut ring: Ring = ts.iter().map(|&t| p(t, 0.0)).collect();
        ring.extend(ts.iter().rev().map(|&t| p(t, 0.2)));
        ring
    };
    vec![strip(0.0), strip(0.1)]
}

/// `k` concentric squares, alternately counter-clockwise and clockwise:
/// winding numbers 1, 0, 1, 0, ... from the outside in, so the nonzero
/// simplification keeps every square boundary (`k` rings).
pub fn nested_squares(k: usize) -> Vec<Ring> {
    (0..k)
        .map(|i| {
            let h = (k - i) as f64;
            let mut r = square(-h, -h, 2.0 * h);
            if i % 2 == 1 {
                r.reverse();
            }
            r
        })
        .collect()
}

/// The rows of the simplification table.
pub fn sweep_cases(max_random: usize) -> Vec<SweepCase> {
    let mut rows = Vec::new();
    for (n, alpha) in [
        (1000, 1e-5),
        (5000, 1.581e-9),
        (20000, 9.88e-7),
        (20000, 1.581e-9),
    ] {
        let (a, b) = rotated_ngon_pair(n, alpha);
        rows.push(SweepCase {
            label: format!("n-gon union n={n} alpha={alpha:e}"),
            rings: vec![a, b],
            expected: Some((1, Some(4 * n))),
        });
    }
    for n in [100, 500, 1000, 2000, 5000] {
        if n <= max_random {
            rows.push(SweepCase {
                label: format!("random polygon n={n}"),
                rings: vec![random_topological_polygon(n as u64, n)],
                expected: None,
            });
        }
    }
    rows.push(SweepCase {
        label: "checkerboards 2 x 100x100".into(),
        rings: checkerboards(100),
        expected: None,
    });
    rows.push(SweepCase {
        label: "spirals 2 x 20000 v".into(),
        rings: spirals(20000),
        expected: None,
    });
    rows.push(SweepCase {
        label: "nested squares 1000".into(),
        rings: nested_squares(1000),
        expected: Some((1000, Some(4000))),
    });
    rows
}

/// Ring count, vertex count and signed area of a result.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SweepStats {
    /// Rings.
    pub rings: usize,
    /// Vertices over all rings.
    pub vertices: usize,
    /// Sum of signed ring areas.
    pub area: f64,
}

fn ring_area(r: &Ring) -> f64 {
    let n = r.len();
    (0..n)
        .map(|i| r[i][0] * r[(i + 1) % n][1] - r[(i + 1) % n][0] * r[i][1])
        .sum::<f64>()
        / 2.0
}

fn stats_of(rings: &[Ring]) -> SweepStats {
    SweepStats {
        rings: rings.len(),
        vertices: rings.iter().map(Vec::len).sum(),
        area: rings.iter().map(ring_area).sum(),
    }
}

/// A simplification library under test.
pub trait SweepPeer {
    /// Prepared input.
    type Input;
    /// Native output.
    type Output;
    /// A short name.
    fn name(&self) -> &'static str;
    /// Converts the rings (not timed); `None` when the peer has no such
    /// operation for this row.
    fn prepare(&self, case: &SweepCase) -> Option<Self::Input>;
    /// Simplifies by the nonzero rule (timed).
    fn run(&self, input: &Self::Input) -> Self::Output;
    /// Counts and area of the output (not timed).
    fn stats(&self, out: &Self::Output) -> Option<SweepStats>;
}

/// Umbra: `simplify_2d::simplify(set, FillRule::NonZero)`; rings traced
/// from the output edges with `PolygonSet2::loops` (not timed).
#[derive(Clone, Copy, Debug, Default)]
pub struct UmbraSweep;

impl SweepPeer for UmbraSweep {
    type Input = PolygonSet2;
    type Output = Option<PolygonSet2>;
    fn name(&self) -> &'static str {
        "umbra"
    }
    fn prepare(&self, case: &SweepCase) -> Option<PolygonSet2> {
        let mut set = PolygonSet2::new();
        for r in &case.rings {
            set.add_loop(r);
        }
        Some(set)
    }
    fn run(&self, input: &PolygonSet2) -> Self::Output {
        simplify(input, UmbraRule::NonZero).ok().map(|s| s.shape)
    }
    fn stats(&self, out: &Self::Output) -> Option<SweepStats> {
        let set = out.as_ref()?;
        let rings: Vec<Ring> = set
            .loops()
            .iter()
            .map(|l| l.iter().map(|&v| set.vertex(v)).collect())
            .collect();
        Some(stats_of(&rings))
    }
}

/// `i_overlay` 9 `simplify_shape(FillRule::NonZero)` with the default
/// 32-bit engine, or the 64-bit one (`wide`).
#[derive(Clone, Copy, Debug, Default)]
pub struct IOverlaySweep {
    /// Use `simplify_shape_as::<i64>`.
    pub wide: bool,
}

impl SweepPeer for IOverlaySweep {
    type Input = Vec<Vec<[f64; 2]>>;
    type Output = Vec<Vec<Vec<[f64; 2]>>>;
    fn name(&self) -> &'static str {
        if self.wide {
            "i_overlay-i64"
        } else {
            "i_overlay"
        }
    }
    fn prepare(&self, case: &SweepCase) -> Option<Self::Input> {
        Some(case.rings.clone())
    }
    fn run(&self, input: &Self::Input) -> Self::Output {
        if self.wide {
            input.simplify_shape_as::<i64>(FillRule::NonZero)
        } else {
            input.simplify_shape(FillRule::NonZero)
        }
    }
    fn stats(&self, out: &Self::Output) -> Option<SweepStats> {
        let rings: Vec<Ring> = out.iter().flatten().cloned().collect();
        Some(stats_of(&rings))
    }
}

/// `geo` 0.33 `BooleanOps::union` of the two n-gons (only the n-gon rows:
/// geo has no fill-rule simplification of a self-intersecting ring).
#[derive(Clone, Copy, Debug, Default)]
pub struct GeoSweep;

fn geo_poly(r: &Ring) -> MultiPolygon<f64> {
    let mut cs: Vec<Coord<f64>> = r.iter().map(|p| Coord { x: p[0], y: p[1] }).collect();
    if let Some(&f) = cs.first() {
        cs.push(f);
    }
    MultiPolygon(vec![Polygon::new(LineString(cs), vec![])])
}

impl SweepPeer for GeoSweep {
    type Input = (MultiPolygon<f64>, MultiPolygon<f64>);
    type Output = MultiPolygon<f64>;
    fn name(&self) -> &'static str {
        "geo"
    }
    fn prepare(&self, case: &SweepCase) -> Option<Self::Input> {
        (case.label.starts_with("n-gon") && case.rings.len() == 2)
            .then(|| (geo_poly(&case.rings[0]), geo_poly(&case.rings[1])))
    }
    fn run(&self, input: &Self::Input) -> Self::Output {
        input.0.union(&input.1)
    }
    fn stats(&self, out: &Self::Output) -> Option<SweepStats> {
        let mut rings = Vec::new();
        for p in &out.0 {
            for ls in std::iter::once(p.exterior()).chain(p.interiors()) {
                let mut r: Ring = ls.0.iter().map(|c| [c.x, c.y]).collect();
                if r.len() > 1 && r.first() == r.last() {
                    r.pop();
                }
                rings.push(r);
            }
        }
        Some(stats_of(&rings))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn umbra_and_i_overlay_agree_on_small_rows() {
        let cases = [
            SweepCase {
                label: "checker".into(),
                rings: checkerboards(6),
                expected: None,
            },
            SweepCase {
                label: "nested".into(),
                rings: nested_squares(10),
                expected: Some((10, Some(40))),
            },
            SweepCase {
                label: "spiral".into(),
                rings: spirals(400),
                expected: None,
            },
        ];
        for case in &cases {
            let u = UmbraSweep
                .stats(&UmbraSweep.run(&UmbraSweep.prepare(case).unwrap()))
                .unwrap();
            let p = IOverlaySweep { wide: true };
            let i = p.stats(&p.run(&p.prepare(case).unwrap())).unwrap();
            assert!(
                (u.area - i.area).abs() < 1e-6 * u.area.abs().max(1.0),
                "{}: {u:?} {i:?}",
                case.label
            );
            if let Some((rings, vertices)) = case.expected {
                assert_eq!(u.rings, rings, "{}", case.label);
                if let Some(v) = vertices {
                    assert_eq!(u.vertices, v, "{}", case.label);
                }
            }
        }
        // Two boards of 18 unit cells each, overlapping in part.
        let u = UmbraSweep
            .stats(&UmbraSweep.run(&UmbraSweep.prepare(&cases[0]).unwrap()))
            .unwrap();
        assert!(u.area > 18.0 && u.area < 36.0);
    }
}
