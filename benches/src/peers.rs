//! The [`Peer`] trait and its implementations: Umbra's 2D Boolean, the C++
//! Clipper2 (`clipper2` crate) and its pure-Rust port (`clipper2-rust`),
//! both on Clipper2's `i64` engine at the grid of [`crate::clipper`],
//! `i_overlay` 9 (float API, 32- and 64-bit integer engines) and `geo` 0.33
//! (`BooleanOps`, itself built on `i_overlay` 4).

use crate::clipper::{cpp_paths, cpp_rings, rust_paths, rust_rings, Fine};
use crate::{BenchError, Ring};
use boolean_2d::{boolean, BooleanError, BooleanOp, BooleanOutput};
use geo::{BooleanOps, Coord, LineString, MultiPolygon, Polygon};
use i_overlay::core::fill_rule::FillRule;
use i_overlay::core::overlay_rule::OverlayRule;
use i_overlay::float::single::SingleFloatOverlay;
use topology::PolygonSet2;

/// The shape of a result: how many rings and how many vertices in all, and
/// the area they enclose.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct RingStats {
    /// The number of rings (outer boundaries and holes alike).
    pub rings: usize,
    /// The number of vertices over all rings, closing duplicates excluded.
    pub vertices: usize,
    /// The number of zero-length ring edges (consecutive vertices at the
    /// same coordinates, the closing edge included); they are counted in
    /// `vertices`.
    pub zero_length_edges: usize,
    /// The sum of the rings' signed areas (shoelace formula).
    pub area: f64,
}

/// The exact area of the union of a Table 7.4 pair: two regular `n`-gons
/// of circumradius 1, the second rotated by `alpha_deg` degrees (less than
/// one edge's angle). Both are the intersections of `n` half-planes at the
/// apothem `a = cos(pi / n)` from the centre, so their intersection is the
/// `2n`-gon circumscribed about the circle of radius `a` whose edge normals
/// are `alpha` and `2 pi / n - alpha` apart, alternately, of area
/// `n a^2 (tan(alpha / 2) + tan(pi / n - alpha / 2))`; each n-gon has area
/// `n a^2 tan(pi / n)`, and the union is twice that less the intersection.
pub fn exact_union_area(n: usize, alpha_deg: f64) -> f64 {
    let nf = n as f64;
    let half = std::f64::consts::PI / nf;
    let alpha = alpha_deg.to_radians();
    let a2 = half.cos() * half.cos();
    nf * a2 * (2.0 * half.tan() - (alpha / 2.0).tan() - (half - alpha / 2.0).tan())
}

impl RingStats {
    /// The statistics of `rings`.
    pub fn of(rings: &[Ring]) -> RingStats {
        let mut stats = RingStats {
            rings: rings.len(),
            ..RingStats::default()
        };
        for ring in rings {
            stats.vertices += ring.len();
            let next = ring.iter().skip(1).chain(ring.first());
            stats.zero_length_edges += ring.iter().zip(next).filter(|(p, q)| p == q).count();
            let next = ring.iter().skip(1).chain(ring.first());
            stats.area += ring
                .iter()
                .zip(next)
                .map(|(p, q)| p[0] * q[1] - q[0] * p[1])
                .sum::<f64>()
                / 2.0;
        }
        stats
    }

    /// True when the result is the exact union of the Table 7.4 row
    /// `case`: one ring of `4n` vertices, no zero-length edge, and the area
    /// of [`exact_union_area`] to 1e-9 relative (either orientation).
    pub fn is_exact_union(&self, case: &crate::Case) -> bool {
        let want = exact_union_area(case.n, case.alpha_deg);
        self.is_single_ring_with(case.expected_vertices())
            && (self.area.abs() - want).abs() <= 1e-9 * want
    }

    /// True when the result is exactly one ring of `vertices` vertices with
    /// no zero-length edge (the exact combinatorics of a Table 7.4 row has
    /// `vertices = 4n`).
    pub fn is_single_ring_with(&self, vertices: usize) -> bool {
        self.rings == 1 && self.vertices == vertices && self.zero_length_edges == 0
    }
}

/// A library under test. Each peer converts the input once
/// ([`Peer::prepare`], not timed), runs the union ([`Peer::union`], the
/// only timed part) and reads its own output back as rings
/// ([`Peer::rings`], not timed).
pub trait Peer {
    /// The peer's native, prepared input (both operands).
    type Input;
    /// The peer's native output.
    type Output;

    /// A short name for tables and benchmark ids.
    fn name(&self) -> &'static str;

    /// Converts two polygon sets, each a list of counter-clockwise rings,
    /// into the peer's native input.
    fn prepare(&self, a: &[Ring], b: &[Ring]) -> Self::Input;

    /// The union of the two prepared operands.
    fn union(&self, input: &Self::Input) -> Self::Output;

    /// The result as rings (no closing duplicates).
    fn rings(&self, output: &Self::Output) -> Result<Vec<Ring>, BenchError>;

    /// Ring and vertex counts of the result.
    fn stats(&self, output: &Self::Output) -> Result<RingStats, BenchError> {
        self.rings(output).map(|rings| RingStats::of(&rings))
    }
}

/// Umbra: [`boolean_2d::boolean`] with [`BooleanOp::Union`] on two
/// [`PolygonSet2`]. Its output is a set of directed edges; the rings are
/// traced afterwards with [`PolygonSet2::loops`] (not timed).
#[derive(Clone, Copy, Debug, Default)]
pub struct Umbra;

/// The polygon set of a list of rings.
fn polygon_set(rings: &[Ring]) -> PolygonSet2 {
    let mut set = PolygonSet2::new();
    for ring in rings {
        set.add_loop(ring);
    }
    set
}

impl Peer for Umbra {
    type Input = (PolygonSet2, PolygonSet2);
    type Output = Result<BooleanOutput, BooleanError>;

    fn name(&self) -> &'static str {
        "umbra"
    }

    fn prepare(&self, a: &[Ring], b: &[Ring]) -> Self::Input {
        (polygon_set(a), polygon_set(b))
    }

    fn union(&self, input: &Self::Input) -> Self::Output {
        boolean(&input.0, &input.1, BooleanOp::Union)
    }

    fn rings(&self, output: &Self::Output) -> Result<Vec<Ring>, BenchError> {
        let out = output.as_ref().map_err(|e| BenchError::Umbra(e.clone()))?;
        let vertices = out.shape.vertices();
        out.shape
            .loops()
            .into_iter()
            .map(|ring| {
                ring.into_iter()
                    .map(|v| {
                        vertices.get(v as usize).copied().ok_or_else(|| {
                            BenchError::Internal(format!("umbra loop vertex {v} out of range"))
                        })
                    })
                    .collect()
            })
            .collect()
    }
}

/// The contours of a list of rings, as `i_overlay` takes them.
fn contours(rings: &[Ring]) -> Vec<Vec<[f64; 2]>> {
    rings.to_vec()
}

/// The rings of an `i_overlay` result (shapes of contours, not closed).
fn i_overlay_rings(shapes: &[Vec<Vec<[f64; 2]>>]) -> Vec<Ring> {
    shapes.iter().flatten().cloned().collect()
}

/// `i_overlay` 9 through its float API with the default 32-bit integer
/// engine (`SingleFloatOverlay::overlay`, `OverlayRule::Union`,
/// `FillRule::NonZero`). Coordinates are snapped to a 32-bit grid over
/// the bounding box inside the call.
#[derive(Clone, Copy, Debug, Default)]
pub struct IOverlay;

impl Peer for IOverlay {
    type Input = (Vec<Vec<[f64; 2]>>, Vec<Vec<[f64; 2]>>);
    type Output = Vec<Vec<Vec<[f64; 2]>>>;

    fn name(&self) -> &'static str {
        "i_overlay"
    }

    fn prepare(&self, a: &[Ring], b: &[Ring]) -> Self::Input {
        (contours(a), contours(b))
    }

    fn union(&self, input: &Self::Input) -> Self::Output {
        input
            .0
            .overlay(&input.1, OverlayRule::Union, FillRule::NonZero)
    }

    fn rings(&self, output: &Self::Output) -> Result<Vec<Ring>, BenchError> {
        Ok(i_overlay_rings(output))
    }
}

/// `i_overlay` 9 through its float API with the 64-bit integer engine
/// (`SingleFloatOverlay::overlay_as::<i64>`), the finest grid it offers.
#[derive(Clone, Copy, Debug, Default)]
pub struct IOverlay64;

impl Peer for IOverlay64 {
    type Input = (Vec<Vec<[f64; 2]>>, Vec<Vec<[f64; 2]>>);
    type Output = Vec<Vec<Vec<[f64; 2]>>>;

    fn name(&self) -> &'static str {
        "i_overlay-i64"
    }

    fn prepare(&self, a: &[Ring], b: &[Ring]) -> Self::Input {
        (contours(a), contours(b))
    }

    fn union(&self, input: &Self::Input) -> Self::Output {
        input
            .0
            .overlay_as::<i64>(&input.1, OverlayRule::Union, FillRule::NonZero)
    }

    fn rings(&self, output: &Self::Output) -> Result<Vec<Ring>, BenchError> {
        Ok(i_overlay_rings(output))
    }
}

/// `geo` 0.33: `BooleanOps::union` on two `MultiPolygon<f64>` (each ring an
/// exterior without holes).
#[derive(Clone, Copy, Debug, Default)]
pub struct Geo;

/// The multipolygon of a list of rings, one polygon per ring.
fn multi_polygon(rings: &[Ring]) -> MultiPolygon<f64> {
    MultiPolygon::new(
        rings
            .iter()
            .map(|ring| {
                let coords: Vec<Coord<f64>> = ring.iter().map(|&[x, y]| Coord { x, y }).collect();
                Polygon::new(LineString::new(coords), Vec::new())
            })
            .collect(),
    )
}

/// A closed `geo` line string as a ring without the closing point.
fn geo_ring(line: &LineString<f64>) -> Ring {
    let mut ring: Ring = line.0.iter().map(|c| [c.x, c.y]).collect();
    if ring.len() > 1 && ring.first() == ring.last() {
        ring.pop();
    }
    ring
}

impl Peer for Geo {
    type Input = (MultiPolygon<f64>, MultiPolygon<f64>);
    type Output = MultiPolygon<f64>;

    fn name(&self) -> &'static str {
        "geo"
    }

    fn prepare(&self, a: &[Ring], b: &[Ring]) -> Self::Input {
        (multi_polygon(a), multi_polygon(b))
    }

    fn union(&self, input: &Self::Input) -> Self::Output {
        input.0.union(&input.1)
    }

    fn rings(&self, output: &Self::Output) -> Result<Vec<Ring>, BenchError> {
        Ok(output
            .iter()
            .flat_map(|p| std::iter::once(p.exterior()).chain(p.interiors()))
            .map(geo_ring)
            .collect())
    }
}

/// The C++ Clipper2 through the `clipper2` crate: `clipper2::union` of the
/// two operands (subject and clip) by the nonzero rule, on its `i64`
/// engine with 2^50 grid units per unit ([`crate::clipper`]). The API
/// takes its paths by value and copies them into the C++ structures, so
/// the timed call includes one copy of the input (a `Vec` clone and the
/// crate's own conversion).
#[derive(Clone, Copy, Debug, Default)]
pub struct Clipper2;

impl Peer for Clipper2 {
    type Input = (clipper2::Paths<Fine>, clipper2::Paths<Fine>);
    type Output = Result<clipper2::Paths<Fine>, clipper2::ClipperError>;

    fn name(&self) -> &'static str {
        "clipper2"
    }

    fn prepare(&self, a: &[Ring], b: &[Ring]) -> Self::Input {
        (cpp_paths(a), cpp_paths(b))
    }

    fn union(&self, input: &Self::Input) -> Self::Output {
        clipper2::union(
            input.0.clone(),
            input.1.clone(),
            clipper2::FillRule::NonZero,
        )
    }

    fn rings(&self, output: &Self::Output) -> Result<Vec<Ring>, BenchError> {
        output
            .as_ref()
            .map(cpp_rings)
            .map_err(|e| BenchError::Peer(format!("clipper2: {e}")))
    }
}

/// `clipper2-rust`, the pure-Rust port of Clipper2: `union_64` of the two
/// operands by the nonzero rule, on the same `i64` grid as [`Clipper2`].
#[derive(Clone, Copy, Debug, Default)]
pub struct Clipper2Rust;

impl Peer for Clipper2Rust {
    type Input = (clipper2_rust::Paths64, clipper2_rust::Paths64);
    type Output = clipper2_rust::Paths64;

    fn name(&self) -> &'static str {
        "clipper2-rust"
    }

    fn prepare(&self, a: &[Ring], b: &[Ring]) -> Self::Input {
        (rust_paths(a), rust_paths(b))
    }

    fn union(&self, input: &Self::Input) -> Self::Output {
        clipper2_rust::union_64(&input.0, &input.1, clipper2_rust::FillRule::NonZero)
    }

    fn rings(&self, output: &Self::Output) -> Result<Vec<Ring>, BenchError> {
        Ok(rust_rings(output))
    }
}
