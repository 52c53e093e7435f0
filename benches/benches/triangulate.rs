//! Criterion benchmarks of the triangulation of facets by internal edges
//! (section 4.8, `topology::triangulate_facet`) on the facets that made
//! the triangle-mesh variant of "slab minus 1,000 boxes" slow: a rectangle
//! with a grid of `n` rectangular holes (the slab's top and bottom faces),
//! for `n` = 100, 400 and 1,000, and a 4,000-gon with 1,000 holes shaped
//! as small diamonds.
//!
//! ```text
//! cargo bench -p umbra-benches --bench triangulate
//! ```

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use std::f64::consts::TAU;
use std::hint::black_box;
use std::time::Duration;
use topology::triangulate_facet;

type Facet = (Vec<[f64; 3]>, Vec<(u32, u32)>);

/// Appends a loop over `pts` (as vertices `base..`) to `hes`.
fn push_loop(pts: &mut Vec<[f64; 3]>, hes: &mut Vec<(u32, u32)>, ring: &[[f64; 2]]) {
    let base = pts.len() as u32;
    let n = ring.len() as u32;
    pts.extend(ring.iter().map(|p| [p[0], p[1], 1.0]));
    hes.extend((0..n).map(|i| (base + i, base + (i + 1) % n)));
}

/// A `w x h` rectangle with a `0.5 x 0.5` hole in every unit cell, the
/// holes shifted by multiples of 1/32 (shared coordinates between
/// neighbours, as the slab's boxes have).
fn plate(w: u32, h: u32) -> Facet {
    let (mut pts, mut hes) = (Vec::new(), Vec::new());
    let (fw, fh) = (f64::from(w), f64::from(h));
    push_loop(
        &mut pts,
        &mut hes,
        &[[0.0, 0.0], [fw, 0.0], [fw, fh], [0.0, fh]],
    );
    for i in 0..w {
        for j in 0..h {
            let x = f64::from(i) + 0.25 + f64::from((i * 7 + j * 3) % 5) / 32.0 - 2.0 / 32.0;
            let y = f64::from(j) + 0.25 + f64::from((i * 3 + j * 5) % 5) / 32.0 - 2.0 / 32.0;
            // Clockwise: the facet's interior on the left.
            let hole = [[x, y], [x, y + 0.5], [x + 0.5, y + 0.5], [x + 0.5, y]];
            push_loop(&mut pts, &mut hes, &hole);
        }
    }
    (pts, hes)
}

/// A regular 4,000-gon of radius 20 with 1,000 small diamonds in a
/// 40 x 25 grid inside it.
fn disc() -> Facet {
    let (mut pts, mut hes) = (Vec::new(), Vec::new());
    let ring: Vec<[f64; 2]> = (0..4000)
        .map(|i| {
            let t = TAU * f64::from(i) / 4000.0;
            [20.0 * t.cos(), 20.0 * t.sin()]
        })
        .collect();
    push_loop(&mut pts, &mut hes, &ring);
    for i in 0..40 {
        for j in 0..25 {
            let (x, y) = (-13.0 + 0.65 * f64::from(i), -13.0 + 1.05 * f64::from(j));
            // Clockwise, as the holes of `plate`.
            let hole = [[x + 0.2, y], [x, y - 0.3], [x - 0.2, y], [x, y + 0.3]];
            push_loop(&mut pts, &mut hes, &hole);
        }
    }
    (pts, hes)
}

fn triangulate(c: &mut Criterion) {
    let mut group = c.benchmark_group("triangulate_facet");
    group.sample_size(20);
    group.measurement_time(Duration::from_secs(4));
    let cases = [
        ("plate 10x10 holes", plate(10, 10)),
        ("plate 20x20 holes", plate(20, 20)),
        ("plate 40x25 holes", plate(40, 25)),
        ("4000-gon 1000 diamonds", disc()),
    ];
    for (label, (pts, hes)) in &cases {
        group.throughput(Throughput::Elements(hes.len() as u64));
        group.bench_with_input(
            BenchmarkId::from_parameter(label),
            &(pts, hes),
            |b, (pts, hes)| {
                b.iter(|| {
                    let mut out = Vec::with_capacity(hes.len() * 2);
                    triangulate_facet(pts, hes, &mut out);
                    black_box(out)
                })
            },
        );
    }
    group.finish();
}

criterion_group!(benches, triangulate);
criterion_main!(benches);
