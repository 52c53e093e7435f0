//! Times sphere minus a sphere shifted by half its radius (UV spheres of
//! about 2k to 200k triangles per operand): the triangle-mesh variant, the
//! polygon-mesh variant on the same triangles, and the polygon-mesh variant
//! on the quadrilateral UV sphere with the same vertices; prints
//! milliseconds (best of 3).
//!
//! Run with `cargo run --release -p boolean-3d --example sphere_diff`
//! (optionally `-- 2000 20000` for chosen triangle counts; set
//! `RAYON_NUM_THREADS=1` for one thread; add `triangles` to run only the
//! triangle-mesh variant, e.g. to read the peak memory).

use boolean_3d::{boolean_mesh, boolean_triangles, BooleanOp};
use std::time::Instant;
use test_support::shapes::{uv_sphere, uv_sphere_quads};

fn best_of<T>(runs: usize, mut f: impl FnMut() -> T) -> (f64, T) {
    let mut best = f64::INFINITY;
    let mut last = None;
    for _ in 0..runs {
        let t = Instant::now();
        let r = f();
        best = best.min(t.elapsed().as_secs_f64() * 1e3);
        last = Some(r);
    }
    match last {
        Some(r) => (best, r),
        None => (best, f()),
    }
}

fn main() {
    // `triangles` as an argument runs the triangle variant only (for peak
    // memory measurements).
    let only_triangles = std::env::args().any(|a| a == "triangles");
    let sizes: Vec<u32> = {
        let args: Vec<u32> = std::env::args()
            .skip(1)
            .filter_map(|a| a.parse().ok())
            .collect();
        if args.is_empty() {
            vec![2_000, 20_000, 200_000]
        } else {
            args
        }
    };
    println!(
        "threads: {}  (sphere r = 1 minus sphere shifted by (0.5, 0.013, 0.007))",
        rayon::current_num_threads()
    );
    println!(
        "triangles/operand  variant    ms(best of 3)  out_vertices  out_facets  intersections"
    );
    for n in sizes {
        // 2 s (s/2 - 1) ~ n with stacks = slices / 2.
        let slices = ((n as f64).sqrt().round() as u32).max(4);
        let stacks = (slices / 2).max(3);
        let a = uv_sphere([0.0; 3], 1.0, slices, stacks);
        let b = uv_sphere([0.5, 0.013, 0.007], 1.0, slices, stacks);
        let (ms, out) = best_of(3, || boolean_triangles(&a, &b, BooleanOp::Difference));
        match out {
            Ok(o) => {
                let valid = o.mesh.check_topology().is_ok();
                println!(
                    "{:>17}  triangles {:>13.2}  {:>12}  {:>10}  {:>13}  valid={valid} volume={:.6}",
                    a.triangles.len(),
                    ms,
                    o.mesh.vertices.len(),
                    o.mesh.triangles.len(),
                    o.intersections,
                    o.mesh.signed_volume()
                );
            }
            Err(e) => println!("{n}: error {e}"),
        }
        if only_triangles {
            continue;
        }
        let (pa, pb) = (a.to_polygon_mesh(), b.to_polygon_mesh());
        let (ms, out) = best_of(3, || boolean_mesh(&pa, &pb, BooleanOp::Difference));
        match out {
            Ok(o) => println!(
                "{:>17}  polygons  {:>13.2}  {:>12}  {:>10}  {:>13}  valid={}",
                a.triangles.len(),
                ms,
                o.mesh.vertices.len(),
                o.mesh.facets.len(),
                o.intersections,
                o.mesh.check_topology().is_ok()
            ),
            Err(e) => println!("{n}: error {e}"),
        }
        let (qa, qb) = (
            uv_sphere_quads([0.0; 3], 1.0, slices, stacks),
            uv_sphere_quads([0.5, 0.013, 0.007], 1.0, slices, stacks),
        );
        let (ms, out) = best_of(3, || boolean_mesh(&qa, &qb, BooleanOp::Difference));
        match out {
            Ok(o) => println!(
                "{:>17}  quads     {:>13.2}  {:>12}  {:>10}  {:>13}  valid={} ({} quad facets/operand)",
                a.triangles.len(),
                ms,
                o.mesh.vertices.len(),
                o.mesh.facets.len(),
                o.intersections,
                o.mesh.check_topology().is_ok(),
                qa.facets.len()
            ),
            Err(e) => println!("{n}: error {e}"),
        }
    }
}
