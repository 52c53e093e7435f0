//! The benchmark crate's tests: its input generators and every peer's
//! integration-test binary, so the library is compiled once for them.

mod batch;
mod clipper;
mod generate;
mod peers;
mod solid;
mod sweep;
