//! `umbra smooth IN -o OUT [--tol T]`: data smoothing (Appendix A) of a
//! mesh or a 2D file: vertices within T merge, edges near a vertex or near
//! each other crack, opposing half-edges and facets cancel, and what is
//! left is written; the closure constraints hold throughout.

use super::{invalid_result, millis_since, orientation, tolerance_arg, warn_orphans};
use crate::files::OutputArgs;
use crate::stdout::outln;
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::Instant;
use umbra::{
    as_triangle_mesh, default_mesh_tolerance, default_set_tolerance, encode_mesh_with,
    encode_polygon_set, read_mesh, smooth_polygon_set, smooth_solid, FileKind,
    MeshCounts, MeshReadOptions, MeshVariant, ReadOptions, SetCounts, SmoothFileReport,
    SmoothOptions, SmoothReport, UmbraError, WrittenMeshReport,
};

/// Smooth a mesh (.obj, .off, .stl, .ply, .3mf, .glb, .gltf) or a 2D file
/// (.wkt, .geojson): remove gaps, slivers, zero-length edges and
/// coincident opposing facets below a tolerance (Appendix A). A triangle
/// mesh stays a triangle mesh; a polygon mesh written to .stl, .3mf, .glb
/// or .gltf is triangulated first and smoothed as triangles.
#[derive(clap::Args, Debug)]
pub struct SmoothArgs {
    /// The input file.
    input: PathBuf,
    #[command(flatten)]
    out: OutputArgs,
    /// The tolerance: features closer than this are made to coincide.
    /// Default: 1e-9 times the largest extent of the input's bounding box.
    #[arg(long, value_name = "T", value_parser = tolerance_arg)]
    tol: Option<f64>,
    /// 2D: read every ring as a directed loop exactly as written and
    /// write loops as they are.
    #[arg(long)]
    keep_orientation: bool,
}

impl SmoothArgs {
    /// Reads, smooths, writes the output (and the report), prints a summary.
    pub fn run(self) -> anyhow::Result<ExitCode> {
        let in_kind = FileKind::from_path(&self.input)?;
        let out_kind = FileKind::from_path(&self.out.output)?;
        if in_kind.is_mesh() != out_kind.is_mesh() {
            return Err(crate::errors::usage(
                "the input and the output must both be 2D files (.wkt, .geojson; .svg output) or both 3D files (.obj, .off, .stl, .ply, .3mf, .glb, .gltf)",
            ));
        }
        self.out.refuse_overlaps(&[("the input", &self.input)])?;
        if in_kind.is_mesh() {
            self.run_3d(out_kind)
        } else {
            self.run_2d(out_kind)
        }
    }

    fn run_3d(&self, out_kind: FileKind) -> anyhow::Result<ExitCode> {
        let mesh = read_mesh(&self.input, MeshReadOptions::default(), true)?;
        let tol = self.tol.unwrap_or_else(|| default_mesh_tolerance(&mesh));
        // A triangle mesh stays one; a polygon mesh written to a format of
        // triangles only is triangulated first and smoothed as triangles,
        // so the triangles written are the ones smoothing cleaned.
        let variant = if as_triangle_mesh(&mesh).is_some() || out_kind.holds_triangles_only() {
            MeshVariant::TriangleMesh
        } else {
            MeshVariant::PolygonMesh
        };
        let start = Instant::now();
        let result = smooth_solid(&mesh, variant, &SmoothOptions::new(tol).guarded());
        let total = millis_since(start);
        let smoothed = result.map_err(|source| smooth_error(&self.input, source))?;
        let out_file = self.out.output.display().to_string();
        let encoded = encode_mesh_with(
            out_kind,
            &smoothed.shape,
            self.out.mesh_options(),
            &out_file,
        )?;
        let report = SmoothFileReport::new(
            MeshCounts::of_mesh(self.input.display().to_string(), &mesh),
            MeshCounts::of_mesh(out_file.clone(), &smoothed.shape),
            &smoothed,
            smoothed.shape.check_topology(),
            total,
        );
        // The report describes the file: for a format of `f32`
        // coordinates, the mesh as rounded and repaired; for facets split
        // into triangles, the triangles.
        let report = report.written_as(&encoded);
        self.out.write(&encoded.bytes, &report)?;
        if let Some(rounded) = &encoded.rounded {
            super::warn_f32_defects(&rounded.report, &self.out.output);
        }
        outln!(
            "smooth ({}): {} -> {} vertices, {} -> {} facets; {}; volume {} -> {}; {:.3} ms -> {}",
            variant.name(),
            report.input.vertices,
            report.output.vertices,
            report.input.facets,
            report.output.facets,
            summary(&report.smoothing),
            report.input.signed_volume,
            report.output.signed_volume,
            report.timings_ms.total,
            self.out.output.display()
        )?;
        finish(report.topologically_valid)
    }

    fn run_2d(&self, out_kind: FileKind) -> anyhow::Result<ExitCode> {
        let keep = self.keep_orientation;
        let options = ReadOptions {
            orientation: orientation(keep),
            ..ReadOptions::default()
        };
        let set = super::read_set(&self.input, options)?;
        let tol = self.tol.unwrap_or_else(|| default_set_tolerance(&set));
        let start = Instant::now();
        let result = smooth_polygon_set(&set, &SmoothOptions::new(tol));
        let total = millis_since(start);
        let smoothed = result.map_err(|source| smooth_error(&self.input, source))?;
        let out_file = self.out.output.display().to_string();
        let encoded = encode_polygon_set(out_kind, &smoothed.shape, orientation(keep), &out_file)?;
        let report = SmoothFileReport::new(
            SetCounts::of_set(self.input.display().to_string(), &set),
            encoded.counts(out_file),
            &smoothed,
            smoothed.shape.check_topology(),
            total,
        );
        self.out.write(&encoded.bytes, &report)?;
        warn_orphans(encoded.orphan_holes, &self.out.output);
        outln!(
            "smooth: {} -> {} vertices, {} -> {} rings; {}; area {} -> {}; {:.3} ms -> {}",
            report.input.vertices,
            report.output.vertices,
            report.input.rings,
            report.output.rings,
            summary(&report.smoothing),
            report.input.signed_area,
            report.output.signed_area,
            report.timings_ms.total,
            self.out.output.display()
        )?;
        finish(report.topologically_valid)
    }
}

/// A smoothing error naming the file smoothed.
fn smooth_error(file: &Path, source: umbra::SmoothError) -> UmbraError {
    UmbraError::Smooth {
        file: file.display().to_string(),
        source,
    }
}

/// One clause for a summary line: tolerance, adjustments, bound; or, when
/// the guard undid smoothing, what it would have left.
pub fn summary(r: &SmoothReport) -> String {
    let undone = match &r.reverted {
        Some(undone) if !undone.is_partial() => {
            return format!("at tolerance {:e}, {undone}", r.tolerance)
        }
        Some(undone) => format!("; {undone}"),
        None => String::new(),
    };
    format!(
        "smoothed at tolerance {:e}: {} adjustments, distortion bound {:e}{}{undone}",
        r.tolerance,
        r.counts.adjustments(),
        r.distortion_bound,
        if r.budget_hit {
            " (SAFETY BUDGET HIT: stopped early)"
        } else {
            ""
        }
    )
}

fn finish(valid: bool) -> anyhow::Result<ExitCode> {
    if valid {
        Ok(ExitCode::SUCCESS)
    } else {
        Err(invalid_result())
    }
}
