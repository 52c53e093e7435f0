//! Seeded pseudo-random generators for reproducible test data, with no
//! `rand` dependency. Four algorithms, each kept bit for bit as the copy it
//! replaced used it, so every seeded corpus and test case is unchanged:
//!
//! - [`SplitMix64`] (Steele, Lea and Flood): the generator of `cargo xtask`
//!   corpora, the benches' inputs and the section 8.3 experiment;
//! - [`Xorshift64`] (Marsaglia's 13/7/17 triple): the unit tests' small
//!   random cases;
//! - [`Xorshift64Star`] (Vigna's xorshift64*, seed mixed by the golden
//!   ratio): the simplification tests' section 7.7 polygons;
//! - [`Lcg64`] (a 64-bit LCG with a PCG-style output mix): the 3D Boolean
//!   tests' random solids.
//!
//! Statistical quality is ample for test data; none of them is for
//! cryptography.

/// `2^-53`: the step of the uniform `[0, 1)` grid built from 53 bits.
const UNIT: f64 = 1.0 / 9_007_199_254_740_992.0;

/// The top 53 bits of `bits` as a uniform f64 in `[0, 1)`.
fn unit_of(bits: u64) -> f64 {
    (bits >> 11) as f64 * UNIT
}

/// SplitMix64: 64 bits of state, full period.
#[derive(Clone, Debug)]
pub struct SplitMix64(u64);

impl SplitMix64 {
    /// A generator from a seed (the seed is the initial state).
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
        unit_of(self.next_u64())
    }

    /// A uniformly distributed f64 in `[-1, 1]` with full precision at every
    /// scale: 64 random bits scaled by `2^-64` (rounded to nearest), and a
    /// random sign (the input of the section 8.3 experiment).
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

/// Marsaglia's xorshift64 with the shift triple (13, 7, 17). The state
/// must not be 0 (it would stay 0).
#[derive(Clone, Debug)]
pub struct Xorshift64(u64);

impl Xorshift64 {
    /// A generator whose initial state is `seed` (not 0).
    pub fn new(seed: u64) -> Self {
        Xorshift64(seed)
    }

    /// The next state, which is also the output.
    pub fn next_u64(&mut self) -> u64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        self.0
    }

    /// The next output reduced modulo `n` (a value in `0..n`; 0 when `n`
    /// is 0).
    pub fn below(&mut self, n: u64) -> u64 {
        self.next_u64() % n.max(1)
    }
}

/// Vigna's xorshift64*: an xorshift (12, 25, 27) state and a multiplied
/// output; the seed is mixed by the golden ratio and made odd.
#[derive(Clone, Debug)]
pub struct Xorshift64Star(u64);

impl Xorshift64Star {
    /// A generator from any seed.
    pub fn new(seed: u64) -> Self {
        Xorshift64Star(seed.wrapping_mul(0x9E37_79B9_7F4A_7C15) | 1)
    }

    /// The next 64 random bits.
    pub fn next_u64(&mut self) -> u64 {
        let mut x = self.0;
        x ^= x >> 12;
        x ^= x << 25;
        x ^= x >> 27;
        self.0 = x;
        x.wrapping_mul(0x2545_F491_4F6C_DD1D)
    }

    /// A uniform f64 in `[0, 1)`.
    pub fn unit(&mut self) -> f64 {
        unit_of(self.next_u64())
    }

    /// A uniform random point in the unit disc (rejection from the square).
    pub fn in_disc(&mut self) -> [f64; 2] {
        loop {
            let x = 2.0 * self.unit() - 1.0;
            let y = 2.0 * self.unit() - 1.0;
            if x * x + y * y <= 1.0 {
                return [x, y];
            }
        }
    }
}

/// A 64-bit linear congruential generator (Knuth's MMIX constants) with a
/// PCG-style xor-shift-multiply output.
#[derive(Clone, Debug)]
pub struct Lcg64(u64);

impl Lcg64 {
    /// A generator whose initial state is `seed`.
    pub fn new(seed: u64) -> Self {
        Lcg64(seed)
    }

    /// The next 64 random bits.
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self
            .0
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        let x = self.0;
        (x ^ (x >> 33)).wrapping_mul(0xff51_afd7_ed55_8ccd) ^ (x >> 29)
    }

    /// A uniform f64 in `[0, 1)`.
    pub fn unit(&mut self) -> f64 {
        unit_of(self.next_u64())
    }

    /// A uniform f64 in `[lo, hi)`.
    pub fn uniform(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.unit()
    }

    /// The next output modulo `n` (a value in `0..n`; 0 when `n` is 0).
    pub fn below(&mut self, n: u64) -> u64 {
        self.next_u64() % n.max(1)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The first outputs of each generator, as the replaced copies produced
    /// them (written out from the algorithms' definitions), so a change to
    /// any of them fails here before it silently changes a corpus.
    #[test]
    fn sequences_are_pinned() {
        // SplitMix64 from 0: the published reference values.
        let mut s = SplitMix64::new(0);
        assert_eq!(s.next_u64(), 0xe220_a839_7b1d_cdaf);
        assert_eq!(s.next_u64(), 0x6e78_9e6a_a1b9_65f4);
        assert_eq!(s.next_u64(), 0x06c4_5d18_8009_454f);

        // xorshift64 from 1: 1 ^ 1 << 13 = 0x2001; ^ >> 7 = 0x2041;
        // ^ << 17 = 0x4082_2041.
        let mut x = Xorshift64::new(1);
        assert_eq!(x.next_u64(), 0x4082_2041);

        // Every generator is a pure function of its seed.
        let a: Vec<u64> = {
            let mut g = Lcg64::new(7);
            (0..8).map(|_| g.next_u64()).collect()
        };
        let b: Vec<u64> = {
            let mut g = Lcg64::new(7);
            (0..8).map(|_| g.next_u64()).collect()
        };
        assert_eq!(a, b);
        let mut g = Xorshift64Star::new(0);
        assert_eq!(g.0, 1);
        let first = g.next_u64();
        let mut h = 1u64;
        h ^= h >> 12;
        h ^= h << 25;
        h ^= h >> 27;
        assert_eq!(first, h.wrapping_mul(0x2545_F491_4F6C_DD1D));
    }

    #[test]
    fn ranges_hold() {
        let mut s = SplitMix64::new(42);
        let mut l = Lcg64::new(42);
        let mut x = Xorshift64::new(42);
        let mut t = Xorshift64Star::new(42);
        for _ in 0..10_000 {
            let r = s.range(-3, 5);
            assert!((-3..=5).contains(&r));
            let u = s.unit();
            assert!((0.0..1.0).contains(&u));
            assert!((-1.0..=1.0).contains(&s.pm1()));
            let m = s.magnitude(-4, 4).abs();
            assert!((2f64.powi(-4)..2f64.powi(5)).contains(&m));
            assert!((2.0..3.0).contains(&l.uniform(2.0, 3.0)));
            assert!(l.below(7) < 7);
            assert!(x.below(9) < 9);
            let [px, py] = t.in_disc();
            assert!(px * px + py * py <= 1.0);
        }
        assert_eq!(x.below(0), 0);
    }
}
