//! Pictures of shapes: PNG (own z-buffered raster) and SVG (text), the
//! public items flat.
//!
//! - 3D meshes ([`render_mesh`], [`render_mesh_svg`]): flat shading by a
//!   directional light plus ambient, an orthographic camera fitted to the
//!   mesh for each [`View`]; the raster is a z-buffer over horizontal bands
//!   of pixels, the bands in parallel; the SVG paints facets back to front.
//!   With [`RenderOptions::highlight`] what [`crate::check_mesh`] finds
//!   (open and non-manifold edges and vertices, facets of self-intersecting
//!   pairs) is drawn in [`HIGHLIGHT`] on top.
//! - 2D polygon sets ([`render_polygons`], [`render_polygons_svg`]): every
//!   pixel shaded by its winding number (crossings of its row counted with
//!   multiplicity), cells of equal winding in equal shades; or the
//!   dissertation's figures ([`Style::Topology`]): directed edges with one
//!   arrowhead per unit of multiplicity, vertices as dots.

mod camera;
mod canvas;
mod mesh;
mod options;
mod plane;
mod svg;

pub use canvas::Image;
pub use mesh::{render_mesh, render_mesh_svg};
pub use options::{RenderError, RenderOptions, Style, View, HIGHLIGHT, MAX_PIXELS, MAX_SIDE};
pub use plane::{render_polygons, render_polygons_svg};
