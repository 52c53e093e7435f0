//! 2D smoothing (Appendix A on polygon sets, followed by the
//! simplification sweep of chapter 7 where the adjustments left crossings
//! or winding numbers outside `{0, 1}`).
//!
//! One pass applies, in this order: unreferenced vertex removal, vertex
//! merging, edge cracking between edges (one round, the only phase that
//! creates positions), edge cracking by vertex (to its end, on a fixed
//! vertex set), and after each of them zero-length edge removal and
//! cancellation of opposing edges; after merging and after cracking,
//! vertices exactly on the straight line between their two neighbours
//! are dropped. Then the set is checked exactly; if it
//! is not simple it is simplified by the sweep and the next pass smooths
//! the sweep's output. At most [`MAX_PLANAR_PASSES`] passes run; the algorithm
//! note `docs/algorithms/smooth_2d.md` gives the order and the measures
//! that make every phase end.

mod broad;
mod budget;
mod check;
mod crack;
/// Plane geometry, dimension-generic where it can be shared with 3D.
pub(crate) mod geom;
mod merge;
mod near;
mod resolve;
mod straighten;
mod work;

pub use check::{sanity_check_polygon_set, PlanarDefect};
pub use near::smooth_polygon_set_near;

use crate::{SmoothCounts, SmoothError, SmoothOptions, SmoothReport, Smoothed};
use budget::Budget;
use resolve::Resolution;
use robust_arith::{intersection_error_bound, UNIT_ROUNDOFF};
use topology::PolygonSet2;
use work::Work;

/// The most passes one run makes. The first pass resolves what the input
/// had; a sweep after it rebuilds the set from its cells, and the second
/// pass smooths the vertices the sweep created; the third exists for the
/// rare set whose second pass left crossings again. After the last sweep
/// the result is the sweep's output, cleaned by the exact operations only.
pub const MAX_PLANAR_PASSES: u32 = 3;

/// Smooths a polygon set with tolerance `delta = options.tolerance`
/// (Appendix A, then simplification where needed).
///
/// The input is validated first (tolerance, coordinates, closure and
/// indices); on error it is returned untouched. The result is
/// topologically valid (section 4.2) and, whenever the run ends before
/// the pass limit (`report.passes < MAX_PLANAR_PASSES`, as it does on the
/// outputs of Booleans in every test), clean: no two vertices within
/// `delta`, no edge shorter than `delta`, no vertex within `delta` of an
/// edge's interior where Appendix A's rule would crack it, no crossings,
/// and winding numbers in `{0, 1}` ([`sanity_check_polygon_set`] tests
/// all of it). Its area differs from
/// the input's by at most about perimeter times the distortion bound.
/// Smoothing the result again returns it unchanged (vertices sorted by
/// position, edges by vertex ids).
///
/// ```
/// use smooth::{smooth_polygon_set, SmoothOptions};
/// use topology::PolygonSet2;
///
/// // Two unit squares sharing the edge x = 1, drawn separately.
/// let mut s = PolygonSet2::new();
/// s.add_loop(&[[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]);
/// s.add_loop(&[[1.0, 1e-9], [2.0, 0.0], [2.0, 1.0], [1.0, 1.0]]);
/// let out = smooth_polygon_set(&s, &SmoothOptions::new(1e-6)).unwrap();
/// assert_eq!(out.shape.edge_count(), 4); // one rectangle
/// assert_eq!(out.shape.signed_area(), 2.0);
/// ```
pub fn smooth_polygon_set(
    set: &PolygonSet2,
    options: &SmoothOptions,
) -> Result<Smoothed<PolygonSet2>, SmoothError> {
    options.validate()?;
    set.validate_coordinates()?;
    set.check_topology()?;
    let coordinates = set.vertices().iter().flatten().copied();
    let Some((down, up)) = crate::mesh::range_scale_of(coordinates, options.tolerance) else {
        return smooth_in_range(set, options);
    };
    // Beyond 2^200 squared distances overflow: smooth at an exact
    // power-of-two scale, as 3D smoothing does (see the algorithm note),
    // adding the rounding of coordinates that became subnormal.
    let mut loss = 0.0f64;
    let (vertices, edges) = set.clone().into_parts();
    let scaled: Vec<[f64; 2]> = vertices
        .iter()
        .map(|p| {
            let q = p.map(|x| x * down);
            loss = loss.max((q[0] * up - p[0]).abs() + (q[1] * up - p[1]).abs());
            q
        })
        .collect();
    let scaled_options = SmoothOptions {
        tolerance: crate::mesh::scaled_tolerance(options.tolerance, down),
        ..*options
    };
    let out = smooth_in_range(&PolygonSet2::from_parts(scaled, edges), &scaled_options)?;
    let (vertices, edges) = out.shape.into_parts();
    let vertices = vertices.iter().map(|p| p.map(|x| x * up)).collect();
    let mut report = out.report;
    report.tolerance = options.tolerance;
    report.distortion_bound = report.distortion_bound * up + loss;
    report.max_displacement = report.max_displacement * up + loss;
    report.epsilon = report.epsilon * up + loss;
    Ok(Smoothed {
        shape: PolygonSet2::from_parts(vertices, edges),
        report,
    })
}

/// [`smooth_polygon_set`] on a validated set whose coordinates and
/// tolerance are at most `2^200` in magnitude.
fn smooth_in_range(
    set: &PolygonSet2,
    options: &SmoothOptions,
) -> Result<Smoothed<PolygonSet2>, SmoothError> {
    let tol = options.tolerance;
    let mut budget = Budget::new(options.budget_for(set.vertex_count(), set.edge_count()));
    let mut counts = SmoothCounts::default();
    let mut w = Work::from_set(set);
    w.normalize(&mut counts);
    debug_check(&w, "the copy")?;
    let mut sweep_epsilon = 0.0;
    let mut passes = 0;
    let mut crossing_error = 0.0;
    loop {
        passes += 1;
        crossing_error += local_phases(&mut w, tol, &mut counts, &mut budget, true)?;
        match resolve::resolve(&mut w, &mut counts)? {
            Resolution::Clean => break,
            Resolution::Swept(eps) => {
                sweep_epsilon += eps;
                w.normalize(&mut counts);
                w.remove_unreferenced(&mut counts);
                debug_check(&w, "simplification")?;
            }
        }
        if passes == MAX_PLANAR_PASSES {
            break;
        }
    }
    let k = w.k_max();
    let input = set.vertices();
    let (shape, tracked) = w.into_canonical(&mut counts);
    let max_displacement = tracked
        .iter()
        .enumerate()
        .filter_map(|(i, t)| t.map(|v| (input[i], shape.vertex(v))))
        .map(|(p, q)| geom::dist2(&p, &q).sqrt())
        .fold(0.0f64, f64::max);
    Ok(Smoothed {
        shape,
        report: report(
            tol,
            counts,
            passes,
            &budget,
            k,
            sweep_epsilon + crossing_error,
            max_displacement,
        ),
    })
}

/// The report of a 2D run at tolerance `tol`: `k` the largest adjustment
/// count of a vertex, `rounding` what the sweeps and cracking between
/// edges added; the distortion bound is `k tol (1 + 8u)` plus that
/// (section 8.4).
fn report(
    tol: f64,
    counts: SmoothCounts,
    passes: u32,
    budget: &Budget,
    k: u32,
    rounding: f64,
    max_displacement: f64,
) -> SmoothReport {
    let distortion_bound = f64::from(k) * tol * (1.0 + 8.0 * UNIT_ROUNDOFF) + rounding;
    SmoothReport {
        tolerance: tol,
        counts,
        passes,
        budget_hit: budget.hit(),
        max_adjustments: k,
        distortion_bound,
        max_displacement,
        epsilon: distortion_bound,
        reverted: None,
    }
}

/// One pass of the phases that work on neighbourhoods (everything but
/// the check and simplification), in the order of the module header, the
/// unreferenced vertices removed at the end. Returns the rounding that
/// cracking between edges added to the distortion (0 when it computed no
/// position). `closed` says whether `w` satisfies the closure constraints
/// (a whole set) or is a region cut out of one, whose phases are then not
/// checked for closure in debug builds.
fn local_phases(
    w: &mut Work,
    tol: f64,
    counts: &mut SmoothCounts,
    budget: &mut Budget,
    closed: bool,
) -> Result<f64, SmoothError> {
    let check = |w: &Work, phase: &str| {
        if closed {
            debug_check(w, phase)
        } else {
            Ok(())
        }
    };
    merge::merge_phase(w, tol, counts, budget);
    check(w, "vertex merging")?;
    // One index of the vertex positions serves every phase until
    // cracking between edges or the removal of unreferenced vertices
    // changes them.
    let mut index = None;
    straighten::straighten(w, tol, counts, &mut index);
    check(w, "straight-through vertex removal")?;
    let alpha = intersection_error_bound(max_abs(w));
    let mut crossing_error = 0.0;
    if crack::crack_between_edges(w, tol, counts, budget)? {
        crossing_error = alpha;
        index = None;
    }
    check(w, "edge cracking between edges")?;
    crack::crack_by_vertices(w, tol, counts, budget, &mut index);
    check(w, "edge cracking by vertex")?;
    straighten::straighten(w, tol, counts, &mut index);
    check(w, "straight-through vertex removal")?;
    w.remove_unreferenced(counts);
    Ok(crossing_error)
}

fn max_abs(w: &Work) -> f64 {
    w.pts
        .iter()
        .flat_map(|p| p.iter())
        .fold(0.0f64, |m, &c| m.max(c.abs()))
}

/// In debug builds, the closure constraints after a phase (section 4.2).
fn debug_check(w: &Work, phase: &str) -> Result<(), SmoothError> {
    if cfg!(debug_assertions) {
        w.to_set()
            .check_topology()
            .map_err(|e| SmoothError::Internal(format!("after {phase}: {e}")))?;
    }
    Ok(())
}
