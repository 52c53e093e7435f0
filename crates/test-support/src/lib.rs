//! Development-only support shared by the tests, `xtask`, the benches and
//! the fuzz targets: seeded generators ([`rng`]), exact oracles in big
//! integer and rational arithmetic ([`exact`]), floating-point measures
//! such as winding numbers and volumes ([`measure`]) and the primitive
//! shapes tests build again and again ([`shapes`]); with the feature
//! `proptest`, coordinate strategies for property tests (`strategies`).
//!
//! Nothing here is part of Umbra's API. A library crate may take this crate
//! only as a dev-dependency (the tidy test enforces it), so no test code can
//! be reached from library code.
//!
//! Every generator keeps the exact algorithm of the copy it replaced, so a
//! seed gives the same sequence as before and no corpus changed when the
//! copies were merged; the different algorithms are kept as named variants.

#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub mod canonical;
pub mod exact;
pub mod measure;
pub mod rng;
pub mod shapes;
#[cfg(feature = "proptest")]
pub mod strategies;

/// The path of a real data file shipped with this crate, e.g.
/// `data_path("pyvista/nut.ply")` (see `data/*/README.md` for where each
/// file comes from and its licence).
pub fn data_path(relative: &str) -> std::path::PathBuf {
    std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("data")
        .join(relative)
}

/// A property test's case count: `base`, multiplied by the environment
/// variable `UMBRA_PROPTEST_SCALE` when it holds a positive integer, so
/// that a long campaign raises every property test in proportion to its
/// own budget (`UMBRA_PROPTEST_SCALE=20 cargo test --release`) while CI
/// runs the budgets written in the tests. Proptest's own `PROPTEST_CASES`
/// only changes the tests that keep the default count. A test that rejects
/// draws (`prop_assume!`) scales its `max_global_rejects` the same way.
pub fn cases(base: u32) -> u32 {
    let scale = std::env::var("UMBRA_PROPTEST_SCALE")
        .ok()
        .and_then(|v| v.trim().parse::<u32>().ok())
        .filter(|&s| s > 0)
        .unwrap_or(1);
    base.saturating_mul(scale)
}
