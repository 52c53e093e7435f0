//! The `umbra` command-line tool (being written).
fn main() {}
