//! Errors of the tool beyond the facade's [`umbra::UmbraError`]: usage
//! errors found after parsing (exit 2, like clap's own), and the facade's
//! operation errors with the offending operand named by its file.

use std::path::Path;
use umbra::{Boolean3Error, BooleanError, Operand, SimplifyError, UmbraError};

/// A usage error found after parsing: exit code 2.
#[derive(Debug)]
pub struct Usage(pub String);

impl std::fmt::Display for Usage {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for Usage {}

/// A [`Usage`] error as an `anyhow::Error`.
pub fn usage(msg: impl Into<String>) -> anyhow::Error {
    Usage(msg.into()).into()
}

/// The file of an operand (empty when the error names none).
fn operand_file(operand: Option<Operand>, files: [&Path; 2]) -> String {
    match operand {
        Some(Operand::A) => files[0].display().to_string(),
        Some(Operand::B) => files[1].display().to_string(),
        None => String::new(),
    }
}

/// A 2D basic Boolean error naming the operand's file.
pub fn boolean2(source: BooleanError, files: [&Path; 2]) -> UmbraError {
    let operand = match &source {
        BooleanError::InvalidInput { operand, .. } => Some(*operand),
        _ => None,
    };
    UmbraError::Boolean {
        file: operand_file(operand, files),
        source,
    }
}

/// A 3D Boolean error naming the operand's file.
pub fn boolean3(source: Boolean3Error, files: [&Path; 2]) -> UmbraError {
    let operand = match &source {
        Boolean3Error::InvalidInput { operand, .. } => Some(*operand),
        _ => None,
    };
    UmbraError::Boolean3 {
        file: operand_file(operand, files),
        source,
    }
}

/// A simplification error naming the input's file (`files[i]` for
/// operand `i`).
pub fn simplify(source: SimplifyError, files: &[&Path]) -> UmbraError {
    let file = match &source {
        SimplifyError::InvalidInput { operand, .. } => files
            .get(*operand)
            .map(|p| p.display().to_string())
            .unwrap_or_default(),
        SimplifyError::Internal(_) => String::new(),
    };
    UmbraError::Simplify { file, source }
}
