//! Fuzz target: the STL reader (binary and ASCII) on any bytes never
//! panics; a mesh that reads is checked for closure (the linear
//! `check_topology`: the self-intersection check, which is quadratic in
//! memory on large facets, is exercised by the `parse` target), written in
//! every mesh format to a sink, and (when its coordinates are finite)
//! written as ASCII STL and read back to the same welded mesh bit for bit
//! (without its triangles with a repeated corner, which writing drops).
#![no_main]

use libfuzzer_sys::fuzz_target;
use umbra::{mesh_to_stl, parse_stl};
#[path = "common/io.rs"]
mod io;
use io::write_mesh_everywhere;
use test_support::canonical;

fuzz_target!(|data: &[u8]| {
    let Ok(tris) = parse_stl(data, "fuzz.stl") else {
        return;
    };
    let mesh = tris.to_polygon_mesh();
    let _ = mesh.check_topology();
    write_mesh_everywhere(&mesh);
    if let Ok(text) = mesh_to_stl(&mesh, true) {
        let back = parse_stl(&text, "back.stl").expect("written STL reads back");
        // A triangle with a repeated corner (two corners welded to one
        // vertex) balances itself and triangulates to nothing (section
        // 4.8), so writing drops it: the proper triangles come back, the
        // same bit for bit (and numbered alike when none was dropped).
        let proper = io::proper_triangles(&tris);
        if proper.len() == tris.triangles.len() {
            assert_eq!(
                format!("{:?}", back.triangles),
                format!("{:?}", tris.triangles),
                "STL round trip"
            );
            let bits = |m: &umbra::TriangleMesh| -> Vec<[u64; 3]> {
                m.vertices.iter().map(|p| p.map(f64::to_bits)).collect()
            };
            assert_eq!(bits(&back), bits(&tris), "STL round trip");
        } else {
            let kept = umbra::TriangleMesh::new(tris.vertices.clone(), proper);
            assert_eq!(
                canonical::triangles(&back),
                canonical::triangles(&kept),
                "STL round trip without the degenerate triangles"
            );
        }
    }
});
