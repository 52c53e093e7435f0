//! The [`Peer`] trait and its implementations: Umbra's 2D Boolean and the
//! two Rust peers, `i_overlay` 9 (float API, 32- and 64-bit integer
//! engines) and `geo` 0.33 (`BooleanOps`, itself built on `i_overlay` 4).

use crate::{BenchError, Ring};
use boolean_2d::{boolean, BooleanError, BooleanOp, BooleanOutput};
use geo::{BooleanOps, Coord, LineString, MultiPolygon, Polygon};
use i_overlay::core::fill_rule::FillRule;
use i_overlay::core::overlay_rule::OverlayRule;
use i_overlay::float::single::SingleFloatOverlay;
use topology::PolygonSet2;

/// The shape of a result: how many rings and how many vertices in all.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct RingStats {
    /// The number of rings (outer boundaries and holes alike).
    pub rings: usize,
    /// The number of vertices over all rings, closing duplicates excluded.
    pub vertices: usize,
    /// The number of zero-length ring edges (consecutive vertices at the
    /// same coordinates, the closing edge included); they are counted in
    /// `vertices`.
    pub zero_length_edges: usize,
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
        }
        stats
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rotated_ngon_pair;

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
        ];
        for (name, s) in stats {
            assert!(s.is_single_ring_with(expected), "{name}: {s:?}");
        }
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
        let (a, _) = rotated_ngon_pair(10, 0.0);
        let mp = multi_polygon(&[a]);
        let rings = Geo.rings(&mp).unwrap_or_default();
        assert_eq!(rings.len(), 1);
        assert_eq!(rings[0].len(), 10);
    }
}
