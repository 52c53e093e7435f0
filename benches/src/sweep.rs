//! Inputs and peers for simplification (the bench of issue 4): Umbra's
//! sweep (`simplify_2d`, chapters 6-7) beside the C++ Clipper2 (`clipper2`)
//! and its Rust port (`clipper2-rust`), each the union of all rings as
//! subjects by the matching fill rule on the grid of [`crate::clipper`],
//! `i_overlay` 9 (`simplify_shape`, 32- and 64-bit engines) with the
//! matching fill rule,
//! `i_overlay`'s Boolean (the union of the two rings as subject and clip,
//! with the matching fill rule) on the n-gon rows, and `geo` 0.33 where it
//! has the operation (the n-gon union rows).
//!
//! Inputs: the ten rotated n-gon pairs of Table 7.4 ([`TABLE_7_4`], the
//! rows of the 2D Boolean bench) assembled into one set (its nonzero
//! simplification is the union), random topological polygons of section
//! 7.7 (cyclic sequences of seeded random points in the unit disc, heavily
//! self-intersecting) by the nonzero rule and, at 1,000 vertices, by the
//! even-odd and positive rules as well, and i_overlay's kinds of stress
//! input: two checkerboards offset by half a cell, a spiral strip against
//! its rotated copy, and nested squares of alternating orientation.

use crate::clipper::{cpp_paths, cpp_rings, rust_paths, rust_rings, Fine};
use crate::{rotated_ngon_pair, Case, Ring, TABLE_7_4};
use geo::{BooleanOps, Coord, LineString, MultiPolygon, Polygon};
use i_overlay::core::fill_rule::FillRule;
use i_overlay::core::overlay_rule::OverlayRule;
use i_overlay::float::simplify::SimplifyShape;
use i_overlay::float::single::SingleFloatOverlay;
use simplify_2d::{simplify, FillRule as UmbraRule, SimplifyError};
use test_support::rng::SplitMix64;
use test_support::shapes::square;
use topology::PolygonSet2;

/// The fill rules the table exercises, each with its counterpart in Umbra
/// and in `i_overlay` (both count counter-clockwise loops as winding +1,
/// so `Positive` means the same region in both).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SweepRule {
    /// Winding number other than zero.
    NonZero,
    /// Odd winding number.
    EvenOdd,
    /// Winding number greater than zero.
    Positive,
}

impl SweepRule {
    /// Umbra's fill rule.
    pub fn umbra(self) -> UmbraRule {
        match self {
            SweepRule::NonZero => UmbraRule::NonZero,
            SweepRule::EvenOdd => UmbraRule::EvenOdd,
            SweepRule::Positive => UmbraRule::Positive,
        }
    }

    /// `i_overlay`'s fill rule.
    pub fn i_overlay(self) -> FillRule {
        match self {
            SweepRule::NonZero => FillRule::NonZero,
            SweepRule::EvenOdd => FillRule::EvenOdd,
            SweepRule::Positive => FillRule::Positive,
        }
    }

    /// Clipper2's fill rule (the C++ library's, through `clipper2`).
    pub fn clipper2(self) -> clipper2::FillRule {
        match self {
            SweepRule::NonZero => clipper2::FillRule::NonZero,
            SweepRule::EvenOdd => clipper2::FillRule::EvenOdd,
            SweepRule::Positive => clipper2::FillRule::Positive,
        }
    }

    /// `clipper2-rust`'s fill rule.
    pub fn clipper2_rust(self) -> clipper2_rust::FillRule {
        match self {
            SweepRule::NonZero => clipper2_rust::FillRule::NonZero,
            SweepRule::EvenOdd => clipper2_rust::FillRule::EvenOdd,
            SweepRule::Positive => clipper2_rust::FillRule::Positive,
        }
    }

    /// A short name for tables.
    pub fn name(self) -> &'static str {
        match self {
            SweepRule::NonZero => "nonzero",
            SweepRule::EvenOdd => "evenodd",
            SweepRule::Positive => "positive",
        }
    }
}

/// A simplification row: named input rings, the fill rule and what a
/// correct result is.
#[derive(Clone, Debug)]
pub struct SweepCase {
    /// Row label, unique over [`sweep_cases`].
    pub label: String,
    /// The fill rule of the simplification.
    pub rule: SweepRule,
    /// The rings, all taken as directed loops.
    pub rings: Vec<Ring>,
    /// The Table 7.4 row when the input is a rotated n-gon pair (then
    /// `rings` holds the two n-gons and the Boolean peers apply).
    pub ngon: Option<Case>,
    /// The exact ring and vertex counts when known (the n-gon rows: one
    /// ring of `4n` vertices; nested squares: one ring per square).
    pub expected: Option<(usize, Option<usize>)>,
}

/// Section 7.7: `n` random points in the unit disc joined cyclically,
/// drawn from the splitmix64 stream of `seed` (the same seed gives the
/// same polygon on every machine).
pub fn random_topological_polygon(seed: u64, n: usize) -> Ring {
    let mut rng = SplitMix64::new(seed);
    let mut out = Vec::with_capacity(n);
    while out.len() < n {
        let (x, y) = (2.0 * rng.unit() - 1.0, 2.0 * rng.unit() - 1.0);
        if x * x + y * y <= 1.0 {
            out.push([x, y]);
        }
    }
    out
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

/// The row of one Table 7.4 case: the two n-gons in one set, nonzero rule.
pub fn ngon_case(case: Case) -> SweepCase {
    let (a, b) = rotated_ngon_pair(case.n, case.alpha_deg);
    SweepCase {
        label: format!("n-gon union n={} alpha={:e}", case.n, case.alpha_deg),
        rule: SweepRule::NonZero,
        rings: vec![a, b],
        ngon: Some(case),
        expected: Some((1, Some(case.expected_vertices()))),
    }
}

/// The row of a random topological polygon of `n` vertices (seed `n`)
/// simplified by `rule`; the label names the rule unless it is nonzero.
pub fn random_case(n: usize, rule: SweepRule) -> SweepCase {
    let label = match rule {
        SweepRule::NonZero => format!("random polygon n={n}"),
        _ => format!("random polygon n={n} {}", rule.name()),
    };
    SweepCase {
        label,
        rule,
        rings: vec![random_topological_polygon(n as u64, n)],
        ngon: None,
        expected: None,
    }
}

/// The checkerboard row: two 100 x 100 boards offset by half a cell.
pub fn checkerboard_case() -> SweepCase {
    SweepCase {
        label: "checkerboards 2 x 100x100".into(),
        rule: SweepRule::NonZero,
        rings: checkerboards(100),
        ngon: None,
        expected: None,
    }
}

/// The rows of the simplification table: every Table 7.4 row, random
/// polygons of 100 to 5,000 vertices (those above `max_random` left out)
/// by the nonzero rule, the 1,000-vertex one by the even-odd and positive
/// rules too, and the three stress inputs.
pub fn sweep_cases(max_random: usize) -> Vec<SweepCase> {
    let mut rows: Vec<SweepCase> = TABLE_7_4.iter().map(|&c| ngon_case(c)).collect();
    for n in [100, 500, 1000, 2000, 5000] {
        if n <= max_random {
            rows.push(random_case(n, SweepRule::NonZero));
        }
    }
    if 1000 <= max_random {
        rows.push(random_case(1000, SweepRule::EvenOdd));
        rows.push(random_case(1000, SweepRule::Positive));
    }
    rows.push(checkerboard_case());
    rows.push(SweepCase {
        label: "spirals 2 x 20000 v".into(),
        rule: SweepRule::NonZero,
        rings: spirals(20000),
        ngon: None,
        expected: None,
    });
    rows.push(SweepCase {
        label: "nested squares 1000".into(),
        rule: SweepRule::NonZero,
        rings: nested_squares(1000),
        ngon: None,
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
    /// Ring edges of zero length (consecutive equal vertices, the closing
    /// edge included); a result with exact expected counts has none.
    pub zero_length_edges: usize,
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
        zero_length_edges: rings
            .iter()
            .map(|r| {
                let next = r.iter().skip(1).chain(r.first());
                r.iter().zip(next).filter(|(p, q)| p == q).count()
            })
            .sum(),
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
    /// Simplifies by the row's fill rule (timed).
    fn run(&self, input: &Self::Input) -> Self::Output;
    /// Counts and area of the output (not timed), or why there is none.
    fn stats(&self, out: &Self::Output) -> Result<SweepStats, String>;
}

/// Umbra: `simplify_2d::simplify(set, rule)`; rings traced from the output
/// edges with `PolygonSet2::loops` (not timed).
#[derive(Clone, Copy, Debug, Default)]
pub struct UmbraSweep;

impl SweepPeer for UmbraSweep {
    type Input = (PolygonSet2, UmbraRule);
    type Output = Result<PolygonSet2, SimplifyError>;
    fn name(&self) -> &'static str {
        "umbra"
    }
    fn prepare(&self, case: &SweepCase) -> Option<Self::Input> {
        let mut set = PolygonSet2::new();
        for r in &case.rings {
            set.add_loop(r);
        }
        Some((set, case.rule.umbra()))
    }
    fn run(&self, input: &Self::Input) -> Self::Output {
        simplify(&input.0, input.1).map(|s| s.shape)
    }
    fn stats(&self, out: &Self::Output) -> Result<SweepStats, String> {
        let set = out.as_ref().map_err(|e| e.to_string())?;
        let rings: Vec<Ring> = set
            .loops()
            .iter()
            .map(|l| l.iter().map(|&v| set.vertex(v)).collect())
            .collect();
        Ok(stats_of(&rings))
    }
}

/// `i_overlay` 9 `simplify_shape(rule)` with the default 32-bit engine, or
/// the 64-bit one (`wide`, `simplify_shape_as::<i64>`).
#[derive(Clone, Copy, Debug, Default)]
pub struct IOverlaySweep {
    /// Use `simplify_shape_as::<i64>`.
    pub wide: bool,
}

impl SweepPeer for IOverlaySweep {
    type Input = (Vec<Vec<[f64; 2]>>, FillRule);
    type Output = Vec<Vec<Vec<[f64; 2]>>>;
    fn name(&self) -> &'static str {
        if self.wide {
            "i_overlay-i64"
        } else {
            "i_overlay"
        }
    }
    fn prepare(&self, case: &SweepCase) -> Option<Self::Input> {
        Some((case.rings.clone(), case.rule.i_overlay()))
    }
    fn run(&self, input: &Self::Input) -> Self::Output {
        if self.wide {
            input.0.simplify_shape_as::<i64>(input.1)
        } else {
            input.0.simplify_shape(input.1)
        }
    }
    fn stats(&self, out: &Self::Output) -> Result<SweepStats, String> {
        let rings: Vec<Ring> = out.iter().flatten().cloned().collect();
        Ok(stats_of(&rings))
    }
}

/// The C++ Clipper2 (`clipper2` crate): the union of every ring as a
/// subject (no clip) by the row's fill rule, which is Clipper2's
/// simplification; on its `i64` engine at the grid of [`crate::clipper`].
/// The timed call includes one copy of the input paths (the API takes
/// them by value and copies them into the C++ structures).
#[derive(Clone, Copy, Debug, Default)]
pub struct Clipper2Sweep;

impl SweepPeer for Clipper2Sweep {
    type Input = (clipper2::Paths<Fine>, clipper2::FillRule);
    type Output = Result<clipper2::Paths<Fine>, clipper2::ClipperError>;
    fn name(&self) -> &'static str {
        "clipper2"
    }
    fn prepare(&self, case: &SweepCase) -> Option<Self::Input> {
        Some((cpp_paths(&case.rings), case.rule.clipper2()))
    }
    fn run(&self, input: &Self::Input) -> Self::Output {
        clipper2::union(
            input.0.clone(),
            clipper2::Paths::<Fine>::new(Vec::new()),
            input.1,
        )
    }
    fn stats(&self, out: &Self::Output) -> Result<SweepStats, String> {
        let paths = out.as_ref().map_err(|e| format!("clipper2: {e}"))?;
        Ok(stats_of(&cpp_rings(paths)))
    }
}

/// `clipper2-rust`: `union_subjects_64` of every ring by the row's fill
/// rule, on the same grid as [`Clipper2Sweep`].
#[derive(Clone, Copy, Debug, Default)]
pub struct Clipper2RustSweep;

impl SweepPeer for Clipper2RustSweep {
    type Input = (clipper2_rust::Paths64, clipper2_rust::FillRule);
    type Output = clipper2_rust::Paths64;
    fn name(&self) -> &'static str {
        "clipper2-rust"
    }
    fn prepare(&self, case: &SweepCase) -> Option<Self::Input> {
        Some((rust_paths(&case.rings), case.rule.clipper2_rust()))
    }
    fn run(&self, input: &Self::Input) -> Self::Output {
        clipper2_rust::union_subjects_64(&input.0, input.1)
    }
    fn stats(&self, out: &Self::Output) -> Result<SweepStats, String> {
        Ok(stats_of(&rust_rings(out)))
    }
}

/// `i_overlay` 9's Boolean with the matching fill rule on the n-gon rows:
/// `SingleFloatOverlay::overlay` of the first n-gon (subject) and the
/// second (clip) with `OverlayRule::Union` and the row's fill rule, on the
/// default 32-bit engine or the 64-bit one (`wide`, `overlay_as::<i64>`).
#[derive(Clone, Copy, Debug, Default)]
pub struct IOverlayBoolSweep {
    /// Use `overlay_as::<i64>`.
    pub wide: bool,
}

impl SweepPeer for IOverlayBoolSweep {
    type Input = (Vec<Vec<[f64; 2]>>, Vec<Vec<[f64; 2]>>, FillRule);
    type Output = Vec<Vec<Vec<[f64; 2]>>>;
    fn name(&self) -> &'static str {
        if self.wide {
            "i_overlay-bool-i64"
        } else {
            "i_overlay-bool"
        }
    }
    fn prepare(&self, case: &SweepCase) -> Option<Self::Input> {
        (case.ngon.is_some() && case.rings.len() == 2).then(|| {
            (
                vec![case.rings[0].clone()],
                vec![case.rings[1].clone()],
                case.rule.i_overlay(),
            )
        })
    }
    fn run(&self, input: &Self::Input) -> Self::Output {
        if self.wide {
            input
                .0
                .overlay_as::<i64>(&input.1, OverlayRule::Union, input.2)
        } else {
            input.0.overlay(&input.1, OverlayRule::Union, input.2)
        }
    }
    fn stats(&self, out: &Self::Output) -> Result<SweepStats, String> {
        let rings: Vec<Ring> = out.iter().flatten().cloned().collect();
        Ok(stats_of(&rings))
    }
}

/// `geo` 0.33 `BooleanOps::union` of the two n-gons (only the n-gon rows,
/// which are by the nonzero rule: geo has no fill-rule simplification of a
/// self-intersecting ring).
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
        (case.ngon.is_some() && case.rule == SweepRule::NonZero && case.rings.len() == 2)
            .then(|| (geo_poly(&case.rings[0]), geo_poly(&case.rings[1])))
    }
    fn run(&self, input: &Self::Input) -> Self::Output {
        input.0.union(&input.1)
    }
    fn stats(&self, out: &Self::Output) -> Result<SweepStats, String> {
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
        Ok(stats_of(&rings))
    }
}
