//! The `umbra` command-line tool (the CLI contract of DESIGN.md):
//!
//! ```text
//! umbra boolean <union|intersection|difference|xor> A B -o OUT [--report R.json]
//!       [--keep-orientation] [--via basic|simplify] [--triangulate]
//! umbra simplify IN -o OUT [--rule positive|nonzero|evenodd|negative|at-least-2]
//!       [--keep-orientation] [--report R.json]
//! umbra check IN [--json] [--keep-orientation]
//! ```
//!
//! The file extension decides the dimension: `.wkt` and `.geojson` are 2D
//! polygon sets, `.obj` and `.off` are 3D meshes. 2D Booleans run the basic
//! Boolean of chapter 4 by default and through simplification (chapter 6,
//! which also resolves self-intersecting input and offers `xor`) with
//! `--via simplify`; 3D Booleans run the polygon-mesh variant, or the
//! triangle-mesh variant with `--triangulate` (section 4.8; operands that
//! are not triangle meshes are triangulated by internal edges first). The
//! report's `variant` names the variant that ran.
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
    boolean, boolean_mesh, boolean_triangles, check_mesh, check_polygon_set, read_mesh,
    read_polygon_set, triangulate_mesh, write_mesh, write_polygon_set, Boolean3Error, BooleanError,
    BooleanOp, FileKind, FillRule, MeshReadOptions, Operand, PolygonMesh, PolygonSet2, ReadOptions,
    RingOrientation, SimplifyError, TriangleMesh, UmbraError,
};

/// Topologically robust Boolean operations on polygon sets and polyhedra
/// (plain f64 arithmetic). `.wkt`/`.geojson` files are 2D, `.obj`/`.off` 3D.
#[derive(Parser, Debug)]
#[command(name = "umbra", version, about, propagate_version = true)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand, Debug)]
enum Command {
    /// Union, intersection, difference (or, via simplify, xor) of two files
    /// of the same dimension (.wkt/.geojson or .obj/.off).
    Boolean {
        /// The operation.
        #[arg(value_enum)]
        op: OpArg,
        /// The first operand, A.
        a: PathBuf,
        /// The second operand, B.
        b: PathBuf,
        /// The output file (its extension picks the format).
        #[arg(short, long)]
        output: PathBuf,
        /// Write a JSON report (counts, validity, epsilon, timings) here.
        #[arg(long)]
        report: Option<PathBuf>,
        /// 2D: read every ring as a directed loop exactly as written and
        /// write every loop as its own polygon (keeps inside-out and
        /// multiply enclosed shapes); by default rings are read by role.
        #[arg(long)]
        keep_orientation: bool,
        /// 2D: the algorithm. `basic` is the basic Boolean of chapter 4
        /// (tolerates invalid input); `simplify` assembles both boundaries
        /// and simplifies (chapter 6: resolves self-intersections).
        #[arg(long, value_enum, default_value = "basic")]
        via: Via,
        /// 3D: run the triangle-mesh variant (section 4.8) instead of the
        /// polygon-mesh one: operands with other facets are triangulated by
        /// internal edges first, and the output is triangles.
        #[arg(long)]
        triangulate: bool,
    },
    /// Simplify a 2D polygon file by a winding-number fill rule (chapters
    /// 6-7): the result is geometrically valid up to the reported epsilon.
    Simplify {
        /// The input file (.wkt or .geojson).
        input: PathBuf,
        /// The output file (.wkt or .geojson).
        #[arg(short, long)]
        output: PathBuf,
        /// Which winding numbers are inside.
        #[arg(long, value_enum, default_value = "positive")]
        rule: RuleArg,
        /// Read every ring as a directed loop exactly as written (winding
        /// rules on invalid input need it) and write loops as they are.
        #[arg(long)]
        keep_orientation: bool,
        /// Write a JSON report (counts, validity, epsilon, k_max, timings).
        #[arg(long)]
        report: Option<PathBuf>,
    },
    /// Check a file: topological validity, coordinates, and geometric
    /// validity hints (2D: crossing edges; 3D: 2-manifoldness,
    /// self-intersecting facet pairs, signed volume).
    Check {
        /// The file to check.
        input: PathBuf,
        /// Print the report as JSON.
        #[arg(long)]
        json: bool,
        /// 2D: read every ring as written instead of by role.
        #[arg(long)]
        keep_orientation: bool,
    },
}

/// The Boolean operations, as named on the command line.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
enum OpArg {
    Union,
    Intersection,
    Difference,
    /// Symmetric difference (2D, with --via simplify only).
    Xor,
}

impl OpArg {
    fn name(self) -> &'static str {
        match self {
            OpArg::Union => "union",
            OpArg::Intersection => "intersection",
            OpArg::Difference => "difference",
            OpArg::Xor => "xor",
        }
    }
    fn basic(self) -> Option<BooleanOp> {
        match self {
            OpArg::Union => Some(BooleanOp::Union),
            OpArg::Intersection => Some(BooleanOp::Intersection),
            OpArg::Difference => Some(BooleanOp::Difference),
            OpArg::Xor => None,
        }
    }
    fn solid(self) -> Option<BooleanOp> {
        match self {
            OpArg::Union => Some(BooleanOp::Union),
            OpArg::Intersection => Some(BooleanOp::Intersection),
            OpArg::Difference => Some(BooleanOp::Difference),
            OpArg::Xor => None,
        }
    }
    fn swept(self) -> simplify_2d::BooleanOp {
        match self {
            OpArg::Union => simplify_2d::BooleanOp::Union,
            OpArg::Intersection => simplify_2d::BooleanOp::Intersection,
            OpArg::Difference => simplify_2d::BooleanOp::Difference,
            OpArg::Xor => simplify_2d::BooleanOp::Xor,
        }
    }
}

/// The 2D algorithm.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
enum Via {
    /// The basic Boolean (chapter 4).
    Basic,
    /// Through simplification (chapter 6).
    Simplify,
}

/// The fill rules of section 6.1.
#[derive(Clone, Copy, Debug, ValueEnum)]
enum RuleArg {
    /// Winding number > 0 (the standard form).
    Positive,
    /// Winding number != 0.
    Nonzero,
    /// Odd winding number.
    Evenodd,
    /// Winding number < 0 (inside-out regions).
    Negative,
    /// Winding number >= 2.
    #[value(name = "at-least-2")]
    AtLeast2,
}

impl RuleArg {
    fn rule(self) -> FillRule {
        match self {
            RuleArg::Positive => FillRule::Positive,
            RuleArg::Nonzero => FillRule::NonZero,
            RuleArg::Evenodd => FillRule::EvenOdd,
            RuleArg::Negative => FillRule::Negative,
            RuleArg::AtLeast2 => FillRule::AtLeast2,
        }
    }
    fn name(self) -> &'static str {
        match self {
            RuleArg::Positive => "positive",
            RuleArg::Nonzero => "nonzero",
            RuleArg::Evenodd => "evenodd",
            RuleArg::Negative => "negative",
            RuleArg::AtLeast2 => "at-least-2",
        }
    }
}

/// A usage error found after parsing: exit code 2, like clap's own.
#[derive(Debug)]
struct Usage(String);

impl std::fmt::Display for Usage {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for Usage {}

fn usage(msg: impl Into<String>) -> anyhow::Error {
    Usage(msg.into()).into()
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
            // An UmbraError's Display is already complete (file, problem
            // and cause on one line); other errors print their chain.
            let text = if e.downcast_ref::<UmbraError>().is_some() {
                format!("{e}")
            } else {
                format!("{e:#}")
            };
            eprintln!("umbra: {}", text.replace(['\n', '\r'], " "));
            if e.downcast_ref::<Usage>().is_some() {
                ExitCode::from(2)
            } else {
                ExitCode::from(1)
            }
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
            via,
            triangulate,
        } => {
            let kinds = [
                FileKind::from_path(&a)?,
                FileKind::from_path(&b)?,
                FileKind::from_path(&output)?,
            ];
            let meshes = kinds.iter().filter(|k| k.is_mesh()).count();
            if meshes != 0 && meshes != 3 {
                return Err(usage(
                    "A, B and the output must all be 2D files (.wkt, .geojson) or all 3D files (.obj, .off)",
                ));
            }
            if meshes == 3 {
                if via == Via::Simplify {
                    return Err(usage("--via simplify is for 2D files only"));
                }
                if keep_orientation {
                    return Err(usage("--keep-orientation is for 2D files only"));
                }
                let op3 = op.solid().ok_or_else(|| {
                    usage("xor is only available for 2D files with --via simplify")
                })?;
                run_boolean_3d(op3, &a, &b, &output, report.as_deref(), triangulate)
            } else {
                if triangulate {
                    return Err(usage("--triangulate is for 3D files (.obj, .off) only"));
                }
                match via {
                    Via::Basic => {
                        let op2 = op.basic().ok_or_else(|| {
                            usage("xor needs --via simplify (the basic Boolean has union, intersection, difference)")
                        })?;
                        run_boolean(op2, &a, &b, &output, report.as_deref(), keep_orientation)
                    }
                    Via::Simplify => {
                        run_boolean_swept(op, &a, &b, &output, report.as_deref(), keep_orientation)
                    }
                }
            }
        }
        Command::Simplify {
            input,
            output,
            rule,
            keep_orientation,
            report,
        } => run_simplify(&input, &output, rule, keep_orientation, report.as_deref()),
        Command::Check {
            input,
            json,
            keep_orientation,
        } => {
            if FileKind::from_path(&input)?.is_mesh() {
                run_check_3d(&input, json)
            } else {
                run_check_2d(&input, json, keep_orientation)
            }
        }
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

/// The file name and counts of a mesh, for reports.
fn mesh_counts(file: &Path, mesh: &PolygonMesh) -> Value {
    json!({
        "file": file.display().to_string(),
        "vertices": mesh.vertices.len(),
        "facets": mesh.facets.len(),
        "half_edges": mesh.half_edge_count(),
        "signed_volume": umbra::mesh_signed_volume(mesh),
    })
}

fn millis(d: Duration) -> f64 {
    d.as_secs_f64() * 1e3
}

/// Writes a report file, naming it on failure.
fn write_report(path: Option<&Path>, value: &Value) -> Result<()> {
    if let Some(path) = path {
        let text = serde_json::to_string_pretty(value)
            .context("internal error: cannot serialise the report")?;
        std::fs::write(path, text + "\n").map_err(|source| UmbraError::Io {
            file: path.display().to_string(),
            action: "write",
            source,
        })?;
    }
    Ok(())
}

/// Names the operand's file in an error.
fn operand_file(operand: Option<Operand>, a: &Path, b: &Path) -> String {
    match operand {
        Some(Operand::A) => a.display().to_string(),
        Some(Operand::B) => b.display().to_string(),
        None => String::new(),
    }
}

fn warn_orphans(orphans: usize, out_path: &Path) {
    if orphans > 0 {
        eprintln!(
            "umbra: warning: {}: {orphans} clockwise ring(s) lie inside no outer ring (inside-out result); rerun with --keep-orientation to keep their direction",
            out_path.display()
        );
    }
}

fn run_boolean(
    op: BooleanOp,
    a_path: &Path,
    b_path: &Path,
    out_path: &Path,
    report: Option<&Path>,
    keep: bool,
) -> Result<ExitCode> {
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
        let operand = match &source {
            BooleanError::InvalidInput { operand, .. } => Some(*operand),
            _ => None,
        };
        UmbraError::Boolean {
            file: operand_file(operand, a_path, b_path),
            source,
        }
    })?;

    let orphans = write_polygon_set(out_path, &out.shape, orientation(keep))?;
    warn_orphans(orphans, out_path);
    let valid = out.shape.check_topology();
    let t = out.timings;
    let mut timings = Map::new();
    timings.insert("total".into(), json!(millis(total)));
    for (name, ms) in [
        ("validate", t.validate),
        ("broad_phase", t.broad_phase),
        ("intersections", t.intersections),
        ("winding_numbers", t.winding),
        ("construct", t.construct),
    ] {
        timings.insert(name.into(), json!(ms));
    }
    let report_value = json!({
        "operation": op.name(),
        "algorithm": "basic Boolean (chapter 4)",
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
    write_report(report, &report_value)?;
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

/// The report fields of a simplification result.
fn swept_report(out: &umbra::Simplified, total: Duration) -> (Value, Value) {
    let s = &out.stats;
    let stats = json!({
        "input_edges": s.input_edges,
        "merged_input_edges": s.merged_input_edges,
        "events": s.events,
        "intersections": s.intersections,
        "vertex_on_edge_splits": s.vertex_on_edge_splits,
        "misgrouped_splits": s.misgrouped_splits,
        "full_scans": s.full_scans,
        "max_sweep_len": s.max_sweep_len,
    });
    (stats, json!({ "total": millis(total) }))
}

fn simplify_error(source: SimplifyError, files: &[&Path]) -> UmbraError {
    let file = match &source {
        SimplifyError::InvalidInput { operand, .. } => files
            .get(*operand)
            .map(|p| p.display().to_string())
            .unwrap_or_default(),
        SimplifyError::Internal(_) => String::new(),
    };
    UmbraError::Simplify { file, source }
}

fn run_boolean_swept(
    op: OpArg,
    a_path: &Path,
    b_path: &Path,
    out_path: &Path,
    report: Option<&Path>,
    keep: bool,
) -> Result<ExitCode> {
    let options = ReadOptions {
        orientation: orientation(keep),
        ..ReadOptions::default()
    };
    let a = read_polygon_set(a_path, options)?;
    let b = read_polygon_set(b_path, options)?;
    let start = Instant::now();
    let result = simplify_2d::boolean(&a, &b, op.swept());
    let total = start.elapsed();
    let out = result.map_err(|e| simplify_error(e, &[a_path, b_path]))?;
    let orphans = write_polygon_set(out_path, &out.shape, orientation(keep))?;
    warn_orphans(orphans, out_path);
    let valid = out.shape.check_topology();
    let (stats, timings) = swept_report(&out, total);
    let report_value = json!({
        "operation": op.name(),
        "algorithm": "Boolean through simplification (chapter 6)",
        "keep_orientation": keep,
        "inputs": { "a": counts(a_path, &a), "b": counts(b_path, &b) },
        "output": counts(out_path, &out.shape),
        "topologically_valid": valid.is_ok(),
        "topology_error": valid.as_ref().err().map(ToString::to_string),
        "epsilon": out.epsilon,
        "k_max": out.k_max,
        "sweep": stats,
        "timings_ms": timings,
    });
    write_report(report, &report_value)?;
    println!(
        "{} (via simplify): {} vertices, {} rings, k_max {}, epsilon {:e}, {:.3} ms -> {}",
        op.name(),
        out.shape.vertex_count(),
        report_value["output"]["rings"],
        out.k_max,
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

fn run_simplify(
    in_path: &Path,
    out_path: &Path,
    rule: RuleArg,
    keep: bool,
    report: Option<&Path>,
) -> Result<ExitCode> {
    for p in [in_path, out_path] {
        if FileKind::from_path(p)?.is_mesh() {
            return Err(usage("simplify works on 2D files (.wkt, .geojson)"));
        }
    }
    let options = ReadOptions {
        orientation: orientation(keep),
        ..ReadOptions::default()
    };
    let set = read_polygon_set(in_path, options)?;
    let start = Instant::now();
    let result = simplify_2d::simplify(&set, rule.rule());
    let total = start.elapsed();
    let out = result.map_err(|e| simplify_error(e, &[in_path]))?;
    let orphans = write_polygon_set(out_path, &out.shape, orientation(keep))?;
    warn_orphans(orphans, out_path);
    let valid = out.shape.check_topology();
    let (stats, timings) = swept_report(&out, total);
    let report_value = json!({
        "operation": "simplify",
        "rule": rule.name(),
        "keep_orientation": keep,
        "input": counts(in_path, &set),
        "output": counts(out_path, &out.shape),
        "topologically_valid": valid.is_ok(),
        "topology_error": valid.as_ref().err().map(ToString::to_string),
        "epsilon": out.epsilon,
        "k_max": out.k_max,
        "sweep": stats,
        "timings_ms": timings,
    });
    write_report(report, &report_value)?;
    println!(
        "simplify ({}): {} vertices, {} rings, k_max {}, epsilon {:e}, {:.3} ms -> {}",
        rule.name(),
        out.shape.vertex_count(),
        report_value["output"]["rings"],
        out.k_max,
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

/// `Some(triangles)` when every facet is one loop of three half-edges (the
/// operand is already a triangle mesh).
fn as_triangles(mesh: &PolygonMesh) -> Option<TriangleMesh> {
    let mut tris = Vec::with_capacity(mesh.facets.len());
    for f in &mesh.facets {
        let h = &f.half_edges;
        if h.len() != 3
            || h[0].end != h[1].start
            || h[1].end != h[2].start
            || h[2].end != h[0].start
        {
            return None;
        }
        tris.push([h[0].start, h[1].start, h[2].start]);
    }
    Some(TriangleMesh::new(mesh.vertices.clone(), tris))
}

fn run_boolean_3d(
    op: BooleanOp,
    a_path: &Path,
    b_path: &Path,
    out_path: &Path,
    report: Option<&Path>,
    triangulate: bool,
) -> Result<ExitCode> {
    let a = read_mesh(a_path, MeshReadOptions::default(), true)?;
    let b = read_mesh(b_path, MeshReadOptions::default(), true)?;
    let err3 = |source: Boolean3Error| {
        let operand = match &source {
            Boolean3Error::InvalidInput { operand, .. } => Some(match operand {
                boolean_3d::Operand::A => Operand::A,
                boolean_3d::Operand::B => Operand::B,
            }),
            _ => None,
        };
        UmbraError::Boolean3 {
            file: operand_file(operand, a_path, b_path),
            source,
        }
    };
    let mut timings = Map::new();
    let start = Instant::now();
    // With --triangulate the triangle-mesh variant runs (section 4.8:
    // triangles in, every retained facet triangulated by internal edges
    // only). An operand with other facets is first triangulated the same
    // way, which keeps it closed, so that variant runs whatever the input.
    let (mesh, intersections, variant, triangulated) = if triangulate {
        let t = Instant::now();
        let ta = as_triangles(&a);
        let tb = as_triangles(&b);
        let triangulated = json!({ "a": ta.is_none(), "b": tb.is_none() });
        let ta = ta.unwrap_or_else(|| triangulate_mesh(&a));
        let tb = tb.unwrap_or_else(|| triangulate_mesh(&b));
        timings.insert("triangulate_inputs".into(), json!(millis(t.elapsed())));
        let out = boolean_triangles(&ta, &tb, op).map_err(err3)?;
        (
            out.mesh.to_polygon_mesh(),
            out.intersections,
            "triangle mesh",
            triangulated,
        )
    } else {
        let out = boolean_mesh(&a, &b, op).map_err(err3)?;
        (
            out.mesh,
            out.intersections,
            "polygon mesh",
            json!({ "a": false, "b": false }),
        )
    };
    let total = start.elapsed();
    timings.insert("total".into(), json!(millis(total)));
    write_mesh(out_path, &mesh)?;
    let valid = mesh.check_topology();
    let report_value = json!({
        "operation": op.name(),
        "variant": variant,
        "inputs_triangulated": triangulated,
        "inputs": { "a": mesh_counts(a_path, &a), "b": mesh_counts(b_path, &b) },
        "output": mesh_counts(out_path, &mesh),
        "intersections": intersections,
        "topologically_valid": valid.is_ok(),
        "topology_error": valid.as_ref().err().map(ToString::to_string),
        "timings_ms": Value::Object(timings),
    });
    write_report(report, &report_value)?;
    println!(
        "{} ({variant}): {} vertices, {} facets, {} edge-facet intersections, volume {}, {:.3} ms -> {}",
        op.name(),
        mesh.vertices.len(),
        mesh.facets.len(),
        intersections,
        report_value["output"]["signed_volume"],
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

fn run_check_3d(path: &Path, json_out: bool) -> Result<ExitCode> {
    let options = MeshReadOptions {
        validate_coordinates: false,
    };
    let mesh = read_mesh(path, options, false)?;
    let r = check_mesh(&mesh);
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
            "  vertices: {}, facets: {}, half-edges: {}, edges: {}",
            r.vertices, r.facets, r.half_edges, r.edges
        );
        match &r.coordinate_error {
            None => println!("  coordinates: valid (finite, |c| <= f64::MAX/4)"),
            Some(e) => println!("  coordinates: INVALID: {e}"),
        }
        if let Some(m) = r.two_manifold {
            println!(
                "  2-manifold: {} ({} non-manifold edges, {} non-manifold vertices)",
                if m { "yes" } else { "no" },
                r.non_manifold_edges.unwrap_or(0),
                r.non_manifold_vertices.unwrap_or(0)
            );
        }
        if let Some(n) = r.self_intersecting_facet_pairs {
            println!("  self-intersecting facet pairs: {n}");
        }
        if let Some(v) = r.signed_volume {
            println!("  signed volume: {v}");
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

fn run_check_2d(path: &Path, json_out: bool, keep: bool) -> Result<ExitCode> {
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
