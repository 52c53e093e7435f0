//! A tiny seeded pseudo-random generator (SplitMix64) for reproducible
//! experiment and verification corpora; no `rand` dependency needed.

/// SplitMix64 (Steele, Lea and Flood): 64 bits of state, full period,
/// good enough statistical quality for test-data generation.
#[derive(Clone, Debug)]
pub struct SplitMix64(u64);

impl SplitMix64 {
    /// A generator from a seed.
    pub fn new(seed: u64) -> Self {
        SplitMix64(seed)
    }

    /// A generator for stream `index` of a run seeded with `seed`: streams
    /// are independent, so parallel chunks give the same data whatever the
    /// thread count.
    pub fn stream(seed: u64, index: u64) -> Self {
        let mut g = SplitMix64(seed ^ index.wrapping_mul(0xd1b5_4a32_d192_ed03));
        g.next_u64();
        g
    }

    /// The next 64 random bits.
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    /// A uniform integer in `[lo, hi]` (slightly biased for huge ranges,
    /// which test data does not care about).
    pub fn range(&mut self, lo: i64, hi: i64) -> i64 {
        let span = (hi - lo + 1) as u64;
        lo + (self.next_u64() % span) as i64
    }

    /// A uniform f64 in `[0, 1)` on the grid of `2^-53`.
    pub fn unit(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 * (1.0 / 9_007_199_254_740_992.0)
    }

    /// A uniformly distributed f64 in `[-1, 1]` with full precision at every
    /// scale: 64 random bits scaled by `2^-64` (rounded to nearest), and a
    /// random sign. This is the input of the section 8.3 experiment.
    pub fn pm1(&mut self) -> f64 {
        let v = self.next_u64() as f64 * (1.0 / 18_446_744_073_709_551_616.0);
        if self.next_u64() & 1 == 1 {
            -v
        } else {
            v
        }
    }

    /// A value of random sign, random 52-bit mantissa and binary exponent in
    /// `[lo, hi]` (garbage data of mixed magnitude).
    pub fn magnitude(&mut self, lo: i32, hi: i32) -> f64 {
        let m = 1.0 + (self.next_u64() >> 12) as f64 / 4_503_599_627_370_496.0;
        let e = self.range(i64::from(lo), i64::from(hi)) as i32;
        let v = m * 2f64.powi(e);
        if self.next_u64() & 1 == 1 {
            -v
        } else {
            v
        }
    }
}
