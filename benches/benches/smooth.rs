//! Criterion benchmarks of data smoothing (Appendix A) beside the 3D
//! Boolean whose output it smooths: the sphere difference of the
//! `boolean_3d` bench at 20k to 1M triangles per operand, timed as the
//! Boolean alone (`boolean`), smoothing its whole result at the default
//! tolerance, 1e-9 of the size (`smooth`), the Boolean with the operands'
//! contacts at that tolerance (`boolean_contacts`) and smoothing only near
//! them (`smooth_near`), and the same with the guard the command line
//! turns on (`smooth_near_guarded`, what it runs), in both variants.
//! The goal (issue: smoothing adds at most 25% to the Boolean's time at
//! 1M triangles) is the ratio of `boolean_contacts + smooth_near` minus
//! `boolean` to `boolean` at the same size; the figures are in `docs/performance.md`. The 2D groups smooth the basic
//! Boolean's union of two 1k-to-100k-gons, and its union and symmetric
//! difference of a real map (Natural Earth's countries) with a rotated
//! and with a minutely scaled copy of itself, whole (`smooth`) and near
//! the contacts of the Boolean that found them (`boolean_contacts`,
//! `smooth_near`: what `umbra boolean` runs).
//!
//! ```text
//! cargo bench -p umbra-benches --bench smooth
//! ```

use boolean_3d::{
    boolean_mesh, boolean_mesh_with_contacts, boolean_triangles, boolean_triangles_with_contacts,
    BooleanOp,
};
use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use std::hint::black_box;
use std::time::Duration;
use umbra::{
    default_mesh_tolerance, smooth_mesh, smooth_mesh_near, smooth_polygon_set,
    smooth_polygon_set_near, smooth_triangles, smooth_triangles_near,
};
use umbra::{default_set_tolerance, SmoothOptions};
use umbra_benches::solid::{sphere_pair, sphere_pair_quads};

fn spheres(c: &mut Criterion) {
    let mut group = c.benchmark_group("smooth_sphere_difference");
    for size in [20_000usize, 200_000, 1_000_000] {
        group.throughput(Throughput::Elements(2 * size as u64));
        group.sample_size(10);
        group.measurement_time(Duration::from_secs(if size >= 200_000 { 10 } else { 3 }));
        let (a, b) = sphere_pair(size);
        let out = boolean_triangles(&a, &b, BooleanOp::Difference)
            .unwrap()
            .mesh;
        let opts = SmoothOptions::new(default_mesh_tolerance(&a.to_polygon_mesh()));
        group.bench_with_input(
            BenchmarkId::new("triangles/boolean", size),
            &(),
            |bench, _| {
                bench.iter(|| black_box(boolean_triangles(&a, &b, BooleanOp::Difference).unwrap()));
            },
        );
        group.bench_with_input(
            BenchmarkId::new("triangles/smooth", size),
            &(),
            |bench, _| {
                bench.iter(|| black_box(smooth_triangles(&out, &opts).unwrap()));
            },
        );
        let tol = opts.tolerance;
        let near = |a, b| boolean_triangles_with_contacts(a, b, BooleanOp::Difference, tol);
        let contacts = near(&a, &b).unwrap().1;
        group.bench_with_input(
            BenchmarkId::new("triangles/boolean_contacts", size),
            &(),
            |bench, _| bench.iter(|| black_box(near(&a, &b).unwrap())),
        );
        group.bench_with_input(
            BenchmarkId::new("triangles/smooth_near", size),
            &(),
            |bench, _| {
                bench.iter(|| {
                    black_box(smooth_triangles_near(&out, &opts, &contacts.boxes).unwrap())
                });
            },
        );
        let guarded = opts.guarded();
        group.bench_with_input(
            BenchmarkId::new("triangles/smooth_near_guarded", size),
            &(),
            |bench, _| {
                bench.iter(|| {
                    black_box(smooth_triangles_near(&out, &guarded, &contacts.boxes).unwrap())
                });
            },
        );
        let (qa, qb) = sphere_pair_quads(size);
        let out = boolean_mesh(&qa, &qb, BooleanOp::Difference).unwrap().mesh;
        group.bench_with_input(
            BenchmarkId::new("polygons/boolean", size),
            &(),
            |bench, _| {
                bench.iter(|| black_box(boolean_mesh(&qa, &qb, BooleanOp::Difference).unwrap()));
            },
        );
        group.bench_with_input(
            BenchmarkId::new("polygons/smooth", size),
            &(),
            |bench, _| {
                bench.iter(|| black_box(smooth_mesh(&out, &opts).unwrap()));
            },
        );
        let near = |a, b| boolean_mesh_with_contacts(a, b, BooleanOp::Difference, tol);
        let contacts = near(&qa, &qb).unwrap().1;
        group.bench_with_input(
            BenchmarkId::new("polygons/boolean_contacts", size),
            &(),
            |bench, _| bench.iter(|| black_box(near(&qa, &qb).unwrap())),
        );
        group.bench_with_input(
            BenchmarkId::new("polygons/smooth_near", size),
            &(),
            |bench, _| {
                bench.iter(|| black_box(smooth_mesh_near(&out, &opts, &contacts.boxes).unwrap()));
            },
        );
        group.bench_with_input(
            BenchmarkId::new("polygons/smooth_near_guarded", size),
            &(),
            |bench, _| {
                bench
                    .iter(|| black_box(smooth_mesh_near(&out, &guarded, &contacts.boxes).unwrap()));
            },
        );
    }
    group.finish();
}

fn polygons(c: &mut Criterion) {
    let mut group = c.benchmark_group("smooth_ngon_union");
    for n in [1_000usize, 10_000, 100_000] {
        let ring = |rot: f64| test_support::shapes::regular_ngon(n, 1.0, rot);
        let mut a = umbra::PolygonSet2::new();
        a.add_loop(&ring(0.0));
        let mut b = umbra::PolygonSet2::new();
        b.add_loop(&ring(180.0 / n as f64 * 0.37));
        let out = boolean_2d::boolean(&a, &b, BooleanOp::Union).unwrap().shape;
        let opts = SmoothOptions::new(default_set_tolerance(&a));
        group.throughput(Throughput::Elements(2 * n as u64));
        group.sample_size(10);
        group.bench_with_input(BenchmarkId::new("boolean", n), &(), |bench, _| {
            bench.iter(|| black_box(boolean_2d::boolean(&a, &b, BooleanOp::Union).unwrap()));
        });
        group.bench_with_input(BenchmarkId::new("smooth", n), &(), |bench, _| {
            bench.iter(|| black_box(smooth_polygon_set(&out, &opts).unwrap()));
        });
    }
    group.finish();
}

/// A real map: Natural Earth's countries (shipped with `test-support`),
/// the basic Boolean of the map with a copy of itself (rotated by 0.37
/// degrees and shifted by about 1% of its width: a few hundred crossings;
/// scaled by `1 + 1e-7` about the origin: thousands of crossings and
/// slivers along every border), and smoothing its result at the default
/// tolerance, whole and near the contacts, as `umbra boolean` runs them.
fn map(c: &mut Criterion) {
    let mut group = c.benchmark_group("smooth_map_boolean");
    let raw = umbra::read_polygon_set(
        &test_support::data_path("naturalearth/countries.geojson"),
        umbra::ReadOptions::default(),
    )
    .unwrap();
    // Made a set first, as `umbra boolean` makes its operands (shared
    // borders drawn once; raw, their duplicate positions send smoothing
    // near the contacts to whole smoothing).
    let world = umbra::regularized_operand(&raw).unwrap().shape;
    let moved = |f: &dyn Fn([f64; 2]) -> [f64; 2]| {
        let (vertices, edges) = world.clone().into_parts();
        umbra::PolygonSet2::from_parts(vertices.into_iter().map(f).collect(), edges)
    };
    let (sin, cos) = (0.37f64.to_radians().sin(), 0.37f64.to_radians().cos());
    let copies = [
        (
            "rotated",
            moved(&|p| [cos * p[0] - sin * p[1] + 4.3, sin * p[0] + cos * p[1] - 2.5]),
        ),
        (
            "scaled",
            moved(&|p| [p[0] * (1.0 + 1e-7), p[1] * (1.0 + 1e-7)]),
        ),
    ];
    group.sample_size(10);
    for (name, copy) in &copies {
        for op in [BooleanOp::Union, BooleanOp::Xor] {
            let id = format!("{name}/{}", op.name());
            let out = boolean_2d::boolean(&world, copy, op).unwrap().shape;
            let opts =
                SmoothOptions::new(umbra::default_boolean_set_tolerance([&world, copy], false));
            group.bench_with_input(BenchmarkId::new("boolean", &id), &(), |bench, _| {
                bench.iter(|| black_box(boolean_2d::boolean(&world, copy, op).unwrap()));
            });
            group.bench_with_input(BenchmarkId::new("smooth", &id), &(), |bench, _| {
                bench.iter(|| black_box(smooth_polygon_set(&out, &opts).unwrap()));
            });
            let tol = opts.tolerance;
            let (near_out, contacts) = umbra::boolean_with_contacts(&world, copy, op, tol).unwrap();
            group.bench_with_input(
                BenchmarkId::new("boolean_contacts", &id),
                &(),
                |bench, _| {
                    bench.iter(|| {
                        black_box(umbra::boolean_with_contacts(&world, copy, op, tol).unwrap())
                    });
                },
            );
            group.bench_with_input(BenchmarkId::new("smooth_near", &id), &(), |bench, _| {
                bench.iter(|| {
                    black_box(
                        smooth_polygon_set_near(&near_out.shape, &opts, &contacts.boxes).unwrap(),
                    )
                });
            });
        }
    }
    group.finish();
}

criterion_group!(benches, spheres, polygons, map);
criterion_main!(benches);
