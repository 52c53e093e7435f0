//! The plane a facet is triangulated in (section 4.8, step 2 of
//! `triangulate`): the coordinate plane most perpendicular to the facet's
//! Newell normal, mirrored so that the facet's outer loops run
//! anticlockwise, with coordinates taken relative to one of its vertices
//! for accuracy.
//!
//! The triangle-mesh Boolean's fast path for a facet that is one triangle
//! (`boolean-3d`'s `retriangulate`) must give the triangle
//! [`triangulate_facet`](super::triangulate_facet) would give, bit for
//! bit; both take the plane from here, so the choice of plane and every
//! projected coordinate are the same computation.

use robust_arith::Point3;

/// A facet's projection plane: the origin vertex's position and the two
/// coordinate axes kept, in the order that makes the facet's outer loops
/// anticlockwise.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FacetProjection {
    origin: Point3,
    u: usize,
    v: usize,
}

impl FacetProjection {
    /// The plane of the facet bounded by `half_edges` (vertex ids into
    /// `positions`), relative to `positions[origin]`. The Newell normal is
    /// summed over the half-edges in the order given (facet boundary
    /// closure makes it the sum over the facet's loops); its largest
    /// component names the axis dropped, ties going to the later axis, and
    /// a negative one mirrors the plane. Half-edges or an origin beyond
    /// `positions` are skipped (the origin then counts as `[0, 0, 0]`):
    /// the callers check the facet first.
    #[inline]
    pub fn new(positions: &[Point3], half_edges: &[(u32, u32)], origin: u32) -> Self {
        let origin = positions.get(origin as usize).copied().unwrap_or([0.0; 3]);
        let rel = |p: Point3| [p[0] - origin[0], p[1] - origin[1], p[2] - origin[2]];
        let mut n = [0.0f64; 3];
        for &(s, e) in half_edges {
            let (Some(&p), Some(&q)) = (positions.get(s as usize), positions.get(e as usize))
            else {
                continue;
            };
            let (p, q) = (rel(p), rel(q));
            n[0] += (p[1] - q[1]) * (p[2] + q[2]);
            n[1] += (p[2] - q[2]) * (p[0] + q[0]);
            n[2] += (p[0] - q[0]) * (p[1] + q[1]);
        }
        let axis = if n[0].abs() > n[1].abs() && n[0].abs() > n[2].abs() {
            0
        } else if n[1].abs() > n[2].abs() {
            1
        } else {
            2
        };
        let (u, v) = match axis {
            0 => (1, 2),
            1 => (2, 0),
            _ => (0, 1),
        };
        let (u, v) = if n[axis] < 0.0 { (v, u) } else { (u, v) };
        FacetProjection { origin, u, v }
    }

    /// `p` in the plane: its coordinates relative to the origin, on the
    /// two axes kept.
    #[inline]
    pub fn project(&self, p: Point3) -> [f64; 2] {
        let o = self.origin;
        let rel = [p[0] - o[0], p[1] - o[1], p[2] - o[2]];
        [rel[self.u], rel[self.v]]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_square_projects_anticlockwise_whichever_way_it_faces() {
        // The unit square in the plane y = 2, once each way round: the
        // normal is along y, so x and z are kept, mirrored for the
        // reversed square.
        let p: Vec<Point3> = vec![
            [0.0, 2.0, 0.0],
            [0.0, 2.0, 1.0],
            [1.0, 2.0, 1.0],
            [1.0, 2.0, 0.0],
        ];
        let ring = [(0, 1), (1, 2), (2, 3), (3, 0)];
        let back: Vec<(u32, u32)> = ring.iter().map(|&(s, e)| (e, s)).collect();
        for hes in [&ring[..], &back[..]] {
            let proj = FacetProjection::new(&p, hes, 0);
            let area: f64 = hes
                .iter()
                .map(|&(s, e)| {
                    let (a, b) = (proj.project(p[s as usize]), proj.project(p[e as usize]));
                    a[0] * b[1] - a[1] * b[0]
                })
                .sum();
            assert_eq!(area, 2.0, "{hes:?}");
            assert_eq!(proj.project(p[0]), [0.0, 0.0]);
        }
    }

    #[test]
    fn out_of_range_ids_are_skipped_not_a_panic() {
        let p: Vec<Point3> = vec![[0.0; 3], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]];
        let proj = FacetProjection::new(&p, &[(0, 1), (1, 9), (9, 2), (2, 0)], 7);
        assert!(proj.project([1.0, 1.0, 1.0]).iter().all(|c| c.is_finite()));
    }
}
