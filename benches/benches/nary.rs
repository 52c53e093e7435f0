//! Criterion benchmarks of n-ary 3D Booleans in one call (issue 13):
//! Umbra's `union_all_solids` / `difference_all_solids` (both variants)
//! beside `manifold-rust` and `boolmesh` (`umbra_benches::batch`) on the
//! union of 125 overlapping spheres and a 10 x 10 x 1 slab minus 100 boxes
//! (the rows of `perf-table-nary` at an eighth and a tenth of their size,
//! so that criterion's samples stay short; the full rows, 1,000 operands
//! each, are in that binary).
//!
//! ```text
//! cargo bench -p umbra-benches --bench nary
//! RAYON_NUM_THREADS=1 cargo bench -p umbra-benches --bench nary
//! ```

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use std::hint::black_box;
use std::time::Duration;
use umbra::MeshVariant;
use umbra_benches::batch::{
    slab_case, sphere_union_case, BatchCase, BatchPeer, BoolmeshBatch, ManifoldRustBatch,
    UmbraBatch,
};

fn bench_peer<P: BatchPeer>(
    group: &mut criterion::BenchmarkGroup<'_, criterion::measurement::WallTime>,
    peer: &P,
    case: &BatchCase,
) {
    let Some(input) = peer.prepare(case) else {
        eprintln!("note: {} refused {}", peer.name(), case.label);
        return;
    };
    group.bench_with_input(
        BenchmarkId::new(peer.name(), &case.label),
        &input,
        |b, input| b.iter(|| black_box(peer.run(input))),
    );
}

fn nary(c: &mut Criterion) {
    let mut group = c.benchmark_group("nary");
    group.sample_size(10);
    group.measurement_time(Duration::from_secs(4));
    for case in [sphere_union_case(125, 12), slab_case(10, 10)] {
        bench_peer(&mut group, &UmbraBatch(MeshVariant::PolygonMesh), &case);
        bench_peer(&mut group, &UmbraBatch(MeshVariant::TriangleMesh), &case);
        bench_peer(&mut group, &ManifoldRustBatch { fold: false }, &case);
        bench_peer(&mut group, &BoolmeshBatch, &case);
    }
    group.finish();
}

criterion_group!(benches, nary);
criterion_main!(benches);
