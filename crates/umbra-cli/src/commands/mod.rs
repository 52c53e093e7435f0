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
}

/// The ring orientation of `--keep-orientation`.
pub fn orientation(keep: bool) -> umbra::RingOrientation {
    if keep {
        umbra::RingOrientation::AsWritten
    } else {
        umbra::RingOrientation::ByRole
    }
}

/// Milliseconds since `start`.
pub fn millis_since(start: std::time::Instant) -> f64 {
    start.elapsed().as_secs_f64() * 1e3
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

/// The error for a result that is not topologically valid (a bug of the
/// algorithm: its output always satisfies the closure constraints).
pub fn invalid_result() -> anyhow::Error {
    anyhow::anyhow!(
        "internal error (this is a bug, please report it): the result is not topologically valid"
    )
}
