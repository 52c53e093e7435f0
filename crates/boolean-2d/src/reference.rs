//! The reference evaluation of level 2: every function of Table 4.1
//! evaluated for every pair, with no broad phase. Quadratic, and the oracle
//! the fast path is tested against.

use crate::error::BooleanError;
use crate::level_data::LevelData;
use shadow_1d::{s01, s10};
use shadow_2d::x11;
use topology::PolygonSet2;

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
