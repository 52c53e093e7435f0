//! Criterion benchmarks of the 2D Boolean beside its peers: the union of a
//! regular n-gon with a copy rotated by alpha degrees, every row of the
//! dissertation's Table 7.4 (section 7.6), on Umbra, the C++ Clipper2
//! (`clipper2`), its Rust port (`clipper2-rust`), `i_overlay` 9 (32- and
//! 64-bit engines) and `geo` 0.33 with identical coordinates.
//!
//! ```text
//! cargo bench -p umbra-benches --bench boolean_2d
//! cargo bench -p umbra-benches --bench boolean_2d -- 'umbra/n=1000'
//! ```
//!
//! Inputs are converted to each peer's native type before timing; only the
//! union is measured. Sample counts and measurement times shrink as `n`
//! grows so that the whole group takes a few minutes on two cores. Every
//! peer's result is checked once before timing and a wrong result (not one
//! ring of `4n` vertices of the exact area) is printed to stderr, not
//! hidden.

use criterion::{
    criterion_group, criterion_main, BenchmarkId, Criterion, SamplingMode, Throughput,
};
use std::hint::black_box;
use std::time::Duration;
use umbra_benches::{
    exact_union_area, rotated_ngon_pair, Case, Clipper2, Clipper2Rust, Geo, IOverlay, IOverlay64,
    Peer, Umbra, TABLE_7_4,
};

/// Sample size and measurement time for a row of `n` vertices.
fn budget(n: usize) -> (usize, Duration) {
    match n {
        0..=499 => (30, Duration::from_secs(2)),
        500..=1999 => (20, Duration::from_secs(2)),
        2000..=9999 => (10, Duration::from_secs(3)),
        _ => (10, Duration::from_secs(4)),
    }
}

/// Prints a note when `peer` does not get the exact combinatorics.
fn check<P: Peer>(peer: &P, case: &Case, input: &P::Input) {
    match peer.stats(&peer.union(input)) {
        Ok(s) if s.is_exact_union(case) => {}
        Ok(s) => eprintln!(
            "note: {} on {}: {} rings, {} vertices, {} zero-length edges, area {} (expected 1 ring, {} vertices, area {})",
            peer.name(),
            case.label(),
            s.rings,
            s.vertices,
            s.zero_length_edges,
            s.area,
            case.expected_vertices(),
            exact_union_area(case.n, case.alpha_deg)
        ),
        Err(e) => eprintln!("note: {} on {}: {e}", peer.name(), case.label()),
    }
}

fn bench_peer<P: Peer>(
    group: &mut criterion::BenchmarkGroup<'_, criterion::measurement::WallTime>,
    peer: &P,
    case: &Case,
) {
    let (a, b) = rotated_ngon_pair(case.n, case.alpha_deg);
    let input = peer.prepare(&[a], &[b]);
    // The result is checked once, inside the routine so that benchmarks
    // left out by a command-line filter cost nothing.
    let mut checked = false;
    group.bench_with_input(
        BenchmarkId::new(peer.name(), case.label()),
        &input,
        |bencher, input| {
            if !checked {
                checked = true;
                check(peer, case, input);
            }
            bencher.iter(|| peer.union(black_box(input)));
        },
    );
}

fn rotated_ngon_union(c: &mut Criterion) {
    let mut group = c.benchmark_group("union_rotated_ngon");
    group.sampling_mode(SamplingMode::Flat);
    group.warm_up_time(Duration::from_millis(500));
    for case in &TABLE_7_4 {
        let (samples, time) = budget(case.n);
        group.sample_size(samples);
        group.measurement_time(time);
        group.throughput(Throughput::Elements(2 * case.n as u64));
        bench_peer(&mut group, &Umbra, case);
        bench_peer(&mut group, &Clipper2, case);
        bench_peer(&mut group, &Clipper2Rust, case);
        bench_peer(&mut group, &IOverlay, case);
        bench_peer(&mut group, &IOverlay64, case);
        bench_peer(&mut group, &Geo, case);
    }
    group.finish();
}

criterion_group!(benches, rotated_ngon_union);
criterion_main!(benches);
