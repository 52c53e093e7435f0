//! `cargo xtask verify`: topology-invariant runs behind Theorems 1-2 and
//! shape boundary closure (section 4.9) over seeded corpora, for the 2D
//! Boolean; built as a list of named checks so the 3D Boolean (Theorems
//! 3-4) can add a corpus type and its own checks later.
//!
//! Corpora: `valid` (convex polygons with holes, geometrically valid),
//! `random` (loops of random points in `[-1, 1]^2`, self-intersecting),
//! `grid` (loops on a small integer grid: exact ties, shared and
//! coincident edges and vertices), `garbage` (loops of points of mixed
//! magnitude `2^-300 .. 2^300`, repeated points, multiplicities -2..2).
//!
//! Checks for each case and each operation (union, intersection,
//! difference), via `boolean_2d::boolean_reference`:
//!
//! - `theorem-1`: level 2 never lacks an interpolation partner (no
//!   internal error), and every X11 point lies in both edges' bounding
//!   boxes (eq. 8.18-8.19);
//! - `theorem-2`: every composite edge has as many start- as end-vertices;
//! - `closure`: the result satisfies shape boundary closure
//!   (`check_topology`);
//! - `level-2-sums`: the Table 4.1 identities between the level data:
//!   `sum_eB m_B X11(e_A, e_B) = -(X02(v_e) - X02(v_s))` for every edge of A
//!   and `sum_eA m_A X11(e_A, e_B) = X20(v_e) - X20(v_s)` for every edge of B;
//! - `eq-8.17`: every X11 point is within `sqrt(153) u L` of both edges
//!   (exact distance);
//! - `fast=ref`: the fast path (`boolean_audit`) gives the reference's
//!   level data and shape bit for bit;
//! - `eq-4.20`: at random sample points farther than `64 u L` from every
//!   input edge, the exact winding number of the result equals
//!   `c_A a + c_B b + c_I a b` of the exact winding numbers of A and B.

use boolean_2d::{boolean_audit, boolean_reference, BooleanOp, BooleanOutput, LevelData};
use rayon::prelude::*;
use robust_arith::{INTERSECTION_ERROR_FACTOR, UNIT_ROUNDOFF};
use std::collections::BTreeMap;
use test_support::exact::{distance_to_segment, l_exp, winding};
use test_support::rng::SplitMix64;
use topology::PolygonSet2;

type P = [f64; 2];

/// The outcome of one check on one case.
#[derive(Clone, Debug, PartialEq)]
pub enum Outcome {
    /// The invariant holds.
    Pass,
    /// The check does not apply (e.g. no sample point far enough from the
    /// boundary).
    Skip,
    /// The invariant is broken: what and where.
    Fail(String),
}

/// A named invariant over cases of type `C`.
pub struct Check<C> {
    /// Short name for the table.
    pub name: &'static str,
    /// The theorem or equation it stands for.
    pub source: &'static str,
    /// The check itself.
    pub run: fn(&C) -> Outcome,
}

/// A named corpus of cases of type `C`.
pub struct Corpus<C> {
    /// Short name for the table.
    pub name: &'static str,
    /// Builds case `index` from a seeded generator.
    pub make: fn(&mut SplitMix64) -> C,
}

/// A suite: corpora and checks over one case type (the 2D Boolean now;
/// a 3D suite plugs in with its own case type).
pub struct Suite<C> {
    /// The suite's name.
    pub name: &'static str,
    /// The corpora.
    pub corpora: Vec<Corpus<C>>,
    /// The checks.
    pub checks: Vec<Check<C>>,
}

/// Counts for one (corpus, check) cell of the summary table.
#[derive(Clone, Debug, Default)]
pub struct Tally {
    /// Cases passed.
    pub pass: usize,
    /// Cases skipped.
    pub skip: usize,
    /// Cases failed.
    pub fail: usize,
    /// The first few failure messages, with their case index.
    pub examples: Vec<String>,
}

/// The summary of a suite run: `(corpus, check) -> tally`.
pub type Summary = BTreeMap<(usize, usize), Tally>;

impl<C: Send + Sync> Suite<C> {
    /// Runs every check on `cases` cases of every corpus.
    pub fn run(&self, cases: usize, seed: u64) -> Summary {
        let mut summary = Summary::new();
        for (ci, corpus) in self.corpora.iter().enumerate() {
            let results: Vec<Vec<Outcome>> = (0..cases)
                .into_par_iter()
                .map(|i| {
                    let mut rng = SplitMix64::stream(seed ^ ((ci as u64 + 1) << 48), i as u64);
                    let case = (corpus.make)(&mut rng);
                    self.checks.iter().map(|k| (k.run)(&case)).collect()
                })
                .collect();
            for (i, outcomes) in results.into_iter().enumerate() {
                for (ki, o) in outcomes.into_iter().enumerate() {
                    let t = summary.entry((ci, ki)).or_default();
                    match o {
                        Outcome::Pass => t.pass += 1,
                        Outcome::Skip => t.skip += 1,
                        Outcome::Fail(msg) => {
                            t.fail += 1;
                            if t.examples.len() < 3 {
                                t.examples.push(format!("case {i}: {msg}"));
                            }
                        }
                    }
                }
            }
        }
        summary
    }

    /// Prints the summary table and the failure examples; returns the
    /// number of failures.
    pub fn print(&self, summary: &Summary, cases: usize, seed: u64) -> usize {
        println!("{}: {} cases per corpus, seed {seed}", self.name, cases);
        print!("{:<14} {:<30}", "check", "stands for");
        for c in &self.corpora {
            print!(" {:>16}", c.name);
        }
        println!();
        let mut failures = 0;
        for (ki, k) in self.checks.iter().enumerate() {
            print!("{:<14} {:<30}", k.name, k.source);
            for ci in 0..self.corpora.len() {
                let t = summary.get(&(ci, ki)).cloned().unwrap_or_default();
                failures += t.fail;
                let cell = if t.fail > 0 {
                    format!("FAIL {}/{}", t.fail, t.pass + t.fail)
                } else if t.skip > 0 {
                    format!("ok {} ({} skip)", t.pass, t.skip)
                } else {
                    format!("ok {}", t.pass)
                };
                print!(" {cell:>16}");
            }
            println!();
        }
        for ((ci, ki), t) in summary {
            for e in &t.examples {
                println!(
                    "  FAIL {} / {}: {e}",
                    self.corpora[*ci].name, self.checks[*ki].name
                );
            }
        }
        failures
    }
}

// ------------------------------------------------------------ 2D suite

/// The reference result of one operation, or the error it gave.
pub type OpResult = Result<(BooleanOutput, LevelData), String>;

/// A 2D Boolean case: two operands, and the reference result of every
/// operation (or the error it gave).
pub struct Case2 {
    /// Operand A.
    pub a: PolygonSet2,
    /// Operand B.
    pub b: PolygonSet2,
    /// `(op, result)` for union, intersection and difference.
    pub results: Vec<(BooleanOp, OpResult)>,
    /// Sample points for eq. 4.20.
    pub samples: Vec<P>,
}

impl Case2 {
    /// Evaluates every operation on the operands.
    pub fn new(a: PolygonSet2, b: PolygonSet2, rng: &mut SplitMix64) -> Case2 {
        let results = BooleanOp::BASIC
            .iter()
            .map(|&op| (op, boolean_reference(&a, &b, op).map_err(|e| e.to_string())))
            .collect();
        // Sample points in the common bounding box (slightly enlarged).
        let mut lo = [f64::INFINITY; 2];
        let mut hi = [f64::NEG_INFINITY; 2];
        for p in a.vertices().iter().chain(b.vertices()) {
            for k in 0..2 {
                lo[k] = lo[k].min(p[k]);
                hi[k] = hi[k].max(p[k]);
            }
        }
        let samples = if lo[0].is_finite() {
            (0..12)
                .map(|_| {
                    let mut p = [0.0; 2];
                    for k in 0..2 {
                        let t = rng.unit() * 1.2 - 0.1;
                        p[k] = lo[k] + t * (hi[k] - lo[k]);
                        if !p[k].is_finite() {
                            p[k] = lo[k];
                        }
                    }
                    p
                })
                .collect()
        } else {
            Vec::new()
        };
        Case2 {
            a,
            b,
            results,
            samples,
        }
    }

    fn max_abs(&self) -> f64 {
        self.a.max_abs_coordinate().max(self.b.max_abs_coordinate())
    }
}

fn add_loop_mult(set: &mut PolygonSet2, pts: &[P], mult: i32) {
    let first = set.vertex_count() as u32;
    let n = pts.len() as u32;
    for &p in pts {
        set.add_vertex(p);
    }
    for i in 0..n {
        set.add_edge_mult(first + i, first + (i + 1) % n, mult);
    }
}

/// A convex polygon (anticlockwise) with an optional clockwise hole.
fn valid_shape(rng: &mut SplitMix64) -> PolygonSet2 {
    let mut s = PolygonSet2::new();
    let c = [rng.pm1() * 0.5, rng.pm1() * 0.5];
    let r = 0.2 + 0.6 * rng.unit();
    let n = rng.range(3, 9) as usize;
    let phase = rng.unit() * 6.0;
    let ring = |rad: f64| -> Vec<P> {
        (0..n)
            .map(|i| {
                let t = phase + std::f64::consts::TAU * i as f64 / n as f64;
                [c[0] + rad * t.cos(), c[1] + rad * t.sin()]
            })
            .collect()
    };
    s.add_loop(&ring(r));
    if rng.next_u64().is_multiple_of(2) {
        let mut hole = ring(r * 0.4);
        hole.reverse();
        s.add_loop(&hole);
    }
    s
}

fn random_shape(rng: &mut SplitMix64) -> PolygonSet2 {
    let mut s = PolygonSet2::new();
    for _ in 0..rng.range(1, 3) {
        let pts: Vec<P> = (0..rng.range(3, 8))
            .map(|_| [rng.pm1(), rng.pm1()])
            .collect();
        s.add_loop(&pts);
    }
    s
}

fn grid_shape(rng: &mut SplitMix64) -> PolygonSet2 {
    let mut s = PolygonSet2::new();
    for _ in 0..rng.range(1, 3) {
        if rng.next_u64().is_multiple_of(2) {
            // An axis-aligned rectangle on the grid (valid, shares lines).
            let (x0, y0) = (rng.range(-4, 2) as f64, rng.range(-4, 2) as f64);
            let (x1, y1) = (x0 + rng.range(1, 4) as f64, y0 + rng.range(1, 4) as f64);
            s.add_loop(&[[x0, y0], [x1, y0], [x1, y1], [x0, y1]]);
        } else {
            let pts: Vec<P> = (0..rng.range(1, 7))
                .map(|_| [rng.range(-4, 4) as f64, rng.range(-4, 4) as f64])
                .collect();
            s.add_loop(&pts);
        }
    }
    s
}

fn garbage_shape(rng: &mut SplitMix64) -> PolygonSet2 {
    let mut s = PolygonSet2::new();
    let mut pool: Vec<P> = Vec::new();
    for _ in 0..rng.range(1, 3) {
        let pts: Vec<P> = (0..rng.range(1, 7))
            .map(|_| {
                if !pool.is_empty() && rng.next_u64().is_multiple_of(4) {
                    pool[rng.range(0, pool.len() as i64 - 1) as usize]
                } else {
                    let p = [rng.magnitude(-300, 300), rng.magnitude(-300, 300)];
                    pool.push(p);
                    p
                }
            })
            .collect();
        let mult = rng.range(-2, 2) as i32;
        add_loop_mult(&mut s, &pts, mult);
    }
    s
}

fn pair(rng: &mut SplitMix64, f: fn(&mut SplitMix64) -> PolygonSet2) -> Case2 {
    let a = f(rng);
    let b = f(rng);
    Case2::new(a, b, rng)
}

fn each_result(
    case: &Case2,
    mut f: impl FnMut(BooleanOp, &BooleanOutput, &LevelData) -> Outcome,
) -> Outcome {
    let mut any = false;
    for (op, r) in &case.results {
        match r {
            Err(e) => return Outcome::Fail(format!("{}: {e}", op.name())),
            Ok((out, data)) => match f(*op, out, data) {
                Outcome::Pass => any = true,
                Outcome::Skip => {}
                fail => return fail,
            },
        }
    }
    if any {
        Outcome::Pass
    } else {
        Outcome::Skip
    }
}

/// The fast path (`boolean_audit`: broad phase, ray casts, propagation)
/// computes exactly the reference's level data and shape.
fn check_fast_path(case: &Case2) -> Outcome {
    each_result(case, |op, out, data| {
        match boolean_audit(&case.a, &case.b, op) {
            Ok((fast, fast_data)) => {
                if &fast_data != data {
                    Outcome::Fail(format!(
                        "{}: level data differ from the reference",
                        op.name()
                    ))
                } else if fast.shape != out.shape {
                    Outcome::Fail(format!("{}: shape differs from the reference", op.name()))
                } else {
                    Outcome::Pass
                }
            }
            Err(e) => Outcome::Fail(format!("{}: {e}", op.name())),
        }
    })
}

fn check_theorem_1(case: &Case2) -> Outcome {
    each_result(case, |op, _, data| {
        for &(ia, ib, _, p) in &data.x11 {
            let ea = &case.a.edges()[ia as usize];
            let eb = &case.b.edges()[ib as usize];
            let (a0, a1) = case.a.edge_points(ea);
            let (b0, b1) = case.b.edge_points(eb);
            for (s, e) in [(a0, a1), (b0, b1)] {
                for k in 0..2 {
                    if p[k] < s[k].min(e[k]) || p[k] > s[k].max(e[k]) {
                        return Outcome::Fail(format!(
                            "{}: X11 point {p:?} of edges {ia}, {ib} outside the bounding box of {s:?}-{e:?}",
                            op.name()
                        ));
                    }
                }
            }
        }
        Outcome::Pass
    })
}

fn check_theorem_2(case: &Case2) -> Outcome {
    each_result(case, |op, _, data| {
        match data.composite_counts.iter().position(|(s, e)| s != e) {
            Some(i) => Outcome::Fail(format!(
                "{}: composite edge {i} has {:?} (starts, ends)",
                op.name(),
                data.composite_counts[i]
            )),
            None => Outcome::Pass,
        }
    })
}

fn check_closure(case: &Case2) -> Outcome {
    each_result(case, |op, out, _| match out.shape.check_topology() {
        Ok(()) => Outcome::Pass,
        Err(e) => Outcome::Fail(format!("{}: {e}", op.name())),
    })
}

fn check_level_2_sums(case: &Case2) -> Outcome {
    // Level data is the same for every operation; check the first.
    let Some((_, Ok((_, data)))) = case.results.first() else {
        return Outcome::Fail("no level data".into());
    };
    let mut per_a = vec![0i64; case.a.edge_count()];
    let mut per_b = vec![0i64; case.b.edge_count()];
    for &(ia, ib, x, _) in &data.x11 {
        let ma = i64::from(case.a.edges()[ia as usize].mult);
        let mb = i64::from(case.b.edges()[ib as usize].mult);
        per_a[ia as usize] += i64::from(x) * mb;
        per_b[ib as usize] += i64::from(x) * ma;
    }
    for (i, e) in case.a.edges().iter().enumerate() {
        if e.mult == 0 {
            continue;
        }
        let want = -(i64::from(data.x02[e.end as usize]) - i64::from(data.x02[e.start as usize]));
        if per_a[i] != want {
            return Outcome::Fail(format!(
                "edge {i} of A: sum X11 = {} but -(X02(v_e) - X02(v_s)) = {want}",
                per_a[i]
            ));
        }
    }
    for (i, e) in case.b.edges().iter().enumerate() {
        if e.mult == 0 {
            continue;
        }
        let want = i64::from(data.x20[e.end as usize]) - i64::from(data.x20[e.start as usize]);
        if per_b[i] != want {
            return Outcome::Fail(format!(
                "edge {i} of B: sum X11 = {} but X20(v_e) - X20(v_s) = {want}",
                per_b[i]
            ));
        }
    }
    Outcome::Pass
}

fn check_eq_8_17(case: &Case2) -> Outcome {
    let Some((_, Ok((_, data)))) = case.results.first() else {
        return Outcome::Fail("no level data".into());
    };
    if data.x11.is_empty() {
        return Outcome::Skip;
    }
    let le = l_exp(case.max_abs());
    for &(ia, ib, _, p) in &data.x11 {
        let (a0, a1) = case.a.edge_points(&case.a.edges()[ia as usize]);
        let (b0, b1) = case.b.edge_points(&case.b.edges()[ib as usize]);
        let da = distance_to_segment(p, a0, a1, le) / UNIT_ROUNDOFF;
        let db = distance_to_segment(p, b0, b1, le) / UNIT_ROUNDOFF;
        if !(da <= INTERSECTION_ERROR_FACTOR && db <= INTERSECTION_ERROR_FACTOR) {
            return Outcome::Fail(format!(
                "X11 point {p:?} of edges {ia}, {ib} is {da:.2} u L and {db:.2} u L from them"
            ));
        }
    }
    Outcome::Pass
}

fn check_eq_4_20(case: &Case2) -> Outcome {
    let le = l_exp(case.max_abs());
    let margin = 64.0 * UNIT_ROUNDOFF;
    let far = |p: P, set: &PolygonSet2| {
        set.edges().iter().filter(|e| e.mult != 0).all(|e| {
            let (s, t) = set.edge_points(e);
            distance_to_segment(p, s, t, le) > margin
        })
    };
    let points: Vec<P> = case
        .samples
        .iter()
        .copied()
        .filter(|&p| far(p, &case.a) && far(p, &case.b))
        .collect();
    if points.is_empty() {
        return Outcome::Skip;
    }
    each_result(case, |op, out, _| {
        for &p in &points {
            let (wa, wb) = (winding(p, &case.a), winding(p, &case.b));
            let want = op.result_winding(wa, wb);
            let got = winding(p, &out.shape);
            if got != want {
                return Outcome::Fail(format!(
                    "{} at {p:?}: result winding {got}, eq. 4.20 gives {want} (a = {wa}, b = {wb})",
                    op.name()
                ));
            }
        }
        Outcome::Pass
    })
}

/// The 2D Boolean suite.
pub fn boolean_2d_suite() -> Suite<Case2> {
    Suite {
        name: "2D basic Boolean (boolean_2d::boolean_reference, union/intersection/difference)",
        corpora: vec![
            Corpus {
                name: "valid",
                make: |r| pair(r, valid_shape),
            },
            Corpus {
                name: "random",
                make: |r| pair(r, random_shape),
            },
            Corpus {
                name: "grid",
                make: |r| pair(r, grid_shape),
            },
            Corpus {
                name: "garbage",
                make: |r| pair(r, garbage_shape),
            },
        ],
        checks: vec![
            Check {
                name: "theorem-1",
                source: "Thm 1, eq. 8.18-8.19",
                run: check_theorem_1,
            },
            Check {
                name: "theorem-2",
                source: "Thm 2 (composite edges)",
                run: check_theorem_2,
            },
            Check {
                name: "closure",
                source: "sec. 4.2 shape closure",
                run: check_closure,
            },
            Check {
                name: "level-2-sums",
                source: "Table 4.1 identities",
                run: check_level_2_sums,
            },
            Check {
                name: "eq-8.17",
                source: "X11 point <= sqrt(153) u L",
                run: check_eq_8_17,
            },
            Check {
                name: "eq-4.20",
                source: "winding of result",
                run: check_eq_4_20,
            },
            Check {
                name: "fast=ref",
                source: "fast path == brute force",
                run: check_fast_path,
            },
        ],
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn small_suite_run_passes() {
        let suite = boolean_2d_suite();
        let summary = suite.run(8, 1);
        for ((ci, ki), t) in &summary {
            assert_eq!(
                t.fail, 0,
                "{} / {}: {:?}",
                suite.corpora[*ci].name, suite.checks[*ki].name, t.examples
            );
        }
    }

    /// The checks can fail: a result with a wrong edge breaks closure and
    /// eq. 4.20.
    #[test]
    fn checks_detect_a_broken_result() {
        let mut rng = SplitMix64::new(3);
        let mut a = PolygonSet2::new();
        a.add_loop(&[[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]]);
        let mut b = PolygonSet2::new();
        b.add_loop(&[[1.0, 1.0], [3.0, 1.0], [3.0, 3.0], [1.0, 3.0]]);
        let mut case = Case2::new(a, b, &mut rng);
        case.samples = vec![[0.5, 0.5], [1.5, 1.5], [2.5, 2.5], [5.0, 5.0]];
        assert_eq!(check_closure(&case), Outcome::Pass);
        assert_eq!(check_eq_4_20(&case), Outcome::Pass);
        if let Some((_, Ok((out, _)))) = case.results.get_mut(0) {
            let v = out.shape.add_vertex([10.0, -10.0]);
            let w = out.shape.add_vertex([10.0, 10.0]);
            out.shape.add_edge(v, w);
        }
        assert!(matches!(check_closure(&case), Outcome::Fail(_)));
        assert!(matches!(check_eq_4_20(&case), Outcome::Fail(_)));
    }
}
