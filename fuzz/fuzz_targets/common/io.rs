//! Shared by the reader fuzz targets (included with `#[path]`, since the
//! targets' library is kept by the other targets): write a mesh that was
//! read in every mesh format to a sink, so the writers' error paths run on
//! whatever the readers accept.

use std::io::Write;
use umbra::{
    mesh_to_3mf, mesh_to_glb, mesh_to_obj, mesh_to_off, mesh_to_ply, mesh_to_stl, PolygonMesh,
};

/// Writes `mesh` as OBJ, OFF, PLY, STL (both encodings), 3MF and GLB to a
/// sink; a writer may refuse (a coordinate beyond `f32`, say) but never
/// panics. Returns `true` if the mesh should read back bit for bit from
/// the formats that keep `f64` (every coordinate finite, every facet one
/// loop through distinct vertices).
pub fn write_mesh_everywhere(mesh: &PolygonMesh) -> bool {
    let mut sink = std::io::sink();
    sink.write_all(mesh_to_obj(mesh).as_bytes()).unwrap();
    sink.write_all(mesh_to_off(mesh).as_bytes()).unwrap();
    for text in [false, true] {
        sink.write_all(&mesh_to_ply(mesh, text)).unwrap();
        if let Ok(bytes) = mesh_to_stl(mesh, text) {
            sink.write_all(&bytes).unwrap();
        }
    }
    if let Ok(bytes) = mesh_to_3mf(mesh) {
        sink.write_all(&bytes).unwrap();
    }
    if let Ok(bytes) = mesh_to_glb(mesh) {
        sink.write_all(&bytes).unwrap();
    }
    let finite = mesh.vertices.iter().flatten().all(|x| x.is_finite());
    let simple = mesh.facets.iter().all(|f| {
        let mut starts: Vec<u32> = f.half_edges.iter().map(|h| h.start).collect();
        starts.sort_unstable();
        starts.dedup();
        starts.len() == f.half_edges.len() && f.loops().len() == 1
    });
    finite && simple
}

/// The triangles of `mesh` without a repeated corner: what every mesh
/// writer keeps (such a triangle balances itself and triangulates to
/// nothing, section 4.8), so what a written file reads back as.
#[allow(dead_code)] // Not every target that includes this module calls it.
pub fn proper_triangles(mesh: &umbra::TriangleMesh) -> Vec<[u32; 3]> {
    mesh.triangles
        .iter()
        .copied()
        .filter(|t| t[0] != t[1] && t[1] != t[2] && t[2] != t[0])
        .collect()
}
