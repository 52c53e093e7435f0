//! Evaluates the demo process-plant scene and prints its size, validity
//! and timing: `cargo run --release -p umbra --example demo_plant [coarse]
//! [OUT.obj]`.

use std::io::Write;
use std::time::Instant;
use umbra::{demo_plant, evaluate_csg, CsgOptions, DemoDetail};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let detail = if args.iter().any(|a| a == "coarse") {
        DemoDetail::Coarse
    } else {
        DemoDetail::Full
    };
    let tree = demo_plant(detail);
    let start = Instant::now();
    let out = evaluate_csg(&tree, CsgOptions::default())?;
    let secs = start.elapsed().as_secs_f64();
    let r = &out.report;
    let mut stdout = std::io::stdout().lock();
    writeln!(
        stdout,
        "{detail:?}: {} Booleans over {} leaves in {secs:.2} s on {} threads; {} vertices, {} facets, valid {}, open edges {:?}, non-manifold edges {:?}, volume {:.4} m^3",
        r.booleans, r.leaves, r.threads, r.vertices, r.facets, r.topologically_valid, r.open_edges, r.non_manifold_edges, r.volume
    )?;
    let mut slow: Vec<_> = r.nodes.iter().filter(|n| n.booleans > 0).collect();
    slow.sort_by(|a, b| b.ms.total_cmp(&a.ms));
    for n in slow.iter().take(5) {
        println!(
            "  {:8.1} ms  {} {} ({} facets)",
            n.ms, n.path, n.kind, n.facets
        );
    }
    if let Some(path) = args.iter().find(|a| a.ends_with(".obj")) {
        umbra::write_mesh(std::path::Path::new(path), &out.mesh)?;
    }
    Ok(())
}
