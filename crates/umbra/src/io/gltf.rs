//! glTF 2.0 writing, binary (`.glb`) and JSON (`.gltf`): one mesh of one
//! triangle primitive, positions (`VEC3` of `f32`, with the exact `min` and
//! `max` of the stored values the specification requires) and `u32`
//! indices, in a single buffer. In a `.glb` the JSON chunk is padded with
//! spaces and the binary chunk with zeros to 4-byte boundaries; a `.gltf`
//! carries the buffer in a base64 `data:` URI, so the document is one
//! self-contained file.
//!
//! Coordinates are rounded to the nearest `f32` (glTF positions are
//! `f32`); a coordinate beyond the `f32` range is an error. Polygon facets
//! are triangulated (section 4.8). glTF's y axis points up; the mesh's
//! coordinates are written as they are (z up), so a viewer shows the model
//! lying on its back unless it offers a z-up switch.

use super::stl::to_f32;
use crate::UmbraError;
use base64::Engine;
use serde_json::json;
use topology::PolygonMesh;

const FORMAT: &str = "glTF";
/// `ARRAY_BUFFER` and `ELEMENT_ARRAY_BUFFER`.
const VERTEX_TARGET: u32 = 34962;
const INDEX_TARGET: u32 = 34963;
/// `FLOAT` and `UNSIGNED_INT`.
const FLOAT: u32 = 5126;
const UNSIGNED_INT: u32 = 5125;

fn too_big(what: &str) -> UmbraError {
    UmbraError::Unwritable {
        file: "<output>".to_string(),
        format: FORMAT,
        message: format!("{what} exceeds the 4 GiB limit of a binary glTF file"),
    }
}

/// The document and the buffer of a mesh (see the module docs): no buffer
/// when the mesh has no triangle.
fn document(mesh: &PolygonMesh) -> Result<(serde_json::Value, Vec<u8>), UmbraError> {
    let tris = boolean_3d::triangulate_mesh(mesh);
    let mut bin: Vec<u8> = Vec::with_capacity(12 * tris.vertices.len() + 12 * tris.triangles.len());
    let mut min = [f32::INFINITY; 3];
    let mut max = [f32::NEG_INFINITY; 3];
    for (v, p) in tris.vertices.iter().enumerate() {
        for axis in 0..3 {
            let x = to_f32(p[axis], v, axis, FORMAT)?;
            min[axis] = min[axis].min(x);
            max[axis] = max[axis].max(x);
            bin.extend_from_slice(&x.to_le_bytes());
        }
    }
    let positions_len = bin.len();
    for t in &tris.triangles {
        for i in t {
            bin.extend_from_slice(&i.to_le_bytes());
        }
    }
    let indices_len = bin.len() - positions_len;
    let mut doc = json!({
        "asset": {"version": "2.0", "generator": "umbra"},
        "scene": 0,
        "scenes": [{"nodes": []}],
    });
    if !tris.triangles.is_empty() {
        doc["scenes"][0]["nodes"] = json!([0]);
        doc["nodes"] = json!([{"mesh": 0}]);
        doc["meshes"] =
            json!([{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "mode": 4}]}]);
        doc["buffers"] = json!([{"byteLength": bin.len()}]);
        doc["bufferViews"] = json!([
            {"buffer": 0, "byteOffset": 0, "byteLength": positions_len, "target": VERTEX_TARGET},
            {"buffer": 0, "byteOffset": positions_len, "byteLength": indices_len, "target": INDEX_TARGET},
        ]);
        doc["accessors"] = json!([
            {"bufferView": 0, "componentType": FLOAT, "count": tris.vertices.len(), "type": "VEC3",
             "min": min.map(f64::from), "max": max.map(f64::from)},
            {"bufferView": 1, "componentType": UNSIGNED_INT, "count": 3 * tris.triangles.len(), "type": "SCALAR"},
        ]);
    } else {
        bin.clear();
    }
    Ok((doc, bin))
}

/// The `.glb` bytes of a mesh (see the module docs).
pub fn mesh_to_glb(mesh: &PolygonMesh) -> Result<Vec<u8>, UmbraError> {
    let (doc, mut bin) = document(mesh)?;
    let mut json_bytes =
        serde_json::to_vec(&doc).map_err(|e| UmbraError::Internal(format!("glTF JSON: {e}")))?;
    while !json_bytes.len().is_multiple_of(4) {
        json_bytes.push(b' ');
    }
    while !bin.len().is_multiple_of(4) {
        bin.push(0);
    }
    let bin_chunk = if bin.is_empty() { 0 } else { 8 + bin.len() };
    let total = 12 + 8 + json_bytes.len() + bin_chunk;
    let total32 = u32::try_from(total).map_err(|_| too_big("the mesh"))?;
    let mut out = Vec::with_capacity(total);
    out.extend_from_slice(b"glTF");
    out.extend_from_slice(&2u32.to_le_bytes());
    out.extend_from_slice(&total32.to_le_bytes());
    out.extend_from_slice(&(json_bytes.len() as u32).to_le_bytes());
    out.extend_from_slice(b"JSON");
    out.extend_from_slice(&json_bytes);
    if !bin.is_empty() {
        out.extend_from_slice(&(bin.len() as u32).to_le_bytes());
        out.extend_from_slice(b"BIN\0");
        out.extend_from_slice(&bin);
    }
    Ok(out)
}

/// The `.gltf` bytes of a mesh (see the module docs): JSON text, the buffer
/// in a base64 `data:` URI.
///
/// ```
/// use umbra::{cuboid, mesh_to_gltf, DVec3};
/// let text = mesh_to_gltf(&cuboid(DVec3::ONE, true).unwrap()).unwrap();
/// let doc: serde_json::Value = serde_json::from_slice(&text).unwrap();
/// let uri = doc["buffers"][0]["uri"].as_str().unwrap();
/// assert!(uri.starts_with("data:application/octet-stream;base64,"));
/// ```
pub fn mesh_to_gltf(mesh: &PolygonMesh) -> Result<Vec<u8>, UmbraError> {
    let (mut doc, bin) = document(mesh)?;
    if !bin.is_empty() {
        let encoded = base64::engine::general_purpose::STANDARD.encode(&bin);
        doc["buffers"][0]["uri"] =
            serde_json::Value::String(format!("data:application/octet-stream;base64,{encoded}"));
    }
    let mut text =
        serde_json::to_vec(&doc).map_err(|e| UmbraError::Internal(format!("glTF JSON: {e}")))?;
    text.push(b'\n');
    Ok(text)
}
