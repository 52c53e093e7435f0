//! Evaluation of a CSG tree with the 3D Boolean: n-ary operations as
//! balanced trees of binary Booleans, independent branches in parallel
//! (rayon), the same output bit for bit whatever the thread count, a
//! progress callback and a typed report with per-node timings.
//!
//! On request the evaluation also gathers where the operands of every
//! Boolean came close ([`Contacts`]), carried up the tree through the
//! nodes' transforms into the root's frame, so that the result can be
//! smoothed only there ([`crate::smooth_solid_near`]) instead of as a
//! whole: every vertex a Boolean of the tree created, and every sliver or
//! gap between its operands, lies in one of those boxes.

use super::clean;
use super::error::ModelError;
use super::primitives::{cuboid, cylinder, torus, uv_sphere};
use super::transform::{transform_mesh, transform_triangles};
use super::tree::{path_string, CsgNode, CsgShape, MAX_DEPTH};
use crate::nary::reduce_op;
use crate::{F32Rounding, RoundedMesh};
use boolean_3d::{
    boolean_mesh, boolean_mesh_with_contacts, boolean_triangles, boolean_triangles_with_contacts,
    triangulate_mesh, BooleanOp, Contacts,
};
use glam::{DMat3, DMat4, DVec3};
use rayon::prelude::*;
use robust_arith::Point3;
use serde::Serialize;
use smooth::{SmoothReport, Smoothed};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Mutex;
use std::time::Instant;
use topology::{PolygonMesh, TriangleMesh};

/// How a tree is evaluated.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct CsgOptions {
    /// Use the triangle-mesh variant of the 3D Boolean (every leaf
    /// triangulated, every result triangulated, section 4.8) instead of
    /// the polygon-mesh variant.
    pub triangulate: bool,
    /// Gather the Booleans' [`Contacts`] into [`CsgResult::contacts`] at a
    /// proximity of at least this distance in the root's frame (`None`:
    /// not gathered). Each Boolean looks at least
    /// `CONTACT_RELATIVE_PROXIMITY` (1e-6) times its operands' extent around
    /// them, so that `Some(0.0)` gives contacts that serve smoothing at the
    /// default tolerance ([`crate::DEFAULT_RELATIVE_TOLERANCE`] times the
    /// result's extent) unless a Boolean's operands are a thousand times
    /// smaller than the result; [`Contacts::proximity`] of the result says
    /// what was reached.
    pub contacts: Option<f64>,
    /// Feed every Boolean's raw output to the next Boolean as it is. By
    /// default (`false`) an intermediate result with two vertices at one
    /// position (what degenerate contacts leave) is first cleaned near
    /// the contacts of the Boolean that made it: smoothing at the rounding
    /// tolerance `16 u L`, which merges coincident vertices and removes
    /// zero-area and touching facets while moving no point by more than
    /// the Boolean's own rounding, so that chains of operations do not
    /// grow (the module `clean`). The root's own result is never cleaned:
    /// with `raw_intermediates` or not, it is what the last Boolean
    /// returned.
    pub raw_intermediates: bool,
}

/// The least proximity at which a Boolean of a tree gathers contacts
/// ([`CsgOptions::contacts`]), relative to the largest extent of its two
/// operands' bounding boxes: a thousand times the default smoothing
/// tolerance, so that the contacts of a part serve smoothing the whole
/// tree's result at its default tolerance when the part is at least a
/// thousandth of the result's size. The boxes grow by it, which costs
/// little: facets are much larger than this.
pub const CONTACT_RELATIVE_PROXIMITY: f64 = 1e-6;

/// The timing and sizes of one node of the tree.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct NodeReport {
    /// The node's path (`children[2].children[0]`, or `root`).
    pub path: String,
    /// `union`, `intersection`, `difference`, `box`, `sphere`, ...
    pub kind: String,
    /// The Booleans this node ran (not counting its children's).
    pub booleans: usize,
    /// The facet counts of the operands (the children's results), for an
    /// operation.
    pub operand_facets: Vec<usize>,
    /// The result's vertex count (after the node's transform).
    pub vertices: usize,
    /// The result's facet count.
    pub facets: usize,
    /// Wall-clock milliseconds of this node's own work (its Booleans, or
    /// building the primitive), children excluded.
    pub ms: f64,
}

/// The report of an evaluation (serialisable for `--report`).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct CsgReport {
    /// `polygon` or `triangle`: the variant of the 3D Boolean.
    pub variant: &'static str,
    /// The number of binary Booleans run.
    pub booleans: usize,
    /// The number of leaves.
    pub leaves: usize,
    /// Intermediate results cleaned before they fed the next Boolean
    /// ([`CsgOptions::raw_intermediates`]).
    pub cleaned: usize,
    /// The rayon threads available.
    pub threads: usize,
    /// The output's vertex count.
    pub vertices: usize,
    /// The output's facet count.
    pub facets: usize,
    /// The output's half-edge count.
    pub half_edges: usize,
    /// `true` when the output satisfies the constraints of section 4.2.
    pub topologically_valid: bool,
    /// The violated constraint, when not valid (never expected).
    pub topology_error: Option<String>,
    /// The output is a closed 2-manifold. This and the three counts below
    /// are those of `umbra check` ([`crate::check_mesh`], by
    /// [`PolygonMesh::manifold_report`]); `null` when the output is not
    /// topologically valid.
    pub two_manifold: Option<bool>,
    /// Edges used in one direction only (in a topologically valid output,
    /// zero-length half-edges `a -> a`).
    pub open_edges: Option<usize>,
    /// Edges used both ways but not exactly once each way (touching parts
    /// legitimately give some).
    pub non_manifold_edges: Option<usize>,
    /// Vertices around which the facets form more than one fan (parts
    /// touching at a point).
    pub non_manifold_vertices: Option<usize>,
    /// The signed volume of the output.
    pub volume: f64,
    /// The axis-aligned bounds `[min, max]`, if the output has a vertex.
    pub bounds: Option<[[f64; 3]; 2]>,
    /// What smoothing did, when the result was smoothed
    /// ([`CsgReport::smoothed`]); `null` otherwise.
    pub smoothing: Option<SmoothReport>,
    /// Whether smoothing looked only near the Booleans' contacts
    /// ([`CsgResult::contacts`]) rather than at the whole mesh; `null`
    /// when the result was not smoothed.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub smoothed_near_contacts: Option<bool>,
    /// What rounding to `f32` did, when the result was written to a format
    /// of `f32` coordinates ([`crate::WrittenMeshReport::written_as`]); absent
    /// otherwise.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub f32_rounding: Option<F32Rounding>,
    /// Wall-clock milliseconds: `total` is the whole evaluation.
    pub timings_ms: CsgTimings,
    /// One entry per node, in tree order (pre-order).
    pub nodes: Vec<NodeReport>,
}

impl CsgReport {
    /// Describes `mesh` as the output: counts, validity, manifoldness,
    /// volume and bounds.
    fn describe(&mut self, mesh: &PolygonMesh) {
        let topology = mesh.check_topology();
        self.vertices = mesh.vertices.len();
        self.facets = mesh.facets.len();
        self.half_edges = mesh.half_edge_count();
        self.topologically_valid = topology.is_ok();
        self.topology_error = topology.err().map(|e| e.to_string());
        self.set_manifold_counts(mesh);
        self.volume = topology::mesh_signed_volume(mesh);
        self.bounds = mesh.bounding_box();
    }

    /// The 2-manifoldness counts of `mesh`, as `umbra check` states them.
    fn set_manifold_counts(&mut self, mesh: &PolygonMesh) {
        let counts = mesh.manifold_report().ok().map(|r| r.counts());
        self.two_manifold = counts.map(|c| c.two_manifold);
        self.open_edges = counts.map(|c| c.open_edges);
        self.non_manifold_edges = counts.map(|c| c.non_manifold_edges);
        self.non_manifold_vertices = counts.map(|c| c.non_manifold_vertices);
    }

    /// The report once the result was smoothed in `smooth_ms` (only near
    /// the contacts when `near`): the output described again (counts,
    /// validity, manifoldness, volume, bounds), the smoothing report kept,
    /// `total` including smoothing.
    pub fn smoothed(
        mut self,
        smoothed: &Smoothed<PolygonMesh>,
        smooth_ms: f64,
        near: bool,
    ) -> Self {
        self.smoothed_near_contacts = Some(near);
        self.describe(&smoothed.shape);
        self.smoothing = Some(smoothed.report.clone());
        self.timings_ms.smooth = Some(smooth_ms);
        self.timings_ms.total += smooth_ms;
        self
    }
}

impl crate::WrittenMeshReport for CsgReport {
    /// The output described as written (counts, validity, manifoldness,
    /// volume, bounds); a CSG report names no file.
    fn describe_written(mut self, _file: &str, written: &PolygonMesh) -> Self {
        self.describe(written);
        self
    }

    fn record_f32_rounding(mut self, rounded: &RoundedMesh) -> Self {
        self.f32_rounding = Some(rounded.report.clone());
        self.timings_ms.round_f32 = Some(rounded.ms);
        self.timings_ms.total += rounded.ms;
        self
    }
}

/// The timings of an evaluation, in milliseconds.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct CsgTimings {
    /// The whole evaluation (parsing and file I/O excluded), smoothing
    /// and rounding to `f32` included when they ran.
    pub total: f64,
    /// Smoothing of the result, when it ran.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub smooth: Option<f64>,
    /// Rounding the result to `f32` and repairing it for a format of
    /// `f32` coordinates ([`crate::round_to_f32`]), when it ran.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub round_f32: Option<f64>,
}

/// The result of an evaluation.
#[derive(Clone, Debug)]
pub struct CsgResult {
    /// The output mesh (one triangle per facet in the triangle variant).
    pub mesh: PolygonMesh,
    /// The report.
    pub report: CsgReport,
    /// Where the operands of the tree's Booleans came close, in the root's
    /// frame, when [`CsgOptions::contacts`] asked for it and a Boolean
    /// ran: the boxes of every Boolean of the tree, each grown by at least
    /// [`Contacts::proximity`] (the least proximity any Boolean reached,
    /// measured in the root's frame). Smoothing the result at a tolerance
    /// up to that proximity near these boxes
    /// ([`crate::smooth_solid_near`]) equals smoothing it whole
    /// ([`crate::smooth_solid`]) when the leaves themselves need no
    /// smoothing.
    pub contacts: Option<Contacts>,
}

/// A solid in the variant being evaluated.
pub(super) enum Solid {
    Poly(PolygonMesh),
    Tri(TriangleMesh),
}

impl Solid {
    fn facets(&self) -> usize {
        match self {
            Solid::Poly(m) => m.facets.len(),
            Solid::Tri(m) => m.triangles.len(),
        }
    }

    fn vertices(&self) -> usize {
        match self {
            Solid::Poly(m) => m.vertices.len(),
            Solid::Tri(m) => m.vertices.len(),
        }
    }
}

/// A node's result with the contacts of the Booleans below it, in the
/// node's frame before its own transform.
struct Part {
    solid: Solid,
    /// For a Boolean's output not yet cleaned (module `clean`), the
    /// contact boxes of that Boolean alone: everything it created lies
    /// in them, and the parts below were cleaned before it ran.
    raw: Option<Vec<[Point3; 2]>>,
    /// The contact boxes of every Boolean below ([`Contacts::boxes`]),
    /// when [`CsgOptions::contacts`] asked for them.
    boxes: Vec<[Point3; 2]>,
    /// The least distance by which those boxes are grown, measured in the
    /// root's frame (infinite when no Boolean ran below).
    margin: f64,
}

impl Part {
    fn new(solid: Solid) -> Part {
        Part {
            solid,
            raw: None,
            boxes: Vec::new(),
            margin: f64::INFINITY,
        }
    }

    /// The largest extent of the solid's bounding box (0 when empty).
    fn extent(&self) -> f64 {
        crate::smoothing::extent(match &self.solid {
            Solid::Poly(m) => m.bounding_box(),
            Solid::Tri(m) => m.bounding_box(),
        })
    }
}

/// An upper bound of `1 / sigma_min` of the linear part of `m` (the
/// Frobenius norm of its inverse, at least its spectral norm): points
/// within `D` of each other after `m` were within `D * bound` before it,
/// and a box grown by `d` before `m` is grown by at least `d / bound`
/// after it. Infinite when the part is singular or not finite.
fn inverse_norm_bound(m: &DMat4) -> f64 {
    let l = DMat3::from_mat4(*m);
    let det = l.determinant();
    if !det.is_finite() || det == 0.0 {
        return f64::INFINITY;
    }
    let inv = l.inverse();
    let f = [inv.x_axis, inv.y_axis, inv.z_axis]
        .iter()
        .map(|c| c.length_squared())
        .sum::<f64>()
        .sqrt();
    if f.is_finite() {
        f
    } else {
        f64::INFINITY
    }
}

/// The box of the image of box `b` under `m`, grown by a bound of the
/// rounding of the transform (the mesh's vertices are transformed in
/// `f64`, so the images of points in `b` lie in it).
fn transform_box(m: &DMat4, [lo, hi]: [Point3; 2]) -> [Point3; 2] {
    let mut out_lo = [f64::INFINITY; 3];
    let mut out_hi = [f64::NEG_INFINITY; 3];
    let mut mag: f64 = 0.0;
    for k in 0..8 {
        let c = DVec3::new(
            if k & 1 == 0 { lo[0] } else { hi[0] },
            if k & 2 == 0 { lo[1] } else { hi[1] },
            if k & 4 == 0 { lo[2] } else { hi[2] },
        );
        mag = mag.max(c.abs().max_element());
        let q = m.transform_point3(c).to_array();
        for a in 0..3 {
            out_lo[a] = out_lo[a].min(q[a]);
            out_hi[a] = out_hi[a].max(q[a]);
            mag = mag.max(q[a].abs());
        }
    }
    let entries: f64 = m.to_cols_array().iter().map(|x| x.abs()).sum();
    let slack = 1e-12 * mag * (1.0 + entries);
    [out_lo.map(|x| x - slack), out_hi.map(|x| x + slack)]
}

struct Ctx<'a> {
    options: CsgOptions,
    total: usize,
    done: AtomicUsize,
    progress: Option<&'a (dyn Fn(usize, usize) + Sync)>,
    nodes: Mutex<Vec<(Vec<usize>, NodeReport)>>,
    /// Intermediate results cleaned (module `clean`).
    cleaned: AtomicUsize,
}

impl Ctx<'_> {
    /// `part` as an operand of a Boolean: a raw Boolean output with
    /// coincident vertices cleaned near its contacts (module `clean`),
    /// unless [`CsgOptions::raw_intermediates`].
    fn operand(&self, mut part: Part) -> Part {
        if let Some(fresh) = part.raw.take() {
            if !self.options.raw_intermediates
                && !fresh.is_empty()
                && clean::needs_cleaning(&part.solid)
            {
                if let Some(solid) = clean::cleaned(&part.solid, &fresh) {
                    part.solid = solid;
                    self.cleaned.fetch_add(1, Ordering::Relaxed);
                }
            }
        }
        part
    }

    /// The Boolean of two parts at a node whose result reaches the root's
    /// frame through a linear part with [`inverse_norm_bound`] `inv`,
    /// gathering its contacts when asked.
    fn boolean(
        &self,
        a: Part,
        b: Part,
        op: BooleanOp,
        path: &[usize],
        inv: f64,
    ) -> Result<Part, ModelError> {
        let err = |source| ModelError::Boolean {
            node: path_string(path),
            source,
        };
        let (a, b) = (self.operand(a), self.operand(b));
        let least =
            (CONTACT_RELATIVE_PROXIMITY * a.extent().max(b.extent())).max(f64::MIN_POSITIVE);
        // The proximity here: the wanted one carried back from the root's
        // frame, and at least the relative one; none when the transforms
        // above cannot carry a distance back. Without contacts asked for,
        // the least one, for the clean-up of the result (module `clean`).
        let proximity = match self.options.contacts {
            Some(want) => {
                // The factors keep the reached margin (below) at least
                // `want` whatever the rounding of these products.
                let local = (want.max(0.0) * inv * (1.0 + 1e-11)).max(least);
                (local.is_finite() && inv.is_finite()).then_some(local)
            }
            None => (!self.options.raw_intermediates && least.is_finite()).then_some(least),
        };
        let (solid, contacts) = match (a.solid, b.solid, proximity) {
            (Solid::Poly(x), Solid::Poly(y), None) => (
                Solid::Poly(boolean_mesh(&x, &y, op).map_err(err)?.mesh),
                None,
            ),
            (Solid::Poly(x), Solid::Poly(y), Some(p)) => {
                let (o, c) = boolean_mesh_with_contacts(&x, &y, op, p).map_err(err)?;
                (Solid::Poly(o.mesh), Some(c))
            }
            (Solid::Tri(x), Solid::Tri(y), None) => (
                Solid::Tri(boolean_triangles(&x, &y, op).map_err(err)?.mesh),
                None,
            ),
            (Solid::Tri(x), Solid::Tri(y), Some(p)) => {
                let (o, c) = boolean_triangles_with_contacts(&x, &y, op, p).map_err(err)?;
                (Solid::Tri(o.mesh), Some(c))
            }
            _ => {
                return Err(err(boolean_3d::Boolean3Error::Internal(
                    "operands of different variants".into(),
                )))
            }
        };
        let mut boxes = a.boxes;
        boxes.extend(b.boxes);
        // Without contacts (not asked, or the transforms above are
        // singular) the margin is 0: the result's contacts serve nothing.
        let mut margin = a.margin.min(b.margin);
        let mut fresh = None;
        match contacts {
            Some(c) => {
                margin = margin.min(c.proximity / inv * (1.0 - 1e-12));
                if self.options.contacts.is_some() {
                    boxes.extend_from_slice(&c.boxes);
                }
                fresh = Some(c.boxes);
            }
            None => margin = 0.0,
        }
        let done = self.done.fetch_add(1, Ordering::SeqCst) + 1;
        if let Some(p) = self.progress {
            p(done, self.total);
        }
        Ok(Part {
            solid,
            raw: fresh,
            boxes,
            margin,
        })
    }

    /// The n-ary `op` of `items` as a balanced tree of binary Booleans
    /// ([`crate::nary::reduce_op`], the reduction of the n-ary facade
    /// functions): the pairing depends only on the count, so the result
    /// does not depend on the schedule.
    fn reduce(
        &self,
        items: Vec<Part>,
        op: BooleanOp,
        path: &[usize],
        inv: f64,
    ) -> Result<Part, ModelError> {
        reduce_op(items, op, &|a, b, op| self.boolean(a, b, op, path, inv))?.ok_or_else(|| {
            ModelError::Script {
                file: String::new(),
                node: path_string(path),
                message: "an operation needs at least one child".into(),
            }
        })
    }

    fn leaf(&self, node: &CsgNode, path: &[usize]) -> Result<Solid, ModelError> {
        let located = |e: ModelError| match e {
            ModelError::InvalidParameter { param, message } => ModelError::Script {
                file: String::new(),
                node: path_string(path),
                message: format!("{param} {message}"),
            },
            other => other,
        };
        let mesh = match &node.shape {
            CsgShape::Box(b) => cuboid(DVec3::from_array(b.size), b.center),
            CsgShape::Sphere(s) => uv_sphere(s.radius, s.segments, s.rings()),
            CsgShape::Cylinder(c) => cylinder(
                c.radius,
                c.radius_top.unwrap_or(c.radius),
                c.height,
                c.segments,
                c.center,
            ),
            CsgShape::Torus(t) => torus(t.radius, t.tube, t.segments),
            CsgShape::File(p) => read_file(p, path),
            CsgShape::Op { .. } => Err(ModelError::Script {
                file: String::new(),
                node: path_string(path),
                message: "an operation is not a leaf".into(),
            }),
        }
        .map_err(located)?;
        Ok(if self.options.triangulate {
            Solid::Tri(triangulate_mesh(&mesh))
        } else {
            Solid::Poly(mesh)
        })
    }

    /// Evaluates `node`, whose result reaches the root's frame through
    /// `above` (the product of its ancestors' transforms).
    fn eval(&self, node: &CsgNode, path: &[usize], above: &DMat4) -> Result<Part, ModelError> {
        let own = (!node.transform.is_identity()).then(|| node.transform.matrix());
        let to_root = own.map_or(*above, |m| *above * m);
        let (part, booleans, operand_facets, own_ms) = match &node.shape {
            CsgShape::Op { op, children } => {
                let results: Vec<Result<Part, ModelError>> = children
                    .par_iter()
                    .enumerate()
                    .map(|(i, c)| {
                        let mut p = path.to_vec();
                        p.push(i);
                        self.eval(c, &p, &to_root)
                    })
                    .collect();
                let parts: Vec<Part> = results.into_iter().collect::<Result<_, _>>()?;
                let operand_facets = parts.iter().map(|p| p.solid.facets()).collect();
                let start = Instant::now();
                let booleans = parts.len().saturating_sub(1);
                let inv = if self.options.contacts.is_some() {
                    inverse_norm_bound(&to_root)
                } else {
                    f64::INFINITY
                };
                // Xor reaches the 3D Boolean, which refuses it with an
                // error naming the node.
                let part = self.reduce(parts, *op, path, inv)?;
                (part, booleans, operand_facets, start.elapsed())
            }
            _ => {
                let start = Instant::now();
                let part = Part::new(self.leaf(node, path)?);
                (part, 0, Vec::new(), start.elapsed())
            }
        };
        let start = Instant::now();
        let part = match own {
            None => part,
            Some(m) => {
                let located = |e: ModelError| ModelError::Script {
                    file: String::new(),
                    node: path_string(path),
                    message: e.to_string(),
                };
                let solid = match part.solid {
                    Solid::Poly(s) => Solid::Poly(transform_mesh(&s, &m).map_err(located)?),
                    Solid::Tri(s) => Solid::Tri(transform_triangles(&s, &m).map_err(located)?),
                };
                Part {
                    solid,
                    raw: part
                        .raw
                        .map(|fresh| fresh.into_iter().map(|b| transform_box(&m, b)).collect()),
                    boxes: part
                        .boxes
                        .into_iter()
                        .map(|b| transform_box(&m, b))
                        .collect(),
                    margin: part.margin,
                }
            }
        };
        let ms = (own_ms + start.elapsed()).as_secs_f64() * 1e3;
        let report = NodeReport {
            path: path_string(path),
            kind: node.shape.kind().to_string(),
            booleans,
            operand_facets,
            vertices: part.solid.vertices(),
            facets: part.solid.facets(),
            ms,
        };
        if let Ok(mut nodes) = self.nodes.lock() {
            nodes.push((path.to_vec(), report));
        }
        Ok(part)
    }
}

#[cfg(feature = "io")]
fn read_file(p: &std::path::Path, path: &[usize]) -> Result<PolygonMesh, ModelError> {
    let mesh = crate::read_mesh(p, crate::MeshReadOptions::default(), true).map_err(|e| {
        ModelError::File {
            node: path_string(path),
            message: e.to_string(),
        }
    })?;
    // A leaf is a solid: one written with its facets facing inward (the
    // opposite orientation convention) is turned outward, as `umbra
    // boolean` does by default (a script has no inside-out leaves).
    Ok(crate::turned_outward(&mesh).unwrap_or(mesh))
}

#[cfg(not(feature = "io"))]
fn read_file(p: &std::path::Path, path: &[usize]) -> Result<PolygonMesh, ModelError> {
    Err(ModelError::File {
        node: path_string(path),
        message: format!(
            "{}: reading mesh files needs the facade's `io` feature",
            p.display()
        ),
    })
}

/// Evaluates a CSG tree (see [`evaluate_csg_with_progress`]).
pub fn evaluate_csg(root: &CsgNode, options: CsgOptions) -> Result<CsgResult, ModelError> {
    evaluate_csg_with_progress(root, options, None)
}

/// Evaluates a CSG tree with the 3D Boolean of chapter 4: every node's
/// children in parallel, an n-ary union or intersection as a balanced tree
/// of binary Booleans, a difference as the first child minus the union of
/// the others, each node's transform applied to its result. `progress` is
/// called after every Boolean with (done, total), from any thread. The
/// output mesh is the same bit for bit whatever the number of threads; the
/// first failing node in tree order is reported. Trees built in code are
/// checked here as scripts are when parsed (parameters, transforms, at
/// least one child per operation, depth at most [`MAX_DEPTH`]): a bad tree
/// gives an error, never a panic.
///
/// # Example
///
/// ```
/// use umbra::{evaluate_csg, parse_csg, CsgOptions};
///
/// let tree = parse_csg(r#"{"op": "difference", "children": [
///     {"box": {"size": [2, 2, 2], "center": true}},
///     {"cylinder": {"radius": 0.5, "height": 3, "segments": 8, "center": true}}]}"#)?;
/// let out = evaluate_csg(&tree, CsgOptions::default())?;
/// assert!(out.report.topologically_valid);
/// assert_eq!(out.report.booleans, 1);
/// // The box minus the octagonal prism: 8 - 2 * (8 / 2) * 0.25 * sin(pi / 4).
/// let prism = 2.0 * 4.0 * 0.25 * (std::f64::consts::TAU / 8.0).sin();
/// assert!((out.report.volume - (8.0 - prism)).abs() < 1e-12);
/// # Ok::<(), umbra::ModelError>(())
/// ```
pub fn evaluate_csg_with_progress(
    root: &CsgNode,
    options: CsgOptions,
    progress: Option<&(dyn Fn(usize, usize) + Sync)>,
) -> Result<CsgResult, ModelError> {
    let start = Instant::now();
    let depth = root.depth();
    if depth > MAX_DEPTH + 1 {
        return Err(ModelError::Script {
            file: String::new(),
            node: "root".into(),
            message: format!("nesting deeper than {MAX_DEPTH} ({depth} levels)"),
        });
    }
    let ctx = Ctx {
        options,
        total: root.boolean_count(),
        done: AtomicUsize::new(0),
        progress,
        nodes: Mutex::new(Vec::new()),
        cleaned: AtomicUsize::new(0),
    };
    let part = ctx.eval(root, &[], &DMat4::IDENTITY)?;
    let contacts =
        (options.contacts.is_some() && ctx.done.load(Ordering::SeqCst) > 0).then_some(Contacts {
            proximity: part.margin,
            boxes: part.boxes,
        });
    let mesh = match part.solid {
        Solid::Poly(m) => m,
        Solid::Tri(t) => t.to_polygon_mesh(),
    };
    let mut nodes = ctx.nodes.into_inner().unwrap_or_else(|e| e.into_inner());
    nodes.sort_by(|a, b| a.0.cmp(&b.0));
    let topology = mesh.check_topology();
    let bounds = mesh.bounding_box();
    let mut report = CsgReport {
        variant: if options.triangulate {
            "triangle"
        } else {
            "polygon"
        },
        booleans: ctx.done.load(Ordering::SeqCst),
        leaves: root.leaf_count(),
        cleaned: ctx.cleaned.load(Ordering::SeqCst),
        threads: rayon::current_num_threads(),
        vertices: mesh.vertices.len(),
        facets: mesh.facets.len(),
        half_edges: mesh.half_edge_count(),
        topologically_valid: topology.is_ok(),
        topology_error: topology.err().map(|e| e.to_string()),
        two_manifold: None,
        open_edges: None,
        non_manifold_edges: None,
        non_manifold_vertices: None,
        volume: topology::mesh_signed_volume(&mesh),
        bounds,
        smoothing: None,
        smoothed_near_contacts: None,
        f32_rounding: None,
        timings_ms: CsgTimings {
            total: start.elapsed().as_secs_f64() * 1e3,
            smooth: None,
            round_f32: None,
        },
        nodes: nodes.into_iter().map(|(_, r)| r).collect(),
    };
    report.set_manifold_counts(&mesh);
    // The whole evaluation, its report's census included.
    report.timings_ms.total = start.elapsed().as_secs_f64() * 1e3;
    Ok(CsgResult {
        mesh,
        report,
        contacts,
    })
}
