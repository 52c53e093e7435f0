//! Collecting the two interpolation partners of eq. 4.2-4.6.

use robust_arith::interpolate_pair;
use shadow_1d::Hit;

/// Accumulates lower-level hits and keeps, for the shadow coordinate
/// `level`, the closest pair where B shadows A (`Delta_+ >= 0`, the smallest)
/// and the closest where A shadows B (`Delta_- < 0`, the largest).
#[derive(Clone, Copy, Debug)]
pub struct Partners<const N: usize> {
    level: usize,
    plus: Option<(f64, Hit<N>)>,
    minus: Option<(f64, Hit<N>)>,
}

impl<const N: usize> Partners<N> {
    /// No partners yet; `level` is the coordinate the shadows compare
    /// (1 for level-1 hits, 2 for level-2 hits).
    #[inline]
    pub fn new(level: usize) -> Self {
        Partners {
            level,
            plus: None,
            minus: None,
        }
    }

    /// Offers a lower-level hit; returns its shadow value (eq. 4.1).
    #[inline]
    pub fn offer(&mut self, hit: Hit<N>) -> i32 {
        let d = hit.delta(self.level);
        if d >= 0.0 {
            if self.plus.is_none_or(|(best, _)| d < best) {
                self.plus = Some((d, hit));
            }
            hit.value
        } else {
            if self.minus.is_none_or(|(best, _)| d > best) {
                self.minus = Some((d, hit));
            }
            0
        }
    }

    /// The interpolated pair (eq. 4.2-4.6) at this level, or `None` when a
    /// partner of either type is missing.
    #[inline]
    pub fn interpolate(&self) -> Option<([f64; N], [f64; N])> {
        let (_, p) = self.plus?;
        let (_, m) = self.minus?;
        Some(interpolate_pair(self.level, p.a, p.b, m.a, m.b))
    }
}
