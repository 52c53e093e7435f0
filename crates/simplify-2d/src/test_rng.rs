//! A small xorshift generator for the unit tests' random operation
//! sequences, so that every case is reproducible.

/// A generator, seeded with `seed`, of values in `0..n` for each call with
/// `n` (`0` when `n` is 0).
pub(crate) fn below(seed: u64) -> impl FnMut(u64) -> u64 {
    let mut s = seed;
    move |n| {
        s ^= s << 13;
        s ^= s >> 7;
        s ^= s << 17;
        s % n.max(1)
    }
}
