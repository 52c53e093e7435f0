//! The best-fit plane of a facet (Appendix A, footnote 1): the normal is
//! the direction that maximises the facet's apparent area, which is the
//! direction of Newell's normal (the vector area of the facet, computed
//! from its half-edges, so holes and several loops count with their
//! orientation), and the plane passes through the mid-point (mean) of the
//! facet's vertices. Interior tests project onto that plane.

use crate::mesh::geom::{cross, dot, sub};
use topology::{HalfEdge, Point3};

/// A facet's plane with an orthonormal basis `(u, v)` of it such that
/// `u x v = normal`: the facet's outer loops run anticlockwise in
/// `(u, v)`.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Plane {
    pub normal: Point3,
    pub point: Point3,
    u: Point3,
    v: Point3,
}

fn unit(a: Point3) -> Option<Point3> {
    let n = dot(a, a).sqrt();
    if n > 0.0 && n.is_finite() {
        Some([a[0] / n, a[1] / n, a[2] / n])
    } else {
        None
    }
}

/// The unit Newell normal of the facet with the given half-edges (relative
/// to its first vertex, for accuracy), `None` when its vector area is zero
/// (no direction maximises the apparent area uniquely: the facet has no
/// side to face).
pub(crate) fn facet_normal(pos: &[Point3], half_edges: &[HalfEdge]) -> Option<Point3> {
    let first = half_edges.first()?;
    let o = pos[first.start as usize];
    let mut n = [0.0f64; 3];
    for h in half_edges {
        let p = sub(pos[h.start as usize], o);
        let q = sub(pos[h.end as usize], o);
        n[0] += (p[1] - q[1]) * (p[2] + q[2]);
        n[1] += (p[2] - q[2]) * (p[0] + q[0]);
        n[2] += (p[0] - q[0]) * (p[1] + q[1]);
    }
    unit(n)
}

/// The best-fit plane of the facet with the given half-edges, `None` when
/// its vector area is zero ([`facet_normal`]).
pub(crate) fn best_fit_plane(pos: &[Point3], half_edges: &[HalfEdge]) -> Option<Plane> {
    let normal = facet_normal(pos, half_edges)?;
    let o = pos[half_edges[0].start as usize];
    let mut vs: Vec<u32> = half_edges.iter().map(|h| h.start).collect();
    vs.sort_unstable();
    vs.dedup();
    let mut c = [0.0f64; 3];
    for &v in &vs {
        let p = sub(pos[v as usize], o);
        for k in 0..3 {
            c[k] += p[k];
        }
    }
    let m = vs.len() as f64;
    let point = [o[0] + c[0] / m, o[1] + c[1] / m, o[2] + c[2] / m];
    // The axis least aligned with the normal gives a well-conditioned u.
    let a = normal.map(f64::abs);
    let axis = if a[0] <= a[1] && a[0] <= a[2] {
        [1.0, 0.0, 0.0]
    } else if a[1] <= a[2] {
        [0.0, 1.0, 0.0]
    } else {
        [0.0, 0.0, 1.0]
    };
    let u = unit(cross(axis, normal))?;
    let v = cross(normal, u);
    Some(Plane {
        normal,
        point,
        u,
        v,
    })
}

impl Plane {
    /// The signed distance of `p` from the plane.
    pub fn distance(&self, p: Point3) -> f64 {
        dot(self.normal, sub(p, self.point))
    }

    /// `p` in the plane's coordinates.
    pub fn project(&self, p: Point3) -> [f64; 2] {
        let d = sub(p, self.point);
        [dot(d, self.u), dot(d, self.v)]
    }

    /// The winding number of the facet's half-edges around `q` (projected
    /// onto this plane): 1 inside a region of a facet facing this plane's
    /// way, 0 outside, -1 inside a hole or an inside-out region.
    pub fn winding(&self, pos: &[Point3], half_edges: &[HalfEdge], q: Point3) -> i64 {
        let q = self.project(q);
        let mut w = 0;
        for h in half_edges {
            let a = self.project(pos[h.start as usize]);
            let b = self.project(pos[h.end as usize]);
            let side = (b[0] - a[0]) * (q[1] - a[1]) - (q[0] - a[0]) * (b[1] - a[1]);
            if a[1] <= q[1] {
                if b[1] > q[1] && side > 0.0 {
                    w += 1;
                }
            } else if b[1] <= q[1] && side < 0.0 {
                w -= 1;
            }
        }
        w
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn square_plane_and_winding() {
        let pos = [
            [0.0, 0.0, 1.0],
            [2.0, 0.0, 1.0],
            [2.0, 2.0, 1.0],
            [0.0, 2.0, 1.0],
        ];
        let hs: Vec<HalfEdge> = (0..4)
            .map(|i| HalfEdge {
                start: i,
                end: (i + 1) % 4,
            })
            .collect();
        let p = best_fit_plane(&pos, &hs).unwrap();
        assert_eq!(p.normal, [0.0, 0.0, 1.0]);
        assert_eq!(p.point, [1.0, 1.0, 1.0]);
        assert_eq!(p.distance([5.0, 5.0, 3.0]), 2.0);
        assert_eq!(p.winding(&pos, &hs, [1.0, 1.0, 1.0]), 1);
        assert_eq!(p.winding(&pos, &hs, [3.0, 1.0, 1.0]), 0);
        let rev: Vec<HalfEdge> = hs
            .iter()
            .map(|h| HalfEdge {
                start: h.end,
                end: h.start,
            })
            .collect();
        let q = best_fit_plane(&pos, &rev).unwrap();
        assert_eq!(q.normal, [0.0, 0.0, -1.0]);
        assert_eq!(q.winding(&pos, &rev, [1.0, 1.0, 1.0]), 1);
        assert_eq!(p.winding(&pos, &rev, [1.0, 1.0, 1.0]), -1);
    }

    #[test]
    fn zero_area_facet_has_no_plane() {
        let pos = [[0.0; 3], [1.0, 0.0, 0.0]];
        let hs = [HalfEdge { start: 0, end: 1 }, HalfEdge { start: 1, end: 0 }];
        assert!(best_fit_plane(&pos, &hs).is_none());
    }
}
