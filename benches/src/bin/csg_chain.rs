//! `csg-chain`: the iterated-CSG chain of issue 13, a 40 x 25 x 1 slab
//! minus 1,000 boxes one difference at a time, in the triangle-mesh and
//! the polygon-mesh variant. Prints the summed operation time, the final
//! size and volume of each variant, and writes the per-step counts as CSV
//! (`step,variant,ms,facets,vertices,volume`) for `docs/performance.md`.
//!
//! ```text
//! cargo run --release -p umbra-benches --bin csg-chain -- [--boxes 1000] [--variant both|tri|poly] [--csv docs/data/csg_chain.csv]
//! ```
//!
//! Every step's result is checked (topological validity, a triangle mesh
//! for the triangle-mesh variant, and the volume
//! `1000 - k / 4` within 1e-9 relative); a failed check ends the run with
//! an error. The last column says whether the final f64 volume is exactly
//! 750 (it is whenever every vertex stays on the boxes' dyadic grid).

use std::fmt::Write as _;
use umbra::MeshVariant;
use umbra_benches::chain::{expected_volume, run_chain, ChainMesh, MAX_BOXES};

type Result<T> = std::result::Result<T, Box<dyn std::error::Error>>;

fn next(args: &mut impl Iterator<Item = String>, what: &str) -> Result<String> {
    args.next()
        .ok_or_else(|| format!("{what}: missing value").into())
}

fn main() -> Result<()> {
    let mut boxes = MAX_BOXES;
    let mut variants = vec![MeshVariant::TriangleMesh, MeshVariant::PolygonMesh];
    let mut csv_path: Option<String> = None;
    let mut args = std::env::args().skip(1);
    while let Some(a) = args.next() {
        match a.as_str() {
            "--boxes" => boxes = next(&mut args, "--boxes N")?.parse()?,
            "--variant" => {
                variants = match next(&mut args, "--variant both|tri|poly")?.as_str() {
                    "both" => vec![MeshVariant::TriangleMesh, MeshVariant::PolygonMesh],
                    "tri" => vec![MeshVariant::TriangleMesh],
                    "poly" => vec![MeshVariant::PolygonMesh],
                    v => return Err(format!("unknown variant {v:?} (both, tri or poly)").into()),
                }
            }
            "--direct" => {
                let (ms, m) = umbra_benches::chain::run_chain_triangles(boxes)?;
                println!(
                    "direct boolean_triangles: {:.3} s, {} triangles",
                    ms / 1e3,
                    m.triangles.len()
                );
                return Ok(());
            }
            "--csv" => csv_path = Some(next(&mut args, "--csv PATH")?),
            _ => return Err(format!("unknown argument {a:?}").into()),
        }
    }
    let mut csv = String::from("step,variant,ms,facets,vertices,volume\n");
    println!("| variant | boxes | summed time | facets | vertices | volume | exact |");
    println!("|---|---|---|---|---|---|---|");
    for variant in variants {
        let name = match variant {
            MeshVariant::TriangleMesh => "triangle-mesh",
            MeshVariant::PolygonMesh => "polygon-mesh",
        };
        let mut total = 0.0;
        let mut last = None;
        let mut failure = None;
        let final_mesh = run_chain(variant, boxes, |s, mesh| {
            total += s.ms;
            let _ = writeln!(
                csv,
                "{},{name},{:.3},{},{},{}",
                s.step, s.ms, s.facets, s.vertices, s.volume
            );
            if s.step % 100 == 0 {
                eprintln!("{name}: step {} {} facets", s.step, s.facets);
            }
            if failure.is_none() {
                if let Err(e) = mesh.check_topology() {
                    failure = Some(format!("step {}: {e}", s.step));
                } else if variant == MeshVariant::TriangleMesh
                    && !matches!(mesh, ChainMesh::Triangles(_))
                {
                    failure = Some(format!("step {}: not a triangle mesh", s.step));
                } else if (s.volume - expected_volume(s.step)).abs() > 1e-9 * 1000.0 {
                    failure = Some(format!(
                        "step {}: volume {} instead of {}",
                        s.step,
                        s.volume,
                        expected_volume(s.step)
                    ));
                }
            }
            last = Some(*s);
        })?;
        if let ChainMesh::Polygons(final_mesh) = &final_mesh {
            // The triangulation of the final polygon mesh (its top and
            // bottom faces have `boxes` holes each), section 4.8.
            let t = std::time::Instant::now();
            let tri = umbra::triangulate_mesh(final_mesh);
            println!(
                "triangulate_mesh of the polygon result: {:.3} s, {} triangles, volume {}, {:?}",
                t.elapsed().as_secs_f64(),
                tri.triangles.len(),
                tri.signed_volume(),
                tri.check_topology()
            );
        }
        if let Some(f) = failure {
            return Err(format!("{name}: {f}").into());
        }
        if let Some(s) = last {
            println!(
                "| {name} | {boxes} | {:.3} s | {} | {} | {} | {} |",
                total / 1e3,
                s.facets,
                s.vertices,
                s.volume,
                s.volume == expected_volume(boxes)
            );
        }
    }
    if let Some(p) = csv_path {
        std::fs::write(&p, csv).map_err(|e| format!("writing {p}: {e}"))?;
    }
    Ok(())
}
