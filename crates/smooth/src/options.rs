//! The parameters of one smoothing run.

use crate::SmoothError;

/// How a shape is smoothed.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SmoothOptions {
    /// The length tolerance `delta` of Appendix A: vertices within `delta`
    /// merge, edges passing within `delta` of a vertex or of each other
    /// crack, opposing facets within `delta` of each other's plane cancel.
    /// Zero keeps only the exact operations (coincident vertices,
    /// zero-length edges, opposing half-edges and facets).
    pub tolerance: f64,
    /// The safety net: the most adjustments one run may make. The process
    /// terminates by design (see the crate's algorithm note); hitting the
    /// budget stops it early with a valid shape and is reported in
    /// [`crate::SmoothReport::budget_hit`]. `None` derives it from the
    /// input size: `1000 * (vertices + half-edges) + 1_000_000`.
    pub budget: Option<u64>,
    /// Keep the input where smoothing would make a 3D mesh worse: after
    /// smoothing, the facets it changed (by position, and at positions
    /// whose vertex count changed) are checked for intersecting facet
    /// pairs (the exact test of `topology`), non-manifold edges and
    /// vertices, and open edges, place by place (patches of changed
    /// facets); where the result has more pairs than the input at the
    /// same place, or as many and more of the others
    /// ([`crate::MeshDefects::worse_than`]), the input's facets are put
    /// back there, or the input is returned unchanged, and
    /// [`crate::SmoothReport::reverted`] says what smoothing would have
    /// left. Smoothing is not guaranteed to keep a clean result clean
    /// where surfaces lie within the tolerance of each other at an angle
    /// (near-coincident rotated copies); the guard keeps such places as
    /// the Boolean made them. Off by default: the algorithm's
    /// postconditions ([`crate::sanity_check_mesh`]) hold for an
    /// unguarded result, not where the input was put back. 2D smoothing
    /// ignores it.
    pub guard: bool,
}

impl SmoothOptions {
    /// Options with the given tolerance and the default budget.
    pub fn new(tolerance: f64) -> Self {
        SmoothOptions {
            tolerance,
            budget: None,
            guard: false,
        }
    }

    /// The same options with [`SmoothOptions::guard`] on.
    ///
    /// ```
    /// let o = smooth::SmoothOptions::new(1e-9).guarded();
    /// assert!(o.guard && o.tolerance == 1e-9);
    /// ```
    pub fn guarded(self) -> Self {
        SmoothOptions {
            guard: true,
            ..self
        }
    }

    /// Checks the tolerance: finite and not negative.
    pub fn validate(&self) -> Result<(), SmoothError> {
        if self.tolerance.is_finite() && self.tolerance >= 0.0 {
            Ok(())
        } else {
            Err(SmoothError::InvalidTolerance(self.tolerance))
        }
    }

    /// The budget for an input of `vertices` vertices and `half_edges`
    /// half-edges (or directed edges, in 2D).
    pub fn budget_for(&self, vertices: usize, half_edges: usize) -> u64 {
        self.budget.unwrap_or_else(|| {
            let n = (vertices as u64).saturating_add(half_edges as u64);
            n.saturating_mul(1000).saturating_add(1_000_000)
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bad_tolerances_are_refused() {
        for t in [f64::NAN, f64::INFINITY, -1e-12, f64::NEG_INFINITY] {
            assert!(matches!(
                SmoothOptions::new(t).validate(),
                Err(SmoothError::InvalidTolerance(_))
            ));
        }
        assert!(SmoothOptions::new(0.0).validate().is_ok());
        assert!(SmoothOptions::new(1e-5).validate().is_ok());
    }

    #[test]
    fn default_budget_grows_with_size_and_saturates() {
        let o = SmoothOptions::new(1e-6);
        assert_eq!(o.budget_for(0, 0), 1_000_000);
        assert_eq!(o.budget_for(10, 20), 1_030_000);
        assert_eq!(o.budget_for(usize::MAX, usize::MAX), u64::MAX);
        let fixed = SmoothOptions {
            budget: Some(7),
            ..o
        };
        assert_eq!(fixed.budget_for(10, 20), 7);
    }
}
