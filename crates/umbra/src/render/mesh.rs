//! Pictures of 3D meshes: flat shading (a directional light plus ambient),
//! a z-buffered raster for PNG and facets painted back to front for SVG.
//!
//! The raster is a z-buffer of our own rather than a 2D vector library:
//! the facets of a mesh must hide each other per pixel, which a 2D
//! painter cannot do right for intersecting facets (exactly the meshes
//! `--highlight` is for), and a z-buffer over tiny triangles is a few
//! lines and fast. Triangles are binned into horizontal bands of
//! [`BAND`] rows (in parallel chunks, concatenated in order) and the
//! bands rasterised in parallel; within a band triangles are drawn in
//! index order and a pixel keeps the first nearest one, so the picture
//! does not depend on the number of threads.

use super::camera::{basis, dot, normaliser, normalize, Frame};
use super::canvas::Image;
use super::options::{RenderError, RenderOptions, Style, HIGHLIGHT};
use super::svg::{path_data, Svg};
use rayon::prelude::*;
use std::collections::BTreeMap;
use topology::{triangulate_facet, Facet, PolygonMesh};

/// The background.
const BACKGROUND: [u8; 3] = [255, 255, 255];
/// The base colour of facets seen from their front.
const FRONT: [f64; 3] = [150.0, 180.0, 215.0];
/// The base colour of facets seen from behind (inside an open mesh).
const BACK: [f64; 3] = [215.0, 180.0, 140.0];
/// Facet outlines of [`Style::Topology`].
const OUTLINE: [u8; 3] = [40, 40, 48];
/// The share of light that reaches every facet.
const AMBIENT: f64 = 0.3;
/// Rows per band of the raster.
const BAND: usize = 8;
/// Triangles per binning chunk.
const CHUNK: usize = 1 << 15;
/// No triangle at a pixel.
const NONE: u32 = u32::MAX;

/// What the mesh check found, to highlight.
#[derive(Default)]
struct Marks {
    /// Open and non-manifold edges.
    edges: Vec<[u32; 2]>,
    /// Non-manifold vertices.
    vertices: Vec<u32>,
    /// Facets of self-intersecting pairs.
    facets: Vec<u32>,
}

/// A mesh projected into the picture.
struct Scene {
    width: u32,
    height: u32,
    /// Per vertex: pixel x, pixel y, depth (larger is farther).
    screen: Vec<[f64; 3]>,
    /// Per facet: its shade.
    colours: Vec<[u8; 3]>,
    marks: Marks,
    /// Half-width of highlight strokes, pixels.
    stroke: f64,
}

impl Scene {
    fn new(mesh: &PolygonMesh, opts: &RenderOptions) -> Result<Scene, RenderError> {
        opts.validate()?;
        mesh.validate_coordinates()?;
        let marks = if opts.highlight {
            marks(mesh)?
        } else {
            Marks::default()
        };
        let (centre, half) = normaliser(mesh.vertices.iter());
        let norm = |p: &[f64; 3]| [0, 1, 2].map(|k| (p[k] - centre[k]) / half);
        let [right, up, forward] = basis(opts.view);
        let plane: Vec<[f64; 3]> = mesh
            .vertices
            .par_iter()
            .map(|p| {
                let q = norm(p);
                [dot(q, right), dot(q, up), dot(q, forward)]
            })
            .collect();
        let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
        for p in &plane {
            for k in 0..2 {
                lo[k] = lo[k].min(p[k]);
                hi[k] = hi[k].max(p[k]);
            }
        }
        if lo[0] > hi[0] {
            (lo, hi) = ([0.0; 2], [0.0; 2]);
        }
        let frame = Frame::fit(lo, hi, opts.width, opts.height);
        let screen: Vec<[f64; 3]> = plane
            .par_iter()
            .map(|p| {
                let s = frame.to_pixel([p[0], p[1]]);
                [s[0], s[1], p[2]]
            })
            .collect();
        let light =
            normalize([0, 1, 2].map(|k| -0.25 * right[k] + 0.45 * up[k] - 0.86 * forward[k]));
        let n = mesh.vertices.len();
        let flagged = &marks.facets;
        let colours: Vec<[u8; 3]> = mesh
            .facets
            .par_iter()
            .enumerate()
            .map(|(i, f)| {
                if f.half_edges
                    .iter()
                    .any(|h| h.start as usize >= n || h.end as usize >= n)
                {
                    return BACKGROUND;
                }
                let mut normal = [0.0; 3];
                for h in &f.half_edges {
                    let (a, b) = (
                        norm(&mesh.vertices[h.start as usize]),
                        norm(&mesh.vertices[h.end as usize]),
                    );
                    normal[0] += (a[1] - b[1]) * (a[2] + b[2]);
                    normal[1] += (a[2] - b[2]) * (a[0] + b[0]);
                    normal[2] += (a[0] - b[0]) * (a[1] + b[1]);
                }
                let normal = normalize(normal);
                let (base, sign) = if dot(normal, forward) <= 0.0 {
                    (FRONT, 1.0)
                } else {
                    (BACK, -1.0)
                };
                let lit = (sign * dot(normal, light)).max(0.0);
                let shade = AMBIENT + (1.0 - AMBIENT) * lit;
                if flagged.binary_search(&(i as u32)).is_ok() {
                    // A shade of the highlight, never the colour itself
                    // (kept for the strokes on top).
                    return HIGHLIGHT.map(|c| (f64::from(c) * (0.5 + 0.45 * lit)).round() as u8);
                }
                base.map(|c| (c * shade).round() as u8)
            })
            .collect();
        Ok(Scene {
            width: opts.width,
            height: opts.height,
            screen,
            colours,
            marks,
            stroke: (f64::from(opts.width.min(opts.height)) / 400.0).max(1.0),
        })
    }

    /// The screen position of a vertex.
    fn at(&self, v: u32) -> [f64; 2] {
        let s = self.screen[v as usize];
        [s[0], s[1]]
    }

    /// The highlight strokes: open and non-manifold edges, the outlines
    /// of self-intersecting facets, non-manifold vertices as dots.
    fn mark_strokes(&self, mesh: &PolygonMesh) -> (Vec<[[f64; 2]; 2]>, Vec<[f64; 2]>) {
        let mut lines: Vec<[[f64; 2]; 2]> = self
            .marks
            .edges
            .iter()
            .map(|&[a, b]| [self.at(a), self.at(b)])
            .collect();
        for &f in &self.marks.facets {
            for h in &mesh.facets[f as usize].half_edges {
                lines.push([self.at(h.start), self.at(h.end)]);
            }
        }
        let dots = self.marks.vertices.iter().map(|&v| self.at(v)).collect();
        (lines, dots)
    }
}

/// What the mesh check finds, for highlighting: for a topologically valid
/// mesh its open and non-manifold edges and vertices and the facets of
/// self-intersecting pairs; for one that is not, the edges whose
/// half-edges do not balance (shape boundary closure, section 4.2).
fn marks(mesh: &PolygonMesh) -> Result<Marks, RenderError> {
    let n = mesh.vertices.len() as u32;
    if mesh.check_topology().is_err() {
        let mut balance: BTreeMap<[u32; 2], i64> = BTreeMap::new();
        for h in mesh.facets.iter().flat_map(|f| &f.half_edges) {
            if h.start >= n || h.end >= n {
                return Err(RenderError::Unsupported(
                    "cannot highlight a mesh whose facets refer to missing vertices",
                ));
            }
            if h.start != h.end {
                let (key, d) = if h.start < h.end {
                    ([h.start, h.end], 1)
                } else {
                    ([h.end, h.start], -1)
                };
                *balance.entry(key).or_default() += d;
            }
        }
        return Ok(Marks {
            edges: balance
                .into_iter()
                .filter(|&(_, b)| b != 0)
                .map(|(e, _)| e)
                .collect(),
            ..Marks::default()
        });
    }
    let manifold = mesh.manifold_report()?;
    let edges = manifold
        .open_edges
        .iter()
        .chain(&manifold.non_manifold_edges)
        .map(|e| [e.a, e.b])
        .collect();
    let mut facets: Vec<u32> = mesh.self_intersections()?.into_iter().flatten().collect();
    facets.sort_unstable();
    facets.dedup();
    Ok(Marks {
        edges,
        vertices: manifold.non_manifold_vertices,
        facets,
    })
}

/// The triangles of the facets (section 4.8 for facets that are not a
/// single triangle) with the facet of each, in facet order.
fn triangles(mesh: &PolygonMesh) -> (Vec<[u32; 3]>, Vec<u32>) {
    let n = mesh.vertices.len();
    let parts: Vec<(Vec<[u32; 3]>, Vec<u32>)> = mesh
        .facets
        .par_chunks(4096)
        .enumerate()
        .map(|(c, facets)| {
            let (mut tris, mut owner) = (Vec::with_capacity(facets.len()), Vec::new());
            let mut scratch = Vec::new();
            for (k, f) in facets.iter().enumerate() {
                triangulate(f, n, &mesh.vertices, &mut scratch, &mut tris);
                owner.resize(tris.len(), (c * 4096 + k) as u32);
            }
            (tris, owner)
        })
        .collect();
    let total = parts.iter().map(|p| p.0.len()).sum();
    let (mut tris, mut owner) = (Vec::with_capacity(total), Vec::with_capacity(total));
    for (t, o) in parts {
        tris.extend(t);
        owner.extend(o);
    }
    (tris, owner)
}

/// Appends the triangles of one facet: a facet of one triangular loop as
/// it is, any other by [`triangulate_facet`].
fn triangulate(
    f: &Facet,
    n: usize,
    vertices: &[[f64; 3]],
    scratch: &mut Vec<(u32, u32)>,
    out: &mut Vec<[u32; 3]>,
) {
    if let [a, b, c] = f.half_edges[..] {
        if a.end == b.start && b.end == c.start && c.end == a.start {
            if [a.start, b.start, c.start]
                .iter()
                .all(|&v| (v as usize) < n)
            {
                out.push([a.start, b.start, c.start]);
            }
            return;
        }
    }
    scratch.clear();
    scratch.extend(f.half_edges.iter().map(|h| (h.start, h.end)));
    triangulate_facet(vertices, scratch, out);
}

/// The rows whose pixel centres lie in `[lo, hi]`, within `0..height`.
fn row_range(lo: f64, hi: f64, height: usize) -> Option<(usize, usize)> {
    let first = (lo - 0.5).ceil().max(0.0);
    let last = (hi - 0.5).floor().min(height as f64 - 1.0);
    (first <= last).then_some((first as usize, last as usize))
}

/// Rasterises one triangle into a band starting at row `y0`.
fn raster_triangle(
    t: u32,
    p: [[f64; 3]; 3],
    width: usize,
    y0: usize,
    depth: &mut [f64],
    ids: &mut [u32],
) {
    let [a, b, c] = p;
    let area = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
    if area == 0.0 || !area.is_finite() {
        return;
    }
    let rows = ids.len() / width;
    let lo_y = a[1].min(b[1]).min(c[1]);
    let hi_y = a[1].max(b[1]).max(c[1]);
    let Some((r0, r1)) = row_range(lo_y, hi_y, y0 + rows) else {
        return;
    };
    let lo_x = a[0].min(b[0]).min(c[0]);
    let hi_x = a[0].max(b[0]).max(c[0]);
    let Some((x0, x1)) = row_range(lo_x, hi_x, width) else {
        return;
    };
    let edge = |u: [f64; 3], v: [f64; 3], x: f64, y: f64| {
        (v[0] - u[0]) * (y - u[1]) - (v[1] - u[1]) * (x - u[0])
    };
    for y in r0.max(y0)..=r1 {
        let yc = y as f64 + 0.5;
        let row = (y - y0) * width;
        for x in x0..=x1 {
            let xc = x as f64 + 0.5;
            let (w0, w1, w2) = (edge(b, c, xc, yc), edge(c, a, xc, yc), edge(a, b, xc, yc));
            let inside = if area > 0.0 {
                w0 >= 0.0 && w1 >= 0.0 && w2 >= 0.0
            } else {
                w0 <= 0.0 && w1 <= 0.0 && w2 <= 0.0
            };
            if inside {
                let z = (w0 * a[2] + w1 * b[2] + w2 * c[2]) / area;
                let i = row + x;
                if z < depth[i] {
                    depth[i] = z;
                    ids[i] = t;
                }
            }
        }
    }
}

/// The nearest triangle at every pixel ([`NONE`] for the background).
fn zbuffer(scene: &Scene, tris: &[[u32; 3]]) -> Vec<u32> {
    let (w, h) = (scene.width as usize, scene.height as usize);
    let bands = h.div_ceil(BAND);
    let corners = |t: &[u32; 3]| t.map(|v| scene.screen[v as usize]);
    let bins: Vec<Vec<Vec<u32>>> = tris
        .par_chunks(CHUNK)
        .enumerate()
        .map(|(c, chunk)| {
            let mut bins = vec![Vec::new(); bands];
            for (k, t) in chunk.iter().enumerate() {
                let p = corners(t);
                let lo = p[0][1].min(p[1][1]).min(p[2][1]);
                let hi = p[0][1].max(p[1][1]).max(p[2][1]);
                if let Some((r0, r1)) = row_range(lo, hi, h) {
                    for bin in &mut bins[r0 / BAND..=r1 / BAND] {
                        bin.push((c * CHUNK + k) as u32);
                    }
                }
            }
            bins
        })
        .collect();
    let mut ids = vec![NONE; w * h];
    ids.par_chunks_mut(w * BAND)
        .enumerate()
        .for_each(|(band, ids)| {
            let mut depth = vec![f64::INFINITY; ids.len()];
            for chunk in &bins {
                for &t in &chunk[band] {
                    let p = corners(&tris[t as usize]);
                    raster_triangle(t, p, w, band * BAND, &mut depth, ids);
                }
            }
        });
    ids
}

/// A PNG-ready picture of a mesh: facets shaded flat and hidden by a
/// z-buffer, the camera fitted to the mesh for `opts.view`; with
/// `opts.highlight`, what [`crate::check_mesh`] finds drawn on top in
/// [`HIGHLIGHT`] (for a mesh that is not topologically valid, the edges
/// whose half-edges do not balance). Coordinates must be finite; facets
/// referring to missing vertices are skipped (refused when highlighting).
///
/// ```
/// use umbra::{render_mesh, Facet, PolygonMesh, RenderOptions};
/// let v = vec![[0.0; 3], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
/// let loops = [[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2]];
/// let tetra = PolygonMesh::new(v, loops.iter().map(|l| Facet::from_loop(l)).collect());
/// let image = render_mesh(&tetra, &RenderOptions { width: 64, height: 48, ..Default::default() })?;
/// assert_eq!((image.width(), image.height()), (64, 48));
/// assert!(image.to_png()?.starts_with(b"\x89PNG"));
/// # Ok::<(), umbra::RenderError>(())
/// ```
pub fn render_mesh(mesh: &PolygonMesh, opts: &RenderOptions) -> Result<Image, RenderError> {
    let scene = Scene::new(mesh, opts)?;
    let (tris, owner) = triangles(mesh);
    let ids = zbuffer(&scene, &tris);
    let w = scene.width as usize;
    let facet_at = |i: usize| match ids[i] {
        NONE => NONE,
        t => owner[t as usize],
    };
    let mut data = vec![0u8; ids.len() * 3];
    data.par_chunks_mut(w * 3).enumerate().for_each(|(y, row)| {
        for x in 0..w {
            let i = y * w + x;
            let f = facet_at(i);
            let mut c = if f == NONE {
                BACKGROUND
            } else {
                scene.colours[f as usize]
            };
            if opts.style == Style::Topology && f != NONE {
                let right = (x + 1 < w).then(|| facet_at(i + 1));
                let below = (i + w < ids.len()).then(|| facet_at(i + w));
                if right.is_some_and(|g| g != f) || below.is_some_and(|g| g != f) {
                    c = OUTLINE;
                }
            }
            row[x * 3..x * 3 + 3].copy_from_slice(&c);
        }
    });
    let mut image = Image::from_rgb(scene.width, scene.height, data);
    let (lines, dots) = scene.mark_strokes(mesh);
    for [a, b] in lines {
        image.stroke(a, b, scene.stroke, HIGHLIGHT);
    }
    for d in dots {
        image.fill_disc(d, 2.5 * scene.stroke, HIGHLIGHT);
    }
    Ok(image)
}

/// An SVG picture of a mesh: the facets as polygons (holes even-odd),
/// painted from the farthest (by mean depth of their corners) to the
/// nearest, in the shades of [`render_mesh`], and the same highlight.
/// Suited to meshes of some thousands of facets; intersecting facets are
/// painted whole, one over the other.
pub fn render_mesh_svg(mesh: &PolygonMesh, opts: &RenderOptions) -> Result<String, RenderError> {
    let scene = Scene::new(mesh, opts)?;
    let n = mesh.vertices.len();
    let mut order: Vec<(f64, usize)> = mesh
        .facets
        .iter()
        .enumerate()
        .filter(|(_, f)| {
            !f.half_edges.is_empty()
                && f.half_edges
                    .iter()
                    .all(|h| (h.start as usize) < n && (h.end as usize) < n)
        })
        .map(|(i, f)| {
            let sum: f64 = f
                .half_edges
                .iter()
                .map(|h| scene.screen[h.start as usize][2])
                .sum();
            (sum / f.half_edges.len() as f64, i)
        })
        .collect();
    order.sort_by(|a, b| b.0.total_cmp(&a.0).then(a.1.cmp(&b.1)));
    let mut svg = Svg::new(scene.width, scene.height, BACKGROUND);
    for (_, i) in order {
        let loops: Vec<Vec<[f64; 2]>> = mesh.facets[i]
            .loops_in_plane(&mesh.vertices)
            .iter()
            .map(|l| l.iter().map(|&v| scene.at(v)).collect())
            .collect();
        let colour = scene.colours[i];
        let stroke = match opts.style {
            Style::Filled => (colour, 0.5),
            Style::Topology => (OUTLINE, 0.75),
        };
        svg.path(&path_data(&loops), colour, Some(stroke));
    }
    let (lines, dots) = scene.mark_strokes(mesh);
    for [a, b] in lines {
        svg.line(a, b, HIGHLIGHT, 2.0 * scene.stroke);
    }
    for d in dots {
        svg.circle(d, 2.5 * scene.stroke, HIGHLIGHT);
    }
    Ok(svg.finish())
}
