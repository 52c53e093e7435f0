//! Criterion benchmark of iterated CSG (issue 13): the 40 x 25 x 1 slab
//! minus its first 100 boxes of 0.5 x 0.5 x 2, one difference at a time,
//! each result feeding the next, in both mesh variants of the facade
//! (`boolean_solid` on polygon meshes, `boolean_solid_triangles` on
//! triangle meshes). One iteration is the whole chain. The full 1,000-box
//! chain, with per-step counts, is the `csg-chain` binary.
//!
//! ```text
//! cargo bench -p umbra-benches --bench csg_chain
//! ```

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use std::hint::black_box;
use std::time::Duration;
use umbra::MeshVariant;
use umbra_benches::chain::run_chain;

const BOXES: usize = 100;

fn chain(c: &mut Criterion) {
    let mut group = c.benchmark_group("csg_chain");
    group.sample_size(10);
    group.measurement_time(Duration::from_secs(10));
    for (name, variant) in [
        ("umbra-tri", MeshVariant::TriangleMesh),
        ("umbra-poly", MeshVariant::PolygonMesh),
    ] {
        group.bench_function(BenchmarkId::new(name, BOXES), |bench| {
            bench.iter(|| black_box(run_chain(variant, BOXES, |_, _| {}).map(|m| m.facet_count())));
        });
    }
    group.finish();
}

criterion_group!(benches, chain);
criterion_main!(benches);
