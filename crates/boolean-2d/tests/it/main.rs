//! The integration tests of `boolean-2d`, one module per former test file,
//! in one test binary: each binary links the whole stack, so one per crate
//! instead of one per file saves most of the test build's link time.

mod fast_equals_reference;
mod oracles;
