//! `cargo xtask <task>`: Umbra developer tasks (see the library docs).
//!
//! ```text
//! cargo xtask tidy
//! cargo xtask arith-experiment [--pairs N] [--seed S]
//! cargo xtask verify [--cases N] [--seed S]
//! ```

use anyhow::{bail, Context, Result};
use std::process::ExitCode;
use xtask::{experiment, tidy, verify, verify3, verify_smooth};

const USAGE: &str = "usage: cargo xtask <task>

tasks:
  tidy                                   dependency direction (docs/ARCHITECTURE.md), unused
                                         dependencies, //! headers, no reference outside
                                         the repository
  arith-experiment [--pairs N] [--seed S]  section 8.3 experiment (default N = 10000000)
  verify [--suite 2d|3d|simplify|smooth|all] [--cases N] [--seed S]
                                         2D: Theorems 1-2, closure, eq. 4.20 (default N = 2000);
                                         3D: Theorems 1-4 by Audit::verify (N = 300);
                                         simplify: cell structure, closure, vertex bound (N = 500)
  fingerprint [--cases N] [--seed S]     digests of every result over the verify corpora
                                         (default N = 200): equal lines before and after
                                         a refactoring mean unchanged results";

/// Parses `--name value` options into `u64`s, rejecting unknown ones.
fn options(args: &[String], known: &[(&str, u64)]) -> Result<Vec<u64>> {
    let mut values: Vec<u64> = known.iter().map(|k| k.1).collect();
    let mut i = 0;
    while i < args.len() {
        let Some(k) = known.iter().position(|k| k.0 == args[i]) else {
            bail!("unknown argument '{}'\n\n{USAGE}", args[i]);
        };
        let v = args
            .get(i + 1)
            .with_context(|| format!("{} needs a value", args[i]))?;
        values[k] = v
            .replace('_', "")
            .parse()
            .with_context(|| format!("{} {v}: not a non-negative integer", args[i]))?;
        i += 2;
    }
    Ok(values)
}

fn run(args: &[String]) -> Result<bool> {
    let Some(task) = args.first() else {
        bail!("{USAGE}");
    };
    let rest = &args[1..];
    match task.as_str() {
        "tidy" => {
            options(rest, &[])?;
            tidy::tidy(&tidy::workspace_root())?;
            println!("tidy: ok (dependency directions, //! headers)");
            Ok(true)
        }
        "arith-experiment" => {
            let v = options(rest, &[("--pairs", 10_000_000), ("--seed", 1)])?;
            let start = std::time::Instant::now();
            let r = experiment::run(v[0] as usize, v[1]);
            experiment::print(&r, v[1]);
            println!("  ({:.1} s)", start.elapsed().as_secs_f64());
            Ok(r.beyond_bound == 0 && r.path_mismatches == 0)
        }
        "verify" => {
            let suite_name = rest
                .iter()
                .position(|a| a == "--suite")
                .and_then(|i| rest.get(i + 1))
                .cloned()
                .unwrap_or_else(|| "all".into());
            let rest: Vec<String> = match rest.iter().position(|a| a == "--suite") {
                Some(i) => rest[..i]
                    .iter()
                    .chain(rest.iter().skip(i + 2))
                    .cloned()
                    .collect(),
                None => rest.to_vec(),
            };
            let v = options(&rest, &[("--cases", 0), ("--seed", 1)])?;
            let pick = |default: u64| {
                if v[0] == 0 {
                    default as usize
                } else {
                    v[0] as usize
                }
            };
            let mut failures = 0;
            let known = ["all", "2d", "3d", "simplify", "smooth"];
            if !known.contains(&suite_name.as_str()) {
                bail!("unknown suite '{suite_name}' (2d, 3d, simplify, smooth or all)");
            }
            if matches!(suite_name.as_str(), "all" | "2d") {
                let suite = verify::boolean_2d_suite();
                let n = pick(2000);
                failures += suite.print(&suite.run(n, v[1]), n, v[1]);
            }
            if matches!(suite_name.as_str(), "all" | "3d") {
                let suite = verify3::boolean_3d_suite();
                let n = pick(300);
                failures += suite.print(&suite.run(n, v[1]), n, v[1]);
            }
            if matches!(suite_name.as_str(), "all" | "simplify") {
                let suite = verify3::simplify_suite();
                let n = pick(500);
                failures += suite.print(&suite.run(n, v[1]), n, v[1]);
            }
            if matches!(suite_name.as_str(), "all" | "smooth") {
                let suite = verify_smooth::smooth_3d_suite();
                let n = pick(200);
                failures += suite.print(&suite.run(n, v[1]), n, v[1]);
                let suite = verify_smooth::smooth_2d_suite();
                let n = pick(300);
                failures += suite.print(&suite.run(n, v[1]), n, v[1]);
            }
            if failures > 0 {
                println!("verify: {failures} failure(s)");
            } else {
                println!("verify: all checks passed");
            }
            Ok(failures == 0)
        }
        "fingerprint" => {
            let v = options(rest, &[("--cases", 200), ("--seed", 1)])?;
            for line in xtask::fingerprint::run(v[0] as usize, v[1]) {
                println!("{line}");
            }
            Ok(true)
        }
        "-h" | "--help" | "help" => {
            println!("{USAGE}");
            Ok(true)
        }
        other => bail!("unknown task '{other}'\n\n{USAGE}"),
    }
}

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    match run(&args) {
        Ok(true) => ExitCode::SUCCESS,
        Ok(false) => ExitCode::FAILURE,
        Err(e) => {
            eprintln!("error: {e:#}");
            ExitCode::from(2)
        }
    }
}
