//! The integration tests of `simplify-2d`, one module per former test file,
//! in one test binary: each binary links the whole stack, so one per crate
//! instead of one per file saves most of the test build's link time.

mod common;

mod booleans;
mod errors;
mod figures;
mod properties;
mod special_cases;
