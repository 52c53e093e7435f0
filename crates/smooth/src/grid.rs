//! Vertex adjustment of Appendix A on a spatial hash grid: vertices are
//! taken in index order; a vertex within `delta` of an already accepted
//! vertex is merged into the earliest such vertex (and takes its
//! position), otherwise it is accepted. Never all pairs: each vertex looks
//! only at the accepted vertices of the grid cells around it that a point
//! within `delta` can lie in (at most 3^N, usually 2^N). The cells are keyed
//! in a hash map with the Fx hash (integer keys, no adversary: the keys are
//! cell coordinates).

use rustc_hash::FxHashMap;

/// The end of a cell's list.
const NONE: u32 = u32::MAX;

/// The outcome of [`merge_vertices`].
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct VertexMerge {
    /// For every input vertex, the accepted vertex it became (itself when
    /// accepted). Always `representative[representative[i]] ==
    /// representative[i]` and `representative[i] <= i`.
    pub representative: Vec<u32>,
    /// The number of vertices merged into another.
    pub merged: u64,
}

/// The cell size for `tolerance` over points bounded by `max_abs`: at
/// least `2 * tolerance`, and at least `max_abs * 2^-48`, so that cell
/// coordinates stay below 2^49 and the rounding of `x / cell` never moves
/// two points within `tolerance` more than one cell apart.
fn cell_size(tolerance: f64, max_abs: f64) -> f64 {
    let floor = max_abs * (1.0 / 281_474_976_710_656.0); // 2^-48
    let s = (2.0 * tolerance).max(floor);
    if s > 0.0 && s.is_finite() {
        s
    } else {
        f64::MIN_POSITIVE
    }
}

fn cell_of<const N: usize>(p: &[f64; N], size: f64) -> [i64; N] {
    // `as` saturates, and every coordinate is below 2^49 cells by the
    // choice of `size`, so no two distinct cells collide by saturation.
    p.map(|x| (x / size).floor() as i64)
}

fn within<const N: usize>(a: &[f64; N], b: &[f64; N], tol_sq: f64) -> bool {
    let mut d = 0.0;
    for k in 0..N {
        let t = a[k] - b[k];
        d += t * t;
    }
    d <= tol_sq
}

/// The cell offsets (per axis, within `-1..=1`) where a point within
/// `reach` cells of `p` can lie: the neighbour below only when `p` is near
/// its cell's lower face, above only near its upper face. The margin
/// covers the rounding of `x / size` for both points (`|x / size| <
/// 2^49`, so an error of at most `(|x / size| + 2) 2^-52` each) and of
/// the fraction, so no candidate that the full `3^N` scan would see is
/// left out.
fn neighbour_range<const N: usize>(
    p: &[f64; N],
    c: &[i64; N],
    size: f64,
    reach: f64,
) -> ([i64; N], [i64; N]) {
    let mut lo = [0i64; N];
    let mut hi = [0i64; N];
    for k in 0..N {
        let q = p[k] / size;
        let f = q - c[k] as f64;
        let margin = (q.abs() + 2.0) * (1.0 / 1_125_899_906_842_624.0) + 1e-6; // 2^-50
        if f < reach + margin {
            lo[k] = -1;
        }
        if f > 1.0 - reach - margin {
            hi[k] = 1;
        }
    }
    (lo, hi)
}

/// Merges the points within `tolerance` of an earlier accepted point
/// (Appendix A, "vertex adjustment"). With `tolerance == 0` only exactly
/// coincident points merge (`-0.0 == 0.0`). Points must be finite (the
/// callers validate coordinates first).
///
/// ```
/// let pts = [[0.0, 0.0], [1e-7, 0.0], [1.0, 0.0], [1.0, 5e-7]];
/// let m = smooth::merge_vertices(&pts, 1e-6);
/// assert_eq!(m.representative, vec![0, 0, 2, 2]);
/// assert_eq!(m.merged, 2);
/// ```
pub fn merge_vertices<const N: usize>(points: &[[f64; N]], tolerance: f64) -> VertexMerge {
    let max_abs = points
        .iter()
        .flat_map(|p| p.iter())
        .fold(0.0f64, |m, x| m.max(x.abs()));
    let size = cell_size(tolerance, max_abs);
    let tol_sq = tolerance * tolerance;
    // The tolerance in cells (at most 0.5 by the choice of `size`).
    let reach = tolerance / size;
    // Each cell's accepted points as a linked list: the cell maps to its
    // latest point, `next` to the one before (no allocation per cell).
    let mut cells: FxHashMap<[i64; N], u32> = FxHashMap::default();
    cells.reserve(points.len());
    let mut next: Vec<u32> = vec![NONE; points.len()];
    let mut representative = Vec::with_capacity(points.len());
    let mut merged = 0;
    for (i, p) in points.iter().enumerate() {
        let c = cell_of(p, size);
        let (lo, hi) = neighbour_range(p, &c, size, reach);
        let mut best: Option<u32> = None;
        for offset in 0..3usize.pow(N as u32) {
            let mut key = c;
            let mut o = offset;
            let mut skip = false;
            for k in 0..N {
                let d = (o % 3) as i64 - 1;
                o /= 3;
                skip |= d < lo[k] || d > hi[k];
                key[k] = key[k].saturating_add(d);
            }
            if skip {
                continue;
            }
            let mut j = cells.get(&key).copied().unwrap_or(NONE);
            while j != NONE {
                if best.is_none_or(|b| j < b) && within(p, &points[j as usize], tol_sq) {
                    best = Some(j);
                }
                j = next[j as usize];
            }
        }
        match best {
            Some(j) => {
                representative.push(j);
                merged += 1;
            }
            None => {
                let i = i as u32;
                representative.push(i);
                if let Some(prev) = cells.insert(c, i) {
                    next[i as usize] = prev;
                }
            }
        }
    }
    VertexMerge {
        representative,
        merged,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    /// The definition of Appendix A evaluated over all pairs: the oracle.
    fn merge_all_pairs<const N: usize>(points: &[[f64; N]], tol: f64) -> Vec<u32> {
        let mut accepted: Vec<u32> = Vec::new();
        let mut rep = Vec::new();
        for (i, p) in points.iter().enumerate() {
            match accepted
                .iter()
                .find(|&&j| within(p, &points[j as usize], tol * tol))
            {
                Some(&j) => rep.push(j),
                None => {
                    accepted.push(i as u32);
                    rep.push(i as u32);
                }
            }
        }
        rep
    }

    #[test]
    fn zero_tolerance_merges_exact_duplicates_only() {
        let pts = [
            [0.0, -0.0, 1.0],
            [-0.0, 0.0, 1.0],
            [0.0, 0.0, 1.0 + f64::EPSILON],
        ];
        let m = merge_vertices(&pts, 0.0);
        assert_eq!(m.representative, vec![0, 0, 2]);
        assert_eq!(m.merged, 1);
    }

    #[test]
    fn chains_do_not_merge_transitively() {
        // 0 is accepted; 1 is within tol of 0; 2 is within tol of 1 but
        // not of 0 and 1 is not accepted, so 2 is accepted.
        let pts = [[0.0], [0.9], [1.8]];
        assert_eq!(merge_vertices(&pts, 1.0).representative, vec![0, 0, 2]);
    }

    #[test]
    fn huge_coordinates_with_tiny_tolerance() {
        let big = 1e300;
        let pts = [[big, -big], [big, -big], [-big, big], [0.0, 0.0]];
        let m = merge_vertices(&pts, 1e-300);
        assert_eq!(m.representative, vec![0, 0, 2, 3]);
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(test_support::cases(256)))]

        #[test]
        fn grid_equals_all_pairs_definition(
            pts in prop::collection::vec(prop::array::uniform3(-4i32..4), 0..60),
            scale in prop::sample::select(vec![1e-9, 0.25, 1.0, 1e6, 1e150]),
            tol in prop::sample::select(vec![0.0, 0.3, 0.5, 1.0, 1.5]),
        ) {
            let p: Vec<[f64; 3]> = pts
                .iter()
                .map(|q| q.map(|x| f64::from(x) * scale / 2.0))
                .collect();
            let m = merge_vertices(&p, tol * scale);
            prop_assert_eq!(&m.representative, &merge_all_pairs(&p, tol * scale));
            let merged = m.representative.iter().enumerate().filter(|(i, &r)| r as usize != *i).count();
            prop_assert_eq!(m.merged, merged as u64);
        }
    }
}
