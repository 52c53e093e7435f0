//! PLY (polygon file format) reading and writing, ASCII and binary (little
//! and big endian).
//!
//! Reading uses the maintained `ply-rs-bw` crate (the maintained fork of
//! the abandoned `ply-rs`) for the header grammar and for decoding one
//! element at a time; this module drives it record by record so that every
//! error names the element and its line (ASCII) or record (binary), and so
//! that nothing is reserved on the word of the header: before any element
//! is read, the element counts are checked against the bytes after the
//! header (each element needs at least its minimal record size: one byte
//! per ASCII number and its separator, the fixed size of a binary scalar or
//! list count), so a huge count is an error at once.
//!
//! The mesh is the `vertex` element's `x`, `y` and `z` (any numeric type)
//! and the `face` element's `vertex_indices` (or `vertex_index`) lists of
//! any integer type, 0-based; polygon faces are kept as polygon facets.
//! Other properties and elements (normals, colours, edges, ...) are read
//! and ignored. A leading UTF-8 byte-order mark is dropped.
//!
//! Writing: vertices as `double` (so binary and ASCII PLY read back bit for
//! bit) and faces as `vertex_indices` lists (a facet with holes is written
//! as its triangulation, section 4.8). Binary little endian by default.

use super::mesh_text::{faces, MeshReadOptions};
use super::origin::{finish, refuse_vertices_alone, Origins};
use super::text::{is_infinity_literal, overflow_message, push_f64, shorten};
use crate::UmbraError;
use ply_rs_bw::parser::{Parser, Reader};
use ply_rs_bw::ply::{
    BeginList, ElementDef, Encoding, Header, PropertyAccess, PropertyAccessResult, PropertyType,
    ScalarType,
};
use robust_arith::Point3;
use std::fmt::Write as _;
use std::io::Cursor;
use topology::{Facet, PolygonMesh};

const FORMAT: &str = "PLY";

fn malformed(file: &str, message: impl Into<String>) -> UmbraError {
    UmbraError::Malformed {
        file: file.to_string(),
        format: FORMAT,
        message: message.into(),
    }
}

/// A message of the crate on one line, white space collapsed, at most 160
/// characters.
fn one_line(e: &dyn std::fmt::Display) -> String {
    let text = e.to_string();
    let words: Vec<&str> = text.split_whitespace().collect();
    let joined = words.join(" ");
    shorten_long(&joined, 160)
}

fn shorten_long(s: &str, n: usize) -> String {
    if s.chars().count() > n {
        format!("{}...", s.chars().take(n).collect::<String>())
    } else {
        s.to_string()
    }
}

/// A vertex: x, y, z of any numeric type; everything else ignored.
#[derive(Default)]
struct Vertex {
    p: [f64; 3],
    seen: [bool; 3],
}

impl Vertex {
    fn set(&mut self, name: &str, value: f64) -> PropertyAccessResult {
        let axis = match name {
            "x" => 0,
            "y" => 1,
            "z" => 2,
            _ => return PropertyAccessResult::Ignored,
        };
        self.p[axis] = value;
        self.seen[axis] = true;
        PropertyAccessResult::Set
    }
}

impl PropertyAccess for Vertex {
    fn new() -> Self {
        Vertex::default()
    }
    fn set_char(&mut self, name: &str, v: i8) -> PropertyAccessResult {
        self.set(name, f64::from(v))
    }
    fn set_uchar(&mut self, name: &str, v: u8) -> PropertyAccessResult {
        self.set(name, f64::from(v))
    }
    fn set_short(&mut self, name: &str, v: i16) -> PropertyAccessResult {
        self.set(name, f64::from(v))
    }
    fn set_ushort(&mut self, name: &str, v: u16) -> PropertyAccessResult {
        self.set(name, f64::from(v))
    }
    fn set_int(&mut self, name: &str, v: i32) -> PropertyAccessResult {
        self.set(name, f64::from(v))
    }
    fn set_uint(&mut self, name: &str, v: u32) -> PropertyAccessResult {
        self.set(name, f64::from(v))
    }
    fn set_float(&mut self, name: &str, v: f32) -> PropertyAccessResult {
        self.set(name, f64::from(v))
    }
    fn set_double(&mut self, name: &str, v: f64) -> PropertyAccessResult {
        self.set(name, v)
    }
}

/// A face: the vertex index list; a negative index is recorded as such.
#[derive(Default)]
struct Face {
    indices: Vec<u32>,
    negative: Option<i64>,
    seen: bool,
}

fn is_index_list(name: &str) -> bool {
    name == "vertex_indices" || name == "vertex_index"
}

impl Face {
    fn set_signed(
        &mut self,
        name: &str,
        values: impl IntoIterator<Item = i64>,
    ) -> PropertyAccessResult {
        if !is_index_list(name) {
            return PropertyAccessResult::Ignored;
        }
        self.seen = true;
        self.indices.clear();
        for v in values {
            match u32::try_from(v) {
                Ok(u) => self.indices.push(u),
                Err(_) => {
                    self.negative.get_or_insert(v);
                }
            }
        }
        PropertyAccessResult::Set
    }
}

impl PropertyAccess for Face {
    fn new() -> Self {
        Face::default()
    }
    fn begin_list_uchar(&mut self, _: &str, _: usize) -> BeginList<'_, u8> {
        BeginList::UseSetter
    }
    fn set_list_char(&mut self, name: &str, v: Vec<i8>) -> PropertyAccessResult {
        self.set_signed(name, v.into_iter().map(i64::from))
    }
    fn set_list_uchar(&mut self, name: &str, v: Vec<u8>) -> PropertyAccessResult {
        self.set_signed(name, v.into_iter().map(i64::from))
    }
    fn set_list_short(&mut self, name: &str, v: Vec<i16>) -> PropertyAccessResult {
        self.set_signed(name, v.into_iter().map(i64::from))
    }
    fn set_list_ushort(&mut self, name: &str, v: Vec<u16>) -> PropertyAccessResult {
        self.set_signed(name, v.into_iter().map(i64::from))
    }
    fn set_list_int(&mut self, name: &str, v: Vec<i32>) -> PropertyAccessResult {
        self.set_signed(name, v.into_iter().map(i64::from))
    }
    fn begin_list_uint(&mut self, name: &str, _: usize) -> BeginList<'_, u32> {
        if is_index_list(name) {
            self.seen = true;
            BeginList::Fill(&mut self.indices)
        } else {
            BeginList::UseSetter
        }
    }
    fn set_list_float(&mut self, name: &str, _: Vec<f32>) -> PropertyAccessResult {
        if is_index_list(name) {
            PropertyAccessResult::UnsupportedType
        } else {
            PropertyAccessResult::Ignored
        }
    }
    fn set_list_double(&mut self, name: &str, _: Vec<f64>) -> PropertyAccessResult {
        if is_index_list(name) {
            PropertyAccessResult::UnsupportedType
        } else {
            PropertyAccessResult::Ignored
        }
    }
}

/// Any other element: read and dropped.
struct Skip;

impl PropertyAccess for Skip {
    fn new() -> Self {
        Skip
    }
}

fn scalar_size(t: &ScalarType) -> u64 {
    match t {
        ScalarType::Char | ScalarType::UChar => 1,
        ScalarType::Short | ScalarType::UShort => 2,
        ScalarType::Int | ScalarType::UInt | ScalarType::Float => 4,
        ScalarType::Double => 8,
    }
}

/// The fewest bytes one record of `e` can take.
fn min_record(e: &ElementDef, encoding: Encoding) -> u64 {
    e.properties
        .values()
        .map(|p| match (&p.data_type, encoding) {
            (_, Encoding::Ascii) => 2,
            (PropertyType::Scalar(t), _) => scalar_size(t),
            (PropertyType::List(count, _), _) => scalar_size(count),
        })
        .sum()
}

/// The byte offset just after the `end_header` line, or an error.
fn header_end(bytes: &[u8], file: &str) -> Result<usize, UmbraError> {
    let mut at = 0;
    let mut line = 0usize;
    while at < bytes.len() {
        line += 1;
        let end = bytes[at..]
            .iter()
            .position(|&b| b == b'\n')
            .map_or(bytes.len(), |i| at + i + 1);
        let text = bytes[at..end].trim_ascii();
        if line == 1 && text != b"ply" {
            return Err(malformed(
                file,
                format!(
                    "line 1: not a PLY file (it must start with the line 'ply', found '{}')",
                    shorten(&String::from_utf8_lossy(&text[..text.len().min(40)]))
                ),
            ));
        }
        if text == b"end_header" {
            return Ok(end);
        }
        at = end;
    }
    Err(malformed(
        file,
        format!("truncated header: no 'end_header' line in {line} line(s)"),
    ))
}

/// Parses PLY bytes into a polygon mesh (unchecked: indices out of range
/// are left for [`PolygonMesh::check_topology`] to name); `file` names the
/// source in errors.
///
/// ```
/// use umbra::{mesh_to_ply, parse_ply, Facet, PolygonMesh};
/// let square = PolygonMesh::new(
///     vec![[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [1.0, 1.0, 0.0], [0.0, 1.0, 0.1]],
///     vec![Facet::from_loop(&[0, 1, 2, 3]), Facet::from_loop(&[3, 2, 1, 0])],
/// );
/// for ascii in [false, true] {
///     let bytes = mesh_to_ply(&square, ascii);
///     assert_eq!(parse_ply(&bytes, "sq.ply").unwrap(), square);
/// }
/// ```
pub fn parse_ply(bytes: &[u8], file: &str) -> Result<PolygonMesh, UmbraError> {
    parse_ply_with_origins(bytes, file).map(|(mesh, _)| mesh)
}

/// [`parse_ply`] with the line or record of every vertex and face.
pub(crate) fn parse_ply_with_origins(
    bytes: &[u8],
    file: &str,
) -> Result<(PolygonMesh, Origins), UmbraError> {
    let bytes = bytes.strip_prefix("\u{feff}".as_bytes()).unwrap_or(bytes);
    if bytes.iter().all(u8::is_ascii_whitespace) {
        return Err(UmbraError::Empty {
            file: file.to_string(),
        });
    }
    let end = header_end(bytes, file)?;
    super::text::decode(&bytes[..end], file, FORMAT)?;
    let mut reader = Reader::new(Cursor::new(bytes));
    let header: Header = Parser::<Skip>::new()
        .read_header(&mut reader)
        .map_err(|e| malformed(file, format!("header: {}", one_line(&e))))?;
    let header_lines = bytes[..end].iter().filter(|&&b| b == b'\n').count();
    // The crate's header reader stops right after `end_header`.
    let data = &bytes[end..];
    let encoding = header.encoding;

    // No count may claim more records than the data can hold.
    let mut need: u64 = 0;
    for e in header.elements.values() {
        let min = min_record(e, encoding).max(1);
        need = need.saturating_add((e.count as u64).saturating_mul(min));
        if need > data.len() as u64 {
            return Err(malformed(
                file,
                format!(
                    "the header declares {} '{}' element(s) of at least {min} byte(s) each, more than the {} byte(s) after the header can hold (truncated or a corrupt count)",
                    e.count,
                    shorten(&e.name),
                    data.len()
                ),
            ));
        }
    }

    let vertex_def = header.elements.get("vertex");
    if let Some(v) = vertex_def {
        for axis in ["x", "y", "z"] {
            match v.properties.get(axis).map(|p| &p.data_type) {
                Some(PropertyType::Scalar(_)) => {}
                Some(PropertyType::List(..)) => {
                    return Err(malformed(
                        file,
                        format!("header: vertex property '{axis}' is a list"),
                    ))
                }
                None => {
                    return Err(malformed(
                        file,
                        format!("header: the vertex element has no '{axis}' property"),
                    ))
                }
            }
        }
    }
    if let Some(f) = header.elements.get("face") {
        if !f.properties.keys().any(|k| is_index_list(k)) {
            return Err(malformed(
                file,
                "header: the face element has no 'vertex_indices' list",
            ));
        }
    }
    // Triangle strips (the `tristrips` element of some scanners' files)
    // would otherwise be dropped as an unknown element, leaving the
    // vertices as an empty solid.
    if header
        .elements
        .get("tristrips")
        .is_some_and(|t| t.count > 0)
    {
        return Err(malformed(
            file,
            "header: triangle strips (element 'tristrips') are not supported; write the mesh with a 'face' element",
        ));
    }
    if vertex_def.is_none() && header.elements.get("face").is_none_or(|f| f.count == 0) {
        return Err(UmbraError::Empty {
            file: file.to_string(),
        });
    }

    let ascii = encoding == Encoding::Ascii;
    let mut origins = Origins::new(0, "face", if ascii { "line" } else { "" });
    let mut vertices: Vec<Point3> = Vec::new();
    let mut facets: Vec<Facet> = Vec::new();
    let mut cursor = Cursor::new(data);
    // ASCII: one element per non-empty line.
    let text = if ascii {
        Some(
            super::text::decode(data, file, FORMAT).map_err(|e| match e {
                UmbraError::Malformed { message, .. } => malformed(
                    file,
                    format!("after the header (line {}): {message}", header_lines),
                ),
                other => other,
            })?,
        )
    } else {
        None
    };
    let mut lines = text.map(|t| {
        t.lines()
            .enumerate()
            .map(move |(i, l)| (header_lines + 1 + i, l))
            .filter(|(_, l)| !l.trim().is_empty())
    });
    let vertex_parser = Parser::<Vertex>::new();
    let face_parser = Parser::<Face>::new();
    let skip_parser = Parser::<Skip>::new();

    for e in header.elements.values() {
        let remaining = data.len() as u64 - cursor.position().min(data.len() as u64);
        let cap = (e.count as u64).min(remaining / min_record(e, encoding).max(1)) as usize;
        let is_vertex = e.name == "vertex";
        let is_face = e.name == "face";
        if is_vertex {
            vertices.reserve(cap);
        } else if is_face {
            facets.reserve(cap);
        }
        for k in 0..e.count {
            let place = match lines.as_mut() {
                Some(l) => match l.next() {
                    Some((n, line)) => Place::Line(n, line),
                    None => {
                        return Err(malformed(
                            file,
                            format!(
                                "truncated: expected {} '{}' element(s), found {k}",
                                e.count,
                                shorten(&e.name)
                            ),
                        ))
                    }
                },
                None => Place::Record(k + 1),
            };
            let where_ = match place {
                Place::Line(n, _) => format!("line {n}"),
                Place::Record(r) => format!("{} record {r}", shorten(&e.name)),
            };
            let fail = |err: &dyn std::fmt::Display| {
                let text = one_line(err);
                if text.contains("failed to fill whole buffer") {
                    malformed(
                        file,
                        format!("{where_}: truncated: the data ends inside it"),
                    )
                } else {
                    malformed(file, format!("{where_}: {text}"))
                }
            };
            macro_rules! read {
                ($parser:expr) => {
                    match place {
                        Place::Line(_, line) => $parser.read_ascii_element(line, e),
                        Place::Record(_) => match encoding {
                            Encoding::BinaryBigEndian => {
                                $parser.read_big_endian_element(&mut cursor, e)
                            }
                            _ => $parser.read_little_endian_element(&mut cursor, e),
                        },
                    }
                    .map_err(|err| fail(&err))?
                };
            }
            // A literal too large for f64 would be read as infinity.
            if let Place::Line(_, line) = place {
                if let Some(t) = line.split_ascii_whitespace().find(|t| {
                    t.parse::<f64>().is_ok_and(f64::is_infinite) && !is_infinity_literal(t)
                }) {
                    return Err(malformed(
                        file,
                        format!("{where_}: {}", overflow_message(t)),
                    ));
                }
            }
            let place_no = match place {
                Place::Line(n, _) => n as u32,
                Place::Record(r) => r as u32,
            };
            if is_vertex {
                let v = read!(vertex_parser);
                if !v.seen.iter().all(|&s| s) {
                    return Err(malformed(
                        file,
                        format!("{where_}: a vertex without x, y and z"),
                    ));
                }
                vertices.push(v.p);
                origins.vertex_places.push(place_no);
            } else if is_face {
                let f = read!(face_parser);
                if let Some(n) = f.negative {
                    return Err(malformed(
                        file,
                        format!("{where_}: negative vertex index {n}"),
                    ));
                }
                if f.indices.len() < 3 {
                    return Err(malformed(
                        file,
                        format!(
                            "{where_}: a face needs at least 3 vertices, found {}",
                            f.indices.len()
                        ),
                    ));
                }
                facets.push(Facet::from_loop(&f.indices));
                origins.face_places.push(place_no);
            } else {
                read!(skip_parser);
            }
        }
    }
    if !ascii && (cursor.position() as usize) < data.len() {
        // Trailing bytes after the last record: a count too small, or junk.
        let extra = data.len() - cursor.position() as usize;
        if data[cursor.position() as usize..]
            .iter()
            .any(|b| !b.is_ascii_whitespace())
        {
            return Err(malformed(
                file,
                format!("{extra} unexpected byte(s) after the last element"),
            ));
        }
    }
    if let Some(mut l) = lines {
        if let Some((n, line)) = l.next() {
            return Err(malformed(
                file,
                format!(
                    "line {n}: unexpected data after the last element: '{}'",
                    shorten(line)
                ),
            ));
        }
    }
    // A header with a vertex element of count 0 is the empty mesh (what
    // the writer writes for an empty result).
    refuse_vertices_alone(vertices.len(), facets.len(), &origins, file, FORMAT)?;
    Ok((PolygonMesh::new(vertices, facets), origins))
}

#[derive(Clone, Copy)]
enum Place<'a> {
    Line(usize, &'a str),
    Record(usize),
}

/// Reads PLY bytes into a polygon mesh: coordinates validated if asked,
/// closure checked if `check` (see [`crate::read_mesh`]).
pub(crate) fn read_ply_bytes(
    bytes: &[u8],
    file: &str,
    options: MeshReadOptions,
    check: bool,
) -> Result<PolygonMesh, UmbraError> {
    let (mesh, origins) = parse_ply_with_origins(bytes, file)?;
    finish(mesh, &origins, file, options, check)
}

/// The PLY bytes of a mesh, binary little endian or (`ascii`) text (see the
/// module docs).
pub fn mesh_to_ply(mesh: &PolygonMesh, ascii: bool) -> Vec<u8> {
    ply_of_faces(mesh, &faces(mesh), ascii)
}

/// [`mesh_to_ply`] of the mesh's vertices and its faces already made
/// ([`super::mesh_text::faces`]).
pub(crate) fn ply_of_faces(mesh: &PolygonMesh, faces: &[Vec<u32>], ascii: bool) -> Vec<u8> {
    let wide = faces.iter().any(|f| f.len() > 255);
    let mut head = String::new();
    let _ = write!(
        head,
        "ply\nformat {} 1.0\ncomment written by umbra\nelement vertex {}\nproperty double x\nproperty double y\nproperty double z\nelement face {}\nproperty list {} uint vertex_indices\nend_header\n",
        if ascii { "ascii" } else { "binary_little_endian" },
        mesh.vertices.len(),
        faces.len(),
        if wide { "uint" } else { "uchar" },
    );
    if ascii {
        let mut s = head;
        s.reserve(40 * mesh.vertices.len() + 20 * faces.len());
        for p in &mesh.vertices {
            for (i, &x) in p.iter().enumerate() {
                if i > 0 {
                    s.push(' ');
                }
                push_f64(&mut s, x);
            }
            s.push('\n');
        }
        for f in faces {
            let _ = write!(s, "{}", f.len());
            for v in f {
                let _ = write!(s, " {v}");
            }
            s.push('\n');
        }
        return s.into_bytes();
    }
    let mut out = head.into_bytes();
    out.reserve(24 * mesh.vertices.len() + 16 * faces.len());
    for p in &mesh.vertices {
        for x in p {
            out.extend_from_slice(&x.to_le_bytes());
        }
    }
    for f in faces {
        if wide {
            out.extend_from_slice(&(f.len() as u32).to_le_bytes());
        } else {
            out.push(f.len() as u8);
        }
        for v in f {
            out.extend_from_slice(&v.to_le_bytes());
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn cube() -> PolygonMesh {
        let v: Vec<Point3> = (0..8u32)
            .map(|i| {
                [
                    f64::from(i & 1) * 0.1,
                    f64::from((i >> 1) & 1) / 3.0,
                    -f64::from((i >> 2) & 1) * 1e-300,
                ]
            })
            .collect();
        let quads: [[u32; 4]; 6] = [
            [0, 2, 3, 1],
            [4, 5, 7, 6],
            [0, 1, 5, 4],
            [2, 6, 7, 3],
            [0, 4, 6, 2],
            [1, 3, 7, 5],
        ];
        PolygonMesh::new(v, quads.iter().map(|q| Facet::from_loop(q)).collect())
    }

    /// A big-endian file with float coordinates, int indices and extra
    /// properties and elements, written by hand.
    fn big_endian() -> Vec<u8> {
        let mut b = b"ply\nformat binary_big_endian 1.0\ncomment hand made\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nproperty uchar red\nelement face 2\nproperty list uchar int vertex_indices\nproperty float quality\nelement edge 1\nproperty int vertex1\nproperty int vertex2\nend_header\n".to_vec();
        for p in [[0f32, 0., 0.], [1., 0., 0.], [0., 1., 0.5]] {
            for x in p {
                b.extend_from_slice(&x.to_be_bytes());
            }
            b.push(200);
        }
        for f in [[0i32, 1, 2], [0, 2, 1]] {
            b.push(3);
            for i in f {
                b.extend_from_slice(&i.to_be_bytes());
            }
            b.extend_from_slice(&1f32.to_be_bytes());
        }
        b.extend_from_slice(&0i32.to_be_bytes());
        b.extend_from_slice(&1i32.to_be_bytes());
        b
    }

    #[test]
    fn triangle_strips_are_refused_by_name() {
        let text = "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\nelement tristrips 1\nproperty list int int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n6 0 2 1 3 0 2\n";
        let e = parse_ply(text.as_bytes(), "strips.ply")
            .unwrap_err()
            .to_string();
        assert!(e.contains("strips.ply") && e.contains("tristrips"), "{e}");
    }

    #[test]
    fn round_trips_bit_for_bit() {
        let c = cube();
        for ascii in [false, true] {
            let bytes = mesh_to_ply(&c, ascii);
            let back = parse_ply(&bytes, "c.ply").unwrap();
            assert_eq!(back.vertices.len(), 8);
            for (a, b) in back.vertices.iter().zip(&c.vertices) {
                assert_eq!(a.map(f64::to_bits), b.map(f64::to_bits));
            }
            assert_eq!(back.facets, c.facets);
        }
    }

    #[test]
    fn big_endian_with_extra_properties() {
        let m = read_ply_bytes(&big_endian(), "be.ply", MeshReadOptions::default(), true).unwrap();
        assert_eq!(
            m.vertices,
            vec![[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.5]]
        );
        assert_eq!(m.facets.len(), 2);
    }

    #[test]
    fn the_empty_mesh_round_trips() {
        let empty = PolygonMesh::default();
        for ascii in [false, true] {
            assert_eq!(
                parse_ply(&mesh_to_ply(&empty, ascii), "e.ply").unwrap(),
                empty
            );
        }
        // A header without a vertex or face element holds no mesh.
        let e = parse_ply(b"ply\nformat ascii 1.0\nend_header\n", "e.ply")
            .unwrap_err()
            .to_string();
        assert_eq!(e, "e.ply: the file is empty (no geometry)");
    }

    #[test]
    fn hostile_files_name_the_problem() {
        let head = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
        let cases: Vec<(Vec<u8>, &str)> = vec![
            (b"".to_vec(), "empty"),
            (b"PLY?\n".to_vec(), "line 1: not a PLY file"),
            (b"ply\nformat ascii 1.0\n".to_vec(), "no 'end_header'"),
            (
                b"ply\nformat binary_little_endian 1.0\nelement vertex 4000000000\nproperty float x\nproperty float y\nproperty float z\nend_header\n\0\0".to_vec(),
                "4000000000 'vertex' element(s) of at least 12 byte(s) each, more than the 2 byte(s)",
            ),
            (format!("{head}0 0 0\n1 0 0\n").into_bytes(), "3 'vertex' element(s) of at least 6 byte(s) each, more than the 12"),
            (format!("{head}0 0 0\n1 0 0\n{}", "\n".repeat(20)).into_bytes(), "truncated: expected 3 'vertex' element(s), found 2"),
            (format!("{head}0 0 0\n1 0 0\n0 1 0\n\n\n").into_bytes(), "truncated: expected 1 'face'"),
            (format!("{head}0 0 0\n1 0 0\n0 1 0\n3 0 1 -2\n").into_bytes(), "line 13: negative vertex index -2"),
            (format!("{head}0 0 0\n1 0 0\n0 1 0\n2 0 1\n").into_bytes(), "line 13: a face needs at least 3"),
            (format!("{head}0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n9 9 9\n").into_bytes(), "line 14: unexpected data"),
            (format!("{head}0 0 0\n1 x 0\n0 1 0\n3 0 1 2\n").into_bytes(), "line 11: "),
            (format!("{head}0 0 0\n1 1e400 0\n0 1 0\n3 0 1 2\n").into_bytes(), "line 11: '1e400' overflows f64"),
            (format!("{head}0 0 0\n1 \u{e9} 0\n0 1 0\n3 0 1 2\n").into_bytes().iter().map(|&b| if b == 0xc3 { 0xff } else { b }).collect(), "not UTF-8"),
            (
                b"ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nend_header\n0 0\n".to_vec(),
                "no 'z' property",
            ),
        ];
        for (bytes, want) in cases {
            let e = parse_ply(&bytes, "h.ply").unwrap_err().to_string();
            assert!(e.starts_with("h.ply: ") && e.contains(want), "{want}: {e}");
            assert!(!e.contains('\n') && !e.contains('\t'), "{e}");
        }
        // Truncated binary data names the record.
        let mut b = big_endian();
        b.truncate(b.len() - 20);
        let e = parse_ply(&b, "t.ply").unwrap_err().to_string();
        assert!(
            e.contains("face record 2: truncated: the data ends inside it"),
            "{e}"
        );
    }

    #[test]
    fn dangling_and_open_are_named_in_file_terms() {
        let bytes = b"ply\nformat ascii 1.0\nelement vertex 3\nproperty double x\nproperty double y\nproperty double z\nelement face 2\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 2 7\n";
        let e = read_ply_bytes(bytes, "d.ply", MeshReadOptions::default(), true)
            .unwrap_err()
            .to_string();
        assert!(e.contains("face 2 (line 14) refers to vertex 7"), "{e}");
    }
}
