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
//! at most surface area x bound), `triangles` (the triangle variant stays
//! triangles and closed).
//!
//! 2D corpora: `squares` (grid squares with jittered coincident edges
//! combined by the basic Boolean), `random` (random loops jittered near
//! their own vertices), `garbage`; checks: `closure`, `idempotent`,
//! `features`, `area` (area change at most perimeter x bound).

use crate::verify::{Check, Corpus, Outcome, Suite};
use boolean_3d::{boolean_mesh, BooleanOp};
use smooth::{smooth_mesh, smooth_polygon_set, smooth_triangles, SmoothOptions, Smoothed};
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
    let delta = r.magnitude(-60, 0);
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

fn idempotent3(case: &CaseM) -> Outcome {
    with3(case, |out| {
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
    let t = topology::triangulate_mesh(m);
    t.triangles
        .iter()
        .map(|tr| {
            let [a, b, c] = tr.map(|i| t.vertices[i as usize]);
            let u = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
            let v = [c[0] - a[0], c[1] - a[1], c[2] - a[2]];
            0.5 * ((u[1] * v[2] - u[2] * v[1]).powi(2)
                + (u[2] * v[0] - u[0] * v[2]).powi(2)
                + (u[0] * v[1] - u[1] * v[0]).powi(2))
            .sqrt()
        })
        .sum()
}

fn volume3(case: &CaseM) -> Outcome {
    with3(case, |out| {
        let before =
            test_support::exact::triangle_mesh_volume(&topology::triangulate_mesh(&case.mesh));
        let after =
            test_support::exact::triangle_mesh_volume(&topology::triangulate_mesh(&out.shape));
        let allowed = area3(&case.mesh) * out.report.distortion_bound * (1.0 + 1e-9)
            + 1e-12 * max_abs(&case.mesh.vertices).powi(3);
        if (after - before).abs() > allowed {
            return Err(format!(
                "volume moved from {before} to {after} (allowed {allowed})"
            ));
        }
        Ok(())
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
        delta: r.magnitude(-60, 0),
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

fn area2(case: &CaseP) -> Outcome {
    with2(case, |out| {
        let before = case.set.signed_area();
        let after = out.shape.signed_area();
        let perimeter: f64 = case
            .set
            .edges()
            .iter()
            .map(|e| {
                let (a, b) = case.set.edge_points(e);
                f64::from(e.mult.unsigned_abs()) * (b[0] - a[0]).hypot(b[1] - a[1])
            })
            .sum();
        let allowed = perimeter * out.report.distortion_bound * (1.0 + 1e-9)
            + 1e-12 * case.set.max_abs_coordinate().powi(2);
        if (after - before).abs() > allowed {
            return Err(format!(
                "area moved from {before} to {after} (allowed {allowed})"
            ));
        }
        Ok(())
    })
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
        ],
    }
}
