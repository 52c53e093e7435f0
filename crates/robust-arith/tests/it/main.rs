//! The integration tests of `robust-arith`, one module per former test
//! file, in one test binary: each binary links the whole stack, so one per
//! crate instead of one per file saves most of the test build's link time.

mod common;

mod exact_predicates;
mod experiment_8_3;
mod section_7_2_points;
mod table_7_1;
mod table_7_2;
