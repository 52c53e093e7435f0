//! `peak-memory-2d`: the memory one 2D operation takes, Umbra beside the
//! 2D peers (issue 13: "peak memory no higher than the peers'"), printed
//! as a markdown table for `docs/performance.md`.
//!
//! ```text
//! cargo run --release -p umbra-benches --bin peak-memory-2d -- [--sizes 10000,100000,1000000] [--random 1000]
//! ```
//!
//! Rows:
//!
//! - the union of a regular `n`-gon with its copy rotated by a tenth of an
//!   edge's angle (the scaling row of `scaling`), `2n` input vertices in
//!   all, on Umbra's basic Boolean, Umbra's sweep (the nonzero
//!   simplification of both rings), the C++ Clipper2 (`clipper2`),
//!   `clipper2-rust`, `i_overlay` and `geo`;
//! - the nonzero simplification of the random polygon of section 7.7
//!   (`n` points joined cyclically) on Umbra's sweep, both Clipper2 peers
//!   and `i_overlay` (64-bit, the one correct there).
//!
//! Each cell runs in a fresh child process (this binary with `--child`):
//! the child builds and converts the input, runs the peer once on a small
//! input of the same kind (a 16-gon pair, a 16-point random polygon), so
//! that neither the code's pages nor the allocator's or thread pool's
//! set-up count as the operation's memory, reads `VmRSS`, resets the
//! kernel's peak RSS (`/proc/self/clear_refs`, value 5), runs the operation
//! once and reads `VmHWM`. The cell is the *RSS growth* `VmHWM - VmRSS`:
//! what the operation took from the operating system at its peak, allocator
//! retention included. It is the one measure that sees the C++ library's
//! allocations as well as the Rust ones (a counting global allocator sees
//! only Rust's). Threads: rayon's default (all cores). Linux only (`/proc`).

use std::process::Command;
use umbra_benches::rss::RssGrowth;
use umbra_benches::sweep::{
    random_case, Clipper2RustSweep, Clipper2Sweep, IOverlaySweep, SweepCase, SweepPeer, SweepRule,
    UmbraSweep,
};
use umbra_benches::{
    rotated_ngon_pair, Case, Clipper2, Clipper2Rust, Geo, IOverlay, Peer, RingStats, Umbra,
};

type Result<T> = std::result::Result<T, String>;

/// The peers of the n-gon rows, in column order.
const NGON_PEERS: [&str; 6] = [
    "umbra-basic",
    "umbra-sweep",
    "clipper2",
    "clipper2-rust",
    "i_overlay",
    "geo",
];

/// The peers of the random-polygon rows, in column order.
const RANDOM_PEERS: [&str; 4] = ["umbra-sweep", "clipper2", "clipper2-rust", "i_overlay-i64"];

/// The n-gon row of `vertices` input vertices.
fn ngon_case(vertices: usize) -> Case {
    let n = vertices / 2;
    Case {
        n,
        alpha_deg: 0.1 * 360.0 / n as f64,
    }
}

/// One Boolean peer on an n-gon row: prints `kib correct`.
fn child_ring<P: Peer>(peer: &P, case: &Case) {
    let (a, b) = rotated_ngon_pair(8, case.alpha_deg);
    drop(peer.union(&peer.prepare(&[a], &[b])));
    let (a, b) = rotated_ngon_pair(case.n, case.alpha_deg);
    let input = peer.prepare(&[a], &[b]);
    let rss = RssGrowth::start();
    let out = peer.union(&input);
    let kib = rss.kib();
    let correct = peer
        .stats(&out)
        .is_ok_and(|s: RingStats| s.is_exact_union(case));
    println!("{kib} {correct}");
}

/// One simplification peer on a case: prints `kib correct` (correct: an
/// output the peer could read back; the tables of `perf-table-simplify`
/// compare the areas).
fn child_sweep<P: SweepPeer>(peer: &P, case: &SweepCase) {
    let warm = match case.ngon {
        Some(ngon) => ngon_sweep_case(&Case { n: 8, ..ngon }),
        None => random_case(16, case.rule),
    };
    if let Some(input) = peer.prepare(&warm) {
        drop(peer.run(&input));
    }
    let Some(input) = peer.prepare(case) else {
        println!("0 false");
        return;
    };
    let rss = RssGrowth::start();
    let out = peer.run(&input);
    let kib = rss.kib();
    let correct = match (case.ngon, peer.stats(&out)) {
        (Some(ngon), Ok(s)) => RingStats {
            rings: s.rings,
            vertices: s.vertices,
            zero_length_edges: s.zero_length_edges,
            area: s.area,
        }
        .is_exact_union(&ngon),
        (None, Ok(_)) => true,
        (_, Err(_)) => false,
    };
    println!("{kib} {correct}");
}

fn ngon_sweep_case(case: &Case) -> SweepCase {
    let (a, b) = rotated_ngon_pair(case.n, case.alpha_deg);
    SweepCase {
        label: String::new(),
        rule: SweepRule::NonZero,
        rings: vec![a, b],
        ngon: Some(*case),
        expected: None,
    }
}

fn child(args: &[String]) -> Result<()> {
    let [kind, peer, size] = args else {
        return Err("--child KIND PEER SIZE".into());
    };
    let size: usize = size.parse().map_err(|e| format!("size: {e}"))?;
    match kind.as_str() {
        "ngon" => {
            let case = ngon_case(size);
            match peer.as_str() {
                "umbra-basic" => child_ring(&Umbra, &case),
                "umbra-sweep" => child_sweep(&UmbraSweep, &ngon_sweep_case(&case)),
                "clipper2" => child_ring(&Clipper2, &case),
                "clipper2-rust" => child_ring(&Clipper2Rust, &case),
                "i_overlay" => child_ring(&IOverlay, &case),
                "geo" => child_ring(&Geo, &case),
                other => return Err(format!("unknown peer {other}")),
            }
        }
        "random" => {
            let case = random_case(size, SweepRule::NonZero);
            match peer.as_str() {
                "umbra-sweep" => child_sweep(&UmbraSweep, &case),
                "clipper2" => child_sweep(&Clipper2Sweep, &case),
                "clipper2-rust" => child_sweep(&Clipper2RustSweep, &case),
                "i_overlay-i64" => child_sweep(&IOverlaySweep { wide: true }, &case),
                other => return Err(format!("unknown peer {other}")),
            }
        }
        other => return Err(format!("unknown row kind {other}")),
    }
    Ok(())
}

/// Runs one cell in a child process: `(MiB, correct)`.
fn cell(kind: &str, peer: &str, size: usize) -> Result<(f64, bool)> {
    let exe = std::env::current_exe().map_err(|e| e.to_string())?;
    let out = Command::new(exe)
        .args(["--child", kind, peer, &size.to_string()])
        .output()
        .map_err(|e| e.to_string())?;
    let text = String::from_utf8_lossy(&out.stdout);
    let mut f = text.split_whitespace();
    let kib: f64 = f
        .next()
        .and_then(|s| s.parse().ok())
        .ok_or_else(|| format!("{kind} {peer} {size}: no result ({})", out.status))?;
    let correct = f.next() == Some("true");
    eprintln!(
        "{kind} {size}: {peer} {:.1} MiB (correct {correct})",
        kib / 1024.0
    );
    Ok((kib / 1024.0, correct))
}

fn list(args: &[String], name: &str, default: &str) -> Result<Vec<usize>> {
    umbra_benches::flag_value(args, name)
        .unwrap_or_else(|| default.into())
        .split(',')
        .filter(|s| !s.trim().is_empty())
        .map(|s| s.trim().parse().map_err(|e| format!("{name}: {e}")))
        .collect()
}

fn table(kind: &str, title: &str, peers: &[&str], sizes: &[usize]) -> Result<()> {
    println!();
    println!(
        "| {title} | {} | Umbra / smallest correct peer ({}) |",
        peers.join(" MiB | ") + " MiB",
        peers
            .iter()
            .filter(|p| p.starts_with("umbra"))
            .copied()
            .collect::<Vec<_>>()
            .join(", ")
    );
    println!("|---|{}---:|", "---:|".repeat(peers.len()));
    for &size in sizes {
        let cells: Vec<(f64, bool)> = peers
            .iter()
            .map(|p| cell(kind, p, size))
            .collect::<Result<_>>()?;
        let best_peer = cells
            .iter()
            .zip(peers)
            .filter(|(c, p)| c.1 && !p.starts_with("umbra"))
            .map(|(c, _)| c.0)
            .fold(f64::INFINITY, f64::min);
        let shown: Vec<String> = cells
            .iter()
            .map(|&(mib, ok)| {
                if ok {
                    format!("{mib:.1}")
                } else {
                    format!("{mib:.1} (wrong)")
                }
            })
            .collect();
        let ratio = cells
            .iter()
            .zip(peers)
            .filter(|(_, p)| p.starts_with("umbra"))
            .map(|(c, _)| {
                if best_peer.is_finite() && best_peer > 0.0 {
                    format!("{:.2}", c.0 / best_peer)
                } else {
                    "—".into()
                }
            })
            .collect::<Vec<_>>()
            .join(", ");
        println!("| {size} | {} | {ratio} |", shown.join(" | "));
    }
    Ok(())
}

fn run() -> Result<()> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    if args.first().map(String::as_str) == Some("--child") {
        return child(&args[1..]);
    }
    let sizes = list(&args, "--sizes", "10000,100000,1000000")?;
    let random = list(&args, "--random", "1000")?;
    let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
    println!(
        "<!-- peak-memory-2d | {cores} logical cores | one run per cell in a fresh process | MiB = VmHWM - VmRSS before the operation | ratios: each Umbra column over the smallest correct peer's -->"
    );
    table("ngon", "n-gon union, input vertices", &NGON_PEERS, &sizes)?;
    table(
        "random",
        "random polygon (nonzero), n",
        &RANDOM_PEERS,
        &random,
    )?;
    Ok(())
}

fn main() {
    if let Err(e) = run() {
        eprintln!("peak-memory-2d: {e}");
        std::process::exit(1);
    }
}
