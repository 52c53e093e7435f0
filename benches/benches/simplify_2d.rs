//! Criterion benchmarks of simplification beside `i_overlay` and `geo`
//! (issue 4): every row of `umbra_benches::sweep::sweep_cases` (the rotated
//! n-gon union of Table 7.4, random topological polygons of section 7.7 up
//! to 1,000 vertices here, checkerboards, spirals, nested squares), nonzero
//! rule, identical coordinates.
//!
//! ```text
//! cargo bench -p umbra-benches --bench simplify_2d
//! ```

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use std::hint::black_box;
use std::time::Duration;
use umbra_benches::sweep::{
    sweep_cases, GeoSweep, IOverlaySweep, SweepCase, SweepPeer, UmbraSweep,
};

fn bench_peer<P: SweepPeer>(
    group: &mut criterion::BenchmarkGroup<'_, criterion::measurement::WallTime>,
    peer: &P,
    case: &SweepCase,
) {
    if let Some(input) = peer.prepare(case) {
        group.bench_with_input(
            BenchmarkId::new(peer.name(), &case.label),
            &input,
            |b, input| {
                b.iter(|| black_box(peer.run(input)));
            },
        );
    }
}

fn simplification(c: &mut Criterion) {
    let mut group = c.benchmark_group("simplify_nonzero");
    group.sample_size(10);
    group.measurement_time(Duration::from_secs(3));
    for case in sweep_cases(1000) {
        let edges: usize = case.rings.iter().map(Vec::len).sum();
        group.throughput(Throughput::Elements(edges as u64));
        bench_peer(&mut group, &UmbraSweep, &case);
        bench_peer(&mut group, &IOverlaySweep { wide: false }, &case);
        bench_peer(&mut group, &IOverlaySweep { wide: true }, &case);
        bench_peer(&mut group, &GeoSweep, &case);
    }
    group.finish();
}

criterion_group!(benches, simplification);
criterion_main!(benches);
