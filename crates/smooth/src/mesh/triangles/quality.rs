//! The re-triangulation of one smoothed facet that is a single simple
//! loop: among all triangulations by internal edges (section 4.8), the
//! one that folds least, then leaves the fewest internal edges that a
//! second smoothing would crack, then is shortest. Ear clipping picks
//! ears greedily in a coordinate projection, so on a cut cap whose
//! straight edges carry vertices that cracking put there it clips the
//! zero-area ear across such a vertex: a triangle folded by rounding (an
//! intersecting pair for the exact test) whose internal edge passes
//! within `delta` of the vertex (cracked again by a second run). Here
//! every candidate triangle is judged in the facet's best-fit plane.

use crate::mesh::geom::{dist2, point_segment};
use crate::mesh::plane::best_fit_plane;
use topology::{HalfEdge, Point3};

/// Facets of at most this many vertices are triangulated here (`O(n^3)`
/// time, `O(n^2)` memory); larger ones keep ear clipping.
pub(crate) const MAX_VERTICES: usize = 160;

/// Whether the segment `a b` passes within `delta` of `p` inside its
/// interior, with both parts shorter than it: the condition under which
/// edge cracking by vertex splits `a b` at `p` (`crack_by_vertex`).
pub(crate) fn crackable(p: Point3, a: Point3, b: Point3, delta: f64) -> bool {
    let l2 = dist2(a, b);
    let (t, d2) = point_segment(p, a, b);
    t > 0.0 && t < 1.0 && d2 <= delta * delta && dist2(a, p) < l2 && dist2(p, b) < l2
}

/// The facet's vertices in loop order when its half-edges form one
/// closed loop through distinct vertices, else `None`.
fn single_loop(boundary: &[HalfEdge]) -> Option<Vec<u32>> {
    let n = boundary.len();
    let mut by_start: Vec<(u32, u32)> = boundary.iter().map(|h| (h.start, h.end)).collect();
    by_start.sort_unstable();
    if by_start.windows(2).any(|w| w[0].0 == w[1].0) {
        return None; // a vertex the facet passes twice
    }
    let mut ring = Vec::with_capacity(n);
    let first = boundary[0].start;
    let mut at = first;
    for _ in 0..n {
        ring.push(at);
        let k = by_start.binary_search_by_key(&at, |e| e.0).ok()?;
        at = by_start[k].1;
        if at == first {
            break;
        }
    }
    (at == first && ring.len() == n).then_some(ring)
}

/// The cost of a (partial) triangulation, compared lexicographically:
/// twice the area of its triangles facing against the facet in its
/// best-fit plane (the fold), the number of its internal edges a second
/// run would crack, the total length of its internal edges.
#[derive(Clone, Copy, PartialEq, PartialOrd)]
struct Cost(f64, u32, f64);

impl std::ops::Add for Cost {
    type Output = Cost;
    fn add(self, o: Cost) -> Cost {
        Cost(self.0 + o.0, self.1 + o.1, self.2 + o.2)
    }
}

/// Triangulates the facet with half-edges `boundary` into `out` when it
/// is one simple loop of 4 to [`MAX_VERTICES`] vertices with a best-fit
/// plane; returns whether it did (otherwise `out` is untouched).
///
/// The result is a triangulation by internal edges of the loop, so its
/// half-edges are the facet's plus both half-edges of every internal
/// edge (closure holds whatever the geometry). Of all such
/// triangulations (the classic recurrence over sub-polygons: every
/// internal edge splits a polygon in two) it minimises, in this order:
/// the total area of triangles facing against the facet in its best-fit
/// plane (for a facet whose projection is simple that is zero: no fold;
/// otherwise the invalid region is extended least, as section 4.8 asks);
/// the number of internal edges passing within `delta` of a vertex of
/// the facet (`crackable`); their total length (the minimum-weight
/// triangulation, which favours short internal edges). A NaN fold
/// (coordinates whose products overflow) counts as infinite; the result
/// is always complete.
pub(crate) fn triangulate_loop(
    pos: &[Point3],
    boundary: &[HalfEdge],
    delta: f64,
    out: &mut Vec<[u32; 3]>,
) -> bool {
    let n = boundary.len();
    if !(4..=MAX_VERTICES).contains(&n) {
        return false;
    }
    let Some(ring) = single_loop(boundary) else {
        return false;
    };
    let Some(plane) = best_fit_plane(pos, boundary) else {
        return false;
    };
    let p3: Vec<Point3> = ring.iter().map(|&v| pos[v as usize]).collect();
    let p2: Vec<[f64; 2]> = p3.iter().map(|&p| plane.project(p)).collect();
    // The cost of the internal edge i-j (i < j, not a loop edge).
    let chord = |i: usize, j: usize| {
        let bad = (0..n).any(|k| k != i && k != j && crackable(p3[k], p3[i], p3[j], delta));
        Cost(0.0, u32::from(bad), dist2(p3[i], p3[j]).sqrt())
    };
    let mut chords = vec![Cost(0.0, 0, 0.0); n * n];
    for i in 0..n {
        for j in i + 2..n {
            if !(i == 0 && j == n - 1) {
                chords[i * n + j] = chord(i, j);
            }
        }
    }
    let fold = |i: usize, k: usize, j: usize| {
        let (a, b, c) = (p2[i], p2[k], p2[j]);
        let o = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
        // A NaN (products of huge coordinates overflowing) never wins.
        let folded = if o.is_nan() {
            f64::INFINITY
        } else if o < 0.0 {
            -o
        } else {
            0.0
        };
        Cost(folded, 0, 0.0)
    };
    let mut cost = vec![Cost(0.0, 0, 0.0); n * n];
    let mut split = vec![0u32; n * n];
    for len in 2..n {
        for i in 0..n - len {
            let j = i + len;
            let mut best: Option<(Cost, usize)> = None;
            for k in i + 1..j {
                let c = cost[i * n + k]
                    + cost[k * n + j]
                    + chords[i * n + k]
                    + chords[k * n + j]
                    + fold(i, k, j);
                let better = match best {
                    None => true,
                    Some((b, _)) => c < b,
                };
                if better {
                    best = Some((c, k));
                }
            }
            let (c, k) = best.unwrap_or((Cost(f64::INFINITY, 0, 0.0), i + 1));
            cost[i * n + j] = c;
            split[i * n + j] = k as u32;
        }
    }
    let mut stack = vec![(0, n - 1)];
    while let Some((i, j)) = stack.pop() {
        if j - i >= 2 {
            let k = split[i * n + j] as usize;
            out.push([ring[i], ring[k], ring[j]]);
            stack.push((k, j));
            stack.push((i, k));
        }
    }
    true
}

#[cfg(test)]
mod tests {
    use super::*;

    fn loop_of(ids: &[u32]) -> Vec<HalfEdge> {
        (0..ids.len())
            .map(|i| HalfEdge {
                start: ids[i],
                end: ids[(i + 1) % ids.len()],
            })
            .collect()
    }

    #[test]
    fn collinear_vertices_on_a_cap_get_no_sliver() {
        // A square whose bottom edge carries two vertices cracking put
        // there: ear clipping may clip (0 1 2) across vertex 1, a zero-area
        // triangle; here every triangle has positive area and no internal
        // edge passes near a vertex.
        let pos = [
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [2.0, 0.0, 0.0],
            [3.0, 0.0, 0.0],
            [3.0, 3.0, 0.0],
            [0.0, 3.0, 0.0],
        ];
        let mut out = Vec::new();
        assert!(triangulate_loop(
            &pos,
            &loop_of(&[0, 1, 2, 3, 4, 5]),
            1e-9,
            &mut out
        ));
        assert_eq!(out.len(), 4);
        for t in &out {
            let [a, b, c] = t.map(|v| pos[v as usize]);
            let o = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
            assert!(o > 0.0, "{out:?}");
        }
    }

    #[test]
    fn a_vertex_off_a_chord_by_less_than_delta_is_avoided() {
        // Vertex 2 lies 1e-7 inside the chord 1-3; with delta = 1e-6 the
        // chord is crackable, so the triangulation avoids it (the fan
        // from 0 uses 0-2 instead).
        let pos = [
            [0.0, -5.0, 0.0],
            [-1.0, 0.0, 0.0],
            [0.0, 1e-7, 0.0],
            [1.0, 0.0, 0.0],
        ];
        let mut out = Vec::new();
        assert!(triangulate_loop(
            &pos,
            &loop_of(&[0, 3, 2, 1]),
            1e-6,
            &mut out
        ));
        assert_eq!(out.len(), 2);
        assert!(
            out.iter().all(|t| t.contains(&0) && t.contains(&2)),
            "{out:?}"
        );
    }

    #[test]
    fn non_simple_loops_and_repeated_vertices_are_left_to_ear_clipping() {
        let pos = [[0.0; 3], [1.0, 0.0, 0.0], [1.0, 1.0, 0.0], [0.0, 1.0, 0.0]];
        let mut out = Vec::new();
        // Two loops (a triangle twice over is not one loop of six).
        let mut two = loop_of(&[0, 1, 2]);
        two.extend(loop_of(&[0, 2, 3]));
        assert!(!triangulate_loop(&pos, &two, 1e-9, &mut out));
        // A triangle: nothing to choose.
        assert!(!triangulate_loop(
            &pos,
            &loop_of(&[0, 1, 2]),
            1e-9,
            &mut out
        ));
        // Zero area: no plane.
        let line = [[0.0; 3], [1.0, 0.0, 0.0], [2.0, 0.0, 0.0], [3.0, 0.0, 0.0]];
        assert!(!triangulate_loop(
            &line,
            &loop_of(&[0, 1, 2, 3]),
            1e-9,
            &mut out
        ));
        assert!(out.is_empty());
    }

    /// A convex polygon of `corners` (angles on a circle of radius `r`)
    /// with `extra[e]` fractions of a point inserted on edge `e` (points a
    /// cracking would put there), embedded in the plane spanned by `e1`,
    /// `e2` through `o`: positions and the loop's half-edges.
    fn cap(
        angles: &[f64],
        extra: &[Vec<f64>],
        r: f64,
        o: Point3,
        e1: Point3,
        e2: Point3,
    ) -> (Vec<Point3>, Vec<HalfEdge>) {
        let at = |x: f64, y: f64| {
            [
                o[0] + x * e1[0] + y * e2[0],
                o[1] + x * e1[1] + y * e2[1],
                o[2] + x * e1[2] + y * e2[2],
            ]
        };
        let k = angles.len();
        let mut pos = Vec::new();
        for i in 0..k {
            let (a, b) = (angles[i], angles[(i + 1) % k]);
            let (ax, ay) = (r * a.cos(), r * a.sin());
            let (bx, by) = (r * b.cos(), r * b.sin());
            pos.push(at(ax, ay));
            for &t in &extra[i] {
                pos.push(at(ax + t * (bx - ax), ay + t * (by - ay)));
            }
        }
        let ids: Vec<u32> = (0..pos.len() as u32).collect();
        (pos, loop_of(&ids))
    }

    proptest::proptest! {
        #![proptest_config(proptest::test_runner::Config::with_cases(test_support::cases(256)))]

        #[test]
        fn cut_caps_triangulate_without_folds_or_crackable_edges(
            gaps in proptest::collection::vec(0.3f64..1.5, 3..8),
            extra in proptest::collection::vec(
                proptest::collection::btree_set(1u32..20, 0..4), 8),
            r in 0.5f64..200.0,
            o in proptest::array::uniform3(-100.0f64..100.0),
            dir in proptest::array::uniform3(-1.0f64..1.0),
        ) {
            // Corner angles (the gaps scaled to a full turn: convex).
            let total: f64 = gaps.iter().sum();
            let mut angles = Vec::new();
            let mut a = 0.0;
            for g in &gaps {
                angles.push(a);
                a += g / total * std::f64::consts::TAU;
            }
            let extra: Vec<Vec<f64>> = extra
                .iter()
                .map(|s| s.iter().map(|&i| f64::from(i) / 20.0).collect())
                .collect();
            // An orthonormal pair spanning a random plane.
            let n = dir;
            let len = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
            proptest::prop_assume!(len > 0.1);
            let n = n.map(|x| x / len);
            let t = if n[0].abs() < 0.5 { [1.0, 0.0, 0.0] } else { [0.0, 1.0, 0.0] };
            let e1 = crate::mesh::geom::cross(t, n);
            let l1 = crate::mesh::geom::dot(e1, e1).sqrt();
            let e1 = e1.map(|x| x / l1);
            let e2 = crate::mesh::geom::cross(n, e1);
            let (pos, boundary) = cap(&angles, &extra, r, o, e1, e2);
            let delta = 1e-9 * r;
            let mut out = Vec::new();
            proptest::prop_assert!(triangulate_loop(&pos, &boundary, delta, &mut out)
                || pos.len() == 3);
            if pos.len() == 3 {
                return Ok(());
            }
            proptest::prop_assert_eq!(out.len(), pos.len() - 2);
            // Closure: the triangles' half-edges are the loop's plus both
            // half-edges of every internal edge.
            let mut balance = std::collections::HashMap::new();
            for t in &out {
                for k in 0..3 {
                    *balance.entry((t[k], t[(k + 1) % 3])).or_insert(0i32) += 1;
                }
            }
            for h in &boundary {
                *balance.entry((h.start, h.end)).or_insert(0) -= 1;
            }
            for (&(a, b), &c) in &balance {
                let back = balance.get(&(b, a)).copied().unwrap_or(0);
                proptest::prop_assert!(c == 0 || (c == 1 && back == 1),
                    "unbalanced {a}->{b}");
            }
            // No fold: every triangle faces the facet's way in 3D.
            for t in &out {
                let [a, b, c] = t.map(|v| pos[v as usize]);
                let m = crate::mesh::geom::cross(
                    crate::mesh::geom::sub(b, a),
                    crate::mesh::geom::sub(c, a),
                );
                proptest::prop_assert!(crate::mesh::geom::dot(m, n) > 0.0, "fold {t:?}");
            }
            // No internal edge a second smoothing would crack.
            for t in &out {
                for k in 0..3 {
                    let (a, b) = (t[k], t[(k + 1) % 3]);
                    for w in 0..pos.len() as u32 {
                        if w != a && w != b {
                            proptest::prop_assert!(
                                !crackable(pos[w as usize], pos[a as usize], pos[b as usize], delta),
                                "edge {a}-{b} passes {w}"
                            );
                        }
                    }
                }
            }
        }
    }

    proptest::proptest! {
        #![proptest_config(proptest::test_runner::Config::with_cases(test_support::cases(256)))]

        #[test]
        fn garbage_loops_triangulate_completely_and_closed(
            pts in proptest::collection::vec(
                proptest::array::uniform3(proptest::prop_oneof![
                    proptest::strategy::Just(0.0f64), proptest::strategy::Just(1.0), -1e3f64..1e3, -1e-9f64..1e-9
                ]), 4..40),
            delta in proptest::prop_oneof![proptest::strategy::Just(0.0f64), 1e-12f64..1.0],
        ) {
            let ids: Vec<u32> = (0..pts.len() as u32).collect();
            let boundary = loop_of(&ids);
            let mut out = Vec::new();
            if !triangulate_loop(&pts, &boundary, delta, &mut out) {
                proptest::prop_assert!(out.is_empty());
                return Ok(());
            }
            proptest::prop_assert_eq!(out.len(), pts.len() - 2);
            let mut balance = std::collections::HashMap::new();
            for t in &out {
                proptest::prop_assert!(t[0] != t[1] && t[1] != t[2] && t[2] != t[0]);
                for k in 0..3 {
                    *balance.entry((t[k], t[(k + 1) % 3])).or_insert(0i32) += 1;
                }
            }
            for h in &boundary {
                *balance.entry((h.start, h.end)).or_insert(0) -= 1;
            }
            for (&(a, b), &c) in &balance {
                let back = balance.get(&(b, a)).copied().unwrap_or(0);
                proptest::prop_assert!(c == 0 || (c == 1 && back == 1), "unbalanced {a}->{b}");
            }
        }
    }
}
