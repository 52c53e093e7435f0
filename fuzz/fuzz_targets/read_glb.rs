//! Fuzz target: the glTF reader (binary or JSON, buffers in the binary
//! chunk or in base64 data URIs) on any bytes never panics and never
//! places more than its triangle budget; a mesh that reads is checked for
//! closure (the linear `check_topology`), written in every mesh format to
//! a sink, and (when every coordinate is an `f32` value, as untransformed
//! positions are) written as `.glb` and as `.gltf` and each read back to
//! the same triangles by position (without the triangles with a repeated
//! corner, which writing drops).
#![no_main]

use libfuzzer_sys::fuzz_target;
use umbra::{mesh_to_glb, mesh_to_gltf, parse_glb, TriangleMesh};
#[path = "common/io.rs"]
mod io;
use io::write_mesh_everywhere;
use test_support::canonical;

fuzz_target!(|data: &[u8]| {
    let Ok(tris) = parse_glb(data, "fuzz.glb") else {
        return;
    };
    assert!(tris.triangles.len() <= 1 << 25, "triangle budget");
    let mesh = tris.to_polygon_mesh();
    let _ = mesh.check_topology();
    write_mesh_everywhere(&mesh);
    let exact = tris
        .vertices
        .iter()
        .flatten()
        .all(|&x| x.is_finite() && f64::from(x as f32) == x);
    let proper = io::proper_triangles(&tris);
    if !exact || proper.is_empty() {
        return;
    }
    let kept = TriangleMesh::new(tris.vertices.clone(), proper);
    let glb = mesh_to_glb(&mesh).expect("f32 coordinates are written");
    let gltf = mesh_to_gltf(&mesh).expect("f32 coordinates are written");
    for bytes in [glb, gltf] {
        let back = parse_glb(&bytes, "back.gltf").expect("written glTF reads back");
        assert_eq!(
            canonical::triangles(&back),
            canonical::triangles(&kept),
            "glTF round trip"
        );
    }
});
