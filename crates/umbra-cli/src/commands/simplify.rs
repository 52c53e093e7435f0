//! `umbra simplify IN -o OUT --rule R`: simplification of a 2D polygon
//! file by a winding-number fill rule (chapters 6-7).

use super::{invalid_result, millis_since, orientation, warn_orphans};
use crate::errors::{self, usage};
use crate::files::OutputArgs;
use crate::stdout::outln;
use clap::ValueEnum;
use std::path::PathBuf;
use std::process::ExitCode;
use std::time::Instant;
use umbra::{
    encode_polygon_set, simplify, FileKind, FillRule, ReadOptions, SetCounts,
    SimplifyReport,
};

/// Simplify a 2D polygon file by a winding-number fill rule (chapters
/// 6-7): the result is geometrically valid up to the reported epsilon.
#[derive(clap::Args, Debug)]
pub struct SimplifyArgs {
    /// The input file (.wkt or .geojson).
    input: PathBuf,
    #[command(flatten)]
    out: OutputArgs,
    /// Which winding numbers are inside.
    #[arg(long, value_enum, default_value = "positive")]
    rule: RuleArg,
    /// Read every ring as a directed loop exactly as written (winding
    /// rules on invalid input need it) and write loops as they are.
    #[arg(long)]
    keep_orientation: bool,
}

/// The fill rules of section 6.1.
#[derive(Clone, Copy, Debug, ValueEnum)]
enum RuleArg {
    /// Winding number > 0 (the standard form).
    Positive,
    /// Winding number != 0.
    Nonzero,
    /// Odd winding number.
    Evenodd,
    /// Winding number < 0 (inside-out regions).
    Negative,
    /// Winding number >= 2.
    #[value(name = "at-least-2")]
    AtLeast2,
}

impl RuleArg {
    fn rule(self) -> FillRule {
        match self {
            RuleArg::Positive => FillRule::Positive,
            RuleArg::Nonzero => FillRule::NonZero,
            RuleArg::Evenodd => FillRule::EvenOdd,
            RuleArg::Negative => FillRule::Negative,
            RuleArg::AtLeast2 => FillRule::AtLeast2,
        }
    }
}

impl SimplifyArgs {
    /// Checks the arguments, simplifies, writes the output (and the
    /// report) and prints a summary.
    pub fn run(self) -> anyhow::Result<ExitCode> {
        let (in_path, out_path) = (&self.input, &self.out.output);
        let in_kind = FileKind::from_path(in_path)?;
        let out_kind = FileKind::from_path(out_path)?;
        for kind in [in_kind, out_kind] {
            if kind.is_mesh() {
                return Err(usage("simplify works on 2D files (.wkt, .geojson)"));
            }
        }
        self.out.refuse_overlaps(&[("the input", in_path)])?;
        let keep = self.keep_orientation;
        let options = ReadOptions {
            orientation: orientation(keep),
            ..ReadOptions::default()
        };
        let set = super::read_set(in_path, options)?;
        let rule = self.rule.rule();
        let start = Instant::now();
        let result = simplify(&set, rule);
        let total = millis_since(start);
        let out = result.map_err(|e| errors::simplify(e, &[in_path]))?;
        let out_file = out_path.display().to_string();
        let encoded = encode_polygon_set(out_kind, &out.shape, orientation(keep), &out_file)?;
        let report = SimplifyReport::new(
            rule,
            keep,
            SetCounts::of_set(in_path.display().to_string(), &set),
            encoded.counts(out_file),
            &out,
            total,
        );
        self.out.write(&encoded.bytes, &report)?;
        warn_orphans(encoded.orphan_holes, out_path);
        outln!(
            "simplify ({}): {} vertices, {} rings, k_max {}, epsilon {:e}, {:.3} ms -> {}",
            report.rule,
            report.output.vertices,
            report.output.rings,
            report.k_max,
            report.epsilon,
            report.timings_ms.total,
            out_path.display()
        )?;
        if !report.topologically_valid {
            return Err(invalid_result());
        }
        Ok(ExitCode::SUCCESS)
    }
}
