//! `write-inputs-3d`: writes the 3D bench inputs as binary PLY files
//! (`double` coordinates, so every bit of the `f64` inputs survives) for
//! runs outside Rust, such as `benches/manifold3d/run.py` (the C++
//! Manifold through its Python package):
//!
//! - `sphere-a-N.ply`, `sphere-b-N.ply`: the operands of the sphere
//!   difference of `perf-table-3d` (`umbra_benches::solid::sphere_pair`) at
//!   each size `N` (triangles per operand);
//! - `spheres-K.ply`: the `K` overlapping spheres of `perf-table-nary` in
//!   one file (one connected component each);
//! - `slab.ply`, `boxes-K.ply`: the slab and its `K` boxes;
//! - `chain-slab.ply`, `chain-boxes-1000.ply`: the slab and the 1,000
//!   boxes of the iterated-CSG chain of `csg-chain`
//!   (`umbra_benches::chain`), the boxes in chain order, triangulated as
//!   the chain's triangle-mesh variant sees them.
//!
//! ```text
//! cargo run --release -p umbra-benches --bin write-inputs-3d -- [--sizes 2000,20000,200000,1000000] [--dir target/bench-inputs]
//! ```

use std::path::{Path, PathBuf};
use topology::{PolygonMesh, TriangleMesh};
use umbra_benches::batch::{slab_case, sphere_union_case};
use umbra_benches::chain;
use umbra_benches::solid::sphere_pair;

/// All meshes in one, vertex indices shifted.
fn merged(meshes: &[TriangleMesh]) -> PolygonMesh {
    let mut vertices = Vec::new();
    let mut triangles = Vec::new();
    for m in meshes {
        let base = vertices.len() as u32;
        vertices.extend_from_slice(&m.vertices);
        triangles.extend(m.triangles.iter().map(|t| t.map(|v| v + base)));
    }
    TriangleMesh::new(vertices, triangles).to_polygon_mesh()
}

fn write(dir: &Path, name: &str, mesh: &PolygonMesh) -> Result<(), String> {
    let path = dir.join(name);
    umbra::write_mesh(&path, mesh).map_err(|e| e.to_string())?;
    println!("{}", path.display());
    Ok(())
}

fn run() -> Result<(), String> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let value = |name: &str| umbra_benches::flag_value(&args, name);
    let sizes: Vec<usize> = value("--sizes")
        .unwrap_or_else(|| "2000,20000,200000,1000000".into())
        .split(',')
        .map(|s| s.trim().parse().map_err(|e| format!("--sizes: {e}")))
        .collect::<Result<_, _>>()?;
    let dir = PathBuf::from(value("--dir").unwrap_or_else(|| "target/bench-inputs".into()));
    std::fs::create_dir_all(&dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    for &n in &sizes {
        let (a, b) = sphere_pair(n);
        write(&dir, &format!("sphere-a-{n}.ply"), &a.to_polygon_mesh())?;
        write(&dir, &format!("sphere-b-{n}.ply"), &b.to_polygon_mesh())?;
    }
    let spheres = sphere_union_case(1000, 12);
    write(&dir, "spheres-1000.ply", &merged(&spheres.operands))?;
    let slab = slab_case(40, 25);
    if let Some(a) = &slab.minuend {
        write(&dir, "slab.ply", &a.to_polygon_mesh())?;
    }
    write(&dir, "boxes-1000.ply", &merged(&slab.operands))?;
    let chain_slab = umbra::triangulate_mesh(&chain::slab());
    write(&dir, "chain-slab.ply", &chain_slab.to_polygon_mesh())?;
    let chain_boxes: Vec<TriangleMesh> = chain::holes(chain::MAX_BOXES)
        .iter()
        .map(umbra::triangulate_mesh)
        .collect();
    write(&dir, "chain-boxes-1000.ply", &merged(&chain_boxes))?;
    Ok(())
}

fn main() {
    if let Err(e) = run() {
        eprintln!("write-inputs-3d: {e}");
        std::process::exit(1);
    }
}
