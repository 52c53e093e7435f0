//! OBJ and OFF reading and writing of polygon meshes.
//!
//! OBJ: `v x y z [w]` vertices and `f` faces with `i`, `i/t`, `i//n` or
//! `i/t/n` references (1-based, negative = relative to the vertices read so
//! far); polygon faces are kept as facets. Other statements (`vt`, `vn`,
//! `o`, `g`, `s`, `usemtl`, `mtllib`, `l`, `p`, ...) and `#` comments are
//! ignored. OFF: the `OFF` header (or `COFF`/`NOFF`/`CNOFF`), optional `#`
//! comments, the counts line, the vertices and the faces (`k i1 .. ik`,
//! 0-based, any trailing colour values ignored). Text with a control
//! character other than whitespace is rejected as binary data; a leading
//! UTF-8 byte-order mark is dropped. A literal too large for `f64`
//! (`1e400`) is an error naming it, not an infinity.
//!
//! A reader only parses: indices out of range are left in the mesh so that
//! [`topology::PolygonMesh::check_topology`] names them (dangling index,
//! facet or shape boundary closure, section 4.2) in the file's terms: faces
//! counted from 1 with their line, vertices in the file's numbering.
//! Coordinates are validated on request ([`MeshReadOptions`]).
//!
//! Writers print coordinates in the shortest form that reads back to the
//! same `f64`. OBJ and OFF faces have no holes, so a facet with several
//! loops is written as its triangulation by internal edges only (section
//! 4.8), which keeps the mesh closed.

use super::origin::{finish, refuse_vertices_alone, Origins};
use super::text::{parse_number, shorten, strip_bom};
use crate::UmbraError;
use boolean_3d::triangulate_facet;
use robust_arith::Point3;
use std::fmt::Write as _;
use topology::{Facet, HalfEdge, PolygonMesh};

/// Options for reading mesh files.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct MeshReadOptions {
    /// Reject NaN, infinite and out-of-range coordinates (`true` by
    /// default). `umbra check` turns it off to report them instead.
    pub validate_coordinates: bool,
}

impl Default for MeshReadOptions {
    fn default() -> Self {
        MeshReadOptions {
            validate_coordinates: true,
        }
    }
}

/// At most this many vertices or faces (indices are `u32`).
const MAX_COUNT: usize = (u32::MAX / 2) as usize;

fn malformed(
    file: &str,
    format: &'static str,
    line: usize,
    message: impl Into<String>,
) -> UmbraError {
    let message = message.into();
    UmbraError::Malformed {
        file: file.to_string(),
        format,
        message: if line > 0 {
            format!("line {line}: {message}")
        } else {
            message
        },
    }
}

fn parse_f64(
    token: &str,
    file: &str,
    format: &'static str,
    line: usize,
) -> Result<f64, UmbraError> {
    parse_number(token).map_err(|message| malformed(file, format, line, message))
}

/// Rejects text holding an ASCII control character other than whitespace
/// (tab, line feed, vertical tab, form feed, carriage return): such a file
/// is binary data (a binary STL or PLY under another name, say) that
/// happens to be valid UTF-8, and reading only the lines that look like
/// statements would turn it into a mesh of whatever they say.
fn reject_binary(text: &str, file: &str, format: &'static str) -> Result<(), UmbraError> {
    let bad = |b: u8| (b < 0x20 && !matches!(b, b'\t' | b'\n' | 0x0b | 0x0c | b'\r')) || b == 0x7f;
    match text.bytes().position(bad) {
        None => Ok(()),
        Some(at) => {
            let line = 1 + text.as_bytes()[..at]
                .iter()
                .filter(|&&b| b == b'\n')
                .count();
            Err(malformed(
                file,
                format,
                line,
                format!(
                    "binary data (control byte 0x{:02x}), not a text {format} file",
                    text.as_bytes()[at]
                ),
            ))
        }
    }
}

/// Parses OBJ text into a polygon mesh (unchecked; see the module docs).
pub fn parse_obj(text: &str, file: &str) -> Result<PolygonMesh, UmbraError> {
    parse_obj_with_origins(text, file).map(|(mesh, _)| mesh)
}

/// [`parse_obj`] with the line of every vertex and face.
pub(crate) fn parse_obj_with_origins(
    text: &str,
    file: &str,
) -> Result<(PolygonMesh, Origins), UmbraError> {
    const F: &str = "OBJ";
    let text = strip_bom(text);
    reject_binary(text, file, F)?;
    let mut origins = Origins::new(1, "face", "line");
    let mut vertices: Vec<Point3> = Vec::new();
    let mut facets: Vec<Facet> = Vec::new();
    let mut loop_: Vec<u32> = Vec::new();
    // Whether any line is a comment or an OBJ statement: a file of those
    // without vertices or faces (the writer's empty mesh) is the empty
    // mesh, a file of anything else is no OBJ at all.
    let mut saw_obj = false;
    for (i, raw) in text.lines().enumerate() {
        let line_no = i + 1;
        let line = raw.split('#').next().unwrap_or("");
        let mut tokens = line.split_whitespace();
        let first = tokens.next();
        saw_obj |= raw.trim_start().starts_with('#') || first.is_some_and(is_obj_statement);
        match first {
            Some("v") => {
                let mut p = [0.0; 3];
                for slot in &mut p {
                    let t = tokens.next().ok_or_else(|| {
                        malformed(file, F, line_no, "a vertex needs 3 coordinates")
                    })?;
                    *slot = parse_f64(t, file, F, line_no)?;
                }
                // An optional weight w (and, in some files, colours) follow.
                for t in tokens {
                    parse_f64(t, file, F, line_no)?;
                }
                if vertices.len() >= MAX_COUNT {
                    return Err(malformed(file, F, line_no, "too many vertices"));
                }
                vertices.push(p);
                origins.vertex_places.push(line_no as u32);
            }
            Some("f") => {
                loop_.clear();
                for t in tokens {
                    let index = t.split('/').next().unwrap_or("");
                    let k: i64 = index.parse().map_err(|_| {
                        malformed(
                            file,
                            F,
                            line_no,
                            format!("'{}' is not a vertex reference", shorten(t)),
                        )
                    })?;
                    let v = match k {
                        0 => {
                            return Err(malformed(
                                file,
                                F,
                                line_no,
                                "vertex reference 0 (OBJ indices start at 1)",
                            ))
                        }
                        k if k > 0 => k - 1,
                        k => vertices.len() as i64 + k,
                    };
                    if v < 0 || v > i64::from(u32::MAX) {
                        return Err(malformed(
                            file,
                            F,
                            line_no,
                            format!(
                                "vertex reference {k} is out of range ({} vertices so far)",
                                vertices.len()
                            ),
                        ));
                    }
                    loop_.push(v as u32);
                }
                if loop_.len() < 3 {
                    return Err(malformed(
                        file,
                        F,
                        line_no,
                        "a face needs at least 3 vertices",
                    ));
                }
                if facets.len() >= MAX_COUNT {
                    return Err(malformed(file, F, line_no, "too many faces"));
                }
                facets.push(Facet::from_loop(&loop_));
                origins.face_places.push(line_no as u32);
            }
            _ => {}
        }
    }
    if !saw_obj {
        return Err(UmbraError::Empty {
            file: file.to_string(),
        });
    }
    refuse_vertices_alone(vertices.len(), facets.len(), &origins, file, F)?;
    Ok((PolygonMesh::new(vertices, facets), origins))
}

/// The keywords of OBJ's geometry, grouping and material statements.
fn is_obj_statement(word: &str) -> bool {
    matches!(
        word,
        "v" | "vt" | "vn" | "vp" | "f" | "l" | "p" | "o" | "g" | "s" | "mg" | "usemtl" | "mtllib"
    )
}

/// Parses OFF text into a polygon mesh (unchecked; see the module docs).
pub fn parse_off(text: &str, file: &str) -> Result<PolygonMesh, UmbraError> {
    parse_off_with_origins(text, file).map(|(mesh, _)| mesh)
}

/// [`parse_off`] with the line of every vertex and face.
pub(crate) fn parse_off_with_origins(
    text: &str,
    file: &str,
) -> Result<(PolygonMesh, Origins), UmbraError> {
    const F: &str = "OFF";
    let text = strip_bom(text);
    reject_binary(text, file, F)?;
    let mut origins = Origins::new(0, "face", "line");
    // Tokens with their line numbers, comments removed.
    let mut lines = text
        .lines()
        .enumerate()
        .map(|(i, l)| (i + 1, l.split('#').next().unwrap_or("")))
        .filter(|(_, l)| !l.trim().is_empty());
    let (header_line, header) = lines.next().ok_or_else(|| UmbraError::Empty {
        file: file.to_string(),
    })?;
    let mut header_tokens = header.split_whitespace();
    let magic = header_tokens.next().unwrap_or("");
    if !matches!(magic, "OFF" | "COFF" | "NOFF" | "CNOFF") {
        return Err(malformed(
            file,
            F,
            header_line,
            format!("expected the header 'OFF', found '{}'", shorten(magic)),
        ));
    }
    // The counts may follow the header on the same line.
    let rest: Vec<&str> = header_tokens.collect();
    let (counts_line, counts): (usize, Vec<&str>) = if rest.is_empty() {
        let (n, l) = lines
            .next()
            .ok_or_else(|| malformed(file, F, 0, "truncated: no vertex and face counts"))?;
        (n, l.split_whitespace().collect())
    } else {
        (header_line, rest)
    };
    if counts.len() < 2 {
        return Err(malformed(
            file,
            F,
            counts_line,
            "expected the counts 'vertices faces [edges]'",
        ));
    }
    let count = |t: &str| -> Result<usize, UmbraError> {
        let n: usize = t.parse().map_err(|_| {
            malformed(
                file,
                F,
                counts_line,
                format!("'{}' is not a count", shorten(t)),
            )
        })?;
        if n > MAX_COUNT {
            return Err(malformed(
                file,
                F,
                counts_line,
                format!("count {n} is too large"),
            ));
        }
        Ok(n)
    };
    let (nv, nf) = (count(counts[0])?, count(counts[1])?);
    // Capacity bounded by the text size: a vertex line takes at least 6
    // bytes (`0 0 0\n`), a face line at least 8 (`3 0 1 2\n`).
    let mut vertices = Vec::with_capacity(nv.min(text.len() / 6 + 1));
    for k in 0..nv {
        let (n, l) = lines.next().ok_or_else(|| {
            malformed(
                file,
                F,
                0,
                format!("truncated: expected {nv} vertices, found {k}"),
            )
        })?;
        let mut tokens = l.split_whitespace();
        let mut p = [0.0; 3];
        for slot in &mut p {
            let t = tokens
                .next()
                .ok_or_else(|| malformed(file, F, n, "a vertex needs 3 coordinates"))?;
            *slot = parse_f64(t, file, F, n)?;
        }
        vertices.push(p);
        origins.vertex_places.push(n as u32);
    }
    let mut facets = Vec::with_capacity(nf.min(text.len() / 8 + 1));
    let mut loop_ = Vec::new();
    for k in 0..nf {
        let (n, l) = lines.next().ok_or_else(|| {
            malformed(
                file,
                F,
                0,
                format!("truncated: expected {nf} faces, found {k}"),
            )
        })?;
        let mut tokens = l.split_whitespace();
        let size: usize = tokens
            .next()
            .and_then(|t| t.parse().ok())
            .ok_or_else(|| malformed(file, F, n, "a face must start with its vertex count"))?;
        if size < 3 {
            return Err(malformed(file, F, n, "a face needs at least 3 vertices"));
        }
        loop_.clear();
        for _ in 0..size {
            let t = tokens.next().ok_or_else(|| {
                malformed(
                    file,
                    F,
                    n,
                    format!("the face has fewer than {size} vertex indices"),
                )
            })?;
            let v: u32 = t.parse().map_err(|_| {
                malformed(
                    file,
                    F,
                    n,
                    format!("'{}' is not a vertex index", shorten(t)),
                )
            })?;
            loop_.push(v);
        }
        facets.push(Facet::from_loop(&loop_));
        origins.face_places.push(n as u32);
    }
    refuse_vertices_alone(vertices.len(), facets.len(), &origins, file, F)?;
    Ok((PolygonMesh::new(vertices, facets), origins))
}

/// Reads an OBJ or OFF file (by extension) into a polygon mesh: parsed,
/// coordinates validated if asked, and checked for the closure constraints
/// of section 4.2, so a returned mesh is topologically valid unless
/// `check` is `false`.
pub(crate) fn read_mesh_text(
    text: &str,
    file: &str,
    off: bool,
    options: MeshReadOptions,
    check: bool,
) -> Result<PolygonMesh, UmbraError> {
    let (mesh, origins) = if off {
        parse_off_with_origins(text, file)?
    } else {
        parse_obj_with_origins(text, file)?
    };
    finish(mesh, &origins, file, options, check)
}

/// The faces to write: each facet's single loop, or the triangles of a
/// facet with several loops (section 4.8).
pub(crate) fn faces(mesh: &PolygonMesh) -> Vec<Vec<u32>> {
    faces_split(mesh).0
}

/// [`faces`], and `true` when they are not the facets one for one (a facet
/// with several loops was triangulated, or one without a loop left out).
pub(crate) fn faces_split(mesh: &PolygonMesh) -> (Vec<Vec<u32>>, bool) {
    let mut split = false;
    let mut out = Vec::with_capacity(mesh.facets.len());
    let mut tris = Vec::new();
    let mut hes = Vec::new();
    for f in &mesh.facets {
        let loops = f.loops_in_plane(&mesh.vertices);
        split |= loops.len() != 1;
        if loops.len() == 1 {
            out.push(loops.into_iter().next().unwrap_or_default());
        } else if loops.len() > 1 {
            tris.clear();
            hes.clear();
            hes.extend(
                f.half_edges
                    .iter()
                    .map(|&HalfEdge { start, end }| (start, end)),
            );
            triangulate_facet(&mesh.vertices, &hes, &mut tris);
            out.extend(tris.iter().map(|t| t.to_vec()));
        }
    }
    (out, split)
}

/// OBJ text of a mesh.
pub fn mesh_to_obj(mesh: &PolygonMesh) -> String {
    obj_of_faces(mesh, &faces(mesh))
}

/// [`mesh_to_obj`] of the mesh's vertices and its [`faces`] already made.
pub(crate) fn obj_of_faces(mesh: &PolygonMesh, faces: &[Vec<u32>]) -> String {
    let mut s = String::with_capacity(40 * mesh.vertices.len() + 24 * faces.len());
    s.push_str("# written by umbra\n");
    for p in &mesh.vertices {
        let _ = writeln!(s, "v {} {} {}", p[0], p[1], p[2]);
    }
    for f in faces {
        s.push('f');
        for v in f {
            let _ = write!(s, " {}", u64::from(*v) + 1);
        }
        s.push('\n');
    }
    s
}

/// OFF text of a mesh.
pub fn mesh_to_off(mesh: &PolygonMesh) -> String {
    off_of_faces(mesh, &faces(mesh))
}

/// [`mesh_to_off`] of the mesh's vertices and its [`faces`] already made.
pub(crate) fn off_of_faces(mesh: &PolygonMesh, faces: &[Vec<u32>]) -> String {
    let mut s = String::with_capacity(40 * mesh.vertices.len() + 24 * faces.len());
    let _ = writeln!(s, "OFF\n{} {} 0", mesh.vertices.len(), faces.len());
    for p in &mesh.vertices {
        let _ = writeln!(s, "{} {} {}", p[0], p[1], p[2]);
    }
    for f in faces {
        let _ = write!(s, "{}", f.len());
        for v in f {
            let _ = write!(s, " {v}");
        }
        s.push('\n');
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    const CUBE_OBJ: &str = "# a unit cube\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n\
        vn 0 0 1\nf 1 4 3 2\nf 5/1 6/1 7/1 8/1\nf 1//1 2//1 6//1 5//1\nf -6 -5 -1 -2\nf 2 3 7 6\nf 4 1 5 8\n";

    #[test]
    fn obj_cube_reads_and_round_trips() {
        let m = parse_obj(CUBE_OBJ, "cube.obj").unwrap();
        assert_eq!(m.vertices.len(), 8);
        assert_eq!(m.facets.len(), 6);
        m.check_topology().unwrap();
        let back = parse_obj(&mesh_to_obj(&m), "x").unwrap();
        assert_eq!(back.vertices, m.vertices);
        assert_eq!(back.facets.len(), 6);
        let off = parse_off(&mesh_to_off(&m), "x").unwrap();
        assert_eq!(off.vertices, m.vertices);
        off.check_topology().unwrap();
    }

    #[test]
    fn the_empty_mesh_round_trips_and_text_without_obj_is_empty() {
        let empty = PolygonMesh::default();
        assert_eq!(parse_obj(&mesh_to_obj(&empty), "e.obj").unwrap(), empty);
        assert_eq!(parse_off(&mesh_to_off(&empty), "e.off").unwrap(), empty);
        for text in [
            "# nothing\n",
            "o part\ng group\n",
            "mtllib a.mtl\nusemtl b\n",
        ] {
            assert_eq!(parse_obj(text, "e.obj").unwrap(), empty, "{text:?}");
        }
        for text in ["", " \n\t\n", "hello world\n"] {
            let e = parse_obj(text, "e.obj").unwrap_err().to_string();
            assert_eq!(e, "e.obj: the file is empty (no geometry)", "{text:?}");
        }
    }

    #[test]
    fn errors_name_line_and_problem() {
        let obj = [
            ("v 0 0\n", "line 1: a vertex needs 3 coordinates"),
            ("v 0 0 x\n", "'x' is not a number"),
            ("v 0 0 0\nf 1 2\n", "at least 3"),
            ("v 0 0 0\nf 1 0 1\n", "reference 0"),
            ("v 0 0 0\nf 1 -5 1\n", "out of range"),
            ("v 0 0 0\nf 1 a 1\n", "not a vertex reference"),
            ("", "empty"),
            (
                "v 0 0 0\n\u{0}\u{1}\u{2}\n",
                "line 2: binary data (control byte 0x00)",
            ),
            (
                "v 0 0 0 \u{7f}\n",
                "line 1: binary data (control byte 0x7f)",
            ),
        ];
        for (text, want) in obj {
            let e = parse_obj(text, "m.obj").unwrap_err().to_string();
            assert!(
                e.contains(want) && e.starts_with("m.obj: "),
                "{text:?}: {e}"
            );
        }
        let off = [
            ("PLY\n", "expected the header 'OFF'"),
            ("OFF\n", "no vertex and face counts"),
            ("OFF\n3 1 0\n0 0 0\n1 0 0\n", "expected 3 vertices, found 2"),
            (
                "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n",
                "expected 1 faces, found 0",
            ),
            ("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1\n", "fewer than 3"),
            (
                "OFF\n3 1 0\n0 0 0\n1 0 nan?\n0 1 0\n3 0 1 2\n",
                "not a number",
            ),
            ("OFF\n99999999999 1 0\n", "too large"),
            (
                "OFF\n3 1 0\n\u{1b}[0m\n",
                "line 3: binary data (control byte 0x1b)",
            ),
        ];
        for (text, want) in off {
            let e = parse_off(text, "m.off").unwrap_err().to_string();
            assert!(
                e.contains(want) && e.starts_with("m.off: "),
                "{text:?}: {e}"
            );
        }
    }

    #[test]
    fn the_largest_reference_is_written_back_without_overflow() {
        let m = parse_obj("v 0 0 0\nv 1 0 0\nf 1 2 4294967296\n", "w.obj").unwrap();
        assert_eq!(m.facets[0].half_edges[1].end, u32::MAX);
        assert!(mesh_to_obj(&m).contains("f 1 2 4294967296\n"));
    }

    #[test]
    fn whitespace_controls_are_text() {
        let m = parse_obj("v 0\t0 0\r\nv 1 0 0\x0c\nv 0 1 0\x0b\nf 1 2 3\n", "w.obj").unwrap();
        assert_eq!((m.vertices.len(), m.facets.len()), (3, 1));
    }

    #[test]
    fn topology_errors_come_from_the_check() {
        let dangling = "OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 2 7\n";
        let e = read_mesh_text(dangling, "d.off", true, MeshReadOptions::default(), true)
            .unwrap_err()
            .to_string();
        assert!(e.contains("d.off") && e.contains('7'), "{e}");
        let open = "OFF\n4 1 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n";
        let e = read_mesh_text(open, "o.off", true, MeshReadOptions::default(), true)
            .unwrap_err()
            .to_string();
        assert!(e.contains("o.off") && e.contains("closure"), "{e}");
        let nan = "v 0 0 0\nv NaN 0 0\nv 0 1 0\nf 1 2 3\nf 1 3 2\n";
        let e = read_mesh_text(nan, "n.obj", false, MeshReadOptions::default(), true)
            .unwrap_err()
            .to_string();
        assert!(
            e.contains("n.obj") && e.to_lowercase().contains("nan"),
            "{e}"
        );
    }
}
