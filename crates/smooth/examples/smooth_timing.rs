//! Times smoothing against the Boolean it follows: the union of two offset
//! icospheres (`LEVEL` subdivisions, default 6: 81,920 triangles each) by
//! `boolean_triangles`, then `smooth_triangles` at `TOL` (default 1e-9), in
//! one process; prints the times and the smoothed result's vertex and
//! triangle counts, volume bits and a hash of its coordinates and
//! triangles (to compare outputs across versions bit for bit).
//! The figures of `docs/algorithms/smooth.md` come from
//! `CARGO_PROFILE_RELEASE_LTO=false CARGO_PROFILE_RELEASE_CODEGEN_UNITS=16
//! cargo run --release -p smooth --example smooth_timing -- LEVEL [TOL]`.
//! (Criterion benches beside the peers live in `benches/`.)
use boolean_3d::{boolean_triangles, BooleanOp};
use smooth::{smooth_triangles, SmoothOptions};
use std::time::Instant;
use test_support::shapes::icosphere;

fn main() {
    let l: u32 = std::env::args()
        .nth(1)
        .map(|s| s.parse().unwrap())
        .unwrap_or(6);
    let tol: f64 = std::env::args()
        .nth(2)
        .map(|s| s.parse().unwrap())
        .unwrap_or(1e-9);
    let a = icosphere([0.0; 3], 1.0, l);
    let b = icosphere([0.3, 0.2, 0.1], 1.0, l);
    let t = Instant::now();
    let r = boolean_triangles(&a, &b, BooleanOp::Union).unwrap().mesh;
    let tb = t.elapsed();
    let t = Instant::now();
    let s = smooth_triangles(&r, &SmoothOptions::new(tol))
        .unwrap()
        .shape;
    let ts = t.elapsed();
    println!(
        "operand {} boolean {:?} smooth {:?} ({:.0}%)",
        a.triangles.len(),
        tb,
        ts,
        100.0 * ts.as_secs_f64() / tb.as_secs_f64()
    );
    // FNV-1a over the coordinates' bits and the triangles' indices.
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    let words = s.vertices.iter().flatten().map(|x| x.to_bits());
    for w in words.chain(s.triangles.iter().flatten().map(|&i| u64::from(i))) {
        h = (h ^ w).wrapping_mul(0x0100_0000_01b3);
    }
    println!(
        "result {} vertices {} triangles volume {:#018x} hash {h:#018x}",
        s.vertices.len(),
        s.triangles.len(),
        s.signed_volume().to_bits()
    );
}
