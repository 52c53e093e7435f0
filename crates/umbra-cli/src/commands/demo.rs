//! `umbra demo [-o DIR]`: no input needed. Builds a small process-plant
//! model (vessels, pipes with flanges, a supporting frame) from built-in
//! primitives through a chain of some hundreds of 3D Booleans, smooths
//! the result once (Appendix A, the default tolerance), writes the
//! mesh, its script and a picture (`plant.png`, iso view) and a report
//! (`report.json`: the evaluation and every other file as written), and
//! prints a validity and timing summary.

use super::{csg_options, millis_since, smooth_result};
use crate::files::write_all;
use crate::progress::Progress;
use crate::stdout::outln;
use std::path::PathBuf;
use std::process::ExitCode;
use std::time::Instant;
use umbra::{
    check_mesh, demo_plant, encode_mesh_with, evaluate_csg_with_progress, render_mesh,
    DemoDetail, DemoReport, FileKind, MeshWriteOptions, RenderOptions, WrittenFile,
};

/// Build the demo model (a process plant of some hundreds of Booleans),
/// write it as meshes (STL, 3MF, OBJ) with its CSG script, a picture and
/// `report.json` (the evaluation, and every file as written), and print a
/// summary.
#[derive(clap::Args, Debug)]
pub struct DemoArgs {
    /// The folder to write into (created if missing).
    #[arg(short, long, default_value = "umbra-demo")]
    output: PathBuf,
    /// Run the triangle-mesh variant of the 3D Boolean.
    #[arg(long)]
    triangulate: bool,
    /// No progress bar.
    #[arg(long)]
    quiet: bool,
}

/// The files written: name and format.
const MESHES: [(&str, FileKind); 3] = [
    ("plant.stl", FileKind::Stl),
    ("plant.3mf", FileKind::ThreeMf),
    ("plant.obj", FileKind::Obj),
];

impl DemoArgs {
    /// Builds, evaluates, checks and writes the model.
    pub fn run(self) -> anyhow::Result<ExitCode> {
        let tree = demo_plant(DemoDetail::Full);
        let start = Instant::now();
        let bar = Progress::new(tree.boolean_count(), self.quiet);
        let result = evaluate_csg_with_progress(
            &tree,
            csg_options(self.triangulate, None),
            Some(&|done, _| bar.set(done)),
        );
        bar.finish();
        let result = smooth_result(result?, self.triangulate, None)?;
        let eval_ms = millis_since(start);
        let check_start = Instant::now();
        let check = check_mesh(&result.mesh);
        let check_ms = millis_since(check_start);

        std::fs::create_dir_all(&self.output).map_err(|e| {
            umbra::UmbraError::Io {
                file: self.output.display().to_string(),
                action: "create the folder",
                source: e,
            }
        })?;
        let mut files: Vec<(PathBuf, Vec<u8>)> = Vec::new();
        // Every file but the report, as written.
        let mut written: Vec<WrittenFile> = Vec::new();
        for (name, kind) in MESHES {
            let path = self.output.join(name);
            let encoded = encode_mesh_with(
                kind,
                &result.mesh,
                MeshWriteOptions::default(),
                &path.display().to_string(),
            )?;
            if let Some(rounded) = &encoded.rounded {
                super::warn_f32_defects(&rounded.report, &path);
            }
            written.push(WrittenFile::mesh(
                path.display().to_string(),
                kind.name(),
                encoded.bytes.len(),
                encoded.written(&result.mesh),
            ));
            files.push((path, encoded.bytes));
        }
        let picture = render_mesh(
            &result.mesh,
            &RenderOptions {
                width: 800,
                height: 600,
                ..RenderOptions::default()
            },
        )
        .and_then(|image| image.to_png())
        .map_err(|e| anyhow::anyhow!("{}: {e}", self.output.join("plant.png").display()))?;
        for (name, format, bytes) in [
            ("plant.png", "PNG", picture),
            ("plant.json", "JSON", tree.to_json_string().into_bytes()),
        ] {
            let path = self.output.join(name);
            written.push(WrittenFile::other(
                path.display().to_string(),
                format,
                bytes.len(),
            ));
            files.push((path, bytes));
        }
        let report = DemoReport {
            evaluation: result.report,
            files: written,
        };
        files.push((
            self.output.join("report.json"),
            crate::files::report_json(&report)?,
        ));
        let refs: Vec<(&std::path::Path, &[u8])> = files
            .iter()
            .map(|(p, b)| (p.as_path(), b.as_slice()))
            .collect();
        write_all(&refs)?;

        let r = &report.evaluation;
        outln!(
            "umbra demo: a process plant of {} primitives and {} Booleans ({} variant, {} threads)",
            r.leaves,
            r.booleans,
            r.variant,
            r.threads
        )?;
        outln!("  evaluated in {eval_ms:.0} ms; checked in {check_ms:.0} ms")?;
        if let Some(s) = &r.smoothing {
            outln!("  {}", super::smooth::summary(s))?;
        }
        outln!(
            "  result: {} vertices, {} facets, volume {:.3}",
            r.vertices,
            r.facets,
            r.volume
        )?;
        outln!(
            "  topologically valid: {}; 2-manifold: {}; self-intersecting facet pairs: {}",
            if check.topology_error.is_none() { "yes" } else { "NO" },
            match check.two_manifold {
                Some(true) => "yes".to_string(),
                Some(false) => format!(
                    "no ({} open edges, {} non-manifold edges, {} non-manifold vertices)",
                    check.open_edges.unwrap_or(0),
                    check.non_manifold_edges.unwrap_or(0),
                    check.non_manifold_vertices.unwrap_or(0)
                ),
                None => "not computed".to_string(),
            },
            check
                .self_intersecting_facet_pairs
                .map_or("not computed".to_string(), |n| n.to_string())
        )?;
        for f in &report.files {
            match (f.vertices, f.facets, f.triangles_only) {
                (Some(v), Some(n), Some(t)) => outln!(
                    "  wrote {} ({v} vertices, {n} {})",
                    f.file,
                    if t { "triangles" } else { "facets" }
                )?,
                _ => outln!("  wrote {}", f.file)?,
            }
        }
        outln!("  wrote {}", self.output.join("report.json").display())?;
        if check.topology_error.is_none() {
            Ok(ExitCode::SUCCESS)
        } else {
            Err(super::invalid_result())
        }
    }
}
