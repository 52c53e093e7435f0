//! Pictures of 2D polygon sets: every pixel shaded by its winding number,
//! computed per row from the crossings of the row through the pixel
//! centres, each counted with its edge's multiplicity (+ upward, -
//! downward, ray to the right); or the dissertation's figures: directed
//! edges with one arrowhead per unit of multiplicity, vertices as dots.

use super::camera::Frame;
use super::canvas::Image;
use super::options::{RenderError, RenderOptions, Style};
use super::svg::Svg;
use rayon::prelude::*;
use std::collections::BTreeMap;
use topology::PolygonSet2;

/// The background (winding 0).
const BACKGROUND: [u8; 3] = [255, 255, 255];
/// Edges.
const EDGE: [u8; 3] = [40, 40, 48];
/// Vertices.
const VERTEX: [u8; 3] = [15, 15, 20];
/// At most this many arrowheads on one edge (multiplicities beyond are
/// drawn with this many).
const MAX_ARROWS: u32 = 12;

/// The shade of winding number `w` (pale for the topology style): blues
/// darkening with positive winding, oranges with negative, white for 0;
/// windings beyond +-5 share the shade of +-5.
pub(crate) fn winding_colour(w: i64, pale: bool) -> [u8; 3] {
    if w == 0 {
        return BACKGROUND;
    }
    let (light, dark) = if w > 0 {
        ([200.0, 222.0, 247.0], [25.0, 55.0, 135.0])
    } else {
        ([250.0, 218.0, 185.0], [160.0, 65.0, 15.0])
    };
    let t = (w.unsigned_abs().min(5) - 1) as f64 / 4.0;
    let mut c = [0, 1, 2].map(|k| light[k] + (dark[k] - light[k]) * t);
    if pale {
        c = c.map(|x| 255.0 - (255.0 - x) * 0.45);
    }
    c.map(|x| x.round() as u8)
}

/// Rows per band of the edge bins.
const BAND: usize = 8;

/// The edges binned by the bands of rows they may cross (conservatively:
/// a row more on each side), or no bins when the bins would hold more than
/// four entries per edge plus four million (long edges in a tall picture):
/// memory stays linear in the input.
fn bands(edges: &[([f64; 2], [f64; 2], i64)], frame: &Frame, height: u32) -> Vec<Vec<u32>> {
    let count = (height as usize).div_ceil(BAND);
    let span = |e: &([f64; 2], [f64; 2], i64)| {
        let (ya, yb) = (frame.to_pixel(e.0)[1], frame.to_pixel(e.1)[1]);
        let first = (ya.min(yb) - 1.5).floor().max(0.0);
        let last = (ya.max(yb) + 1.5).ceil().min(f64::from(height) - 1.0);
        (first <= last).then_some((first as usize / BAND, last as usize / BAND))
    };
    let total: usize = edges
        .iter()
        .filter_map(span)
        .map(|(b0, b1)| b1 - b0 + 1)
        .sum();
    if total > 4 * edges.len() + (4 << 20) {
        return Vec::new();
    }
    let mut bins = vec![Vec::new(); count];
    for (i, e) in edges.iter().enumerate() {
        if let Some((b0, b1)) = span(e) {
            for bin in &mut bins[b0..=b1] {
                bin.push(i as u32);
            }
        }
    }
    bins
}

/// A set prepared for drawing: its edges in plane coordinates with their
/// multiplicity, and the frame.
struct Plan {
    edges: Vec<([f64; 2], [f64; 2], i64)>,
    /// Per band of [`BAND`] rows, the edges whose rows may cross it (in
    /// edge order); empty when the bins would be too large, and then every
    /// row tests every edge.
    bands: Vec<Vec<u32>>,
    frame: Frame,
    width: u32,
    height: u32,
    /// Half-width of edge strokes, pixels.
    stroke: f64,
}

impl Plan {
    fn new(set: &PolygonSet2, opts: &RenderOptions) -> Result<Plan, RenderError> {
        opts.validate()?;
        if opts.highlight {
            return Err(RenderError::Unsupported(
                "highlighting marks the problems of a 3D mesh; for a 2D set, `check` counts crossing edges",
            ));
        }
        set.validate_coordinates()?;
        let vs = set.vertices();
        let edges: Vec<([f64; 2], [f64; 2], i64)> = set
            .edges()
            .iter()
            .filter(|e| e.mult != 0)
            .filter_map(|e| {
                Some((
                    *vs.get(e.start as usize)?,
                    *vs.get(e.end as usize)?,
                    i64::from(e.mult),
                ))
            })
            .collect();
        // The box of the edges drawn (edges naming a missing vertex are
        // left out, as above).
        let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
        for p in edges.iter().flat_map(|e| [e.0, e.1]) {
            for k in 0..2 {
                lo[k] = lo[k].min(p[k]);
                hi[k] = hi[k].max(p[k]);
            }
        }
        if edges.is_empty() {
            (lo, hi) = ([0.0; 2], [0.0; 2]);
        }
        let frame = Frame::fit(lo, hi, opts.width, opts.height);
        let bands = bands(&edges, &frame, opts.height);
        Ok(Plan {
            edges,
            bands,
            frame,
            width: opts.width,
            height: opts.height,
            stroke: (f64::from(opts.width.min(opts.height)) / 300.0).max(1.0),
        })
    }

    /// The winding number at the centre of every pixel of row `y`.
    fn row(&self, y: u32, crossings: &mut Vec<(f64, i64)>, out: &mut Vec<i64>) {
        let v = self.frame.row_v(y);
        crossings.clear();
        let all = 0..self.edges.len() as u32;
        let edges: Box<dyn Iterator<Item = u32> + '_> = match self.bands.get(y as usize / BAND) {
            Some(band) => Box::new(band.iter().copied()),
            None => Box::new(all),
        };
        for (a, b, m) in edges.map(|e| self.edges[e as usize]) {
            if (a[1] <= v) != (b[1] <= v) {
                let t = (v - a[1]) / (b[1] - a[1]);
                let x = a[0] + t * (b[0] - a[0]);
                crossings.push((self.frame.pixel_x(x), if b[1] > a[1] { m } else { -m }));
            }
        }
        crossings.sort_by(|p, q| p.0.total_cmp(&q.0).then(p.1.cmp(&q.1)));
        // The winding at x counts the crossings to its right.
        let mut w: i64 = crossings.iter().map(|c| c.1).sum();
        let mut next = 0;
        out.clear();
        for x in 0..self.width {
            let xc = f64::from(x) + 0.5;
            while next < crossings.len() && crossings[next].0 < xc {
                w -= crossings[next].1;
                next += 1;
            }
            out.push(w);
        }
    }

    /// The pixel positions of an edge.
    fn pixels(&self, a: [f64; 2], b: [f64; 2]) -> ([f64; 2], [f64; 2]) {
        (self.frame.to_pixel(a), self.frame.to_pixel(b))
    }

    /// The arrowheads of an edge: one per unit of multiplicity (at most
    /// [`MAX_ARROWS`]), evenly spaced over 10% to 60% of its length, pointing along the edge for a
    /// positive multiplicity.
    fn arrows(&self, a: [f64; 2], b: [f64; 2], m: i64) -> Vec<[[f64; 2]; 3]> {
        let (pa, pb) = self.pixels(a, b);
        let (dx, dy) = (pb[0] - pa[0], pb[1] - pa[1]);
        let len = (dx * dx + dy * dy).sqrt();
        if !(len > 0.0 && len.is_finite()) {
            return Vec::new();
        }
        let k = m.unsigned_abs().min(u64::from(MAX_ARROWS));
        let sign = if m > 0 { 1.0 } else { -1.0 };
        let (ux, uy) = (sign * dx / len, sign * dy / len);
        let size = (5.0 * self.stroke + 6.0).min(len * 0.5 / (k as f64 + 1.0) * 0.9);
        (1..=k)
            .map(|i| {
                // Spread over the middle of the edge, off its midpoint
                // (where a figure eight's edges cross).
                let t = 0.1 + 0.5 * i as f64 / (k as f64 + 1.0);
                let c = [pa[0] + dx * t, pa[1] + dy * t];
                let tip = [c[0] + ux * size / 2.0, c[1] + uy * size / 2.0];
                let back = [c[0] - ux * size / 2.0, c[1] - uy * size / 2.0];
                let (px, py) = (-uy * size * 0.45, ux * size * 0.45);
                [
                    tip,
                    [back[0] + px, back[1] + py],
                    [back[0] - px, back[1] - py],
                ]
            })
            .collect()
    }

    /// The vertices that edges use, in pixels, each once.
    fn dots(&self) -> Vec<[f64; 2]> {
        let mut seen = std::collections::BTreeSet::new();
        let mut dots = Vec::new();
        for &(a, b, _) in &self.edges {
            for p in [a, b] {
                if seen.insert((p[0].to_bits(), p[1].to_bits())) {
                    dots.push(self.frame.to_pixel(p));
                }
            }
        }
        dots
    }
}

/// A PNG-ready picture of a 2D polygon set: each pixel in the shade of its
/// winding number ([`Style::Filled`], the edges drawn thin on top), or the
/// edges with arrowheads and the vertices as dots over a pale shade
/// ([`Style::Topology`]). The set's box is fitted into the frame with a
/// margin at its true aspect ratio; `opts.view` is ignored (2D is seen
/// from above) and `opts.highlight` refused.
///
/// ```
/// use umbra::{render_polygons, PolygonSet2, RenderOptions};
/// let mut s = PolygonSet2::new();
/// s.add_loop(&[[0.0, 0.0], [2.0, 0.0], [2.0, 1.0], [0.0, 1.0]]);
/// let image = render_polygons(&s, &RenderOptions { width: 40, height: 40, ..Default::default() })?;
/// // The centre lies inside (winding 1), the corner outside.
/// assert_ne!(image.pixel(20, 20), image.pixel(0, 0));
/// # Ok::<(), umbra::RenderError>(())
/// ```
pub fn render_polygons(set: &PolygonSet2, opts: &RenderOptions) -> Result<Image, RenderError> {
    let plan = Plan::new(set, opts)?;
    let pale = opts.style == Style::Topology;
    let w = plan.width as usize;
    let mut data = vec![0u8; w * plan.height as usize * 3];
    data.par_chunks_mut(w * 3).enumerate().for_each_init(
        || (Vec::new(), Vec::new()),
        |(crossings, windings), (y, row)| {
            plan.row(y as u32, crossings, windings);
            for (x, &wn) in windings.iter().enumerate() {
                row[x * 3..x * 3 + 3].copy_from_slice(&winding_colour(wn, pale));
            }
        },
    );
    let mut image = Image::from_rgb(plan.width, plan.height, data);
    match opts.style {
        Style::Filled => {
            for &(a, b, _) in &plan.edges {
                let (pa, pb) = plan.pixels(a, b);
                image.stroke(pa, pb, 0.5 * plan.stroke, EDGE);
            }
        }
        Style::Topology => {
            for &(a, b, _) in &plan.edges {
                let (pa, pb) = plan.pixels(a, b);
                image.stroke(pa, pb, 0.6 * plan.stroke, EDGE);
            }
            for &(a, b, m) in &plan.edges {
                for t in plan.arrows(a, b, m) {
                    image.fill_convex(&t, EDGE);
                }
            }
            for d in plan.dots() {
                image.fill_disc(d, 2.2 * plan.stroke, VERTEX);
            }
        }
    }
    Ok(image)
}

/// An SVG picture of a 2D polygon set, the same as [`render_polygons`]:
/// the winding shade as runs of equal winding merged into rectangles
/// (the raster's exact cells at the picture's resolution), the edges,
/// arrowheads and dots as vectors.
pub fn render_polygons_svg(set: &PolygonSet2, opts: &RenderOptions) -> Result<String, RenderError> {
    let plan = Plan::new(set, opts)?;
    let pale = opts.style == Style::Topology;
    let mut svg = Svg::new(plan.width, plan.height, BACKGROUND);
    // Open rectangles: (x0, x1, winding) -> first row.
    let mut open: BTreeMap<(u32, u32, i64), u32> = BTreeMap::new();
    let (mut crossings, mut windings) = (Vec::new(), Vec::new());
    for y in 0..=plan.height {
        let mut runs = Vec::new();
        if y < plan.height {
            plan.row(y, &mut crossings, &mut windings);
            let mut x0 = 0;
            for x in 1..=windings.len() {
                if x == windings.len() || windings[x] != windings[x0] {
                    if windings[x0] != 0 {
                        runs.push((x0 as u32, x as u32, windings[x0]));
                    }
                    x0 = x;
                }
            }
        }
        let closed: Vec<(u32, u32, i64)> = open
            .keys()
            .filter(|k| runs.binary_search(k).is_err())
            .copied()
            .collect();
        for k in closed {
            if let Some(first) = open.remove(&k) {
                svg.rect(k.0, first, k.1 - k.0, y - first, winding_colour(k.2, pale));
            }
        }
        for r in runs {
            open.entry(r).or_insert(y);
        }
    }
    let hw = plan.stroke;
    for &(a, b, _) in &plan.edges {
        let (pa, pb) = plan.pixels(a, b);
        let width = if pale { 1.2 * hw } else { hw };
        svg.line(pa, pb, EDGE, width);
    }
    if opts.style == Style::Topology {
        for &(a, b, m) in &plan.edges {
            for t in plan.arrows(a, b, m) {
                svg.polygon(&t, EDGE);
            }
        }
        for d in plan.dots() {
            svg.circle(d, 2.2 * hw, VERTEX);
        }
    }
    Ok(svg.finish())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The binned rows equal the rows that test every edge, for edges of
    /// every slope, length and multiplicity.
    #[test]
    fn binned_rows_equal_unbinned_rows() {
        let mut set = PolygonSet2::new();
        let mut state = 0x9e37_79b9_7f4a_7c15_u64;
        let mut next = || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state >> 11) as f64 / (1u64 << 53) as f64 * 10.0
        };
        for m in 1..40 {
            let a = set.add_vertex([next(), next()]);
            let b = set.add_vertex([next(), next()]);
            let c = set.add_vertex([next(), next()]);
            let m = if m % 3 == 0 { -m } else { m };
            set.add_edge_mult(a, b, m);
            set.add_edge_mult(b, c, m);
            set.add_edge_mult(c, a, m);
        }
        let opts = RenderOptions {
            width: 97,
            height: 203,
            ..RenderOptions::default()
        };
        let binned = Plan::new(&set, &opts).unwrap();
        assert!(!binned.bands.is_empty());
        let mut plain = Plan::new(&set, &opts).unwrap();
        plain.bands.clear();
        let (mut c, mut w1, mut w2) = (Vec::new(), Vec::new(), Vec::new());
        let mut nonzero = 0;
        for y in 0..opts.height {
            binned.row(y, &mut c, &mut w1);
            plain.row(y, &mut c, &mut w2);
            assert_eq!(w1, w2, "row {y}");
            nonzero += w1.iter().filter(|&&w| w != 0).count();
        }
        assert!(nonzero > 1000);
    }
}
