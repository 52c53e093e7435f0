//! Umbra developer tasks (being written).
fn main() {}
