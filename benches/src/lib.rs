//! Inputs and peers for Umbra's benchmarks: deterministic input generators
//! and a [`Peer`] trait with one implementation per library under test
//! (Umbra's 2D Boolean, the C++ Clipper2 through the `clipper2` crate, its
//! Rust port `clipper2-rust`, `i_overlay` 9 and `geo` 0.33), so that every
//! library runs the same operation on the same coordinates in one process.
//! [`solid`] holds the 3D rows (beside `manifold-rust`) and [`sweep`] the
//! simplification rows (beside `i_overlay`'s `simplify_shape` and `geo`).
//!
//! The headline case is the dissertation's Table 7.4 (section 7.6, after
//! \[MY04\]): the union of a regular n-gon with a copy of itself rotated by a
//! tiny angle alpha. The exact result is one ring with `4n` vertices: the
//! `n` vertices of each polygon and `2n` crossings (one near each vertex and
//! one near the middle of each pair of almost parallel edges). See
//! [`TABLE_7_4`] and [`rotated_ngon_pair`].
//!
//! Each peer converts the input rings into its native type once, outside
//! any timing ([`Peer::prepare`]); only [`Peer::union`] is timed. The
//! result is then turned back into rings ([`Peer::rings`]) and summarised
//! by [`RingStats`] so that the combinatorics of every peer can be checked.
//!
//! # Example
//!
//! ```
//! use umbra_benches::{rotated_ngon_pair, Peer, Umbra};
//!
//! let (a, b) = rotated_ngon_pair(100, 1.0e-2);
//! let peer = Umbra;
//! let input = peer.prepare(&[a], &[b]);
//! let out = peer.union(&input);
//! let stats = peer.stats(&out).unwrap();
//! assert!(stats.is_single_ring_with(400));
//! ```

#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub mod batch;
pub mod chain;
pub mod clipper;
mod error;
mod generate;
mod peers;
pub mod rss;
pub mod solid;
pub mod sweep;

pub use error::BenchError;
pub use generate::{random_star_polygon, regular_ngon, rotated_ngon_pair, Case, Ring, TABLE_7_4};
pub use peers::{
    exact_union_area, Clipper2, Clipper2Rust, Geo, IOverlay, IOverlay64, Peer, RingStats, Umbra,
};

/// The value after the command-line flag `name` in `args`, if any (the
/// benchmark binaries' `--flag value` arguments).
pub fn flag_value(args: &[String], name: &str) -> Option<String> {
    args.iter()
        .position(|a| a == name)
        .and_then(|i| args.get(i + 1))
        .cloned()
}
