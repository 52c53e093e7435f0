//! Criterion benchmarks of simplification beside the C++ Clipper2
//! (`clipper2`), `clipper2-rust`, `i_overlay` and `geo` (issue 4): every row of `umbra_benches::sweep::sweep_cases(5000)` with
//! identical coordinates: the ten rotated n-gon unions of Table 7.4 (up to
//! n = 20,000, alpha = 9.88e-7 degrees; with `i_overlay`'s Boolean and
//! `geo`'s union beside the simplifications), random topological polygons
//! of section 7.7 from 100 to 5,000 vertices (seeded: the polygon of `n`
//! vertices is drawn from seed `n`, so every run sees the same input) by
//! the nonzero rule and the 1,000-vertex one by the even-odd and positive
//! rules, two offset 100 x 100 checkerboards, spirals and nested squares.
//!
//! ```text
//! cargo bench -p umbra-benches --bench simplify_2d
//! cargo bench -p umbra-benches --bench simplify_2d -- 'umbra/checkerboards'
//! cargo bench -p umbra-benches --bench simplify_2d -- --test
//! ```
//!
//! Benchmark ids are `simplify/PEER/ROW`; throughput is in input vertices.
//! Inputs are converted to each peer's native type before timing. The two
//! largest random rows (2,000 and 5,000 vertices, seconds per run) get ten
//! flat samples of one run each and a minimal warm-up, so criterion warns
//! that the target time is exceeded there; the whole bench takes about ten
//! minutes on two cores. Each result is checked once before timing, and an
//! error or a wrong exact count is printed to stderr, not hidden.

use criterion::{
    criterion_group, criterion_main, BenchmarkId, Criterion, SamplingMode, Throughput,
};
use std::hint::black_box;
use std::time::Duration;
use umbra_benches::sweep::{
    sweep_cases, Clipper2RustSweep, Clipper2Sweep, GeoSweep, IOverlayBoolSweep, IOverlaySweep,
    SweepCase, SweepPeer, UmbraSweep,
};

/// Warm-up time, sample size and measurement time for a row with `work`
/// input vertices squared per ring (random polygons have about `n^2 / 10`
/// crossings, so their cost grows with `n^2`; the other rows are near
/// linear and cheap).
fn budget(case: &SweepCase) -> (Duration, usize, Duration) {
    let work: usize = case
        .rings
        .iter()
        .map(|r| r.len() * r.len())
        .max()
        .unwrap_or(0);
    let is_random = case.label.starts_with("random");
    match (is_random, work) {
        (true, w) if w >= 2000 * 2000 => (Duration::from_millis(1), 10, Duration::from_secs(5)),
        (true, w) if w >= 1000 * 1000 => (Duration::from_millis(300), 10, Duration::from_secs(4)),
        _ => (Duration::from_millis(500), 20, Duration::from_secs(3)),
    }
}

/// Prints a note when `peer` fails on `case` or misses its exact counts.
fn check<P: SweepPeer>(peer: &P, case: &SweepCase, input: &P::Input) {
    match peer.stats(&peer.run(input)) {
        Ok(s) => {
            if let Some((rings, vertices)) = case.expected {
                let ok = s.rings == rings
                    && vertices.is_none_or(|v| s.vertices == v)
                    && s.zero_length_edges == 0;
                if !ok {
                    let vertices = vertices.map_or("any number of".into(), |v| v.to_string());
                    eprintln!(
                        "note: {} on {}: {} rings, {} vertices, {} zero-length edges (expected {rings} rings, {vertices} vertices)",
                        peer.name(),
                        case.label,
                        s.rings,
                        s.vertices,
                        s.zero_length_edges
                    );
                }
            }
        }
        Err(e) => eprintln!("note: {} on {}: {e}", peer.name(), case.label),
    }
}

fn bench_peer<P: SweepPeer>(
    group: &mut criterion::BenchmarkGroup<'_, criterion::measurement::WallTime>,
    peer: &P,
    case: &SweepCase,
) {
    let Some(input) = peer.prepare(case) else {
        return;
    };
    // The result is checked once, inside the routine, so that benchmarks
    // left out by a command-line filter cost nothing.
    let mut checked = false;
    group.bench_with_input(
        BenchmarkId::new(peer.name(), &case.label),
        &input,
        |b, input| {
            if !checked {
                checked = true;
                check(peer, case, input);
            }
            b.iter(|| black_box(peer.run(black_box(input))));
        },
    );
}

fn simplification(c: &mut Criterion) {
    let mut group = c.benchmark_group("simplify");
    group.sampling_mode(SamplingMode::Flat);
    for case in sweep_cases(5000) {
        let (warm_up, samples, time) = budget(&case);
        group.warm_up_time(warm_up);
        group.sample_size(samples);
        group.measurement_time(time);
        let vertices: usize = case.rings.iter().map(Vec::len).sum();
        group.throughput(Throughput::Elements(vertices as u64));
        bench_peer(&mut group, &UmbraSweep, &case);
        bench_peer(&mut group, &Clipper2Sweep, &case);
        bench_peer(&mut group, &Clipper2RustSweep, &case);
        bench_peer(&mut group, &IOverlaySweep { wide: false }, &case);
        bench_peer(&mut group, &IOverlaySweep { wide: true }, &case);
        bench_peer(&mut group, &IOverlayBoolSweep { wide: false }, &case);
        bench_peer(&mut group, &IOverlayBoolSweep { wide: true }, &case);
        bench_peer(&mut group, &GeoSweep, &case);
    }
    group.finish();
}

criterion_group!(benches, simplification);
criterion_main!(benches);
