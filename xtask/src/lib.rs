//! Umbra developer tasks as a library, so that the checks run both from
//! the `cargo xtask` command line and as ordinary `cargo test` tests:
//!
//! - [`tidy`]: dependencies point only down the pyramid (the table of
//!   `docs/ARCHITECTURE.md`), every declared dependency is used, every
//!   `.rs` file starts with a `//!` header, and no doc or comment points
//!   outside the repository;
//! - [`experiment`]: the section 8.3 measurement of the intersection-point
//!   error of Tables 7.1-7.2 against the `sqrt(153) u L` bound (eq. 8.17);
//! - [`verify`]: the topology invariants behind Theorems 1-2 and closure
//!   (section 4.9) and eq. 4.20 over seeded corpora, as named checks;
//! - [`verify3`]: the same for the 3D Boolean (Theorems 1-4 through
//!   `Audit::verify`) and the simplification sweep (cell structure,
//!   closure, vertex bound);
//! - [`verify_smooth`]: the postconditions of data smoothing (Appendix A)
//!   on meshes and polygon sets, checked independently of the `smooth`
//!   crate (closure, idempotence, distortion bound, minimum feature size,
//!   volume and area change);
//! - [`fingerprint`]: a digest of every result over those corpora, to show
//!   that a refactoring leaves results unchanged.
//!
//! The exact oracles and the seeded generator come from the dev-only
//! `test-support` crate.

#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub mod experiment;
pub mod fingerprint;
pub mod tidy;
pub mod verify;
pub mod verify3;
pub mod verify_smooth;
