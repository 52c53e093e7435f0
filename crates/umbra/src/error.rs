//! The error type of the facade: what went wrong with which file.
//!
//! Every variant names the file (or `<string>` for in-memory text) and the
//! problem, and its `Display` is a single line, so the command-line tool can
//! print it as is.

use boolean_2d::BooleanError;
use boolean_3d::Boolean3Error;
use robust_arith::ArithError;
use simplify_2d::SimplifyError;
use smooth::SmoothError;
use std::fmt;
use topology::TopologyError;

/// An error of file input/output, parsing, or an operation run through the
/// facade.
#[derive(Debug)]
pub enum UmbraError {
    /// The file could not be read or written.
    Io {
        /// The file.
        file: String,
        /// What was attempted (`"read"` or `"write"`).
        action: &'static str,
        /// The operating-system error.
        source: std::io::Error,
    },
    /// The file extension names no supported format.
    UnsupportedFileType {
        /// The file.
        file: String,
        /// Why the type is not supported (one sentence).
        detail: String,
    },
    /// The file holds nothing but white space (an OBJ file: no comment or
    /// OBJ statement either; a PLY header: neither a vertex nor a face
    /// element). A well-formed file without facets is the empty mesh.
    Empty {
        /// The file.
        file: String,
    },
    /// The text is malformed or truncated.
    Parse {
        /// The file.
        file: String,
        /// What is wrong, one line.
        message: String,
    },
    /// The text is well-formed but holds a geometry that is not a polygon
    /// (a `POINT`, `LINESTRING`, ...), or 3D/measured coordinates.
    UnsupportedGeometry {
        /// The file.
        file: String,
        /// What was found instead of a 2D polygon.
        found: String,
    },
    /// A coordinate is NaN, infinite or beyond `f64::MAX / 4` (section 8.5).
    BadCoordinate {
        /// The file.
        file: String,
        /// Where the coordinate is (`polygon 1, ring 2, point 3`, 1-based).
        location: String,
        /// The axis (0 = x, 1 = y).
        axis: u8,
        /// What is wrong with the value.
        source: ArithError,
    },
    /// A shape violates a topological constraint of section 4.2 or has a
    /// bad coordinate (for shapes built in memory and handed to a writer).
    InvalidShape {
        /// The file (or `<output>`).
        file: String,
        /// The violated constraint.
        source: TopologyError,
    },
    /// A Boolean failed; the operands are named by file.
    Boolean {
        /// The file of the offending operand, or an empty string for an
        /// internal error.
        file: String,
        /// The error of the Boolean.
        source: BooleanError,
    },
    /// The text of a GeoJSON, OBJ or OFF file is malformed or truncated.
    Malformed {
        /// The file.
        file: String,
        /// The format (`"GeoJSON"`, `"OBJ"`, `"OFF"`).
        format: &'static str,
        /// What is wrong, one line.
        message: String,
    },
    /// A simplification or a Boolean through simplification failed.
    Simplify {
        /// The file of the offending input, or an empty string for an
        /// internal error.
        file: String,
        /// The error of the sweep.
        source: SimplifyError,
    },
    /// A 3D Boolean failed; the operands are named by file.
    Boolean3 {
        /// The file of the offending operand, or an empty string for an
        /// internal error.
        file: String,
        /// The error of the 3D Boolean.
        source: Boolean3Error,
    },
    /// Smoothing (Appendix A) failed; the shape is named by its file.
    Smooth {
        /// The file of the shape smoothed, or an empty string when it has
        /// none (an operation's result).
        file: String,
        /// The error of smoothing.
        source: SmoothError,
    },
    /// A mesh read from a file violates a constraint of section 4.2 or has
    /// a bad coordinate; the message says where in the file (1-based face
    /// and vertex numbers in the file's own numbering, with the line or
    /// record) and, for an open edge, the positions of its two vertices.
    InvalidMesh {
        /// The file.
        file: String,
        /// What is wrong and where, one line.
        message: String,
        /// The violated constraint as the topology check reports it
        /// (0-based indices of the mesh in memory).
        source: TopologyError,
    },
    /// A shape cannot be written in the requested format (a coordinate
    /// beyond the format's `f32` range, say).
    Unwritable {
        /// The file (or `<output>`).
        file: String,
        /// The format.
        format: &'static str,
        /// Why, one line.
        message: String,
    },
    /// An invariant of the facade failed: this is a bug, please report it.
    Internal(String),
}

impl fmt::Display for UmbraError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let text = match self {
            UmbraError::Io {
                file,
                action,
                source,
            } => format!("{file}: cannot {action} the file: {source}"),
            UmbraError::UnsupportedFileType { file, detail } => {
                format!("{file}: unsupported file type: {detail}")
            }
            UmbraError::Empty { file } => format!("{file}: the file is empty (no geometry)"),
            UmbraError::Parse { file, message } => format!("{file}: malformed WKT: {message}"),
            UmbraError::UnsupportedGeometry { file, found } => {
                format!("{file}: unsupported geometry: {found} (expected POLYGON or MULTIPOLYGON)")
            }
            UmbraError::BadCoordinate {
                file,
                location,
                axis,
                source,
            } => {
                let name = if *axis == 0 { "x" } else { "y" };
                format!("{file}: {location}: {name} {source}")
            }
            UmbraError::InvalidShape { file, source } => format!("{file}: invalid shape: {source}"),
            UmbraError::Boolean { file, source } => {
                if file.is_empty() {
                    format!("boolean: {source}")
                } else {
                    format!("{file}: {source}")
                }
            }
            UmbraError::Malformed {
                file,
                format,
                message,
            } => format!("{file}: malformed {format}: {message}"),
            UmbraError::Simplify { file, source } => {
                if file.is_empty() {
                    format!("simplify: {source}")
                } else {
                    format!("{file}: {source}")
                }
            }
            UmbraError::Boolean3 { file, source } => {
                if file.is_empty() {
                    format!("boolean: {source}")
                } else {
                    format!("{file}: {source}")
                }
            }
            UmbraError::Smooth { file, source } => {
                if file.is_empty() {
                    format!("smooth: {source}")
                } else {
                    format!("{file}: {source}")
                }
            }
            UmbraError::InvalidMesh { file, message, .. } => {
                format!("{file}: invalid shape: {message}")
            }
            UmbraError::Unwritable {
                file,
                format,
                message,
            } => format!("{file}: cannot write {format}: {message}"),
            UmbraError::Internal(msg) => {
                format!("internal error (this is a bug, please report it): {msg}")
            }
        };
        // One line, whatever a lower layer put in its message.
        f.write_str(&text.replace(['\n', '\r'], " "))
    }
}

impl std::error::Error for UmbraError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            UmbraError::Io { source, .. } => Some(source),
            UmbraError::BadCoordinate { source, .. } => Some(source),
            UmbraError::InvalidShape { source, .. } => Some(source),
            UmbraError::InvalidMesh { source, .. } => Some(source),
            UmbraError::Boolean { source, .. } => Some(source),
            UmbraError::Simplify { source, .. } => Some(source),
            UmbraError::Boolean3 { source, .. } => Some(source),
            UmbraError::Smooth { source, .. } => Some(source),
            _ => None,
        }
    }
}
