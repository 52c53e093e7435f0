//! The commands, one module each. A module holds a `#[derive(clap::Args)]`
//! struct whose `run(self)` does the work and returns the exit code;
//! adding a command is one new module and one line in the `commands!` list below.

use std::process::ExitCode;

/// Declares the command modules, the [`Command`] enum (one variant per
/// command, its help from the module's argument struct) and the dispatch.
macro_rules! commands {
    ($($variant:ident => $module:ident :: $args:ident),* $(,)?) => {
        $(pub mod $module;)*

        /// The command to run.
        #[derive(clap::Subcommand, Debug)]
        pub enum Command {
            $(
                #[allow(missing_docs)]
                $variant($module::$args),
            )*
        }

        impl Command {
            /// Runs the command: the exit code, or an error to print on
            /// one line (exit 1, or 2 for [`crate::errors::Usage`]).
            pub fn run(self) -> anyhow::Result<ExitCode> {
                match self {
                    $(Command::$variant(args) => args.run(),)*
                }
            }
        }
    };
}

commands! {
    Boolean => boolean::BooleanArgs,
    Simplify => simplify::SimplifyArgs,
    Check => check::CheckArgs,
    Csg => csg::CsgArgs,
    Demo => demo::DemoArgs,
    Render => render::RenderArgs,
    Smooth => smooth::SmoothArgs,
}

/// The ring orientation of `--keep-orientation`.
pub fn orientation(keep: bool) -> umbra::RingOrientation {
    if keep {
        umbra::RingOrientation::AsWritten
    } else {
        umbra::RingOrientation::ByRole
    }
}

/// Parses a smoothing tolerance (`--tol`, `--smooth`): a finite number
/// >= 0 (a usage error otherwise).
pub fn tolerance_arg(s: &str) -> Result<f64, String> {
    let t: f64 = s
        .trim()
        .parse()
        .map_err(|_| format!("'{s}' is not a number"))?;
    if t.is_finite() && t >= 0.0 {
        Ok(t)
    } else {
        Err(format!("the tolerance must be finite and >= 0, got '{s}'"))
    }
}

/// Smooths a CSG result once, at the end (the dissertation found one pass
/// at the end of a chain of Booleans cheaper than one per Boolean, section
/// 5.2): at `tolerance`, or by default at
/// [`umbra::DEFAULT_RELATIVE_TOLERANCE`] times the result's extent; a
/// tolerance of 0 leaves the result raw. Where the evaluation gathered
/// contacts at a proximity of at least the tolerance ([`csg_options`]),
/// only near them, as `umbra boolean` smooths (the same result when the
/// leaves need no smoothing themselves); else the whole mesh. A tree
/// without a Boolean cut nothing, so by default it is left as evaluated
/// (smoothing a lone primitive or file leaf whole would cost seconds on a
/// big one and change nothing a Boolean made); an explicit tolerance
/// still smooths it.
pub fn smooth_result(
    result: umbra::CsgResult,
    triangulate: bool,
    tolerance: Option<f64>,
) -> anyhow::Result<umbra::CsgResult> {
    if tolerance.is_none() && result.report.booleans == 0 {
        return Ok(result);
    }
    let tol = tolerance.unwrap_or_else(|| umbra::default_mesh_tolerance(&result.mesh));
    if tol <= 0.0 {
        return Ok(result);
    }
    let variant = if triangulate {
        umbra::MeshVariant::TriangleMesh
    } else {
        umbra::MeshVariant::PolygonMesh
    };
    let start = std::time::Instant::now();
    let options = umbra::SmoothOptions::new(tol).guarded();
    let (smoothed, near) =
        umbra::smooth_csg_result(&result, variant, &options).map_err(|source| {
            umbra::UmbraError::Smooth {
                file: String::new(),
                source,
            }
        })?;
    let report = result.report.smoothed(&smoothed, millis_since(start), near);
    Ok(umbra::CsgResult {
        mesh: smoothed.shape,
        report,
        contacts: None,
    })
}

/// The evaluation options of `umbra csg` and `umbra demo`: the variant,
/// contacts gathered for [`smooth_result`] unless smoothing is off
/// (`--smooth 0`), and intermediate results with coincident vertices
/// cleaned (the root's result is written raw with `--smooth 0`).
pub fn csg_options(triangulate: bool, smooth: Option<f64>) -> umbra::CsgOptions {
    umbra::CsgOptions {
        triangulate,
        contacts: match smooth {
            Some(t) if t <= 0.0 => None,
            t => Some(t.unwrap_or(0.0)),
        },
        raw_intermediates: false,
    }
}

/// Milliseconds since `start`.
pub fn millis_since(start: std::time::Instant) -> f64 {
    start.elapsed().as_secs_f64() * 1e3
}

/// Reads a 2D file ([`umbra::read_polygon_set_counted`]) and warns on
/// standard error, naming it, about the points and lines skipped from its
/// collections (GEOS and shapely overlays return them beside polygons).
pub fn read_set(
    path: &std::path::Path,
    options: umbra::ReadOptions,
) -> Result<umbra::PolygonSet2, umbra::UmbraError> {
    let read = umbra::read_polygon_set_counted(path, options)?;
    if let Some(warning) = read.warning(&path.display().to_string()) {
        crate::stdout::error_line(&format!("warning: {warning}"));
    }
    Ok(read.set)
}

/// Warns on standard error about holes written as exteriors.
pub fn warn_orphans(orphans: usize, out_path: &std::path::Path) {
    if orphans > 0 {
        crate::stdout::error_line(&format!(
            "warning: {}: {orphans} clockwise ring(s) lie inside no outer ring (inside-out result); rerun with --keep-orientation to keep their direction",
            out_path.display()
        ));
    }
}

/// Warns on standard error when rounding a mesh to the `f32` coordinates
/// of its format (binary STL, glTF) left intersecting facet pairs or
/// coinciding vertices in the file written (features thinner than the
/// `f32` spacing, which have no faithful `f32` form).
pub fn warn_f32_defects(rounding: &umbra::F32Rounding, out_path: &std::path::Path) {
    if rounding.pairs_left > 0 || rounding.collisions_left > 0 {
        crate::stdout::error_line(&format!(
            "warning: {}: rounding to f32 left {} intersecting facet pair(s) and {} pair(s) of coinciding vertices (features thinner than the f32 spacing); write .obj, .off, .ply, .3mf or --ascii .stl to keep every f64",
            out_path.display(),
            rounding.pairs_left,
            rounding.collisions_left
        ));
    }
}

/// The error for a result that is not topologically valid (a bug of the
/// algorithm: its output always satisfies the closure constraints).
pub fn invalid_result() -> anyhow::Error {
    anyhow::anyhow!(
        "internal error (this is a bug, please report it): the result is not topologically valid"
    )
}
