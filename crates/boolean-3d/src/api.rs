//! The public entry points: validation, the two mesh variants, and the
//! audit mode that returns the level data behind Theorems 1-4.

use crate::construct::{construct, CompositeKind, CompositeRecord, FacetSource, Retained};
use crate::contacts::{exact_box, Contacts};
use crate::level3::{
    level3 as level3_fast, level3_broad, level3_brute, level3_with_contacts, Broad, Level3Data,
    Winding,
};
use crate::merge::Merged;
use crate::mesh::Flat;
use crate::par;
use crate::retriangulate::{to_triangle_mesh, Source};
use crate::{Boolean3Error, BooleanOp, Operand};
use rayon::prelude::*;
use robust_arith::Point3;
use std::collections::HashMap;
use topology::{Facet, HalfEdge, PolygonMesh, TopologyError, TriangleMesh};

/// The result of the polygon-mesh variant.
#[derive(Clone, Debug, PartialEq)]
pub struct MeshOutput {
    /// The resulting shape (level 6), always topologically valid. Facets
    /// may have holes or several regions.
    pub mesh: PolygonMesh,
    /// For each facet of `mesh`, the input facet it is the retained part of
    /// (level 5).
    pub sources: Vec<FacetSource>,
    /// The number of edge-facet pairs with `X12 != 0` or `X21 != 0` (the
    /// intersection vertices of the result).
    pub intersections: usize,
}

/// The result of the triangle-mesh variant.
#[derive(Clone, Debug, PartialEq)]
pub struct TriangleOutput {
    /// The resulting shape, each retained facet triangulated by internal
    /// edges (section 4.8); always topologically valid.
    pub mesh: TriangleMesh,
    /// The number of edge-facet intersection vertices.
    pub intersections: usize,
}

/// One retained facet as the audit saw it (Theorem 3).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct FacetAudit {
    /// The input facet it was retained from.
    pub source: FacetSource,
    /// Its number of half-edges.
    pub half_edges: u32,
    /// Whether it satisfies facet boundary closure.
    pub closed: bool,
}

/// The level data of one Boolean, for checking Theorems 1-4 independently
/// of the construction code (section 4.9).
#[derive(Clone, Debug, PartialEq)]
pub struct Audit {
    /// Level 3 as the fast path computed it (broad phase, one ray cast per
    /// connected component, winding numbers propagated along edges).
    pub level3: Level3Data,
    /// `X03(v_A, B)` by one ray cast per vertex (independent of the
    /// propagation identity).
    pub x03_per_vertex: Vec<i32>,
    /// `X30(A, v_B)` by one ray cast per vertex.
    pub x30_per_vertex: Vec<i32>,
    /// Start- and end-vertex counts of every composite edge as built.
    pub composites: Vec<CompositeRecord>,
    /// `E13`, `E22`, `E31` recomputed from the level-3 values by
    /// eq. 4.21-4.23 for every edge of A, every facet pair with an
    /// intersection, and every edge of B (Theorem 2 says all are 0).
    pub net_counts: Vec<(CompositeKind, i64)>,
    /// Every retained facet (Theorem 3).
    pub facets: Vec<FacetAudit>,
    /// Level-3 hits whose point lies outside where eq. 4.2-4.6 must put it:
    /// x and y are interpolated from points of the entity of A (the edge
    /// for `X12`, the facet for `X21`) with `|lambda| <= 1/2` and monotone
    /// rounding, so they lie in that entity's closed box; z comes from one
    /// of the two entities, so it lies in the union of their z-ranges.
    pub misplaced_points: Vec<(CompositeKind, [f64; 3])>,
    /// Shape boundary closure of the polygon-mesh result (Theorem 4).
    pub shape_closure: Result<(), TopologyError>,
}

impl Audit {
    /// Checks Theorem 1 at level 3 (every non-zero value has its
    /// interpolated point, and the propagated winding numbers equal the
    /// per-vertex casts), Theorem 2 (both as built and by eq. 4.21-4.23),
    /// Theorem 3 and Theorem 4. Levels 1-2 of Theorem 1 are checked inside
    /// every level-2 call (a missing partner aborts with
    /// [`Boolean3Error::Internal`]). Returns the first violation.
    pub fn verify(&self) -> Result<(), String> {
        for (name, hits) in [("X12", &self.level3.x12), ("X21", &self.level3.x21)] {
            if let Some(h) = hits
                .iter()
                .find(|h| h.value == 0 || h.point.iter().any(|c| !c.is_finite()))
            {
                return Err(format!("Theorem 1: {name} hit {h:?} has no valid point"));
            }
        }
        if let Some(m) = self.misplaced_points.first() {
            return Err(format!(
                "Theorem 1: level-3 point {m:?} outside its entities"
            ));
        }
        if self.level3.x03 != self.x03_per_vertex {
            return Err("Theorem 1: propagated X03 differs from per-vertex ray casts".into());
        }
        if self.level3.x30 != self.x30_per_vertex {
            return Err("Theorem 1: propagated X30 differs from per-vertex ray casts".into());
        }
        if let Some(c) = self.composites.iter().find(|c| c.starts != c.ends) {
            return Err(format!("Theorem 2: composite edge {c:?} is unbalanced"));
        }
        if let Some(e) = self.net_counts.iter().find(|e| e.1 != 0) {
            return Err(format!("Theorem 2: eq. 4.21-4.23 give {e:?}"));
        }
        if let Some(f) = self.facets.iter().find(|f| !f.closed) {
            return Err(format!("Theorem 3: retained facet {f:?} is not closed"));
        }
        self.shape_closure
            .clone()
            .map_err(|e| format!("Theorem 4: {e}"))
    }
}

/// Validates a polygon mesh operand (coordinates, then the constraints of
/// section 4.2) and builds its flat form.
fn flat_polygon(m: &PolygonMesh, operand: Operand) -> Result<Flat<'_>, Boolean3Error> {
    if m.half_edge_count() >= u32::MAX as usize || m.facets.len() >= u32::MAX as usize {
        return Err(Boolean3Error::TooLarge {
            what: "input half-edges",
        });
    }
    m.validate_coordinates()
        .and_then(|()| Flat::from_polygon_mesh(m))
        .map_err(|source| Boolean3Error::InvalidInput { operand, source })
}

/// Validates a triangle mesh operand and builds its flat form.
pub(crate) fn flat_triangles(
    m: &TriangleMesh,
    operand: Operand,
) -> Result<Flat<'_>, Boolean3Error> {
    if m.triangles.len() >= (u32::MAX / 3) as usize {
        return Err(Boolean3Error::TooLarge {
            what: "input triangles",
        });
    }
    m.validate_coordinates()
        .and_then(|()| Flat::from_triangle_mesh(m))
        .map_err(|source| Boolean3Error::InvalidInput { operand, source })
}

/// Both operands' flat forms, built in parallel when the smaller has at
/// least `smaller` facets worth splitting for; A's error is reported first.
fn flat_pair<'a, M: Sync>(
    a: &'a M,
    b: &'a M,
    smaller: usize,
    f: impl Fn(&'a M, Operand) -> Result<Flat<'a>, Boolean3Error> + Sync,
) -> Result<(Flat<'a>, Flat<'a>), Boolean3Error> {
    let (fa, fb) = par::join(smaller, || f(a, Operand::A), || f(b, Operand::B));
    Ok((fa?, fb?))
}

/// What [`run`] computes: the retained facets, the level data, the audit
/// when asked for and the contacts when asked for.
type Run = (Retained, Level3Data, Option<Audit>, Option<Contacts>);

/// Levels 3-5 on two validated operands (on their broad phases when
/// given), and with `Some(proximity)` the operands' [`Contacts`] at that
/// distance.
fn run(
    a: &Flat<'_>,
    b: &Flat<'_>,
    broad: Option<[&Broad; 2]>,
    op: BooleanOp,
    audit: bool,
    proximity: Option<f64>,
) -> Result<Run, Boolean3Error> {
    let (l3, near) = match broad {
        Some([ba, bb]) => level3_broad(a, b, ba, bb, Winding::Propagate, proximity)?,
        None => level3_with_contacts(a, b, Winding::Propagate, proximity)?,
    };
    let contacts = near
        .zip(proximity)
        .map(|(near, p)| crate::contacts::contacts(a, b, &near, p));
    let retained = construct(a, b, &l3, op, audit)?;
    let audit = if audit {
        Some(make_audit(a, b, op, &l3, &retained)?)
    } else {
        None
    };
    Ok((retained, l3, audit, contacts))
}

/// A proximity for [`Contacts`] must be finite and not negative.
fn check_proximity(proximity: f64) -> Result<(), Boolean3Error> {
    if proximity.is_finite() && proximity >= 0.0 {
        Ok(())
    } else {
        Err(Boolean3Error::InvalidProximity(proximity))
    }
}

fn make_audit(
    a: &Flat<'_>,
    b: &Flat<'_>,
    op: BooleanOp,
    l3: &Level3Data,
    r: &Retained,
) -> Result<Audit, Boolean3Error> {
    let cast = level3_fast(a, b, Winding::CastEach)?;
    let mut misplaced = Vec::new();
    let inside = |p: &Point3, own: &[Point3; 2], other: &[Point3; 2]| {
        (0..2).all(|c| own[0][c] <= p[c] && p[c] <= own[1][c])
            && own[0][2].min(other[0][2]) <= p[2]
            && p[2] <= own[1][2].max(other[1][2])
    };
    for h in &l3.x12 {
        let (p, q) = a.edge_points(h.edge);
        let own = exact_box([p, q]);
        let other = exact_box(b.facet_points(h.facet).map(|(s, _)| s));
        if !inside(&h.point, &own, &other) {
            misplaced.push((CompositeKind::EdgeA(h.edge), h.point));
        }
    }
    for h in &l3.x21 {
        let (p, q) = b.edge_points(h.edge);
        let own = exact_box(a.facet_points(h.facet).map(|(s, _)| s));
        let other = exact_box([p, q]);
        if !inside(&h.point, &own, &other) {
            misplaced.push((CompositeKind::EdgeB(h.edge), h.point));
        }
    }
    let (ca, cb, ci) = op.coefficients();
    let (ca, cb, ci) = (i64::from(ca), i64::from(cb), i64::from(ci));
    let i03 = |v: u32| ca + ci * i64::from(l3.x03[v as usize]);
    let i30 = |v: u32| cb + ci * i64::from(l3.x30[v as usize]);
    let ra = &a.referenced;
    let rb = &b.referenced;
    let mut net = Vec::new();
    // eq. 4.21: E13(e_A, B) = I03(v_e) - I03(v_s) + sum_f I12(e_A, f).
    let mut e13: Vec<i64> = a
        .edges
        .iter()
        .map(|&(s, t)| {
            let is = if ra[s as usize] { i03(s) } else { 0 };
            let it = if ra[t as usize] { i03(t) } else { 0 };
            it - is
        })
        .collect();
    for h in &l3.x12 {
        e13[h.edge as usize] += ci * i64::from(h.value);
    }
    net.extend(
        e13.iter()
            .enumerate()
            .map(|(e, &v)| (CompositeKind::EdgeA(e as u32), v)),
    );
    // eq. 4.22: E22(f_A, f_B) = -sum_{h in f_A} I12(h, f_B) + sum_{h in
    // f_B} I21(f_A, h), half-edge values signed by direction.
    let mut e22: HashMap<(u32, u32), i64> = HashMap::new();
    for h in &l3.x12 {
        for &he in a.edge_half_edges(h.edge) {
            let dir = if a.he_fwd(he) { 1 } else { -1 };
            *e22.entry((a.he_facet(he), h.facet)).or_default() -= ci * i64::from(h.value) * dir;
        }
    }
    for h in &l3.x21 {
        for &he in b.edge_half_edges(h.edge) {
            let dir = if b.he_fwd(he) { 1 } else { -1 };
            *e22.entry((h.facet, b.he_facet(he))).or_default() += ci * i64::from(h.value) * dir;
        }
    }
    let mut e22: Vec<_> = e22.into_iter().collect();
    e22.sort_unstable();
    net.extend(
        e22.into_iter()
            .map(|((fa, fb), v)| (CompositeKind::FacetPair(fa, fb), v)),
    );
    // eq. 4.23: E31(A, e_B) = sum_f I21(f, e_B) + I30(v_e) - I30(v_s).
    let mut e31: Vec<i64> = b
        .edges
        .iter()
        .map(|&(s, t)| {
            let is = if rb[s as usize] { i30(s) } else { 0 };
            let it = if rb[t as usize] { i30(t) } else { 0 };
            it - is
        })
        .collect();
    for h in &l3.x21 {
        e31[h.edge as usize] += ci * i64::from(h.value);
    }
    net.extend(
        e31.iter()
            .enumerate()
            .map(|(e, &v)| (CompositeKind::EdgeB(e as u32), v)),
    );
    // Theorem 3, counted afresh from the retained half-edges.
    let mut facets = Vec::with_capacity(r.facet_count());
    let mut bal: HashMap<u32, i64> = HashMap::new();
    for (src, hes) in r.facets() {
        bal.clear();
        for &(s, e) in hes {
            *bal.entry(e).or_default() += 1;
            *bal.entry(s).or_default() -= 1;
        }
        facets.push(FacetAudit {
            source: src,
            half_edges: hes.len() as u32,
            closed: bal.values().all(|&v| v == 0),
        });
    }
    let shape = to_polygon_mesh(r, r.vertices.clone());
    Ok(Audit {
        level3: l3.clone().with_edges(a, b),
        x03_per_vertex: cast.x03,
        x30_per_vertex: cast.x30,
        composites: r.composites.clone(),
        net_counts: net,
        facets,
        misplaced_points: misplaced,
        shape_closure: shape.check_topology(),
    })
}

/// The retained facets of `r` as a polygon mesh on `vertices` (the
/// result's vertices, moved out of `r` when it is no longer needed).
fn to_polygon_mesh(r: &Retained, vertices: Vec<Point3>) -> PolygonMesh {
    // Chunks in parallel, collected in order.
    let facets = r
        .chunks
        .par_iter()
        .with_min_len(par::min_len(1024))
        .flat_map_iter(|(_, hes, list)| {
            let mut k = 0usize;
            list.iter().map(move |&(_, n)| {
                let part = &hes[k..k + n as usize];
                k += n as usize;
                Facet {
                    half_edges: part
                        .iter()
                        .map(|&(start, end)| HalfEdge { start, end })
                        .collect(),
                }
            })
        })
        .collect();
    PolygonMesh::new(vertices, facets)
}

/// The Boolean `op` of two polygon meshes (the polygon-mesh variant of
/// chapter 4): levels 3-6 with inclusion values (eq. 4.7-4.13), composite
/// edges (eq. 4.14-4.16) and retained facets (section 4.6).
///
/// Both operands are validated first (coordinates finite and at most
/// `f64::MAX / 4`; dangling indices, facet and shape boundary closure of
/// section 4.2); a bad operand gives [`Boolean3Error::InvalidInput`] naming
/// the violated constraint. Any topologically valid input is accepted,
/// including non-manifold, multi-shell, self-intersecting and inside-out
/// shapes, and the result is always topologically valid (Theorems 1-4).
/// The output is the same bit for bit whatever the number of threads.
pub fn boolean_mesh(
    a: &PolygonMesh,
    b: &PolygonMesh,
    op: BooleanOp,
) -> Result<MeshOutput, Boolean3Error> {
    boolean_mesh_impl(a, b, op, false, None).map(|(o, _, _)| o)
}

/// [`boolean_mesh`] together with the operands' [`Contacts`] at
/// `proximity` (finite, not negative): the boxes outside which the result
/// is made of pieces of one operand that the other neither cuts nor comes
/// within `proximity` of. Data smoothing after the Boolean looks only
/// inside them (`smooth::smooth_mesh_near`). The result is the same as
/// [`boolean_mesh`]'s, bit for bit.
pub fn boolean_mesh_with_contacts(
    a: &PolygonMesh,
    b: &PolygonMesh,
    op: BooleanOp,
    proximity: f64,
) -> Result<(MeshOutput, Contacts), Boolean3Error> {
    check_proximity(proximity)?;
    let (o, _, c) = boolean_mesh_impl(a, b, op, false, Some(proximity))?;
    Ok((o, c.unwrap_or_default()))
}

/// [`boolean_mesh`] together with the [`Audit`] of its level data.
pub fn boolean_mesh_audit(
    a: &PolygonMesh,
    b: &PolygonMesh,
    op: BooleanOp,
) -> Result<(MeshOutput, Audit), Boolean3Error> {
    let (o, audit, _) = boolean_mesh_impl(a, b, op, true, None)?;
    let audit = audit.ok_or_else(|| Boolean3Error::Internal("audit not produced".into()))?;
    Ok((o, audit))
}

/// The 3D Boolean builds union, intersection and difference; a half-edge
/// has no multiplicity, so the doubled intersection curves of `Xor`
/// (`c_I = -2`) cannot be represented and it is refused before any work.
pub(crate) fn supported(op: BooleanOp) -> Result<(), Boolean3Error> {
    if op == BooleanOp::Xor {
        return Err(Boolean3Error::UnsupportedOperation(op));
    }
    Ok(())
}

fn boolean_mesh_impl(
    a: &PolygonMesh,
    b: &PolygonMesh,
    op: BooleanOp,
    audit: bool,
    proximity: Option<f64>,
) -> Result<(MeshOutput, Option<Audit>, Option<Contacts>), Boolean3Error> {
    supported(op)?;
    let larger = a.half_edge_count().max(b.half_edge_count());
    par::on_pool(larger, || {
        let smaller = a.facets.len().min(b.facets.len());
        let (fa, fb) = flat_pair(a, b, smaller, flat_polygon)?;
        let (mut r, l3, audit, contacts) = run(&fa, &fb, None, op, audit, proximity)?;
        let intersections = l3.x12.len() + l3.x21.len();
        // The operands' flat arrays and the level data are no longer
        // needed: free them before the output is assembled, to lower the
        // peak memory.
        drop((fa, fb, l3));
        let sources = r.facets().map(|(src, _)| src).collect();
        let vertices = std::mem::take(&mut r.vertices);
        let out = MeshOutput {
            mesh: to_polygon_mesh(&r, vertices),
            sources,
            intersections,
        };
        Ok((out, audit, contacts))
    })
}

/// The Boolean `op` of two triangle meshes (the triangle-mesh variant):
/// edge-adjacent triangles that are exactly coplanar and face the same way
/// are merged into polygon facets, vertices that only subdivide a straight
/// edge between two such facets are dropped, the Boolean runs as
/// [`boolean_mesh`] on those facets, and every retained facet is
/// triangulated by adding internal edges only (section 4.8), re-using the
/// input triangles outside the region the Boolean changed. Merging and
/// dropping remove only opposite half-edge pairs, so the result is
/// topologically valid whatever the coordinates, and a chain of operations
/// keeps the triangle count of the shape's real complexity.
pub fn boolean_triangles(
    a: &TriangleMesh,
    b: &TriangleMesh,
    op: BooleanOp,
) -> Result<TriangleOutput, Boolean3Error> {
    boolean_triangles_impl(a, b, op, false, None).map(|(o, _, _)| o)
}

/// [`boolean_triangles`] together with the operands' [`Contacts`] at
/// `proximity` (finite, not negative), as [`boolean_mesh_with_contacts`];
/// data smoothing after the Boolean looks only inside them
/// (`smooth::smooth_triangles_near`). The result is the same as
/// [`boolean_triangles`]'s, bit for bit.
pub fn boolean_triangles_with_contacts(
    a: &TriangleMesh,
    b: &TriangleMesh,
    op: BooleanOp,
    proximity: f64,
) -> Result<(TriangleOutput, Contacts), Boolean3Error> {
    check_proximity(proximity)?;
    let (o, _, c) = boolean_triangles_impl(a, b, op, false, Some(proximity))?;
    Ok((o, c.unwrap_or_default()))
}

/// [`boolean_triangles`] together with the [`Audit`] of its level data
/// (Theorem 4 in the audit is checked on the polygon form; check the
/// triangles with `TriangleMesh::check_topology`).
pub fn boolean_triangles_audit(
    a: &TriangleMesh,
    b: &TriangleMesh,
    op: BooleanOp,
) -> Result<(TriangleOutput, Audit), Boolean3Error> {
    let (o, audit, _) = boolean_triangles_impl(a, b, op, true, None)?;
    let audit = audit.ok_or_else(|| Boolean3Error::Internal("audit not produced".into()))?;
    Ok((o, audit))
}

fn boolean_triangles_impl(
    a: &TriangleMesh,
    b: &TriangleMesh,
    op: BooleanOp,
    audit: bool,
    proximity: Option<f64>,
) -> Result<(TriangleOutput, Option<Audit>, Option<Contacts>), Boolean3Error> {
    supported(op)?;
    let larger = 3 * a.triangles.len().max(b.triangles.len());
    par::on_pool(larger, || {
        let smaller = a.triangles.len().min(b.triangles.len());
        let (ta, tb) = flat_pair(a, b, smaller, flat_triangles)?;
        // The coplanar merge (module `merge`): the Boolean runs on the merged
        // facets; an operand without any merge keeps its triangle form.
        let internal = |e: TopologyError| {
            Boolean3Error::Internal(format!("coplanar merge broke closure: {e}"))
        };
        let (ma, mb) = par::join(smaller, || Merged::new(ta), || Merged::new(tb));
        let ((ma, fa), (mb, fb)) = (ma.map_err(internal)?, mb.map_err(internal)?);
        triangle_result([(a, &ma, &fa), (b, &mb, &fb)], None, op, audit, proximity)
    })
}

/// One operand of the triangle variant after the coplanar merge: the
/// input mesh, the merge and the merged facets' flat form.
pub(crate) type MergedOperand<'r, 'm> = (&'r TriangleMesh, &'r Merged, &'r Flat<'m>);

/// Levels 3-6 of the triangle variant on two merged operands (on their
/// broad phases when given) and the re-triangulation of the result.
pub(crate) fn triangle_result(
    [(a, ma, fa), (b, mb, fb)]: [MergedOperand<'_, '_>; 2],
    broad: Option<[&Broad; 2]>,
    op: BooleanOp,
    audit: bool,
    proximity: Option<f64>,
) -> Result<(TriangleOutput, Option<Audit>, Option<Contacts>), Boolean3Error> {
    let (r, l3, mut audit, mut contacts) = run(fa, fb, broad, op, audit, proximity)?;
    let intersections = l3.x12.len() + l3.x21.len();
    drop(l3);
    let sigma_b = if op == BooleanOp::Difference { -1 } else { 1 };
    let (mesh, changed) = to_triangle_mesh(
        r,
        [
            Source {
                triangles: &a.triangles,
                pos: &a.vertices,
                merged: ma,
                facets: fa,
                sigma: 1,
            },
            Source {
                triangles: &b.triangles,
                pos: &b.vertices,
                merged: mb,
                facets: fb,
                sigma: sigma_b,
            },
        ],
        contacts.is_some(),
    );
    if let Some(c) = contacts.as_mut() {
        // The regions re-triangulated anew lie at the contacts when the
        // Boolean cut them; the others (a merge dropped a vertex that only
        // subdivided a straight edge) are places the result differs from
        // the operands too.
        c.add_changed(changed);
    }
    if let Some(au) = audit.as_mut() {
        // Theorem 4 on the polygon result the Boolean built, then shape
        // boundary closure of its triangulation.
        if au.shape_closure.is_ok() {
            au.shape_closure = mesh.check_topology();
        }
    }
    let out = TriangleOutput {
        mesh,
        intersections,
    };
    Ok((out, audit, contacts))
}

/// The level-3 data of two polygon meshes by the fast path (broad phase,
/// propagated winding numbers). Operands are validated as in
/// [`boolean_mesh`].
pub fn level3(a: &PolygonMesh, b: &PolygonMesh) -> Result<Level3Data, Boolean3Error> {
    let smaller = a.facets.len().min(b.facets.len());
    let (fa, fb) = flat_pair(a, b, smaller, flat_polygon)?;
    Ok(level3_fast(&fa, &fb, Winding::Propagate)?.with_edges(&fa, &fb))
}

/// The level-3 data by brute force straight from Table 4.1 (every pair, no
/// broad phase, no propagation): the oracle the fast path is tested
/// against. Quadratic in the input size.
pub fn level3_reference(a: &PolygonMesh, b: &PolygonMesh) -> Result<Level3Data, Boolean3Error> {
    let (fa, fb) = flat_pair(a, b, 0, flat_polygon)?;
    level3_brute(&fa, &fb)
}
