//! Smoothing near contacts: data smoothing (chapter 5, Appendix A) of
//! only the part of a mesh that lies near given boxes, such as the places
//! where the two operands of a Boolean cut or touch each other
//! (`boolean_3d::Contacts`). Away from them the result of a Boolean is
//! made of untouched pieces of one operand, which smoothing would leave
//! as they are when the operands themselves need no smoothing; looking
//! only near the contacts makes smoothing cost what the Boolean changed,
//! not the size of the shape.
//!
//! The region is every facet whose box comes within `REACH * delta` of a
//! contact box, widened by one ring (every facet sharing a vertex with
//! it), so that the vertices smoothing may merge or crack near lie inside.
//! The region is cut out as an open mesh, smoothed by the same phases as
//! a whole mesh, and put back. Putting back is checked, not assumed: the
//! smoothed region together with the facet made of the rest of the mesh's
//! half-edges along the cut (the "frozen" boundary) must satisfy the
//! closure constraints of section 4.2, and every vertex on the cut must
//! still be there, unmoved. Then the whole result is closed (the argument
//! is in `docs/algorithms/smooth.md`, "Smoothing near contacts"). When the
//! check fails (smoothing reached the cut), the region grows by a ring and
//! smoothing is redone, and after [`MAX_GROWTHS`] growths the whole mesh
//! is smoothed.

use crate::mesh::guard;
use crate::mesh::index::{grown_box, BoxIndex, IdBox};
use crate::mesh::run_with;
use crate::mesh::triangles::triangulate_result;
use crate::{SmoothError, SmoothOptions, SmoothReport, Smoothed};
use rayon::prelude::*;
use rustc_hash::{FxHashMap, FxHashSet};
use std::collections::HashMap;
use topology::{Facet, HalfEdge, Point3, PolygonMesh, TopologyError, TriangleMesh};

/// How far from a contact box (in tolerances) a facet still belongs to
/// the region: merging moves a vertex by at most `delta`, a created vertex
/// lies within `2.5 delta` of its edges, and a vertex within `delta` of
/// one of those is met next, so chains of a few adjustments stay inside.
pub const REACH: f64 = 8.0;

/// How many times the region grows by a ring when smoothing reached its
/// cut before the whole mesh is smoothed instead.
pub const MAX_GROWTHS: usize = 3;

/// The facets of a mesh, as the region code reads them.
pub(crate) trait Facets: Sync {
    /// The number of facets.
    fn count(&self) -> usize;
    /// The start vertices of facet `f`'s half-edges.
    fn starts(&self, f: usize) -> impl Iterator<Item = u32>;
    /// Facet `f`'s half-edges.
    fn half_edges(&self, f: usize) -> impl Iterator<Item = (u32, u32)>;
}

impl Facets for [Facet] {
    fn count(&self) -> usize {
        self.len()
    }
    fn starts(&self, f: usize) -> impl Iterator<Item = u32> {
        self[f].half_edges.iter().map(|h| h.start)
    }
    fn half_edges(&self, f: usize) -> impl Iterator<Item = (u32, u32)> {
        self[f].half_edges.iter().map(|h| (h.start, h.end))
    }
}

impl Facets for [[u32; 3]] {
    fn count(&self) -> usize {
        self.len()
    }
    fn starts(&self, f: usize) -> impl Iterator<Item = u32> {
        self[f].into_iter()
    }
    fn half_edges(&self, f: usize) -> impl Iterator<Item = (u32, u32)> {
        let t = self[f];
        (0..3).map(move |k| (t[k], t[(k + 1) % 3]))
    }
}

/// Every index in range (the cheap part of validation that the whole
/// mesh gets; closure is checked where smoothing works).
fn check_indices<F: Facets + ?Sized>(n: usize, facets: &F) -> Result<(), SmoothError> {
    let bad = |f: usize| {
        facets
            .half_edges(f)
            .any(|(s, e)| s as usize >= n || e as usize >= n)
    };
    let count = facets.count();
    let any_bad = (0..count.div_ceil(4096)).into_par_iter().any(|c| {
        let end = (c * 4096 + 4096).min(count);
        (c * 4096..end).any(bad)
    });
    if !any_bad {
        return Ok(());
    }
    let f = (0..count).find(|&f| bad(f)).unwrap_or(0);
    let vertex = facets
        .half_edges(f)
        .flat_map(|(s, e)| [s, e])
        .find(|&v| v as usize >= n)
        .unwrap_or(u32::MAX);
    Err(SmoothError::InvalidInput(TopologyError::DanglingIndex {
        entity: "facet",
        entity_index: f as u32,
        vertex,
        vertex_count: n as u32,
    }))
}

/// The most cells of the occupancy grid along an axis.
const GRID: f64 = 64.0;

/// The most cell markings the occupancy grid may cost (beyond it every
/// facet inside the contacts' box goes to the hierarchy).
const GRID_WORK: usize = 1 << 24;

/// A coarse grid over the contact boxes' bounding box marking the cells
/// a contact box meets: a facet whose cells are all unmarked meets no
/// contact box. Cells are numbered by a monotone rounding of the
/// coordinates, so two boxes that meet have cell ranges that meet.
struct Occupancy {
    lo: Point3,
    scale: [f64; 3],
    dims: [usize; 3],
    marked: Vec<bool>,
}

impl Occupancy {
    /// The grid over `[lo, hi]` marked by `boxes`, or `None` when marking
    /// would cost more than [`GRID_WORK`] or the box is not finite.
    fn new(lo: Point3, hi: Point3, boxes: &[IdBox]) -> Option<Occupancy> {
        let extent = (0..3).map(|c| hi[c] - lo[c]).fold(0.0, f64::max);
        if !extent.is_finite() || !(0..3).all(|c| lo[c].is_finite() && hi[c].is_finite()) {
            return None;
        }
        let cell = (extent / GRID).max(f64::MIN_POSITIVE);
        let dims: [usize; 3] =
            std::array::from_fn(|c| (((hi[c] - lo[c]) / cell).ceil() as usize).clamp(1, 64));
        let scale: [f64; 3] = std::array::from_fn(|c| dims[c] as f64 / (hi[c] - lo[c]).max(cell));
        let mut g = Occupancy {
            lo,
            scale,
            dims,
            marked: vec![false; dims[0] * dims[1] * dims[2]],
        };
        let mut work = 0usize;
        for b in boxes {
            let (a, z) = (g.cell(&b.lo), g.cell(&b.hi));
            work += (0..3).map(|c| z[c] - a[c] + 1).product::<usize>();
            if work > GRID_WORK {
                return None;
            }
            for i in a[0]..=z[0] {
                for j in a[1]..=z[1] {
                    for k in a[2]..=z[2] {
                        g.marked[(i * dims[1] + j) * dims[2] + k] = true;
                    }
                }
            }
        }
        Some(g)
    }

    /// The cell of `p` (clamped into the grid). Truncation is the floor
    /// of the non-negative values, and the others go to cell 0 either way
    /// (no call to `floor`, a library call on the baseline target).
    fn cell(&self, p: &Point3) -> [usize; 3] {
        std::array::from_fn(|c| {
            let x = (p[c] - self.lo[c]) * self.scale[c];
            if x >= 0.0 {
                (x as usize).min(self.dims[c] - 1)
            } else {
                0
            }
        })
    }

    /// Whether a marked cell meets the box `[lo, hi]`.
    fn meets(&self, lo: &Point3, hi: &Point3) -> bool {
        let (a, z) = (self.cell(lo), self.cell(hi));
        (a[0]..=z[0]).any(|i| {
            (a[1]..=z[1]).any(|j| {
                (a[2]..=z[2]).any(|k| self.marked[(i * self.dims[1] + j) * self.dims[2] + k])
            })
        })
    }
}

/// The facets whose box comes within `reach` of a contact box.
pub(crate) fn near_facets<F: Facets + ?Sized>(
    pos: &[Point3],
    facets: &F,
    contacts: &[[Point3; 2]],
    reach: f64,
) -> Vec<bool> {
    let boxes: Vec<IdBox> = contacts
        .iter()
        .enumerate()
        .filter(|(_, b)| (0..3).all(|c| b[0][c] <= b[1][c]))
        .map(|(i, b)| IdBox {
            lo: b[0].map(|x| x - reach),
            hi: b[1].map(|x| x + reach),
            id: i as u32,
        })
        .collect();
    if boxes.is_empty() {
        return vec![false; facets.count()];
    }
    // The box around all contact boxes and a coarse grid in it: most
    // facets fail these tests alone.
    let (mut all_lo, mut all_hi) = ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]);
    for b in &boxes {
        for c in 0..3 {
            all_lo[c] = all_lo[c].min(b.lo[c]);
            all_hi[c] = all_hi[c].max(b.hi[c]);
        }
    }
    let grid = Occupancy::new(all_lo, all_hi, &boxes);
    let index = BoxIndex::new(boxes);
    // Most facets are found apart from the box of all contacts by their
    // corners' codes alone.
    let beyond = topology::sides_beyond(pos, &[all_lo, all_hi]);
    (0..facets.count())
        .into_par_iter()
        .map(|f| {
            if topology::facet_apart(&beyond, facets.starts(f)) {
                return false;
            }
            let (lo, hi) = grown_box(facets.starts(f).map(|v| pos[v as usize]), 0.0);
            if grid.as_ref().is_some_and(|g| !g.meets(&lo, &hi)) {
                return false;
            }
            let mut hit = false;
            index.visit(&lo, &hi, |_| hit = true);
            hit
        })
        .collect()
}

/// The facets sharing a vertex with a facet of `region`.
pub(crate) fn widen<F: Facets + ?Sized>(n: usize, facets: &F, region: &[bool]) -> Vec<bool> {
    let mut hot = vec![false; n];
    for f in (0..facets.count()).filter(|&f| region[f]) {
        for v in facets.starts(f) {
            hot[v as usize] = true;
        }
    }
    (0..facets.count())
        .into_par_iter()
        .map(|f| region[f] || facets.starts(f).any(|v| hot[v as usize]))
        .collect()
}

/// A region cut out of a mesh: the open sub-mesh and what putting it back
/// needs.
struct Cut {
    /// The region's facets as a polygon mesh over its own vertices.
    sub: PolygonMesh,
    /// The global index of every vertex of `sub`.
    global: Vec<u32>,
    /// The rest of the mesh's half-edges on the region's edges (the
    /// frozen boundary), in global indices.
    frozen: Vec<(u32, u32)>,
}

/// Cuts `region` out of the mesh.
fn cut<F: Facets + ?Sized>(pos: &[Point3], facets: &F, region: &[bool]) -> Cut {
    let n = pos.len();
    let inside: Vec<usize> = (0..facets.count())
        .into_par_iter()
        .filter(|&f| region[f])
        .collect();
    let mut local = vec![u32::MAX; n];
    let mut edges: FxHashSet<(u32, u32)> = FxHashSet::default();
    for &f in &inside {
        for (s, e) in facets.half_edges(f) {
            edges.insert((s.min(e), s.max(e)));
            local[s as usize] = 0;
        }
    }
    // Local indices in global order (the merge's "earlier vertex" order is
    // kept).
    let mut global = Vec::new();
    for (v, l) in local.iter_mut().enumerate() {
        if *l == 0 {
            *l = global.len() as u32;
            global.push(v as u32);
        }
    }
    let sub_facets: Vec<Facet> = inside
        .iter()
        .map(|&f| Facet {
            half_edges: facets
                .half_edges(f)
                .map(|(s, e)| HalfEdge {
                    start: local[s as usize],
                    end: local[e as usize],
                })
                .collect(),
        })
        .collect();
    // The rest's facets that touch the region, then their half-edges on
    // the region's edges.
    let touching: Vec<usize> = (0..facets.count())
        .into_par_iter()
        .filter(|&f| !region[f] && facets.starts(f).any(|v| local[v as usize] != u32::MAX))
        .collect();
    let frozen: Vec<(u32, u32)> = touching
        .iter()
        .flat_map(|&f| facets.half_edges(f))
        .filter(|&(s, e)| edges.contains(&(s.min(e), s.max(e))))
        .collect();
    let sub = PolygonMesh::new(
        global.iter().map(|&v| pos[v as usize]).collect(),
        sub_facets,
    );
    Cut {
        sub,
        global,
        frozen,
    }
}

/// The global index of every vertex of a smoothed region: the input
/// vertex at the same position (smoothing keeps every surviving input
/// vertex where it was, and leaves no two vertices at one position), or a
/// new index from `next` for a created vertex. Where several input
/// vertices of the region share a position (coincident vertices, which
/// smoothing merges into one), the output vertex there is the one on the
/// cut when one of them is (the frozen half-edges name it), else the one
/// of least index; the others are no longer used. `None` when two of them
/// are on the cut (the region cannot be put back this way: it grows).
fn place(out: &[Point3], cut: &Cut, next: &mut u32) -> Option<Vec<u32>> {
    let on_cut: FxHashSet<u32> = cut.frozen.iter().flat_map(|&(s, e)| [s, e]).collect();
    let mut at: HashMap<[u64; 3], u32> = HashMap::with_capacity(cut.global.len());
    for (i, p) in cut.sub.vertices.iter().enumerate() {
        let v = cut.global[i];
        match at.entry(p.map(f64::to_bits)) {
            std::collections::hash_map::Entry::Vacant(slot) => {
                slot.insert(v);
            }
            std::collections::hash_map::Entry::Occupied(mut slot) => {
                let w = *slot.get();
                let keep = match (on_cut.contains(&w), on_cut.contains(&v)) {
                    (true, true) => return None,
                    (true, false) => w,
                    (false, true) => v,
                    (false, false) => w.min(v),
                };
                slot.insert(keep);
            }
        }
    }
    Some(
        out.iter()
            .map(|p| {
                at.get(&p.map(f64::to_bits)).copied().unwrap_or_else(|| {
                    *next += 1;
                    *next - 1
                })
            })
            .collect(),
    )
}

/// Whether the smoothed region (its half-edges by facet, in global
/// indices) fits the frozen boundary: the region's facets plus one facet
/// of the frozen half-edges satisfy facet and shape boundary closure.
fn fits(region: &[Vec<(u32, u32)>], frozen: &[(u32, u32)]) -> bool {
    // Compact indices for the check.
    let mut ids: FxHashMap<u32, u32> = FxHashMap::default();
    let mut id = |v: u32| {
        let k = ids.len() as u32;
        *ids.entry(v).or_insert(k)
    };
    let mut facets: Vec<Facet> = region
        .iter()
        .map(|f| Facet {
            half_edges: f
                .iter()
                .map(|&(s, e)| HalfEdge {
                    start: id(s),
                    end: id(e),
                })
                .collect(),
        })
        .collect();
    facets.push(Facet {
        half_edges: frozen
            .iter()
            .map(|&(s, e)| HalfEdge {
                start: id(s),
                end: id(e),
            })
            .collect(),
    });
    let vertices = vec![[0.0; 3]; ids.len()];
    PolygonMesh::new(vertices, facets).check_topology().is_ok()
}

/// The report of a mesh nothing was near: nothing to do.
fn untouched(delta: f64) -> SmoothReport {
    SmoothReport {
        tolerance: delta,
        ..SmoothReport::default()
    }
}

/// The used vertices of `pos` followed by `created` (`used` flags both,
/// in that order), in their order, and every vertex's new index
/// (`u32::MAX` for unused ones).
fn compact_vertices(pos: &[Point3], created: &[Point3], used: &[bool]) -> (Vec<Point3>, Vec<u32>) {
    let mut map = vec![u32::MAX; used.len()];
    let mut out = Vec::with_capacity(used.len());
    for (i, &u) in used.iter().enumerate() {
        if u {
            map[i] = out.len() as u32;
            out.push(if i < pos.len() {
                pos[i]
            } else {
                created[i - pos.len()]
            });
        }
    }
    (out, map)
}

/// What smoothing a region gave.
enum Outcome {
    /// No facet comes near a contact, or smoothing the region gave it
    /// back unchanged: the mesh as it is.
    Untouched(SmoothReport),
    /// The region, smoothed and fitting its cut.
    Smoothed {
        /// The positions of the created vertices, whose global indices
        /// follow the input's.
        created: Vec<Point3>,
        /// The smoothed region's facets as half-edges, global indices.
        facets: Vec<Vec<(u32, u32)>>,
        /// Which input facets the region replaced.
        region: Vec<bool>,
        /// The region's smoothing report.
        report: SmoothReport,
    },
    /// Smoothing reached the cut at every growth.
    Reached,
}

/// Whether `out` holds exactly the facets of `facets` marked in `region`,
/// in their order, each with the same half-edges in the same order.
fn same_facets<F: Facets + ?Sized>(facets: &F, region: &[bool], out: &[Vec<(u32, u32)>]) -> bool {
    let mut out = out.iter();
    for f in (0..facets.count()).filter(|&f| region[f]) {
        match out.next() {
            Some(o) if facets.half_edges(f).eq(o.iter().copied()) => {}
            _ => return false,
        }
    }
    out.next().is_none()
}

/// Smooths the region of `facets` near the contacts, re-triangulating
/// when `triangles`.
fn smooth_region<F: Facets + ?Sized>(
    pos: &[Point3],
    facets: &F,
    options: &SmoothOptions,
    contacts: &[[Point3; 2]],
    triangles: bool,
) -> Result<Outcome, SmoothError> {
    let delta = options.tolerance;
    let mut region = near_facets(pos, facets, contacts, REACH * delta);
    if !region.iter().any(|&r| r) {
        return Ok(Outcome::Untouched(untouched(delta)));
    }
    for growth in 0..=MAX_GROWTHS {
        if growth > 0 {
            region = widen(pos.len(), facets, &region);
        }
        let c = cut(pos, facets, &region);
        let (shape, mut report) = run_with(&c.sub, options, false)?;
        let (out_pos, out_facets): (Vec<Point3>, Vec<Vec<(u32, u32)>>) = if triangles {
            let t = triangulate_result(&shape, &mut report, delta);
            let f = t
                .triangles
                .iter()
                .map(|t| vec![(t[0], t[1]), (t[1], t[2]), (t[2], t[0])])
                .collect();
            (t.vertices, f)
        } else {
            let f = shape
                .facets
                .iter()
                .map(|f| f.half_edges.iter().map(|h| (h.start, h.end)).collect())
                .collect();
            (shape.vertices, f)
        };
        let mut next = pos.len() as u32;
        let Some(global) = place(&out_pos, &c, &mut next) else {
            break;
        };
        // Every vertex on the cut must be one the smoothed region still has
        // or none of its facets uses any more; `fits` checks the rest.
        let region_facets: Vec<Vec<(u32, u32)>> = out_facets
            .iter()
            .map(|f| {
                f.iter()
                    .map(|&(s, e)| (global[s as usize], global[e as usize]))
                    .collect()
            })
            .collect();
        if fits(&region_facets, &c.frozen) {
            // Smoothing that changed nothing gives the mesh back as it
            // is, facets in their order (as whole smoothing does), not
            // with the region's facets moved to the end.
            if next as usize == pos.len() && same_facets(facets, &region, &region_facets) {
                return Ok(Outcome::Untouched(report));
            }
            // An input vertex keeps its position (`place` matched it by
            // position); created ones are new.
            let mut created = vec![[0.0; 3]; next as usize - pos.len()];
            for (i, &g) in global.iter().enumerate() {
                if g as usize >= pos.len() {
                    created[g as usize - pos.len()] = out_pos[i];
                }
            }
            return Ok(Outcome::Smoothed {
                created,
                facets: region_facets,
                region,
                report,
            });
        }
    }
    Ok(Outcome::Reached)
}

/// Smooths a polygon mesh only near `contacts` (boxes `[lo, hi]`, such as
/// `boolean_3d::Contacts::boxes`): facets whose box comes within
/// [`REACH`]` * tolerance` of a contact box, and their neighbours, are
/// smoothed as [`crate::smooth_mesh`] smooths a whole mesh; every other
/// facet is kept as it is. On a Boolean result of operands that need no
/// smoothing themselves, with the Boolean's contacts at a proximity of at
/// least the tolerance, the result is the whole-mesh smoothing's (the
/// operations only apply where two elements of different operands, or
/// created ones, come within the tolerance), at a cost proportional to the
/// region instead of the mesh.
///
/// Indices and coordinates of the whole mesh are validated; closure is
/// checked on the region and where it meets the rest. If smoothing
/// reaches the region's cut, the region grows, and in the end the whole
/// mesh is smoothed by [`crate::smooth_mesh`].
pub fn smooth_mesh_near(
    mesh: &PolygonMesh,
    options: &SmoothOptions,
    contacts: &[[Point3; 2]],
) -> Result<Smoothed<PolygonMesh>, SmoothError> {
    options.validate()?;
    mesh.validate_coordinates()?;
    check_indices(mesh.vertices.len(), mesh.facets.as_slice())?;
    let outcome = smooth_region(
        &mesh.vertices,
        mesh.facets.as_slice(),
        options,
        contacts,
        false,
    )?;
    let (created, region_out, region, report) = match outcome {
        Outcome::Untouched(report) => {
            return Ok(Smoothed {
                shape: mesh.clone(),
                report,
            })
        }
        Outcome::Reached => return crate::smooth_mesh(mesh, options),
        Outcome::Smoothed {
            created,
            facets,
            region,
            report,
        } => (created, facets, region, report),
    };
    // The vertices used, in order, then the kept facets renamed in
    // parallel (one allocation per facet) and the region's appended.
    let n = mesh.vertices.len();
    let mut used = vec![false; n + created.len()];
    for (f, _) in mesh.facets.iter().zip(&region).filter(|(_, &r)| !r) {
        for h in &f.half_edges {
            used[h.start as usize] = true;
            used[h.end as usize] = true;
        }
    }
    for &(s, e) in region_out.iter().flatten() {
        used[s as usize] = true;
        used[e as usize] = true;
    }
    let (vertices, map) = compact_vertices(&mesh.vertices, &created, &used);
    let rename = |s: u32, e: u32| HalfEdge {
        start: map[s as usize],
        end: map[e as usize],
    };
    let mut facets: Vec<Facet> = mesh
        .facets
        .par_iter()
        .zip(region.par_iter())
        .filter(|(_, &r)| !r)
        .map(|(f, _)| Facet {
            half_edges: f
                .half_edges
                .iter()
                .map(|h| rename(h.start, h.end))
                .collect(),
        })
        .collect();
    facets.extend(region_out.iter().map(|f| Facet {
        half_edges: f.iter().map(|&(s, e)| rename(s, e)).collect(),
    }));
    let shape = PolygonMesh::new(vertices, facets);
    let (shape, report) = if options.guard {
        let kept = shape.facets.len() - region_out.len();
        let replaced: Vec<bool> = (0..shape.facets.len()).map(|f| f >= kept).collect();
        guard::guard(&report, (mesh, &region), (&shape, &replaced)).apply(mesh, shape, report)
    } else {
        (shape, report)
    };
    // The postconditions of a smoothing result; the guard's undone
    // places (and an input handed back) keep the input's features.
    #[cfg(debug_assertions)]
    if report.reverted.is_none() {
        crate::sanity_check_mesh(&shape, options.tolerance)?;
    }
    Ok(Smoothed { shape, report })
}

/// Smooths a triangle mesh only near `contacts`, as [`smooth_mesh_near`]
/// does for polygon meshes; the smoothed region is re-triangulated as
/// [`crate::smooth_triangles`] does, so the result stays a triangle mesh.
pub fn smooth_triangles_near(
    mesh: &TriangleMesh,
    options: &SmoothOptions,
    contacts: &[[Point3; 2]],
) -> Result<Smoothed<TriangleMesh>, SmoothError> {
    options.validate()?;
    mesh.validate_coordinates()?;
    check_indices(mesh.vertices.len(), mesh.triangles.as_slice())?;
    let outcome = smooth_region(
        &mesh.vertices,
        mesh.triangles.as_slice(),
        options,
        contacts,
        true,
    )?;
    let (created, region_out, region, report) = match outcome {
        Outcome::Untouched(report) => {
            return Ok(Smoothed {
                shape: mesh.clone(),
                report,
            })
        }
        Outcome::Reached => return crate::smooth_triangles(mesh, options),
        Outcome::Smoothed {
            created,
            facets,
            region,
            report,
        } => (created, facets, region, report),
    };
    let mut triangles: Vec<[u32; 3]> = mesh
        .triangles
        .iter()
        .zip(&region)
        .filter(|(_, &r)| !r)
        .map(|(t, _)| *t)
        .collect();
    triangles.extend(region_out.iter().map(|f| [f[0].0, f[1].0, f[2].0]));
    let mut used = vec![false; mesh.vertices.len() + created.len()];
    for &v in triangles.iter().flatten() {
        used[v as usize] = true;
    }
    let (vertices, map) = compact_vertices(&mesh.vertices, &created, &used);
    triangles
        .par_iter_mut()
        .for_each(|t| *t = t.map(|v| map[v as usize]));
    let shape = TriangleMesh::new(vertices, triangles);
    let (shape, report) = if options.guard {
        let kept = shape.triangles.len() - region_out.len();
        let replaced: Vec<bool> = (0..shape.triangles.len()).map(|t| t >= kept).collect();
        guard::guard(&report, (mesh, &region), (&shape, &replaced)).apply(mesh, shape, report)
    } else {
        (shape, report)
    };
    // The postconditions of a smoothing result; the guard's undone
    // places (and an input handed back) keep the input's features.
    #[cfg(debug_assertions)]
    if report.reverted.is_none() {
        crate::sanity_check_triangles(&shape, options.tolerance)?;
    }
    Ok(Smoothed { shape, report })
}

#[cfg(test)]
mod tests {
    use super::*;
    use boolean_3d::{boolean_triangles_with_contacts, BooleanOp};
    use test_support::shapes::{box_triangles, uv_sphere};

    fn cut_with(frozen: Vec<(u32, u32)>) -> Cut {
        let (p, q) = ([1.0, 2.0, 3.0], [4.0, 5.0, 6.0]);
        Cut {
            sub: PolygonMesh::new(vec![p, q, p], Vec::new()),
            global: vec![7, 9, 5],
            frozen,
        }
    }

    #[test]
    fn coincident_input_vertices_are_placed_as_the_one_on_the_cut() {
        let out = [[1.0, 2.0, 3.0], [4.0, 5.0, 6.0], [0.0; 3]];
        let mut next = 100;
        // Neither on the cut: the least index; a new position: a new one.
        assert_eq!(
            place(&out, &cut_with(vec![]), &mut next),
            Some(vec![5, 9, 100])
        );
        let mut next = 100;
        assert_eq!(
            place(&out, &cut_with(vec![(7, 9)]), &mut next),
            Some(vec![7, 9, 100])
        );
        // Both on the cut: the region cannot be put back by position.
        assert_eq!(
            place(&out, &cut_with(vec![(7, 9), (9, 5)]), &mut next),
            None
        );
    }

    /// The raw output of a Boolean that meets in a degenerate way (a
    /// sphere centred on a cube's corner, its pole on the cube's edge and
    /// its meridians in the faces) has coincident vertices; at tolerance
    /// 0 the region merges them and is put back, without whole smoothing.
    #[test]
    fn a_region_with_coincident_vertices_is_put_back() {
        let a = box_triangles([-1.0; 3], [1.0; 3]);
        let s = uv_sphere([1.0, 1.0, -1.0], 0.3, 16, 8);
        let (out, c) = boolean_triangles_with_contacts(&a, &s, BooleanOp::Difference, 0.0).unwrap();
        let m = &out.mesh;
        let mut seen = FxHashSet::default();
        assert!(m.vertices.iter().any(|p| !seen.insert(p.map(f64::to_bits))));
        let exact = SmoothOptions::new(0.0);
        let outcome = smooth_region(&m.vertices, m.triangles.as_slice(), &exact, &c.boxes, true);
        assert!(matches!(outcome, Ok(Outcome::Smoothed { .. })));
    }
}
