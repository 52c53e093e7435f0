//! The point key of the sweep: a 2D point with the lexicographic order of
//! section 7.1.2 as a total order, usable as a map key.

use robust_arith::{from_total_order_key, total_order_key};
use std::cmp::Ordering;
use std::collections::HashMap;
use std::hash::{BuildHasherDefault, Hash, Hasher};

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
    /// for sorting. Two `u64` rather than one `u128`, whose 16-byte
    /// alignment would pad the heap and sort entries that carry it.
    #[inline]
    pub(crate) fn sort_key(self) -> SortKey {
        (total_order_key(self.x), total_order_key(self.y))
    }

    /// The point whose [`Pt::sort_key`] is `key`.
    #[inline]
    pub(crate) fn from_sort_key(key: SortKey) -> Pt {
        Pt {
            x: from_total_order_key(key.0),
            y: from_total_order_key(key.1),
        }
    }
}

/// [`Pt::sort_key`]: compared lexicographically, x's key first.
pub(crate) type SortKey = (u64, u64);

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
        // Coordinates are finite and never `-0.0` (see [`Pt::new`]), where
        // the IEEE total order is the plain `<` of floating point, which
        // costs one comparison instead of two bit transformations.
        if self.x < other.x {
            Ordering::Less
        } else if self.x > other.x {
            Ordering::Greater
        } else if self.y < other.y {
            Ordering::Less
        } else if self.y > other.y {
            Ordering::Greater
        } else {
            Ordering::Equal
        }
    }
}

impl Hash for Pt {
    fn hash<H: Hasher>(&self, state: &mut H) {
        self.x.to_bits().hash(state);
        self.y.to_bits().hash(state);
    }
}

/// A small multiplicative hasher for point keys (two `u64` bit patterns):
/// the sweep's point maps are on the hot path and need no DoS resistance.
#[derive(Default)]
pub(crate) struct PointHasher(u64);

impl Hasher for PointHasher {
    #[inline]
    fn finish(&self) -> u64 {
        // The murmur3 finalizer: coordinates on a grid (integers, halves)
        // have all-zero low mantissa bits, and the multiply below keeps
        // them zero; hashbrown picks buckets by the low bits, so without
        // this every grid point collided (the checkerboard bench ran 9x
        // slower than it should).
        let mut h = self.0;
        h ^= h >> 33;
        h = h.wrapping_mul(0xff51_afd7_ed55_8ccd);
        h ^= h >> 33;
        h = h.wrapping_mul(0xc4ce_b9fe_1a85_ec53);
        h ^ (h >> 33)
    }
    #[inline]
    fn write(&mut self, bytes: &[u8]) {
        for &b in bytes {
            self.write_u64(u64::from(b));
        }
    }
    #[inline]
    fn write_u64(&mut self, v: u64) {
        self.0 = (self.0.rotate_left(5) ^ v).wrapping_mul(0x51_7c_c1_b7_27_22_0a_95);
    }
}

/// A hash map keyed by sweep points.
pub(crate) type PointMap<V> = HashMap<Pt, V, BuildHasherDefault<PointHasher>>;
