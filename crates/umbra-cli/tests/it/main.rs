//! The end-to-end tests of the `umbra` binary, one module per former test
//! file, in one test binary: each binary links the whole stack, so one per
//! crate instead of one per file saves most of the test build's link time.

mod common;

mod cli;
mod cli_formats;
mod cli_mesh_and_simplify;
mod cli_model;
mod cli_output_safety;
mod cli_render;
mod cli_smooth;
