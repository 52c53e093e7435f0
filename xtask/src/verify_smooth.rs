//! `cargo xtask verify --suite smooth`: the postconditions of data
//! smoothing (Appendix A) over seeded corpora, checked by code independent
//! of the smoothing crate (all-pairs distances, exact volumes and areas),
//! on the [`crate::verify::Suite`] machinery.
//!
//! 3D corpora (each a Boolean result smoothed at a tolerance `delta`):
//! `stacked` (two unit boxes face to face with a gap or overlap of
//! `10^-k`, k = 6..12, union in either order, delta 1e-5: figures
//! 5.1-5.2), `chains` (3-6 grid boxes jittered by `10^-k` combined by
//! random operations, delta 1e-6), `near-vertical` (four coincident,
//! almost vertical, slightly non-planar facets from two stacked pairs of
//! boxes whose shared face is tilted by `10^-k`: the section 5.2 field
//! case), `garbage` (shells with coordinates of magnitude `2^-60 .. 2^60`,
//! delta random).
//!
//! 3D checks: `closure` (the result satisfies the constraints of section
//! 4.2, the budget is never hit), `idempotent` (smoothing the result again
//! changes nothing), `bound` (every result vertex lies within the reported
//! distortion bound of an input vertex or edge, and the reported maximum
//! displacement is within the bound), `features` (no edge shorter than
//! delta, no two vertices within delta), `volume` (the volume, exact, moves by
//! at most the input's surface area x bound; an input with non-planar
//! facets, whose volume depends on the triangulation, is triangulated and
//! checked through the triangle variant), `triangles` (the triangle variant
//! stays triangles and closed). The bound of `volume` and `area` is the
//! documented one (`documented_bound`): the reported distortion bound,
//! and at least the tolerance once any adjustment ran.
//!
//! 2D corpora: `squares` (grid squares with jittered coincident edges
//! combined by the basic Boolean), `random` (random loops jittered near
//! their own vertices), `garbage`; checks: `closure`, `idempotent`,
//! `features`, `area` (the result is simple, and its area differs from the
//! input's area under the positive fill rule, computed by an independent
//! slab decomposition, by at most the input's perimeter x bound: the final
//! sweep legitimately fills inside-out and multiply covered input by that
//! rule), `near` (smoothing near one contact box over the whole set gives
//! whole smoothing's set bit for bit: `smooth_polygon_set_near` cuts out
//! every edge, or hands the set to whole smoothing).

use crate::verify::{Check, Corpus, Outcome, Suite};
use boolean_3d::{boolean_mesh, BooleanOp};
use smooth::{
    smooth_mesh, smooth_polygon_set, smooth_polygon_set_near, smooth_triangles, SmoothOptions,
    Smoothed,
};
use test_support::rng::SplitMix64;
use test_support::shapes::push_box;
use topology::{PolygonMesh, PolygonSet2};

/// A 3D smoothing case: a shape and a tolerance.
pub struct CaseM {
    /// The shape to smooth (a Boolean result or garbage).
    pub mesh: PolygonMesh,
    /// The tolerance.
    pub delta: f64,
}

fn boxes(list: &[([f64; 3], [f64; 3])]) -> PolygonMesh {
    let (mut v, mut f) = (Vec::new(), Vec::new());
    for &(lo, hi) in list {
        push_box(&mut v, &mut f, lo, hi, false);
    }
    PolygonMesh::new(v, f)
}

fn jitter(r: &mut SplitMix64) -> f64 {
    let k = r.range(6, 12) as i32;
    r.pm1() * 10f64.powi(-k)
}

fn stacked(r: &mut SplitMix64) -> CaseM {
    let g = jitter(r);
    let lower = boxes(&[([0.0; 3], [1.0; 3])]);
    let upper = boxes(&[([0.0, 0.0, 1.0 + g], [1.0, 1.0, 2.0 + g])]);
    let (a, b) = if r.range(0, 1) == 0 {
        (lower, upper)
    } else {
        (upper, lower)
    };
    let mesh = boolean_mesh(&a, &b, BooleanOp::Union)
        .map(|o| o.mesh)
        .unwrap_or(a);
    CaseM { mesh, delta: 1e-5 }
}

fn chain(r: &mut SplitMix64) -> CaseM {
    let grid_box = |r: &mut SplitMix64| {
        let mut lo = [0.0; 3];
        let mut hi = [0.0; 3];
        for k in 0..3 {
            let a = r.range(0, 3);
            lo[k] = a as f64 + jitter(r);
            hi[k] = r.range(a + 1, 4) as f64 + jitter(r);
        }
        boxes(&[(lo, hi)])
    };
    let mut acc = grid_box(r);
    for _ in 0..r.range(2, 5) {
        let b = grid_box(r);
        let op = [
            BooleanOp::Union,
            BooleanOp::Intersection,
            BooleanOp::Difference,
        ][r.range(0, 2) as usize];
        if let Ok(out) = boolean_mesh(&acc, &b, op) {
            acc = out.mesh;
        }
    }
    CaseM {
        mesh: acc,
        delta: 1e-6,
    }
}

/// Two pairs of boxes whose shared faces are tilted by `10^-k` from
/// vertical and bent by a smaller amount: four almost coincident, almost
/// vertical, slightly non-planar facets.
fn near_vertical(r: &mut SplitMix64) -> CaseM {
    let t = 10f64.powi(-(r.range(3, 9) as i32));
    let bend = t * 1e-3 * r.pm1();
    let tilt = |mut m: PolygonMesh, x0: f64| {
        for p in &mut m.vertices {
            if (p[0] - x0).abs() < 0.5 {
                p[0] += t * p[2] + bend * p[1] * p[2];
            }
        }
        m
    };
    let a = tilt(boxes(&[([-1.0, 0.0, 0.0], [0.0, 1.0, 1.0])]), 0.0);
    let b = tilt(boxes(&[([0.0, 0.0, 0.0], [1.0, 1.0, 1.0])]), 0.0);
    let c = tilt(boxes(&[([-1.0, 0.0, 0.5], [0.0, 1.0, 1.5])]), 0.0);
    let d = tilt(boxes(&[([0.0, 0.0, 0.5], [1.0, 1.0, 1.5])]), 0.0);
    let mut acc = a;
    for m in [b, c, d] {
        if let Ok(out) = boolean_mesh(&acc, &m, BooleanOp::Union) {
            acc = out.mesh;
        }
    }
    CaseM {
        mesh: acc,
        delta: 1e-5 * (1.0 + r.unit()),
    }
}

fn garbage(r: &mut SplitMix64) -> CaseM {
    let mesh = crate::verify3::garbage_mesh(r);
    // `magnitude` draws a random sign; a tolerance is a size.
    let delta = r.magnitude(-60, 0).abs();
    CaseM { mesh, delta }
}

fn dist(a: [f64; 3], b: [f64; 3]) -> f64 {
    ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2) + (a[2] - b[2]).powi(2)).sqrt()
}

fn dist_segment(p: [f64; 3], a: [f64; 3], b: [f64; 3]) -> f64 {
    let ab = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
    let ap = [p[0] - a[0], p[1] - a[1], p[2] - a[2]];
    let len2 = ab[0] * ab[0] + ab[1] * ab[1] + ab[2] * ab[2];
    let t = if len2 > 0.0 {
        ((ap[0] * ab[0] + ap[1] * ab[1] + ap[2] * ab[2]) / len2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    dist(p, [a[0] + t * ab[0], a[1] + t * ab[1], a[2] + t * ab[2]])
}

fn run3(case: &CaseM) -> Result<Option<Smoothed<PolygonMesh>>, String> {
    if case.mesh.check_topology().is_err() || case.mesh.validate_coordinates().is_err() {
        return Ok(None);
    }
    let out =
        smooth_mesh(&case.mesh, &SmoothOptions::new(case.delta)).map_err(|e| e.to_string())?;
    Ok(Some(out))
}

fn with3(case: &CaseM, f: impl Fn(&Smoothed<PolygonMesh>) -> Result<(), String>) -> Outcome {
    match run3(case) {
        Ok(None) => Outcome::Skip,
        Ok(Some(out)) => match f(&out) {
            Ok(()) => Outcome::Pass,
            Err(e) => Outcome::Fail(e),
        },
        Err(e) => Outcome::Fail(e),
    }
}

fn closure3(case: &CaseM) -> Outcome {
    with3(case, |out| {
        out.shape.check_topology().map_err(|e| e.to_string())?;
        if out.report.budget_hit {
            return Err("safety budget hit".into());
        }
        Ok(())
    })
}

/// Idempotence is checked where the tolerance is resolved by the
/// coordinates: at least `2^-40` of their largest magnitude (about 8,000
/// units in the last place). Below that the point-segment distances that
/// decide cracking carry rounding errors of the tolerance's own size, so
/// whether a second run cracks can depend on the vertex order
/// (`needle_triangle_is_smoothed_idempotently`); `docs/algorithms/smooth.md`
/// states the exception.
fn tolerance_resolved(delta: f64, max_abs: f64) -> bool {
    delta >= max_abs * 2f64.powi(-40)
}

fn idempotent3(case: &CaseM) -> Outcome {
    with3(case, |out| {
        if !tolerance_resolved(case.delta, max_abs(&out.shape.vertices)) {
            return Ok(());
        }
        let again =
            smooth_mesh(&out.shape, &SmoothOptions::new(case.delta)).map_err(|e| e.to_string())?;
        if again.shape.vertices != out.shape.vertices
            || again.shape.facets.len() != out.shape.facets.len()
            || again.shape.half_edge_count() != out.shape.half_edge_count()
        {
            return Err(format!(
                "second pass changed the shape ({} adjustments)",
                again.report.counts.adjustments()
            ));
        }
        Ok(())
    })
}

fn bound3(case: &CaseM) -> Outcome {
    with3(case, |out| {
        let bound = out.report.distortion_bound;
        if out.report.max_displacement > bound {
            return Err(format!(
                "reported displacement {} > bound {bound}",
                out.report.max_displacement
            ));
        }
        let input = &case.mesh;
        let slack = bound * (1.0 + 1e-9) + 1e-15 * max_abs(&input.vertices);
        for (i, &p) in out.shape.vertices.iter().enumerate() {
            let near_vertex = input.vertices.iter().any(|&q| dist(p, q) <= slack);
            let near_edge = near_vertex
                || input.facets.iter().flat_map(|f| &f.half_edges).any(|h| {
                    dist_segment(
                        p,
                        input.vertices[h.start as usize],
                        input.vertices[h.end as usize],
                    ) <= slack
                });
            if !near_edge {
                return Err(format!(
                    "vertex {i} lies farther than {bound} from the input"
                ));
            }
        }
        Ok(())
    })
}

fn max_abs(v: &[[f64; 3]]) -> f64 {
    v.iter().flatten().fold(0.0, |m: f64, x| m.max(x.abs()))
}

fn used_vertices(m: &PolygonMesh) -> Vec<u32> {
    let mut used: Vec<u32> = m
        .facets
        .iter()
        .flat_map(|f| &f.half_edges)
        .flat_map(|h| [h.start, h.end])
        .collect();
    used.sort_unstable();
    used.dedup();
    used
}

fn features3(case: &CaseM) -> Outcome {
    with3(case, |out| {
        let m = &out.shape;
        // Relative slack for rounding in the distance computation.
        let d = case.delta * (1.0 - 1e-9);
        for f in &m.facets {
            for h in &f.half_edges {
                let l = dist(m.vertices[h.start as usize], m.vertices[h.end as usize]);
                if l < d {
                    return Err(format!("edge {}-{} of length {l}", h.start, h.end));
                }
            }
        }
        let used = used_vertices(m);
        if used.len() <= 2000 {
            for (k, &i) in used.iter().enumerate() {
                for &j in &used[k + 1..] {
                    let l = dist(m.vertices[i as usize], m.vertices[j as usize]);
                    if l <= d {
                        return Err(format!("vertices {i} and {j} are {l} apart"));
                    }
                }
            }
        }
        Ok(())
    })
}

fn area3(m: &PolygonMesh) -> f64 {
    test_support::measure::triangle_mesh_area(&topology::triangulate_mesh(m))
}

/// How far smoothing may have moved the boundary, as the algorithm notes
/// state it: the reported distortion bound, and at least the tolerance
/// once any adjustment ran. The report's `distortion_bound` only covers
/// the vertices of the *result* (`max_adjustments` is the largest `k` of a
/// result vertex): where a whole sliver collapses (its vertices merge, its
/// facets cancel and nothing of it is left) it reports 0 although every
/// collapsed vertex moved by up to the tolerance, while the notes say the
/// bound is the tolerance whenever input vertices merged (see
/// `report_bound_covers_collapsed_slivers` below). With no adjustment at
/// all this is 0, so the check then demands an unchanged volume or area.
fn documented_bound(report: &smooth::SmoothReport) -> f64 {
    let floor = if report.counts.adjustments() > 0 {
        report.tolerance
    } else {
        0.0
    };
    report.distortion_bound.max(floor)
}

/// Whether every facet of `m` lies exactly in one plane (exact
/// `orient3d` against a non-collinear triple of its vertices; a facet with
/// all vertices collinear counts as planar).
fn planar_facets(m: &PolygonMesh) -> bool {
    let collinear = |a: [f64; 3], b: [f64; 3], c: [f64; 3]| {
        let proj = |i: usize, j: usize| {
            robust_arith::orient2d([a[i], a[j]], [b[i], b[j]], [c[i], c[j]])
                == std::cmp::Ordering::Equal
        };
        proj(0, 1) && proj(1, 2) && proj(2, 0)
    };
    m.facets.iter().all(|f| {
        let mut ids: Vec<u32> = f.half_edges.iter().map(|h| h.start).collect();
        ids.sort_unstable();
        ids.dedup();
        let pts: Vec<[f64; 3]> = ids.iter().map(|&i| m.vertices[i as usize]).collect();
        if pts.len() <= 3 {
            return true;
        }
        let Some(b) = pts.iter().position(|&p| p != pts[0]) else {
            return true;
        };
        let Some(c) = pts.iter().position(|&p| !collinear(pts[0], pts[b], p)) else {
            return true;
        };
        pts.iter().all(|&d| {
            robust_arith::orient3d(pts[0], pts[b], pts[c], d) == std::cmp::Ordering::Equal
        })
    })
}

/// The volume check. The volume of a mesh with non-planar facets depends
/// on how its facets are triangulated (for a random quad, by as much as
/// the tetrahedron of its four corners), so it is not a property of the
/// shape and smoothing may legitimately change it beyond any bound (the
/// `garbage` corpus, whose cubes have random corners). Such an input is
/// triangulated first and the triangle variant is checked on it, so that
/// the volume before and after is that of definite triangles; an input
/// with planar facets is checked through `smooth_mesh` itself.
fn volume3(case: &CaseM) -> Outcome {
    let allowed = |report: &smooth::SmoothReport| {
        area3(&case.mesh) * documented_bound(report) * (1.0 + 1e-9)
            + 1e-12 * max_abs(&case.mesh.vertices).powi(3)
    };
    let compare = |before: f64, after: f64, allowed: f64, what: &str| {
        if (after - before).abs() > allowed {
            return Err(format!(
                "volume{what} moved from {before} to {after} (allowed {allowed})"
            ));
        }
        Ok(())
    };
    if case.mesh.check_topology().is_ok()
        && case.mesh.validate_coordinates().is_ok()
        && !planar_facets(&case.mesh)
    {
        let tri = topology::triangulate_mesh(&case.mesh);
        return match smooth_triangles(&tri, &SmoothOptions::new(case.delta)) {
            Ok(out) => match compare(
                test_support::exact::triangle_mesh_volume(&tri),
                test_support::exact::triangle_mesh_volume(&out.shape),
                allowed(&out.report),
                " (non-planar input, triangle variant)",
            ) {
                Ok(()) => Outcome::Pass,
                Err(e) => Outcome::Fail(e),
            },
            Err(e) => Outcome::Fail(e.to_string()),
        };
    }
    with3(case, |out| {
        compare(
            test_support::exact::triangle_mesh_volume(&topology::triangulate_mesh(&case.mesh)),
            test_support::exact::triangle_mesh_volume(&topology::triangulate_mesh(&out.shape)),
            allowed(&out.report),
            "",
        )
    })
}

fn triangles3(case: &CaseM) -> Outcome {
    if case.mesh.check_topology().is_err() || case.mesh.validate_coordinates().is_err() {
        return Outcome::Skip;
    }
    let tri = topology::triangulate_mesh(&case.mesh);
    match smooth_triangles(&tri, &SmoothOptions::new(case.delta)) {
        Ok(out) => match out.shape.check_topology() {
            Ok(()) if !out.report.budget_hit => Outcome::Pass,
            Ok(()) => Outcome::Fail("safety budget hit".into()),
            Err(e) => Outcome::Fail(e.to_string()),
        },
        Err(e) => Outcome::Fail(e.to_string()),
    }
}

/// The 3D smoothing suite.
pub fn smooth_3d_suite() -> Suite<CaseM> {
    Suite {
        name: "smoothing of meshes (smooth_mesh, smooth_triangles; Appendix A)",
        corpora: vec![
            Corpus {
                name: "stacked",
                make: stacked,
            },
            Corpus {
                name: "chains",
                make: chain,
            },
            Corpus {
                name: "near-vertical",
                make: near_vertical,
            },
            Corpus {
                name: "garbage",
                make: garbage,
            },
        ],
        checks: vec![
            Check {
                name: "closure",
                source: "sec. 4.2, budget",
                run: closure3,
            },
            Check {
                name: "idempotent",
                source: "App. A fixpoint",
                run: idempotent3,
            },
            Check {
                name: "bound",
                source: "ch. 8 k, distortion",
                run: bound3,
            },
            Check {
                name: "features",
                source: "App. A postconditions",
                run: features3,
            },
            Check {
                name: "volume",
                source: "area x bound",
                run: volume3,
            },
            Check {
                name: "triangles",
                source: "sec. 4.8 variant",
                run: triangles3,
            },
        ],
    }
}

// ------------------------------------------------------------- 2D suite

/// A 2D smoothing case.
pub struct CaseP {
    /// The set to smooth.
    pub set: PolygonSet2,
    /// The tolerance.
    pub delta: f64,
}

fn squares(r: &mut SplitMix64) -> CaseP {
    let sq = |r: &mut SplitMix64| {
        let x = r.range(0, 3) as f64 + jitter(r);
        let y = r.range(0, 3) as f64 + jitter(r);
        let w = r.range(1, 2) as f64 + jitter(r);
        let mut s = PolygonSet2::new();
        s.add_loop(&[[x, y], [x + w, y], [x + w, y + w], [x, y + w]]);
        s
    };
    let mut acc = sq(r);
    for _ in 0..r.range(1, 4) {
        let b = sq(r);
        let op = [
            BooleanOp::Union,
            BooleanOp::Intersection,
            BooleanOp::Difference,
        ][r.range(0, 2) as usize];
        if let Ok(out) = boolean_2d::boolean(&acc, &b, op) {
            acc = out.shape;
        }
    }
    CaseP {
        set: acc,
        delta: 1e-5,
    }
}

fn random_loops(r: &mut SplitMix64) -> CaseP {
    let mut s = PolygonSet2::new();
    let delta = 10f64.powi(-(r.range(2, 8) as i32));
    for _ in 0..r.range(1, 3) {
        let n = r.range(3, 12) as usize;
        let mut pts: Vec<[f64; 2]> = Vec::with_capacity(n);
        for _ in 0..n {
            if !pts.is_empty() && r.range(0, 3) == 0 {
                let q = pts[r.range(0, pts.len() as i64 - 1) as usize];
                pts.push([q[0] + delta * r.pm1(), q[1] + delta * r.pm1()]);
            } else {
                pts.push([r.pm1(), r.pm1()]);
            }
        }
        s.add_loop(&pts);
    }
    CaseP { set: s, delta }
}

fn garbage2(r: &mut SplitMix64) -> CaseP {
    let mut s = PolygonSet2::new();
    for _ in 0..r.range(1, 3) {
        let n = r.range(3, 8) as usize;
        let pts: Vec<[f64; 2]> = (0..n)
            .map(|_| {
                let mut c = || {
                    let m = r.magnitude(-60, 60);
                    if r.range(0, 1) == 0 {
                        -m
                    } else {
                        m
                    }
                };
                [c(), c()]
            })
            .collect();
        s.add_loop(&pts);
    }
    CaseP {
        set: s,
        // `magnitude` draws a random sign; a tolerance is a size.
        delta: r.magnitude(-60, 0).abs(),
    }
}

fn with2(case: &CaseP, f: impl Fn(&Smoothed<PolygonSet2>) -> Result<(), String>) -> Outcome {
    if case.set.check_topology().is_err() || case.set.validate_coordinates().is_err() {
        return Outcome::Skip;
    }
    match smooth_polygon_set(&case.set, &SmoothOptions::new(case.delta)) {
        Ok(out) => match f(&out) {
            Ok(()) => Outcome::Pass,
            Err(e) => Outcome::Fail(e),
        },
        Err(e) => Outcome::Fail(e.to_string()),
    }
}

fn closure2(case: &CaseP) -> Outcome {
    with2(case, |out| {
        out.shape.check_topology().map_err(|e| e.to_string())?;
        if out.report.budget_hit {
            return Err("safety budget hit".into());
        }
        Ok(())
    })
}

fn idempotent2(case: &CaseP) -> Outcome {
    with2(case, |out| {
        if !tolerance_resolved(case.delta, out.shape.max_abs_coordinate()) {
            return Ok(());
        }
        let again = smooth_polygon_set(&out.shape, &SmoothOptions::new(case.delta))
            .map_err(|e| e.to_string())?;
        let key = |s: &PolygonSet2| {
            let mut e: Vec<([u64; 2], [u64; 2], i32)> = s
                .edges()
                .iter()
                .map(|e| {
                    let (a, b) = s.edge_points(e);
                    (a.map(f64::to_bits), b.map(f64::to_bits), e.mult)
                })
                .collect();
            e.sort_unstable();
            e
        };
        if key(&again.shape) != key(&out.shape) {
            return Err("second pass changed the set".into());
        }
        Ok(())
    })
}

/// Smoothing near one contact box over the whole set is whole smoothing,
/// bit for bit: on a set whole smoothing cleans in one pass the region is
/// every edge and the phases are the same, and on any other the exact
/// check sends near smoothing to whole smoothing.
fn near2(case: &CaseP) -> Outcome {
    with2(case, |out| {
        let Some([lo, hi]) = case.set.bounding_box() else {
            return Ok(());
        };
        let everything = [[lo.map(|x| x - x.abs() - 1.0), hi.map(|x| x + x.abs() + 1.0)]];
        let near = smooth_polygon_set_near(&case.set, &SmoothOptions::new(case.delta), &everything)
            .map_err(|e| e.to_string())?;
        if near.shape != out.shape {
            return Err(format!(
                "near smoothing gave {} edges, whole smoothing {}",
                near.shape.edge_count(),
                out.shape.edge_count()
            ));
        }
        Ok(())
    })
}

fn features2(case: &CaseP) -> Outcome {
    with2(case, |out| {
        let s = &out.shape;
        let d = case.delta * (1.0 - 1e-9);
        for e in s.edges() {
            let (a, b) = s.edge_points(e);
            let l = (b[0] - a[0]).hypot(b[1] - a[1]);
            if l < d {
                return Err(format!("edge {}-{} of length {l}", e.start, e.end));
            }
        }
        Ok(())
    })
}

/// The area of the region of positive winding number (the positive fill
/// rule of section 6.1), computed independently of the sweep: the plane is
/// cut into vertical slabs at every vertex and every crossing of two
/// edges, so that inside a slab no two edges cross; the edges spanning a
/// slab are ordered by height at its middle, the winding number is
/// accumulated upwards (an edge running in +x adds its multiplicity above
/// it, one running in -x subtracts it), and the trapezoids between
/// consecutive edges with positive winding are summed. Quadratic in the
/// number of edges: meant for the small cases of this suite.
pub fn positive_area(set: &PolygonSet2) -> f64 {
    let segs: Vec<([f64; 2], [f64; 2], i32)> = set
        .edges()
        .iter()
        .map(|e| {
            let (a, b) = set.edge_points(e);
            (a, b, e.mult)
        })
        .filter(|&(a, b, m)| a[0] != b[0] && m != 0)
        .collect();
    let mut xs: Vec<f64> = set.vertices().iter().map(|p| p[0]).collect();
    for (i, &(p, q, _)) in segs.iter().enumerate() {
        for &(r, t, _) in &segs[i + 1..] {
            let d = [q[0] - p[0], q[1] - p[1]];
            let e = [t[0] - r[0], t[1] - r[1]];
            let den = d[0] * e[1] - d[1] * e[0];
            if den == 0.0 {
                continue;
            }
            let w = [r[0] - p[0], r[1] - p[1]];
            let s = (w[0] * e[1] - w[1] * e[0]) / den;
            let u = (w[0] * d[1] - w[1] * d[0]) / den;
            if (0.0..=1.0).contains(&s) && (0.0..=1.0).contains(&u) {
                let x = p[0] + s * d[0];
                if x.is_finite() {
                    xs.push(x);
                }
            }
        }
    }
    xs.sort_by(f64::total_cmp);
    xs.dedup();
    let y_at = |a: [f64; 2], b: [f64; 2], x: f64| {
        let t = ((x - a[0]) / (b[0] - a[0])).clamp(0.0, 1.0);
        a[1] + t * (b[1] - a[1])
    };
    let mut area = 0.0;
    let mut spanning: Vec<(f64, f64, f64, i32)> = Vec::new();
    for w in xs.windows(2) {
        let (x0, x1) = (w[0], w[1]);
        let xm = 0.5 * (x0 + x1);
        spanning.clear();
        for &(a, b, m) in &segs {
            let (lo, hi) = (a[0].min(b[0]), a[0].max(b[0]));
            if lo <= x0 && x1 <= hi {
                let dir = if a[0] < b[0] { m } else { -m };
                spanning.push((y_at(a, b, xm), y_at(a, b, x0), y_at(a, b, x1), dir));
            }
        }
        spanning.sort_by(|p, q| p.0.total_cmp(&q.0));
        let mut winding = 0i64;
        for pair in spanning.windows(2) {
            winding += i64::from(pair[0].3);
            if winding > 0 {
                area += (x1 - x0) * ((pair[1].1 - pair[0].1) + (pair[1].2 - pair[0].2)) * 0.5;
            }
        }
    }
    area
}

fn area2(case: &CaseP) -> Outcome {
    with2(case, |out| area_within(&case.set, &out.shape, &out.report))
}

/// The area check proper: smoothing ends with the positive-rule sweep
/// wherever crossings or winding numbers outside {0, 1} remain, so the
/// result's area is compared with the input's area *as the positive rule
/// reads it* (for a simple input, its signed area), within the input's
/// perimeter times the documented bound. The result must itself be simple
/// (winding 0 or 1), so its signed area and its positive area agree.
fn area_within(
    input: &PolygonSet2,
    result: &PolygonSet2,
    report: &smooth::SmoothReport,
) -> Result<(), String> {
    let before = positive_area(input);
    let after = result.signed_area();
    let scale = input.max_abs_coordinate().max(result.max_abs_coordinate());
    let slack = 1e-12 * scale.powi(2);
    let after_positive = positive_area(result);
    if (after - after_positive).abs() > slack {
        return Err(format!(
            "result not simple: signed area {after}, positive area {after_positive}"
        ));
    }
    let perimeter: f64 = input
        .edges()
        .iter()
        .map(|e| {
            let (a, b) = input.edge_points(e);
            f64::from(e.mult.unsigned_abs()) * (b[0] - a[0]).hypot(b[1] - a[1])
        })
        .sum();
    let allowed = perimeter * documented_bound(report) * (1.0 + 1e-9) + slack;
    if (after - before).abs() > allowed {
        return Err(format!(
            "positive-rule area moved from {before} to {after} (allowed {allowed})"
        ));
    }
    Ok(())
}

/// The 2D smoothing suite.
pub fn smooth_2d_suite() -> Suite<CaseP> {
    Suite {
        name: "smoothing of polygon sets (smooth_polygon_set; Appendix A + sweep)",
        corpora: vec![
            Corpus {
                name: "squares",
                make: squares,
            },
            Corpus {
                name: "random",
                make: random_loops,
            },
            Corpus {
                name: "garbage",
                make: garbage2,
            },
        ],
        checks: vec![
            Check {
                name: "closure",
                source: "sec. 4.2, budget",
                run: closure2,
            },
            Check {
                name: "idempotent",
                source: "App. A fixpoint",
                run: idempotent2,
            },
            Check {
                name: "features",
                source: "no edge < delta",
                run: features2,
            },
            Check {
                name: "area",
                source: "perimeter x bound",
                run: area2,
            },
            Check {
                name: "near",
                source: "near = whole",
                run: near2,
            },
        ],
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn set(loops: &[&[[f64; 2]]]) -> PolygonSet2 {
        let mut s = PolygonSet2::new();
        for l in loops {
            s.add_loop(l);
        }
        s
    }

    const SQ: [[f64; 2]; 4] = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];

    #[test]
    fn positive_area_matches_analytic_values() {
        let cw: Vec<[f64; 2]> = SQ.iter().rev().copied().collect();
        let shifted: Vec<[f64; 2]> = SQ.iter().map(|p| [p[0] + 0.5, p[1] + 0.5]).collect();
        // A simple square; inside out; covered twice; two overlapping
        // squares (the union, 1.75); a square with a hole.
        assert_eq!(positive_area(&set(&[&SQ])), 1.0);
        assert_eq!(positive_area(&set(&[&cw])), 0.0);
        assert_eq!(positive_area(&set(&[&SQ, &SQ])), 1.0);
        assert_eq!(positive_area(&set(&[&SQ, &shifted])), 1.75);
        let big = [[-1.0, -1.0], [2.0, -1.0], [2.0, 2.0], [-1.0, 2.0]];
        assert_eq!(positive_area(&set(&[&big, &cw])), 8.0);
        // A bow tie: one lobe counter-clockwise, one clockwise.
        let bow = [[0.0, 0.0], [2.0, 2.0], [2.0, 0.0], [0.0, 2.0]];
        let a = positive_area(&set(&[&bow]));
        assert!((a - 1.0).abs() < 1e-15, "{a}");
        assert_eq!(set(&[&bow]).signed_area(), 0.0);
        // A pentagram traced in one loop: the centre has winding 2, the
        // positive rule fills the star's whole outline.
        let pts: Vec<[f64; 2]> = (0..5)
            .map(|i| {
                let t =
                    std::f64::consts::FRAC_PI_2 + f64::from(i * 2) * std::f64::consts::TAU / 5.0;
                [t.cos(), t.sin()]
            })
            .collect();
        let star = positive_area(&set(&[&pts]));
        // The outline of a pentagram of circumradius 1: 10 triangles
        // centre-tip-notch, the notches at radius cos 72 / cos 36.
        let r_in = (0.4 * std::f64::consts::PI).cos() / (0.2 * std::f64::consts::PI).cos();
        let expect = 10.0 * 0.5 * r_in * (0.2 * std::f64::consts::PI).sin();
        assert!((star - expect).abs() < 1e-12, "{star} vs {expect}");
    }

    #[test]
    fn the_area_check_can_fail() {
        // Each corpus: the smoothed result passes, the same result scaled
        // by 3 about the origin (area x 9) fails.
        for (ci, make) in [squares as fn(&mut SplitMix64) -> CaseP, random_loops]
            .into_iter()
            .enumerate()
        {
            let mut failed = 0;
            for i in 0..20 {
                let mut rng = SplitMix64::stream(7 + ci as u64, i);
                let case = make(&mut rng);
                if case.set.check_topology().is_err() {
                    continue;
                }
                let out = smooth_polygon_set(&case.set, &SmoothOptions::new(case.delta)).unwrap();
                area_within(&case.set, &out.shape, &out.report).unwrap();
                if out.shape.signed_area() <= 0.1 {
                    continue;
                }
                let grown: Vec<[f64; 2]> = out
                    .shape
                    .vertices()
                    .iter()
                    .map(|p| [p[0] * 3.0, p[1] * 3.0])
                    .collect();
                let bad = PolygonSet2::from_parts(grown, out.shape.edges().to_vec());
                assert!(area_within(&case.set, &bad, &out.report).is_err());
                failed += 1;
            }
            assert!(failed > 5, "corpus {ci}: only {failed} perturbed cases");
        }
    }

    #[test]
    fn planarity_is_exact() {
        let mut m = boxes(&[([0.1, 0.2, 0.3], [1.7, 2.9, 3.1])]);
        assert!(planar_facets(&m));
        // One corner lifted by the smallest step off its three faces.
        m.vertices[0][0] = m.vertices[0][0].next_up();
        assert!(!planar_facets(&m));
        // The garbage cubes are not planar, their tetrahedra are.
        let mut seen = [false; 2];
        for i in 0..50 {
            let mut rng = SplitMix64::stream(5, i);
            let g = garbage(&mut rng);
            let tri = g.mesh.facets.iter().all(|f| f.half_edges.len() == 3);
            assert!(!tri || planar_facets(&g.mesh));
            seen[usize::from(planar_facets(&g.mesh))] = true;
        }
        assert_eq!(seen, [true, true]);
    }

    #[test]
    fn garbage_tolerances_are_sizes() {
        for i in 0..200 {
            let mut rng = SplitMix64::stream(1, i);
            assert!(garbage(&mut rng).delta >= 0.0);
            let mut rng = SplitMix64::stream(2, i);
            assert!(garbage2(&mut rng).delta >= 0.0);
        }
    }

    /// A finding of this suite, fixed in the smoothing crate: a sliver box of
    /// thickness below the tolerance (a chain of grid boxes, corpus
    /// `chains`, seed 1, case 2) collapses in full: 4 vertices merge, its
    /// facets cancel, the result is empty, the volume moves from 6.4e-7 to
    /// 0, and the report gives `distortion_bound` 0 and `max_adjustments`
    /// 0. The algorithm note says the bound is the tolerance whenever input
    /// vertices merged, and issue 10's guarantee (volume change within
    /// area x bound) needs it; the report now counts every adjusted vertex,
    /// also one whose facets were all cancelled. This test asserts the
    /// report itself.
    #[test]
    fn report_bound_covers_collapsed_slivers() {
        let lo = [2.000000000000808, 1.0000001846522832, 2.0000000000003557];
        let hi = [3.9999999991121573, 1.0000005057971384, 2.999999999998388];
        let mesh = boxes(&[(lo, hi)]);
        let out = smooth_mesh(&mesh, &SmoothOptions::new(1e-6)).unwrap();
        assert!(out.shape.facets.is_empty());
        assert!(out.report.counts.vertices_merged > 0);
        assert!(
            out.report.distortion_bound >= 1e-6,
            "bound {} after {} merges",
            out.report.distortion_bound,
            out.report.counts.vertices_merged
        );
    }

    /// A real finding, left to the smoothing crate (corpus `garbage` 2D,
    /// seed 1, case 182): a needle triangle 4.4e17 long whose vertex
    /// `(0, -1.446e12)` lies 0.0897 (exactly: the cross product over the
    /// length) from the opposite edge's interior, tolerance 0.807. The
    /// first run cracks nothing and returns the triangle; smoothing that
    /// result (the same triangle, its vertices renumbered by position)
    /// cracks the edge and cancels everything. The f64 point-segment
    /// distance loses all its digits at this aspect ratio (the tolerance is
    /// below the coordinates' resolution), so the decision depends on the
    /// vertex order: not idempotent, and the first result keeps a vertex
    /// within the tolerance of an edge that both parts would shorten. The
    /// 3D `garbage` idempotence failures (seed 1, cases 57 and 116;
    /// tolerance 0.012 and 0.0057 against coordinates near 1e18) look the
    /// same.
    #[test]
    #[ignore = "smooth's distance tests lose all digits when the tolerance is below the coordinates' resolution (reported to the lead)"]
    fn needle_triangle_is_smoothed_idempotently() {
        let mut s = PolygonSet2::new();
        s.add_loop(&[
            [27390.359510482816, -4.417812339847444e17],
            [-3.761998648798771e-9, 2.0986140547907535e-13],
            [-7.744171575102481e-17, -1446036723199.0815],
        ]);
        let delta = 0.8069319098258729;
        let out = smooth_polygon_set(&s, &SmoothOptions::new(delta)).unwrap();
        let again = smooth_polygon_set(&out.shape, &SmoothOptions::new(delta)).unwrap();
        assert_eq!(
            out.shape.edges().len(),
            again.shape.edges().len(),
            "first {:?}, second {:?}",
            out.shape,
            again.shape
        );
    }
}
