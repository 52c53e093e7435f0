//! The exact minimum-overlap triangulation of a small polygon (section
//! 4.8, step 5; figure 4.10 generalised): over all its triangulations by
//! internal edges, the one of least total absolute triangle area.

use super::{orient, P2};

/// The triangulation of a polygon (as positions in `poly`) of least total
/// absolute area, and twice that area, by the classic recurrence over
/// sub-polygons `i..=j` (every internal edge splits a polygon in two, so
/// these are all the triangulations by internal edges). Non-finite areas
/// (garbage coordinates) never win a comparison, so the result is always a
/// complete triangulation.
pub(super) fn min_overlap(poly: &[(u32, P2)]) -> (f64, Vec<[usize; 3]>) {
    let n = poly.len();
    let mut cost = vec![0.0f64; n * n];
    let mut split = vec![0u32; n * n];
    for len in 2..n {
        for i in 0..n - len {
            let j = i + len;
            let (mut best, mut arg) = (f64::INFINITY, i + 1);
            for k in i + 1..j {
                let c = cost[i * n + k]
                    + cost[k * n + j]
                    + orient(poly[i].1, poly[k].1, poly[j].1).abs();
                if c < best {
                    best = c;
                    arg = k;
                }
            }
            cost[i * n + j] = best;
            split[i * n + j] = arg as u32;
        }
    }
    let mut tris = Vec::with_capacity(n.saturating_sub(2));
    let mut stack = vec![(0, n - 1)];
    while let Some((i, j)) = stack.pop() {
        if j - i >= 2 {
            let k = split[i * n + j] as usize;
            tris.push([i, k, j]);
            stack.push((k, j));
            stack.push((i, k));
        }
    }
    (cost[n - 1], tris)
}
