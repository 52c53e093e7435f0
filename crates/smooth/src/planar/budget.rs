//! The safety budget of one smoothing run: adjustments are charged to it,
//! and once it is spent the tolerance operations stop (the shape stays
//! valid; the report says the budget was hit).

/// What is left of the budget.
#[derive(Clone, Copy, Debug)]
pub struct Budget {
    left: u64,
    hit: bool,
}

impl Budget {
    /// A budget of `total` adjustments.
    pub fn new(total: u64) -> Self {
        Budget {
            left: total,
            hit: false,
        }
    }

    /// Charges `n` adjustments; `false` (and the budget marked hit) when
    /// fewer than `n` were left.
    pub fn spend(&mut self, n: u64) -> bool {
        if self.left >= n {
            self.left -= n;
            true
        } else {
            self.left = 0;
            self.hit = true;
            false
        }
    }

    /// `true` once nothing is left (further adjustments are refused).
    pub fn exhausted(&self) -> bool {
        self.hit || self.left == 0
    }

    /// Whether an adjustment was ever refused.
    pub fn hit(&self) -> bool {
        self.hit
    }
}
