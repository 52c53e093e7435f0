//! `perf-table-nary`: n-ary 3D Booleans in one call (issue 13), the union
//! of 1,000 overlapping low-resolution spheres and a 40 x 25 x 1 slab minus
//! 1,000 boxes of 0.5 x 0.5 x 2, on Umbra's `union_all_solids` /
//! `difference_all_solids` (both variants) beside `manifold-rust` and
//! `boolmesh` under rayon's `reduce_with` (and, asked for by name, the
//! port's `batch_boolean`, a left fold: `manifold-rust-fold`)
//! (`umbra_benches::batch`); prints a markdown table for
//! `docs/performance.md`.
//!
//! ```text
//! cargo run --release -p umbra-benches --bin perf-table-nary -- [--spheres 1000] [--slices 12] [--slab 40x25] [--peers umbra-poly,umbra-tri,manifold-rust,boolmesh,manifold-rust-fold] [--runs 1]
//! ```
//!
//! Each cell is the best of `--runs` runs of the whole operation (inputs
//! converted before timing). A result is correct when it passes its
//! library's validity check and its volume is the exact one (the slab) or
//! agrees with Umbra's polygon variant to 1e-9 relative (the spheres: no
//! closed form). Run with `RAYON_NUM_THREADS=1` for one thread.

use std::time::Instant;
use umbra::MeshVariant;
use umbra_benches::batch::{
    slab_case, sphere_union_case, BatchCase, BatchPeer, BoolmeshBatch, ManifoldRustBatch,
    UmbraBatch,
};
use umbra_benches::solid::SolidStats;

const PEERS: [&str; 5] = [
    "umbra-poly",
    "umbra-tri",
    "manifold-rust",
    "boolmesh",
    "manifold-rust-fold",
];

struct Config {
    spheres: usize,
    slices: u32,
    slab: (usize, usize),
    peers: Vec<String>,
    runs: usize,
}

fn parse_args() -> Result<Config, String> {
    let mut c = Config {
        spheres: 1000,
        slices: 12,
        slab: (40, 25),
        // The left fold takes minutes on the sphere row: asked for by name.
        peers: PEERS[..4].iter().map(|p| p.to_string()).collect(),
        runs: 1,
    };
    let mut args = std::env::args().skip(1);
    while let Some(arg) = args.next() {
        let mut value = || args.next().ok_or_else(|| format!("{arg} needs a value"));
        match arg.as_str() {
            "--spheres" => c.spheres = value()?.parse().map_err(|e| format!("--spheres: {e}"))?,
            "--slices" => c.slices = value()?.parse().map_err(|e| format!("--slices: {e}"))?,
            "--runs" => {
                c.runs = value()?
                    .parse::<usize>()
                    .map_err(|e| format!("--runs: {e}"))?
                    .max(1)
            }
            "--slab" => {
                let v = value()?;
                let (x, y) = v.split_once('x').ok_or("--slab: NXxNY")?;
                c.slab = (
                    x.parse().map_err(|e| format!("--slab: {e}"))?,
                    y.parse().map_err(|e| format!("--slab: {e}"))?,
                );
            }
            "--peers" => {
                c.peers = value()?.split(',').map(|p| p.trim().to_string()).collect();
                if let Some(bad) = c.peers.iter().find(|p| !PEERS.contains(&p.as_str())) {
                    return Err(format!("--peers: no peer {bad} (one of {})", PEERS.join(", ")));
                }
            }
            "-h" | "--help" => {
                return Err("usage: perf-table-nary [--spheres N] [--slices S] [--slab NXxNY] [--peers ...] [--runs K]".into())
            }
            other => return Err(format!("unknown argument {other}")),
        }
    }
    Ok(c)
}

fn measure<P: BatchPeer>(peer: &P, case: &BatchCase, runs: usize) -> Option<(f64, SolidStats)> {
    let input = peer.prepare(case)?;
    let mut best = f64::INFINITY;
    let mut stats = None;
    for _ in 0..runs {
        let t = Instant::now();
        let out = peer.run(&input);
        best = best.min(t.elapsed().as_secs_f64() * 1e3);
        stats = Some(peer.stats(&out));
    }
    Some((best, stats?))
}

fn main() {
    let config = match parse_args() {
        Ok(c) => c,
        Err(e) => {
            eprintln!("{e}");
            std::process::exit(2);
        }
    };
    println!(
        "<!-- perf-table-nary | {} logical cores | rayon threads {} | best of {} run(s) -->\n",
        std::thread::available_parallelism().map_or(1, |n| n.get()),
        rayon::current_num_threads(),
        config.runs
    );
    println!("| row | input triangles | peer | ms | x umbra-poly | output facets | volume | volume check | valid |");
    println!("|---|---:|---|---:|---:|---:|---:|---|---|");
    let cases = [
        sphere_union_case(config.spheres, config.slices),
        slab_case(config.slab.0, config.slab.1),
    ];
    for case in &cases {
        let mut reference: Option<(f64, f64)> = None;
        for name in PEERS
            .iter()
            .filter(|p| config.peers.iter().any(|q| q == *p))
        {
            eprintln!("{}: {name}", case.label);
            let cell = match *name {
                "umbra-poly" => measure(&UmbraBatch(MeshVariant::PolygonMesh), case, config.runs),
                "umbra-tri" => measure(&UmbraBatch(MeshVariant::TriangleMesh), case, config.runs),
                "manifold-rust" => measure(&ManifoldRustBatch { fold: false }, case, config.runs),
                "manifold-rust-fold" => {
                    measure(&ManifoldRustBatch { fold: true }, case, config.runs)
                }
                _ => measure(&BoolmeshBatch, case, config.runs),
            };
            let Some((ms, s)) = cell else {
                println!(
                    "| {} | {} | {name} | — | — | — | — | refused the input | — |",
                    case.label,
                    case.input_triangles()
                );
                continue;
            };
            if *name == "umbra-poly" {
                reference = Some((ms, s.volume));
            }
            let check = match (case.exact_volume, reference) {
                (Some(want), _) => {
                    let err = (s.volume - want) / want;
                    if err.abs() <= 1e-9 {
                        format!("exact ({err:+.1e})")
                    } else {
                        format!("**wrong** ({err:+.1e})")
                    }
                }
                (None, Some((_, v))) => {
                    let err = (s.volume - v) / v;
                    if err.abs() <= 1e-9 {
                        format!("= umbra-poly ({err:+.1e})")
                    } else {
                        format!("**differs** ({err:+.1e})")
                    }
                }
                (None, None) => "—".into(),
            };
            let ratio = reference.map_or("—".into(), |(r, _)| format!("{:.2}", ms / r));
            println!(
                "| {} | {} | {name} | {ms:.0} | {ratio} | {} | {:.6} | {check} | {} |",
                case.label,
                case.input_triangles(),
                s.facets,
                s.volume,
                if s.valid { "yes" } else { "**no**" }
            );
        }
    }
}
