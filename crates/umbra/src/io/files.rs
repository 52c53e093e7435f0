//! File types by extension and the format-independent read/write entry
//! points (the command-line tool goes through these). The extension decides
//! the dimension: `.wkt` and `.geojson` are 2D polygon sets,
//! `.obj` and `.off` are 3D meshes.

use super::geojson::{read_geojson_file, write_geojson_file};
use super::mesh_text::{read_mesh_text, write_mesh_file, MeshReadOptions};
use crate::{read_wkt_file, write_wkt_file, ReadOptions, RingOrientation, UmbraError};
use std::path::Path;
use topology::{PolygonMesh, PolygonSet2};

/// A supported file format, decided by the file extension.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum FileKind {
    /// Well-known text (`.wkt`): 2D polygon sets.
    Wkt,
    /// GeoJSON (`.geojson`, RFC 7946): 2D polygon sets.
    GeoJson,
    /// Wavefront OBJ (`.obj`): 3D polygon meshes.
    Obj,
    /// Object File Format (`.off`): 3D polygon meshes.
    Off,
}

const SUPPORTED: &str = "supported: .wkt .geojson (2D), .obj .off (3D)";

impl FileKind {
    /// The format of `path` by its extension (case-insensitive), or
    /// [`UmbraError::UnsupportedFileType`] naming the file.
    ///
    /// ```
    /// use std::path::Path;
    /// use umbra::FileKind;
    /// assert_eq!(FileKind::from_path(Path::new("shape.WKT")).unwrap(), FileKind::Wkt);
    /// assert!(FileKind::from_path(Path::new("part.off")).unwrap().is_mesh());
    /// assert!(FileKind::from_path(Path::new("shape.txt")).is_err());
    /// ```
    pub fn from_path(path: &Path) -> Result<FileKind, UmbraError> {
        let file = path.display().to_string();
        let ext = path
            .extension()
            .and_then(|e| e.to_str())
            .map(str::to_ascii_lowercase);
        let detail = match ext.as_deref() {
            Some("wkt") => return Ok(FileKind::Wkt),
            Some("geojson") => return Ok(FileKind::GeoJson),
            Some("obj") => return Ok(FileKind::Obj),
            Some("off") => return Ok(FileKind::Off),
            Some(e @ ("stl" | "ply" | "svg" | "png")) => {
                format!("'.{e}' is not supported yet ({SUPPORTED})")
            }
            Some(e) => format!("unknown extension '.{e}' ({SUPPORTED})"),
            None => format!("no file extension ({SUPPORTED})"),
        };
        Err(UmbraError::UnsupportedFileType { file, detail })
    }

    /// `true` for the 3D mesh formats.
    pub fn is_mesh(self) -> bool {
        matches!(self, FileKind::Obj | FileKind::Off)
    }
}

/// Reads a file as UTF-8 text, naming the file on failure.
pub(crate) fn read_text(path: &Path) -> Result<String, UmbraError> {
    let file = path.display().to_string();
    let bytes = std::fs::read(path).map_err(|source| UmbraError::Io {
        file: file.clone(),
        action: "read",
        source,
    })?;
    String::from_utf8(bytes).map_err(|e| UmbraError::Parse {
        file,
        message: format!(
            "not UTF-8 text (invalid byte at offset {})",
            e.utf8_error().valid_up_to()
        ),
    })
}

/// The error for a file of the wrong dimension.
fn wrong_dimension(path: &Path, want: &str) -> UmbraError {
    UmbraError::UnsupportedFileType {
        file: path.display().to_string(),
        detail: format!("expected a {want} file here ({SUPPORTED})"),
    }
}

/// Reads a 2D polygon set from a file whose format is decided by its
/// extension.
pub fn read_polygon_set(path: &Path, options: ReadOptions) -> Result<PolygonSet2, UmbraError> {
    match FileKind::from_path(path)? {
        FileKind::Wkt => read_wkt_file(path, options),
        FileKind::GeoJson => read_geojson_file(path, options),
        FileKind::Obj | FileKind::Off => Err(wrong_dimension(path, "2D (.wkt, .geojson)")),
    }
}

/// Writes a 2D polygon set to a file whose format is decided by its
/// extension. Returns the number of orphan holes of the by-role layout
/// (see [`crate::PolygonLayout::orphan_holes`]).
pub fn write_polygon_set(
    path: &Path,
    set: &PolygonSet2,
    orientation: RingOrientation,
) -> Result<usize, UmbraError> {
    match FileKind::from_path(path)? {
        FileKind::Wkt => write_wkt_file(path, set, orientation),
        FileKind::GeoJson => write_geojson_file(path, set, orientation),
        FileKind::Obj | FileKind::Off => Err(wrong_dimension(path, "2D (.wkt, .geojson)")),
    }
}

/// Reads a 3D polygon mesh from an OBJ or OFF file (by extension):
/// coordinates validated if `options` asks, and the closure constraints of
/// section 4.2 checked when `check` is `true` (the first violation is
/// returned as [`UmbraError::InvalidShape`] naming the file).
pub fn read_mesh(
    path: &Path,
    options: MeshReadOptions,
    check: bool,
) -> Result<PolygonMesh, UmbraError> {
    let kind = FileKind::from_path(path)?;
    if !kind.is_mesh() {
        return Err(wrong_dimension(path, "3D (.obj, .off)"));
    }
    let text = read_text(path)?;
    read_mesh_text(
        &text,
        &path.display().to_string(),
        kind == FileKind::Off,
        options,
        check,
    )
}

/// Writes a 3D polygon mesh as OBJ or OFF (by extension). Facets with holes
/// are written as their triangulation (section 4.8).
pub fn write_mesh(path: &Path, mesh: &PolygonMesh) -> Result<(), UmbraError> {
    match FileKind::from_path(path)? {
        FileKind::Obj => write_mesh_file(path, mesh, false),
        FileKind::Off => write_mesh_file(path, mesh, true),
        _ => Err(wrong_dimension(path, "3D (.obj, .off)")),
    }
}
