//! The `umbra` command-line tool (the CLI contract of DESIGN.md):
//!
//! ```text
//! umbra boolean <union|intersection|difference> A.wkt B.wkt -o OUT.wkt [--report R.json] [--keep-orientation]
//! umbra check IN.wkt [--json] [--keep-orientation]
//! ```
//!
//! Exit codes: 0 success, 1 bad input (a one-line message on stderr naming
//! the file and the problem), 2 usage error (from clap).

use anyhow::{Context, Result};
use clap::{Parser, Subcommand, ValueEnum};
use serde_json::{json, Map, Value};
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::{Duration, Instant};
use umbra::{
    boolean, check_polygon_set, read_polygon_set, write_polygon_set, BooleanError, BooleanOp,
    FileKind, Operand, PolygonSet2, ReadOptions, RingOrientation, UmbraError,
};

/// Topologically robust Boolean operations on polygon sets (f64 arithmetic).
#[derive(Parser, Debug)]
#[command(name = "umbra", version, about, propagate_version = true)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand, Debug)]
enum Command {
    /// Union, intersection or difference of two polygon files (.wkt).
    Boolean {
        /// The operation.
        #[arg(value_enum)]
        op: OpArg,
        /// The first operand, A.
        a: PathBuf,
        /// The second operand, B.
        b: PathBuf,
        /// The output file (.wkt).
        #[arg(short, long)]
        output: PathBuf,
        /// Write a JSON report (counts, validity, epsilon, timings) here.
        #[arg(long)]
        report: Option<PathBuf>,
        /// Read every ring as a directed loop exactly as written and write
        /// every loop as its own polygon (keeps inside-out and multiply
        /// enclosed shapes); by default rings are read by role.
        #[arg(long)]
        keep_orientation: bool,
    },
    /// Check a polygon file: topological validity, coordinates, crossings.
    Check {
        /// The file to check (.wkt).
        input: PathBuf,
        /// Print the report as JSON.
        #[arg(long)]
        json: bool,
        /// Read every ring as written instead of by role.
        #[arg(long)]
        keep_orientation: bool,
    },
}

/// The Boolean operations, as named on the command line.
#[derive(Clone, Copy, Debug, ValueEnum)]
enum OpArg {
    Union,
    Intersection,
    Difference,
}

impl From<OpArg> for BooleanOp {
    fn from(op: OpArg) -> Self {
        match op {
            OpArg::Union => BooleanOp::Union,
            OpArg::Intersection => BooleanOp::Intersection,
            OpArg::Difference => BooleanOp::Difference,
        }
    }
}

fn main() -> ExitCode {
    // A panic is a bug; report it on one line instead of a backtrace dump.
    std::panic::set_hook(Box::new(|info| {
        let msg = info
            .payload()
            .downcast_ref::<&str>()
            .map(|s| s.to_string())
            .or_else(|| info.payload().downcast_ref::<String>().cloned())
            .unwrap_or_default();
        let at = info
            .location()
            .map(|l| format!(" at {}:{}", l.file(), l.line()))
            .unwrap_or_default();
        eprintln!(
            "umbra: internal error (this is a bug, please report it): {}{at}",
            msg.replace('\n', " ")
        );
    }));
    let cli = Cli::parse();
    match run(cli) {
        Ok(code) => code,
        Err(e) => {
            eprintln!("umbra: {}", format!("{e:#}").replace(['\n', '\r'], " "));
            ExitCode::from(1)
        }
    }
}

fn run(cli: Cli) -> Result<ExitCode> {
    match cli.command {
        Command::Boolean {
            op,
            a,
            b,
            output,
            report,
            keep_orientation,
        } => run_boolean(
            op.into(),
            &a,
            &b,
            &output,
            report.as_deref(),
            keep_orientation,
        ),
        Command::Check {
            input,
            json,
            keep_orientation,
        } => run_check(&input, json, keep_orientation),
    }
}

fn orientation(keep: bool) -> RingOrientation {
    if keep {
        RingOrientation::AsWritten
    } else {
        RingOrientation::ByRole
    }
}

/// The file name and counts of a set, for reports.
fn counts(file: &Path, set: &PolygonSet2) -> Value {
    json!({
        "file": file.display().to_string(),
        "vertices": set.vertex_count(),
        "edges": set.edge_count(),
        "rings": set.loops().len(),
        "signed_area": set.signed_area(),
    })
}

fn millis(d: Duration) -> f64 {
    d.as_secs_f64() * 1e3
}

fn run_boolean(
    op: BooleanOp,
    a_path: &Path,
    b_path: &Path,
    out_path: &Path,
    report: Option<&Path>,
    keep: bool,
) -> Result<ExitCode> {
    // Fail on an unsupported output type before doing any work.
    FileKind::from_path(out_path)?;
    let options = ReadOptions {
        orientation: orientation(keep),
        ..ReadOptions::default()
    };
    let a = read_polygon_set(a_path, options)?;
    let b = read_polygon_set(b_path, options)?;

    let start = Instant::now();
    let result = boolean(&a, &b, op);
    let total = start.elapsed();
    let out = result.map_err(|source| {
        let file = match &source {
            BooleanError::InvalidInput {
                operand: Operand::A,
                ..
            } => a_path.display().to_string(),
            BooleanError::InvalidInput {
                operand: Operand::B,
                ..
            } => b_path.display().to_string(),
            _ => String::new(),
        };
        UmbraError::Boolean { file, source }
    })?;

    let orphans = write_polygon_set(out_path, &out.shape, orientation(keep))?;
    if orphans > 0 {
        eprintln!(
            "umbra: warning: {}: {orphans} clockwise ring(s) lie inside no outer ring (inside-out result); rerun with --keep-orientation to keep their direction",
            out_path.display()
        );
    }
    let valid = out.shape.check_topology();
    let mut timings = Map::new();
    timings.insert("total".into(), json!(millis(total)));
    for (name, d) in phase_timings(&out) {
        timings.insert(name.into(), json!(millis(d)));
    }
    let report_value = json!({
        "operation": op.name(),
        "keep_orientation": keep,
        "inputs": {
            "a": counts(a_path, &a),
            "b": counts(b_path, &b),
        },
        "output": counts(out_path, &out.shape),
        "intersections": out.intersections,
        "topologically_valid": valid.is_ok(),
        "topology_error": valid.as_ref().err().map(ToString::to_string),
        "epsilon": out.epsilon,
        "timings_ms": Value::Object(timings),
    });
    if let Some(path) = report {
        let text = serde_json::to_string_pretty(&report_value)
            .context("internal error: cannot serialise the report")?;
        std::fs::write(path, text + "\n").map_err(|source| UmbraError::Io {
            file: path.display().to_string(),
            action: "write",
            source,
        })?;
    }
    println!(
        "{}: {} vertices, {} rings, {} intersecting edge pairs, epsilon {:e}, {:.3} ms -> {}",
        op.name(),
        out.shape.vertex_count(),
        report_value["output"]["rings"],
        out.intersections,
        out.epsilon,
        millis(total),
        out_path.display()
    );
    if valid.is_err() {
        anyhow::bail!(
            "internal error (this is a bug, please report it): the result is not topologically valid"
        );
    }
    Ok(ExitCode::SUCCESS)
}

/// The phase timings of the Boolean, when it reports them.
fn phase_timings(_out: &umbra::BooleanOutput) -> Vec<(&'static str, Duration)> {
    Vec::new()
}

fn run_check(path: &Path, json_out: bool, keep: bool) -> Result<ExitCode> {
    let options = ReadOptions {
        orientation: orientation(keep),
        validate_coordinates: false,
    };
    let set = read_polygon_set(path, options)?;
    let r = check_polygon_set(&set);
    let file = path.display().to_string();
    if json_out {
        let mut v =
            serde_json::to_value(&r).context("internal error: cannot serialise the report")?;
        if let Value::Object(m) = &mut v {
            m.insert("file".into(), json!(file));
        }
        println!(
            "{}",
            serde_json::to_string_pretty(&v)
                .context("internal error: cannot serialise the report")?
        );
    } else {
        match &r.topology_error {
            None => println!("{file}: topologically valid"),
            Some(e) => println!("{file}: NOT topologically valid: {e}"),
        }
        println!(
            "  rings: {} ({} counter-clockwise, {} clockwise), vertices: {}, edges: {}",
            r.rings, r.ccw_rings, r.cw_rings, r.vertices, r.edges
        );
        println!("  signed area: {}", r.signed_area);
        match &r.coordinate_error {
            None => println!("  coordinates: valid (finite, |c| <= f64::MAX/4)"),
            Some(e) => println!("  coordinates: INVALID: {e}"),
        }
        if let Some([lo, hi]) = r.bounding_box {
            println!(
                "  bounding box: [{}, {}] x [{}, {}]",
                lo[0], hi[0], lo[1], hi[1]
            );
        }
        match (r.crossing_edge_pairs, r.overlapping_edge_pairs) {
            (Some(c), Some(o)) => println!(
                "  crossing edge pairs: {c}, overlapping edge pairs: {o} ({})",
                if c == 0 && o == 0 {
                    "no crossings: geometrically valid if the rings are oriented with the interior on the left"
                } else {
                    "geometrically invalid; the Booleans still accept it (section 4.7)"
                }
            ),
            _ => println!("  crossing edge pairs: not computed (invalid coordinates)"),
        }
    }
    if r.is_valid() {
        Ok(ExitCode::SUCCESS)
    } else {
        let problem = r
            .coordinate_error
            .as_deref()
            .or(r.topology_error.as_deref())
            .unwrap_or("invalid");
        eprintln!("umbra: {file}: {problem}");
        Ok(ExitCode::from(1))
    }
}
