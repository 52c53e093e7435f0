//! A uniform grid over a box of the projection plane, used as the spatial
//! index of the hole bridging and the ear test of the triangulation: each
//! cell lists items (vertices, or edges by their boxes) meeting it, and a
//! query visits the cells meeting a query box.
//!
//! The cell of a coordinate is monotone in it (a difference, a product by
//! a positive constant and a floor, each rounded monotonically, then
//! clamped), so a point inside a query box always lies in a cell the
//! query visits: the index only narrows the candidates, it never changes
//! which of them pass the exact tests that follow.

use super::P2;

/// Items per cell aimed at.
const PER_CELL: usize = 2;

pub(super) struct Grid {
    min: P2,
    scale: P2,
    nx: usize,
    ny: usize,
    cells: Vec<Vec<u32>>,
}

impl Grid {
    /// A grid over the box `lo..=hi` (finite corners) sized for about
    /// `items` items.
    pub(super) fn new(lo: P2, hi: P2, items: usize) -> Grid {
        let cells = (items / PER_CELL).max(1);
        let (w, h) = (hi[0] - lo[0], hi[1] - lo[1]);
        // Finite corners: `w` and `h` are never NaN (at most infinite).
        let (nx, ny) = if w <= 0.0 || h <= 0.0 || !(w / h).is_finite() {
            // A flat or needle-like box: cells along its longer side only.
            if w >= h {
                (cells, 1)
            } else {
                (1, cells)
            }
        } else {
            let nx = ((cells as f64 * w / h).sqrt().round() as usize).clamp(1, cells);
            (nx, (cells / nx).max(1))
        };
        let scale = |n: usize, w: f64| {
            let s = n as f64 / w;
            if s.is_finite() {
                s
            } else {
                0.0
            }
        };
        Grid {
            min: lo,
            scale: [scale(nx, w), scale(ny, h)],
            nx,
            ny,
            cells: vec![Vec::new(); nx * ny],
        }
    }

    #[inline]
    fn index(v: f64, min: f64, scale: f64, n: usize) -> usize {
        // `as usize` saturates (negative and NaN to 0, too large to max).
        (((v - min) * scale).floor() as usize).min(n - 1)
    }

    /// The column of abscissa `x`.
    #[inline]
    pub(super) fn col(&self, x: f64) -> usize {
        Self::index(x, self.min[0], self.scale[0], self.nx)
    }

    /// The row of ordinate `y`.
    #[inline]
    pub(super) fn row(&self, y: f64) -> usize {
        Self::index(y, self.min[1], self.scale[1], self.ny)
    }

    /// The number of columns.
    pub(super) fn cols(&self) -> usize {
        self.nx
    }

    /// Lists `item` in every cell meeting the box `lo..=hi`.
    pub(super) fn insert(&mut self, lo: P2, hi: P2, item: u32) {
        for r in self.row(lo[1])..=self.row(hi[1]) {
            for c in self.col(lo[0])..=self.col(hi[0]) {
                self.cells[r * self.nx + c].push(item);
            }
        }
    }

    /// The items of the cell at `(col, row)`.
    #[inline]
    pub(super) fn cell(&self, col: usize, row: usize) -> &[u32] {
        &self.cells[row * self.nx + col]
    }

    /// Calls `f` on every item listed in a cell meeting the box `lo..=hi`
    /// (an item meeting several such cells, once per cell) until it
    /// returns `true`; returns whether it did.
    pub(super) fn any_in(&self, lo: P2, hi: P2, mut f: impl FnMut(u32) -> bool) -> bool {
        for r in self.row(lo[1])..=self.row(hi[1]) {
            for c in self.col(lo[0])..=self.col(hi[0]) {
                if self.cells[r * self.nx + c].iter().any(|&i| f(i)) {
                    return true;
                }
            }
        }
        false
    }
}

/// The box of a set of points (`None` when empty).
pub(super) fn bounds(points: impl IntoIterator<Item = P2>) -> Option<(P2, P2)> {
    let mut it = points.into_iter();
    let first = it.next()?;
    let (mut lo, mut hi) = (first, first);
    for p in it {
        lo = [lo[0].min(p[0]), lo[1].min(p[1])];
        hi = [hi[0].max(p[0]), hi[1].max(p[1])];
    }
    Some((lo, hi))
}
