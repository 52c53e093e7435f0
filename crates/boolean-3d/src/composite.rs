//! Composite edges (level 4, section 4.6): start- and end-vertices from net
//! end-vertex counts, paired along the edge direction (eq. 4.14-4.16).

use robust_arith::Point3;
use smallvec::SmallVec;

/// A composite edge under construction. Assigning a vertex a net
/// end-vertex count `n` (section 4.6) enters it `n` times as an end-vertex
/// when `n > 0` and `-n` times as a start-vertex when `n < 0`.
#[derive(Clone, Debug, Default)]
pub struct CompositeEdge3 {
    /// Start-vertices: `(output vertex id, position)`.
    pub starts: SmallVec<[(u32, Point3); 4]>,
    /// End-vertices: `(output vertex id, position)`.
    pub ends: SmallVec<[(u32, Point3); 4]>,
}

impl CompositeEdge3 {
    /// Assigns vertex `id` at `pos` a net end-vertex count `n`.
    #[inline]
    pub fn assign(&mut self, id: u32, pos: Point3, n: i32) {
        let list = if n > 0 {
            &mut self.ends
        } else {
            &mut self.starts
        };
        for _ in 0..n.unsigned_abs() {
            list.push((id, pos));
        }
    }

    /// Clears the edge, keeping its storage.
    #[inline]
    pub fn clear(&mut self) {
        self.starts.clear();
        self.ends.clear();
    }

    /// Theorem 2: as many start-vertices as end-vertices.
    #[inline]
    pub fn is_balanced(&self) -> bool {
        self.starts.len() == self.ends.len()
    }

    /// Breaks the composite edge into single-segment edges `(start, end)`
    /// appended to `out`: both lists are ordered along
    /// `v = sum x_e - sum x_s` (eq. 4.14) so that `(x_{i+1} - x_i) . v >= 0`
    /// (eq. 4.15-4.16) and paired in order. Any pairing keeps topology;
    /// this one keeps geometry when the vertices alternate along a line.
    /// The sort is stable, so ties keep the order of assignment and the
    /// result is deterministic.
    ///
    /// Returns `false` (appending nothing) when the counts differ, which
    /// Theorem 2 rules out.
    pub fn pair_into(&mut self, out: &mut Vec<(u32, u32)>) -> bool {
        if !self.is_balanced() {
            return false;
        }
        if self.starts.len() == 1 {
            out.push((self.starts[0].0, self.ends[0].0));
            return true;
        }
        if self.starts.is_empty() {
            return true;
        }
        // eq. 4.14
        let mut v = [0.0f64; 3];
        for (_, p) in &self.ends {
            for c in 0..3 {
                v[c] += p[c];
            }
        }
        for (_, p) in &self.starts {
            for c in 0..3 {
                v[c] -= p[c];
            }
        }
        let key = |p: &Point3| p[0] * v[0] + p[1] * v[1] + p[2] * v[2];
        // eq. 4.15-4.16
        self.starts.sort_by(|a, b| key(&a.1).total_cmp(&key(&b.1)));
        self.ends.sort_by(|a, b| key(&a.1).total_cmp(&key(&b.1)));
        out.extend(
            self.starts
                .iter()
                .zip(self.ends.iter())
                .map(|(s, e)| (s.0, e.0)),
        );
        true
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn alternating_vertices_pair_along_the_edge() {
        // Along x: start 0 at 0, end 1 at 1, start 2 at 2, end 3 at 3.
        let mut c = CompositeEdge3::default();
        c.assign(3, [3.0, 0.0, 0.0], 1);
        c.assign(0, [0.0, 0.0, 0.0], -1);
        c.assign(2, [2.0, 0.0, 0.0], -1);
        c.assign(1, [1.0, 0.0, 0.0], 1);
        let mut out = Vec::new();
        assert!(c.pair_into(&mut out));
        assert_eq!(out, vec![(0, 1), (2, 3)]);
    }

    #[test]
    fn unbalanced_is_refused_and_counts_above_one_repeat() {
        let mut c = CompositeEdge3::default();
        c.assign(7, [0.0; 3], 2);
        c.assign(8, [1.0; 3], -1);
        let mut out = Vec::new();
        assert!(!c.pair_into(&mut out));
        assert!(out.is_empty());
        c.assign(9, [2.0; 3], -1);
        assert!(c.pair_into(&mut out));
        assert_eq!(out.len(), 2);
    }
}
