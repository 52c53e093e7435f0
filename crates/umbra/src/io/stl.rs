//! STL (stereolithography) reading and writing, binary and ASCII.
//!
//! An STL file is a triangle soup: every triangle repeats its three corner
//! positions. Reading welds corners by exact position: two corners are the
//! same vertex when their coordinates are equal as numbers, bit for bit,
//! except that `-0.0` and `0.0` are the same coordinate (they compare equal,
//! and exporters write either on the two sides of one edge); the vertex
//! keeps the first spelling read. A welded soup that does not close is
//! reported by the closure check of section 4.2 naming an open edge by the
//! positions of its two vertices and the record of each.
//!
//! Binary STL: an 80-byte header, a little-endian `u32` triangle count and
//! 50 bytes per triangle (normal, three corners as `f32`, a 2-byte
//! attribute). The count is believed only when the file's size is exactly
//! `84 + 50 * count`, so a count can never make the reader reserve more than
//! the file holds. A file that does not have that size and starts with
//! `solid` is read as ASCII (`solid`, then `facet normal ..`, `outer loop`,
//! three `vertex x y z`, `endloop`, `endfacet`, and `endsolid`; several
//! solids may follow each other). ASCII coordinates are read as `f64`.
//! Stored normals are ignored (they are implied by the corner order).
//!
//! Writing triangulates polygon facets (section 4.8). Binary STL rounds
//! each coordinate to the nearest `f32` (a coordinate beyond the `f32`
//! range is an error); ASCII STL writes the shortest decimal of each `f64`,
//! so it reads back bit for bit.
//!
//! The `stl_io` crate was considered and not used: it takes any file whose
//! first line starts with `solid ` for ASCII (many binary exporters write
//! that in the header), its ASCII errors carry no line, it reports `1e400`
//! as an infinite value and it has no ASCII writer.

use super::mesh_text::MeshReadOptions;
use super::origin::{finish, Origins};
use super::text::{parse_number, push_f64, shorten, strip_bom};
use super::weld::Welder;
use crate::UmbraError;
use robust_arith::Point3;
use topology::{PolygonMesh, TriangleMesh};

const FORMAT: &str = "STL";
/// Bytes before the first binary record.
const HEADER: usize = 84;
/// Bytes of one binary triangle record.
const RECORD: usize = 50;

fn malformed(file: &str, message: impl Into<String>) -> UmbraError {
    UmbraError::Malformed {
        file: file.to_string(),
        format: FORMAT,
        message: message.into(),
    }
}

/// `true` if `bytes` has the exact size of a binary STL by its own count.
fn binary_size_matches(bytes: &[u8]) -> Option<(u64, u64)> {
    let count = u32::from_le_bytes(bytes.get(80..84)?.try_into().ok()?);
    let want = HEADER as u64 + RECORD as u64 * u64::from(count);
    Some((u64::from(count), want))
}

/// Parses STL bytes (binary or ASCII, see the module docs) into a welded
/// triangle mesh, unchecked; `file` names the source in errors.
///
/// ```
/// use umbra::{mesh_to_stl, parse_stl, TriangleMesh};
/// let tet = TriangleMesh::new(
///     vec![[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]],
///     vec![[0, 1, 2], [0, 3, 1], [1, 3, 2], [0, 2, 3]],
/// );
/// let bytes = mesh_to_stl(&tet.to_polygon_mesh(), false).unwrap();
/// assert_eq!(bytes.len(), 84 + 4 * 50);
/// let back = parse_stl(&bytes, "tet.stl").unwrap();
/// // Welded back to the same vertices (first-seen order) and triangles.
/// assert_eq!(back, tet);
/// ```
pub fn parse_stl(bytes: &[u8], file: &str) -> Result<TriangleMesh, UmbraError> {
    let (mesh, _) = parse_stl_with_origins(bytes, file)?;
    Ok(mesh)
}

/// [`parse_stl`] with the record or line of every triangle and vertex. A
/// well-formed file without triangles (a binary header with count 0,
/// `solid ... endsolid`: what the writer writes for an empty result) is the
/// empty mesh; a file of nothing but white space is [`UmbraError::Empty`].
pub(crate) fn parse_stl_with_origins(
    bytes: &[u8],
    file: &str,
) -> Result<(TriangleMesh, Origins), UmbraError> {
    parse_stl_any(bytes, file)
}

/// Binary or ASCII by the rules of the module docs.
fn parse_stl_any(bytes: &[u8], file: &str) -> Result<(TriangleMesh, Origins), UmbraError> {
    if bytes.iter().all(u8::is_ascii_whitespace) {
        return Err(UmbraError::Empty {
            file: file.to_string(),
        });
    }
    let size = bytes.len() as u64;
    let sized = binary_size_matches(bytes);
    if let Some((count, want)) = sized {
        if want == size {
            return Ok(parse_binary(bytes, count as usize));
        }
    }
    let text_start = bytes
        .strip_prefix("\u{feff}".as_bytes())
        .unwrap_or(bytes)
        .trim_ascii_start();
    let looks_ascii = text_start.len() >= 5 && text_start[..5].eq_ignore_ascii_case(b"solid");
    let binary_problem = match sized {
        Some((count, want)) if want > size => {
            let whole = (size - HEADER as u64) / RECORD as u64;
            format!(
                "truncated binary STL: the header says {count} triangles ({want} bytes) but the file has {size} bytes, ending inside triangle record {}",
                whole + 1
            )
        }
        Some((count, want)) => format!(
            "binary STL of {count} triangles ({want} bytes) followed by {} unexpected bytes",
            size - want
        ),
        None => format!("too short for a binary STL ({size} bytes, at least 84)"),
    };
    if !looks_ascii {
        return Err(malformed(
            file,
            format!("{binary_problem}, and not ASCII STL (which starts with 'solid')"),
        ));
    }
    parse_ascii(bytes, file).map_err(|e| match e {
        UmbraError::Malformed {
            file,
            format,
            message,
        } if sized.is_some() => UmbraError::Malformed {
            file,
            format,
            message: format!("{message} (read as ASCII STL since it starts with 'solid'; as binary STL: {binary_problem})"),
        },
        other => other,
    })
}

/// Reads `count` binary records; the size was checked by the caller.
fn parse_binary(bytes: &[u8], count: usize) -> (TriangleMesh, Origins) {
    let mut welder = Welder::new(count, "record");
    for (k, record) in bytes[HEADER..].chunks_exact(RECORD).enumerate() {
        let f = |i: usize| {
            let at = 12 + 4 * i;
            f64::from(f32::from_le_bytes([
                record[at],
                record[at + 1],
                record[at + 2],
                record[at + 3],
            ]))
        };
        let corners = [[f(0), f(1), f(2)], [f(3), f(4), f(5)], [f(6), f(7), f(8)]];
        welder.triangle(corners, k as u32 + 1);
    }
    let mesh = TriangleMesh::new(welder.vertices, welder.triangles);
    (mesh, welder.origins)
}

/// The ASCII grammar's tokens, with their line numbers.
struct Tokens<'a> {
    lines: std::iter::Peekable<Box<dyn Iterator<Item = (usize, &'a str)> + 'a>>,
    current: std::str::SplitAsciiWhitespace<'a>,
    line: usize,
    file: &'a str,
}

impl<'a> Tokens<'a> {
    fn new(text: &'a str, file: &'a str) -> Self {
        let lines: Box<dyn Iterator<Item = (usize, &'a str)> + 'a> =
            Box::new(text.lines().enumerate().map(|(i, l)| (i + 1, l)));
        Tokens {
            lines: lines.peekable(),
            current: "".split_ascii_whitespace(),
            line: 0,
            file,
        }
    }

    fn next(&mut self) -> Option<&'a str> {
        loop {
            if let Some(t) = self.current.next() {
                return Some(t);
            }
            let (n, l) = self.lines.next()?;
            self.line = n;
            self.current = l.split_ascii_whitespace();
        }
    }

    /// The rest of the current line (a solid's name), skipped.
    fn skip_line(&mut self) {
        self.current = "".split_ascii_whitespace();
    }

    fn error(&self, message: impl Into<String>) -> UmbraError {
        let line = if self.line == 0 {
            "at the end".to_string()
        } else {
            format!("line {}", self.line)
        };
        malformed(self.file, format!("{line}: {}", message.into()))
    }

    fn expect(&mut self, keyword: &str) -> Result<(), UmbraError> {
        match self.next() {
            Some(t) if t.eq_ignore_ascii_case(keyword) => Ok(()),
            Some(t) => Err(self.error(format!("expected '{keyword}', found '{}'", shorten(t)))),
            None => Err(self.error(format!("truncated: expected '{keyword}'"))),
        }
    }

    fn number(&mut self) -> Result<f64, UmbraError> {
        match self.next() {
            Some(t) => parse_number(t).map_err(|m| self.error(m)),
            None => Err(self.error("truncated: expected a number")),
        }
    }
}

/// Reads ASCII STL.
fn parse_ascii(bytes: &[u8], file: &str) -> Result<(TriangleMesh, Origins), UmbraError> {
    let text = super::text::decode(bytes, file, FORMAT)?;
    let text = strip_bom(text);
    if let Some(at) = text
        .bytes()
        .position(|b| b.is_ascii_control() && !b.is_ascii_whitespace())
    {
        let line = 1 + text.as_bytes()[..at]
            .iter()
            .filter(|&&b| b == b'\n')
            .count();
        return Err(malformed(
            file,
            format!(
                "line {line}: binary data (control byte 0x{:02x}) in an ASCII STL",
                text.as_bytes()[at]
            ),
        ));
    }
    // Every facet takes well over 50 bytes of text.
    let mut welder = Welder::new(text.len() / 64 + 1, "line");
    let mut tokens = Tokens::new(text, file);
    let mut solids = 0usize;
    loop {
        match tokens.next() {
            None if solids > 0 => break,
            None => return Err(tokens.error("truncated: expected 'solid'")),
            Some(t) if t.eq_ignore_ascii_case("solid") => solids += 1,
            Some(t) => {
                return Err(tokens.error(format!(
                    "expected 'solid' (the start of a solid), found '{}'",
                    shorten(t)
                )))
            }
        }
        tokens.skip_line();
        loop {
            match tokens.next() {
                Some(t) if t.eq_ignore_ascii_case("endsolid") => {
                    tokens.skip_line();
                    break;
                }
                Some(t) if t.eq_ignore_ascii_case("facet") => {}
                Some(t) => {
                    return Err(tokens.error(format!(
                        "expected 'facet' or 'endsolid', found '{}'",
                        shorten(t)
                    )))
                }
                None => return Err(tokens.error("truncated: expected 'facet' or 'endsolid'")),
            }
            let place = tokens.line as u32;
            tokens.expect("normal")?;
            for _ in 0..3 {
                tokens.number()?;
            }
            tokens.expect("outer")?;
            tokens.expect("loop")?;
            let mut corners = [[0.0; 3]; 3];
            for corner in &mut corners {
                tokens.expect("vertex")?;
                for c in corner.iter_mut() {
                    *c = tokens.number()?;
                }
            }
            match tokens.next() {
                Some(t) if t.eq_ignore_ascii_case("endloop") => {}
                Some(t) if t.eq_ignore_ascii_case("vertex") => {
                    return Err(tokens
                        .error("a facet with more than 3 vertices (STL facets are triangles)"))
                }
                Some(t) => {
                    return Err(tokens.error(format!("expected 'endloop', found '{}'", shorten(t))))
                }
                None => return Err(tokens.error("truncated: expected 'endloop'")),
            }
            tokens.expect("endfacet")?;
            if welder.triangles.len() >= u32::MAX as usize / 4 {
                return Err(tokens.error("too many triangles"));
            }
            welder.triangle(corners, place);
        }
    }
    let mesh = TriangleMesh::new(welder.vertices, welder.triangles);
    Ok((mesh, welder.origins))
}

/// Reads STL bytes into a polygon mesh of triangles: welded, coordinates
/// validated if asked, closure checked if `check` (see
/// [`crate::read_mesh`]).
pub(crate) fn read_stl_bytes(
    bytes: &[u8],
    file: &str,
    options: MeshReadOptions,
    check: bool,
) -> Result<PolygonMesh, UmbraError> {
    let (mesh, origins) = parse_stl_with_origins(bytes, file)?;
    finish(mesh.to_polygon_mesh(), &origins, file, options, check)
}

/// The triangles to write: facets triangulated (section 4.8).
pub(crate) fn triangles_stl(mesh: &PolygonMesh) -> TriangleMesh {
    boolean_3d::triangulate_mesh(mesh)
}

/// The unit normal of a triangle (zero for a degenerate one), in `f32`.
fn normal(a: Point3, b: Point3, c: Point3) -> [f32; 3] {
    let u = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
    let v = [c[0] - a[0], c[1] - a[1], c[2] - a[2]];
    let n = [
        u[1] * v[2] - u[2] * v[1],
        u[2] * v[0] - u[0] * v[2],
        u[0] * v[1] - u[1] * v[0],
    ];
    let len = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
    if len > 0.0 && len.is_finite() {
        [
            (n[0] / len) as f32,
            (n[1] / len) as f32,
            (n[2] / len) as f32,
        ]
    } else {
        [0.0; 3]
    }
}

/// A coordinate as `f32` (rounded to nearest), or an error for one that is
/// not finite or beyond the `f32` range.
pub(crate) fn to_f32(
    value: f64,
    vertex: usize,
    axis: usize,
    format: &'static str,
) -> Result<f32, UmbraError> {
    let r = value as f32;
    if r.is_finite() {
        Ok(r)
    } else {
        Err(UmbraError::Unwritable {
            file: "<output>".to_string(),
            format,
            message: format!(
                "vertex {vertex}: {} = {value:e} is not a finite f32 (|v| <= 3.4e38)",
                ["x", "y", "z"][axis]
            ),
        })
    }
}

/// The STL bytes of a mesh, binary or (`ascii`) text (see the module docs).
/// Fails on a NaN or infinite coordinate, on a coordinate beyond the `f32`
/// range in binary STL, and on more than `u32::MAX` triangles in binary
/// STL.
pub fn mesh_to_stl(mesh: &PolygonMesh, ascii: bool) -> Result<Vec<u8>, UmbraError> {
    triangles_to_stl(&triangles_stl(mesh), ascii)
}

/// [`mesh_to_stl`] of triangles already made: every triangle written as it
/// is, in order.
pub(crate) fn triangles_to_stl(tris: &TriangleMesh, ascii: bool) -> Result<Vec<u8>, UmbraError> {
    for (v, p) in tris.vertices.iter().enumerate() {
        for (axis, &c) in p.iter().enumerate() {
            if ascii {
                if !c.is_finite() {
                    return Err(UmbraError::Unwritable {
                        file: "<output>".to_string(),
                        format: FORMAT,
                        message: format!(
                            "vertex {v}: {} = {c} is not finite",
                            ["x", "y", "z"][axis]
                        ),
                    });
                }
            } else {
                to_f32(c, v, axis, FORMAT)?;
            }
        }
    }
    if ascii {
        let mut s = String::with_capacity(64 + 200 * tris.triangles.len());
        s.push_str("solid umbra\n");
        for t in &tris.triangles {
            let [a, b, c] = t.map(|i| tris.vertices[i as usize]);
            let n = normal(a, b, c);
            s.push_str("  facet normal");
            for x in n {
                s.push(' ');
                push_f64(&mut s, f64::from(x));
            }
            s.push_str("\n    outer loop\n");
            for p in [a, b, c] {
                s.push_str("      vertex");
                for x in p {
                    s.push(' ');
                    push_f64(&mut s, x);
                }
                s.push('\n');
            }
            s.push_str("    endloop\n  endfacet\n");
        }
        s.push_str("endsolid umbra\n");
        return Ok(s.into_bytes());
    }
    let count = u32::try_from(tris.triangles.len()).map_err(|_| UmbraError::Unwritable {
        file: "<output>".to_string(),
        format: FORMAT,
        message: format!(
            "{} triangles (binary STL holds at most {})",
            tris.triangles.len(),
            u32::MAX
        ),
    })?;
    let mut out = Vec::with_capacity(HEADER + RECORD * tris.triangles.len());
    let mut header = [b' '; 80];
    let title = b"binary STL written by umbra";
    header[..title.len()].copy_from_slice(title);
    out.extend_from_slice(&header);
    out.extend_from_slice(&count.to_le_bytes());
    for t in &tris.triangles {
        let [a, b, c] = t.map(|i| tris.vertices[i as usize]);
        for x in normal(a, b, c) {
            out.extend_from_slice(&x.to_le_bytes());
        }
        for p in [a, b, c] {
            for x in p {
                // Checked above.
                out.extend_from_slice(&(x as f32).to_le_bytes());
            }
        }
        out.extend_from_slice(&[0, 0]);
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn cube() -> TriangleMesh {
        let v: Vec<Point3> = (0..8u32)
            .map(|i| {
                [
                    f64::from(i & 1),
                    f64::from((i >> 1) & 1),
                    f64::from((i >> 2) & 1),
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
        let mut t = Vec::new();
        for q in quads {
            t.push([q[0], q[1], q[2]]);
            t.push([q[0], q[2], q[3]]);
        }
        TriangleMesh::new(v, t)
    }

    /// The triangles as bit patterns of their corners.
    fn soup(m: &TriangleMesh) -> Vec<[[u64; 3]; 3]> {
        m.triangles
            .iter()
            .map(|t| t.map(|i| m.vertices[i as usize].map(f64::to_bits)))
            .collect()
    }

    #[test]
    fn binary_and_ascii_round_trip() {
        let c = cube();
        for ascii in [false, true] {
            let bytes = mesh_to_stl(&c.to_polygon_mesh(), ascii).unwrap();
            let back = parse_stl(&bytes, "c.stl").unwrap();
            assert_eq!(soup(&back), soup(&c), "ascii {ascii}");
            assert_eq!(back.vertices.len(), 8);
            back.check_topology().unwrap();
        }
    }

    #[test]
    fn binary_header_starting_with_solid_is_binary() {
        let mut bytes = mesh_to_stl(&cube().to_polygon_mesh(), false).unwrap();
        bytes[..6].copy_from_slice(b"solid ");
        assert_eq!(soup(&parse_stl(&bytes, "s.stl").unwrap()), soup(&cube()));
    }

    #[test]
    fn minus_zero_welds_with_zero() {
        let text = "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\n\
                    facet normal 0 0 -1\nouter loop\nvertex -0 0 -0.0\nvertex 0 1 0\nvertex 1 0 0\nendloop\nendfacet\nendsolid t\n";
        let m = parse_stl(text.as_bytes(), "z.stl").unwrap();
        assert_eq!(m.vertices.len(), 3);
        assert_eq!(m.vertices[0][0].to_bits(), 0.0f64.to_bits());
        m.check_topology().unwrap();
    }

    #[test]
    fn open_soup_names_an_edge_by_positions() {
        let mut c = cube();
        c.triangles.pop();
        let bytes = mesh_to_stl(&c.to_polygon_mesh(), false).unwrap();
        let e = read_stl_bytes(&bytes, "open.stl", MeshReadOptions::default(), true)
            .unwrap_err()
            .to_string();
        assert!(
            e.starts_with(
                "open.stl: invalid shape: shape boundary closure violated: the edge from vertex"
            ),
            "{e}"
        );
        assert!(
            e.contains("(record ") && e.contains("(1.0, ") || e.contains("(0.0, "),
            "{e}"
        );
    }

    #[test]
    fn hostile_headers_and_text() {
        let cases: Vec<(Vec<u8>, &str)> = vec![
            (b"".to_vec(), "empty"),
            (b"hello".to_vec(), "too short for a binary STL (5 bytes, at least 84), and not ASCII STL"),
            (
                {
                    let mut b = vec![0u8; 84 + 30];
                    b[80..84].copy_from_slice(&u32::MAX.to_le_bytes());
                    b
                },
                "the header says 4294967295 triangles (214748364834 bytes) but the file has 114 bytes, ending inside triangle record 1",
            ),
            (
                {
                    let mut b = vec![0u8; 84 + 50 + 7];
                    b[80..84].copy_from_slice(&1u32.to_le_bytes());
                    b
                },
                "followed by 7 unexpected bytes",
            ),
            (b"solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 1e400\n".to_vec(), "line 4: '1e400' overflows f64"),
            (b"solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0\nendloop".to_vec(), "line 5: 'endloop' is not a number"),
            (b"solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 0 0 0\nvertex 0 0 0\nvertex 0 0 0\n".to_vec(), "line 7: a facet with more than 3 vertices"),
            (b"solid x\nfacet normal 0 0 1\n".to_vec(), "line 2: truncated: expected 'outer'"),
            (b"solid x\n\xff\n".to_vec(), "line 2: not UTF-8"),
            (b"solid x\n\x01\n".to_vec(), "line 2: binary data (control byte 0x01)"),
            (b"solid x\nendsolid\ngarbage".to_vec(), "line 3: expected 'solid'"),
        ];
        for (bytes, want) in cases {
            let e = parse_stl(&bytes, "h.stl").unwrap_err().to_string();
            assert!(e.starts_with("h.stl: ") && e.contains(want), "{want}: {e}");
        }
    }

    #[test]
    fn no_triangles_is_the_empty_mesh_and_white_space_an_error() {
        let mut b = vec![b' '; 84];
        b[80..84].copy_from_slice(&0u32.to_le_bytes());
        for bytes in [
            b,
            b"solid x\nendsolid x\n".to_vec(),
            b"solid\nendsolid".to_vec(),
        ] {
            assert_eq!(parse_stl(&bytes, "e.stl").unwrap(), TriangleMesh::default());
        }
        for bytes in [&b""[..], b" \n\t"] {
            let e = parse_stl(bytes, "e.stl").unwrap_err().to_string();
            assert_eq!(e, "e.stl: the file is empty (no geometry)");
        }
        // Both encodings of the empty mesh read back as written.
        for ascii in [false, true] {
            let bytes = mesh_to_stl(&PolygonMesh::default(), ascii).unwrap();
            assert_eq!(parse_stl(&bytes, "e.stl").unwrap(), TriangleMesh::default());
        }
    }

    #[test]
    fn nan_is_reported_with_its_record() {
        let mut bytes = mesh_to_stl(&cube().to_polygon_mesh(), false).unwrap();
        // Triangle record 3, corner 2, y.
        let at = 84 + 2 * 50 + 12 + 12 + 4;
        bytes[at..at + 4].copy_from_slice(&f32::NAN.to_le_bytes());
        let e = read_stl_bytes(&bytes, "n.stl", MeshReadOptions::default(), true)
            .unwrap_err()
            .to_string();
        assert!(
            e.contains("(record 3): y coordinate NaN is not finite"),
            "{e}"
        );
    }

    #[test]
    fn unwritable_coordinates_are_refused() {
        let mut c = cube();
        c.vertices[3][2] = 1e300;
        let e = mesh_to_stl(&c.to_polygon_mesh(), false)
            .unwrap_err()
            .to_string();
        assert!(
            e.contains("cannot write STL") && e.contains("z = 1e300"),
            "{e}"
        );
    }
}
