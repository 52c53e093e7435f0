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

use crate::mesh::index::{BoxIndex, IdBox};
use crate::mesh::run_with;
use crate::mesh::triangles::triangulate_result;
use crate::{SmoothError, SmoothOptions, SmoothReport, Smoothed};
use rayon::prelude::*;
use std::collections::{HashMap, HashSet};
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
trait Facets: Sync {
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
    let bad = (0..facets.count()).into_par_iter().find_first(|&f| {
        facets
            .half_edges(f)
            .any(|(s, e)| s as usize >= n || e as usize >= n)
    });
    match bad {
        None => Ok(()),
        Some(f) => {
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
    }
}

/// The facets whose box comes within `reach` of a contact box.
fn near_facets<F: Facets + ?Sized>(
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
    // The box around all contact boxes: most facets fail this test alone.
    let (mut all_lo, mut all_hi) = ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]);
    for b in &boxes {
        for c in 0..3 {
            all_lo[c] = all_lo[c].min(b.lo[c]);
            all_hi[c] = all_hi[c].max(b.hi[c]);
        }
    }
    let index = BoxIndex::new(boxes);
    (0..facets.count())
        .into_par_iter()
        .map(|f| {
            let mut lo = [f64::INFINITY; 3];
            let mut hi = [f64::NEG_INFINITY; 3];
            for v in facets.starts(f) {
                let p = pos[v as usize];
                for c in 0..3 {
                    lo[c] = lo[c].min(p[c]);
                    hi[c] = hi[c].max(p[c]);
                }
            }
            if (0..3).any(|c| lo[c] > all_hi[c] || hi[c] < all_lo[c]) {
                return false;
            }
            let mut hit = false;
            index.visit(&lo, &hi, |_| hit = true);
            hit
        })
        .collect()
}

/// The facets sharing a vertex with a facet of `region`.
fn widen<F: Facets + ?Sized>(n: usize, facets: &F, region: &[bool]) -> Vec<bool> {
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
    let mut local = vec![u32::MAX; n];
    let mut global = Vec::new();
    let mut edges = HashSet::new();
    for f in (0..facets.count()).filter(|&f| region[f]) {
        for (s, e) in facets.half_edges(f) {
            edges.insert((s.min(e), s.max(e)));
            local[s as usize] = 0;
        }
    }
    // Local indices in global order (the merge's "earlier vertex" order is
    // kept).
    for (v, l) in local.iter_mut().enumerate() {
        if *l == 0 {
            *l = global.len() as u32;
            global.push(v as u32);
        }
    }
    let sub_facets: Vec<Facet> = (0..facets.count())
        .filter(|&f| region[f])
        .map(|f| Facet {
            half_edges: facets
                .half_edges(f)
                .map(|(s, e)| HalfEdge {
                    start: local[s as usize],
                    end: local[e as usize],
                })
                .collect(),
        })
        .collect();
    let frozen: Vec<(u32, u32)> = (0..facets.count())
        .into_par_iter()
        .filter(|&f| !region[f])
        .flat_map_iter(|f| {
            let edges = &edges;
            let local = &local;
            facets.half_edges(f).filter(move |&(s, e)| {
                local[s as usize] != u32::MAX
                    && local[e as usize] != u32::MAX
                    && edges.contains(&(s.min(e), s.max(e)))
            })
        })
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
/// new index from `next` for a created vertex. `None` when two input
/// vertices of the region share a position (then positions do not name
/// vertices and the region cannot be put back this way).
fn place(out: &[Point3], cut: &Cut, next: &mut u32) -> Option<Vec<u32>> {
    let mut at: HashMap<[u64; 3], u32> = HashMap::with_capacity(cut.global.len());
    for (i, p) in cut.sub.vertices.iter().enumerate() {
        if at.insert(p.map(f64::to_bits), cut.global[i]).is_some() {
            return None;
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
    let mut ids: HashMap<u32, u32> = HashMap::new();
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

/// The vertices of `pos` that `facets` (vertex lists of any kind) use,
/// in their order, and the facets renumbered to them.
fn compact_vertices<T: AsMut<[u32]> + AsRef<[u32]> + Send>(
    pos: Vec<Point3>,
    facets: &mut [T],
) -> Vec<Point3> {
    let mut used = vec![false; pos.len()];
    for f in facets.iter() {
        for &v in f.as_ref() {
            used[v as usize] = true;
        }
    }
    let mut map = vec![u32::MAX; pos.len()];
    let mut out = Vec::with_capacity(pos.len());
    for (i, p) in pos.into_iter().enumerate() {
        if used[i] {
            map[i] = out.len() as u32;
            out.push(p);
        }
    }
    facets
        .par_iter_mut()
        .for_each(|f| f.as_mut().iter_mut().for_each(|v| *v = map[*v as usize]));
    out
}

/// What smoothing a region gave.
enum Outcome {
    /// No facet comes near a contact: nothing to smooth.
    Untouched(SmoothReport),
    /// The region, smoothed and fitting its cut.
    Smoothed {
        /// Every vertex position: the input's, then created ones.
        pos: Vec<Point3>,
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
    for _ in 0..=MAX_GROWTHS {
        region = widen(pos.len(), facets, &region);
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
            let mut all_pos = pos.to_vec();
            all_pos.resize(next as usize, [0.0; 3]);
            for (i, &g) in global.iter().enumerate() {
                all_pos[g as usize] = out_pos[i];
            }
            return Ok(Outcome::Smoothed {
                pos: all_pos,
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
    let (pos, region_out, region, report) = match outcome {
        Outcome::Untouched(report) => {
            return Ok(Smoothed {
                shape: mesh.clone(),
                report,
            })
        }
        Outcome::Reached => return crate::smooth_mesh(mesh, options),
        Outcome::Smoothed {
            pos,
            facets,
            region,
            report,
        } => (pos, facets, region, report),
    };
    let mut cycles: Vec<Vec<u32>> = mesh
        .facets
        .iter()
        .zip(&region)
        .filter(|(_, &r)| !r)
        .map(|(f, _)| f.half_edges.iter().flat_map(|h| [h.start, h.end]).collect())
        .collect();
    cycles.extend(
        region_out
            .iter()
            .map(|f| f.iter().flat_map(|&(s, e)| [s, e]).collect::<Vec<u32>>()),
    );
    let vertices = compact_vertices(pos, &mut cycles);
    let facets = cycles
        .iter()
        .map(|c| Facet {
            half_edges: c
                .chunks_exact(2)
                .map(|p| HalfEdge {
                    start: p[0],
                    end: p[1],
                })
                .collect(),
        })
        .collect();
    let shape = PolygonMesh::new(vertices, facets);
    #[cfg(debug_assertions)]
    crate::sanity_check_mesh(&shape, options.tolerance)?;
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
    let (pos, region_out, region, report) = match outcome {
        Outcome::Untouched(report) => {
            return Ok(Smoothed {
                shape: mesh.clone(),
                report,
            })
        }
        Outcome::Reached => return crate::smooth_triangles(mesh, options),
        Outcome::Smoothed {
            pos,
            facets,
            region,
            report,
        } => (pos, facets, region, report),
    };
    let mut triangles: Vec<[u32; 3]> = mesh
        .triangles
        .iter()
        .zip(&region)
        .filter(|(_, &r)| !r)
        .map(|(t, _)| *t)
        .collect();
    triangles.extend(region_out.iter().map(|f| [f[0].0, f[1].0, f[2].0]));
    let vertices = compact_vertices(pos, &mut triangles);
    let shape = TriangleMesh::new(vertices, triangles);
    #[cfg(debug_assertions)]
    crate::sanity_check_triangles(&shape, options.tolerance)?;
    Ok(Smoothed { shape, report })
}
