//! `umbra csg SCRIPT.json -o OUT`: evaluates a CSG tree of primitives,
//! files and Booleans (the JSON form below) with the 3D Boolean, batched and
//! in parallel, deterministic whatever the thread count. `Evaluation`
//! also serves `umbra boolean` with more than two 3D operands.

use super::{csg_options, millis_since, smooth_result, tolerance_arg, warn_f32_defects};
use crate::files::OutputArgs;
use crate::progress::Progress;
use crate::stdout::outln;
use std::path::PathBuf;
use std::process::ExitCode;
use std::time::Instant;
use anyhow::Context;
use umbra::{
    encode_mesh_with, evaluate_csg_with_progress, read_csg_file, CsgNode, FileKind,
    WrittenMeshReport,
};

/// The script form, shown by `umbra csg --help`.
const SCRIPT_HELP: &str = "\
SCRIPT FORM (JSON; every node is one object):
  {\"op\": \"union\"|\"intersection\"|\"difference\", \"children\": [node, ...]}
      difference: the first child minus all the others
  {\"box\": {\"size\": [x, y, z], \"center\": false}}
      corner at the origin unless centred
  {\"sphere\": {\"radius\": r, \"segments\": n}}            centred (UV sphere)
  {\"cylinder\": {\"radius\": r, \"radius_top\": r2, \"height\": h, \"segments\": n, \"center\": false}}
      axis z, from z = 0 unless centred; radius_top optional (cones: 0 allowed)
  {\"torus\": {\"radius\": R, \"tube\": r, \"segments\": [n, m]}}   axis z, centred
  {\"file\": \"relative/path.stl\"}    a mesh file, relative to the script's folder
Any node may carry \"translate\": [x, y, z], \"rotate\": [ax, ay, az] (degrees,
about x, then y, then z) and \"scale\": s or [sx, sy, sz], applied in the order
scale, rotate, translate.

EXAMPLE:
  {\"op\": \"difference\", \"children\": [
     {\"box\": {\"size\": [2, 2, 2], \"center\": true}},
     {\"cylinder\": {\"radius\": 0.5, \"height\": 3, \"segments\": 32, \"center\": true}}]}

See examples/*.json.";

/// Evaluate a CSG script (JSON tree of primitives, files and Booleans) and
/// write the resulting mesh.
#[derive(clap::Args, Debug)]
#[command(after_long_help = SCRIPT_HELP)]
pub struct CsgArgs {
    /// The script (JSON; `umbra csg --help` shows the form).
    script: PathBuf,
    #[command(flatten)]
    out: OutputArgs,
    /// Run the triangle-mesh variant of the 3D Boolean (every leaf and
    /// every result triangulated, section 4.8); the output is triangles.
    /// Implied when the output is .stl, .3mf, .glb or .gltf (formats of
    /// triangles only).
    #[arg(long)]
    triangulate: bool,
    /// No progress bar and no summary on standard output.
    #[arg(long)]
    quiet: bool,
    /// Smooth the result once, at the end, at this tolerance (Appendix
    /// A), near where the Booleans' operands met (as `umbra boolean`
    /// does; `umbra smooth` cleans a whole mesh). Default: 1e-9 times the
    /// result's largest bounding-box extent; `--smooth 0` writes the
    /// Booleans' raw output.
    #[arg(long, value_name = "T", value_parser = tolerance_arg)]
    smooth: Option<f64>,
}

impl CsgArgs {
    /// Parses, evaluates, writes the mesh (and the report), prints a summary.
    pub fn run(self) -> anyhow::Result<ExitCode> {
        let kind = FileKind::from_path(&self.out.output)?;
        self.out
            .refuse_overlaps(&[("the script", self.script.as_path())])?;
        let tree = read_csg_file(&self.script)?;
        // The mesh files the script reads are inputs too.
        let leaves: Vec<(&str, &std::path::Path)> =
            tree.files().into_iter().map(|p| ("a file of the script", p)).collect();
        self.out.refuse_overlaps(&leaves)?;
        let evaluation = Evaluation {
            triangulate: self.triangulate || kind.holds_triangles_only(),
            smooth: self.smooth,
            quiet: self.quiet,
        };
        evaluation.run(&tree, kind, &self.out, &self.script.display().to_string())
    }
}

/// How a CSG tree is evaluated and written: by `umbra csg`, and by
/// `umbra boolean` for more than two 3D operands (one operation node over
/// the files).
pub(super) struct Evaluation {
    /// The triangle-mesh variant.
    pub(super) triangulate: bool,
    /// `--smooth`.
    pub(super) smooth: Option<f64>,
    /// No progress bar and no summary.
    pub(super) quiet: bool,
}

impl Evaluation {
    /// Evaluates `tree`, smooths the result, writes it as `kind` (and the
    /// report) and prints a summary; evaluation errors are given the
    /// context `source` (the script, or the command's operands).
    pub(super) fn run(
        &self,
        tree: &CsgNode,
        kind: FileKind,
        out: &OutputArgs,
        source: &str,
    ) -> anyhow::Result<ExitCode> {
        let start = Instant::now();
        let triangulate = self.triangulate;
        let bar = Progress::new(tree.boolean_count(), self.quiet);
        let result = evaluate_csg_with_progress(
            tree,
            csg_options(triangulate, self.smooth),
            Some(&|done, _| bar.set(done)),
        );
        bar.finish();
        // Evaluation errors name the node; the source names the file(s).
        let result = result.with_context(|| source.to_string())?;
        let result = smooth_result(result, triangulate, self.smooth)?;
        let file = out.output.display().to_string();
        // The report describes the file: for a format of `f32`
        // coordinates, the mesh as rounded and repaired; for facets split
        // into triangles, the triangles.
        let encoded = encode_mesh_with(kind, &result.mesh, out.mesh_options(), &file)?;
        let report = result.report.written_as(&encoded);
        out.write(&encoded.bytes, &report)?;
        if let Some(rounded) = &encoded.rounded {
            warn_f32_defects(&rounded.report, &out.output);
        }
        if !self.quiet {
            let r = &report;
            let near = if r.smoothed_near_contacts == Some(true) {
                " near the contacts"
            } else {
                ""
            };
            let smoothing = r.smoothing.as_ref().map_or(String::new(), |s| {
                format!("; {}", super::smooth::summary(s)).replacen(
                    "smoothed at",
                    &format!("smoothed{near} at"),
                    1,
                )
            });
            outln!(
                "{file}: {} Booleans ({} variant) in {:.1} ms{smoothing}; {} vertices, {} facets; {}; volume {}",
                r.booleans,
                r.variant,
                millis_since(start),
                r.vertices,
                r.facets,
                if r.topologically_valid {
                    "topologically valid"
                } else {
                    "NOT topologically valid"
                },
                r.volume
            )?;
        }
        if report.topologically_valid {
            Ok(ExitCode::SUCCESS)
        } else {
            Err(super::invalid_result())
        }
    }
}
