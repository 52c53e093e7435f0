//! File types by extension and the format-independent read/write entry
//! points (the command-line tool goes through these). The extension decides
//! the format and the dimension: `.wkt` and `.geojson` are 2D polygon sets
//! (read and written), `.svg` is a 2D picture (written only); `.obj`,
//! `.off`, `.stl`, `.ply`, `.3mf` and `.glb` are 3D meshes (read and
//! written).

use super::geojson::read_geojson_file_counted;
use super::gltf_read::read_gltf_bytes;
use super::mesh_text::{read_mesh_text, MeshReadOptions};
use super::ply::read_ply_bytes;
use super::rings::PolygonSetRead;
use super::stl::read_stl_bytes;
use super::text::{decode, read_bytes, write_bytes};
use super::threemf_read::read_3mf_bytes;
use super::wkt::read_wkt_file_counted;
use crate::{ReadOptions, RingOrientation, UmbraError};
use std::path::Path;
use topology::{PolygonMesh, PolygonSet2};

/// A supported file format, decided by the file extension.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum FileKind {
    /// Well-known text (`.wkt`): 2D polygon sets, read and written.
    Wkt,
    /// GeoJSON (`.geojson`, RFC 7946): 2D polygon sets, read and written.
    GeoJson,
    /// Scalable vector graphics (`.svg`): 2D polygon sets, written only.
    Svg,
    /// Wavefront OBJ (`.obj`): 3D polygon meshes, read and written.
    Obj,
    /// Object File Format (`.off`): 3D polygon meshes, read and written.
    Off,
    /// Stereolithography (`.stl`), binary or ASCII: 3D triangle meshes,
    /// read (welded) and written.
    Stl,
    /// Polygon file format (`.ply`), ASCII or binary: 3D polygon meshes,
    /// read and written.
    Ply,
    /// 3D Manufacturing Format (`.3mf`): 3D triangle meshes, read (the
    /// build items through their components) and written.
    ThreeMf,
    /// Binary glTF 2.0 (`.glb`): 3D triangle meshes, read (the scene's
    /// mesh instances, welded) and written.
    Glb,
    /// glTF 2.0 as JSON (`.gltf`): 3D triangle meshes, read as `.glb` is
    /// (buffers in `data:` URIs or in files beside the document) and
    /// written (the buffer in a `data:` URI: one self-contained file).
    Gltf,
}

/// The list of supported extensions that errors end with.
fn supported() -> String {
    format!("supported: {}", FileKind::supported_extensions())
}

impl FileKind {
    /// Every kind, in the order of the list of supported extensions.
    pub const ALL: [FileKind; 10] = [
        FileKind::Wkt,
        FileKind::GeoJson,
        FileKind::Svg,
        FileKind::Obj,
        FileKind::Off,
        FileKind::Stl,
        FileKind::Ply,
        FileKind::ThreeMf,
        FileKind::Glb,
        FileKind::Gltf,
    ];

    /// The format of `path` by its extension (case-insensitive), or
    /// [`UmbraError::UnsupportedFileType`] naming the file and listing
    /// every supported extension.
    ///
    /// ```
    /// use std::path::Path;
    /// use umbra::FileKind;
    /// assert_eq!(FileKind::from_path(Path::new("shape.WKT")).unwrap(), FileKind::Wkt);
    /// assert!(FileKind::from_path(Path::new("part.stl")).unwrap().is_mesh());
    /// assert!(FileKind::from_path(Path::new("part.glb")).unwrap().can_read());
    /// assert!(!FileKind::from_path(Path::new("shape.svg")).unwrap().can_read());
    /// let e = FileKind::from_path(Path::new("shape.txt")).unwrap_err().to_string();
    /// assert!(e.contains(".3mf"), "{e}");
    /// let e = FileKind::from_path(Path::new("shape.png")).unwrap_err().to_string();
    /// assert!(e.contains("umbra render"), "{e}");
    /// ```
    pub fn from_path(path: &Path) -> Result<FileKind, UmbraError> {
        let file = path.display().to_string();
        let ext = path
            .extension()
            .and_then(|e| e.to_str())
            .map(str::to_ascii_lowercase);
        if let Some(kind) = FileKind::ALL
            .into_iter()
            .find(|k| Some(k.extension()) == ext.as_deref())
        {
            return Ok(kind);
        }
        let detail = match ext {
            Some(e) if e == "png" => {
                format!(
                    "'.png' is a picture: pictures are written by `umbra render` ({})",
                    supported()
                )
            }
            Some(e) => format!("unknown extension '.{e}' ({})", supported()),
            None => format!("no file extension ({})", supported()),
        };
        Err(UmbraError::UnsupportedFileType { file, detail })
    }

    /// Every supported extension by dimension, generated from
    /// [`FileKind::ALL`] (the table [`FileKind::from_path`] dispatches by):
    /// what a front end lists as the formats it reads and writes.
    ///
    /// ```
    /// use umbra::FileKind;
    /// assert_eq!(
    ///     FileKind::supported_extensions(),
    ///     "2D: .wkt .geojson (.svg written only); 3D: .obj .off .stl .ply .3mf .glb .gltf"
    /// );
    /// ```
    pub fn supported_extensions() -> String {
        let list = |keep: &dyn Fn(FileKind) -> bool| {
            FileKind::ALL
                .into_iter()
                .filter(|&k| keep(k))
                .map(|k| format!(".{}", k.extension()))
                .collect::<Vec<_>>()
                .join(" ")
        };
        let planar_read = list(&|k| !k.is_mesh() && k.can_read());
        let planar_written = list(&|k| !k.is_mesh() && !k.can_read());
        let mesh_read = list(&|k| k.is_mesh() && k.can_read());
        let mesh_written = list(&|k| k.is_mesh() && !k.can_read());
        let only = |l: String| {
            if l.is_empty() {
                l
            } else {
                format!(" ({l} written only)")
            }
        };
        format!(
            "2D: {planar_read}{}; 3D: {mesh_read}{}",
            only(planar_written),
            only(mesh_written)
        )
    }

    /// The extension, without the dot (`"3mf"`).
    pub fn extension(self) -> &'static str {
        match self {
            FileKind::Wkt => "wkt",
            FileKind::GeoJson => "geojson",
            FileKind::Svg => "svg",
            FileKind::Obj => "obj",
            FileKind::Off => "off",
            FileKind::Stl => "stl",
            FileKind::Ply => "ply",
            FileKind::ThreeMf => "3mf",
            FileKind::Glb => "glb",
            FileKind::Gltf => "gltf",
        }
    }

    /// The format's name for messages (`"STL"`).
    pub fn name(self) -> &'static str {
        match self {
            FileKind::Wkt => "WKT",
            FileKind::GeoJson => "GeoJSON",
            FileKind::Svg => "SVG",
            FileKind::Obj => "OBJ",
            FileKind::Off => "OFF",
            FileKind::Stl => "STL",
            FileKind::Ply => "PLY",
            FileKind::ThreeMf => "3MF",
            FileKind::Glb | FileKind::Gltf => "glTF",
        }
    }

    /// `true` for the 3D mesh formats.
    pub fn is_mesh(self) -> bool {
        matches!(
            self,
            FileKind::Obj
                | FileKind::Off
                | FileKind::Stl
                | FileKind::Ply
                | FileKind::ThreeMf
                | FileKind::Glb
                | FileKind::Gltf
        )
    }

    /// `true` for the formats that hold triangles only (`.stl`, `.3mf`,
    /// `.glb`, `.gltf`): a polygon mesh written there is triangulated by internal
    /// edges (section 4.8), so a command that computes a mesh for such a
    /// file runs the triangle-mesh variant, whose smoothing cleans the
    /// triangles themselves.
    ///
    /// ```
    /// use std::path::Path;
    /// use umbra::FileKind;
    /// assert!(FileKind::from_path(Path::new("part.stl")).unwrap().holds_triangles_only());
    /// assert!(!FileKind::from_path(Path::new("part.obj")).unwrap().holds_triangles_only());
    /// ```
    pub fn holds_triangles_only(self) -> bool {
        matches!(
            self,
            FileKind::Stl | FileKind::ThreeMf | FileKind::Glb | FileKind::Gltf
        )
    }

    /// `true` when files of this kind, written with `options`, store `f32`
    /// coordinates: binary STL and glTF (`.glb`, `.gltf`). Such files are
    /// written through [`crate::round_to_f32`].
    ///
    /// ```
    /// use umbra::{FileKind, MeshWriteOptions};
    /// let text = MeshWriteOptions { text: true };
    /// assert!(FileKind::Stl.stores_f32(MeshWriteOptions::default()));
    /// assert!(!FileKind::Stl.stores_f32(text));
    /// assert!(FileKind::Gltf.stores_f32(text));
    /// assert!(!FileKind::ThreeMf.stores_f32(MeshWriteOptions::default()));
    /// ```
    pub fn stores_f32(self, options: MeshWriteOptions) -> bool {
        match self {
            FileKind::Stl => !options.text,
            FileKind::Glb | FileKind::Gltf => true,
            _ => false,
        }
    }

    /// `true` if files of this kind can be read (all but `.svg`).
    pub fn can_read(self) -> bool {
        !matches!(self, FileKind::Svg)
    }
}

/// Reads a file as UTF-8 text (a leading byte-order mark dropped), naming
/// the file and `format` on failure.
pub(crate) fn read_text(path: &Path, format: &'static str) -> Result<String, UmbraError> {
    let bytes = read_bytes(path)?;
    let text = decode(&bytes, &path.display().to_string(), format)?;
    Ok(text.to_string())
}

/// The error for a file of the wrong dimension.
fn wrong_dimension(path: &Path, want: &str) -> UmbraError {
    wrong_dimension_of(&path.display().to_string(), want)
}

/// The error for a file of the other dimension (or a picture) where `want`
/// is expected, naming `file`.
pub(crate) fn wrong_dimension_of(file: &str, want: &str) -> UmbraError {
    UmbraError::UnsupportedFileType {
        file: file.to_string(),
        detail: format!("expected a {want} file here ({})", supported()),
    }
}

/// The error for reading a kind that is written only.
fn write_only(path: &Path, kind: FileKind) -> UmbraError {
    UmbraError::UnsupportedFileType {
        file: path.display().to_string(),
        detail: format!(
            "'.{}' ({}) can be written but not read ({})",
            kind.extension(),
            kind.name(),
            supported()
        ),
    }
}

/// Reads a 2D polygon set from a file whose format is decided by its
/// extension. The points and lines of a collection are skipped; see
/// [`read_polygon_set_counted`] for how many.
pub fn read_polygon_set(path: &Path, options: ReadOptions) -> Result<PolygonSet2, UmbraError> {
    read_polygon_set_counted(path, options).map(|r| r.set)
}

/// Reads a 2D polygon set from a file whose format is decided by its
/// extension, with the number of non-areal parts (points, lines) skipped
/// from its collections, for a front end to warn about. A file with no
/// polygonal part at all is [`UmbraError::UnsupportedGeometry`].
pub fn read_polygon_set_counted(
    path: &Path,
    options: ReadOptions,
) -> Result<PolygonSetRead, UmbraError> {
    let (set, skipped_non_areal) = match FileKind::from_path(path)? {
        FileKind::Wkt => read_wkt_file_counted(path, options)?,
        FileKind::GeoJson => read_geojson_file_counted(path, options)?,
        FileKind::Svg => return Err(write_only(path, FileKind::Svg)),
        _ => return Err(wrong_dimension(path, "2D (.wkt, .geojson)")),
    };
    Ok(PolygonSetRead {
        set,
        skipped_non_areal,
    })
}

/// Writes a 2D polygon set to a file whose format is decided by its
/// extension (`.wkt`, `.geojson`, `.svg`). Returns the number of orphan
/// holes of the by-role layout (see [`crate::PolygonLayout::orphan_holes`]).
pub fn write_polygon_set(
    path: &Path,
    set: &PolygonSet2,
    orientation: RingOrientation,
) -> Result<usize, UmbraError> {
    let kind = FileKind::from_path(path)?;
    let encoded = crate::encode_polygon_set(kind, set, orientation, &path.display().to_string())?;
    write_bytes(path, &encoded.bytes)?;
    Ok(encoded.orphan_holes)
}

/// Reads a 3D polygon mesh from an OBJ, OFF, STL, PLY, 3MF or glTF
/// (`.glb`, `.gltf`) file (by extension): coordinates validated if `options` asks, and the closure
/// constraints of section 4.2 checked when `check` is `true` (the first
/// violation is returned as [`UmbraError::InvalidMesh`] naming the file,
/// the face or vertex with its line or record, and for an open edge the
/// positions of its two vertices). STL and glTF triangles are welded by
/// exact position (see [`crate::parse_stl`] and [`crate::parse_glb`]); the
/// buffers of a `.gltf` may be files beside it, named by relative paths.
pub fn read_mesh(
    path: &Path,
    options: MeshReadOptions,
    check: bool,
) -> Result<PolygonMesh, UmbraError> {
    let kind = FileKind::from_path(path)?;
    if !kind.is_mesh() {
        return Err(wrong_dimension(
            path,
            "3D (.obj, .off, .stl, .ply, .3mf, .glb, .gltf)",
        ));
    }
    if !kind.can_read() {
        return Err(write_only(path, kind));
    }
    let file = path.display().to_string();
    let bytes = read_bytes(path)?;
    match kind {
        FileKind::Stl => read_stl_bytes(&bytes, &file, options, check),
        FileKind::Ply => read_ply_bytes(&bytes, &file, options, check),
        FileKind::Glb | FileKind::Gltf => {
            read_gltf_bytes(&bytes, &file, path.parent(), options, check)
        }
        FileKind::ThreeMf => read_3mf_bytes(&bytes, &file, options, check),
        _ => {
            let text = decode(&bytes, &file, kind.name())?;
            read_mesh_text(text, &file, kind == FileKind::Off, options, check)
        }
    }
}

/// Options for writing mesh files.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct MeshWriteOptions {
    /// Write STL and PLY as text (ASCII) instead of binary (the default).
    /// Other formats have one encoding.
    pub text: bool,
}

/// Writes a 3D polygon mesh to a file whose format is decided by its
/// extension, STL and PLY in binary (see [`write_mesh_with`]).
pub fn write_mesh(path: &Path, mesh: &PolygonMesh) -> Result<(), UmbraError> {
    write_mesh_with(path, mesh, MeshWriteOptions::default())
}

/// Writes a 3D polygon mesh as OBJ, OFF, STL, PLY, 3MF or glTF (`.glb`,
/// or `.gltf` with the buffer embedded; by extension). Facets with holes are written as their triangulation
/// (section 4.8); STL, 3MF and glTF hold triangles only, so every facet is
/// triangulated there. STL (binary) and glTF store `f32` coordinates,
/// rounded to nearest; the other formats keep every `f64` bit for bit.
pub fn write_mesh_with(
    path: &Path,
    mesh: &PolygonMesh,
    options: MeshWriteOptions,
) -> Result<(), UmbraError> {
    let kind = FileKind::from_path(path)?;
    let encoded = crate::encode_mesh_with(kind, mesh, options, &path.display().to_string())?;
    write_bytes(path, &encoded.bytes)
}

/// An error of a writer about `<output>`, renamed to `file`.
pub(crate) fn rename_output(e: UmbraError, file: &str) -> UmbraError {
    let file = file.to_string();
    match e {
        UmbraError::Unwritable {
            format, message, ..
        } => UmbraError::Unwritable {
            file,
            format,
            message,
        },
        UmbraError::InvalidShape { source, .. } => UmbraError::InvalidShape { file, source },
        other => other,
    }
}
