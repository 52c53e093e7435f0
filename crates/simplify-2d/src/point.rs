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
    #[inline]
    fn hash<H: Hasher>(&self, state: &mut H) {
        // One word for both coordinates: y's halves swapped, so that the
        // high (sign, exponent, leading mantissa) bits of each coordinate
        // land in different halves and points on a grid (zero low mantissa
        // bits) stay distinct. Equal points give equal words; unequal ones
        // rarely do, and a collision costs only a probe (keys compare by
        // `==`).
        state.write_u64(self.x.to_bits() ^ self.y.to_bits().rotate_left(32));
    }
}

/// A small multiplicative hasher for point keys (one `u64` word, see the
/// `Hash` of [`Pt`]): the sweep's point maps are on the hot path and need
/// no DoS resistance.
#[derive(Default)]
pub(crate) struct PointHasher(u64);

impl Hasher for PointHasher {
    #[inline]
    fn finish(&self) -> u64 {
        // A folded multiply (the high and low words of the 128-bit product
        // xored): every input bit reaches the low bits, from which
        // hashbrown picks buckets, and the high bits, from which it takes
        // its tags. Coordinates on a grid (integers, halves) have all-zero
        // low mantissa bits, which a plain multiply would keep zero (the
        // checkerboard bench once ran 9x slower for that).
        let m = u128::from(self.0 ^ 0x2d35_8dcc_aa6c_78a5) * u128::from(0x8bb8_4b93_962e_acc9u64);
        (m as u64) ^ ((m >> 64) as u64)
    }
    #[inline]
    fn write(&mut self, bytes: &[u8]) {
        for &b in bytes {
            self.write_u64(u64::from(b));
        }
    }
    #[inline]
    fn write_u64(&mut self, v: u64) {
        self.0 = self.0.rotate_left(5) ^ v;
    }
}

/// A hash map keyed by sweep points.
pub(crate) type PointMap<V> = HashMap<Pt, V, BuildHasherDefault<PointHasher>>;

#[cfg(test)]
mod tests {
    use super::*;
    use std::hash::BuildHasher;

    fn hash(p: Pt) -> u64 {
        BuildHasherDefault::<PointHasher>::default().hash_one(p)
    }

    /// Points on grids (all-zero low mantissa bits) and random points
    /// spread over the low bits (hashbrown's bucket index) and the top
    /// seven bits (its tags), and a map keyed by them agrees with a
    /// `BTreeMap` through inserts, updates and removals.
    #[test]
    fn hashes_spread_and_the_map_matches_an_ordered_map() {
        let mut g = test_support::rng::Xorshift64::new(0x005E_ED0F_9013_7501);
        let grids: [Vec<Pt>; 3] = [
            (0..4096)
                .map(|i| Pt::new([f64::from(i % 64), f64::from(i / 64)]))
                .collect(),
            (0..4096)
                .map(|i| Pt::new([f64::from(i % 64) * 0.5, -f64::from(i / 64) * 0.5]))
                .collect(),
            (0..4096)
                .map(|_| Pt::new([g.below(1 << 40) as f64 / 7.0, g.below(1 << 40) as f64 / 3.0]))
                .collect(),
        ];
        for pts in &grids {
            let low: std::collections::HashSet<u64> = pts.iter().map(|&p| hash(p) & 1023).collect();
            let top: std::collections::HashSet<u64> = pts.iter().map(|&p| hash(p) >> 57).collect();
            assert!(low.len() > 900, "{} of 1024 low buckets", low.len());
            assert!(top.len() > 120, "{} of 128 tags", top.len());
            let mut map: PointMap<u32> = PointMap::default();
            let mut oracle = std::collections::BTreeMap::new();
            for (i, &p) in pts.iter().enumerate() {
                let q = pts[g.below(pts.len() as u64) as usize];
                match i % 3 {
                    0 | 1 => {
                        *map.entry(p).or_insert(0) += i as u32;
                        *oracle.entry(p).or_insert(0) += i as u32;
                    }
                    _ => assert_eq!(map.remove(&q), oracle.remove(&q)),
                }
                assert_eq!(map.get(&q), oracle.get(&q));
            }
            assert_eq!(map.len(), oracle.len());
        }
        // Equal points hash equally, `-0.0` included (normalised).
        assert_eq!(hash(Pt::new([-0.0, 1.0])), hash(Pt::new([0.0, 1.0])));
    }
}
