//! The integration tests of `topology`, one module per former test file, in
//! one test binary: each binary links the whole stack, so one per crate
//! instead of one per file saves most of the test build's link time.

mod big_facets;
mod pinched_hole;
mod plate_with_holes;
