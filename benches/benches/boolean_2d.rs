//! 2D Boolean benchmarks (being written).
fn main() {}
