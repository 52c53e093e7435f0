//! `perf-table-simplify`: simplification (issue 4) on Umbra's sweep beside
//! the C++ Clipper2 (`clipper2`) and its Rust port (`clipper2-rust`), each
//! the union of all rings as subjects by the matching fill rule,
//! `i_overlay` 9 `simplify_shape` (32- and 64-bit engines) with the
//! matching fill rule, `i_overlay`'s Boolean (the union of the two n-gons
//! as subject and clip, matching fill rule, both engines) and `geo` 0.33
//! `BooleanOps::union` on the n-gon rows; prints a markdown table for
//! `docs/performance.md` with the median time, each peer's time over
//! Umbra's and correctness columns. The peers of a row take turns run by
//! run, so that on a shared machine all of them see the same slow and
//! fast phases and the ratios stay steady.
//!
//! ```text
//! cargo run --release -p umbra-benches --bin perf-table-simplify -- [--max-random 5000] [--budget-ms 1500] [--rows SUBSTRING[,SUBSTRING...]]
//! ```
//!
//! The rows are `umbra_benches::sweep::sweep_cases`: the ten rows of Table
//! 7.4, random topological polygons of 100 to `--max-random` vertices by
//! the nonzero rule (and the 1,000-vertex one by the even-odd and positive
//! rules), checkerboards, spirals and nested squares. `--rows` keeps the
//! rows whose label contains one of the comma-separated substrings.
//!
//! A result is correct when it has the exact ring and vertex counts (and
//! no zero-length edge) where the row knows them (n-gon: one ring of `4n`
//! vertices; nested squares: one ring of 4 vertices per square), and where
//! no exact count is known when its signed area agrees with the 64-bit
//! i_overlay `simplify_shape` result by the same rule (the reference,
//! marked `ref`) to 1e-9 relative. A peer that returned an error is marked
//! `**error**` (the message goes to stderr); `—` means the peer has no such
//! operation for the row.

use std::time::{Duration, Instant};
use umbra_benches::sweep::{
    sweep_cases, Clipper2RustSweep, Clipper2Sweep, GeoSweep, IOverlayBoolSweep, IOverlaySweep,
    SweepCase, SweepPeer, SweepStats, UmbraSweep,
};

/// Command-line settings.
struct Config {
    max_random: usize,
    budget: Duration,
    rows: Vec<String>,
}

fn parse_args() -> Result<Config, String> {
    let mut config = Config {
        max_random: 5000,
        budget: Duration::from_millis(1500),
        rows: Vec::new(),
    };
    let mut args = std::env::args().skip(1);
    while let Some(arg) = args.next() {
        let mut value = || args.next().ok_or_else(|| format!("{arg} needs a value"));
        match arg.as_str() {
            "--max-random" => {
                config.max_random = value()?
                    .parse()
                    .map_err(|e| format!("--max-random: {e}"))?;
            }
            "--budget-ms" => {
                let ms: u64 = value()?.parse().map_err(|e| format!("--budget-ms: {e}"))?;
                config.budget = Duration::from_millis(ms);
            }
            "--rows" => {
                config.rows = value()?
                    .split(',')
                    .map(|s| s.trim().to_string())
                    .filter(|s| !s.is_empty())
                    .collect();
            }
            "-h" | "--help" => {
                return Err(
                    "usage: perf-table-simplify [--max-random N] [--budget-ms MS] [--rows SUBSTRING[,SUBSTRING...]]".into(),
                )
            }
            other => return Err(format!("unknown argument {other}")),
        }
    }
    Ok(config)
}

/// One peer on one row.
enum Outcome {
    /// The peer has no such operation for the row.
    Skipped,
    /// The peer returned an error.
    Failed,
    /// The median time in milliseconds and the result's statistics.
    Done(f64, SweepStats),
}

/// A peer prepared for one row, behind a trait object so that the peers
/// of a row can be timed in turns.
trait Timed {
    /// Runs the peer once and returns the time in milliseconds (the output
    /// is dropped outside the timed region).
    fn time_once(&self) -> f64;
}

/// A peer with its prepared input.
struct Ready<'a, P: SweepPeer> {
    peer: &'a P,
    input: P::Input,
}

impl<P: SweepPeer> Timed for Ready<'_, P> {
    fn time_once(&self) -> f64 {
        let t = Instant::now();
        let out = self.peer.run(&self.input);
        let ms = t.elapsed().as_secs_f64() * 1e3;
        drop(out);
        ms
    }
}

/// A peer after its first (checked) run on a row: the outcome so far, and
/// the peer ready for the timed repetitions.
struct Started<'a> {
    outcome: Outcome,
    times: Vec<f64>,
    ready: Option<Box<dyn Timed + 'a>>,
}

/// Prepares `peer` and runs it once, checking the result.
fn start<'a, P: SweepPeer>(peer: &'a P, case: &SweepCase) -> Started<'a> {
    let Some(input) = peer.prepare(case) else {
        return Started {
            outcome: Outcome::Skipped,
            times: Vec::new(),
            ready: None,
        };
    };
    let t = Instant::now();
    let out = peer.run(&input);
    let first = t.elapsed().as_secs_f64() * 1e3;
    match peer.stats(&out) {
        Ok(stats) => {
            drop(out);
            Started {
                outcome: Outcome::Done(first, stats),
                times: vec![first],
                ready: Some(Box::new(Ready { peer, input })),
            }
        }
        Err(e) => {
            eprintln!("error: {} on {}: {e}", peer.name(), case.label);
            Started {
                outcome: Outcome::Failed,
                times: Vec::new(),
                ready: None,
            }
        }
    }
}

/// Repeats every started peer of a row to fill `budget` each (at least 2
/// and at most 50 more runs; none for a peer whose first run alone
/// exceeded the budget), the peers taking turns run by run so that all of
/// them see the same phases of a shared machine, and replaces each time by
/// the median.
fn time_in_turns(started: &mut [Started<'_>], budget: Duration) {
    let budget_ms = budget.as_secs_f64() * 1e3;
    let runs: Vec<usize> = started
        .iter()
        .map(|s| match (&s.ready, s.times.first()) {
            (Some(_), Some(&first)) if first <= budget_ms => {
                (budget_ms / first.max(1e-6)).clamp(2.0, 50.0) as usize
            }
            _ => 0,
        })
        .collect();
    let rounds = runs.iter().copied().max().unwrap_or(0);
    for round in 0..rounds {
        for (s, &n) in started.iter_mut().zip(&runs) {
            if round < n {
                if let Some(ready) = &s.ready {
                    let ms = ready.time_once();
                    s.times.push(ms);
                }
            }
        }
    }
    for s in started.iter_mut() {
        if let Outcome::Done(ms, _) = &mut s.outcome {
            s.times.sort_by(f64::total_cmp);
            if let Some(&median) = s.times.get(s.times.len() / 2) {
                *ms = median;
            }
        }
    }
}

/// The correctness verdict of one outcome; `is_reference` marks the
/// 64-bit i_overlay simplification the areas are compared with.
fn verdict(
    case: &SweepCase,
    outcome: &Outcome,
    reference: Option<&SweepStats>,
    is_reference: bool,
) -> &'static str {
    let s = match outcome {
        Outcome::Skipped => return "—",
        Outcome::Failed => return "**error**",
        Outcome::Done(_, s) => s,
    };
    if let Some((rings, vertices)) = case.expected {
        let ok = s.rings == rings
            && vertices.is_none_or(|v| s.vertices == v)
            && s.zero_length_edges == 0;
        return if ok { "yes" } else { "**no**" };
    }
    if is_reference {
        return "ref";
    }
    match reference {
        Some(r) if (s.area - r.area).abs() <= 1e-9 * r.area.abs().max(1.0) => "yes (area)",
        Some(_) => "**area differs**",
        None => "?",
    }
}

fn main() {
    let config = match parse_args() {
        Ok(config) => config,
        Err(e) => {
            eprintln!("{e}");
            std::process::exit(2);
        }
    };
    let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
    println!(
        "<!-- perf-table-simplify | {cores} logical cores | median of runs within the budget, the peers of a row taking turns | (x) = peer time / umbra time -->\n"
    );
    println!("| row | rule | umbra ms | i_overlay ms (x) | i_overlay-i64 ms (x) | i_overlay-bool ms (x) | i_overlay-bool-i64 ms (x) | geo ms (x) | clipper2 ms (x) | clipper2-rust ms (x) | correct (umbra, i_overlay, i64, bool, bool-i64, geo, clipper2, clipper2-rust) | umbra rings / vertices |");
    println!("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---|---:|");
    let rows = sweep_cases(config.max_random)
        .into_iter()
        .filter(|c| config.rows.is_empty() || config.rows.iter().any(|s| c.label.contains(s)));
    for case in rows {
        eprintln!("row: {}", case.label);
        let (umbra, io32, io64) = (
            UmbraSweep,
            IOverlaySweep { wide: false },
            IOverlaySweep { wide: true },
        );
        let (bool32, bool64, geo) = (
            IOverlayBoolSweep { wide: false },
            IOverlayBoolSweep { wide: true },
            GeoSweep,
        );
        let mut started = vec![
            start(&umbra, &case),
            start(&io32, &case),
            start(&io64, &case),
            start(&bool32, &case),
            start(&bool64, &case),
            start(&geo, &case),
            start(&Clipper2Sweep, &case),
            start(&Clipper2RustSweep, &case),
        ];
        time_in_turns(&mut started, config.budget);
        let mut outcomes = started.into_iter().map(|s| s.outcome);
        let u = outcomes.next().unwrap_or(Outcome::Skipped);
        let peers: Vec<Outcome> = outcomes.collect();
        // The 64-bit i_overlay simplification is the area reference.
        let reference = match &peers[1] {
            Outcome::Done(_, s) => Some(s),
            _ => None,
        };
        let umbra_ms = match &u {
            Outcome::Done(ms, _) => Some(*ms),
            _ => None,
        };
        let cell = |x: &Outcome| match (x, umbra_ms) {
            (Outcome::Done(ms, _), Some(um)) => format!("{ms:.2} ({:.2})", ms / um),
            (Outcome::Done(ms, _), None) => format!("{ms:.2}"),
            (Outcome::Failed, _) => "error".into(),
            (Outcome::Skipped, _) => "—".into(),
        };
        let umbra_cell = match &u {
            Outcome::Done(ms, _) => format!("{ms:.2}"),
            Outcome::Failed => "error".into(),
            Outcome::Skipped => "—".into(),
        };
        let mut verdicts = vec![verdict(&case, &u, reference, false)];
        verdicts.extend(
            peers
                .iter()
                .enumerate()
                .map(|(i, p)| verdict(&case, p, reference, i == 1)),
        );
        let counts = match &u {
            Outcome::Done(_, s) => format!("{} / {}", s.rings, s.vertices),
            _ => "—".into(),
        };
        let peer_cells: Vec<String> = peers.iter().map(cell).collect();
        println!(
            "| {} | {} | {} | {} | {} | {} |",
            case.label,
            case.rule.name(),
            umbra_cell,
            peer_cells.join(" | "),
            verdicts.join(", "),
            counts,
        );
    }
}
