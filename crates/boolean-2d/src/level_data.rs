//! The level-2 intersection data of a 2D Boolean, the one value the
//! level-2 evaluations (brute force and fast path) produce and the
//! construction of levels 3-4 consumes.

/// The level-2 data of a 2D Boolean (section 4.9, "level k intersection
/// data"), from which levels 3 and 4 are built.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct LevelData {
    /// `X02(v, B)` for every vertex `v` of A (multiplicity-weighted).
    pub x02: Vec<i32>,
    /// `X20(A, v)` for every vertex `v` of B (multiplicity-weighted).
    pub x20: Vec<i32>,
    /// Every edge pair with `X11 != 0`: `(edge of A, edge of B, X11, point)`,
    /// sorted by edge of A, then edge of B.
    pub x11: Vec<(u32, u32, i32, [f64; 2])>,
    /// For every composite edge (A's edges, then B's): the number of
    /// start- and end-vertices (Theorem 2 says they are equal).
    pub composite_counts: Vec<(u32, u32)>,
}
