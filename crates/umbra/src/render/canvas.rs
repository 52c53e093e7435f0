//! [`Image`]: an RGB raster with the few drawing operations the pictures
//! need (convex polygons and discs by scanline spans, thick segments), and
//! its PNG encoding. Pixel `(x, y)` covers `[x, x+1) x [y, y+1)`, y down;
//! a shape covers the pixels whose centres it contains.

use super::options::RenderError;

/// An RGB picture, 8 bits per channel, rows top to bottom.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Image {
    width: u32,
    height: u32,
    data: Vec<u8>,
}

impl Image {
    /// A picture of the given pixels (`width * height * 3` bytes).
    pub(crate) fn from_rgb(width: u32, height: u32, data: Vec<u8>) -> Image {
        debug_assert_eq!(data.len(), width as usize * height as usize * 3);
        Image {
            width,
            height,
            data,
        }
    }

    /// The width in pixels.
    pub fn width(&self) -> u32 {
        self.width
    }

    /// The height in pixels.
    pub fn height(&self) -> u32 {
        self.height
    }

    /// The pixels, RGB, row by row from the top.
    pub fn rgb(&self) -> &[u8] {
        &self.data
    }

    /// The colour of pixel `(x, y)`, or `None` outside the picture.
    pub fn pixel(&self, x: u32, y: u32) -> Option<[u8; 3]> {
        if x >= self.width || y >= self.height {
            return None;
        }
        let i = (y as usize * self.width as usize + x as usize) * 3;
        Some([self.data[i], self.data[i + 1], self.data[i + 2]])
    }

    /// The picture as a PNG file (8-bit RGB, deterministic bytes).
    pub fn to_png(&self) -> Result<Vec<u8>, RenderError> {
        let mut out = Vec::new();
        let internal = |e: png::EncodingError| RenderError::Internal(format!("PNG encoding: {e}"));
        {
            let mut encoder = png::Encoder::new(&mut out, self.width, self.height);
            encoder.set_color(png::ColorType::Rgb);
            encoder.set_depth(png::BitDepth::Eight);
            encoder.set_compression(png::Compression::High);
            let mut writer = encoder.write_header().map_err(internal)?;
            writer.write_image_data(&self.data).map_err(internal)?;
            writer.finish().map_err(internal)?;
        }
        Ok(out)
    }

    /// Sets pixel `(x, y)` (inside the picture).
    fn put(&mut self, x: usize, y: usize, colour: [u8; 3]) {
        let i = (y * self.width as usize + x) * 3;
        self.data[i..i + 3].copy_from_slice(&colour);
    }

    /// Fills the pixels in columns whose centres lie in `[x0, x1]` on row
    /// `y`.
    fn span(&mut self, y: i64, x0: f64, x1: f64, colour: [u8; 3]) {
        if y < 0 || y >= i64::from(self.height) || x0.partial_cmp(&x1).is_none_or(|o| o.is_gt()) {
            return;
        }
        let first = (x0 - 0.5).ceil().max(0.0);
        let last = (x1 - 0.5).floor().min(f64::from(self.width) - 1.0);
        if first > last {
            return;
        }
        for x in first as usize..=last as usize {
            self.put(x, y as usize, colour);
        }
    }

    /// The rows whose centres lie in `[y0, y1]`, clipped to the picture
    /// (empty when none, or for NaN bounds).
    fn rows(&self, y0: f64, y1: f64) -> std::ops::Range<i64> {
        let first = (y0 - 0.5).ceil().max(0.0);
        let last = (y1 - 0.5).floor().min(f64::from(self.height) - 1.0);
        if first <= last {
            first as i64..last as i64 + 1
        } else {
            0..0
        }
    }

    /// Fills a convex polygon (either orientation).
    pub(crate) fn fill_convex(&mut self, points: &[[f64; 2]], colour: [u8; 3]) {
        if points.len() < 3
            || points
                .iter()
                .any(|p| !p[0].is_finite() || !p[1].is_finite())
        {
            return;
        }
        let lo = points.iter().map(|p| p[1]).fold(f64::INFINITY, f64::min);
        let hi = points
            .iter()
            .map(|p| p[1])
            .fold(f64::NEG_INFINITY, f64::max);
        for y in self.rows(lo, hi) {
            let yc = y as f64 + 0.5;
            let (mut x0, mut x1) = (f64::INFINITY, f64::NEG_INFINITY);
            for (i, a) in points.iter().enumerate() {
                let b = points[(i + 1) % points.len()];
                let (ya, yb) = (a[1], b[1]);
                if (ya <= yc && yc <= yb) || (yb <= yc && yc <= ya) {
                    let x = if ya == yb {
                        x0 = x0.min(a[0].min(b[0]));
                        a[0].max(b[0])
                    } else {
                        a[0] + (yc - ya) * (b[0] - a[0]) / (yb - ya)
                    };
                    x0 = x0.min(x);
                    x1 = x1.max(x);
                }
            }
            self.span(y, x0, x1, colour);
        }
    }

    /// Fills a disc.
    pub(crate) fn fill_disc(&mut self, c: [f64; 2], r: f64, colour: [u8; 3]) {
        if !(c[0].is_finite() && c[1].is_finite() && r > 0.0) {
            return;
        }
        for y in self.rows(c[1] - r, c[1] + r) {
            let dy = y as f64 + 0.5 - c[1];
            let half = (r * r - dy * dy).max(0.0).sqrt();
            self.span(y, c[0] - half, c[0] + half, colour);
        }
    }

    /// Draws a segment `half_width` thick on each side, with round ends.
    pub(crate) fn stroke(&mut self, a: [f64; 2], b: [f64; 2], half_width: f64, colour: [u8; 3]) {
        let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
        let len = (dx * dx + dy * dy).sqrt();
        if len > 0.0 && len.is_finite() {
            let (nx, ny) = (-dy / len * half_width, dx / len * half_width);
            self.fill_convex(
                &[
                    [a[0] + nx, a[1] + ny],
                    [b[0] + nx, b[1] + ny],
                    [b[0] - nx, b[1] - ny],
                    [a[0] - nx, a[1] - ny],
                ],
                colour,
            );
        }
        self.fill_disc(a, half_width, colour);
        self.fill_disc(b, half_width, colour);
    }
}
