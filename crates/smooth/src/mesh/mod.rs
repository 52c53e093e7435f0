//! 3D data smoothing of polygon meshes (dissertation chapter 5 and
//! Appendix A), in a fixed order of phases that terminates by design
//! (the argument is in `docs/algorithms/smooth.md`):
//!
//! 1. vertex adjustment (merging within `delta`), then zero-length edge
//!    removal and half-edge cancellation; no vertex moves after this;
//! 2. edge cracking between edges, then by vertex in rounds to a fixpoint,
//!    repeated until neither splits anything: every split replaces an
//!    edge by strictly shorter edges, so the multiset of edge lengths
//!    decreases;
//! 3. zero-length edge removal and half-edge cancellation (each removes
//!    half-edges);
//! 4. facet cancellation passes, each swap followed by half-edge
//!    cancellation, repeated while a pass lowers the half-edge count;
//! 5. empty facet and unreferenced vertex removal, and the report.
//!
//! An input vertex moves at most `delta`; a created vertex lies within
//! `2.5 delta` of the input edges it descends from, plus the rounding of
//! its computation (at most 64 units of roundoff of the largest coordinate
//! of its edges): the distortion bound.

mod cancel;
mod crack;
mod geom;
mod guard;
pub(crate) mod index;
mod plane;
pub(crate) mod region;
mod sanity;
mod structure;
mod triangles;

pub use region::{smooth_mesh_near, smooth_triangles_near, MAX_GROWTHS, REACH};
pub use sanity::{sanity_check_mesh, sanity_check_triangles};
pub use triangles::smooth_triangles;

use crate::mesh::geom::{dist2, point_segment};
use crate::mesh::structure::{Origin, Work};
use crate::{SmoothCounts, SmoothError, SmoothOptions, SmoothReport, Smoothed};
use robust_arith::UNIT_ROUNDOFF;
use rustc_hash::FxHashSet;
use topology::{Point3, PolygonMesh};

/// Smooths a polygon mesh (Appendix A): merges vertices within
/// `options.tolerance`, cracks edges at nearby vertices and where two
/// edges pass within the tolerance, cancels opposing half-edges inside a
/// facet and opposing facets (in full, or in part by swapping half-edges
/// as in figure A.1), and removes zero-length edges, empty facets and
/// unreferenced vertices. The result satisfies the closure constraints of
/// section 4.2 and the postconditions of [`sanity_check_mesh`]; every
/// vertex lies within [`SmoothReport::distortion_bound`] of where it was
/// (a created vertex: of the edges it was created on).
///
/// The input is validated first (closure, indices, coordinates: an
/// [`SmoothError::InvalidInput`]) and never modified.
///
/// ```
/// use topology::{Facet, PolygonMesh};
/// // A tetrahedron with a fifth vertex 1e-9 from a corner, used by a
/// // sliver pair of facets: smoothing merges it and cancels the sliver.
/// let v = vec![[0.0; 3], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0], [1e-9, 0.0, 0.0]];
/// let mut facets: Vec<Facet> =
///     [[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2]].iter().map(|l| Facet::from_loop(l)).collect();
/// facets.push(Facet::from_loop(&[0, 4, 1]));
/// facets.push(Facet::from_loop(&[1, 4, 0]));
/// let mesh = PolygonMesh::new(v, facets);
/// let out = smooth::smooth_mesh(&mesh, &smooth::SmoothOptions::new(1e-6)).unwrap();
/// assert_eq!(out.shape.vertices.len(), 4);
/// assert_eq!(out.shape.facets.len(), 4);
/// assert!(smooth::sanity_check_mesh(&out.shape, 1e-6).is_ok());
/// ```
pub fn smooth_mesh(
    mesh: &PolygonMesh,
    options: &SmoothOptions,
) -> Result<Smoothed<PolygonMesh>, SmoothError> {
    options.validate()?;
    mesh.check_topology()?;
    mesh.validate_coordinates()?;
    let (mut shape, mut report) = run(mesh, options)?;
    if options.guard && report.counts != SmoothCounts::default() {
        let all = |n: usize| vec![true; n];
        let verdict = guard::guard(
            &report,
            (mesh, &all(mesh.facets.len())),
            (&shape, &all(shape.facets.len())),
        );
        (shape, report) = verdict.apply(mesh, shape, report);
    }
    // The postconditions of a smoothing result; the guard's undone
    // places (and an input handed back) keep the input's features.
    #[cfg(debug_assertions)]
    if report.reverted.is_none() {
        sanity_check_mesh(&shape, options.tolerance)?;
    }
    Ok(Smoothed { shape, report })
}

/// The closure check after a pass, in debug builds only, and only on a
/// closed mesh (a region smoothed on its own is open along its boundary,
/// which `region.rs` checks once at the end).
fn debug_check(w: &Work, stage: &str, closed: bool) -> Result<(), SmoothError> {
    if cfg!(debug_assertions) && closed {
        w.check_closure(stage)
    } else {
        Ok(())
    }
}

/// The largest magnitude (of the coordinates and the tolerance) that
/// smoothing works at directly: squared distances, the squared tolerance
/// and the plane fits' products of differences stay finite below it.
const RANGE_TOP_EXP: i32 = 200;

/// The smallest scaled tolerance used after scaling: its square is a
/// normal f64, so `d2 <= delta2` still means `d <= delta` to rounding.
const SCALED_TOLERANCE_FLOOR_EXP: i32 = -500;

/// The power-of-two scale factors `(2^-k, 2^k)` that bring the larger of
/// the coordinates' magnitude and `delta` to about `2^200`, or `None` when
/// both are at most `2^200` (no scaling needed). The values must be finite.
pub(crate) fn range_scale(vertices: &[[f64; 3]], delta: f64) -> Option<(f64, f64)> {
    range_scale_of(vertices.iter().flatten().copied(), delta)
}

/// [`range_scale`] over any coordinates (2D smoothing uses it too).
pub(crate) fn range_scale_of(
    coordinates: impl Iterator<Item = f64>,
    delta: f64,
) -> Option<(f64, f64)> {
    let top = coordinates.fold(delta, |m, x| m.max(x.abs()));
    if !top.is_finite() || top <= 2f64.powi(RANGE_TOP_EXP) {
        return None;
    }
    // `top` is a finite normal number above 2^200: its binary exponent.
    let e = ((top.to_bits() >> 52) & 0x7ff) as i32 - 1023;
    let k = e - RANGE_TOP_EXP;
    Some((2f64.powi(-k), 2f64.powi(k)))
}

/// The rounding allowance of a created vertex, in units of `u M` with
/// `u` the unit roundoff and `M` the largest coordinate magnitude of the
/// vertex and the two edges it was made on. Their closest points
/// (`segment_segment`: a difference, a product and a sum per coordinate)
/// lie within `5 sqrt(3) u M` of the edges, their midpoint adds
/// `2 sqrt(3) u M`, and the report's distance to an edge
/// (`point_segment`) errs by at most about `37 u M` (the projection
/// parameter, `28 u M` along the edge, and the closest point,
/// `5 sqrt(3) u M`): together under `50 u M`. No `f64` point need lie
/// closer than that to a long edge, so a tolerance finer than the
/// coordinates' resolution cannot bound a created vertex by itself (a
/// property-test find: edges `1e300` long at tolerance 0, smoothed at the
/// scaled tolerance `2^-500`).
const CREATED_ROUNDING_ULPS: f64 = 64.0;

/// [`CREATED_ROUNDING_ULPS`] `u M` for a vertex at `p` created on the
/// edges with end points `e`.
fn created_rounding(p: Point3, e: &[Point3; 4]) -> f64 {
    let m = e
        .iter()
        .chain(std::iter::once(&p))
        .flatten()
        .fold(0.0f64, |m, x| m.max(x.abs()));
    CREATED_ROUNDING_ULPS * UNIT_ROUNDOFF * m
}

/// The tolerance used at the scale `down` (at least `2^-500`, whose
/// square is a normal number).
pub(crate) fn scaled_tolerance(delta: f64, down: f64) -> f64 {
    (delta * down).max(2f64.powi(SCALED_TOLERANCE_FLOOR_EXP))
}

/// The phases on a validated mesh, at any valid scale. Where the
/// coordinates or the tolerance exceed `2^200` (squared distances would
/// overflow to infinity and every pair would look within the tolerance),
/// the mesh and the tolerance are first scaled by a power of two `2^-k`
/// that brings the larger of them to about `2^200`; the result is scaled
/// back by `2^k`. Both scalings are exact except for coordinates that
/// become subnormal, whose rounding (at most `2^(k-1074)` per coordinate)
/// is measured and added to the reported bound and displacement; the
/// scaled tolerance is at least `2^-500` (its square stays normal), so the
/// tolerance used is at least `2^(k-500)`, far below the coordinates'
/// own resolution at that scale, and the bound reports the one used.
pub(crate) fn run(
    mesh: &PolygonMesh,
    options: &SmoothOptions,
) -> Result<(PolygonMesh, SmoothReport), SmoothError> {
    run_with(mesh, options, true)
}

/// [`run`] on a mesh that is `closed` (shape boundary closure holds) or
/// open (a region cut out of a closed mesh: the closure checks between
/// passes are skipped).
pub(crate) fn run_with(
    mesh: &PolygonMesh,
    options: &SmoothOptions,
    closed: bool,
) -> Result<(PolygonMesh, SmoothReport), SmoothError> {
    let delta = options.tolerance;
    let Some((down, up)) = range_scale(&mesh.vertices, delta) else {
        return run_in_range(mesh, options, closed);
    };
    let mut loss = 0.0f64;
    let vertices: Vec<_> = mesh
        .vertices
        .iter()
        .map(|p| {
            let q = p.map(|x| x * down);
            // The rounding of coordinates that became subnormal (an
            // upper bound on the Euclidean distance: the sum of the
            // per-coordinate errors, which cannot overflow).
            let err: f64 = (0..3).map(|i| (q[i] * up - p[i]).abs()).sum();
            loss = loss.max(err);
            q
        })
        .collect();
    let scaled = PolygonMesh::new(vertices, mesh.facets.clone());
    let scaled_options = SmoothOptions {
        tolerance: scaled_tolerance(delta, down),
        ..*options
    };
    let (mut shape, mut report) = run_in_range(&scaled, &scaled_options, closed)?;
    for p in &mut shape.vertices {
        *p = p.map(|x| x * up);
    }
    report.tolerance = delta;
    report.distortion_bound = report.distortion_bound * up + loss;
    report.max_displacement = report.max_displacement * up + loss;
    report.epsilon = report.epsilon * up + loss;
    Ok((shape, report))
}

/// The phases on a validated mesh whose coordinates and tolerance are at
/// most `2^200` in magnitude.
fn run_in_range(
    mesh: &PolygonMesh,
    options: &SmoothOptions,
    closed: bool,
) -> Result<(PolygonMesh, SmoothReport), SmoothError> {
    phases(mesh, options, closed, true)
}

/// [`run_in_range`], with the later passes of cracking and facet
/// cancellation looking only at what changed since the previous pass
/// (`incremental`, what smoothing runs) or at everything (what the tests
/// compare it with: the results are the same).
fn phases(
    mesh: &PolygonMesh,
    options: &SmoothOptions,
    closed: bool,
    incremental: bool,
) -> Result<(PolygonMesh, SmoothReport), SmoothError> {
    let delta = options.tolerance;
    let budget = options.budget_for(mesh.vertices.len(), mesh.half_edge_count());
    let over_budget = |c: &SmoothCounts| c.adjustments() >= budget;
    let mut counts = SmoothCounts::default();
    let mut passes = 0u32;
    let mut budget_hit = false;
    let mut w = Work::from_mesh(mesh);

    // Phase 1: vertex adjustment, then the cheap removals.
    crack::merge_phase(&mut w, delta, &mut counts);
    cancel::cancel_all(&mut w, &mut counts);
    passes += 1;
    debug_check(&w, "vertex merging", closed)?;

    // Phase 2: edge cracking between edges, then by vertex to a
    // fixpoint, repeated until neither cracks anything.
    // After the first of each, a cracking pass looks only at what changed
    // since the previous one (exact: `crack_between_edges` and
    // `crack_by_vertex` say why): the edges made since, and for cracking
    // by vertex the vertices created since its last fixpoint.
    let mut roots = crack::Roots::default();
    let mut since_between: Option<FxHashSet<(u32, u32)>> = None;
    let mut since_fixpoint: Option<(FxHashSet<(u32, u32)>, u32)> = None;
    loop {
        let (cracked, made) = crack::crack_between_edges(
            &mut w,
            delta,
            &mut counts,
            &mut roots,
            since_between.as_ref(),
        );
        passes += 1;
        debug_check(&w, "edge cracking between edges", closed)?;
        if let Some((changed, _)) = since_fixpoint.as_mut() {
            changed.extend(made.iter().copied());
        }
        let crack::ByVertex {
            rounds,
            budget_hit: hit,
            made: made_by_vertex,
        } = crack::crack_by_vertex(
            &mut w,
            delta,
            &mut counts,
            over_budget,
            &mut roots,
            since_fixpoint.as_ref().map(|(c, first)| (c, *first)),
            |w| debug_check(w, "edge cracking by vertex", closed),
        )?;
        if incremental {
            since_between = Some(made.into_iter().chain(made_by_vertex).collect());
            since_fixpoint = Some((FxHashSet::default(), w.pos.len() as u32));
        }
        passes += rounds;
        budget_hit |= hit;
        if cracked == 0 && rounds == 0 {
            break; // neither kind of cracking applies any more
        }
        if budget_hit || over_budget(&counts) {
            budget_hit = true;
            break;
        }
    }

    // Phase 3: removals and half-edge cancellation.
    cancel::cancel_all(&mut w, &mut counts);
    passes += 1;
    debug_check(&w, "half-edge cancellation", closed)?;

    // Phase 4: facet cancellation while it lowers the half-edge count.
    // After the first pass, a pass looks only at pairs with a facet the
    // previous pass changed (exact: `facet_cancellation_pass`).
    let mut changed_last: Option<Vec<bool>> = None;
    while !budget_hit {
        let before = w.half_edge_count();
        let (changed, hit, mut touched) = cancel::facet_cancellation_pass(
            &mut w,
            delta,
            &mut counts,
            over_budget,
            changed_last.as_deref(),
        );
        budget_hit |= hit;
        cancel::cancel_all_marking(&mut w, &mut counts, &mut touched);
        changed_last = incremental.then_some(touched);
        passes += 1;
        debug_check(&w, "facet cancellation", closed)?;
        if changed == 0 || w.half_edge_count() >= before {
            break;
        }
    }

    // Phase 5: compaction and the report.
    let (shape, map, unreferenced, empty) = w.compact();
    counts.unreferenced_vertices_removed += unreferenced;
    counts.empty_facets_removed += empty;
    let report = report(&w, &map, counts, passes, budget_hit, delta);
    Ok((shape, report))
}

/// The report: k, the distortion bound and the measured displacement.
fn report(
    w: &Work,
    map: &[Option<u32>],
    counts: SmoothCounts,
    passes: u32,
    budget_hit: bool,
    delta: f64,
) -> SmoothReport {
    let mut k = 0u32;
    let mut bound = 0.0f64;
    let mut moved = 0.0f64;
    for (v, slot) in map.iter().enumerate() {
        // k and the bound count every adjusted vertex, also one whose
        // facets were all cancelled afterwards (a collapsed sliver moves
        // the shape's surface by up to `delta` though no vertex of it is
        // left).
        k = k.max(w.adjustments[v]);
        match w.origin[v] {
            Origin::Input(_) if w.adjustments[v] > 0 => bound = bound.max(delta),
            Origin::Input(_) => {}
            Origin::Created(e) => bound = bound.max(2.5 * delta + created_rounding(w.pos[v], &e)),
        }
        if slot.is_none() {
            continue;
        }
        match w.origin[v] {
            Origin::Input(_) => {}
            Origin::Created(e) => {
                let p = w.pos[v];
                let d = point_segment(p, e[0], e[1])
                    .1
                    .max(point_segment(p, e[2], e[3]).1);
                moved = moved.max(d.sqrt());
            }
        }
    }
    // Input vertices: the distance to the vertex they became.
    for (i, &r) in w.representative.iter().enumerate() {
        if map[r as usize].is_some() {
            if let Origin::Input(p0) = w.origin[i] {
                moved = moved.max(dist2(w.pos[r as usize], p0).sqrt());
            }
        }
    }
    SmoothReport {
        tolerance: delta,
        counts,
        passes,
        budget_hit,
        max_adjustments: k,
        distortion_bound: bound,
        max_displacement: moved,
        epsilon: bound,
        reverted: None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use boolean_3d::{boolean_mesh, BooleanOp};
    use proptest::prelude::*;
    use test_support::shapes::{box_mesh, push_box, uv_sphere};

    /// The incremental passes give what passes over everything give: the
    /// same shape, counts, bound and displacement (the pass count may
    /// differ only when the budget stops smoothing, which these cases
    /// never reach). Returns whether a later pass had anything to look
    /// at, so that the tests can insist some cases do.
    fn same_as_exhaustive(mesh: &PolygonMesh, delta: f64) -> Result<bool, TestCaseError> {
        let options = SmoothOptions::new(delta);
        let (a, ra) = phases(mesh, &options, true, true).unwrap();
        let (b, rb) = phases(mesh, &options, true, false).unwrap();
        prop_assert_eq!(&a, &b);
        prop_assert_eq!(ra.counts, rb.counts);
        prop_assert_eq!(ra.budget_hit, rb.budget_hit);
        prop_assert_eq!(ra.max_adjustments, rb.max_adjustments);
        prop_assert_eq!(ra.distortion_bound.to_bits(), rb.distortion_bound.to_bits());
        prop_assert_eq!(ra.max_displacement.to_bits(), rb.max_displacement.to_bits());
        if !ra.budget_hit {
            prop_assert_eq!(ra.passes, rb.passes);
        }
        // More than the first cracking pair and facet pass: the second
        // ones ran incrementally.
        Ok(ra.passes > 5)
    }

    fn rotated(m: &PolygonMesh, axis: usize, degrees: f64, shift: f64) -> PolygonMesh {
        let (s, c) = degrees.to_radians().sin_cos();
        let (i, j) = ((axis + 1) % 3, (axis + 2) % 3);
        let vertices = m
            .vertices
            .iter()
            .map(|p| {
                let mut q = *p;
                q[i] = c * p[i] - s * p[j] + shift;
                q[j] = s * p[i] + c * p[j] + shift;
                q
            })
            .collect();
        PolygonMesh::new(vertices, m.facets.clone())
    }

    /// A UV sphere minus or united with its copy turned by a few degrees
    /// and moved by a hair (the guard's tour cases): many near-coincident
    /// edges and facets, so cracking and facet cancellation run several
    /// passes.
    #[test]
    fn incremental_passes_match_on_rotated_sphere_copies() {
        let sphere = uv_sphere([0.0; 3], 1.0, 24, 12).to_polygon_mesh();
        let mut later = 0;
        for (k, &(axis, degrees, shift)) in [
            (2usize, 7.5, 0.0),
            (0, 90.0, 5e-8),
            (2, 3.0, 1e-9),
            (1, 15.0, 2e-8),
            (2, 37.0, 0.0),
        ]
        .iter()
        .enumerate()
        {
            let copy = rotated(&sphere, axis, degrees, shift);
            for op in [
                BooleanOp::Difference,
                BooleanOp::Union,
                BooleanOp::Intersection,
            ] {
                let m = boolean_mesh(&sphere, &copy, op).unwrap().mesh;
                for delta in [1e-9, 1e-7, 1e-4, 1e-2] {
                    let ran = same_as_exhaustive(&m, delta)
                        .unwrap_or_else(|e| panic!("case {k} {op:?} at {delta}: {e}"));
                    later += usize::from(ran);
                }
            }
        }
        assert!(later >= 10, "only {later} cases ran later passes");
    }

    fn grid_box() -> impl Strategy<Value = ([f64; 3], [f64; 3])> {
        (
            prop::array::uniform3(0i32..4),
            prop::array::uniform3(1i32..4),
            -12i32..=-5,
            prop::array::uniform3(-1i32..=1),
        )
            .prop_map(|(lo, size, e, dir)| {
                let j = 10f64.powi(e);
                let lo: [f64; 3] =
                    std::array::from_fn(|k| 0.25 * f64::from(lo[k]) + j * f64::from(dir[k]));
                let hi: [f64; 3] = std::array::from_fn(|k| lo[k] + 0.25 * f64::from(size[k]));
                (lo, hi)
            })
    }

    fn op() -> impl Strategy<Value = BooleanOp> {
        prop::sample::select(vec![
            BooleanOp::Union,
            BooleanOp::Difference,
            BooleanOp::Intersection,
        ])
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(test_support::cases(96)))]

        /// Boolean chains of jittered grid boxes, smoothed at tolerances
        /// around the jitter.
        #[test]
        fn incremental_passes_match_on_box_chains(
            first in grid_box(),
            rest in prop::collection::vec((op(), grid_box()), 1..4),
            delta in prop::sample::select(vec![1e-9, 1e-7, 1e-5, 3e-3]),
        ) {
            let mut m = box_mesh(first.0, first.1);
            for (o, b) in &rest {
                m = boolean_mesh(&m, &box_mesh(b.0, b.1), *o).unwrap().mesh;
            }
            same_as_exhaustive(&m, delta)?;
        }

        /// Closed topology from boxes with every position drawn within a
        /// few tolerances of a few centres: merging, cracking and
        /// cancellation everywhere.
        #[test]
        fn incremental_passes_match_on_clustered_meshes(
            boxes in prop::collection::vec(grid_box(), 1..4),
            centres in prop::collection::vec(prop::array::uniform3(-2i32..=2), 1..4),
            picks in prop::collection::vec((0usize..4, prop::array::uniform3(-1.0f64..1.0)), 32),
            spread in prop::sample::select(vec![0.3, 1.0, 3.0, 10.0]),
        ) {
            let delta = 1e-5;
            let (mut v, mut f) = (Vec::new(), Vec::new());
            for b in &boxes {
                push_box(&mut v, &mut f, b.0, b.1, false);
            }
            for (i, p) in v.iter_mut().enumerate() {
                let (c, off) = picks[i % picks.len()];
                let c = centres[c % centres.len()];
                *p = std::array::from_fn(|k| 0.5 * f64::from(c[k]) + spread * delta * off[k]);
            }
            same_as_exhaustive(&PolygonMesh::new(v, f), delta)?;
        }
    }
}
