//! The rotated n-gon union of the dissertation's Table 7.4: a regular
//! n-gon united with a copy rotated by `alpha` degrees. Prints the ring and
//! vertex counts (exactly one ring of `4n` vertices is right) and the phase
//! timings of the fast path, and of the brute-force reference when
//! `--reference` is given.
//!
//! `cargo run --release -p boolean-2d --example ngon_union -- 20000 1.581e-9`

use boolean_2d::{boolean, boolean_reference, BooleanOp, BooleanOutput};
use topology::PolygonSet2;

fn ngon(n: usize, alpha_degrees: f64) -> PolygonSet2 {
    let alpha = alpha_degrees.to_radians();
    let points: Vec<[f64; 2]> = (0..n)
        .map(|k| {
            let t = 2.0 * std::f64::consts::PI * k as f64 / n as f64 + alpha;
            [t.cos(), t.sin()]
        })
        .collect();
    let mut set = PolygonSet2::new();
    set.add_loop(&points);
    set
}

fn report(name: &str, n: usize, out: &BooleanOutput) {
    let loops = out.shape.loops();
    let sizes: Vec<usize> = loops.iter().map(Vec::len).collect();
    let ok = sizes == [4 * n];
    println!(
        "{name}: {} ring(s), sizes {:?}{}, {} crossings, {:.3} ms (broad {:.3}, X11 {:.3}, winding {:.3}, construct {:.3})",
        loops.len(),
        &sizes[..sizes.len().min(4)],
        if ok { " (correct)" } else { " (WRONG: want one ring of 4n)" },
        out.intersections,
        out.timings.total,
        out.timings.broad_phase,
        out.timings.intersections,
        out.timings.winding,
        out.timings.construct,
    );
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let n: usize = args.first().and_then(|s| s.parse().ok()).unwrap_or(20_000);
    let alpha: f64 = args.get(1).and_then(|s| s.parse().ok()).unwrap_or(1.581e-9);
    let with_reference = args.iter().any(|a| a == "--reference");
    let (a, b) = (ngon(n, 0.0), ngon(n, alpha));
    match boolean(&a, &b, BooleanOp::Union) {
        Ok(out) => report("fast", n, &out),
        Err(e) => println!("fast: error: {e}"),
    }
    if with_reference {
        match boolean_reference(&a, &b, BooleanOp::Union) {
            Ok((out, _)) => report("reference", n, &out),
            Err(e) => println!("reference: error: {e}"),
        }
    }
}
