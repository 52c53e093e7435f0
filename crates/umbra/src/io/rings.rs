//! Rings and polygons: the bridge between a [`PolygonSet2`] (directed edges)
//! and the ring-based formats (WKT, `geo-types`).
//!
//! Reading turns each ring into a closed loop of directed edges; by default
//! the ring's *role* decides its direction (outer rings enclose positively,
//! holes negatively), with [`RingOrientation::AsWritten`] the stored direction
//! is kept. Writing splits the edges into loops ([`PolygonSet2::loops`]) and,
//! by default, groups each hole into the smallest outer ring containing it
//! (RFC 7946: interior on the left, outer rings counter-clockwise, holes
//! clockwise, which is the dissertation's convention of section 4.2).

use crate::UmbraError;
use robust_arith::{validate_coordinate, Point2};
use rstar::primitives::{GeomWithData, Rectangle};
use rstar::{RTree, AABB};
use topology::{ring_signed_area, PolygonSet2, RingIndex, RingSide};

/// How the direction of a ring is decided when reading, and how loops are
/// grouped when writing.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum RingOrientation {
    /// By role (the default, as every GIS reads polygons). Reading: the first
    /// ring of a polygon is outer and is made counter-clockwise, the others
    /// are holes and are made clockwise, whatever their stored direction
    /// (by the sign of the signed area; a ring of zero area is kept as
    /// written). Writing: outer rings counter-clockwise, holes clockwise,
    /// each hole inside the smallest outer ring containing it.
    #[default]
    ByRole,
    /// Every ring is a directed loop exactly as written (the interior on its
    /// left), so inside-out and multiply-enclosed shapes survive a round
    /// trip. Writing emits every loop as its own polygon.
    AsWritten,
}

/// Polygons as lists of rings, each ring a list of points without the
/// closing duplicate (the last point joins back to the first).
pub type Polygons = Vec<Vec<Vec<Point2>>>;

/// A polygon set read from a file, and what the reader skipped
/// ([`crate::read_polygon_set_counted`]).
#[derive(Clone, Debug, PartialEq)]
pub struct PolygonSetRead {
    /// The set of the file's polygonal parts.
    pub set: PolygonSet2,
    /// Parts without area (points, multipoints, lines, multilines, empty
    /// or not) skipped from a collection (a WKT or GeoJSON
    /// `GeometryCollection`, a GeoJSON `FeatureCollection`), as GEOS and
    /// shapely overlays return beside their polygons. A file with no
    /// polygonal part at all is refused instead.
    pub skipped_non_areal: usize,
}

impl PolygonSetRead {
    /// The warning a front end gives about the parts skipped from `file`,
    /// `None` when nothing was skipped.
    ///
    /// ```
    /// use umbra::{PolygonSet2, PolygonSetRead};
    /// let read = PolygonSetRead { set: PolygonSet2::default(), skipped_non_areal: 2 };
    /// assert_eq!(
    ///     read.warning("a.wkt").unwrap(),
    ///     "a.wkt: 2 non-areal part(s) (points, lines) skipped; only polygons are read"
    /// );
    /// ```
    pub fn warning(&self, file: &str) -> Option<String> {
        (self.skipped_non_areal > 0).then(|| {
            format!(
                "{file}: {} non-areal part(s) (points, lines) skipped; only polygons are read",
                self.skipped_non_areal
            )
        })
    }
}

/// The non-areal parts (points, lines) a 2D reader skipped: counted for
/// a warning, and the first named for the error when nothing areal is
/// left (a file of lines or points alone is no polygon file).
#[derive(Debug, Default)]
pub(crate) struct NonAreal {
    /// Parts skipped.
    pub count: usize,
    /// The first, as an [`UmbraError::UnsupportedGeometry`] names it.
    pub first: Option<String>,
}

impl NonAreal {
    /// Skips the part described by `found`.
    pub fn skip(&mut self, found: impl FnOnce() -> String) {
        self.count += 1;
        if self.first.is_none() {
            self.first = Some(found());
        }
    }

    /// `polygons` and the count skipped, or the error naming the first
    /// part skipped when there is no polygon (not even an empty one).
    pub fn finish(self, polygons: Polygons, file: &str) -> Result<(Polygons, usize), UmbraError> {
        match self.first {
            Some(found) if polygons.is_empty() => Err(UmbraError::UnsupportedGeometry {
                file: file.to_string(),
                found,
            }),
            _ => Ok((polygons, self.count)),
        }
    }
}

/// Removes the closing duplicate of a ring (a last point equal to the
/// first), which is not a separate vertex.
pub(crate) fn strip_closing(ring: &mut Vec<Point2>) {
    if ring.len() > 1 && ring.first() == ring.last() {
        ring.pop();
    }
}

/// Checks every coordinate (finite, at most `f64::MAX / 4`, section 8.5),
/// naming the first bad one by 1-based polygon, ring and point numbers.
pub(crate) fn validate_polygons(polygons: &Polygons, file: &str) -> Result<(), UmbraError> {
    for (pi, poly) in polygons.iter().enumerate() {
        for (ri, ring) in poly.iter().enumerate() {
            for (qi, p) in ring.iter().enumerate() {
                for (axis, &value) in p.iter().enumerate() {
                    if let Err(source) = validate_coordinate(value) {
                        return Err(UmbraError::BadCoordinate {
                            file: file.to_string(),
                            location: format!(
                                "polygon {}, ring {}, point {}",
                                pi + 1,
                                ri + 1,
                                qi + 1
                            ),
                            axis: axis as u8,
                            source,
                        });
                    }
                }
            }
        }
    }
    Ok(())
}

/// Builds a polygon set from polygons of open rings (no closing duplicate).
/// Every ring becomes one closed loop; rings of one or two points are
/// degenerate loops, topologically valid. Empty rings are skipped.
pub(crate) fn build_set(
    polygons: &Polygons,
    orientation: RingOrientation,
    file: &str,
) -> Result<PolygonSet2, UmbraError> {
    let total: usize = polygons.iter().flatten().map(Vec::len).sum();
    if total > (u32::MAX / 2) as usize {
        return Err(UmbraError::Parse {
            file: file.to_string(),
            message: format!(
                "too many points ({total}); at most {} are supported",
                u32::MAX / 2
            ),
        });
    }
    let mut set = PolygonSet2::new();
    let mut reversed: Vec<Point2> = Vec::new();
    for poly in polygons {
        for (ri, ring) in poly.iter().enumerate() {
            if ring.is_empty() {
                continue;
            }
            let flip = match orientation {
                RingOrientation::AsWritten => false,
                RingOrientation::ByRole => {
                    let area = ring_signed_area(ring);
                    if ri == 0 {
                        area < 0.0
                    } else {
                        area > 0.0
                    }
                }
            };
            if flip {
                reversed.clear();
                reversed.extend(ring.iter().rev());
                set.add_loop(&reversed);
            } else {
                set.add_loop(ring);
            }
        }
    }
    Ok(set)
}

/// The polygons of a set, ready to write, and what could not be laid out
/// by role.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct PolygonLayout {
    /// Polygons of open rings: the first ring of each is its exterior.
    pub polygons: Polygons,
    /// Holes (clockwise loops) that no counter-clockwise loop contains: the
    /// set is inside-out there. Each was written as the exterior of its own
    /// polygon, which a by-role reader turns counter-clockwise; write with
    /// [`RingOrientation::AsWritten`] to keep such shapes.
    pub orphan_holes: usize,
}

/// Splits a topologically valid set into polygons.
///
/// With [`RingOrientation::ByRole`] loops of positive signed area are outer
/// rings (counter-clockwise), loops of negative area are holes (clockwise)
/// grouped into the smallest outer ring that contains one of their points
/// (exact point-in-ring test); loops of zero area are their own polygons.
/// With [`RingOrientation::AsWritten`] every loop is its own polygon.
///
/// Fails with [`UmbraError::InvalidShape`] when the set violates shape
/// boundary closure or has a bad coordinate (then no ring layout exists).
pub fn layout_polygons(
    set: &PolygonSet2,
    orientation: RingOrientation,
    file: &str,
) -> Result<PolygonLayout, UmbraError> {
    let invalid = |source| UmbraError::InvalidShape {
        file: file.to_string(),
        source,
    };
    set.check_topology().map_err(invalid)?;
    set.validate_coordinates().map_err(invalid)?;
    let rings_of = |set: &PolygonSet2| -> Vec<Vec<Point2>> {
        set.loops()
            .iter()
            .map(|l| l.iter().map(|&v| set.vertex(v)).collect())
            .collect()
    };
    if orientation == RingOrientation::AsWritten {
        return Ok(PolygonLayout {
            polygons: rings_of(set).into_iter().map(|r| vec![r]).collect(),
            orphan_holes: 0,
        });
    }
    let rings = rings_of(&normalized(set));
    let areas: Vec<f64> = rings.iter().map(|r| ring_signed_area(r)).collect();
    // Outer rings, smallest first, so the first container found is the
    // smallest one.
    let mut outers: Vec<usize> = (0..rings.len()).filter(|&i| areas[i] >= 0.0).collect();
    outers.sort_by(|&i, &j| areas[i].total_cmp(&areas[j]));
    let boxes: Vec<[Point2; 2]> = rings.iter().map(|r| ring_box(r)).collect();
    let mut slot = vec![usize::MAX; rings.len()];
    let mut polygons: Polygons = Vec::with_capacity(outers.len());
    for &o in &outers {
        slot[o] = polygons.len();
        polygons.push(vec![rings[o].clone()]);
    }
    let mut orphan_holes = 0;
    // Point-location indices of the outer rings, built on first use.
    let mut indices: Vec<Option<RingIndex>> = (0..rings.len()).map(|_| None).collect();
    // The boxes of the outer rings of positive area, each with its rank in
    // `outers`: a hole's candidates are found by one query instead of a
    // pass over every outer ring (thousands of rings on a real map's
    // Boolean made that pass most of the writing time).
    let outer_boxes = RTree::bulk_load(
        outers
            .iter()
            .enumerate()
            .filter(|&(_, &o)| areas[o] > 0.0)
            .map(|(rank, &o)| {
                GeomWithData::new(Rectangle::from_corners(boxes[o][0], boxes[o][1]), rank)
            })
            .collect(),
    );
    let mut candidates: Vec<usize> = Vec::new();
    for h in (0..rings.len()).filter(|&i| areas[i] < 0.0) {
        // The candidates in `outers` order: the first container found is
        // the smallest one, as a pass over `outers` would find it.
        candidates.clear();
        candidates.extend(
            outer_boxes
                .locate_in_envelope_intersecting(&AABB::from_corners(boxes[h][0], boxes[h][1]))
                .map(|g| g.data)
                .filter(|&rank| box_contains(&boxes[outers[rank]], &boxes[h])),
        );
        candidates.sort_unstable();
        let container = candidates.iter().map(|&rank| outers[rank]).find(|&o| {
            let index = indices[o].get_or_insert_with(|| RingIndex::new(&rings[o]));
            ring_inside(&rings[h], &rings[o], index)
        });
        match container.map(|o| slot[o]).and_then(|s| polygons.get_mut(s)) {
            Some(poly) => poly.push(rings[h].clone()),
            None => {
                orphan_holes += 1;
                polygons.push(vec![rings[h].clone()]);
            }
        }
    }
    Ok(PolygonLayout {
        polygons,
        orphan_holes,
    })
}

/// The same region with a cleaner edge collection: vertices at equal
/// coordinates merged, zero-length edges dropped, and edges between the
/// same two vertices summed into one net multiplicity (an edge and its
/// reverse cancel). Every change adds zero to every winding number and
/// keeps shape boundary closure, since each vertex balance is a sum of
/// balances that were zero; it only lets [`PolygonSet2::loops`] split rings
/// that touch at a vertex and drop back-and-forth spikes.
fn normalized(set: &PolygonSet2) -> PolygonSet2 {
    // Hashing that needs no protection against chosen keys (the map lives
    // for this call only): a tenth of the cost of `std`'s on a map's
    // hundred thousand vertices.
    use rustc_hash::FxHashMap as HashMap;
    // -0.0 and 0.0 are the same point.
    let key = |p: Point2| (p[0] + 0.0).to_bits() as u128 | (((p[1] + 0.0).to_bits() as u128) << 64);
    let mut ids: HashMap<u128, u32> =
        HashMap::with_capacity_and_hasher(set.vertex_count(), Default::default());
    let mut out = PolygonSet2::new();
    let remap: Vec<u32> = set
        .vertices()
        .iter()
        .map(|&p| *ids.entry(key(p)).or_insert_with(|| out.add_vertex(p)))
        .collect();
    let mut net: HashMap<(u32, u32), i64> =
        HashMap::with_capacity_and_hasher(set.edge_count(), Default::default());
    let mut order: Vec<(u32, u32)> = Vec::new();
    for e in set.edges() {
        let (Some(&s), Some(&t)) = (remap.get(e.start as usize), remap.get(e.end as usize)) else {
            continue;
        };
        if s == t || e.mult == 0 {
            continue;
        }
        let (pair, m) = if s < t {
            ((s, t), i64::from(e.mult))
        } else {
            ((t, s), -i64::from(e.mult))
        };
        let slot = net.entry(pair).or_insert_with(|| {
            order.push(pair);
            0
        });
        *slot += m;
    }
    for pair in order {
        let m = net.get(&pair).copied().unwrap_or(0);
        // Split multiplicities beyond i32 into several entries.
        let mut left = m;
        while left != 0 {
            let step = left.clamp(i64::from(-i32::MAX), i64::from(i32::MAX));
            out.add_edge_mult(pair.0, pair.1, step as i32);
            left -= step;
        }
    }
    out
}

/// The bounding box of a ring.
fn ring_box(ring: &[Point2]) -> [Point2; 2] {
    let mut b = [[f64::INFINITY; 2], [f64::NEG_INFINITY; 2]];
    for p in ring {
        for k in 0..2 {
            b[0][k] = b[0][k].min(p[k]);
            b[1][k] = b[1][k].max(p[k]);
        }
    }
    b
}

/// `true` when box `outer` contains box `inner` (closed).
fn box_contains(outer: &[Point2; 2], inner: &[Point2; 2]) -> bool {
    (0..2).all(|k| outer[0][k] <= inner[0][k] && inner[1][k] <= outer[1][k])
}

/// `true` when the ring `inner` lies inside `outer`, judged at the first of
/// its vertices (then edge midpoints) that is not on `outer`'s boundary; a
/// ring lying wholly on the boundary counts as inside.
fn ring_inside(inner: &[Point2], outer: &[Point2], index: &RingIndex) -> bool {
    let n = inner.len();
    let midpoints = (0..n).map(|i| {
        let a = inner[i];
        let b = inner[(i + 1) % n];
        [a[0] / 2.0 + b[0] / 2.0, a[1] / 2.0 + b[1] / 2.0]
    });
    for p in inner.iter().copied().chain(midpoints) {
        if let RingSide::Off(w) = index.side(outer, p) {
            return w != 0;
        }
    }
    true
}

#[cfg(test)]
mod tests {
    use super::*;

    fn square(x0: f64, y0: f64, s: f64) -> Vec<Point2> {
        vec![[x0, y0], [x0 + s, y0], [x0 + s, y0 + s], [x0, y0 + s]]
    }

    #[test]
    fn by_role_reorients_rings() {
        let mut outer = square(0.0, 0.0, 10.0);
        outer.reverse(); // stored clockwise
        let hole = square(2.0, 2.0, 2.0); // stored counter-clockwise
        let set = build_set(
            &vec![vec![outer.clone(), hole.clone()]],
            RingOrientation::ByRole,
            "t",
        )
        .unwrap();
        assert_eq!(set.signed_area(), 100.0 - 4.0);
        let kept = build_set(&vec![vec![outer, hole]], RingOrientation::AsWritten, "t").unwrap();
        assert_eq!(kept.signed_area(), -100.0 + 4.0);
    }

    #[test]
    fn rings_beyond_the_square_root_of_the_largest_f64_keep_their_roles() {
        // The shoelace products of 1e155 overflow; the rings were dropped
        // (a NaN area is neither an exterior nor a hole) or kept clockwise.
        let s = 1e155;
        let mut outer = square(0.0, 0.0, 4.0 * s);
        outer.reverse(); // stored clockwise
        let hole = square(s, s, s); // stored counter-clockwise
        let set = build_set(&vec![vec![outer, hole]], RingOrientation::ByRole, "t").unwrap();
        let layout = layout_polygons(&set, RingOrientation::ByRole, "t").unwrap();
        assert_eq!(layout.orphan_holes, 0);
        assert_eq!(layout.polygons.len(), 1);
        let poly = &layout.polygons[0];
        assert_eq!(poly.len(), 2);
        assert_eq!(ring_signed_area(&poly[0]), f64::INFINITY);
        assert_eq!(ring_signed_area(&poly[1]), f64::NEG_INFINITY);
    }

    #[test]
    fn holes_go_to_the_smallest_container() {
        // A big square with a hole, an island in the hole with its own hole.
        let mut set = PolygonSet2::new();
        set.add_loop(&square(0.0, 0.0, 10.0));
        let mut h1 = square(1.0, 1.0, 8.0);
        h1.reverse();
        set.add_loop(&h1);
        set.add_loop(&square(2.0, 2.0, 6.0));
        let mut h2 = square(3.0, 3.0, 4.0);
        h2.reverse();
        set.add_loop(&h2);
        let layout = layout_polygons(&set, RingOrientation::ByRole, "t").unwrap();
        assert_eq!(layout.orphan_holes, 0);
        assert_eq!(layout.polygons.len(), 2);
        for poly in &layout.polygons {
            assert_eq!(poly.len(), 2);
            assert!(ring_signed_area(&poly[0]) > 0.0);
            assert!(ring_signed_area(&poly[1]) < 0.0);
            // The hole's box lies within its exterior's box.
            assert!(box_contains(&ring_box(&poly[0]), &ring_box(&poly[1])));
        }
        let areas: Vec<f64> = layout
            .polygons
            .iter()
            .map(|p| p.iter().map(|r| ring_signed_area(r)).sum())
            .collect();
        assert!(areas.contains(&(100.0 - 64.0)) && areas.contains(&(36.0 - 16.0)));
    }

    #[test]
    fn touching_rings_and_spikes_are_cleaned_by_role() {
        // A square hole touching a triangular hole at (2, 2), with a
        // duplicated vertex and a zero-length edge there, and a spike.
        let text_rings: Vec<Vec<Point2>> = vec![
            square(0.0, 0.0, 12.0),
            vec![
                [2.0, 2.0],
                [2.0, 2.0],
                [0.5, 0.5],
                [0.5, 4.0],
                [2.0, 2.0],
                [2.0, 10.0],
                [10.0, 10.0],
                [10.0, 2.0],
            ],
            vec![[11.0, 11.0], [11.5, 11.5], [11.0, 11.0]],
        ];
        let mut set = PolygonSet2::new();
        for r in &text_rings {
            set.add_loop(r);
        }
        let layout = layout_polygons(&set, RingOrientation::ByRole, "t").unwrap();
        assert_eq!(layout.orphan_holes, 0);
        assert_eq!(layout.polygons.len(), 1, "{layout:?}");
        let poly = &layout.polygons[0];
        assert_eq!(poly.len(), 3, "{poly:?}");
        assert_eq!(poly[1].len() + poly[2].len(), 3 + 4);
        let area: f64 = poly.iter().map(|r| ring_signed_area(r)).sum();
        assert_eq!(area, set.signed_area());
        // As written keeps every loop, degenerate ones included.
        let kept = layout_polygons(&set, RingOrientation::AsWritten, "t").unwrap();
        let points: usize = kept.polygons.iter().flatten().map(Vec::len).sum();
        assert_eq!(points, set.edge_count());
    }

    #[test]
    fn inside_out_loops_are_orphans() {
        let mut set = PolygonSet2::new();
        let mut cw = square(0.0, 0.0, 1.0);
        cw.reverse();
        set.add_loop(&cw);
        let layout = layout_polygons(&set, RingOrientation::ByRole, "t").unwrap();
        assert_eq!(layout.orphan_holes, 1);
        assert_eq!(layout.polygons.len(), 1);
    }

    #[test]
    fn invalid_sets_are_refused() {
        let mut set = PolygonSet2::new();
        let a = set.add_vertex([0.0, 0.0]);
        let b = set.add_vertex([1.0, 0.0]);
        set.add_edge(a, b);
        let err = layout_polygons(&set, RingOrientation::ByRole, "out.wkt").unwrap_err();
        assert!(
            err.to_string().starts_with("out.wkt: invalid shape"),
            "{err}"
        );
    }
}
