//! Levels 0 and 1 of the pyramid (Table 4.1, eq. 4.1): the intersection
//! functions `X00`, `X01`, `X10` and the shadow functions `S00`, `S01`,
//! `S10`, for points of any dimension `N >= 2` (2D polygon sets use `N = 2`,
//! polyhedra `N = 3`).
//!
//! Level `k` functions decide intersection in the subspace of the first `k`
//! coordinates; the shadow function of a level-`k` pair compares coordinate
//! `k` at the intersection, ties going to B being above (eq. 4.1):
//!
//! - `X00(v_A, v_B) = 1`, `S00(v_A, v_B) = 1` iff `x_B >= x_A`;
//! - `X01(v_A, e_B) = S00(v_A, v_e(e_B)) - S00(v_A, v_s(e_B))`;
//! - `X10(e_A, v_B) = -S00(v_e(e_A), v_B) + S00(v_s(e_A), v_B)`;
//! - `S01`, `S10`: the X value when the y of B at the intersection point is
//!   `>=` the y of A, else 0.
//!
//! Edges are given by their start and end points, so a half-edge is just an
//! edge with its points in its own order: reversing a half-edge negates every
//! function and leaves the intersection points unchanged (section 4.5).
//!
//! Intersection points of level 1 come from [`robust_arith::point_at_x`]
//! (Table 7.1 with the closer-end choice), so in 2D the y of an edge at a
//! vertex's x is exactly `y_at_x`.
//!
//! # Example
//!
//! ```
//! use shadow_1d::{s01, x01};
//!
//! // A vertex below an edge going left to right: X01 = 1 and the edge
//! // shadows the vertex, S01 = 1.
//! let v = [0.5, 0.0];
//! let hit = x01(&v, &[0.0, 1.0], &[1.0, 1.0]).unwrap();
//! assert_eq!(hit.value, 1);
//! assert_eq!(hit.b, [0.5, 1.0]);
//! assert_eq!(s01(&v, &[0.0, 1.0], &[1.0, 1.0]), 1);
//! // Reversing the half-edge negates both.
//! assert_eq!(s01(&v, &[1.0, 1.0], &[0.0, 1.0]), -1);
//! ```

#![forbid(unsafe_code)]
#![warn(missing_docs)]

mod hit;
mod level0;
mod level1;

pub use hit::Hit;
pub use level0::{s00, x00};
pub use level1::{s01, s10, x01, x10};
