//! Peers for the benchmarks (being written).
