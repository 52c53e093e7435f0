//! Conversions between [`PolygonSet2`] and `geo_types::MultiPolygon<f64>`,
//! with the ring conventions of [`crate::RingOrientation`].

use super::rings::{build_set, layout_polygons, strip_closing, validate_polygons, Polygons};
use crate::{RingOrientation, UmbraError};
use geo_types::{Coord, LineString, MultiPolygon, Polygon};
use robust_arith::Point2;
use topology::PolygonSet2;

/// A `geo-types` multipolygon of a topologically valid set, in the by-role
/// layout (outer rings counter-clockwise, holes clockwise inside the
/// smallest outer ring containing them; see [`crate::layout_polygons`]).
///
/// ```
/// use umbra::{from_geo, to_geo, PolygonSet2, RingOrientation};
/// let mut s = PolygonSet2::new();
/// s.add_loop(&[[0.0, 0.0], [3.0, 0.0], [3.0, 3.0], [0.0, 3.0]]);
/// s.add_loop(&[[1.0, 1.0], [1.0, 2.0], [2.0, 2.0], [2.0, 1.0]]);
/// let mp = to_geo(&s).unwrap();
/// assert_eq!(mp.0.len(), 1);
/// assert_eq!(mp.0[0].interiors().len(), 1);
/// let back = from_geo(&mp, RingOrientation::ByRole).unwrap();
/// assert_eq!(back.signed_area(), 8.0);
/// ```
pub fn to_geo(set: &PolygonSet2) -> Result<MultiPolygon<f64>, UmbraError> {
    let layout = layout_polygons(set, RingOrientation::ByRole, "<geo-types>")?;
    let ring = |r: &Vec<Point2>| -> LineString<f64> {
        r.iter()
            .chain(r.first())
            .map(|p| Coord { x: p[0], y: p[1] })
            .collect()
    };
    Ok(MultiPolygon(
        layout
            .polygons
            .iter()
            .map(|poly| {
                let mut rings = poly.iter().map(ring);
                let exterior = rings.next().unwrap_or_else(|| LineString(Vec::new()));
                Polygon::new(exterior, rings.collect())
            })
            .collect(),
    ))
}

/// A polygon set from a `geo-types` multipolygon: the exterior ring of each
/// polygon first, then its interiors; closing duplicates dropped. Fails on
/// NaN, infinite or out-of-range coordinates.
pub fn from_geo(
    multi: &MultiPolygon<f64>,
    orientation: RingOrientation,
) -> Result<PolygonSet2, UmbraError> {
    let open = |ls: &LineString<f64>| -> Vec<Point2> {
        let mut pts: Vec<Point2> = ls.0.iter().map(|c| [c.x, c.y]).collect();
        strip_closing(&mut pts);
        pts
    };
    let polygons: Polygons = multi
        .0
        .iter()
        .map(|p| {
            std::iter::once(p.exterior())
                .chain(p.interiors())
                .map(open)
                .collect()
        })
        .collect();
    validate_polygons(&polygons, "<geo-types>")?;
    build_set(&polygons, orientation, "<geo-types>")
}

#[cfg(test)]
mod tests {
    use super::*;
    use geo_types::polygon;

    #[test]
    fn geo_round_trip_keeps_roles_and_coordinates() {
        // Exterior stored clockwise, interior counter-clockwise.
        let p = polygon!(
            exterior: [(x: 0.0, y: 0.0), (x: 0.0, y: 4.0), (x: 4.0, y: 4.0), (x: 4.0, y: 0.0)],
            interiors: [[(x: 1.0, y: 1.0), (x: 2.0, y: 1.0), (x: 2.0, y: 2.0), (x: 1.0, y: 2.0)]],
        );
        let mp = MultiPolygon(vec![p]);
        let set = from_geo(&mp, RingOrientation::ByRole).unwrap();
        assert_eq!(set.vertex_count(), 8);
        assert_eq!(set.signed_area(), 15.0);
        let kept = from_geo(&mp, RingOrientation::AsWritten).unwrap();
        assert_eq!(kept.signed_area(), -15.0);
        let out = to_geo(&set).unwrap();
        assert_eq!(out.0.len(), 1);
        let poly = &out.0[0];
        assert_eq!(ring_signed_area_of(poly.exterior()), 16.0);
        assert_eq!(ring_signed_area_of(&poly.interiors()[0]), -1.0);
        // Closed rings of 4 distinct points.
        assert_eq!(poly.exterior().0.len(), 5);
        assert_eq!(poly.exterior().0.first(), poly.exterior().0.last());
    }

    fn ring_signed_area_of(ls: &LineString<f64>) -> f64 {
        let mut pts: Vec<Point2> = ls.0.iter().map(|c| [c.x, c.y]).collect();
        strip_closing(&mut pts);
        crate::ring_signed_area(&pts)
    }

    #[test]
    fn bad_geo_coordinates_are_refused() {
        let p = polygon![(x: 0.0, y: 0.0), (x: f64::NAN, y: 0.0), (x: 1.0, y: 1.0)];
        let err = from_geo(&MultiPolygon(vec![p]), RingOrientation::ByRole).unwrap_err();
        assert!(
            err.to_string().contains("polygon 1, ring 1, point 2: x"),
            "{err}"
        );
    }
}
