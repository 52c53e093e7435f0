//! Where the two operands of a 2D Boolean come close: the boxes outside
//! which the result is made of untouched pieces of one operand's edges, far
//! from the other operand. Data smoothing after the Boolean (chapter 5,
//! Appendix A) looks only there (`smooth::smooth_polygon_set_near`), so
//! that it costs what the Boolean changed rather than the result's size;
//! the 2D counterpart of the 3D Boolean's contacts.
//!
//! The broad phase is the Boolean's own sort-and-sweep over edge boxes
//! (`fast.rs`), on A's boxes grown by the proximity on every side; a
//! conservative segment distance test then keeps the pairs that may come
//! within the proximity.

use crate::fast::{edge_boxes, overlapping_pairs, EdgeBox};
use crate::{validate, BooleanError, BooleanOp, BooleanOutput};
use rayon::prelude::*;
use robust_arith::{orient2d, Point2};
use std::cmp::Ordering;
use topology::{Operand, PolygonSet2};

/// The places where the operands of a 2D Boolean come within
/// [`PlanarContacts::proximity`] of each other.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct PlanarContacts {
    /// The distance asked for.
    pub proximity: f64,
    /// The exact bounding box (`[lo, hi]`) of every edge of either operand
    /// that may come within `proximity` of an edge of the other operand,
    /// grown by `proximity` on every side, in A's edge order then B's. A
    /// pair counts when their boxes come within `proximity` and the two
    /// segments meet (exact orientations) or an end point of one lies
    /// within `proximity` of the other by an `f64` distance with a slack
    /// for its rounding: a conservative test, never a pair that does come
    /// that close left out, and few that do not (a copy of a map scaled by
    /// `1 + 1e-7` comes within its tolerance near its crossings only,
    /// though nearly every edge box meets one of the copy's). Every point of either operand within
    /// `proximity` of the other operand, every intersection point, and so
    /// every vertex the Boolean created lies in one of them.
    pub boxes: Vec<[Point2; 2]>,
}

/// `x - d` rounded down and `x + d` rounded up (a box grown by `d` that
/// contains the exact one).
fn grow(lo: f64, hi: f64, d: f64) -> (f64, f64) {
    if d == 0.0 {
        return (lo, hi);
    }
    ((lo - d).next_down(), (hi + d).next_up())
}

/// The boxes of `set`'s edges of non-zero multiplicity, grown by `d` on
/// every side, sorted by `x0` (as the sweep needs): the Boolean's boxes
/// grown in place, which keeps them sorted (`x0 - d` rounded down never
/// decreases as `x0` grows).
fn grown_boxes(set: &PolygonSet2, d: f64) -> Vec<EdgeBox> {
    let mut boxes = edge_boxes(set, 0.0);
    for b in &mut boxes {
        (b.x0, b.x1) = grow(b.x0, b.x1, d);
        (b.y0, b.y1) = grow(b.y0, b.y1, d);
    }
    boxes
}

/// Candidate pairs above which the distance tests run on the rayon pool.
const PARALLEL_PAIRS: usize = 4096;

/// Whether segments `e` and `f` may come within `d` of each other: they
/// meet (exact orientations), or an end point of one lies within `d` of
/// the other segment by an `f64` distance with a rounding slack of
/// `64 eps` times the largest magnitude involved (two segments that do not
/// meet are closest at an end point of one of them). Conservative: never
/// false for segments that do come within `d`.
fn may_come_within(e: [Point2; 2], f: [Point2; 2], d: f64) -> bool {
    if segments_meet(e, f) {
        return true;
    }
    let size = e.iter().chain(&f).flatten().fold(d, |m, &x| m.max(x.abs()));
    let reach = d + 64.0 * f64::EPSILON * size;
    let reach2 = reach * reach;
    [(e[0], f), (e[1], f), (f[0], e), (f[1], e)]
        .iter()
        .any(|&(p, s)| point_segment_dist2(p, s) <= reach2)
}

/// Whether two closed segments share a point (exact `orient2d`).
fn segments_meet(e: [Point2; 2], f: [Point2; 2]) -> bool {
    use Ordering::Equal;
    let (o1, o2) = (orient2d(e[0], e[1], f[0]), orient2d(e[0], e[1], f[1]));
    let (o3, o4) = (orient2d(f[0], f[1], e[0]), orient2d(f[0], f[1], e[1]));
    let within = |p: Point2, s: [Point2; 2]| {
        (0..2).all(|k| s[0][k].min(s[1][k]) <= p[k] && p[k] <= s[0][k].max(s[1][k]))
    };
    let proper = o1 != o2 && o3 != o4 && [o1, o2, o3, o4].iter().all(|&o| o != Equal);
    proper
        || (o1 == Equal && within(f[0], e))
        || (o2 == Equal && within(f[1], e))
        || (o3 == Equal && within(e[0], f))
        || (o4 == Equal && within(e[1], f))
}

/// The squared `f64` distance from `p` to the segment `s`.
fn point_segment_dist2(p: Point2, s: [Point2; 2]) -> f64 {
    let d = [s[1][0] - s[0][0], s[1][1] - s[0][1]];
    let w = [p[0] - s[0][0], p[1] - s[0][1]];
    let len2 = d[0] * d[0] + d[1] * d[1];
    let t = if len2 > 0.0 {
        ((w[0] * d[0] + w[1] * d[1]) / len2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    let q = [w[0] - t * d[0], w[1] - t * d[1]];
    q[0] * q[0] + q[1] * q[1]
}

/// The contacts of two validated operands (no check of the proximity).
fn contacts_of(a: &PolygonSet2, b: &PolygonSet2, proximity: f64) -> PlanarContacts {
    let (boxes_a, boxes_b) = rayon::join(|| grown_boxes(a, proximity), || grown_boxes(b, 0.0));
    let pairs = overlapping_pairs(&boxes_a, &boxes_b);
    let close = |&(ia, ib): &(u32, u32)| {
        let (p, q) = a.edge_points(&a.edges()[ia as usize]);
        let (r, t) = b.edge_points(&b.edges()[ib as usize]);
        may_come_within([p, q], [r, t], proximity)
    };
    let close: Vec<(u32, u32)> = if pairs.len() >= PARALLEL_PAIRS {
        pairs.into_par_iter().filter(close).collect()
    } else {
        pairs.into_iter().filter(close).collect()
    };
    let mut near_a = vec![false; a.edge_count()];
    let mut near_b = vec![false; b.edge_count()];
    for (ia, ib) in close {
        near_a[ia as usize] = true;
        near_b[ib as usize] = true;
    }
    let boxes = [(a, &near_a), (b, &near_b)]
        .into_iter()
        .flat_map(|(set, near)| {
            set.edges()
                .iter()
                .zip(near.iter())
                .filter(|(_, &n)| n)
                .map(move |(e, _)| {
                    let (p, q) = set.edge_points(e);
                    let (x0, x1) = grow(p[0].min(q[0]), p[0].max(q[0]), proximity);
                    let (y0, y1) = grow(p[1].min(q[1]), p[1].max(q[1]), proximity);
                    [[x0, y0], [x1, y1]]
                })
        })
        .collect();
    PlanarContacts { proximity, boxes }
}

/// The proximity must be finite and not negative.
fn check_proximity(proximity: f64) -> Result<(), BooleanError> {
    if proximity.is_finite() && proximity >= 0.0 {
        Ok(())
    } else {
        Err(BooleanError::InvalidProximity(proximity))
    }
}

/// The places where `a` and `b` come within `proximity` (finite, not
/// negative) of each other ([`PlanarContacts`]). Both operands are
/// validated as [`crate::boolean`] validates them.
///
/// ```
/// use boolean_2d::planar_contacts;
/// use topology::PolygonSet2;
///
/// let mut a = PolygonSet2::new();
/// a.add_loop(&[[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]);
/// let mut b = PolygonSet2::new();
/// b.add_loop(&[[1.5, 0.0], [2.5, 0.0], [2.5, 1.0], [1.5, 1.0]]);
/// assert!(planar_contacts(&a, &b, 0.1).unwrap().boxes.is_empty());
/// // Within 0.5 the right side of `a` and the left side of `b` meet, and
/// // so do the top and bottom sides, whose boxes reach across the gap.
/// assert_eq!(planar_contacts(&a, &b, 0.5).unwrap().boxes.len(), 6);
/// ```
pub fn planar_contacts(
    a: &PolygonSet2,
    b: &PolygonSet2,
    proximity: f64,
) -> Result<PlanarContacts, BooleanError> {
    check_proximity(proximity)?;
    validate(a, Operand::A)?;
    validate(b, Operand::B)?;
    Ok(contacts_of(a, b, proximity))
}

/// [`crate::boolean`] and the operands' [`PlanarContacts`] at `proximity`
/// (finite, not negative), computed side by side: what smoothing near the
/// contacts needs.
pub fn boolean_with_contacts(
    a: &PolygonSet2,
    b: &PolygonSet2,
    op: BooleanOp,
    proximity: f64,
) -> Result<(BooleanOutput, PlanarContacts), BooleanError> {
    check_proximity(proximity)?;
    validate(a, Operand::A)?;
    validate(b, Operand::B)?;
    let (out, contacts) = rayon::join(|| crate::boolean(a, b, op), || contacts_of(a, b, proximity));
    Ok((out?, contacts))
}

#[cfg(test)]
mod tests {
    use super::*;
    use test_support::rng::SplitMix64;

    /// The distance from `p` to the segment `s`.
    fn point_segment(p: Point2, s: [Point2; 2]) -> f64 {
        let d = [s[1][0] - s[0][0], s[1][1] - s[0][1]];
        let len2 = d[0] * d[0] + d[1] * d[1];
        let t = if len2 > 0.0 {
            (((p[0] - s[0][0]) * d[0] + (p[1] - s[0][1]) * d[1]) / len2).clamp(0.0, 1.0)
        } else {
            0.0
        };
        let q = [s[0][0] + t * d[0], s[0][1] + t * d[1]];
        ((p[0] - q[0]).powi(2) + (p[1] - q[1]).powi(2)).sqrt()
    }

    fn segments(set: &PolygonSet2) -> Vec<[Point2; 2]> {
        set.edges()
            .iter()
            .map(|e| {
                let (p, q) = set.edge_points(e);
                [p, q]
            })
            .collect()
    }

    fn inside(p: Point2, b: &[Point2; 2]) -> bool {
        (0..2).all(|c| b[0][c] <= p[c] && p[c] <= b[1][c])
    }

    fn random_ring(rng: &mut SplitMix64, n: usize, scale: f64) -> Vec<Point2> {
        (0..n)
            .map(|_| {
                [
                    (rng.next_u64() % 1000) as f64 * scale,
                    (rng.next_u64() % 1000) as f64 * scale,
                ]
            })
            .collect()
    }

    /// Against brute force on random polygons: every vertex of one operand
    /// within the proximity of an edge of the other, and every crossing
    /// the Boolean computed, lies in a contact box; every edge within the
    /// proximity of the other operand has a box, and no edge whose grown
    /// box meets none of the other's.
    #[test]
    fn contacts_cover_every_close_point_and_only_close_edges() {
        let mut rng = SplitMix64::new(5);
        let (mut total_close, mut total_boxes, mut total_by_box) = (0, 0, 0);
        for round in 0..200 {
            let (mut a, mut b) = (PolygonSet2::new(), PolygonSet2::new());
            a.add_loop(&random_ring(&mut rng, 3 + round % 7, 1e-3));
            b.add_loop(&random_ring(&mut rng, 3 + round % 5, 1e-3));
            let d = [0.0, 1e-3, 0.05][round % 3];
            let c = planar_contacts(&a, &b, d).unwrap();
            let (sa, sb) = (segments(&a), segments(&b));
            for (own, other) in [(&a, &sb), (&b, &sa)] {
                for &p in own.vertices() {
                    if other.iter().any(|&s| point_segment(p, s) <= d) {
                        assert!(
                            c.boxes.iter().any(|bx| inside(p, bx)),
                            "round {round}: {p:?} within {d} of the other operand"
                        );
                    }
                }
            }
            let out = crate::boolean(&a, &b, BooleanOp::Union).unwrap();
            let old: Vec<Point2> = a.vertices().iter().chain(b.vertices()).copied().collect();
            for &p in out.shape.vertices().iter().filter(|p| !old.contains(p)) {
                assert!(
                    c.boxes.iter().any(|bx| inside(p, bx)),
                    "round {round}: {p:?}"
                );
            }
            // Box count: at least every edge that does come within the
            // distance of the other operand (segments crossing by exact
            // orientations, else the end-point distances, a hair inside
            // the distance), at most every edge whose grown box meets a
            // box of the other.
            let crossing = |s: &[Point2; 2], t: &[Point2; 2]| {
                let o = |a, b, c| test_support::exact::orient(a, b, c);
                o(s[0], s[1], t[0]) * o(s[0], s[1], t[1]) < 0
                    && o(t[0], t[1], s[0]) * o(t[0], t[1], s[1]) < 0
            };
            let within = |s: &[Point2; 2], t: &[Point2; 2]| {
                crossing(s, t)
                    || [(s[0], t), (s[1], t), (t[0], s), (t[1], s)]
                        .iter()
                        .any(|&(p, seg)| point_segment(p, *seg) <= d * (1.0 - 1e-9))
            };
            let close = sa
                .iter()
                .filter(|s| sb.iter().any(|t| within(s, t)))
                .count()
                + sb.iter()
                    .filter(|t| sa.iter().any(|s| within(s, t)))
                    .count();
            let boxes = |s: &[Point2; 2], g: f64| {
                [
                    [s[0][0].min(s[1][0]) - g, s[0][1].min(s[1][1]) - g],
                    [s[0][0].max(s[1][0]) + g, s[0][1].max(s[1][1]) + g],
                ]
            };
            let meets = |x: [Point2; 2], y: [Point2; 2]| {
                (0..2).all(|k| x[0][k] <= y[1][k] && y[0][k] <= x[1][k])
            };
            let by_box = sa
                .iter()
                .filter(|s| sb.iter().any(|t| meets(boxes(s, d), boxes(t, 0.0))))
                .count()
                + sb.iter()
                    .filter(|t| sa.iter().any(|s| meets(boxes(s, d), boxes(t, 0.0))))
                    .count();
            assert!(
                c.boxes.len() >= close,
                "round {round}: {} < {close}",
                c.boxes.len()
            );
            // Grown boxes round outwards, so a pair exactly at the
            // distance may count in the crate and not here.
            assert!(c.boxes.len() <= by_box + 2, "round {round}");
            total_close += close;
            total_boxes += c.boxes.len();
            total_by_box += by_box;
            assert!(c.boxes.len() <= sa.len() + sb.len(), "round {round}");
        }
        // The distance test keeps fewer edges than the boxes alone.
        assert!(total_close > 0 && total_boxes < total_by_box);
    }

    #[test]
    fn a_bad_proximity_or_operand_is_refused() {
        let mut a = PolygonSet2::new();
        a.add_loop(&[[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]);
        for p in [f64::NAN, -1.0, f64::INFINITY] {
            assert!(matches!(
                planar_contacts(&a, &a, p),
                Err(BooleanError::InvalidProximity(_))
            ));
            assert!(boolean_with_contacts(&a, &a, BooleanOp::Union, p).is_err());
        }
        let mut bad = PolygonSet2::new();
        bad.add_loop(&[[0.0, 0.0], [f64::NAN, 0.0], [0.0, 1.0]]);
        assert!(matches!(
            planar_contacts(&a, &bad, 1.0),
            Err(BooleanError::InvalidInput {
                operand: Operand::B,
                ..
            })
        ));
        let mut open = PolygonSet2::new();
        let v = open.add_vertex([0.0, 0.0]);
        let w = open.add_vertex([1.0, 0.0]);
        open.add_edge(v, w);
        assert!(boolean_with_contacts(&open, &a, BooleanOp::Union, 1.0).is_err());
    }

    /// The Boolean beside the contacts is the Boolean alone.
    #[test]
    fn the_boolean_beside_the_contacts_is_the_boolean() {
        let mut rng = SplitMix64::new(9);
        for _ in 0..30 {
            let (mut a, mut b) = (PolygonSet2::new(), PolygonSet2::new());
            a.add_loop(&random_ring(&mut rng, 9, 1.0));
            b.add_loop(&random_ring(&mut rng, 7, 1.0));
            let (out, c) = boolean_with_contacts(&a, &b, BooleanOp::Difference, 2.0).unwrap();
            assert_eq!(
                out.shape,
                crate::boolean(&a, &b, BooleanOp::Difference).unwrap().shape
            );
            assert_eq!(c, planar_contacts(&a, &b, 2.0).unwrap());
        }
    }
}
