//! Level 2 of the pyramid (Table 4.1, eq. 4.1-4.6): the intersection
//! functions `X02`, `X11`, `X20` in the (x, y) plane, their intersection
//! point pairs, and (for 3D points) the shadow functions `S02`, `S11`,
//! `S20` in z.
//!
//! - `X02(v_A, f_B) = -sum_{h in f_B} S01(v_A, h)`: the winding number of
//!   `v_A` in the projection of facet `f_B` (a 2D polygon set is one facet);
//! - `X11(e_A, e_B) = S01(v_e(e_A), e_B) - S01(v_s(e_A), e_B)
//!   + S10(e_A, v_e(e_B)) - S10(e_A, v_s(e_B))`: `+1` when `e_A` crosses
//!   `e_B` from left to right;
//! - `X20(f_A, v_B) = sum_{h in f_A} S10(h, v_B)`.
//!
//! When a value is non-zero the intersection point pair is interpolated
//! (eq. 4.2-4.6, [`robust_arith::interpolate_pair`]) from one lower-level
//! pair where B shadows A and one where A shadows B. Theorem 1 guarantees
//! both exist (for `X02`/`X20` given a facet satisfying facet boundary
//! closure); their absence is reported as [`ShadowError::MissingPartner`],
//! a bug or a facet that is not closed. Of several candidates the ones
//! closest in y are used.
//!
//! In 2D (`N = 2`) the `X11` point is exactly the point of Table 7.2.
//!
//! # Example
//!
//! ```
//! use shadow_2d::{x02, x11};
//!
//! let square = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
//! let facet: Vec<_> = (0..4).map(|i| (square[i], square[(i + 1) % 4])).collect();
//! // A point inside an anticlockwise square has winding number 1.
//! assert_eq!(x02(&[0.5, 0.5], facet.iter().copied()).unwrap().unwrap().value, 1);
//! assert!(x02(&[1.5, 0.5], facet.iter().copied()).unwrap().is_none());
//!
//! // e_A crosses e_B from left to right: X11 = +1 at (0.5, 0.5).
//! let hit = x11(&[0.0, 0.0], &[1.0, 1.0], &[1.0, 0.0], &[0.0, 1.0]).unwrap().unwrap();
//! assert_eq!(hit.value, 1);
//! assert_eq!(hit.a, [0.5, 0.5]);
//! ```

#![forbid(unsafe_code)]
#![warn(missing_docs)]

mod error;
mod level2;
mod partners;

pub use error::ShadowError;
pub use level2::{s02, s11, s20, x02, x02_weighted, x11, x20, x20_weighted};
pub use partners::Partners;
pub use shadow_1d::Hit;
