//! Times the rotated n-gon union of Table 7.4: a regular n-gon united with a
//! copy of itself rotated by alpha degrees, through one simplification sweep.
//!
//! ```text
//! cargo run --release -p simplify-2d --example sweep_ngon_union -- [n] [alpha_degrees]
//! ```
//!
//! Prints the time, the number of rings and vertices (correct: one ring of
//! 4n vertices), k_max and epsilon.

use simplify_2d::{boolean, BooleanOp};
use std::time::Instant;
use topology::PolygonSet2;

fn ngon(n: usize, rot_deg: f64) -> PolygonSet2 {
    let rot = rot_deg.to_radians();
    let pts: Vec<[f64; 2]> = (0..n)
        .map(|i| {
            let a = std::f64::consts::TAU * i as f64 / n as f64 + rot;
            [a.cos(), a.sin()]
        })
        .collect();
    let mut s = PolygonSet2::new();
    s.add_loop(&pts);
    s
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let n: usize = args.get(1).and_then(|s| s.parse().ok()).unwrap_or(20_000);
    let alpha: f64 = args.get(2).and_then(|s| s.parse().ok()).unwrap_or(9.88e-7);
    let a = ngon(n, 0.0);
    let b = ngon(n, alpha);
    let runs = 5;
    let mut best = f64::INFINITY;
    let mut last = None;
    for _ in 0..runs {
        let t = Instant::now();
        let out = boolean(&a, &b, BooleanOp::Union);
        best = best.min(t.elapsed().as_secs_f64());
        last = Some(out);
    }
    match last {
        Some(Ok(out)) => {
            let rings = out.shape.loops();
            println!(
                "n = {n}, alpha = {alpha:e} deg: best of {runs} = {:.3} ms; rings = {}, vertices = {} (expected 4n = {}), k_max = {}, epsilon = {:e}",
                best * 1e3,
                rings.len(),
                out.shape.vertex_count(),
                4 * n,
                out.k_max,
                out.epsilon
            );
        }
        Some(Err(e)) => eprintln!("error: {e}"),
        None => {}
    }
}
