//! Draws the output size per step of the iterated-CSG chain (the slab
//! minus 1,000 boxes, one difference at a time) from the CSV the
//! `csg-chain` binary writes: facets (triangles for the triangle-mesh
//! variant) against the step, one line per variant, as a PNG for
//! `docs/performance.md`.
//!
//! ```text
//! cargo run --release -p umbra-benches --bin plot-chain -- \
//!     --csv docs/data/csg_chain.csv --out docs/images/csg_chain.png
//! ```

use plotters::prelude::*;
use std::path::PathBuf;

fn run() -> Result<(), String> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let value = |name: &str| umbra_benches::flag_value(&args, name);
    let csv = PathBuf::from(value("--csv").unwrap_or_else(|| "docs/data/csg_chain.csv".into()));
    let out = PathBuf::from(value("--out").unwrap_or_else(|| "docs/images/csg_chain.png".into()));
    let text = std::fs::read_to_string(&csv).map_err(|e| format!("{}: {e}", csv.display()))?;
    // step,variant,ms,facets,vertices,volume
    let mut series: Vec<(String, Vec<(f64, f64)>)> = Vec::new();
    for (i, line) in text.lines().enumerate().skip(1) {
        let f: Vec<&str> = line.split(',').collect();
        let bad = || {
            format!(
                "{}:{}: expected step,variant,ms,facets,...",
                csv.display(),
                i + 1
            )
        };
        if f.len() < 4 {
            return Err(bad());
        }
        let step: f64 = f[0].parse().map_err(|_| bad())?;
        let facets: f64 = f[3].parse().map_err(|_| bad())?;
        match series.iter_mut().find(|(v, _)| v == f[1]) {
            Some((_, pts)) => pts.push((step, facets)),
            None => series.push((f[1].to_string(), vec![(step, facets)])),
        }
    }
    let steps = series
        .iter()
        .flat_map(|(_, p)| p)
        .fold(1.0f64, |m, p| m.max(p.0));
    let most = series
        .iter()
        .flat_map(|(_, p)| p)
        .fold(1.0f64, |m, p| m.max(p.1));
    plotters::style::register_font("sans-serif", FontStyle::Normal, dejavu::sans::regular())
        .map_err(|_| "the embedded DejaVu Sans font was refused".to_string())?;
    let err = |e: &dyn std::fmt::Display| format!("{}: {e}", out.display());
    let root = BitMapBackend::new(&out, (960, 560)).into_drawing_area();
    root.fill(&WHITE).map_err(|e| err(&e))?;
    let mut chart = ChartBuilder::on(&root)
        .caption(
            "Slab minus 1,000 boxes, one difference per step: output size",
            ("sans-serif", 22),
        )
        .margin(16)
        .x_label_area_size(44)
        .y_label_area_size(80)
        .build_cartesian_2d(0.0..steps, 0.0..most * 1.1)
        .map_err(|e| err(&e))?;
    chart
        .configure_mesh()
        .x_desc("step (boxes subtracted)")
        .y_desc("facets / triangles")
        .label_style(("sans-serif", 15))
        .draw()
        .map_err(|e| err(&e))?;
    let colors = [
        RGBColor(31, 119, 180),
        RGBColor(255, 127, 14),
        RGBColor(44, 160, 44),
    ];
    for (i, (variant, pts)) in series.iter().enumerate() {
        let color = colors[i % colors.len()];
        chart
            .draw_series(LineSeries::new(pts.clone(), color.stroke_width(2)))
            .map_err(|e| err(&e))?
            .label(variant.as_str())
            .legend(move |(x, y)| {
                PathElement::new(vec![(x, y), (x + 24, y)], color.stroke_width(3))
            });
    }
    // The C++ Manifold's final triangle count on the same chain.
    let manifold = 20_012.0;
    chart
        .draw_series(LineSeries::new(
            vec![(0.0, manifold), (steps, manifold)],
            BLACK.mix(0.4).stroke_width(1),
        ))
        .map_err(|e| err(&e))?
        .label("C++ Manifold, final (20,012 triangles)")
        .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 24, y)], BLACK.mix(0.4)));
    chart
        .configure_series_labels()
        .position(SeriesLabelPosition::UpperLeft)
        .label_font(("sans-serif", 16))
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK)
        .draw()
        .map_err(|e| err(&e))?;
    root.present().map_err(|e| err(&e))?;
    Ok(())
}

fn main() {
    if let Err(e) = run() {
        eprintln!("plot-chain: {e}");
        std::process::exit(1);
    }
}
