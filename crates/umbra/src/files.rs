//! File types by extension and the format-independent read/write entry
//! points (the command-line tool goes through these).

use crate::{read_wkt_file, write_wkt_file, ReadOptions, RingOrientation, UmbraError};
use std::path::Path;
use topology::PolygonSet2;

/// A supported file format, decided by the file extension.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum FileKind {
    /// Well-known text (`.wkt`): 2D polygon sets.
    Wkt,
}

impl FileKind {
    /// The format of `path` by its extension (case-insensitive), or
    /// [`UmbraError::UnsupportedFileType`] naming the file.
    ///
    /// ```
    /// use std::path::Path;
    /// use umbra::FileKind;
    /// assert_eq!(FileKind::from_path(Path::new("shape.WKT")).unwrap(), FileKind::Wkt);
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
            Some(e @ ("geojson" | "obj" | "off" | "stl" | "ply" | "svg" | "png")) => {
                format!("'.{e}' is not supported yet (supported: .wkt)")
            }
            Some(e) => format!("unknown extension '.{e}' (supported: .wkt)"),
            None => "no file extension (supported: .wkt)".to_string(),
        };
        Err(UmbraError::UnsupportedFileType { file, detail })
    }
}

/// Reads a 2D polygon set from a file whose format is decided by its
/// extension.
pub fn read_polygon_set(path: &Path, options: ReadOptions) -> Result<PolygonSet2, UmbraError> {
    match FileKind::from_path(path)? {
        FileKind::Wkt => read_wkt_file(path, options),
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
    }
}
