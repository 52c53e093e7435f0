//! The point key of the sweep: a 2D point with the lexicographic order of
//! section 7.1.2 as a total order, usable as a map key.

use robust_arith::{from_total_order_key, total_order_key};
use std::cmp::Ordering;
use std::hash::{Hash, Hasher};

/// A point ordered lexicographically (x first, then y). Constructed through
/// [`Pt::new`], which turns `-0.0` into `+0.0` so that the IEEE total order
/// used for comparison agrees with `==` on finite values. Coordinates are
/// validated finite before any `Pt` is built.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Pt {
    pub(crate) x: f64,
    pub(crate) y: f64,
}

impl Pt {
    /// A normalised point (`-0.0 + 0.0 == +0.0` in round-to-nearest).
    #[inline]
    pub(crate) fn new(p: [f64; 2]) -> Pt {
        Pt {
            x: p[0] + 0.0,
            y: p[1] + 0.0,
        }
    }

    /// The coordinates as an array.
    #[inline]
    pub(crate) fn arr(self) -> [f64; 2] {
        [self.x, self.y]
    }

    /// An integer key whose order is the lexicographic order of points
    /// (IEEE total order per coordinate, `robust_arith::total_order_key`),
    /// for sorting.
    #[inline]
    pub(crate) fn sort_key(self) -> u128 {
        (u128::from(total_order_key(self.x)) << 64) | u128::from(total_order_key(self.y))
    }

    /// The point whose [`Pt::sort_key`] is `key`.
    #[inline]
    pub(crate) fn from_sort_key(key: u128) -> Pt {
        Pt {
            x: from_total_order_key((key >> 64) as u64),
            y: from_total_order_key(key as u64),
        }
    }
}

impl PartialEq for Pt {
    #[inline]
    fn eq(&self, other: &Self) -> bool {
        // Equal in the total order exactly when the bit patterns are equal.
        self.x.to_bits() == other.x.to_bits() && self.y.to_bits() == other.y.to_bits()
    }
}

impl Eq for Pt {}

impl PartialOrd for Pt {
    #[inline]
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for Pt {
    #[inline]
    fn cmp(&self, other: &Self) -> Ordering {
        self.x
            .total_cmp(&other.x)
            .then_with(|| self.y.total_cmp(&other.y))
    }
}

impl Hash for Pt {
    fn hash<H: Hasher>(&self, state: &mut H) {
        self.x.to_bits().hash(state);
        self.y.to_bits().hash(state);
    }
}
