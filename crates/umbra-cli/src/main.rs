//! The `umbra` command-line tool, on the `umbra` facade only:
//!
//! ```text
//! umbra boolean <union|intersection|difference|xor> A B -o OUT [--report R.json]
//!       [--keep-orientation] [--via basic|simplify] [--triangulate]
//! umbra simplify IN -o OUT [--rule positive|nonzero|evenodd|negative|at-least-2]
//!       [--keep-orientation] [--report R.json]
//! umbra check IN [--json] [--keep-orientation]
//! ```
//!
//! The file extension decides the dimension: `.wkt` and `.geojson` are 2D
//! polygon sets (`.svg` written), `.obj`, `.off`, `.stl`, `.ply`, `.3mf`,
//! `.glb` and `.gltf` are 3D meshes. 2D Booleans run the basic
//! Boolean of chapter 4 by default and through simplification (chapter 6,
//! which also resolves self-intersecting input and offers `xor`) with
//! `--via simplify`; 3D Booleans run the polygon-mesh variant, or the
//! triangle-mesh variant with `--triangulate` or when the output format
//! holds triangles only (`.stl`, `.3mf`, `.glb`, `.gltf`; section 4.8: operands
//! that are not triangle meshes are triangulated by internal edges first).
//! The report's `variant` names the variant that ran.
//!
//! Every command computes everything and serializes every output to memory
//! before it writes anything, then writes all its files or none (see
//! `files.rs`); an output that is also an input or the report is refused.
//!
//! Exit codes: 0 success, 1 bad input or a failed write (a one-line message
//! on standard error naming the file and the problem), 2 usage error. A
//! closed standard output pipe is not an error (output stops quietly; the
//! exit code is unchanged); any other failure to write standard output
//! (`> /dev/full`) is exit 1.

#![forbid(unsafe_code)]

mod commands;
mod errors;
mod files;
mod progress;
mod stdout;

use clap::Parser;
use std::process::ExitCode;
use umbra::UmbraError;

/// The command line: its description ([`about`]) lists the formats.
#[derive(Parser, Debug)]
#[command(
    name = "umbra",
    version,
    propagate_version = true,
    about = about(),
    long_about = None
)]
struct Cli {
    #[command(subcommand)]
    command: commands::Command,
}

/// The first lines of `umbra --help`: what the tool does and every file
/// extension it reads or writes, from the table the format dispatch uses
/// ([`umbra::FileKind::supported_extensions`]).
fn about() -> String {
    format!(
        "Topologically robust Boolean operations on polygon sets and polyhedra (plain f64 arithmetic). The file extension decides the format: {}.",
        umbra::FileKind::supported_extensions()
    )
}

fn main() -> ExitCode {
    // A panic is a bug; report it on one line instead of a backtrace dump.
    std::panic::set_hook(Box::new(|info| {
        let msg = info
            .payload()
            .downcast_ref::<&str>()
            .map(|s| s.to_string())
            .or_else(|| info.payload().downcast_ref::<String>().cloned())
            .unwrap_or_default();
        let at = info
            .location()
            .map(|l| format!(" at {}:{}", l.file(), l.line()))
            .unwrap_or_default();
        stdout::error_line(&format!(
            "internal error (this is a bug, please report it): {msg}{at}"
        ));
    }));
    let cli = Cli::parse();
    match cli.command.run() {
        Ok(code) => code,
        Err(e) => {
            // An UmbraError's Display is already complete (file, problem
            // and cause on one line); other errors print their chain.
            let text = if e.downcast_ref::<UmbraError>().is_some() {
                format!("{e}")
            } else {
                format!("{e:#}")
            };
            stdout::error_line(&text);
            if e.downcast_ref::<errors::Usage>().is_some() {
                ExitCode::from(2)
            } else {
                ExitCode::from(1)
            }
        }
    }
}
