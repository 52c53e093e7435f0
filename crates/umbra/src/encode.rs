//! Results serialized to memory before anything is written (feature
//! `io`): a front end encodes every output first, so that a failure leaves
//! every destination untouched, and counts the 2D result as it will be
//! written (writing by role merges coincident vertices, so that rings
//! touching at a point are cut there into simple rings, and drops
//! back-and-forth spikes: the written rings may differ from
//! [`PolygonSet2::loops`] of the set as computed).

use crate::io::{rename_output, wrong_dimension_of as wrong_dimension};
use crate::report::SetCounts;
use crate::{
    layout_polygons, mesh_to_3mf, mesh_to_glb, mesh_to_gltf, mesh_to_obj, mesh_to_off, mesh_to_ply,
    mesh_to_stl, polygon_set_to_svg, polygons_to_geojson, polygons_to_wkt, FileKind,
    MeshWriteOptions, RingOrientation, UmbraError,
};
use topology::{PolygonMesh, PolygonSet2};

/// A 2D result encoded for one file format.
#[derive(Clone, Debug, PartialEq)]
pub struct EncodedPolygons {
    /// The file's contents.
    pub bytes: Vec<u8>,
    /// Rings written.
    pub rings: usize,
    /// Points written over all rings (no closing duplicates).
    pub points: usize,
    /// Holes that no outer ring contains (see
    /// [`crate::PolygonLayout::orphan_holes`]).
    pub orphan_holes: usize,
    /// The signed area of the set.
    pub signed_area: f64,
}

impl EncodedPolygons {
    /// The counts of what is written, under the name `file`.
    pub fn counts(&self, file: impl Into<String>) -> SetCounts {
        SetCounts {
            file: file.into(),
            vertices: self.points,
            edges: self.points,
            rings: self.rings,
            signed_area: self.signed_area,
        }
    }
}

/// Encodes `set` as `kind` (WKT, GeoJSON or SVG) with the ring layout of
/// `orientation` (SVG is always laid out by role: a picture fills by
/// winding number), exactly as [`crate::write_polygon_set`] writes it;
/// errors name `file`.
///
/// ```
/// use umbra::{encode_polygon_set, FileKind, PolygonSet2, RingOrientation};
/// let mut s = PolygonSet2::new();
/// // Two squares sharing an edge: two loops, one ring once written.
/// s.add_loop(&[[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]);
/// s.add_loop(&[[1.0, 0.0], [2.0, 0.0], [2.0, 1.0], [1.0, 1.0]]);
/// let e = encode_polygon_set(FileKind::Wkt, &s, RingOrientation::ByRole, "out.wkt").unwrap();
/// assert_eq!((e.rings, e.points), (1, 6));
/// assert_eq!(e.bytes, b"POLYGON ((0 0, 1 0, 2 0, 2 1, 1 1, 0 1, 0 0))\n");
/// ```
pub fn encode_polygon_set(
    kind: FileKind,
    set: &PolygonSet2,
    orientation: RingOrientation,
    file: &str,
) -> Result<EncodedPolygons, UmbraError> {
    const WANT: &str = "2D (.wkt, .geojson, .svg)";
    if kind.is_mesh() {
        return Err(wrong_dimension(file, WANT));
    }
    let orientation = if kind == FileKind::Svg {
        RingOrientation::ByRole
    } else {
        orientation
    };
    let layout = layout_polygons(set, orientation, file)?;
    let text = match kind {
        FileKind::Wkt => polygons_to_wkt(&layout.polygons),
        FileKind::GeoJson => polygons_to_geojson(&layout.polygons),
        FileKind::Svg => {
            polygon_set_to_svg(set)
                .map_err(|e| rename_output(e, file))?
                .0
        }
        FileKind::Obj
        | FileKind::Off
        | FileKind::Stl
        | FileKind::Ply
        | FileKind::ThreeMf
        | FileKind::Glb
        | FileKind::Gltf => return Err(wrong_dimension(file, WANT)),
    };
    let rings = layout.polygons.iter().map(Vec::len).sum();
    let points = layout.polygons.iter().flatten().map(Vec::len).sum();
    Ok(EncodedPolygons {
        bytes: text.into_bytes(),
        rings,
        points,
        orphan_holes: layout.orphan_holes,
        signed_area: set.signed_area(),
    })
}

/// Encodes `mesh` as `kind` exactly as [`crate::write_mesh`] writes it
/// (STL and PLY in binary); errors name `file`.
pub fn encode_mesh(kind: FileKind, mesh: &PolygonMesh, file: &str) -> Result<Vec<u8>, UmbraError> {
    encode_mesh_with(kind, mesh, MeshWriteOptions::default(), file)
}

/// Encodes `mesh` as `kind` (OBJ, OFF, STL, PLY, 3MF or glTF)
/// exactly as [`crate::write_mesh_with`] writes it; errors name `file`.
/// Where the format stores `f32` coordinates (binary STL, glTF), the mesh
/// is rounded by [`crate::round_to_f32`], which smooths away any facet
/// intersection the rounding would create.
pub fn encode_mesh_with(
    kind: FileKind,
    mesh: &PolygonMesh,
    options: MeshWriteOptions,
    file: &str,
) -> Result<Vec<u8>, UmbraError> {
    let rounded;
    let mesh = if kind.stores_f32(options) {
        rounded = crate::round_to_f32(mesh).mesh.to_polygon_mesh();
        &rounded
    } else {
        mesh
    };
    let bytes = match kind {
        FileKind::Obj => Ok(mesh_to_obj(mesh).into_bytes()),
        FileKind::Off => Ok(mesh_to_off(mesh).into_bytes()),
        FileKind::Stl => mesh_to_stl(mesh, options.text),
        FileKind::Ply => Ok(mesh_to_ply(mesh, options.text)),
        FileKind::ThreeMf => mesh_to_3mf(mesh),
        FileKind::Glb => mesh_to_glb(mesh),
        FileKind::Gltf => mesh_to_gltf(mesh),
        FileKind::Wkt | FileKind::GeoJson | FileKind::Svg => {
            return Err(wrong_dimension(
                file,
                "3D (.obj, .off, .stl, .ply, .3mf, .glb, .gltf)",
            ))
        }
    };
    bytes.map_err(|e| rename_output(e, file))
}
