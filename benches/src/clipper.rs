//! The two Clipper2 peers' common ground: the C++ Clipper2 through the
//! `clipper2` crate (a safe Rust API over the vendored C++ sources, built
//! with the system compiler) and the pure-Rust port `clipper2-rust`. Both
//! run Clipper2's integer engine (`i64` coordinates); rings are scaled by
//! [`SCALE`] = 2^50 and rounded once, before timing, which is the finest
//! grid that keeps every bench input (coordinates up to about 1,000 in
//! magnitude) inside Clipper2's coordinate range (`i64::MAX / 4`): about
//! `1e-15` for the unit-sized inputs, the resolution of `f64` itself. The
//! results are scaled back (exactly, below 2^53 grid units) for the
//! correctness checks, outside the timing.

use crate::Ring;
use clipper2::{Path, Paths, Point, PointScaler};
use clipper2_rust::{Path64, Paths64, Point64};

/// The grid of both Clipper2 peers: 2^50 units per input unit.
pub const SCALE: f64 = (1u64 << 50) as f64;

/// The `clipper2` crate's scaler for [`SCALE`].
#[derive(Clone, Copy, Debug, Default, PartialEq, Hash)]
pub struct Fine;

impl PointScaler for Fine {
    const MULTIPLIER: f64 = SCALE;
}

/// Rings as the C++ Clipper2's paths (scaled and rounded).
pub fn cpp_paths(rings: &[Ring]) -> Paths<Fine> {
    rings
        .iter()
        .map(|r| Path::new(r.iter().map(|&[x, y]| Point::<Fine>::new(x, y)).collect()))
        .collect()
}

/// The C++ Clipper2's paths as rings (scaled back).
pub fn cpp_rings(paths: &Paths<Fine>) -> Vec<Ring> {
    paths
        .iter()
        .map(|p| p.iter().map(|q| [q.x(), q.y()]).collect())
        .collect()
}

/// Rings as `clipper2-rust` paths (scaled and rounded like [`cpp_paths`]).
pub fn rust_paths(rings: &[Ring]) -> Paths64 {
    rings
        .iter()
        .map(|r| {
            r.iter()
                .map(|&[x, y]| Point64::new((x * SCALE).round() as i64, (y * SCALE).round() as i64))
                .collect::<Path64>()
        })
        .collect()
}

/// `clipper2-rust` paths as rings (scaled back).
pub fn rust_rings(paths: &Paths64) -> Vec<Ring> {
    paths
        .iter()
        .map(|p| {
            p.iter()
                .map(|q| [q.x as f64 / SCALE, q.y as f64 / SCALE])
                .collect()
        })
        .collect()
}
