//! 2D smoothing of a real map (`tests/data/planar_map.wkt`, see the
//! README there): about 22,000 vertices in 2,300 rings, smoothed at small
//! tolerances. The result is valid and clean, its area within perimeter
//! times the tolerance of the map's, smoothing it again changes
//! nothing, and exact winding numbers at sample points are 0 or 1 and
//! agree with the map's away from the boundary.

use crate::planar_support::{perimeter, seg_dist};
use smooth::{sanity_check_polygon_set, smooth_polygon_set, SmoothOptions};
use std::str::FromStr;
use test_support::exact::winding;
use topology::PolygonSet2;
use wkt::Wkt;

/// The map as a polygon set: the first ring of each polygon anticlockwise,
/// the others (holes) clockwise, whatever the file's orientation.
fn map() -> PolygonSet2 {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/planar_map.wkt");
    let text = std::fs::read_to_string(path).expect("the map file");
    let Ok(Wkt::MultiPolygon(mp)) = Wkt::<f64>::from_str(&text) else {
        panic!("the map is a MULTIPOLYGON");
    };
    let mut set = PolygonSet2::new();
    for poly in mp.polygons() {
        for (i, ring) in poly.rings().iter().enumerate() {
            let mut pts: Vec<[f64; 2]> = ring.coords().iter().map(|c| [c.x, c.y]).collect();
            if pts.len() > 1 && pts.first() == pts.last() {
                pts.pop();
            }
            let twice: f64 = (0..pts.len())
                .map(|k| {
                    let (p, q) = (pts[k], pts[(k + 1) % pts.len()]);
                    p[0] * q[1] - q[0] * p[1]
                })
                .sum();
            if (twice > 0.0) != (i == 0) {
                pts.reverse();
            }
            set.add_loop(&pts);
        }
    }
    set
}

#[test]
fn real_map_smoothed_at_small_tolerances() {
    let m = map();
    assert!(m.edge_count() > 20_000);
    m.check_topology().unwrap();
    let [lo, hi] = m.bounding_box().unwrap();
    let size = (hi[0] - lo[0]).max(hi[1] - lo[1]);
    let samples: Vec<[f64; 2]> = (0..12)
        .flat_map(|i| {
            (0..12).map(move |j| {
                [
                    lo[0] + (hi[0] - lo[0]) * (i as f64 + 0.53) / 12.0,
                    lo[1] + (hi[1] - lo[1]) * (j as f64 + 0.29) / 12.0,
                ]
            })
        })
        .collect();
    for tol in [1e-3, 1.0] {
        let out = smooth_polygon_set(&m, &SmoothOptions::new(tol)).unwrap();
        let r = &out.report;
        println!(
            "tol {tol}: {} -> {} edges, {r:?}",
            m.edge_count(),
            out.shape.edge_count()
        );
        assert!(!r.budget_hit);
        sanity_check_polygon_set(&out.shape, tol).unwrap_or_else(|d| panic!("{d}; {r:?}"));
        assert!(r.max_displacement <= r.distortion_bound);
        let (a0, a1) = (m.signed_area(), out.shape.signed_area());
        let bound = perimeter(&m) * tol + 1e-12 * a0.abs();
        assert!(
            (a1 - a0).abs() <= bound,
            "tol {tol}: area {a0} -> {a1}, bound {bound}"
        );
        assert!(tol < 1e-3 * size);
        // Winding numbers 0 or 1, and the map's wherever the sample point
        // is farther than the bound from the map's boundary.
        for &p in &samples {
            let w = winding(p, &out.shape);
            assert!(w == 0 || w == 1, "winding {w} at {p:?}");
            let near = m.edges().iter().any(|e| {
                let (a, b) = m.edge_points(e);
                seg_dist(p, a, b) <= 2.0 * r.distortion_bound.max(tol)
            });
            if !near {
                assert_eq!(w, winding(p, &m), "at {p:?}");
            }
        }
        let again = smooth_polygon_set(&out.shape, &SmoothOptions::new(tol)).unwrap();
        assert_eq!(again.shape, out.shape, "idempotent at {tol}");
    }
}
