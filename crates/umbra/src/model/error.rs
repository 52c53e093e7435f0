//! The error type of modelling: bad primitive parameters, bad CSG scripts
//! (with the path of the offending node) and failed evaluations.

use boolean_3d::Boolean3Error;
use std::fmt;

/// An error of a primitive, a transform, a CSG script or its evaluation.
/// `Display` is one line.
#[derive(Debug)]
pub enum ModelError {
    /// A primitive or transform parameter is out of range: `param` names
    /// it (`sphere.segments`), `message` says what it must be.
    InvalidParameter {
        /// The parameter, as `shape.field`.
        param: String,
        /// What is wrong (`must be >= 3`).
        message: String,
    },
    /// A CSG script is not valid JSON (the message has line and column).
    Json {
        /// The script (a file name or `<string>`).
        file: String,
        /// The parser's message.
        message: String,
    },
    /// A CSG script is valid JSON but not a valid tree.
    Script {
        /// The script (a file name or `<string>`).
        file: String,
        /// The path of the offending node (`children[2].children[0]`, or
        /// `root`).
        node: String,
        /// What is wrong, one line.
        message: String,
    },
    /// A script file could not be read.
    Io {
        /// The file.
        file: String,
        /// The operating-system error.
        source: std::io::Error,
    },
    /// A `file` leaf could not be read (or the facade was built without
    /// the `io` feature).
    File {
        /// The node path.
        node: String,
        /// The reader's message.
        message: String,
    },
    /// A Boolean of the evaluation failed.
    Boolean {
        /// The path of the operation node.
        node: String,
        /// The error of the 3D Boolean.
        source: Boolean3Error,
    },
}

impl ModelError {
    pub(crate) fn param(param: impl Into<String>, message: impl Into<String>) -> Self {
        ModelError::InvalidParameter {
            param: param.into(),
            message: message.into(),
        }
    }
}

impl fmt::Display for ModelError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ModelError::InvalidParameter { param, message } => write!(f, "{param} {message}"),
            ModelError::Json { file, message } => write!(f, "{file}: invalid JSON: {message}"),
            ModelError::Script {
                file,
                node,
                message,
            } if file.is_empty() => write!(f, "{node}: {message}"),
            ModelError::Script {
                file,
                node,
                message,
            } => write!(f, "{file}: {node}: {message}"),
            ModelError::Io { file, source } => write!(f, "{file}: cannot read: {source}"),
            ModelError::File { node, message } => write!(f, "{node}: {message}"),
            ModelError::Boolean { node, source } => write!(f, "{node}: Boolean failed: {source}"),
        }
    }
}

/// No variant names a source: each message already ends with its cause
/// (one complete line), and a printer that also walks the chain would say
/// the cause twice.
impl std::error::Error for ModelError {}
