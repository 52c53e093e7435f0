//! Dense clusters: the field case of section 5.2 (four coincident, almost
//! vertical, slightly non-planar facets, on which the original
//! implementation could loop forever) and seeded clusters of boxes whose
//! faces lie on a few planes, every vertex jittered by about the
//! tolerance, and garbage positions drawn from a handful of points. Each
//! must end valid, within its distortion bound, without the safety budget,
//! in a handful of passes, and be idempotent.

use crate::mesh_common::check_result;
use smooth::{smooth_mesh, SmoothOptions};
use test_support::rng::SplitMix64;
use test_support::shapes::push_box;
use topology::PolygonMesh;

const DELTA: f64 = 1e-5;

fn boxes(list: &[([f64; 3], [f64; 3])]) -> PolygonMesh {
    let (mut v, mut f) = (Vec::new(), Vec::new());
    for &(lo, hi) in list {
        push_box(&mut v, &mut f, lo, hi, false);
    }
    PolygonMesh::new(v, f)
}

/// Smooths, checks the result, and smooths the result again: nothing may
/// change the second time.
fn smooth_checked(m: &PolygonMesh, delta: f64) -> smooth::Smoothed<PolygonMesh> {
    let before = m.clone();
    let out = smooth_mesh(m, &SmoothOptions::new(delta)).unwrap();
    assert_eq!(m, &before, "input untouched");
    check_result(&out.shape, &out.report, delta);
    assert!(out.report.passes <= 12, "passes {}", out.report.passes);
    let again = smooth_mesh(&out.shape, &SmoothOptions::new(delta)).unwrap();
    assert_eq!(again.report.counts.adjustments(), 0, "{:?}", again.report);
    assert_eq!(again.shape, out.shape, "not idempotent");
    out
}

#[test]
fn four_coincident_almost_vertical_non_planar_facets() {
    let unit = ([0.0; 3], [1.0; 3]);
    let next = ([1.0, 0.0, 0.0], [2.0, 1.0, 1.0]);
    for seed in 0..8u64 {
        let mut m = boxes(&[unit, unit, next, next]);
        let mut rng = SplitMix64::new(seed);
        for p in &mut m.vertices {
            // Tilt the shared plane x = 1 off the vertical by 1e-3, then
            // jitter every vertex by up to delta / 4 (non-planar facets).
            p[0] += 1e-3 * p[2];
            for x in p.iter_mut() {
                *x += 0.25 * DELTA * rng.pm1();
            }
        }
        let out = smooth_checked(&m, DELTA);
        let c = out.report.counts;
        assert_eq!(c.facets_cancelled, 2, "seed {seed}: {c:?}");
        assert_eq!(out.shape.facets.len(), 4 * 6 - 4);
        assert!((out.shape.signed_volume() - 4.0).abs() < 1e-3);
    }
}

#[test]
fn jittered_box_clusters() {
    for seed in 0..24u64 {
        let mut rng = SplitMix64::new(1000 + seed);
        let n = 2 + rng.range(0, 6) as usize;
        let list: Vec<([f64; 3], [f64; 3])> = (0..n)
            .map(|_| {
                let lo: [f64; 3] = std::array::from_fn(|_| rng.range(0, 2) as f64 * 0.5);
                let hi: [f64; 3] = std::array::from_fn(|k| lo[k] + 0.5 * rng.range(1, 2) as f64);
                (lo, hi)
            })
            .collect();
        let mut m = boxes(&list);
        let scale = [0.1, 0.5, 1.0, 2.0][seed as usize % 4] * DELTA;
        for p in &mut m.vertices {
            for x in p.iter_mut() {
                *x += scale * rng.pm1();
            }
        }
        let out = smooth_checked(&m, DELTA);
        let v0 = m.signed_volume();
        let v1 = out.shape.signed_volume();
        let area: f64 = 6.0 * list.len() as f64; // at most 6 unit faces each
        assert!(
            (v1 - v0).abs() <= area * out.report.distortion_bound.max(DELTA) + 1e-12,
            "seed {seed}: {v0} -> {v1}"
        );
    }
}

#[test]
fn garbage_positions_from_a_few_points() {
    for seed in 0..24u64 {
        let mut rng = SplitMix64::new(7000 + seed);
        let mut m = boxes(&[
            ([0.0; 3], [1.0; 3]),
            ([0.5; 3], [2.0; 3]),
            ([0.0; 3], [1.0; 3]),
        ]);
        let pool: Vec<[f64; 3]> = (0..5)
            .map(|i| {
                let far = if i < 3 { 3.0 * DELTA } else { 1.0 };
                std::array::from_fn(|_| far * rng.pm1())
            })
            .collect();
        for p in &mut m.vertices {
            *p = pool[rng.range(0, 4) as usize];
        }
        let out = smooth_mesh(&m, &SmoothOptions::new(DELTA)).unwrap();
        check_result(&out.shape, &out.report, DELTA);
    }
}
