//! Times smoothing against the Boolean it follows: the union of two offset
//! icospheres (`LEVEL` subdivisions, default 6: 81,920 triangles each) by
//! `boolean_triangles`, then `smooth_triangles` at `TOL` (default 1e-9), in
//! one process, `REPS` times (default 1; the least time of each is shown);
//! prints the times and the smoothed result's vertex and triangle counts,
//! volume bits and a hash of its coordinates and triangles (to compare
//! outputs across versions bit for bit). Then the same with the Boolean's
//! contacts at `TOL` (`boolean_triangles_with_contacts`) and smoothing only
//! near them (`smooth_triangles_near`), and whether both smoothings give
//! the same triangles (as sets of coordinate triples). `MODE` (default
//! `both`) is `full`, `near` or `both`.
//! The figures of `docs/algorithms/smooth.md` come from
//! `CARGO_PROFILE_RELEASE_LTO=false CARGO_PROFILE_RELEASE_CODEGEN_UNITS=16
//! cargo run --release -p smooth --example smooth_timing -- LEVEL [TOL [REPS]]`.
//! (Criterion benches beside the peers live in `benches/`.)
use boolean_3d::{boolean_triangles, boolean_triangles_with_contacts, BooleanOp};
use smooth::{smooth_triangles, smooth_triangles_near, SmoothOptions};
use std::hint::black_box;
use std::time::{Duration, Instant};
use test_support::canonical;
use test_support::shapes::icosphere;
use topology::TriangleMesh;

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
    let reps: u32 = std::env::args()
        .nth(3)
        .map(|s| s.parse().unwrap())
        .unwrap_or(1);
    let mode = std::env::args().nth(4).unwrap_or_else(|| "both".into());
    let mut full = None;
    if mode != "near" {
        // The least time of `reps` runs of each (the machine is shared).
        let (mut tb, mut ts) = (Duration::MAX, Duration::MAX);
        for _ in 0..reps.max(1) {
            let t = Instant::now();
            let r = boolean_triangles(&a, &b, BooleanOp::Union).unwrap().mesh;
            tb = tb.min(t.elapsed());
            let t = Instant::now();
            full = Some(smooth_triangles(&r, &SmoothOptions::new(tol)).unwrap());
            ts = ts.min(t.elapsed());
        }
        let s = &full.as_ref().unwrap().shape;
        println!(
            "operand {} boolean {:?} smooth {:?} ({:.0}%)",
            a.triangles.len(),
            tb,
            ts,
            100.0 * ts.as_secs_f64() / tb.as_secs_f64()
        );
        print_result(s);
    }
    if mode != "full" {
        let (mut tb, mut ts, mut tplain) = (Duration::MAX, Duration::MAX, Duration::MAX);
        let mut near = None;
        for _ in 0..reps.max(1) {
            // The plain Boolean interleaved, for the added cost.
            let t = Instant::now();
            black_box(boolean_triangles(&a, &b, BooleanOp::Union).unwrap());
            tplain = tplain.min(t.elapsed());
            let t = Instant::now();
            let (r, c) = boolean_triangles_with_contacts(&a, &b, BooleanOp::Union, tol).unwrap();
            tb = tb.min(t.elapsed());
            let t = Instant::now();
            near = Some((
                smooth_triangles_near(&r.mesh, &SmoothOptions::new(tol), &c.boxes).unwrap(),
                c.boxes.len(),
            ));
            ts = ts.min(t.elapsed());
        }
        let (n, boxes) = near.unwrap();
        let added = (tb + ts).as_secs_f64() - tplain.as_secs_f64();
        println!(
            "operand {} boolean {:?} boolean+contacts {:?} ({boxes} boxes) smooth near {:?}: adds {:.0}% to the Boolean",
            a.triangles.len(),
            tplain,
            tb,
            ts,
            100.0 * added / tplain.as_secs_f64()
        );
        print_result(&n.shape);
        if let Some(f) = &full {
            println!(
                "same triangles as full smoothing: {} (reports equal: {})",
                canonical::triangles(&f.shape) == canonical::triangles(&n.shape),
                f.report.counts == n.report.counts
            );
        }
    }
}

fn print_result(s: &TriangleMesh) {
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
