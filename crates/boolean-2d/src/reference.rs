//! The reference evaluation of level 2: every function of Table 4.1
//! evaluated for every pair, with no broad phase. Quadratic, and the oracle
//! the fast path is tested against.

use crate::construct::construct;
use crate::fast::ms;
use crate::{output, validate, BooleanError, BooleanOp, BooleanOutput, Operand, Timings};
use shadow_1d::{s01, s10};
use shadow_2d::x11;
use std::time::Instant;
use topology::PolygonSet2;

/// The level-2 data of a 2D Boolean (section 4.9, "level k intersection
/// data"), from which levels 3 and 4 are built.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct LevelData {
    /// `X02(v, B)` for every vertex `v` of A (multiplicity-weighted).
    pub x02: Vec<i32>,
    /// `X20(A, v)` for every vertex `v` of B (multiplicity-weighted).
    pub x20: Vec<i32>,
    /// Every edge pair with `X11 != 0`: `(edge of A, edge of B, X11, point)`,
    /// sorted by edge of A, then edge of B.
    pub x11: Vec<(u32, u32, i32, [f64; 2])>,
    /// For every composite edge (A's edges, then B's): the number of
    /// start- and end-vertices (Theorem 2 says they are equal).
    pub composite_counts: Vec<(u32, u32)>,
}

/// Level 2 by brute force: `X02` and `X20` summed over every edge
/// (Table 4.1), `X11` for every edge pair.
pub(crate) fn level2_brute_force(
    a: &PolygonSet2,
    b: &PolygonSet2,
) -> Result<LevelData, BooleanError> {
    let x02 = a
        .vertices()
        .iter()
        .map(|v| {
            -b.edges()
                .iter()
                .map(|e| {
                    let (s, t) = b.edge_points(e);
                    e.mult * s01(v, &s, &t)
                })
                .sum::<i32>()
        })
        .collect();
    let x20 = b
        .vertices()
        .iter()
        .map(|v| {
            a.edges()
                .iter()
                .map(|e| {
                    let (s, t) = a.edge_points(e);
                    e.mult * s10(&s, &t, v)
                })
                .sum::<i32>()
        })
        .collect();
    let mut hits = Vec::new();
    for (ia, ea) in a.edges().iter().enumerate() {
        if ea.mult == 0 {
            continue;
        }
        let (as_, ae) = a.edge_points(ea);
        for (ib, eb) in b.edges().iter().enumerate() {
            if eb.mult == 0 {
                continue;
            }
            let (bs, be) = b.edge_points(eb);
            let hit = x11(&as_, &ae, &bs, &be)
                .map_err(|e| BooleanError::Internal(format!("edges {ia}, {ib}: {e}")))?;
            if let Some(h) = hit {
                hits.push((ia as u32, ib as u32, h.value, h.a));
            }
        }
    }
    Ok(LevelData {
        x02,
        x20,
        x11: hits,
        composite_counts: Vec::new(),
    })
}

/// The 2D Boolean with level 2 evaluated by brute force (every vertex
/// against every edge, every edge against every edge), returning the level
/// data for audit. `O(n m)`; use [`crate::boolean`] for real work.
pub fn boolean_reference(
    a: &PolygonSet2,
    b: &PolygonSet2,
    op: BooleanOp,
) -> Result<(BooleanOutput, LevelData), BooleanError> {
    let start = Instant::now();
    let mut timings = Timings::default();
    validate(a, Operand::A)?;
    validate(b, Operand::B)?;
    timings.validate = ms(start);
    let clock = Instant::now();
    let mut data = level2_brute_force(a, b)?;
    timings.intersections = ms(clock);
    let clock = Instant::now();
    let shape = construct(a, b, op, &mut data)?;
    timings.construct = ms(clock);
    timings.total = ms(start);
    Ok((output(a, b, shape, &data, timings), data))
}
