//! The integration tests of the `umbra` facade, one module per former test
//! file, in one test binary: each binary links the whole stack, so one per
//! crate instead of one per file saves most of the test build's link time.
//! `hostile_memory` stays a binary of its own: its counting global
//! allocator must see no other test's allocations.

mod facade;
mod formats;
mod garbage;
mod garbage_formats;
mod inspection;
mod model_chain_clean;
mod model_clean;
mod model_contacts;
mod model_csg;
mod model_primitives;
#[cfg(feature = "render")]
mod render;
mod reports;
mod smooth_guard;
mod smooth_near_real;
mod smooth_real;
