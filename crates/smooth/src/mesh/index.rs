//! Broad phases of 3D smoothing: R*-trees (the `rstar` crate, bulk
//! loaded) over points and over boxes grown by the tolerance, so that
//! vertex-near-edge, edge-near-edge and facet-pair candidates are found in
//! O(log n + hits) each, never by testing all pairs. A grid would not do:
//! one long edge would cover many cells.

use rstar::{RTree, RTreeObject, AABB};
use topology::Point3;

/// A box with an id.
pub(crate) struct IdBox {
    pub lo: Point3,
    pub hi: Point3,
    pub id: u32,
}

impl RTreeObject for IdBox {
    type Envelope = AABB<Point3>;
    fn envelope(&self) -> Self::Envelope {
        AABB::from_corners(self.lo, self.hi)
    }
}

/// The box of `points` grown by `margin` on every side.
pub(crate) fn grown_box(points: impl IntoIterator<Item = Point3>, margin: f64) -> (Point3, Point3) {
    let mut lo = [f64::INFINITY; 3];
    let mut hi = [f64::NEG_INFINITY; 3];
    for p in points {
        for k in 0..3 {
            lo[k] = lo[k].min(p[k]);
            hi[k] = hi[k].max(p[k]);
        }
    }
    for k in 0..3 {
        lo[k] -= margin;
        hi[k] += margin;
    }
    (lo, hi)
}

/// Boxes, queried by box intersection.
pub(crate) struct BoxIndex(RTree<IdBox>);

impl BoxIndex {
    pub fn new(boxes: Vec<IdBox>) -> BoxIndex {
        BoxIndex(RTree::bulk_load(boxes))
    }

    /// The ids of the boxes meeting `[lo, hi]` (closed), sorted.
    pub fn meeting(&self, lo: Point3, hi: Point3) -> Vec<u32> {
        let mut ids: Vec<u32> = self
            .0
            .locate_in_envelope_intersecting(&AABB::from_corners(lo, hi))
            .map(|b| b.id)
            .collect();
        ids.sort_unstable();
        ids
    }
}

/// Points with ids, queried by box containment.
pub(crate) struct PointIndex(RTree<rstar::primitives::GeomWithData<Point3, u32>>);

impl PointIndex {
    pub fn new(points: impl IntoIterator<Item = (Point3, u32)>) -> PointIndex {
        PointIndex(RTree::bulk_load(
            points
                .into_iter()
                .map(|(p, id)| rstar::primitives::GeomWithData::new(p, id))
                .collect(),
        ))
    }

    /// The ids of the points in `[lo, hi]` (closed), sorted.
    pub fn inside(&self, lo: Point3, hi: Point3) -> Vec<u32> {
        let mut ids: Vec<u32> = self
            .0
            .locate_in_envelope(&AABB::from_corners(lo, hi))
            .map(|p| p.data)
            .collect();
        ids.sort_unstable();
        ids
    }
}
