//! `cargo xtask fingerprint`: a digest of every result over the seeded
//! verification corpora, so that a refactoring can show its results are
//! unchanged bit for bit (run before and after, compare the lines).
//!
//! For each corpus of the 2D, 3D and simplification suites it hashes
//! (64-bit FNV-1a over the `Debug` text, which prints every `f64` in its
//! shortest round-trip form) the shapes of: the 2D basic Boolean for every
//! operation; the 3D polygon-mesh and triangle-mesh variants for every
//! operation; simplification by every fill rule and the Boolean through
//! simplification for every operation (the case against itself shifted).
//! Errors are hashed by their message, so a changed error shows too.

use crate::verify::{boolean_2d_suite, Suite};
use crate::verify3::{boolean_3d_suite, simplify_suite};
use rayon::prelude::*;
use std::fmt::Debug;
use std::fmt::Write as _;
use test_support::rng::SplitMix64;

/// 64-bit FNV-1a.
fn fnv(bytes: &[u8], mut h: u64) -> u64 {
    for &b in bytes {
        h ^= u64::from(b);
        h = h.wrapping_mul(0x0000_0100_0000_01b3);
    }
    h
}

const FNV_OFFSET: u64 = 0xcbf2_9ce4_8422_2325;

fn digest<T: Debug>(values: &[T]) -> u64 {
    let mut h = FNV_OFFSET;
    let mut s = String::new();
    for v in values {
        s.clear();
        let _ = write!(s, "{v:?}");
        h = fnv(s.as_bytes(), h);
    }
    h
}

/// One corpus's digest line: `suite/corpus cases digest`.
fn corpus_lines<C: Send + Sync>(
    suite: &Suite<C>,
    tag: &str,
    cases: usize,
    seed: u64,
    results: fn(&C) -> Vec<String>,
) -> Vec<String> {
    suite
        .corpora
        .iter()
        .enumerate()
        .map(|(ci, corpus)| {
            let per_case: Vec<u64> = (0..cases)
                .into_par_iter()
                .map(|i| {
                    let mut rng = SplitMix64::stream(seed ^ ((ci as u64 + 1) << 48), i as u64);
                    let case = (corpus.make)(&mut rng);
                    digest(&results(&case))
                })
                .collect();
            format!("{tag}/{} {cases} {:016x}", corpus.name, digest(&per_case))
        })
        .collect()
}

/// The digest lines of every corpus, `cases` cases each.
pub fn run(cases: usize, seed: u64) -> Vec<String> {
    let mut lines = corpus_lines(&boolean_2d_suite(), "2d", cases, seed, |c| {
        boolean_2d::BooleanOp::BASIC
            .iter()
            .map(|&op| match boolean_2d::boolean(&c.a, &c.b, op) {
                Ok(out) => format!("{:?} {:?} {}", out.shape, out.epsilon, out.intersections),
                Err(e) => e.to_string(),
            })
            .collect()
    });
    lines.extend(corpus_lines(&boolean_3d_suite(), "3d", cases, seed, |c| {
        let mut v = Vec::new();
        for op in boolean_3d::BooleanOp::BASIC {
            v.push(match boolean_3d::boolean_mesh(&c.a, &c.b, op) {
                Ok(out) => format!("{:?} {:?} {}", out.mesh, out.sources, out.intersections),
                Err(e) => e.to_string(),
            });
            let ta = boolean_3d::triangulate_mesh(&c.a);
            let tb = boolean_3d::triangulate_mesh(&c.b);
            v.push(match boolean_3d::boolean_triangles(&ta, &tb, op) {
                Ok(out) => format!("{:?} {}", out.mesh, out.intersections),
                Err(e) => e.to_string(),
            });
        }
        v
    }));
    lines.extend(corpus_lines(
        &simplify_suite(),
        "simplify",
        cases,
        seed,
        |c| {
            use simplify_2d::{FillRule, Simplified};
            let show = |r: Result<Simplified, simplify_2d::SimplifyError>| match r {
                Ok(s) => format!("{:?} {} {:?}", s.shape, s.k_max, s.epsilon),
                Err(e) => e.to_string(),
            };
            let mut v: Vec<String> = [
                FillRule::Positive,
                FillRule::NonZero,
                FillRule::EvenOdd,
                FillRule::Negative,
                FillRule::AtLeast2,
            ]
            .into_iter()
            .map(|rule| show(simplify_2d::simplify(&c.set, rule)))
            .collect();
            let mut shifted = topology::PolygonSet2::new();
            for &p in c.set.vertices() {
                shifted.add_vertex([p[0] + 0.25, p[1] - 0.125]);
            }
            for e in c.set.edges() {
                shifted.add_edge_mult(e.start, e.end, e.mult);
            }
            for op in [
                simplify_2d::BooleanOp::Union,
                simplify_2d::BooleanOp::Intersection,
                simplify_2d::BooleanOp::Difference,
                simplify_2d::BooleanOp::Xor,
            ] {
                v.push(show(simplify_2d::boolean(&c.set, &shifted, op)));
            }
            v
        },
    ));
    lines
}
