//! A chain of Booleans on grid boxes (unit 0.25, each jittered by up to
//! 1e-13), smoothing after every step: the result stays valid and its
//! volume stays within 1e-9 of the exact volume, counted on the grid. The
//! issue's 1,000-step chain is `#[ignore]`d (run with `--ignored`); the
//! normal suite runs 60 steps.

use crate::mesh_common::check_result;
use boolean_3d::{boolean_mesh, BooleanOp};
use smooth::{smooth_mesh, SmoothOptions};
use test_support::rng::SplitMix64;
use test_support::shapes::box_mesh;

const N: usize = 8; // cells per axis
const CELL: f64 = 0.25;
const DELTA: f64 = 1e-10;

fn chain(steps: usize, seed: u64) {
    let mut rng = SplitMix64::new(seed);
    let mut cells = vec![false; N * N * N];
    let mut mesh = topology::PolygonMesh::default();
    for step in 0..steps {
        let lo: [usize; 3] = std::array::from_fn(|_| rng.range(0, N as i64 - 1) as usize);
        let hi: [usize; 3] = std::array::from_fn(|k| (lo[k] + rng.range(1, 4) as usize).min(N));
        let op = if step == 0 || rng.range(0, 2) > 0 {
            BooleanOp::Union
        } else {
            BooleanOp::Difference
        };
        for x in lo[0]..hi[0] {
            for y in lo[1]..hi[1] {
                for z in lo[2]..hi[2] {
                    cells[(x * N + y) * N + z] = op == BooleanOp::Union;
                }
            }
        }
        let jitter = |c: usize, rng: &mut SplitMix64| c as f64 * CELL + 1e-13 * rng.pm1();
        let blo: [f64; 3] = std::array::from_fn(|k| jitter(lo[k], &mut rng));
        let bhi: [f64; 3] = std::array::from_fn(|k| jitter(hi[k], &mut rng));
        let raw = boolean_mesh(&mesh, &box_mesh(blo, bhi), op).unwrap().mesh;
        let out = smooth_mesh(&raw, &SmoothOptions::new(DELTA)).unwrap();
        check_result(&out.shape, &out.report, DELTA);
        mesh = out.shape;
        let exact = cells.iter().filter(|&&c| c).count() as f64 * CELL * CELL * CELL;
        let v = mesh.signed_volume();
        assert!(
            (v - exact).abs() <= 1e-9,
            "seed {seed} step {step}: volume {v} vs {exact}"
        );
    }
}

#[test]
fn chain_of_60_booleans_smoothing_every_step() {
    chain(60, 1);
}

#[test]
#[ignore = "the issue's 1,000-step chain: about 20 s in debug builds"]
fn chain_of_1000_booleans_smoothing_every_step() {
    chain(1000, 2);
}
