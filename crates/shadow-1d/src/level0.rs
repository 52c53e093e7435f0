//! Level 0: vertex against vertex (Table 4.1, eq. 4.1).

/// `X00(v_A, v_B) = 1`: at level 0 every pair of vertices "intersects" at the
/// origin, the intersection points being the two vertices themselves.
#[inline]
pub fn x00<const N: usize>(_va: &[f64; N], _vb: &[f64; N]) -> i32 {
    1
}

/// `S00(v_A, v_B)`: 1 when `x_B >= x_A` (B shadows A in x, ties to B), else
/// 0 (eq. 4.1 with `X00 = 1`).
#[inline]
pub fn s00<const N: usize>(va: &[f64; N], vb: &[f64; N]) -> i32 {
    i32::from(vb[0] >= va[0])
}
