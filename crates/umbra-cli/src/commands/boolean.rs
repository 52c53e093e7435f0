//! `umbra boolean OP A B [C ...] -o OUT`: the 2D Boolean (basic, or
//! through simplification with `--via simplify`) or the 3D Boolean
//! (polygon-mesh variant, or triangle-mesh variant with `--triangulate` or
//! an output format of triangles only), by the files' extensions. More
//! than two operands: in 2D one sweep through simplification
//! (`boolean_sets`), in 3D one operation node of the CSG evaluator (a
//! balanced tree of binary Booleans, in parallel).

use super::csg::Evaluation;
use super::smooth::summary;
use super::{
    invalid_result, millis_since, orientation, tolerance_arg, warn_f32_defects, warn_orphans,
};
use crate::errors::{self, usage};
use crate::files::OutputArgs;
use crate::stdout::outln;
use clap::ValueEnum;
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::Instant;
use umbra::{
    boolean_for_smoothing, boolean_sets, boolean_solid, boolean_solid_with_contacts,
    boolean_via_simplify, default_boolean_set_tolerance, default_mesh_tolerance,
    encode_mesh_with, encode_polygon_set, read_mesh, regularized_operands, smooth_set_result,
    smooth_solid_near, turned_outward, Boolean2Report, Boolean3Report, BooleanOp, Contacts,
    CsgNode, FileKind, MeshCounts, MeshReadOptions, MeshVariant, Operands, PlanarContacts,
    PolygonSet2, ReadOptions, SetCounts, SmoothOptions, UmbraError, Via, WrittenMeshReport,
};

/// Union, intersection, difference or (2D only) xor of two or more files
/// of the same dimension (2D: .wkt/.geojson; 3D: .obj/.off/.stl/.ply/.3mf/.glb/.gltf).
#[derive(clap::Args, Debug)]
pub struct BooleanArgs {
    /// The operation.
    #[arg(value_enum)]
    op: OpArg,
    /// The operands A, B and any more. With more than two, union and
    /// intersection take them all, difference is A minus all the others,
    /// and xor (2D) keeps what an odd number of them cover; 2D runs one
    /// sweep through simplification, 3D a balanced tree of binary
    /// Booleans in parallel, reported as `umbra csg` reports.
    #[arg(required = true, num_args = 2.., value_name = "FILE")]
    operands: Vec<PathBuf>,
    #[command(flatten)]
    out: OutputArgs,
    /// Use the operands' orientation as written. 2D: read every ring as
    /// a directed loop exactly as written and write every loop as its own
    /// polygon (keeps inside-out and multiply enclosed shapes); by default
    /// rings are read by role. 3D: an operand whose facets face inward
    /// (negative signed volume) is used as an inside-out solid (section
    /// 4.7); by default it is turned outward, with a warning.
    #[arg(long)]
    keep_orientation: bool,
    /// 2D: the algorithm. `basic` (the default for two operands) is the
    /// basic Boolean of chapter 4 (tolerates invalid input); `simplify`
    /// assembles the boundaries and simplifies (chapter 6: resolves
    /// self-intersections), which more than two operands always use.
    #[arg(long, value_enum)]
    via: Option<ViaArg>,
    /// 3D: run the triangle-mesh variant (section 4.8) instead of the
    /// polygon-mesh one: operands with other facets are triangulated by
    /// internal edges first, and the output is triangles. Implied when
    /// the output is .stl, .3mf, .glb or .gltf (formats of triangles only: the
    /// polygon result triangulated on writing can fold where facets meet
    /// at the intersection curves, which the triangle variant's smoothing
    /// removes).
    #[arg(long)]
    triangulate: bool,
    /// Smooth the result at this tolerance (Appendix A: merges what lies
    /// closer, removes slivers, gaps, coincident opposing facets and
    /// edges). Results are smoothed by default at 1e-9 times the largest
    /// bounding-box extent of either operand; `--smooth 0` writes the
    /// Boolean's raw output (in 2D its degenerate features, such as an
    /// edge running back over a shared boundary, make rings that OGC
    /// Simple Features readers like GEOS call invalid). With
    /// --keep-orientation 2D results are raw unless asked.
    #[arg(long, value_name = "T", value_parser = tolerance_arg)]
    smooth: Option<f64>,
}

/// The Boolean operations, as named on the command line.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
enum OpArg {
    /// A ∪ B.
    Union,
    /// A ∩ B.
    Intersection,
    /// A − B.
    Difference,
    /// Symmetric difference (2D only).
    Xor,
}

impl OpArg {
    fn op(self) -> BooleanOp {
        match self {
            OpArg::Union => BooleanOp::Union,
            OpArg::Intersection => BooleanOp::Intersection,
            OpArg::Difference => BooleanOp::Difference,
            OpArg::Xor => BooleanOp::Xor,
        }
    }
}

/// The 2D algorithm.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
enum ViaArg {
    /// The basic Boolean (chapter 4).
    Basic,
    /// Through simplification (chapter 6).
    Simplify,
}

impl BooleanArgs {
    /// Checks the arguments, runs the Boolean, writes the output (and the
    /// report) and prints a summary.
    pub fn run(self) -> anyhow::Result<ExitCode> {
        let out_kind = FileKind::from_path(&self.out.output)?;
        let mut meshes = usize::from(out_kind.is_mesh());
        for path in &self.operands {
            meshes += usize::from(FileKind::from_path(path)?.is_mesh());
        }
        if meshes != 0 && meshes != self.operands.len() + 1 {
            return Err(usage(
                "the operands and the output must all be 2D files (.wkt, .geojson, .svg output) or all 3D files (.obj, .off, .stl, .ply, .3mf, .glb, .gltf)",
            ));
        }
        let labels: Vec<String> = (0..self.operands.len()).map(operand_label).collect();
        let reads: Vec<(&str, &Path)> = labels
            .iter()
            .zip(&self.operands)
            .map(|(label, path)| (label.as_str(), path.as_path()))
            .collect();
        self.out.refuse_overlaps(&reads)?;
        let op = self.op.op();
        let many = self.operands.len() > 2;
        if meshes > 0 {
            if self.via == Some(ViaArg::Simplify) {
                return Err(usage("--via simplify is for 2D files only"));
            }
            if op == BooleanOp::Xor {
                return Err(usage(
                    "xor is for 2D files only (a 3D half-edge has no multiplicity for the doubled intersection curves)",
                ));
            }
            if many {
                return self.run_3d_many(op, out_kind);
            }
            self.run_3d(op, out_kind)
        } else {
            if self.triangulate {
                return Err(usage("--triangulate is for 3D files only"));
            }
            let via = match self.via {
                Some(ViaArg::Basic) if many => {
                    return Err(usage(
                        "the basic Boolean takes two operands; more go through simplification in one sweep (--via simplify, the default for them)",
                    ))
                }
                None | Some(ViaArg::Basic) if !many => Via::Basic,
                _ => Via::Simplify,
            };
            self.run_2d(op, via, out_kind)
        }
    }

    /// More than two 3D operands: one operation node over the files,
    /// evaluated as `umbra csg` evaluates it (inward-facing operands
    /// turned outward, smoothed near the contacts, its report).
    fn run_3d_many(&self, op: BooleanOp, out_kind: FileKind) -> anyhow::Result<ExitCode> {
        if self.keep_orientation {
            return Err(usage(
                "--keep-orientation takes two 3D operands (more are evaluated as a CSG node, which turns inward-facing operands outward)",
            ));
        }
        let tree = CsgNode::op(op, self.operands.iter().map(CsgNode::file).collect());
        let evaluation = Evaluation {
            triangulate: self.triangulate || out_kind.holds_triangles_only(),
            smooth: self.smooth,
            quiet: false,
        };
        let source = format!("{} of {} files", op.name(), self.operands.len());
        evaluation.run(&tree, out_kind, &self.out, &source)
    }

    fn run_2d(&self, op: BooleanOp, via: Via, out_kind: FileKind) -> anyhow::Result<ExitCode> {
        let out_path = &self.out.output;
        let keep = self.keep_orientation;
        let options = ReadOptions {
            orientation: orientation(keep),
            ..ReadOptions::default()
        };
        let mut sets = Vec::with_capacity(self.operands.len());
        for path in &self.operands {
            sets.push(super::read_set(path, options)?);
        }
        let files: Vec<&Path> = self.operands.iter().map(PathBuf::as_path).collect();
        let mut counts: Vec<SetCounts> = files
            .iter()
            .zip(&sets)
            .map(|(path, set)| SetCounts::of_set(path.display().to_string(), set))
            .collect();
        let more_inputs = counts.split_off(2.min(counts.len()));
        // Two operands at least (clap requires them).
        let ([a, b, ..], [a_path, b_path, ..], Ok([a_counts, b_counts])) =
            (&sets[..], &files[..], <[SetCounts; 2]>::try_from(counts))
        else {
            return Err(usage("a Boolean takes at least two operands"));
        };
        let inputs = Operands {
            a: a_counts,
            b: b_counts,
        };
        let tolerance = default_boolean_set_tolerance(&sets, keep);
        let start = Instant::now();
        let (encoded, report) = match via {
            Via::Basic => {
                // Operands read by role are made sets first (an invalid
                // file's overlapping parts or stray holes would otherwise
                // be counted twice or inside out: `regularized_operand`).
                // Their sweeps' error bound adds to the Boolean's.
                let regular;
                let (a, b, moved) = if keep {
                    (a, b, 0.0)
                } else {
                    let [ra, rb] = regularized_operands(a, b);
                    regular = (
                        ra.map_err(|e| errors::simplify(e, &[a_path]))?,
                        rb.map_err(|e| errors::simplify(e, &[b_path]))?,
                    );
                    let moved = regular.0.epsilon.max(regular.1.epsilon);
                    (&regular.0.shape, &regular.1.shape, moved)
                };
                // Smoothing looks only near where the operands come
                // within its tolerance; those places come from a broad
                // phase run beside the Boolean.
                let tol = self.smooth.unwrap_or(tolerance);
                let result = boolean_for_smoothing(a, b, op, tol);
                let total = millis_since(start);
                let (out, contacts) = result.map_err(|e| errors::boolean2(e, [a_path, b_path]))?;
                let report = |output| {
                    let mut report = Boolean2Report::basic(op, keep, inputs, output, &out, total);
                    report.epsilon += moved;
                    report
                };
                self.finish_2d(&out.shape, report, out_kind, tolerance, contacts.as_ref())?
            }
            Via::Simplify => {
                // Two operands keep the binary sweep's fixed-size winding
                // pairs; more are swept at once (the same selection).
                let result = if more_inputs.is_empty() {
                    boolean_via_simplify(a, b, op)
                } else {
                    boolean_sets(op, &sets)
                };
                let total = millis_since(start);
                let out = result.map_err(|e| errors::simplify(e, &files))?;
                let report = |output| {
                    Boolean2Report::via_simplify(op, keep, inputs, output, &out, total)
                        .with_more_inputs(more_inputs)
                };
                self.finish_2d(&out.shape, report, out_kind, tolerance, None)?
            }
        };
        self.out.write(&encoded.bytes, &report)?;
        warn_orphans(encoded.orphan_holes, out_path);
        let detail = match (report.intersections, report.k_max) {
            (Some(n), _) => format!("{n} intersecting edge pairs"),
            (None, Some(k)) => format!("k_max {k}"),
            (None, None) => String::new(),
        };
        let smoothing = report
            .smoothing
            .as_ref()
            .map_or(String::new(), |r| format!(", {}", summary(r)));
        outln!(
            "{}{}: {} vertices, {} rings, {detail}{smoothing}, epsilon {:e}, {:.3} ms -> {}",
            op.name(),
            if via == Via::Simplify {
                " (via simplify)"
            } else {
                ""
            },
            report.output.vertices,
            report.output.rings,
            report.epsilon,
            report.timings_ms.total,
            out_path.display()
        )?;
        if !report.topologically_valid {
            return Err(invalid_result());
        }
        Ok(ExitCode::SUCCESS)
    }

    fn run_3d(&self, op: BooleanOp, out_kind: FileKind) -> anyhow::Result<ExitCode> {
        let (Some(a_path), Some(b_path)) = (self.operands.first(), self.operands.get(1)) else {
            return Err(usage("a Boolean takes at least two operands"));
        };
        let out_path = &self.out.output;
        let mut a = read_mesh(a_path, MeshReadOptions::default(), true)?;
        let mut b = read_mesh(b_path, MeshReadOptions::default(), true)?;
        if !self.keep_orientation {
            for (mesh, path) in [(&mut a, a_path), (&mut b, b_path)] {
                if let Some(outward) = turned_outward(mesh) {
                    eprintln!(
                        "warning: {}: the facets face inward (signed volume {}): turned outward; rerun with --keep-orientation to use it as an inside-out solid",
                        path.display(),
                        mesh.signed_volume()
                    );
                    *mesh = outward;
                }
            }
        }
        let variant = if self.triangulate || out_kind.holds_triangles_only() {
            MeshVariant::TriangleMesh
        } else {
            MeshVariant::PolygonMesh
        };
        let tol = self
            .smooth
            .unwrap_or_else(|| default_mesh_tolerance(&a).max(default_mesh_tolerance(&b)));
        // The operands' contacts at the tolerance: smoothing looks only
        // where the Boolean cut or touched (`smooth_solid_near`).
        let (out, contacts) = if tol > 0.0 {
            boolean_solid_with_contacts(&a, &b, op, variant, tol)
        } else {
            boolean_solid(&a, &b, op, variant).map(|o| (o, Contacts::default()))
        }
        .map_err(|e| errors::boolean3(e, [a_path, b_path]))?;
        let out_file = out_path.display().to_string();
        let mut report = Boolean3Report::new(
            op,
            Operands {
                a: MeshCounts::of_mesh(a_path.display().to_string(), &a),
                b: MeshCounts::of_mesh(b_path.display().to_string(), &b),
            },
            out_file.clone(),
            &out,
        );
        let mesh = if tol > 0.0 {
            let start = Instant::now();
            let opts = SmoothOptions::new(tol).guarded();
            let smoothed = smooth_solid_near(&out.mesh, variant, &opts, &contacts).map_err(
                |source| UmbraError::Smooth {
                    file: String::new(),
                    source,
                },
            )?;
            report = report.smoothed(out_file.clone(), &smoothed, millis_since(start));
            smoothed.shape
        } else {
            out.mesh
        };
        // The report describes the file: for a format of `f32`
        // coordinates, the mesh as rounded and repaired; for facets split
        // into triangles, the triangles.
        let encoded = encode_mesh_with(out_kind, &mesh, self.out.mesh_options(), &out_file)?;
        report = report.written_as(&encoded);
        self.out.write(&encoded.bytes, &report)?;
        if let Some(rounded) = &encoded.rounded {
            warn_f32_defects(&rounded.report, out_path);
        }
        let smoothing = report
            .smoothing
            .as_ref()
            .map_or(String::new(), |r| format!(", {}", summary(r)));
        outln!(
            "{} ({}): {} vertices, {} facets, {} edge-facet intersections{smoothing}, volume {}, {:.3} ms -> {}",
            op.name(),
            report.variant,
            report.output.vertices,
            report.output.facets,
            report.intersections,
            report.output.signed_volume,
            report.timings_ms.total,
            out_path.display()
        )?;
        if !report.topologically_valid {
            return Err(invalid_result());
        }
        Ok(ExitCode::SUCCESS)
    }

    /// Finishes a 2D result: smoothed at `--smooth T`, by default at
    /// [`umbra::DEFAULT_RELATIVE_TOLERANCE`] times the largest extent of
    /// either operand (`tolerance`), as it is at a tolerance of 0; then
    /// encoded once, and reported by `report` given the counts of what is
    /// written. With the operands' `contacts`, smoothing looks only near
    /// them ([`smooth_set_result`]).
    fn finish_2d(
        &self,
        shape: &PolygonSet2,
        report: impl FnOnce(SetCounts) -> Boolean2Report,
        out_kind: FileKind,
        tolerance: f64,
        contacts: Option<&PlanarContacts>,
    ) -> anyhow::Result<(umbra::EncodedPolygons, Boolean2Report)> {
        let out_file = self.out.output.display().to_string();
        let orientation = orientation(self.keep_orientation);
        let tol = self.smooth.unwrap_or(tolerance);
        if tol <= 0.0 {
            let encoded = encode_polygon_set(out_kind, shape, orientation, &out_file)?;
            let report = report(encoded.counts(&out_file));
            return Ok((encoded, report));
        }
        let start = Instant::now();
        let smoothed = smooth_set_result(shape, &SmoothOptions::new(tol), contacts).map_err(|source| {
            UmbraError::Smooth {
                file: String::new(),
                source,
            }
        })?;
        let ms = millis_since(start);
        let encoded = encode_polygon_set(out_kind, &smoothed.shape, orientation, &out_file)?;
        let counts = encoded.counts(&out_file);
        let report = report(counts.clone()).smoothed(counts, &smoothed, ms);
        Ok((encoded, report))
    }
}

/// The name of operand `i` in messages: `operand A`, `operand B`, ...,
/// `operand 27` past `Z`.
fn operand_label(i: usize) -> String {
    match u8::try_from(i) {
        Ok(k @ 0..=25) => format!("operand {}", char::from(b'A' + k)),
        _ => format!("operand {}", i + 1),
    }
}
