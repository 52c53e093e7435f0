//! `umbra check IN [--json]`: topological and coordinate validity and
//! geometric-validity hints of a 2D polygon file or a 3D mesh file.

use super::orientation;
use crate::files::report_json;
use crate::stdout::{error_line, outln, print};
use std::path::PathBuf;
use std::process::ExitCode;
use umbra::{
    check_mesh, check_polygon_set, read_mesh, CheckReport, FileKind, FileReport,
    MeshCheckReport, MeshReadOptions, ReadOptions, UmbraError,
};

/// Check a file: topological validity, coordinates, and geometric
/// validity hints (2D: crossing edges; 3D: 2-manifoldness,
/// self-intersecting facet pairs, signed volume).
#[derive(clap::Args, Debug)]
pub struct CheckArgs {
    /// The file to check.
    input: PathBuf,
    /// Print the report as JSON.
    #[arg(long)]
    json: bool,
    /// 2D: read every ring as written instead of by role.
    #[arg(long)]
    keep_orientation: bool,
}

impl CheckArgs {
    /// Reads and checks the file, prints the report; exit 1 (with one line
    /// on standard error) when the shape is not valid input.
    pub fn run(self) -> anyhow::Result<ExitCode> {
        let file = self.input.display().to_string();
        let (valid, problem) = if FileKind::from_path(&self.input)?.is_mesh() {
            let options = MeshReadOptions {
                validate_coordinates: false,
            };
            let mut r = check_mesh(&read_mesh(&self.input, options, false)?);
            if !r.is_valid() {
                // The reader names the first violation in the file's own
                // terms (OBJ's 1-based indices and line, a PLY's element,
                // an STL's facet) where the inspection counts from 0: read
                // again, checking, for that message.
                let strict = MeshReadOptions {
                    validate_coordinates: true,
                };
                if let Err(UmbraError::InvalidMesh { message, .. }) =
                    read_mesh(&self.input, strict, true)
                {
                    if r.coordinate_error.is_some() {
                        r.coordinate_error = Some(message);
                    } else if r.topology_error.is_some() {
                        r.topology_error = Some(message);
                    }
                }
            }
            self.print_3d(&file, &r)?;
            (r.is_valid(), problem(&r.coordinate_error, &r.topology_error))
        } else {
            let options = ReadOptions {
                orientation: orientation(self.keep_orientation),
                validate_coordinates: false,
            };
            let r = check_polygon_set(&super::read_set(&self.input, options)?);
            self.print_2d(&file, &r)?;
            (r.is_valid(), problem(&r.coordinate_error, &r.topology_error))
        };
        if valid {
            Ok(ExitCode::SUCCESS)
        } else {
            error_line(&format!("{file}: {problem}"));
            Ok(ExitCode::from(1))
        }
    }

    fn print_json<R: serde::Serialize>(&self, file: &str, report: R) -> anyhow::Result<()> {
        let json = report_json(&FileReport {
            file: file.to_string(),
            report,
        })?;
        print(&String::from_utf8_lossy(&json))?;
        Ok(())
    }

    fn print_3d(&self, file: &str, r: &MeshCheckReport) -> anyhow::Result<()> {
        if self.json {
            return self.print_json(file, r);
        }
        match &r.topology_error {
            None => outln!("{file}: topologically valid")?,
            Some(e) => outln!("{file}: NOT topologically valid: {e}")?,
        }
        outln!(
            "  vertices: {}, facets: {}, half-edges: {}, edges: {}",
            r.vertices,
            r.facets,
            r.half_edges,
            r.edges
        )?;
        match &r.coordinate_error {
            None => outln!("  coordinates: valid (finite, |c| <= f64::MAX/4)")?,
            Some(e) => outln!("  coordinates: INVALID: {e}")?,
        }
        if let Some(m) = r.two_manifold {
            outln!(
                "  2-manifold: {} ({} open edges, {} non-manifold edges, {} non-manifold vertices)",
                if m { "yes" } else { "no" },
                r.open_edges.unwrap_or(0),
                r.non_manifold_edges.unwrap_or(0),
                r.non_manifold_vertices.unwrap_or(0)
            )?;
        }
        if let Some(n) = r.self_intersecting_facet_pairs {
            outln!("  self-intersecting facet pairs: {n}")?;
        }
        if let Some(v) = r.signed_volume {
            outln!("  signed volume: {v}")?;
        }
        Ok(())
    }

    fn print_2d(&self, file: &str, r: &CheckReport) -> anyhow::Result<()> {
        if self.json {
            return self.print_json(file, r);
        }
        match &r.topology_error {
            None => outln!("{file}: topologically valid")?,
            Some(e) => outln!("{file}: NOT topologically valid: {e}")?,
        }
        // Rings of zero signed area (degenerate: one or two points, or
        // back and forth) are neither; say so, so the counts add up.
        let flat = r.rings.saturating_sub(r.ccw_rings + r.cw_rings);
        outln!(
            "  rings: {} ({} counter-clockwise, {} clockwise{}), vertices: {}, edges: {}",
            r.rings,
            r.ccw_rings,
            r.cw_rings,
            if flat > 0 {
                format!(", {flat} of zero area")
            } else {
                String::new()
            },
            r.vertices,
            r.edges
        )?;
        outln!("  signed area: {}", r.signed_area)?;
        match &r.coordinate_error {
            None => outln!("  coordinates: valid (finite, |c| <= f64::MAX/4)")?,
            Some(e) => outln!("  coordinates: INVALID: {e}")?,
        }
        if let Some([lo, hi]) = r.bounding_box {
            outln!(
                "  bounding box: [{}, {}] x [{}, {}]",
                lo[0],
                hi[0],
                lo[1],
                hi[1]
            )?;
        }
        match (r.crossing_edge_pairs, r.overlapping_edge_pairs) {
            (Some(c), Some(o)) => outln!(
                "  crossing edge pairs: {c}, overlapping edge pairs: {o} ({})",
                if c == 0 && o == 0 {
                    "no crossings: geometrically valid if the rings are oriented with the interior on the left"
                } else {
                    "geometrically invalid; the Booleans still accept it (section 4.7)"
                }
            )?,
            _ => outln!("  crossing edge pairs: not computed (invalid coordinates)")?,
        }
        Ok(())
    }
}

/// The first problem of a report that is not valid.
fn problem(coordinate: &Option<String>, topology: &Option<String>) -> String {
    coordinate
        .as_deref()
        .or(topology.as_deref())
        .unwrap_or("invalid")
        .to_string()
}
