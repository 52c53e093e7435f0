//! `perf-table`: runs every row of the dissertation's Table 7.4 (union of a
//! regular n-gon with a copy rotated by alpha degrees) on Umbra and its
//! peers in one process and prints markdown tables for
//! `docs/performance.md`: the median time of the union alone, the result's
//! ring and vertex counts and whether they are the exact union (one ring,
//! `4n` vertices, the exact area to 1e-9), and each peer's time over
//! Umbra's.
//!
//! ```text
//! cargo run --release -p umbra-benches --bin perf-table -- [--budget-ms 1500] [--max-runs 101] [--rows 0,3,9] [--peers umbra,geo]
//! ```
//!
//! Each peer gets one warm-up run (whose result is checked), then `k` timed
//! runs, `k` chosen so that the runs take about `--budget-ms` (at least 3,
//! at most `--max-runs`; a single run when the warm-up alone took more than
//! five budgets). Input conversion is done once before timing; dropping
//! the output is not timed.

use std::time::{Duration, Instant, SystemTime, UNIX_EPOCH};
use umbra_benches::{
    rotated_ngon_pair, Case, Clipper2, Clipper2Rust, Geo, IOverlay, IOverlay64, Peer, RingStats,
    Umbra, TABLE_7_4,
};

/// Command-line settings.
struct Config {
    budget: Duration,
    max_runs: usize,
    rows: Vec<usize>,
    peers: Vec<String>,
}

/// The peers in table order.
const PEERS: [&str; 6] = [
    "umbra",
    "clipper2",
    "clipper2-rust",
    "i_overlay",
    "i_overlay-i64",
    "geo",
];

fn parse_args() -> Result<Config, String> {
    let mut config = Config {
        budget: Duration::from_millis(1500),
        max_runs: 101,
        rows: (0..TABLE_7_4.len()).collect(),
        peers: PEERS.iter().map(|p| p.to_string()).collect(),
    };
    let mut args = std::env::args().skip(1);
    while let Some(arg) = args.next() {
        let mut value = || args.next().ok_or_else(|| format!("{arg} needs a value"));
        match arg.as_str() {
            "--budget-ms" => {
                let ms: u64 = value()?.parse().map_err(|e| format!("--budget-ms: {e}"))?;
                config.budget = Duration::from_millis(ms);
            }
            "--max-runs" => {
                config.max_runs = value()?.parse().map_err(|e| format!("--max-runs: {e}"))?;
                config.max_runs = config.max_runs.max(1);
            }
            "--rows" => {
                config.rows = value()?
                    .split(',')
                    .map(|s| {
                        s.trim()
                            .parse::<usize>()
                            .map_err(|e| format!("--rows: {e}"))
                    })
                    .collect::<Result<_, _>>()?;
                if let Some(bad) = config.rows.iter().find(|&&r| r >= TABLE_7_4.len()) {
                    return Err(format!("--rows: no row {bad} (0..{})", TABLE_7_4.len()));
                }
            }
            "--peers" => {
                config.peers = value()?.split(',').map(|p| p.trim().to_string()).collect();
                if let Some(bad) = config.peers.iter().find(|p| !PEERS.contains(&p.as_str())) {
                    return Err(format!("--peers: no peer {bad} (one of {})", PEERS.join(", ")));
                }
            }
            "-h" | "--help" => {
                return Err(
                    "usage: perf-table [--budget-ms MS] [--max-runs K] [--rows I,J,...] [--peers umbra,clipper2,clipper2-rust,i_overlay,i_overlay-i64,geo]".into(),
                )
            }
            other => return Err(format!("unknown argument {other}")),
        }
    }
    Ok(config)
}

/// One peer on one row.
struct Measurement {
    peer: &'static str,
    median: Duration,
    runs: usize,
    stats: Result<RingStats, String>,
}

fn median(mut times: Vec<Duration>) -> Duration {
    times.sort();
    match times.len() {
        0 => Duration::ZERO,
        len if len % 2 == 1 => times[len / 2],
        len => (times[len / 2 - 1] + times[len / 2]) / 2,
    }
}

fn measure<P: Peer>(peer: &P, case: &Case, config: &Config) -> Measurement {
    let (a, b) = rotated_ngon_pair(case.n, case.alpha_deg);
    let input = peer.prepare(&[a], &[b]);
    let start = Instant::now();
    let out = std::hint::black_box(peer.union(std::hint::black_box(&input)));
    let warm = start.elapsed();
    let stats = peer.stats(&out).map_err(|e| e.to_string());
    drop(out);
    let runs = if warm > config.budget * 5 {
        1
    } else {
        let per = warm.as_secs_f64().max(1e-9);
        ((config.budget.as_secs_f64() / per) as usize).clamp(3, config.max_runs)
    };
    let mut times = Vec::with_capacity(runs);
    if runs == 1 {
        times.push(warm);
    } else {
        for _ in 0..runs {
            let start = Instant::now();
            let out = std::hint::black_box(peer.union(std::hint::black_box(&input)));
            times.push(start.elapsed());
            drop(out);
        }
    }
    Measurement {
        peer: peer.name(),
        median: median(times),
        runs,
        stats,
    }
}

/// The time Umbra's ring tracing (`PolygonSet2::loops`, not part of the
/// Boolean) takes on the row's result, for the notes.
fn umbra_extras(case: &Case) -> (Duration, usize) {
    let (a, b) = rotated_ngon_pair(case.n, case.alpha_deg);
    let input = Umbra.prepare(&[a], &[b]);
    match Umbra.union(&input) {
        Ok(out) => {
            let start = Instant::now();
            let loops = std::hint::black_box(out.shape.loops());
            let t = start.elapsed();
            drop(loops);
            (t, out.intersections)
        }
        Err(_) => (Duration::ZERO, 0),
    }
}

fn ms(d: Duration) -> String {
    let ms = d.as_secs_f64() * 1e3;
    if ms >= 100.0 {
        format!("{ms:.0}")
    } else if ms >= 10.0 {
        format!("{ms:.1}")
    } else {
        format!("{ms:.2}")
    }
}

/// The relative area error of a result against the exact union.
fn area_err(s: &RingStats, case: &Case) -> f64 {
    let want = umbra_benches::exact_union_area(case.n, case.alpha_deg);
    (s.area.abs() - want) / want
}

fn verdict(m: &Measurement, case: &Case) -> String {
    match &m.stats {
        Ok(s) if s.is_exact_union(case) => {
            format!("1 ring, {} v, correct", s.vertices)
        }
        Ok(s) if s.is_single_ring_with(case.expected_vertices()) => {
            format!(
                "1 ring, {} v, area {:.3e} off, **incorrect**",
                s.vertices,
                area_err(s, case)
            )
        }
        Ok(s) => {
            let zero = if s.zero_length_edges > 0 {
                format!(" ({} zero-length)", s.zero_length_edges)
            } else {
                String::new()
            };
            format!(
                "{} ring{}, {} v{zero}, area {:.3e} off, **incorrect**",
                s.rings,
                if s.rings == 1 { "" } else { "s" },
                s.vertices,
                area_err(s, case)
            )
        }
        Err(e) => format!("error: {e}"),
    }
}

/// Today's date (UTC) as `YYYY-MM-DD`, by the civil-from-days algorithm.
fn today() -> String {
    let secs = SystemTime::now()
        .duration_since(UNIX_EPOCH)
        .map(|d| d.as_secs())
        .unwrap_or(0);
    let z = (secs / 86_400) as i64 + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z - era * 146_097;
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let d = doy - (153 * mp + 2) / 5 + 1;
    let m = if mp < 10 { mp + 3 } else { mp - 9 };
    let y = yoe + era * 400 + i64::from(m <= 2);
    format!("{y:04}-{m:02}-{d:02}")
}

fn main() {
    let config = match parse_args() {
        Ok(c) => c,
        Err(msg) => {
            eprintln!("{msg}");
            std::process::exit(2);
        }
    };
    let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
    println!(
        "<!-- perf-table {} | {} logical cores | rayon threads {} | RAYON_NUM_THREADS={} | budget {} ms, max {} runs -->",
        today(),
        cores,
        rayon::current_num_threads(),
        std::env::var("RAYON_NUM_THREADS").unwrap_or_else(|_| "unset".into()),
        config.budget.as_millis(),
        config.max_runs,
    );
    println!();
    let mut rows = Vec::new();
    for &r in &config.rows {
        let case = TABLE_7_4[r];
        eprintln!("row {r}: {}", case.label());
        let ms_row: Vec<Measurement> = PEERS
            .iter()
            .filter(|p| config.peers.iter().any(|q| q == *p))
            .map(|&p| match p {
                "umbra" => measure(&Umbra, &case, &config),
                "i_overlay" => measure(&IOverlay, &case, &config),
                "i_overlay-i64" => measure(&IOverlay64, &case, &config),
                "clipper2" => measure(&Clipper2, &case, &config),
                "clipper2-rust" => measure(&Clipper2Rust, &case, &config),
                _ => measure(&Geo, &case, &config),
            })
            .collect();
        let extras = config
            .peers
            .iter()
            .any(|p| p == "umbra")
            .then(|| umbra_extras(&case));
        rows.push((case, ms_row, extras));
    }

    // Summary: one line per row, times in ms, ratio peer / umbra.
    let peers: Vec<&str> = rows
        .first()
        .map(|(_, m, _)| m.iter().map(|m| m.peer).collect())
        .unwrap_or_default();
    print!("| n | alpha (deg) |");
    for p in &peers {
        if *p == "umbra" {
            print!(" {p} ms |");
        } else {
            print!(" {p} ms | {p} / umbra |");
        }
    }
    println!(" all correct? |");
    print!("|---:|---:|");
    for p in &peers {
        print!("{}", if *p == "umbra" { "---:|" } else { "---:|---:|" });
    }
    println!("---|");
    for (case, row, _) in &rows {
        let umbra = row
            .iter()
            .find(|m| m.peer == "umbra")
            .map(|m| m.median.as_secs_f64());
        print!("| {} | {:e} |", case.n, case.alpha_deg);
        let mut wrong = Vec::new();
        for m in row {
            let ok = matches!(&m.stats, Ok(s) if s.is_exact_union(case));
            if !ok {
                wrong.push(m.peer);
            }
            let mark = if ok { "" } else { " ✗" };
            if m.peer == "umbra" {
                print!(" {}{mark} |", ms(m.median));
            } else {
                let ratio = umbra.map_or_else(
                    || "-".to_string(),
                    |u| format!("{:.2}", m.median.as_secs_f64() / u.max(1e-12)),
                );
                print!(" {}{mark} | {ratio} |", ms(m.median));
            }
        }
        if wrong.is_empty() {
            println!(" yes |");
        } else {
            println!(" wrong: {} |", wrong.join(", "));
        }
    }
    println!();

    // Details: one line per row and peer.
    println!("| n | alpha (deg) | peer | median ms | runs | result (expected 1 ring, 4n v, exact area) |");
    println!("|---:|---:|---|---:|---:|---|");
    for (case, row, _) in &rows {
        for m in row {
            println!(
                "| {} | {:e} | {} | {} | {} | {} |",
                case.n,
                case.alpha_deg,
                m.peer,
                ms(m.median),
                m.runs,
                verdict(m, case)
            );
        }
    }
    println!();
    println!("| n | alpha (deg) | umbra X11 != 0 pairs (expected 2n) | umbra loops() ms (not timed above) |");
    println!("|---:|---:|---:|---:|");
    for (case, _, extras) in &rows {
        let Some((loops, intersections)) = extras else {
            continue;
        };
        println!(
            "| {} | {:e} | {} | {} |",
            case.n,
            case.alpha_deg,
            intersections,
            ms(*loops)
        );
    }
}
