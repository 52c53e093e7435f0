//! Results serialized to memory before anything is written (feature
//! `io`): a front end encodes every output first, so that a failure leaves
//! every destination untouched, and counts the 2D result as it will be
//! written (writing by role merges coincident vertices, so that rings
//! touching at a point are cut there into simple rings, and drops
//! back-and-forth spikes: the written rings may differ from
//! [`PolygonSet2::loops`] of the set as computed).

use crate::io::{
    faces_split, obj_of_faces, off_of_faces, ply_of_faces, rename_output, triangles_3mf,
    triangles_stl, triangles_to_3mf, triangles_to_stl, welded,
    wrong_dimension_of as wrong_dimension,
};
use crate::report::{MeshCounts, SetCounts};
use crate::{
    layout_polygons, mesh_to_glb, mesh_to_gltf, polygon_set_to_svg, polygons_to_geojson,
    polygons_to_wkt, FileKind, MeshWriteOptions, RingOrientation, UmbraError,
};
use std::time::Instant;
use topology::{Facet, PolygonMesh, PolygonSet2};

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

/// A 3D result encoded for one file format: the bytes and, where the file
/// holds another mesh than the one given (rounded to `f32`, or facets
/// split into triangles), that mesh, so that a front end reports what was
/// written rather than what was computed ([`EncodedMesh::written`]).
#[derive(Clone, Debug)]
pub struct EncodedMesh {
    /// The file's name as given to the encoder, under which the reports
    /// count what it holds ([`crate::WrittenMeshReport::written_as`]).
    pub file: String,
    /// The file's contents.
    pub bytes: Vec<u8>,
    /// For a format of `f32` coordinates (binary STL, glTF), the mesh
    /// written ([`crate::round_to_f32`] of the mesh given, triangles,
    /// welded by exact position as the format's reader welds it: its
    /// vertex and facet counts and volume can differ); `None` when the
    /// coordinates were written as they are.
    pub rounded: Option<crate::RoundedMesh>,
    /// For a format of `f64` coordinates whose file holds other facets
    /// than the mesh given, the mesh written: for ASCII STL, the facets'
    /// triangles (section 4.8) welded by exact position as the reader
    /// welds them; for 3MF, the triangles with every vertex (a triangle
    /// with a repeated vertex left out, as the writer does); for OBJ, OFF
    /// and PLY, when a facet has several loops, the mesh with such facets
    /// triangulated. `None` when the facets were written one for one (or
    /// [`EncodedMesh::rounded`] holds the mesh written).
    pub triangulated: Option<PolygonMesh>,
}

impl EncodedMesh {
    /// The mesh the file holds: the rounded mesh, the triangulated mesh,
    /// or `given` (the mesh that was encoded) when it was written facet
    /// for facet.
    ///
    /// ```
    /// use umbra::{cuboid, encode_mesh_with, DVec3, FileKind, MeshWriteOptions};
    /// let cube = cuboid(DVec3::new(1.0, 1.0, 1.0), false).unwrap();
    /// let text = MeshWriteOptions { text: true };
    /// for kind in [FileKind::Stl, FileKind::ThreeMf] {
    ///     let e = encode_mesh_with(kind, &cube, text, "c").unwrap();
    ///     // Six squares written as twelve triangles on the eight corners.
    ///     let w = e.written(&cube);
    ///     assert_eq!((w.vertices.len(), w.facets.len()), (8, 12));
    /// }
    /// ```
    pub fn written<'a>(&'a self, given: &'a PolygonMesh) -> &'a PolygonMesh {
        match (&self.rounded, &self.triangulated) {
            (Some(r), _) => &r.mesh,
            (None, Some(t)) => t,
            (None, None) => given,
        }
    }

    /// The counts of what is written, under the name `file` (`given` is
    /// the mesh that was encoded).
    pub fn counts(&self, file: impl Into<String>, given: &PolygonMesh) -> MeshCounts {
        MeshCounts::of_mesh(file, self.written(given))
    }
}

/// Encodes `mesh` as `kind` exactly as [`crate::write_mesh`] writes it
/// (STL and PLY in binary); errors name `file`. The bytes alone: see
/// [`encode_mesh_with`] for the mesh they hold.
pub fn encode_mesh(kind: FileKind, mesh: &PolygonMesh, file: &str) -> Result<Vec<u8>, UmbraError> {
    encode_mesh_with(kind, mesh, MeshWriteOptions::default(), file).map(|e| e.bytes)
}

/// Encodes `mesh` as `kind` (OBJ, OFF, STL, PLY, 3MF or glTF)
/// exactly as [`crate::write_mesh_with`] writes it; errors name `file`.
/// Where the format stores `f32` coordinates (binary STL, glTF), the mesh
/// is rounded by [`crate::round_to_f32`], which smooths away any facet
/// intersection the rounding would create; the rounded mesh, the rounding
/// report and its time come back in [`EncodedMesh::rounded`]. Where the
/// file holds the facets split into triangles otherwise (ASCII STL, 3MF,
/// facets with holes in OBJ, OFF and PLY), the mesh written comes back in
/// [`EncodedMesh::triangulated`].
///
/// ```
/// use umbra::{cuboid, encode_mesh_with, DVec3, FileKind, MeshWriteOptions};
/// let cube = cuboid(DVec3::new(0.1, 0.2, 0.3), false).unwrap();
/// let stl = encode_mesh_with(FileKind::Stl, &cube, MeshWriteOptions::default(), "c.stl").unwrap();
/// let rounded = stl.rounded.as_ref().unwrap();
/// assert_eq!(rounded.report.moved_vertices, 7); // 0.1, 0.2, 0.3 are not f32 values
/// assert_eq!(stl.counts("c.stl", &cube).facets, 12);
/// let off = encode_mesh_with(FileKind::Off, &cube, MeshWriteOptions::default(), "c.off").unwrap();
/// assert!(off.rounded.is_none() && off.triangulated.is_none());
/// assert_eq!(off.counts("c.off", &cube).facets, 6);
/// let tmf = encode_mesh_with(FileKind::ThreeMf, &cube, MeshWriteOptions::default(), "c.3mf").unwrap();
/// assert_eq!(tmf.counts("c.3mf", &cube).facets, 12);
/// ```
pub fn encode_mesh_with(
    kind: FileKind,
    mesh: &PolygonMesh,
    options: MeshWriteOptions,
    file: &str,
) -> Result<EncodedMesh, UmbraError> {
    let start = Instant::now();
    let rounded = kind.stores_f32(options).then(|| crate::round_to_f32(mesh));
    let ms = start.elapsed().as_secs_f64() * 1e3;
    let written_rounded = rounded.as_ref().map(|r| r.mesh.to_polygon_mesh());
    let written = written_rounded.as_ref().unwrap_or(mesh);
    // The facets as the file holds them, made once for the writer and
    // for the mesh written.
    let as_faces = |faces: Vec<Vec<u32>>| {
        PolygonMesh::new(
            written.vertices.clone(),
            faces.iter().map(|f| Facet::from_loop(f)).collect(),
        )
    };
    let (bytes, triangulated) = match kind {
        FileKind::Obj | FileKind::Off | FileKind::Ply => {
            let (faces, split) = faces_split(written);
            let bytes = match kind {
                FileKind::Obj => obj_of_faces(written, &faces).into_bytes(),
                FileKind::Off => off_of_faces(written, &faces).into_bytes(),
                _ => ply_of_faces(written, &faces, options.text),
            };
            (Ok(bytes), split.then(|| as_faces(faces)))
        }
        FileKind::Stl => {
            let tris = triangles_stl(written);
            let bytes = triangles_to_stl(&tris, options.text);
            // Rounded: `rounded` holds the mesh written.
            let read = (rounded.is_none()).then(|| welded(&tris).to_polygon_mesh());
            (bytes, read)
        }
        FileKind::ThreeMf => {
            let tris = triangles_3mf(written);
            (triangles_to_3mf(&tris), Some(tris.to_polygon_mesh()))
        }
        FileKind::Glb => (mesh_to_glb(written), None),
        FileKind::Gltf => (mesh_to_gltf(written), None),
        FileKind::Wkt | FileKind::GeoJson | FileKind::Svg => {
            return Err(wrong_dimension(
                file,
                "3D (.obj, .off, .stl, .ply, .3mf, .glb, .gltf)",
            ))
        }
    };
    let bytes = bytes.map_err(|e| rename_output(e, file))?;
    // Both formats of `f32` coordinates are read back welded by exact
    // position, so the mesh the file holds is the rounded one welded (a
    // pair of vertices that coincide in the `f64` result, which the
    // closure constraints allow, is one vertex there).
    let rounded = rounded.map(|r| crate::RoundedMesh {
        mesh: welded(&r.mesh).to_polygon_mesh(),
        report: r.report,
        ms,
    });
    Ok(EncodedMesh {
        file: file.to_owned(),
        bytes,
        rounded,
        triangulated,
    })
}
