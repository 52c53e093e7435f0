//! Criterion benchmarks of the 3D Boolean beside `manifold-rust`: sphere
//! minus a sphere shifted by half its radius (issue 3), UV spheres of 2k
//! to 200k triangles per operand, Umbra's triangle-mesh variant, its
//! polygon-mesh variant on the same triangles (`umbra-poly`) and on the
//! quadrilateral spheres they split (`umbra-quads`, the same vertices),
//! `manifold-rust` 0.19 and `boolmesh` 0.2 on the triangles. Larger sizes
//! (to 2M), one-thread runs and peak memory are in the `perf-table-3d`
//! binary.
//!
//! ```text
//! cargo bench -p umbra-benches --bench boolean_3d
//! RAYON_NUM_THREADS=1 cargo bench -p umbra-benches --bench boolean_3d
//! ```

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use std::hint::black_box;
use std::time::Duration;
use umbra_benches::solid::{
    sphere_pair, Boolmesh, ManifoldRust, SolidPeer, UmbraPolygons, UmbraQuads, UmbraTriangles,
};

fn bench_peer<P: SolidPeer>(
    group: &mut criterion::BenchmarkGroup<'_, criterion::measurement::WallTime>,
    peer: &P,
    size: usize,
) {
    let (a, b) = sphere_pair(size);
    let input = peer.prepare(&a, &b);
    group.bench_with_input(
        BenchmarkId::new(peer.name(), size),
        &input,
        |bench, input| {
            bench.iter(|| black_box(peer.difference(input)));
        },
    );
}

fn spheres(c: &mut Criterion) {
    let mut group = c.benchmark_group("sphere_difference");
    for size in [2_000usize, 20_000, 200_000] {
        group.throughput(Throughput::Elements(2 * size as u64));
        group.sample_size(10);
        group.measurement_time(Duration::from_secs(if size >= 200_000 { 8 } else { 3 }));
        bench_peer(&mut group, &UmbraTriangles, size);
        bench_peer(&mut group, &UmbraPolygons, size);
        bench_peer(&mut group, &UmbraQuads, size);
        bench_peer(&mut group, &ManifoldRust, size);
        bench_peer(&mut group, &Boolmesh, size);
    }
    group.finish();
}

criterion_group!(benches, spheres);
criterion_main!(benches);
