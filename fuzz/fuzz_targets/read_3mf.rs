//! Fuzz target: the 3MF reader (zip package, relationships, model XML,
//! components and build items) on any bytes never panics. An input that
//! does not start like a zip archive (`PK`) is taken for the model part's
//! XML and wrapped in a stored package first, so that mutations of the XML
//! reach the model reader (inside a package they would mostly break the
//! entry's checksum). A mesh that
//! reads is checked for closure (the linear `check_topology`), written in
//! every mesh format to a sink, and (when `mesh_to_3mf` accepts it: finite
//! coordinates and a proper triangle) written as 3MF and read back to the
//! same mesh bit for bit, without the triangles with a repeated corner,
//! which the writer leaves out as the specification wants.
#![no_main]

use libfuzzer_sys::fuzz_target;
use std::io::{Cursor, Write};
use umbra::{mesh_to_3mf, parse_3mf};
#[path = "common/io.rs"]
mod io;
use io::write_mesh_everywhere;
use test_support::canonical;

/// The most triangles checked, written and read back per input.
const LARGE: usize = 20_000;

/// A package holding `model` as `3D/3dmodel.model`, stored, without a
/// relationship part (the reader's default).
fn package_of(model: &[u8]) -> Vec<u8> {
    let mut zip = zip::ZipWriter::new(Cursor::new(Vec::new()));
    let options = zip::write::SimpleFileOptions::default()
        .compression_method(zip::CompressionMethod::Stored)
        .large_file(model.len() > u32::MAX as usize / 2);
    zip.start_file("3D/3dmodel.model", options).unwrap();
    zip.write_all(model).unwrap();
    zip.finish().unwrap().into_inner()
}

fuzz_target!(|data: &[u8]| {
    let wrapped;
    let package = if data.starts_with(b"PK") {
        data
    } else {
        wrapped = package_of(data);
        &wrapped
    };
    let Ok(tris) = parse_3mf(package, "fuzz.3mf") else {
        return;
    };
    // Instancing lets a small input expand to millions of triangles within
    // the reader's budget; checking and writing those takes seconds each,
    // so only the reading of such meshes is fuzzed.
    if tris.triangles.len() > LARGE {
        return;
    }
    let mesh = tris.to_polygon_mesh();
    let _ = mesh.check_topology();
    write_mesh_everywhere(&mesh);
    let Ok(bytes) = mesh_to_3mf(&mesh) else {
        return;
    };
    let back = parse_3mf(&bytes, "back.3mf").expect("written 3MF reads back");
    let bits = |m: &umbra::TriangleMesh| -> Vec<[u64; 3]> {
        m.vertices.iter().map(|p| p.map(f64::to_bits)).collect()
    };
    // The writer keeps every vertex (one object, one build item, no
    // transform), so the vertices come back as they are.
    assert_eq!(bits(&back), bits(&tris), "3MF round trip: vertices");
    let proper = io::proper_triangles(&tris);
    if proper.len() == tris.triangles.len() {
        assert_eq!(back.triangles, tris.triangles, "3MF round trip: triangles");
    } else {
        let kept = umbra::TriangleMesh::new(tris.vertices.clone(), proper);
        assert_eq!(
            canonical::triangles(&back),
            canonical::triangles(&kept),
            "3MF round trip without the degenerate triangles"
        );
    }
});
