//! Typed reports of the operations, for JSON output (`serde::Serialize`):
//! what `umbra --report` writes and what any other front end can reuse.
//! Each report is built from an operation's output by a constructor here,
//! so every front end reports the same fields with the same meaning.
//!
//! Counts describe shapes as files hold them ([`SetCounts`],
//! [`MeshCounts`]): a 3D result written to a format of `f32` coordinates
//! is described as rounded ([`WrittenMeshReport::written_as`], with the
//! [`F32Rounding`] report). `timings_ms.total` ([`Timings`]) covers the
//! operation and that rounding's repair, never file input or output.

use crate::ops::{SolidOutput, Via};
use crate::{CsgReport, EncodedMesh, F32Rounding, RoundedMesh};
use boolean_2d::{BooleanOutput, Timings as BooleanTimings};
use serde::Serialize;
use simplify_2d::{FillRule, Simplified, SweepStats};
use smooth::{SmoothReport, Smoothed};
use topology::{BooleanOp, PolygonMesh, PolygonSet2, TopologyError};

/// One value per operand.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize)]
pub struct Operands<T> {
    /// Operand A.
    pub a: T,
    /// Operand B.
    pub b: T,
}

/// The counts of a 2D polygon set and the file it was read from or
/// written to.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct SetCounts {
    /// The file (as given on the command line), or a caller's label.
    pub file: String,
    /// Points of every ring (a ring of `n` points counted `n` times; no
    /// closing duplicates).
    pub vertices: usize,
    /// Edges of every ring (equal to `vertices` for rings as files hold
    /// them; the edge entries of a set built in memory otherwise).
    pub edges: usize,
    /// Rings (closed loops).
    pub rings: usize,
    /// The multiplicity-weighted signed area (f64 shoelace).
    pub signed_area: f64,
}

impl SetCounts {
    /// The counts of a set: its vertices, edge entries and closed loops
    /// ([`PolygonSet2::loops`]). For a set read from a file these are the
    /// file's points and rings; for an operation's output, count what is
    /// written instead (`EncodedPolygons::counts` with the feature `io`),
    /// since writing by role merges touching rings and drops spikes.
    pub fn of_set(file: impl Into<String>, set: &PolygonSet2) -> Self {
        SetCounts {
            file: file.into(),
            vertices: set.vertex_count(),
            edges: set.edge_count(),
            rings: set.loops().len(),
            signed_area: set.signed_area(),
        }
    }
}

/// The counts of a 3D polygon mesh and its file.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct MeshCounts {
    /// The file (as given on the command line), or a caller's label.
    pub file: String,
    /// Vertices.
    pub vertices: usize,
    /// Facets.
    pub facets: usize,
    /// Half-edges over all facet loops.
    pub half_edges: usize,
    /// The enclosed volume (positive for outward-facing facets).
    pub signed_volume: f64,
}

impl MeshCounts {
    /// The counts of `mesh`.
    pub fn of_mesh(file: impl Into<String>, mesh: &PolygonMesh) -> Self {
        MeshCounts {
            file: file.into(),
            vertices: mesh.vertices.len(),
            facets: mesh.facets.len(),
            half_edges: mesh.half_edge_count(),
            signed_volume: crate::mesh_signed_volume(mesh),
        }
    }
}

/// Wall-clock milliseconds: `total` is the operation alone; the phases
/// present depend on the operation (each is part of `total`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
pub struct Timings {
    /// The whole operation (no file input or output).
    pub total: f64,
    /// 2D basic Boolean: validation of both operands.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub validate: Option<f64>,
    /// 2D basic Boolean: the broad phase.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub broad_phase: Option<f64>,
    /// 2D basic Boolean: `X11` on the candidate pairs.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub intersections: Option<f64>,
    /// 2D basic Boolean: `X02` and `X20`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub winding_numbers: Option<f64>,
    /// 2D basic Boolean: levels 3-4 and the shape.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub construct: Option<f64>,
    /// 3D triangle-mesh variant: triangulating the operands.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub triangulate_inputs: Option<f64>,
    /// Smoothing of the result (Appendix A), when it ran.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub smooth: Option<f64>,
    /// Rounding the result to `f32` and repairing what rounding broke
    /// ([`crate::round_to_f32`]), when it was written to such a format.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub round_f32: Option<f64>,
}

impl Timings {
    /// Only a total.
    pub fn total(total: f64) -> Self {
        Timings {
            total,
            ..Timings::default()
        }
    }

    /// A total and the phases of the 2D basic Boolean.
    pub fn with_phases(total: f64, t: &BooleanTimings) -> Self {
        Timings {
            total,
            validate: Some(t.validate),
            broad_phase: Some(t.broad_phase),
            intersections: Some(t.intersections),
            winding_numbers: Some(t.winding),
            construct: Some(t.construct),
            triangulate_inputs: None,
            smooth: None,
            round_f32: None,
        }
    }
}

/// The counters of a simplification sweep.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub struct SweepReport {
    /// Edges handed to the sweep.
    pub input_edges: usize,
    /// Input edges after merging duplicates.
    pub merged_input_edges: usize,
    /// Events processed.
    pub events: u64,
    /// Intersection points found.
    pub intersections: u64,
    /// Splits of an edge at a vertex lying on it.
    pub vertex_on_edge_splits: u64,
    /// Splits whose edges were regrouped.
    pub misgrouped_splits: u64,
    /// Full scans of the sweep line.
    pub full_scans: u64,
    /// The longest sweep line.
    pub max_sweep_len: usize,
}

impl From<&SweepStats> for SweepReport {
    fn from(s: &SweepStats) -> Self {
        SweepReport {
            input_edges: s.input_edges,
            merged_input_edges: s.merged_input_edges,
            events: s.events,
            intersections: s.intersections,
            vertex_on_edge_splits: s.vertex_on_edge_splits,
            misgrouped_splits: s.misgrouped_splits,
            full_scans: s.full_scans,
            max_sweep_len: s.max_sweep_len,
        }
    }
}

/// `(valid, error)` of a topology check.
fn validity(check: Result<(), TopologyError>) -> (bool, Option<String>) {
    (check.is_ok(), check.err().map(|e| e.to_string()))
}

/// The report of a 2D Boolean.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Boolean2Report {
    /// `union`, `intersection`, `difference` or `xor`.
    pub operation: &'static str,
    /// The algorithm that ran ([`Via::algorithm`]).
    pub algorithm: &'static str,
    /// Rings were read and written as directed loops, not by role.
    pub keep_orientation: bool,
    /// The operands.
    pub inputs: Operands<SetCounts>,
    /// The operands after B of an n-ary Boolean in one sweep
    /// ([`crate::boolean_sets`]; a difference is A minus all the others),
    /// in order; absent for two operands.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub more_inputs: Vec<SetCounts>,
    /// The result as written.
    pub output: SetCounts,
    /// Basic Boolean: edge pairs with `X11 != 0`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub intersections: Option<usize>,
    /// The result satisfies shape boundary closure (always, unless a bug).
    pub topologically_valid: bool,
    /// The violated constraint, if any.
    pub topology_error: Option<String>,
    /// The error bound of section 8.4 (the command line adds the bound of
    /// the sweep that made operands read by role sets, and smoothing's
    /// distortion bound).
    pub epsilon: f64,
    /// Through simplification: the largest adjustment count (section 8.4).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub k_max: Option<u32>,
    /// Through simplification: the sweep's counters.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub sweep: Option<SweepReport>,
    /// What smoothing did, when the result was smoothed; `null` otherwise.
    pub smoothing: Option<SmoothReport>,
    /// Milliseconds.
    pub timings_ms: Timings,
}

impl Boolean2Report {
    /// The report of a basic Boolean ([`crate::boolean`]) that took
    /// `total_ms`; `output` counts the result as written.
    pub fn basic(
        op: BooleanOp,
        keep_orientation: bool,
        inputs: Operands<SetCounts>,
        output: SetCounts,
        out: &BooleanOutput,
        total_ms: f64,
    ) -> Self {
        let (topologically_valid, topology_error) = validity(out.shape.check_topology());
        Boolean2Report {
            operation: op.name(),
            algorithm: Via::Basic.algorithm(),
            keep_orientation,
            inputs,
            more_inputs: Vec::new(),
            output,
            intersections: Some(out.intersections),
            topologically_valid,
            topology_error,
            epsilon: out.epsilon,
            k_max: None,
            sweep: None,
            smoothing: None,
            timings_ms: Timings::with_phases(total_ms, &out.timings),
        }
    }

    /// The report of a Boolean through simplification
    /// ([`crate::boolean_via_simplify`]) that took `total_ms`.
    pub fn via_simplify(
        op: BooleanOp,
        keep_orientation: bool,
        inputs: Operands<SetCounts>,
        output: SetCounts,
        out: &Simplified,
        total_ms: f64,
    ) -> Self {
        let (topologically_valid, topology_error) = validity(out.shape.check_topology());
        Boolean2Report {
            operation: op.name(),
            algorithm: Via::Simplify.algorithm(),
            keep_orientation,
            inputs,
            more_inputs: Vec::new(),
            output,
            intersections: None,
            topologically_valid,
            topology_error,
            epsilon: out.epsilon,
            k_max: Some(out.k_max),
            sweep: Some(SweepReport::from(&out.stats)),
            smoothing: None,
            timings_ms: Timings::total(total_ms),
        }
    }

    /// The report of an n-ary Boolean in one sweep: the operands after B
    /// counted in `more_inputs`.
    pub fn with_more_inputs(mut self, more: Vec<SetCounts>) -> Self {
        self.more_inputs = more;
        self
    }

    /// The report once the result was smoothed in `smooth_ms`: `output`
    /// counts the smoothed set as written, validity is checked again, the
    /// epsilon grows by smoothing's, and `total` includes smoothing.
    pub fn smoothed(
        mut self,
        output: SetCounts,
        smoothed: &Smoothed<PolygonSet2>,
        smooth_ms: f64,
    ) -> Self {
        let (valid, error) = validity(smoothed.shape.check_topology());
        self.output = output;
        self.topologically_valid = valid;
        self.topology_error = error;
        self.epsilon += smoothed.report.epsilon;
        self.smoothing = Some(smoothed.report.clone());
        self.timings_ms.smooth = Some(smooth_ms);
        self.timings_ms.total += smooth_ms;
        self
    }
}

/// The name of a fill rule (`positive`, `nonzero`, `evenodd`,
/// `negative`, `at-least-2`, or `custom` for a caller's predicate).
pub fn fill_rule_name(rule: FillRule) -> &'static str {
    match rule {
        FillRule::Positive => "positive",
        FillRule::NonZero => "nonzero",
        FillRule::EvenOdd => "evenodd",
        FillRule::Negative => "negative",
        FillRule::AtLeast2 => "at-least-2",
        FillRule::Custom(_) => "custom",
    }
}

/// The report of a simplification.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct SimplifyReport {
    /// Always `simplify`.
    pub operation: &'static str,
    /// The fill rule ([`fill_rule_name`]).
    pub rule: &'static str,
    /// Rings were read and written as directed loops, not by role.
    pub keep_orientation: bool,
    /// The input.
    pub input: SetCounts,
    /// The result as written.
    pub output: SetCounts,
    /// The result satisfies shape boundary closure (always, unless a bug).
    pub topologically_valid: bool,
    /// The violated constraint, if any.
    pub topology_error: Option<String>,
    /// `(k_max + 1) sqrt(153) u L` (section 8.4).
    pub epsilon: f64,
    /// The largest adjustment count.
    pub k_max: u32,
    /// The sweep's counters.
    pub sweep: SweepReport,
    /// Milliseconds.
    pub timings_ms: Timings,
}

impl SimplifyReport {
    /// The report of [`crate::simplify`] by `rule` that took `total_ms`.
    pub fn new(
        rule: FillRule,
        keep_orientation: bool,
        input: SetCounts,
        output: SetCounts,
        out: &Simplified,
        total_ms: f64,
    ) -> Self {
        let (topologically_valid, topology_error) = validity(out.shape.check_topology());
        SimplifyReport {
            operation: "simplify",
            rule: fill_rule_name(rule),
            keep_orientation,
            input,
            output,
            topologically_valid,
            topology_error,
            epsilon: out.epsilon,
            k_max: out.k_max,
            sweep: SweepReport::from(&out.stats),
            timings_ms: Timings::total(total_ms),
        }
    }
}

/// The report of a 3D Boolean.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Boolean3Report {
    /// `union`, `intersection` or `difference`.
    pub operation: &'static str,
    /// The variant that ran ([`crate::MeshVariant::name`]).
    pub variant: &'static str,
    /// Which operands were triangulated first.
    pub inputs_triangulated: Operands<bool>,
    /// The operands.
    pub inputs: Operands<MeshCounts>,
    /// The result as written (rounded, for a format of `f32`
    /// coordinates).
    pub output: MeshCounts,
    /// Edge-facet intersection vertices.
    pub intersections: usize,
    /// The result satisfies the closure constraints (always, unless a bug).
    pub topologically_valid: bool,
    /// The violated constraint, if any.
    pub topology_error: Option<String>,
    /// What smoothing did, when the result was smoothed; `null` otherwise.
    pub smoothing: Option<SmoothReport>,
    /// What rounding to `f32` did, when the result was written to a format
    /// of `f32` coordinates (binary STL, glTF); absent otherwise.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub f32_rounding: Option<F32Rounding>,
    /// Milliseconds.
    pub timings_ms: Timings,
}

impl Boolean3Report {
    /// The report of [`crate::boolean_solid`]; the result is counted as
    /// `output_file`.
    pub fn new(
        op: BooleanOp,
        inputs: Operands<MeshCounts>,
        output_file: impl Into<String>,
        out: &SolidOutput,
    ) -> Self {
        let (topologically_valid, topology_error) = validity(out.mesh.check_topology());
        Boolean3Report {
            operation: op.name(),
            variant: out.variant.name(),
            inputs_triangulated: Operands {
                a: out.inputs_triangulated[0],
                b: out.inputs_triangulated[1],
            },
            inputs,
            output: MeshCounts::of_mesh(output_file, &out.mesh),
            intersections: out.intersections,
            topologically_valid,
            topology_error,
            smoothing: None,
            f32_rounding: None,
            timings_ms: Timings {
                triangulate_inputs: out.triangulate_ms,
                ..Timings::total(out.total_ms)
            },
        }
    }

    /// The report once the result was smoothed in `smooth_ms`: the output
    /// counted again as `output_file`, validity checked again, `total`
    /// includes smoothing.
    pub fn smoothed(
        mut self,
        output_file: impl Into<String>,
        smoothed: &Smoothed<PolygonMesh>,
        smooth_ms: f64,
    ) -> Self {
        let (valid, error) = validity(smoothed.shape.check_topology());
        self.output = MeshCounts::of_mesh(output_file, &smoothed.shape);
        self.topologically_valid = valid;
        self.topology_error = error;
        self.smoothing = Some(smoothed.report.clone());
        self.timings_ms.smooth = Some(smooth_ms);
        self.timings_ms.total += smooth_ms;
        self
    }
}

/// A 3D report that counts its output as the file written holds it: for a
/// format of `f32` coordinates the mesh as rounded and repaired (with the
/// rounding's report and time), for facets split into triangles the
/// triangles ([`crate::EncodedMesh`]). One rule for every report that
/// describes a mesh file: [`Boolean3Report`], [`SmoothFileReport`] of a
/// mesh and [`CsgReport`].
pub trait WrittenMeshReport: Sized {
    /// The report with its output described as `written`, the mesh the
    /// file `file` holds: counts and validity (and for a CSG report
    /// manifoldness, volume and bounds) again.
    fn describe_written(self, file: &str, written: &PolygonMesh) -> Self;

    /// The report with the rounding to `f32` recorded: its report kept,
    /// its time in the timings and in `total`.
    fn record_f32_rounding(self, rounded: &RoundedMesh) -> Self;

    /// The report once the result was encoded as `encoded`: described as
    /// the file holds it, the rounding recorded for a format of `f32`
    /// coordinates; unchanged when the facets were written one for one.
    fn written_as(self, encoded: &EncodedMesh) -> Self {
        match (&encoded.rounded, &encoded.triangulated) {
            (Some(r), _) => self
                .describe_written(&encoded.file, &r.mesh)
                .record_f32_rounding(r),
            (None, Some(t)) => self.describe_written(&encoded.file, t),
            (None, None) => self,
        }
    }
}

impl WrittenMeshReport for Boolean3Report {
    fn describe_written(mut self, file: &str, written: &PolygonMesh) -> Self {
        (self.output, self.topologically_valid, self.topology_error) = counted(file, written);
        self
    }

    fn record_f32_rounding(mut self, rounded: &RoundedMesh) -> Self {
        record_rounding(rounded, &mut self.f32_rounding, &mut self.timings_ms);
        self
    }
}

/// The counts and validity of a mesh written as `file`.
fn counted(file: &str, written: &PolygonMesh) -> (MeshCounts, bool, Option<String>) {
    let (valid, error) = validity(written.check_topology());
    (MeshCounts::of_mesh(file, written), valid, error)
}

/// The rounding's report and time in a report's fields.
fn record_rounding(
    rounded: &RoundedMesh,
    f32_rounding: &mut Option<F32Rounding>,
    timings: &mut Timings,
) {
    *f32_rounding = Some(rounded.report.clone());
    timings.round_f32 = Some(rounded.ms);
    timings.total += rounded.ms;
}

/// The report of smoothing a file (`umbra smooth`): `C` is [`SetCounts`]
/// or [`MeshCounts`].
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct SmoothFileReport<C> {
    /// Always `smooth`.
    pub operation: &'static str,
    /// The input.
    pub input: C,
    /// The result as written.
    pub output: C,
    /// The result satisfies the closure constraints (always, unless a
    /// bug or an invalid input, which is refused).
    pub topologically_valid: bool,
    /// The violated constraint, if any.
    pub topology_error: Option<String>,
    /// The epsilon smoothing adds (its distortion bound, and in 2D the
    /// sweep's epsilon).
    pub epsilon: f64,
    /// What smoothing did.
    pub smoothing: SmoothReport,
    /// What rounding to `f32` did, when the result was written to a format
    /// of `f32` coordinates (binary STL, glTF); absent otherwise.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub f32_rounding: Option<F32Rounding>,
    /// Milliseconds: `total` is smoothing and any rounding to `f32`.
    pub timings_ms: Timings,
}

impl<C> SmoothFileReport<C> {
    /// The report of `smoothed`, counted as `input` and `output`.
    pub fn new<S>(
        input: C,
        output: C,
        smoothed: &Smoothed<S>,
        check: Result<(), TopologyError>,
        total_ms: f64,
    ) -> Self {
        let (topologically_valid, topology_error) = validity(check);
        SmoothFileReport {
            operation: "smooth",
            input,
            output,
            topologically_valid,
            topology_error,
            epsilon: smoothed.report.epsilon,
            smoothing: smoothed.report.clone(),
            f32_rounding: None,
            timings_ms: Timings {
                smooth: Some(total_ms),
                ..Timings::total(total_ms)
            },
        }
    }
}

impl WrittenMeshReport for SmoothFileReport<MeshCounts> {
    fn describe_written(mut self, file: &str, written: &PolygonMesh) -> Self {
        (self.output, self.topologically_valid, self.topology_error) = counted(file, written);
        self
    }

    fn record_f32_rounding(mut self, rounded: &RoundedMesh) -> Self {
        record_rounding(rounded, &mut self.f32_rounding, &mut self.timings_ms);
        self
    }
}

/// One file a command wrote, described as written (`umbra demo`'s
/// [`DemoReport::files`]).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct WrittenFile {
    /// The path (as given on the command line, joined to the file name).
    pub file: String,
    /// The format: a mesh format's name ([`crate::FileKind`]'s `name`:
    /// `STL`, `3MF`, `OBJ`, ...), `PNG` or `JSON`.
    pub format: &'static str,
    /// The file's size in bytes.
    pub bytes: usize,
    /// For a mesh file, the vertices it holds (for STL and glTF, as the
    /// reader welds them by exact position); absent otherwise.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub vertices: Option<usize>,
    /// For a mesh file, the facets it holds: triangles for STL, 3MF and
    /// glTF; absent otherwise.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub facets: Option<usize>,
    /// For a mesh file, whether every facet it holds is a triangle;
    /// absent otherwise.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub triangles_only: Option<bool>,
    /// For a mesh file, the volume its facets enclose (as written: after
    /// rounding to `f32` for binary STL and glTF); absent otherwise.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub signed_volume: Option<f64>,
}

impl WrittenFile {
    /// A mesh file of `bytes` bytes holding `written` (for an encoded
    /// mesh, `EncodedMesh::written`).
    pub fn mesh(
        file: impl Into<String>,
        format: &'static str,
        bytes: usize,
        written: &PolygonMesh,
    ) -> Self {
        WrittenFile {
            file: file.into(),
            format,
            bytes,
            vertices: Some(written.vertices.len()),
            facets: Some(written.facets.len()),
            triangles_only: Some(written.facets.iter().all(|f| f.half_edges.len() == 3)),
            signed_volume: Some(crate::mesh_signed_volume(written)),
        }
    }

    /// A file that is not a mesh (a picture, a script).
    pub fn other(file: impl Into<String>, format: &'static str, bytes: usize) -> Self {
        WrittenFile {
            file: file.into(),
            format,
            bytes,
            vertices: None,
            facets: None,
            triangles_only: None,
            signed_volume: None,
        }
    }
}

/// The report of `umbra demo` (its `report.json`): the evaluation's
/// report ([`CsgReport`]: the evaluated and smoothed mesh, its fields at
/// the top level) and every other file written, each as written.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct DemoReport {
    /// The evaluation.
    #[serde(flatten)]
    pub evaluation: CsgReport,
    /// The files written besides the report, in the order written.
    pub files: Vec<WrittenFile>,
}

/// A check report with the file it is about (`umbra check --json`): the
/// report's fields and `file` at the same level.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct FileReport<R> {
    /// The file.
    pub file: String,
    /// The report ([`crate::CheckReport`] or [`crate::MeshCheckReport`]).
    #[serde(flatten)]
    pub report: R,
}
