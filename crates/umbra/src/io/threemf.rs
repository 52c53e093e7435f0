//! 3MF writing (3D Manufacturing Format, core specification): a zip
//! package holding the content types, the package relationship and the
//! model part `3D/3dmodel.model`, an XML document with one mesh object
//! (vertices and triangles) and a build item.
//!
//! Every value written into the XML is a number, so no text needs escaping
//! and no XML library is needed. Coordinates are written as the shortest
//! decimal that reads back to the same `f64`. Polygon facets are
//! triangulated (section 4.8); triangles with a repeated vertex index,
//! which the specification forbids, are left out (their half-edges pair up
//! with each other, so closure is kept).

use super::text::push_f64;
use crate::UmbraError;
use std::fmt::Write as _;
use std::io::{Cursor, Write};
use topology::{PolygonMesh, TriangleMesh};
use zip::write::SimpleFileOptions;
use zip::{CompressionMethod, ZipWriter};

const FORMAT: &str = "3MF";

const CONTENT_TYPES: &str = r#"<?xml version="1.0" encoding="UTF-8"?>
<Types xmlns="http://schemas.openxmlformats.org/package/2006/content-types"><Default Extension="rels" ContentType="application/vnd.openxmlformats-package.relationships+xml"/><Default Extension="model" ContentType="application/vnd.ms-package.3dmanufacturing-3dmodel+xml"/></Types>
"#;

const RELS: &str = r#"<?xml version="1.0" encoding="UTF-8"?>
<Relationships xmlns="http://schemas.openxmlformats.org/package/2006/relationships"><Relationship Target="/3D/3dmodel.model" Id="rel0" Type="http://schemas.microsoft.com/3dmanufacturing/2013/01/3dmodel"/></Relationships>
"#;

/// The triangles a 3MF file of `mesh` holds: its facets triangulated
/// (section 4.8), every vertex kept, the triangles with a repeated vertex
/// index left out (see the module docs).
pub(crate) fn triangles_3mf(mesh: &PolygonMesh) -> TriangleMesh {
    let mut tris = boolean_3d::triangulate_mesh(mesh);
    tris.triangles
        .retain(|t| t[0] != t[1] && t[1] != t[2] && t[2] != t[0]);
    tris
}

/// The model part's XML text of [`triangles_3mf`] (see the module docs).
pub(crate) fn model_xml(tris: &TriangleMesh) -> Result<String, UmbraError> {
    if !tris
        .triangles
        .iter()
        .any(|t| t[0] != t[1] && t[1] != t[2] && t[2] != t[0])
    {
        return Err(UmbraError::Unwritable {
            file: "<output>".to_string(),
            format: FORMAT,
            message: "a 3MF mesh object needs at least one triangle of three distinct vertices"
                .to_string(),
        });
    }
    let mut s = String::with_capacity(128 + 60 * tris.vertices.len() + 50 * tris.triangles.len());
    s.push_str("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<model unit=\"millimeter\" xml:lang=\"en-US\" xmlns=\"http://schemas.microsoft.com/3dmanufacturing/core/2015/02\">\n <metadata name=\"Application\">umbra</metadata>\n <resources>\n  <object id=\"1\" type=\"model\">\n   <mesh>\n    <vertices>\n");
    for (v, p) in tris.vertices.iter().enumerate() {
        s.push_str("     <vertex");
        for (axis, (name, &x)) in ["x", "y", "z"].iter().zip(p).enumerate() {
            if !x.is_finite() {
                return Err(UmbraError::Unwritable {
                    file: "<output>".to_string(),
                    format: FORMAT,
                    message: format!("vertex {v}: {} = {x} is not finite", ["x", "y", "z"][axis]),
                });
            }
            let _ = write!(s, " {name}=\"");
            push_f64(&mut s, x);
            s.push('"');
        }
        s.push_str("/>\n");
    }
    s.push_str("    </vertices>\n    <triangles>\n");
    for t in &tris.triangles {
        let _ = writeln!(
            s,
            "     <triangle v1=\"{}\" v2=\"{}\" v3=\"{}\"/>",
            t[0], t[1], t[2]
        );
    }
    s.push_str("    </triangles>\n   </mesh>\n  </object>\n </resources>\n <build>\n  <item objectid=\"1\"/>\n </build>\n</model>\n");
    Ok(s)
}

/// The 3MF package (zip bytes) of a mesh. Fails on a NaN or infinite
/// coordinate and on a mesh without a proper triangle (the specification
/// wants at least one).
pub fn mesh_to_3mf(mesh: &PolygonMesh) -> Result<Vec<u8>, UmbraError> {
    triangles_to_3mf(&triangles_3mf(mesh))
}

/// [`mesh_to_3mf`] of [`triangles_3mf`] already made.
pub(crate) fn triangles_to_3mf(tris: &TriangleMesh) -> Result<Vec<u8>, UmbraError> {
    let model = model_xml(tris)?;
    let zip_error = |e: &dyn std::fmt::Display| UmbraError::Unwritable {
        file: "<output>".to_string(),
        format: FORMAT,
        message: format!("zip: {e}"),
    };
    let mut zip = ZipWriter::new(Cursor::new(Vec::new()));
    let options = SimpleFileOptions::default()
        .compression_method(CompressionMethod::Deflated)
        .large_file(model.len() > u32::MAX as usize / 2);
    for (name, text) in [
        ("[Content_Types].xml", CONTENT_TYPES),
        ("_rels/.rels", RELS),
        ("3D/3dmodel.model", model.as_str()),
    ] {
        zip.start_file(name, options).map_err(|e| zip_error(&e))?;
        zip.write_all(text.as_bytes()).map_err(|e| zip_error(&e))?;
    }
    let cursor = zip.finish().map_err(|e| zip_error(&e))?;
    Ok(cursor.into_inner())
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::io::Read;
    use topology::Facet;

    #[test]
    fn package_holds_the_model() {
        let mesh = PolygonMesh::new(
            vec![
                [0.0, 0.0, 0.0],
                [1.0, 0.0, 0.0],
                [0.0, 1.0, 0.0],
                [0.1, 0.1, 1e-300],
            ],
            vec![
                Facet::from_loop(&[0, 2, 1]),
                Facet::from_loop(&[0, 1, 3]),
                Facet::from_loop(&[1, 2, 3]),
                Facet::from_loop(&[0, 3, 2]),
            ],
        );
        let bytes = mesh_to_3mf(&mesh).unwrap();
        let mut archive = zip::ZipArchive::new(Cursor::new(bytes)).unwrap();
        let mut names: Vec<String> = archive
            .file_names()
            .map(|n| n.unwrap().to_string())
            .collect();
        names.sort();
        assert_eq!(
            names,
            ["3D/3dmodel.model", "[Content_Types].xml", "_rels/.rels"]
        );
        let mut model = String::new();
        archive
            .by_name("3D/3dmodel.model")
            .unwrap()
            .read_to_string(&mut model)
            .unwrap();
        assert_eq!(model.matches("<vertex ").count(), 4);
        assert_eq!(model.matches("<triangle ").count(), 4);
        assert!(
            model.contains("<vertex x=\"0.1\" y=\"0.1\" z=\"1e-300\"/>"),
            "{model}"
        );
        assert!(
            model.contains("<triangle v1=\"0\" v2=\"2\" v3=\"1\"/>"),
            "{model}"
        );
    }

    #[test]
    fn empty_and_non_finite_are_refused() {
        let e = mesh_to_3mf(&PolygonMesh::default())
            .unwrap_err()
            .to_string();
        assert!(e.contains("at least one triangle"), "{e}");
        let mesh = PolygonMesh::new(
            vec![[f64::NAN, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]],
            vec![Facet::from_loop(&[0, 1, 2])],
        );
        let e = mesh_to_3mf(&mesh).unwrap_err().to_string();
        assert!(e.contains("cannot write 3MF: vertex 0: x = NaN"), "{e}");
    }
}
