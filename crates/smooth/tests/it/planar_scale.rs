//! How 2D smoothing scales (ignored by default; run with
//! `cargo test -p smooth --release --test it -- planar_scale:: --ignored
//! --nocapture`): a grid of nudged touching squares and a large polygon
//! against its jittered reversed copy, at growing sizes; prints the time
//! per input edge, which stays near flat (O(n log n)).

use crate::planar_support::set_of;
use smooth::{sanity_check_polygon_set, smooth_polygon_set, SmoothOptions};
use std::time::Instant;
use test_support::rng::Xorshift64Star;
use test_support::shapes::{regular_ngon, square};
use topology::PolygonSet2;

const TOL: f64 = 1e-5;

fn grid(m: usize, rng: &mut Xorshift64Star) -> PolygonSet2 {
    let mut s = PolygonSet2::new();
    for i in 0..m {
        for j in 0..m {
            let ring: Vec<[f64; 2]> = square(i as f64, j as f64, 1.0)
                .iter()
                .map(|p| {
                    [
                        p[0] + TOL / 4.0 * (rng.unit() - 0.5),
                        p[1] + TOL / 4.0 * (rng.unit() - 0.5),
                    ]
                })
                .collect();
            s.add_loop(&ring);
        }
    }
    s
}

fn run(name: &str, s: &PolygonSet2) {
    let t = Instant::now();
    let out = smooth_polygon_set(s, &SmoothOptions::new(TOL)).unwrap();
    let dt = t.elapsed().as_secs_f64();
    sanity_check_polygon_set(&out.shape, TOL).unwrap();
    println!(
        "{name}: {} edges -> {} edges in {:.3} s ({:.2} us/edge), passes {}, k {}",
        s.edge_count(),
        out.shape.edge_count(),
        dt,
        dt * 1e6 / s.edge_count() as f64,
        out.report.passes,
        out.report.max_adjustments
    );
}

#[test]
#[ignore = "timing: run in release with --ignored --nocapture"]
fn scaling() {
    let mut rng = Xorshift64Star::new(7);
    for m in [50, 100, 200, 400] {
        run(&format!("grid {m}x{m}"), &grid(m, &mut rng));
    }
    for n in [10_000, 100_000, 400_000] {
        let p = regular_ngon(n, 1000.0, 0.1);
        let j: Vec<[f64; 2]> = p
            .iter()
            .map(|q| {
                [
                    q[0] + TOL / 4.0 * (rng.unit() - 0.5),
                    q[1] + TOL / 4.0 * (rng.unit() - 0.5),
                ]
            })
            .collect();
        let mut s = set_of(&[p]);
        s.append(&set_of(&[j]));
        run(&format!("{n}-gon + jittered copy"), &s);
    }
}
