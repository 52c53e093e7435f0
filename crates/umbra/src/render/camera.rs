//! The orthographic camera: a view's basis and the fit of a point set into
//! the frame with a margin, keeping the aspect ratio.

use super::options::View;

/// Dot product.
pub(crate) fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// Cross product.
pub(crate) fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// `a` scaled to unit length (zero stays zero).
pub(crate) fn normalize(a: [f64; 3]) -> [f64; 3] {
    let l = dot(a, a).sqrt();
    if l > 0.0 && l.is_finite() {
        [a[0] / l, a[1] / l, a[2] / l]
    } else {
        [0.0; 3]
    }
}

/// The camera's right, up and forward (away from the viewer) directions.
pub(crate) fn basis(view: View) -> [[f64; 3]; 3] {
    match view {
        View::Front => [[1.0, 0.0, 0.0], [0.0, 0.0, 1.0], [0.0, 1.0, 0.0]],
        View::Top => [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, -1.0]],
        View::Side => [[0.0, 1.0, 0.0], [0.0, 0.0, 1.0], [-1.0, 0.0, 0.0]],
        View::Iso => {
            let forward = normalize([-1.0, 1.0, -1.0]);
            let right = normalize(cross(forward, [0.0, 0.0, 1.0]));
            let up = cross(right, forward);
            [right, up, forward]
        }
    }
}

/// The margin around the fitted shape, in pixels, for a frame.
pub(crate) fn margin(width: u32, height: u32) -> f64 {
    (f64::from(width.min(height)) * 0.06).floor()
}

/// A map from plane coordinates `(u, v)` (v up) to pixel coordinates
/// (y down) that fits the box `[lo, hi]` into the frame, centred, with a
/// uniform scale.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Frame {
    centre: [f64; 2],
    scale: f64,
    mid: [f64; 2],
}

impl Frame {
    /// The frame fitting `[lo, hi]` into `width x height` with the margin.
    /// The box is given relative to its own centre's neighbourhood by the
    /// callers, so the arithmetic stays far from overflow.
    pub(crate) fn fit(lo: [f64; 2], hi: [f64; 2], width: u32, height: u32) -> Frame {
        let m = margin(width, height);
        let avail = [
            (f64::from(width) - 2.0 * m).max(1.0),
            (f64::from(height) - 2.0 * m).max(1.0),
        ];
        let ext = [hi[0] - lo[0], hi[1] - lo[1]];
        let mut scale = f64::INFINITY;
        for k in 0..2 {
            if ext[k] > 0.0 {
                scale = scale.min(avail[k] / ext[k]);
            }
        }
        if !scale.is_finite() {
            scale = 1.0;
        }
        Frame {
            centre: [lo[0] / 2.0 + hi[0] / 2.0, lo[1] / 2.0 + hi[1] / 2.0],
            scale,
            mid: [f64::from(width) / 2.0, f64::from(height) / 2.0],
        }
    }

    /// Pixel coordinates of a plane point.
    pub(crate) fn to_pixel(self, p: [f64; 2]) -> [f64; 2] {
        [
            self.mid[0] + (p[0] - self.centre[0]) * self.scale,
            self.mid[1] - (p[1] - self.centre[1]) * self.scale,
        ]
    }

    /// The plane `v` of the centre of pixel row `row`.
    pub(crate) fn row_v(&self, row: u32) -> f64 {
        self.centre[1] - (f64::from(row) + 0.5 - self.mid[1]) / self.scale
    }

    /// The pixel x of a plane `u`.
    pub(crate) fn pixel_x(&self, u: f64) -> f64 {
        self.mid[0] + (u - self.centre[0]) * self.scale
    }
}

/// The box of `points` (which must be finite), its centre and half-size,
/// for normalising coordinates to about `[-1, 1]` before projection.
pub(crate) fn normaliser<'a>(points: impl Iterator<Item = &'a [f64; 3]>) -> ([f64; 3], f64) {
    let mut lo = [f64::INFINITY; 3];
    let mut hi = [f64::NEG_INFINITY; 3];
    for p in points {
        for k in 0..3 {
            lo[k] = lo[k].min(p[k]);
            hi[k] = hi[k].max(p[k]);
        }
    }
    if lo[0] > hi[0] {
        return ([0.0; 3], 1.0);
    }
    let centre = [0, 1, 2].map(|k| lo[k] / 2.0 + hi[k] / 2.0);
    let half = (0..3)
        .map(|k| hi[k] / 2.0 - lo[k] / 2.0)
        .fold(0.0, f64::max);
    (centre, if half > 0.0 { half } else { 1.0 })
}
