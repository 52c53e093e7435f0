//! The integration tests of `boolean-3d`, one module per former test file,
//! in one test binary: each binary links the whole stack, so one per crate
//! instead of one per file saves most of the test build's link time.

mod common;

mod accuracy;
mod contacts;
mod errors;
mod invalid_facets;
mod lean;
mod named;
mod prepared;
mod random_topologies;
mod theorems;
mod triangulation;
