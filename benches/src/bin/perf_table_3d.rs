//! `perf-table-3d`: sphere minus a sphere shifted by half its radius (issue
//! 3), Umbra's triangle-mesh variant, its polygon-mesh variant on the same
//! triangles (`umbra-poly`) and on the quadrilateral spheres the triangles
//! split (`umbra-quads`: the same vertices, UV quadrilaterals with triangle
//! fans at the poles), beside `manifold-rust` 0.19 and `boolmesh` 0.2 on
//! the triangles, with
//! one thread and all threads, printing a markdown table for `docs/performance.md`: best time
//! of the difference alone, peak extra resident memory during it, result
//! size, volume against the analytic lens volume, validity, and ratios.
//!
//! ```text
//! cargo run --release -p umbra-benches --bin perf-table-3d -- [--sizes 2000,20000,200000,2000000] [--threads 1,0]
//! ```
//!
//! Every (peer, size, threads) cell runs in a fresh child process (this
//! binary with `--child`), with `RAYON_NUM_THREADS` set (0 = all cores), so
//! that peak memory is that of one run: the child resets the kernel's peak
//! RSS (`/proc/self/clear_refs`, value 5) after building the inputs and
//! reads `VmHWM` after the Boolean (*RSS growth*: what the process took
//! from the OS, allocator retention included). The *heap peak* comes from
//! the sibling binary `peak-memory-3d`, which counts live heap bytes with a
//! global allocator: the most bytes live at once during the Boolean, minus
//! those live before it.

use std::process::Command;
use std::time::Instant;
use umbra_benches::rss::RssGrowth;
use umbra_benches::solid::{
    analytic_difference_volume, sphere_pair, Boolmesh, ManifoldRust, SolidPeer, UmbraPolygons,
    UmbraPrepared, UmbraQuads, UmbraTriangles,
};

/// The peers, in table order (`cells` below indexes them).
const PEERS: [&str; 5] = [
    "umbra-tri",
    "umbra-poly",
    "umbra-quads",
    "manifold-rust",
    "boolmesh",
];

/// Runs one peer `runs` times; prints `ms peak_kb facets volume valid`.
fn child_run<P: SolidPeer>(peer: &P, size: usize, runs: usize) {
    let (a, b) = sphere_pair(size);
    let input = peer.prepare(&a, &b);
    drop((a, b));
    let rss = RssGrowth::start();
    let mut best = f64::INFINITY;
    let mut last = None;
    for _ in 0..runs {
        drop(last.take());
        let t = Instant::now();
        let out = peer.difference(&input);
        best = best.min(t.elapsed().as_secs_f64() * 1e3);
        last = Some(out);
    }
    let peak = rss.kib();
    let s = peer.stats(last.as_ref().expect("at least one run"));
    println!("{best} {peak} {} {} {}", s.facets, s.volume, s.valid);
}

fn child(args: &[String]) {
    let peer = args[0].as_str();
    let size: usize = args[1].parse().expect("size");
    let runs: usize = args[2].parse().expect("runs");
    match peer {
        "umbra-tri" => child_run(&UmbraTriangles, size, runs),
        "umbra-tri-prepared" => child_run(&UmbraPrepared, size, runs),
        "umbra-poly" => child_run(&UmbraPolygons, size, runs),
        "umbra-quads" => child_run(&UmbraQuads, size, runs),
        "manifold-rust" => child_run(&ManifoldRust, size, runs),
        "boolmesh" => child_run(&Boolmesh, size, runs),
        other => panic!("unknown peer {other}"),
    }
}

struct Cell {
    ms: f64,
    peak_mb: f64,
    heap_mb: f64,
    facets: usize,
    volume: f64,
    valid: bool,
}

fn run_cell(peer: &str, size: usize, threads: usize) -> Option<Cell> {
    let runs = if size >= 1_000_000 { 1 } else { 3 };
    let exe = std::env::current_exe().ok()?;
    let mut cmd = Command::new(exe);
    cmd.args(["--child", peer, &size.to_string(), &runs.to_string()]);
    if threads > 0 {
        cmd.env("RAYON_NUM_THREADS", threads.to_string());
    } else {
        cmd.env_remove("RAYON_NUM_THREADS");
    }
    let out = cmd.output().ok()?;
    if !out.status.success() {
        eprintln!(
            "{peer} at {size}: child failed: {}",
            String::from_utf8_lossy(&out.stderr)
        );
        return None;
    }
    let text = String::from_utf8_lossy(&out.stdout);
    let f: Vec<&str> = text.split_whitespace().collect();
    let mut heap = Command::new(
        std::env::current_exe()
            .ok()?
            .with_file_name("peak-memory-3d"),
    );
    heap.args([peer, &size.to_string()]);
    if threads > 0 {
        heap.env("RAYON_NUM_THREADS", threads.to_string());
    } else {
        heap.env_remove("RAYON_NUM_THREADS");
    }
    let heap_mb = heap
        .output()
        .ok()
        .and_then(|o| {
            String::from_utf8_lossy(&o.stdout)
                .split_whitespace()
                .next()
                .and_then(|t| t.parse::<f64>().ok())
        })
        .map_or(f64::NAN, |b| b / (1024.0 * 1024.0));
    Some(Cell {
        heap_mb,
        ms: f.first()?.parse().ok()?,
        peak_mb: f.get(1)?.parse::<f64>().ok()? / 1024.0,
        facets: f.get(2)?.parse().ok()?,
        volume: f.get(3)?.parse().ok()?,
        valid: f.get(4)? == &"true",
    })
}

fn list(args: &[String], name: &str, default: &[usize]) -> Vec<usize> {
    args.iter()
        .position(|a| a == name)
        .and_then(|i| args.get(i + 1))
        .map(|s| s.split(',').filter_map(|t| t.trim().parse().ok()).collect())
        .unwrap_or_else(|| default.to_vec())
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    if args.first().map(String::as_str) == Some("--child") {
        child(&args[1..]);
        return;
    }
    let sizes = list(&args, "--sizes", &[2_000, 20_000, 200_000, 2_000_000]);
    let threads = list(&args, "--threads", &[1, 0]);
    let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
    let want = analytic_difference_volume();
    println!(
        "<!-- perf-table-3d | {cores} logical cores | best of 3 runs (1 run at >= 1M triangles) | peak = VmHWM - VmRSS before the Boolean -->\n"
    );
    println!("| triangles / operand | threads | umbra-tri ms | umbra-poly ms | umbra-quads ms | manifold-rust ms | boolmesh ms | manifold / umbra-tri | boolmesh / umbra-tri | manifold / umbra-quads | heap peak MB (u-tri, u-poly, u-quads, manifold, boolmesh) | RSS growth MB (u-tri, u-quads, manifold, boolmesh) | umbra volume err (tri, quads) | peers' volume err (manifold, boolmesh) | valid (u-tri, u-poly, u-quads, manifold, boolmesh) |");
    println!("|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|");
    for &size in &sizes {
        for &t in &threads {
            let cells: Vec<Option<Cell>> = PEERS.iter().map(|p| run_cell(p, size, t)).collect();
            let ms = |c: &Option<Cell>| c.as_ref().map_or("—".into(), |c| format!("{:.1}", c.ms));
            let mb = |c: &Option<Cell>| {
                c.as_ref()
                    .map_or("—".into(), |c| format!("{:.0}", c.peak_mb))
            };
            let heap = |c: &Option<Cell>| {
                c.as_ref()
                    .map_or("—".into(), |c| format!("{:.0}", c.heap_mb))
            };
            let err = |c: &Option<Cell>| {
                c.as_ref().map_or("—".into(), |c| {
                    format!("{:+.2e}", (c.volume - want) / want)
                })
            };
            let ratio = |u: &Option<Cell>, m: &Option<Cell>| match (u, m) {
                (Some(u), Some(m)) => format!("{:.2}", m.ms / u.ms),
                _ => "—".into(),
            };
            let valid: Vec<String> = cells
                .iter()
                .map(|c| {
                    c.as_ref().map_or("failed".into(), |c| {
                        // Correct: the library's validity check, and the
                        // volume of Umbra's triangle variant (the same
                        // polyhedral lens) to 1e-9 relative.
                        let same = cells[0]
                            .as_ref()
                            .is_some_and(|u| (c.volume - u.volume).abs() <= 1e-9 * u.volume.abs());
                        let verdict = match (c.valid, same) {
                            (true, true) => "yes",
                            (true, false) => "**volume differs**",
                            _ => "**NO**",
                        };
                        format!("{verdict} ({} f)", c.facets)
                    })
                })
                .collect();
            println!(
                "| {size} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {}, {}, {}, {}, {} | {}, {}, {}, {} | {}, {} | {}, {} | {} |",
                if t == 0 {
                    format!("all ({cores})")
                } else {
                    t.to_string()
                },
                ms(&cells[0]),
                ms(&cells[1]),
                ms(&cells[2]),
                ms(&cells[3]),
                ms(&cells[4]),
                ratio(&cells[0], &cells[3]),
                ratio(&cells[0], &cells[4]),
                ratio(&cells[2], &cells[3]),
                heap(&cells[0]),
                heap(&cells[1]),
                heap(&cells[2]),
                heap(&cells[3]),
                heap(&cells[4]),
                mb(&cells[0]),
                mb(&cells[2]),
                mb(&cells[3]),
                mb(&cells[4]),
                err(&cells[0]),
                err(&cells[2]),
                err(&cells[3]),
                err(&cells[4]),
                valid.join(", ")
            );
        }
    }
}
