//! Which sides of a box each vertex lies beyond: one byte per vertex,
//! from which whether a facet's bounding box meets the box follows
//! exactly without gathering the facet's positions. The near-focus
//! inspections here and smoothing's region search pass over every facet
//! of a large mesh to find the few near a small box; with the codes most
//! facets are rejected by three byte loads from a table that stays in
//! cache, instead of three 24-byte positions from all over the vertex
//! array.

use rayon::prelude::*;
use robust_arith::Point3;

/// The codes of the vertices of `vertices` against a closed box
/// `bounds = [lo, hi]`: bit `2 k` set when a vertex lies below `lo[k]`,
/// bit `2 k + 1` when it lies above `hi[k]` (a NaN coordinate sets
/// neither: callers check finiteness first).
///
/// ```
/// use topology::{facet_apart, sides_beyond};
/// let v = [[0.0, 0.0, 0.0], [4.0, 0.0, 0.0], [0.0, 4.0, 0.0], [5.0, 5.0, 0.0]];
/// let codes = sides_beyond(&v, &[[3.0, 3.0, -1.0], [6.0, 6.0, 1.0]]);
/// assert!(facet_apart(&codes, [0, 1])); // both corners below y = 3
/// assert!(!facet_apart(&codes, [0, 1, 2])); // their box [0, 4]^2 meets [3, 6]^2
/// assert!(!facet_apart(&codes, [3]));
/// assert!(!facet_apart(&codes, [0, 99])); // no code for 99: not apart
/// ```
pub fn sides_beyond(vertices: &[Point3], bounds: &[Point3; 2]) -> Vec<u8> {
    let [lo, hi] = bounds;
    vertices
        .par_iter()
        .map(|p| {
            (0..3).fold(0u8, |code, k| {
                code | (u8::from(p[k] < lo[k]) << (2 * k)) | (u8::from(p[k] > hi[k]) << (2 * k + 1))
            })
        })
        .collect()
}

/// Whether the bounding box of the vertices `corners` (codes from
/// [`sides_beyond`]) lies apart from the box: some side has every corner
/// beyond it. Exactly the negation of closed-box overlap (the box of the
/// corners starts above `hi[k]` exactly when every corner lies above it);
/// a facet without corners has an empty box, apart from everything. A
/// corner without a code (an index past `codes`) counts as inside every
/// side, so such a facet is never called apart.
pub fn facet_apart(codes: &[u8], corners: impl IntoIterator<Item = u32>) -> bool {
    corners.into_iter().fold(0b11_1111u8, |all, v| {
        all & codes.get(v as usize).copied().unwrap_or(0)
    }) != 0
}

#[cfg(test)]
mod tests {
    use super::*;
    use test_support::rng::SplitMix64;

    /// Against the closed-box overlap of the corners' box, on random
    /// facets over a coarse grid (ties on the box's sides are common).
    #[test]
    fn apart_is_the_negation_of_box_overlap() {
        let mut rng = SplitMix64::new(11);
        let coord = |rng: &mut SplitMix64| (rng.unit() * 8.0).floor() - 2.0;
        for _ in 0..200 {
            let vertices: Vec<Point3> = (0..30)
                .map(|_| std::array::from_fn(|_| coord(&mut rng)))
                .collect();
            let a: Point3 = std::array::from_fn(|_| coord(&mut rng));
            let b: Point3 = std::array::from_fn(|_| coord(&mut rng));
            let bounds = [
                std::array::from_fn(|k| a[k].min(b[k])),
                std::array::from_fn(|k| a[k].max(b[k])),
            ];
            let codes = sides_beyond(&vertices, &bounds);
            for _ in 0..50 {
                let n = (rng.unit() * 5.0) as usize;
                let corners: Vec<u32> = (0..n).map(|_| (rng.unit() * 30.0) as u32).collect();
                let meets = !corners.is_empty()
                    && (0..3).all(|k| {
                        let lo = corners
                            .iter()
                            .map(|&v| vertices[v as usize][k])
                            .fold(f64::INFINITY, f64::min);
                        let hi = corners
                            .iter()
                            .map(|&v| vertices[v as usize][k])
                            .fold(f64::NEG_INFINITY, f64::max);
                        lo <= bounds[1][k] && bounds[0][k] <= hi
                    });
                assert_eq!(facet_apart(&codes, corners.iter().copied()), !meets);
            }
        }
    }
}
