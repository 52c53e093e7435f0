//! `perf-table-simplify`: simplification by the nonzero rule (issue 4) on
//! Umbra's sweep, `i_overlay` 9 `simplify_shape` (32- and 64-bit engines)
//! and, on the n-gon union rows, `geo` 0.33 `BooleanOps::union`; prints a
//! markdown table for `docs/performance.md` with the median time, ratios
//! and correctness columns.
//!
//! ```text
//! cargo run --release -p umbra-benches --bin perf-table-simplify -- [--max-random 5000] [--budget-ms 1500]
//! ```
//!
//! A result is correct when it has the exact ring/vertex counts where the
//! row knows them (n-gon: one ring of `4n` vertices; nested squares: one
//! ring of 4 vertices per square), and its area agrees with the 64-bit
//! i_overlay engine to 1e-9 relative where no exact count is known.

use std::time::{Duration, Instant};
use umbra_benches::sweep::{
    sweep_cases, GeoSweep, IOverlaySweep, SweepCase, SweepPeer, SweepStats, UmbraSweep,
};

fn time_peer<P: SweepPeer>(
    peer: &P,
    case: &SweepCase,
    budget: Duration,
) -> Option<(f64, SweepStats)> {
    let input = peer.prepare(case)?;
    let t = Instant::now();
    let out = peer.run(&input);
    let first = t.elapsed();
    let stats = peer.stats(&out)?;
    drop(out);
    let runs = if first > budget {
        0
    } else {
        (budget.as_secs_f64() / first.as_secs_f64().max(1e-6)).clamp(2.0, 51.0) as usize
    };
    let mut times = vec![first.as_secs_f64() * 1e3];
    for _ in 0..runs {
        let t = Instant::now();
        let out = peer.run(&input);
        times.push(t.elapsed().as_secs_f64() * 1e3);
        drop(out);
    }
    times.sort_by(f64::total_cmp);
    Some((times[times.len() / 2], stats))
}

fn verdict(case: &SweepCase, s: &SweepStats, reference: Option<&SweepStats>) -> &'static str {
    if let Some((rings, vertices)) = case.expected {
        let ok = s.rings == rings && vertices.is_none_or(|v| s.vertices == v);
        return if ok { "yes" } else { "**no**" };
    }
    match reference {
        Some(r) if (s.area - r.area).abs() <= 1e-9 * r.area.abs().max(1.0) => "yes (area)",
        Some(_) => "**area differs**",
        None => "?",
    }
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let get = |name: &str, default: usize| {
        args.iter()
            .position(|a| a == name)
            .and_then(|i| args.get(i + 1))
            .and_then(|s| s.parse().ok())
            .unwrap_or(default)
    };
    let max_random = get("--max-random", 5000);
    let budget = Duration::from_millis(get("--budget-ms", 1500) as u64);
    let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
    println!(
        "<!-- perf-table-simplify | {cores} logical cores | median of runs within the budget -->\n"
    );
    println!("| row | umbra ms | i_overlay ms | i_overlay / umbra | i_overlay-i64 ms | i_overlay-i64 / umbra | geo ms | geo / umbra | correct (umbra, i_overlay, i64, geo) | umbra rings / vertices |");
    println!("|---|---:|---:|---:|---:|---:|---:|---:|---|---:|");
    for case in sweep_cases(max_random) {
        eprintln!("row: {}", case.label);
        let u = time_peer(&UmbraSweep, &case, budget);
        let i = time_peer(&IOverlaySweep { wide: false }, &case, budget);
        let w = time_peer(&IOverlaySweep { wide: true }, &case, budget);
        let g = time_peer(&GeoSweep, &case, budget);
        let reference = w.as_ref().map(|(_, s)| s);
        let cell = |x: &Option<(f64, SweepStats)>| {
            x.as_ref()
                .map_or("—".to_string(), |(ms, _)| format!("{ms:.2}"))
        };
        let ratio = |x: &Option<(f64, SweepStats)>| match (x, &u) {
            (Some((p, _)), Some((um, _))) => format!("{:.2}", p / um),
            _ => "—".into(),
        };
        let ok = |x: &Option<(f64, SweepStats)>| {
            x.as_ref()
                .map_or("—", |(_, s)| verdict(&case, s, reference))
        };
        println!(
            "| {} | {} | {} | {} | {} | {} | {} | {} | {}, {}, {}, {} | {} |",
            case.label,
            cell(&u),
            cell(&i),
            ratio(&i),
            cell(&w),
            ratio(&w),
            cell(&g),
            ratio(&g),
            ok(&u),
            ok(&i),
            ok(&w),
            ok(&g),
            u.as_ref().map_or("—".into(), |(_, s)| format!(
                "{} / {}",
                s.rings, s.vertices
            )),
        );
    }
}
