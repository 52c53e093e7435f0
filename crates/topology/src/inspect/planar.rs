//! The inspection of a 2D polygon set: topological validity (section 4.2),
//! coordinate validity (section 8.5) and geometric-validity hints.
//!
//! Geometric validity (no crossing edges, section 4.7) is not required by
//! the Booleans; the count of crossing edge pairs only tells the user how
//! far a shape is from it. Pairs are found by a sort-by-x sweep over edge
//! bounding boxes and decided by the exact orientation predicate.

use super::ring::ring_signed_area;
use crate::PolygonSet2;
use robust_arith::{lex_cmp, orient2d, Point2};
use std::cmp::Ordering;

/// What the inspection of a polygon set reports ([`check_polygon_set`]).
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct CheckReport {
    /// Shape boundary closure holds and every index is in range.
    pub topologically_valid: bool,
    /// The violated constraint and where, when not topologically valid.
    pub topology_error: Option<String>,
    /// Every coordinate is finite and at most `f64::MAX / 4`.
    pub coordinates_valid: bool,
    /// The first bad coordinate, when not valid.
    pub coordinate_error: Option<String>,
    /// The number of vertices.
    pub vertices: usize,
    /// The number of edge entries.
    pub edges: usize,
    /// The number of closed loops ([`PolygonSet2::loops`]); 0 when the
    /// topology is invalid.
    pub rings: usize,
    /// Loops of positive signed area (counter-clockwise).
    pub ccw_rings: usize,
    /// Loops of negative signed area (clockwise).
    pub cw_rings: usize,
    /// The multiplicity-weighted signed area (f64 shoelace).
    pub signed_area: f64,
    /// `[[min x, min y], [max x, max y]]` of the edges' vertices.
    pub bounding_box: Option<[Point2; 2]>,
    /// Pairs of edges whose interiors cross at a single point (exact);
    /// `None` when the coordinates are invalid.
    pub crossing_edge_pairs: Option<usize>,
    /// Pairs of collinear edges that overlap along a segment of positive
    /// length (exact); `None` when the coordinates are invalid.
    pub overlapping_edge_pairs: Option<usize>,
}

impl CheckReport {
    /// `true` when the set is topologically valid with valid coordinates
    /// (what every operation requires).
    pub fn is_valid(&self) -> bool {
        self.topologically_valid && self.coordinates_valid
    }

    /// `true` when, in addition, no edges cross or overlap (a hint of
    /// geometric validity; touching at vertices is allowed).
    pub fn looks_geometrically_valid(&self) -> bool {
        self.is_valid()
            && self.crossing_edge_pairs == Some(0)
            && self.overlapping_edge_pairs == Some(0)
    }
}

/// Checks a polygon set (never fails, never panics: every problem is a
/// field of the report).
///
/// ```
/// use topology::{check_polygon_set, PolygonSet2};
/// let mut bowtie = PolygonSet2::new();
/// bowtie.add_loop(&[[0.0, 0.0], [2.0, 2.0], [2.0, 0.0], [0.0, 2.0]]);
/// let r = check_polygon_set(&bowtie);
/// assert!(r.topologically_valid);
/// assert_eq!(r.crossing_edge_pairs, Some(1));
/// ```
pub fn check_polygon_set(set: &PolygonSet2) -> CheckReport {
    let topology = set.check_topology();
    let coordinates = set.validate_coordinates();
    let mut rings = 0;
    let mut ccw_rings = 0;
    let mut cw_rings = 0;
    if topology.is_ok() {
        for l in set.loops() {
            rings += 1;
            let pts: Vec<Point2> = l.iter().map(|&v| set.vertex(v)).collect();
            let a = ring_signed_area(&pts);
            if a > 0.0 {
                ccw_rings += 1;
            } else if a < 0.0 {
                cw_rings += 1;
            }
        }
    }
    let in_range =
        topology.is_ok() || !matches!(topology, Err(crate::TopologyError::DanglingIndex { .. }));
    let (crossing, overlapping) = if coordinates.is_ok() && in_range {
        let (c, o) = count_crossings(set);
        (Some(c), Some(o))
    } else {
        (None, None)
    };
    CheckReport {
        topologically_valid: topology.is_ok(),
        topology_error: topology.as_ref().err().map(ToString::to_string),
        coordinates_valid: coordinates.is_ok(),
        coordinate_error: coordinates.as_ref().err().map(ToString::to_string),
        vertices: set.vertex_count(),
        edges: set.edge_count(),
        rings,
        ccw_rings,
        cw_rings,
        signed_area: if in_range {
            set.signed_area()
        } else {
            f64::NAN
        },
        bounding_box: if in_range { set.bounding_box() } else { None },
        crossing_edge_pairs: crossing,
        overlapping_edge_pairs: overlapping,
    }
}

impl PolygonSet2 {
    /// The inspection report of this set ([`check_polygon_set`]).
    pub fn check(&self) -> CheckReport {
        check_polygon_set(self)
    }
}

/// Counts (crossing, overlapping) edge pairs by a sort-by-x sweep: edges are
/// sorted by their smallest x, and each is compared only with the following
/// edges whose x-range starts before its own ends and whose y-range meets
/// its own. Requires every vertex index to be in range.
fn count_crossings(set: &PolygonSet2) -> (usize, usize) {
    let vertices = set.vertices();
    let mut segs: Vec<(Point2, Point2)> = set
        .edges()
        .iter()
        .filter(|e| e.mult != 0)
        .filter_map(|e| {
            let a = *vertices.get(e.start as usize)?;
            let b = *vertices.get(e.end as usize)?;
            (a != b).then_some((a, b))
        })
        .collect();
    segs.sort_by(|s, t| s.0[0].min(s.1[0]).total_cmp(&t.0[0].min(t.1[0])));
    let mut crossing = 0;
    let mut overlapping = 0;
    for (i, &(p, q)) in segs.iter().enumerate() {
        let max_x = p[0].max(q[0]);
        let (lo_y, hi_y) = (p[1].min(q[1]), p[1].max(q[1]));
        for &(r, s) in segs.iter().skip(i + 1) {
            if r[0].min(s[0]) > max_x {
                break;
            }
            if r[1].max(s[1]) < lo_y || r[1].min(s[1]) > hi_y {
                continue;
            }
            match classify(p, q, r, s) {
                Contact::Cross => crossing += 1,
                Contact::Overlap => overlapping += 1,
                Contact::None => {}
            }
        }
    }
    (crossing, overlapping)
}

/// How two segments meet.
#[derive(Debug, PartialEq, Eq)]
enum Contact {
    /// The interiors cross at one point.
    Cross,
    /// Collinear with an overlap of positive length.
    Overlap,
    /// Disjoint, or touching at an end point.
    None,
}

/// Classifies segments `p q` and `r s` (both of positive length) exactly.
fn classify(p: Point2, q: Point2, r: Point2, s: Point2) -> Contact {
    let o1 = orient2d(p, q, r);
    let o2 = orient2d(p, q, s);
    let o3 = orient2d(r, s, p);
    let o4 = orient2d(r, s, q);
    let opposite = |a: Ordering, b: Ordering| a != Ordering::Equal && b == a.reverse();
    if opposite(o1, o2) && opposite(o3, o4) {
        return Contact::Cross;
    }
    if [o1, o2, o3, o4].iter().all(|&o| o == Ordering::Equal) {
        // Collinear: compare the lexicographically ordered end points.
        let (a0, a1) = ordered(p, q);
        let (b0, b1) = ordered(r, s);
        let lo = if lex_cmp(&a0, &b0) == Ordering::Less {
            b0
        } else {
            a0
        };
        let hi = if lex_cmp(&a1, &b1) == Ordering::Less {
            a1
        } else {
            b1
        };
        if lex_cmp(&lo, &hi) == Ordering::Less {
            return Contact::Overlap;
        }
    }
    Contact::None
}

/// The two points in lexicographic order.
fn ordered(a: Point2, b: Point2) -> (Point2, Point2) {
    if lex_cmp(&a, &b) == Ordering::Greater {
        (b, a)
    } else {
        (a, b)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn classify_cases() {
        let c = |p: [f64; 2], q, r, s| classify(p, q, r, s);
        assert_eq!(c([0., 0.], [2., 2.], [0., 2.], [2., 0.]), Contact::Cross);
        assert_eq!(c([0., 0.], [2., 2.], [2., 2.], [3., 0.]), Contact::None);
        assert_eq!(c([0., 0.], [2., 0.], [1., 0.], [1., 5.]), Contact::None); // T-junction
        assert_eq!(c([0., 0.], [2., 0.], [1., 0.], [3., 0.]), Contact::Overlap);
        assert_eq!(c([0., 0.], [2., 0.], [2., 0.], [3., 0.]), Contact::None);
        assert_eq!(c([0., 0.], [2., 0.], [2., 0.], [0., 0.]), Contact::Overlap);
        assert_eq!(c([0., 0.], [1., 0.], [0., 1.], [1., 1.]), Contact::None);
    }

    #[test]
    fn sweep_matches_brute_force_on_a_grid_star() {
        // A 7-pointed star polygon {7/3}: every edge crosses 4 others.
        let n = 7;
        let pts: Vec<Point2> = (0..n)
            .map(|i| {
                let t = std::f64::consts::TAU * (3 * i % n) as f64 / n as f64;
                [(t.cos() * 1000.0).round(), (t.sin() * 1000.0).round()]
            })
            .collect();
        let mut s = PolygonSet2::new();
        s.add_loop(&pts);
        let r = check_polygon_set(&s);
        assert_eq!(r.crossing_edge_pairs, Some(7 * 4 / 2));
        assert_eq!(r.overlapping_edge_pairs, Some(0));
        assert!(r.is_valid() && !r.looks_geometrically_valid());
    }

    #[test]
    fn invalid_sets_are_reported_not_refused() {
        let mut s = PolygonSet2::new();
        let a = s.add_vertex([0.0, f64::NAN]);
        let b = s.add_vertex([1.0, 0.0]);
        s.add_edge(a, b);
        let r = check_polygon_set(&s);
        assert!(!r.topologically_valid && !r.coordinates_valid);
        assert!(r.topology_error.unwrap().contains("closure"));
        assert!(r.coordinate_error.unwrap().contains("vertex 0"));
        assert_eq!(r.crossing_edge_pairs, None);
        let dangling = PolygonSet2::from_parts(
            vec![[0.0, 0.0]],
            vec![crate::Edge2 {
                start: 0,
                end: 9,
                mult: 1,
            }],
        );
        let r = check_polygon_set(&dangling);
        assert!(r.topology_error.unwrap().contains("dangling"));
    }
}
