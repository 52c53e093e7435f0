//! Coordinate strategies for property tests (feature `proptest`): the
//! input generators the level tests share, each exactly as the copies it
//! replaced composed it, so the same proptest seed gives the same cases.

use proptest::prelude::*;

/// Random floats in `[-1, 1]` with full precision at every scale: 64
/// random bits scaled by `2^-64`, and a random sign.
pub fn float_coord() -> BoxedStrategy<f64> {
    (any::<u64>(), any::<bool>())
        .prop_map(|(b, neg)| {
            let v = b as f64 * (1.0 / 18_446_744_073_709_551_616.0);
            if neg {
                -v
            } else {
                v
            }
        })
        .boxed()
}

/// Small integers in `[-r, r]`: ties in x and y everywhere.
pub fn grid_coord(r: i32) -> BoxedStrategy<f64> {
    (-r..=r).prop_map(f64::from).boxed()
}

/// Garbage: any sign, binary exponent in `[-1000, 1000]`, sometimes zero
/// or one of a few repeated values.
pub fn garbage_coord() -> BoxedStrategy<f64> {
    prop_oneof![
        4 => (any::<bool>(), 0u64..(1 << 52), -1000i32..=1000).prop_map(|(neg, m, e)| {
            let v = (1.0 + m as f64 / 4_503_599_627_370_496.0) * 2f64.powi(e);
            if neg { -v } else { v }
        }),
        1 => Just(0.0),
        1 => prop::sample::select(vec![1e300, -1e300, 1e-300, 3.0, -3.0]),
    ]
    .boxed()
}

#[cfg(test)]
mod tests {
    use super::*;

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(crate::cases(256)))]

        #[test]
        fn coordinates_stay_in_their_ranges(
            f in float_coord(),
            g in grid_coord(3),
            h in garbage_coord(),
        ) {
            prop_assert!((-1.0..=1.0).contains(&f));
            prop_assert!((-3.0..=3.0).contains(&g) && g.fract() == 0.0);
            prop_assert!(h.is_finite());
        }
    }
}
