//! glTF 2.0 reading, binary (`.glb`) and JSON (`.gltf`): the triangles of
//! every mesh that the scene places, through the node hierarchy's
//! transforms, welded by exact position into one triangle mesh.
//!
//! The `gltf` crate splits the binary container and deserializes the JSON
//! document into its typed structures. Everything after that is done here
//! on those structures, every index looked up with `get` and every offset
//! and length checked against its buffer with checked arithmetic: the
//! crate's validation and its `Document` API index the arrays directly (a
//! POSITION accessor index out of range panics in its validation hook),
//! and its accessor readers assert on mismatched strides and types and
//! trust the counts, which a hostile file sets at will.
//!
//! - **Which meshes.** The nodes of the default scene (the first scene when
//!   none is named), depth first; without scenes, every node that is no
//!   node's child; without nodes, every mesh once, untransformed. A node
//!   reached twice (the hierarchy must be a forest) is an error, so a cycle
//!   or a shared child cannot expand the file exponentially; the mesh
//!   instances together may give at most [`MAX_TRIANGLES`] triangles.
//! - **Transforms.** Each node's matrix (or translation, rotation and
//!   scale), composed from the root in `f64`; the identity is not applied,
//!   so untransformed positions keep their `f32` values exactly. The
//!   specification makes a negative determinant turn the winding order
//!   around (section 3.7.2.1 of glTF 2.0: "If the determinant is a positive
//!   value, the winding order triangle faces is counterclockwise; in the
//!   opposite case, the winding order is clockwise"), so such an
//!   instance's triangles are reversed to keep them facing out.
//! - **Primitives.** Triangle lists, strips and fans (the orders of section
//!   3.7.2.1), with or without an index accessor; points and lines bound
//!   no volume and are passed over. Positions must be `VEC3` of `FLOAT`
//!   (the core specification's only choice); indices `SCALAR` of unsigned
//!   bytes, shorts or ints, each below the position count. Sparse
//!   accessors and accessors without a buffer view are refused with a
//!   message saying so. An extension the file *requires* (mesh compression
//!   such as Draco or meshopt) is refused by name.
//! - **Buffers** (section 3.6.1). A buffer without a `uri` is the binary
//!   chunk of a `.glb`. A `data:` URI carries its bytes in base64 (section
//!   3.6.1.1; the padding may be left out). Any other URI is a file beside
//!   the document, a relative reference with `%`-escapes (RFC 3986): read
//!   from the document's directory when the document was read from a file
//!   ([`Buffers::with_directory`]), refused otherwise. Only plain relative
//!   paths are followed: a URI with a scheme (`http:`, `file:`), an
//!   absolute path, a `..` segment or a backslash is refused, so a document
//!   cannot make the reader open a file outside its own directory. At most
//!   the buffer's `byteLength` is read from a file, and only a regular
//!   file is read. A buffer is loaded the first time a primitive uses it,
//!   so buffers of textures or animations are never touched.
//! - **Welding.** Exporters split vertices at normal and texture seams, so
//!   the corners are welded by exact position (`weld.rs`), across every
//!   primitive and instance, as STL corners are. Errors of closure name a
//!   triangle by its number in reading order and the glTF mesh it belongs
//!   to.
//!
//! A well-formed file that places no triangle is the empty mesh.

use super::mesh_text::MeshReadOptions;
use super::origin::{finish, Origins};
use super::weld::Welder;
use crate::UmbraError;
use base64::engine::{DecodePaddingMode, GeneralPurpose, GeneralPurposeConfig};
use base64::Engine;
use gltf::json::accessor::{ComponentType, Type};
use gltf::json::mesh::{Mode, Semantic};
use gltf::json::validation::Checked;
use gltf::json::Root;
use robust_arith::Point3;
use std::borrow::Cow;
use std::cell::OnceCell;
use std::io::Read;
use std::path::Path;
use topology::{PolygonMesh, TriangleMesh};

const FORMAT: &str = "glTF";

/// The most triangles the placed mesh instances may give together (about
/// 33 million): instancing lets a small file place one mesh many times,
/// and this bounds the memory such a file can claim.
pub(crate) const MAX_TRIANGLES: usize = 1 << 25;

/// A column-major 4 x 4 matrix, as glTF stores it.
type Matrix = [[f64; 4]; 4];

const IDENTITY: Matrix = [
    [1.0, 0.0, 0.0, 0.0],
    [0.0, 1.0, 0.0, 0.0],
    [0.0, 0.0, 1.0, 0.0],
    [0.0, 0.0, 0.0, 1.0],
];

fn malformed(file: &str, message: impl Into<String>) -> UmbraError {
    UmbraError::Malformed {
        file: file.to_string(),
        format: FORMAT,
        message: message.into(),
    }
}

/// Parses glTF bytes, binary (`.glb`) or JSON (`.gltf`), into a welded
/// triangle mesh, unchecked (see the module docs); `file` names the source
/// in errors. Buffers must be in the binary chunk or in `data:` URIs: bytes
/// have no directory in which to find a buffer's file (read such a
/// document with [`crate::read_mesh`]).
///
/// ```
/// use umbra::{mesh_to_glb, mesh_to_gltf, parse_glb, TriangleMesh};
/// // Coordinates that are `f32` values read back exactly.
/// let tet = TriangleMesh::new(
///     vec![[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 0.5]],
///     vec![[0, 1, 2], [0, 3, 1], [1, 3, 2], [0, 2, 3]],
/// );
/// let bytes = mesh_to_glb(&tet.to_polygon_mesh()).unwrap();
/// assert_eq!(parse_glb(&bytes, "tet.glb").unwrap(), tet);
/// let text = mesh_to_gltf(&tet.to_polygon_mesh()).unwrap();
/// assert_eq!(parse_glb(&text, "tet.gltf").unwrap(), tet);
/// ```
pub fn parse_glb(bytes: &[u8], file: &str) -> Result<TriangleMesh, UmbraError> {
    parse_with_origins(bytes, file, None).map(|(mesh, _)| mesh)
}

/// Reads glTF bytes (binary or JSON) into a polygon mesh of triangles:
/// buffer files looked up in `directory` (the document's own), welded,
/// coordinates validated if asked, closure checked if `check` (see
/// [`crate::read_mesh`]).
pub(crate) fn read_gltf_bytes(
    bytes: &[u8],
    file: &str,
    directory: Option<&Path>,
    options: MeshReadOptions,
    check: bool,
) -> Result<PolygonMesh, UmbraError> {
    let (mesh, origins) = parse_with_origins(bytes, file, directory)?;
    finish(mesh.to_polygon_mesh(), &origins, file, options, check)
}

/// [`parse_glb`] with the glTF mesh of every triangle, buffer files looked
/// up in `directory`.
fn parse_with_origins(
    bytes: &[u8],
    file: &str,
    directory: Option<&Path>,
) -> Result<(TriangleMesh, Origins), UmbraError> {
    if bytes.iter().all(u8::is_ascii_whitespace) {
        return Err(UmbraError::Empty {
            file: file.to_string(),
        });
    }
    let (json, blob) = split_container(bytes, file)?;
    let root: Root = gltf::json::deserialize::from_slice(json)
        .map_err(|e| malformed(file, format!("invalid glTF JSON: {e}")))?;
    if let Some(ext) = root.extensions_required.first() {
        return Err(malformed(
            file,
            format!("the file requires the extension {ext}, which Umbra does not read"),
        ));
    }
    let mut reader = Reader {
        file,
        root: &root,
        buffers: Buffers::new(&root, blob, directory),
        welder: Welder::new(0, "mesh"),
    };
    let scene = match root.scene {
        Some(i) => Some(root.scenes.get(i.value()).ok_or_else(|| {
            malformed(
                file,
                format!("the default scene {} does not exist", i.value()),
            )
        })?),
        None => root.scenes.first(),
    };
    if let Some(scene) = scene {
        let roots: Vec<usize> = scene.nodes.iter().map(|n| n.value()).collect();
        reader.place_nodes(&roots)?;
    } else if !root.nodes.is_empty() {
        let mut child = vec![false; root.nodes.len()];
        for n in &root.nodes {
            for c in n.children.iter().flatten() {
                if let Some(flag) = child.get_mut(c.value()) {
                    *flag = true;
                }
            }
        }
        let roots: Vec<usize> = (0..child.len()).filter(|&i| !child[i]).collect();
        reader.place_nodes(&roots)?;
    } else {
        for m in 0..root.meshes.len() {
            reader.place_mesh(m, &IDENTITY)?;
        }
    }
    let Welder {
        vertices,
        triangles,
        origins,
        ..
    } = reader.welder;
    Ok((TriangleMesh::new(vertices, triangles), origins))
}

/// The JSON document and the binary chunk of the bytes. The container's
/// header is checked here before the `gltf` crate splits the chunks (its
/// splitter subtracts the header size from the stated length without a
/// check): the magic, version 2, and a length that the bytes hold. Bytes
/// without the magic are a glTF JSON document without a binary chunk.
fn split_container<'b>(
    bytes: &'b [u8],
    file: &str,
) -> Result<(&'b [u8], Option<&'b [u8]>), UmbraError> {
    if !bytes.starts_with(b"glTF") {
        return Ok((bytes, None));
    }
    let word = |at: usize| {
        bytes
            .get(at..at + 4)
            .and_then(|w| w.try_into().ok())
            .map(u32::from_le_bytes)
    };
    let (Some(version), Some(length)) = (word(4), word(8)) else {
        return Err(malformed(file, "truncated binary glTF header"));
    };
    if version != 2 {
        return Err(malformed(
            file,
            format!("binary glTF version {version} (only version 2 is read)"),
        ));
    }
    // The 12-byte header and at least one 8-byte chunk header.
    if (length as usize) < 20 || length as usize > bytes.len() {
        return Err(malformed(
            file,
            format!(
                "the header gives a length of {length} bytes, but the file holds {}",
                bytes.len()
            ),
        ));
    }
    let glb = gltf::binary::Glb::from_slice(bytes)
        .map_err(|e| malformed(file, format!("invalid binary glTF container: {e}")))?;
    // `Glb::from_slice` splits the slice in place: both chunks borrow
    // from `bytes`.
    let borrowed = |chunk: Cow<'b, [u8]>, what: &str| match chunk {
        Cow::Borrowed(b) => Ok(b),
        Cow::Owned(_) => Err(malformed(file, format!("the {what} chunk was copied"))),
    };
    let json = borrowed(glb.json, "JSON")?;
    let bin = glb.bin.map(|b| borrowed(b, "binary")).transpose()?;
    Ok((json, bin))
}

/// The reading state: the document, its buffers and the welded triangles
/// so far.
struct Reader<'a> {
    file: &'a str,
    root: &'a Root,
    buffers: Buffers<'a>,
    welder: Welder,
}

/// The buffers of a document (section 3.6.1), each loaded when first used:
/// the binary chunk, a `data:` URI decoded, or a file of the document's
/// directory read.
struct Buffers<'a> {
    root: &'a Root,
    blob: Option<&'a [u8]>,
    directory: Option<&'a Path>,
    /// Buffer `i`'s bytes, or why it has none.
    loaded: Vec<OnceCell<Result<Cow<'a, [u8]>, String>>>,
}

/// Base64 as in RFC 4648 with the standard alphabet, padding optional
/// (encoders in the wild leave it out).
const BASE64: GeneralPurpose = GeneralPurpose::new(
    &base64::alphabet::STANDARD,
    GeneralPurposeConfig::new().with_decode_padding_mode(DecodePaddingMode::Indifferent),
);

impl<'a> Buffers<'a> {
    fn new(root: &'a Root, blob: Option<&'a [u8]>, directory: Option<&'a Path>) -> Self {
        Buffers {
            root,
            blob,
            directory,
            loaded: (0..root.buffers.len()).map(|_| OnceCell::new()).collect(),
        }
    }

    /// The bytes of buffer `index`, loaded once; `Err` says why there are
    /// none (the caller adds where it was asked for).
    fn get(&self, index: usize) -> Result<&[u8], String> {
        let Some(cell) = self.loaded.get(index) else {
            return Err(format!("buffer {index} does not exist"));
        };
        match cell.get_or_init(|| self.load(index)) {
            Ok(bytes) => Ok(bytes),
            Err(e) => Err(e.clone()),
        }
    }

    fn load(&self, index: usize) -> Result<Cow<'a, [u8]>, String> {
        let buffer = self
            .root
            .buffers
            .get(index)
            .ok_or_else(|| format!("buffer {index} does not exist"))?;
        let Some(uri) = &buffer.uri else {
            return self.blob.map(Cow::Borrowed).ok_or_else(|| {
                format!("buffer {index} has no uri, and the file has no binary chunk")
            });
        };
        if let Some(data) = strip_prefix_ignore_case(uri, "data:") {
            return decode_data_uri(data)
                .map(Cow::Owned)
                .map_err(|e| format!("buffer {index}: {e}"));
        }
        let relative = relative_path(uri).map_err(|e| format!("buffer {index}: {e}"))?;
        let Some(directory) = self.directory else {
            return Err(format!(
                "buffer {index} is the file '{}' beside the document, and bytes alone have no directory to find it in (read the document from its file)",
                shown(uri)
            ));
        };
        let path = directory.join(&relative);
        read_buffer_file(&path, buffer.byte_length.0)
            .map(Cow::Owned)
            .map_err(|e| format!("buffer {index} ('{}'): {e}", path.display()))
    }
}

/// `text` without `prefix`, compared ASCII case-insensitively (URI schemes
/// are case-insensitive, RFC 3986 section 3.1).
fn strip_prefix_ignore_case<'t>(text: &'t str, prefix: &str) -> Option<&'t str> {
    let head = text.get(..prefix.len())?;
    head.eq_ignore_ascii_case(prefix)
        .then(|| &text[prefix.len()..])
}

/// At most 40 characters of a URI, for messages.
fn shown(uri: &str) -> String {
    let mut s: String = uri.chars().take(40).collect();
    if s.len() < uri.len() {
        s.push_str("...");
    }
    s
}

/// The bytes of a data URI's rest (after `data:`): `[<media type>];base64,`
/// and the base64 text (RFC 2397; glTF requires base64).
fn decode_data_uri(rest: &str) -> Result<Vec<u8>, String> {
    let Some((header, data)) = rest.split_once(',') else {
        return Err("a data URI without a comma".to_string());
    };
    if !header
        .rsplit(';')
        .next()
        .is_some_and(|p| p.eq_ignore_ascii_case("base64"))
    {
        return Err(format!(
            "the data URI 'data:{}' is not base64 (glTF data URIs are)",
            shown(header)
        ));
    }
    BASE64
        .decode(data.trim_end())
        .map_err(|e| format!("invalid base64 in a data URI: {e}"))
}

/// The relative file path a buffer URI names: `%`-escapes decoded (UTF-8),
/// refused unless a plain relative path (no scheme, not absolute, no `..`
/// segment, no backslash, no query or fragment).
fn relative_path(uri: &str) -> Result<std::path::PathBuf, String> {
    let refuse = |why: &str| Err(format!("the URI '{}' {why}", shown(uri)));
    if uri.is_empty() {
        return refuse("is empty");
    }
    let first = uri.split('/').next().unwrap_or("");
    if first.contains(':') {
        return refuse(
            "has a scheme or a drive: only data URIs and files beside the document are read",
        );
    }
    if uri.starts_with('/') {
        return refuse("is an absolute path: only files beside the document are read");
    }
    if uri.contains(['?', '#']) {
        return refuse("has a query or a fragment");
    }
    let decoded = percent_encoding::percent_decode_str(uri)
        .decode_utf8()
        .map_err(|_| format!("the URI '{}' does not decode to UTF-8", shown(uri)))?;
    if decoded.contains('\\') || decoded.contains('\0') {
        return refuse("holds a backslash or a NUL");
    }
    let mut path = std::path::PathBuf::new();
    for segment in decoded.split('/') {
        match segment {
            "" | "." => {}
            ".." => return refuse("leaves the document's directory ('..')"),
            s if s.contains(':') => return refuse("has a ':' in a segment"),
            s => path.push(s),
        }
    }
    if path.as_os_str().is_empty() {
        return refuse("names no file");
    }
    Ok(path)
}

/// At most `byte_length` bytes of the regular file `path`.
fn read_buffer_file(path: &Path, byte_length: u64) -> Result<Vec<u8>, String> {
    let file = std::fs::File::open(path).map_err(|e| e.to_string())?;
    let meta = file.metadata().map_err(|e| e.to_string())?;
    if !meta.is_file() {
        return Err("not a regular file".to_string());
    }
    let want = byte_length.min(meta.len());
    let mut bytes = Vec::with_capacity(usize::try_from(want).unwrap_or(0));
    file.take(want)
        .read_to_end(&mut bytes)
        .map_err(|e| e.to_string())?;
    Ok(bytes)
}

impl Reader<'_> {
    /// Places the meshes of the trees rooted at `roots`, depth first.
    fn place_nodes(&mut self, roots: &[usize]) -> Result<(), UmbraError> {
        let mut seen = vec![false; self.root.nodes.len()];
        let mut stack: Vec<(usize, Matrix)> = roots.iter().rev().map(|&r| (r, IDENTITY)).collect();
        while let Some((index, parent)) = stack.pop() {
            let Some(node) = self.root.nodes.get(index) else {
                return Err(malformed(self.file, format!("node {index} does not exist")));
            };
            match seen.get_mut(index) {
                Some(s) if !*s => *s = true,
                _ => {
                    return Err(malformed(
                        self.file,
                        format!(
                            "node {index} is reached twice: the node hierarchy is not a forest (a cycle or a shared child)"
                        ),
                    ))
                }
            }
            let world = compose(&parent, &local_matrix(node));
            if let Some(mesh) = node.mesh {
                self.place_mesh(mesh.value(), &world)?;
            }
            let children = node.children.iter().flatten().rev();
            stack.extend(children.map(|c| (c.value(), world)));
        }
        Ok(())
    }

    /// Adds the triangles of every triangle primitive of mesh `index`
    /// under the transform `m`.
    fn place_mesh(&mut self, index: usize, m: &Matrix) -> Result<(), UmbraError> {
        let root = self.root;
        let Some(mesh) = root.meshes.get(index) else {
            return Err(malformed(self.file, format!("mesh {index} does not exist")));
        };
        let flip = determinant(m) < 0.0;
        let transform = *m != IDENTITY;
        for (p, prim) in mesh.primitives.iter().enumerate() {
            let what = format!("mesh {index} primitive {p}");
            let mode = match prim.mode {
                Checked::Valid(mode) => mode,
                Checked::Invalid => {
                    return Err(malformed(self.file, format!("{what}: invalid mode")))
                }
            };
            if !matches!(
                mode,
                Mode::Triangles | Mode::TriangleStrip | Mode::TriangleFan
            ) {
                continue;
            }
            let Some(position) = prim.attributes.get(&Checked::Valid(Semantic::Positions)) else {
                return Err(malformed(
                    self.file,
                    format!("{what}: no POSITION attribute"),
                ));
            };
            let positions = self.positions(position.value(), &what)?;
            let indices = match prim.indices {
                Some(acc) => self.indices(acc.value(), &what, positions.len())?,
                None => (0..positions.len() as u32).collect(),
            };
            let corners = triangle_corners(mode, &indices);
            let total = self.welder.triangles.len().saturating_add(corners.len());
            if total > MAX_TRIANGLES {
                return Err(malformed(
                    self.file,
                    format!(
                        "the scene places more than {MAX_TRIANGLES} triangles (mesh instances expand the file beyond what is read)"
                    ),
                ));
            }
            let placed: Vec<Point3> = if transform {
                positions.iter().map(|p| apply(m, p)).collect()
            } else {
                positions
            };
            let place = index as u32;
            for t in corners {
                let [a, b, c] = t.map(|i| placed.get(i as usize).copied().unwrap_or([0.0; 3]));
                let corners = if flip { [a, c, b] } else { [a, b, c] };
                self.welder.triangle(corners, place);
            }
        }
        Ok(())
    }

    /// The accessor `index`, or an error.
    fn accessor(&self, index: usize, what: &str) -> Result<&gltf::json::Accessor, UmbraError> {
        self.root.accessors.get(index).ok_or_else(|| {
            malformed(
                self.file,
                format!("{what}: accessor {index} does not exist"),
            )
        })
    }

    /// The bytes of buffer view `index` of the binary chunk.
    fn view_bytes(&self, index: usize, what: &str) -> Result<(&[u8], Option<usize>), UmbraError> {
        let file = self.file;
        let view = self.root.buffer_views.get(index).ok_or_else(|| {
            malformed(file, format!("{what}: buffer view {index} does not exist"))
        })?;
        let b = view.buffer.value();
        let blob = self
            .buffers
            .get(b)
            .map_err(|e| malformed(file, format!("{what}: {e}")))?;
        let offset = view.byte_offset.map_or(0, |o| o.0);
        let length = view.byte_length.0;
        let range = usize::try_from(offset)
            .ok()
            .zip(usize::try_from(length).ok())
            .and_then(|(o, l)| Some(o..o.checked_add(l)?));
        let bytes = range.and_then(|r| blob.get(r)).ok_or_else(|| {
            malformed(
                file,
                format!(
                    "{what}: buffer view {index} (bytes {offset}..+{length}) lies beyond its buffer {b} of {} bytes",
                    blob.len()
                ),
            )
        })?;
        Ok((bytes, view.byte_stride.map(|s| s.0)))
    }

    /// The `count` elements of `size` bytes of accessor `acc` (number
    /// `index`), as slices, every bound checked.
    fn elements(
        &self,
        acc: &gltf::json::Accessor,
        index: usize,
        size: usize,
        what: &str,
    ) -> Result<Vec<&[u8]>, UmbraError> {
        if acc.sparse.is_some() {
            return Err(malformed(
                self.file,
                format!("{what}: accessor {index} is sparse, which Umbra does not read"),
            ));
        }
        // Without a buffer view the accessor is zeros (meant for sparse
        // accessors, which are not read): no exporter writes positions or
        // indices that way, and its count would be the file's word alone.
        let Some(view) = acc.buffer_view else {
            return Err(malformed(
                self.file,
                format!("{what}: accessor {index} has no buffer view"),
            ));
        };
        let (bytes, stride) = self.view_bytes(view.value(), what)?;
        let stride = stride.unwrap_or(size).max(size);
        let count = acc.count.0;
        let offset = acc.byte_offset.map_or(0, |o| o.0);
        let span = usize::try_from(count)
            .ok()
            .zip(usize::try_from(offset).ok())
            .and_then(|(count, offset)| {
                let end = match count.checked_sub(1) {
                    None => offset,
                    Some(last) => last
                        .checked_mul(stride)?
                        .checked_add(size)?
                        .checked_add(offset)?,
                };
                Some((count, bytes.get(offset..end)?))
            });
        let Some((count, data)) = span else {
            return Err(malformed(
                self.file,
                format!(
                    "{what}: accessor {index} ({count} elements of {size} bytes, stride {stride}, offset {offset}) runs past its buffer view of {} bytes",
                    bytes.len()
                ),
            ));
        };
        Ok((0..count)
            .filter_map(|i| data.get(i * stride..i * stride + size))
            .collect())
    }

    /// The positions of accessor `index` (`VEC3` of `FLOAT`), as `f64`.
    fn positions(&self, index: usize, what: &str) -> Result<Vec<Point3>, UmbraError> {
        let acc = self.accessor(index, what)?;
        let kind = (&acc.type_, &acc.component_type);
        if !matches!(kind, (Checked::Valid(Type::Vec3), Checked::Valid(c)) if c.0 == ComponentType::F32)
        {
            return Err(malformed(
                self.file,
                format!(
                    "{what}: POSITION accessor {index} is {}, not VEC3 of FLOAT",
                    kind_name(&acc.type_, &acc.component_type)
                ),
            ));
        }
        let f = |b: &[u8], at: usize| {
            b.get(at..at + 4)
                .and_then(|w| w.try_into().ok())
                .map_or(0.0, |w| f64::from(f32::from_le_bytes(w)))
        };
        Ok(self
            .elements(acc, index, 12, what)?
            .iter()
            .map(|b| [f(b, 0), f(b, 4), f(b, 8)])
            .collect())
    }

    /// The indices of accessor `index` (`SCALAR` of unsigned integers),
    /// each checked against the `n` positions.
    fn indices(&self, index: usize, what: &str, n: usize) -> Result<Vec<u32>, UmbraError> {
        let acc = self.accessor(index, what)?;
        let size = match (&acc.type_, &acc.component_type) {
            (Checked::Valid(Type::Scalar), Checked::Valid(c)) => match c.0 {
                ComponentType::U8 => Some(1),
                ComponentType::U16 => Some(2),
                ComponentType::U32 => Some(4),
                _ => None,
            },
            _ => None,
        };
        let Some(size) = size else {
            return Err(malformed(
                self.file,
                format!(
                    "{what}: index accessor {index} is {}, not SCALAR of an unsigned integer",
                    kind_name(&acc.type_, &acc.component_type)
                ),
            ));
        };
        let elements = self.elements(acc, index, size, what)?;
        let mut out = Vec::with_capacity(elements.len());
        for (k, b) in elements.iter().enumerate() {
            let i = b
                .iter()
                .rev()
                .fold(0u32, |acc, &byte| (acc << 8) | u32::from(byte));
            if i as usize >= n {
                return Err(malformed(
                    self.file,
                    format!("{what}: index {k} is {i}, but there are only {n} positions"),
                ));
            }
            out.push(i);
        }
        Ok(out)
    }
}

/// An accessor's element type for messages (`VEC3 of U16`).
fn kind_name(t: &Checked<Type>, c: &Checked<gltf::json::accessor::GenericComponentType>) -> String {
    let t = match t {
        Checked::Valid(t) => format!("{t:?}").to_ascii_uppercase(),
        Checked::Invalid => "an invalid type".to_string(),
    };
    let c = match c {
        Checked::Valid(c) => format!("{:?}", c.0),
        Checked::Invalid => "an invalid component type".to_string(),
    };
    format!("{t} of {c}")
}

/// The triangles of a primitive of mode `mode` over `indices` (section
/// 3.7.2.1 of glTF 2.0: strips alternate their orientation, fans turn
/// around the first vertex).
fn triangle_corners(mode: Mode, indices: &[u32]) -> Vec<[u32; 3]> {
    match mode {
        Mode::Triangles => indices
            .chunks_exact(3)
            .map(|t| [t[0], t[1], t[2]])
            .collect(),
        Mode::TriangleStrip => indices
            .windows(3)
            .enumerate()
            .map(|(i, w)| {
                if i % 2 == 0 {
                    [w[0], w[1], w[2]]
                } else {
                    [w[1], w[0], w[2]]
                }
            })
            .collect(),
        Mode::TriangleFan => match indices.split_first() {
            Some((&first, rest)) => rest.windows(2).map(|w| [w[0], w[1], first]).collect(),
            None => Vec::new(),
        },
        _ => Vec::new(),
    }
}

/// The local matrix of `node` in `f64`: its `matrix`, or `T * R * S` of
/// its translation, rotation (a quaternion `x, y, z, w`, normalized) and
/// scale (section 3.5.3 of glTF 2.0).
fn local_matrix(node: &gltf::json::Node) -> Matrix {
    if let Some(m) = node.matrix {
        let mut out = [[0.0; 4]; 4];
        for (col, out) in out.iter_mut().enumerate() {
            for (row, v) in out.iter_mut().enumerate() {
                *v = f64::from(m[4 * col + row]);
            }
        }
        return out;
    }
    let [tx, ty, tz] = node.translation.unwrap_or([0.0; 3]).map(f64::from);
    let [x, y, z, w] = node
        .rotation
        .map_or([0.0, 0.0, 0.0, 1.0], |q| q.0)
        .map(f64::from);
    let [sx, sy, sz] = node.scale.unwrap_or([1.0; 3]).map(f64::from);
    // The rotation matrix of the quaternion, by columns, with `2 / |q|^2`
    // in place of 2: the rotation of `q / |q|`. glTF asks for unit
    // quaternions, but exporters write `f32` ones a few ulps off, and
    // some far off ([0, 0, 1, 1] for a quarter turn); the plain formula
    // would scale and shear the mesh by `|q|^2`. A zero quaternion, which
    // names no rotation, is none.
    let n2 = x * x + y * y + z * z + w * w;
    let k = if n2 > 0.0 && n2.is_finite() {
        2.0 / n2
    } else {
        0.0
    };
    let r = [
        [
            1.0 - k * (y * y + z * z),
            k * (x * y + z * w),
            k * (x * z - y * w),
        ],
        [
            k * (x * y - z * w),
            1.0 - k * (x * x + z * z),
            k * (y * z + x * w),
        ],
        [
            k * (x * z + y * w),
            k * (y * z - x * w),
            1.0 - k * (x * x + y * y),
        ],
    ];
    let s = [sx, sy, sz];
    let mut out = IDENTITY;
    for col in 0..3 {
        for row in 0..3 {
            out[col][row] = r[col][row] * s[col];
        }
    }
    out[3] = [tx, ty, tz, 1.0];
    out
}

/// `a * b` (column-major).
fn compose(a: &Matrix, b: &Matrix) -> Matrix {
    if *a == IDENTITY {
        return *b;
    }
    if *b == IDENTITY {
        return *a;
    }
    let mut m = [[0.0; 4]; 4];
    for (col, out) in m.iter_mut().enumerate() {
        for (row, v) in out.iter_mut().enumerate() {
            *v = a[0][row] * b[col][0]
                + a[1][row] * b[col][1]
                + a[2][row] * b[col][2]
                + a[3][row] * b[col][3];
        }
    }
    m
}

/// The affine map of `m` applied to `p`.
fn apply(m: &Matrix, p: &Point3) -> Point3 {
    let row = |r: usize| m[0][r] * p[0] + m[1][r] * p[1] + m[2][r] * p[2] + m[3][r];
    [row(0), row(1), row(2)]
}

/// The determinant of the linear part of `m`.
fn determinant(m: &Matrix) -> f64 {
    m[0][0] * (m[1][1] * m[2][2] - m[2][1] * m[1][2])
        - m[1][0] * (m[0][1] * m[2][2] - m[2][1] * m[0][2])
        + m[2][0] * (m[0][1] * m[1][2] - m[1][1] * m[0][2])
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh_to_glb;
    use proptest::prelude::*;
    use serde_json::json;
    use test_support::measure::polygon_mesh_volume;
    use test_support::shapes::{box_triangles, icosphere};

    /// A binary glTF file of `doc` and the binary chunk `bin` (padded).
    fn glb(doc: &serde_json::Value, bin: &[u8]) -> Vec<u8> {
        let mut text = doc.to_string().into_bytes();
        while !text.len().is_multiple_of(4) {
            text.push(b' ');
        }
        let mut bin = bin.to_vec();
        while !bin.len().is_multiple_of(4) {
            bin.push(0);
        }
        let total = 12 + 8 + text.len() + if bin.is_empty() { 0 } else { 8 + bin.len() };
        let mut out = Vec::new();
        out.extend_from_slice(b"glTF");
        out.extend_from_slice(&2u32.to_le_bytes());
        out.extend_from_slice(&(total as u32).to_le_bytes());
        out.extend_from_slice(&(text.len() as u32).to_le_bytes());
        out.extend_from_slice(b"JSON");
        out.extend_from_slice(&text);
        if !bin.is_empty() {
            out.extend_from_slice(&(bin.len() as u32).to_le_bytes());
            out.extend_from_slice(b"BIN\0");
            out.extend_from_slice(&bin);
        }
        out
    }

    /// The unit cube's 8 corners as `f32` bytes and its 12 outward
    /// triangles as `u16` indices, and the byte length of the positions.
    fn cube_bin() -> (Vec<u8>, usize) {
        let cube = box_triangles([0.0; 3], [1.0; 3]);
        let mut bin = Vec::new();
        for p in &cube.vertices {
            for &x in p {
                bin.extend_from_slice(&(x as f32).to_le_bytes());
            }
        }
        let positions = bin.len();
        for t in &cube.triangles {
            for &i in t {
                bin.extend_from_slice(&(i as u16).to_le_bytes());
            }
        }
        (bin, positions)
    }

    /// The JSON document of one cube mesh over [`cube_bin`] (`bin_len`
    /// bytes, positions first) whose index accessor holds `indices`
    /// indices, without scenes or nodes.
    fn cube_json(bin_len: usize, positions: usize, indices: usize) -> serde_json::Value {
        json!({
            "asset": {"version": "2.0"},
            "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
            "buffers": [{"byteLength": bin_len}],
            "bufferViews": [
                {"buffer": 0, "byteOffset": 0, "byteLength": positions},
                {"buffer": 0, "byteOffset": positions, "byteLength": bin_len - positions}
            ],
            "accessors": [
                {"bufferView": 0, "componentType": 5126, "count": 8, "type": "VEC3",
                 "min": [0.0, 0.0, 0.0], "max": [1.0, 1.0, 1.0]},
                {"bufferView": 1, "componentType": 5123, "count": indices, "type": "SCALAR"}
            ]
        })
    }

    /// A file of one cube mesh placed by `nodes` (with `scenes`).
    fn cube_doc(nodes: serde_json::Value, scenes: serde_json::Value) -> Vec<u8> {
        let (bin, positions) = cube_bin();
        let mut doc = cube_json(bin.len(), positions, 36);
        doc["scenes"] = scenes;
        doc["nodes"] = nodes;
        glb(&doc, &bin)
    }

    fn volume(m: &TriangleMesh) -> f64 {
        polygon_mesh_volume(&m.to_polygon_mesh())
    }

    fn message(r: Result<TriangleMesh, UmbraError>) -> String {
        match r {
            Ok(m) => panic!("read {} triangles", m.triangles.len()),
            Err(e) => e.to_string(),
        }
    }

    #[test]
    fn the_writers_files_read_back_to_the_same_triangles() {
        // `f32` coordinates (the format's) read back bit for bit; the
        // writer's vertices are welded already, so the reader's first-seen
        // order is a renumbering that the triangle positions pin down.
        for mesh in [
            box_triangles([-1.5, 0.25, 2.0], [3.0, 4.5, 8.0]),
            icosphere([0.0; 3], 1.0, 2),
        ] {
            let mesh = TriangleMesh::new(
                mesh.vertices
                    .iter()
                    .map(|p| p.map(|x| f64::from(x as f32)))
                    .collect(),
                mesh.triangles,
            );
            let bytes = mesh_to_glb(&mesh.to_polygon_mesh()).unwrap();
            let back = parse_glb(&bytes, "m.glb").unwrap();
            let corners = |m: &TriangleMesh| -> Vec<[[u64; 3]; 3]> {
                m.triangles
                    .iter()
                    .map(|t| t.map(|i| m.vertices[i as usize].map(f64::to_bits)))
                    .collect()
            };
            assert_eq!(corners(&back), corners(&mesh));
            assert_eq!(back.vertices.len(), mesh.vertices.len());
            read_gltf_bytes(&bytes, "m.glb", None, MeshReadOptions::default(), true).unwrap();
        }
    }

    #[test]
    fn nodes_place_mesh_instances_through_their_transforms() {
        // The cube at the origin, translated by (5, 0, 0) in a child of a
        // node scaled by 2, and mirrored in x by a matrix.
        let bytes = cube_doc(
            json!([
                {"mesh": 0},
                {"scale": [2.0, 2.0, 2.0], "children": [2]},
                {"mesh": 0, "translation": [5.0, 0.0, 0.0]},
                {"mesh": 0, "matrix": [-1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0,
                                        0.0, 0.0, 1.0, 0.0, -3.0, 0.0, 0.0, 1.0]}
            ]),
            json!([{"nodes": [0, 1, 3]}]),
        );
        let mesh = parse_glb(&bytes, "cubes.glb").unwrap();
        assert_eq!(mesh.triangles.len(), 36);
        assert_eq!(mesh.vertices.len(), 24);
        // 1 + 8 + 1: the mirrored instance was turned around, so every
        // shell faces out.
        assert_eq!(volume(&mesh), 10.0);
        let xs: Vec<f64> = mesh.vertices.iter().map(|p| p[0]).collect();
        let (lo, hi) = xs
            .iter()
            .fold((f64::MAX, f64::MIN), |(a, b), &x| (a.min(x), b.max(x)));
        assert_eq!((lo, hi), (-4.0, 12.0));
        read_gltf_bytes(&bytes, "cubes.glb", None, MeshReadOptions::default(), true).unwrap();
    }

    #[test]
    fn rotations_are_normalized_quaternions_applied_after_scaling() {
        // The cube scaled by 3 in x, then turned a quarter about z (x -> y)
        // by the unit quaternion and by [0, 0, 1, 1], the same turn at
        // twice its length; [0, 0, 0, 0] names no rotation. All keep the
        // cube's volume (the plain formula would give 3 * 9 and 3 for the
        // last two).
        let h = f64::from(std::f32::consts::FRAC_1_SQRT_2);
        let cases = [
            ([0.0, 0.0, h, h], [-1.0, 0.0, 0.0], [0.0, 3.0, 1.0]),
            ([0.0, 0.0, 1.0, 1.0], [-1.0, 0.0, 0.0], [0.0, 3.0, 1.0]),
            ([0.0, 0.0, 0.0, 0.0], [0.0, 0.0, 0.0], [3.0, 1.0, 1.0]),
        ];
        for (q, want_lo, want_hi) in cases {
            let bytes = cube_doc(
                json!([{"mesh": 0, "rotation": q, "scale": [3.0, 1.0, 1.0]}]),
                json!([{"nodes": [0]}]),
            );
            let mesh = parse_glb(&bytes, "turned.glb").unwrap();
            let lo = mesh.vertices.iter().fold([f64::MAX; 3], |a, p| {
                [a[0].min(p[0]), a[1].min(p[1]), a[2].min(p[2])]
            });
            let hi = mesh.vertices.iter().fold([f64::MIN; 3], |a, p| {
                [a[0].max(p[0]), a[1].max(p[1]), a[2].max(p[2])]
            });
            let near =
                |a: [f64; 3], b: [f64; 3]| a.iter().zip(b).all(|(x, y)| (x - y).abs() < 1e-6);
            assert!(
                near(lo, want_lo) && near(hi, want_hi),
                "{q:?}: {lo:?} {hi:?}"
            );
            assert!((volume(&mesh) - 3.0).abs() < 1e-6, "{q:?}");
        }
    }

    #[test]
    fn without_scenes_the_root_nodes_are_placed_and_without_nodes_every_mesh() {
        let bytes = cube_doc(
            json!([{"children": [1]}, {"mesh": 0, "translation": [0.0, 0.0, 7.0]}]),
            json!([]),
        );
        let mesh = parse_glb(&bytes, "roots.glb").unwrap();
        assert_eq!(mesh.triangles.len(), 12);
        assert!(mesh.vertices.iter().all(|p| p[2] >= 7.0));
        let bytes = cube_doc(json!([]), json!([]));
        assert_eq!(parse_glb(&bytes, "meshes.glb").unwrap().triangles.len(), 12);
    }

    #[test]
    fn strips_and_fans_follow_the_specification() {
        // Six positions on a square's corners and centre, no index buffer.
        let idx = [0u32, 1, 2, 3];
        let strip = triangle_corners(Mode::TriangleStrip, &idx);
        assert_eq!(strip, vec![[0, 1, 2], [2, 1, 3]]);
        let fan = triangle_corners(Mode::TriangleFan, &idx);
        assert_eq!(fan, vec![[1, 2, 0], [2, 3, 0]]);
        assert!(triangle_corners(Mode::Lines, &idx).is_empty());
        assert!(triangle_corners(Mode::TriangleFan, &[]).is_empty());
        assert_eq!(
            triangle_corners(Mode::Triangles, &[0, 1, 2, 3]),
            vec![[0, 1, 2]]
        );
    }

    #[test]
    fn a_document_without_triangles_is_the_empty_mesh() {
        let doc = json!({"asset": {"version": "2.0"}, "scenes": [{"nodes": []}]});
        let mesh = parse_glb(&glb(&doc, &[]), "empty.glb").unwrap();
        assert!(mesh.triangles.is_empty());
        assert!(matches!(
            parse_glb(b" \n", "blank.glb"),
            Err(UmbraError::Empty { .. })
        ));
    }

    #[test]
    fn bad_files_are_named_errors() {
        let good = cube_doc(json!([{"mesh": 0}]), json!([{"nodes": [0]}]));
        // Every truncation is an error, never a panic.
        for cut in 0..good.len() {
            assert!(parse_glb(&good[..cut], "cut.glb").is_err(), "cut at {cut}");
        }
        let mut version = good.clone();
        version[4] = 1;
        assert!(message(parse_glb(&version, "v.glb")).contains("version 1"));
        let mut short = good.clone();
        short[8..12].copy_from_slice(&3u32.to_le_bytes());
        assert!(message(parse_glb(&short, "s.glb")).contains("length of 3"));

        let (bin, positions) = cube_bin();
        let with = |edit: &dyn Fn(&mut serde_json::Value)| {
            let mut doc = cube_json(bin.len(), positions, 36);
            doc["scenes"] = json!([{"nodes": [0]}]);
            doc["nodes"] = json!([{"mesh": 0}]);
            edit(&mut doc);
            message(parse_glb(&glb(&doc, &bin), "bad.glb"))
        };
        type Edit<'e> = &'e dyn Fn(&mut serde_json::Value);
        let cases: Vec<(Edit<'_>, &str)> = vec![
            (
                &|d| d["accessors"][0]["count"] = json!(9),
                "runs past its buffer view",
            ),
            (
                &|d| d["accessors"][0]["count"] = json!(usize::MAX / 2),
                "runs past",
            ),
            (
                &|d| d["accessors"][1]["byteOffset"] = json!(4000),
                "runs past",
            ),
            (
                &|d| d["bufferViews"][1]["byteLength"] = json!(1u64 << 40),
                "beyond its buffer 0 of",
            ),
            (
                &|d| d["accessors"][0]["componentType"] = json!(5123),
                "not VEC3 of FLOAT",
            ),
            (&|d| d["accessors"][1]["type"] = json!("VEC2"), "not SCALAR"),
            (
                &|d| {
                    d["accessors"][0]["sparse"] = json!({"count": 1,
                "indices": {"bufferView": 1, "componentType": 5123},
                "values": {"bufferView": 0}})
                },
                "sparse",
            ),
            (
                &|d| {
                    d["accessors"][0]
                        .as_object_mut()
                        .unwrap()
                        .remove("bufferView");
                },
                "no buffer view",
            ),
            (
                &|d| d["buffers"][0]["uri"] = json!("cube.bin"),
                "bytes alone have no directory",
            ),
            (
                &|d| d["meshes"][0]["primitives"][0]["attributes"] = json!({"NORMAL": 0}),
                "no POSITION",
            ),
            (
                &|d| d["nodes"] = json!([{"mesh": 0, "children": [0]}]),
                "reached twice",
            ),
            (
                &|d| d["nodes"] = json!([{"children": [1, 2]}, {"children": [2]}, {"mesh": 0}]),
                "reached twice",
            ),
            (
                &|d| d["extensionsRequired"] = json!(["KHR_draco_mesh_compression"]),
                "KHR_draco_mesh_compression",
            ),
            (
                &|d| d["nodes"][0]["mesh"] = json!(5),
                "mesh 5 does not exist",
            ),
            (&|d| d["scene"] = json!(3), "scene 3 does not exist"),
            (
                &|d| d["meshes"][0]["primitives"][0]["attributes"]["POSITION"] = json!(9),
                "accessor 9 does not exist",
            ),
            (
                &|d| d["bufferViews"][0]["buffer"] = json!(2),
                "buffer 2 does not exist",
            ),
            (
                &|d| d["meshes"][0]["primitives"][0]["mode"] = json!(9),
                "primitive 0: invalid mode",
            ),
            (&|d| d["asset"] = json!(7), "invalid glTF JSON"),
        ];
        for (edit, want) in cases {
            let got = with(edit);
            assert!(got.contains(want), "{got} (wanted {want})");
            assert!(got.contains("bad.glb"), "{got}");
        }
        // An index beyond the positions names the primitive and the index.
        let mut bad = bin.clone();
        bad[positions..positions + 2].copy_from_slice(&8u16.to_le_bytes());
        let doc = cube_json(bad.len(), positions, 36);
        let got = message(parse_glb(&glb(&doc, &bad), "idx.glb"));
        assert!(
            got.contains("mesh 0 primitive 0: index 0 is 8, but there are only 8 positions"),
            "{got}"
        );
    }

    #[test]
    fn an_open_instance_is_reported_by_triangle_and_mesh() {
        // The cube without its last triangle.
        let (bin, positions) = cube_bin();
        let doc = cube_json(bin.len(), positions, 33);
        let e = read_gltf_bytes(
            &glb(&doc, &bin),
            "open.glb",
            None,
            MeshReadOptions::default(),
            true,
        )
        .unwrap_err()
        .to_string();
        assert!(e.contains("open.glb") && e.contains("(mesh 0)"), "{e}");
    }

    /// The meshes trimesh wrote (see `test-support/data/gltf/README.md`).
    #[test]
    fn trimesh_files_read_closed_with_trimesh_volumes() {
        let read = |name: &str| {
            let path = test_support::data_path(&format!("gltf/{name}"));
            let bytes = std::fs::read(&path).unwrap();
            read_gltf_bytes(&bytes, name, None, MeshReadOptions::default(), true).unwrap()
        };
        let nut = read("nut_unmerged.glb");
        assert_eq!(nut.facets.len(), 1046);
        // Welded from 3138 positions to the nut's 523 vertices.
        assert_eq!(nut.vertices.len(), 523);
        let v = polygon_mesh_volume(&nut);
        assert!((v - 32171.322236985983).abs() < 1e-9 * v, "{v}");
        let scene = read("scene_instances.glb");
        assert_eq!(scene.facets.len(), 2726);
        let v = polygon_mesh_volume(&scene);
        // The mirrored nut's `f32` rotation moves its volume by ~1e-7.
        assert!((v - 16882519.322236985).abs() < 1e-6 * v, "{v}");
        let lo = scene.vertices.iter().fold([f64::MAX; 3], |a, p| {
            [a[0].min(p[0]), a[1].min(p[1]), a[2].min(p[2])]
        });
        let hi = scene.vertices.iter().fold([f64::MIN; 3], |a, p| {
            [a[0].max(p[0]), a[1].max(p[1]), a[2].max(p[2])]
        });
        for (got, want) in lo.iter().zip([-426.0, -139.97146456596238, -127.0]) {
            assert!((got - want).abs() < 1e-4, "{lo:?}");
        }
        for (got, want) in hi.iter().zip([425.0, 126.0, 127.0]) {
            assert!((got - want).abs() < 1e-4, "{hi:?}");
        }
    }

    /// The `.gltf` files trimesh wrote: the nut with its two buffers in
    /// files beside the document, and a scene (a sphere and a mirrored nut)
    /// with its buffers in base64 data URIs.
    #[test]
    fn trimesh_gltf_documents_read_with_their_buffers() {
        let nut = crate::read_mesh(
            &test_support::data_path("gltf/nut_external/nut.gltf"),
            MeshReadOptions::default(),
            true,
        )
        .unwrap();
        assert_eq!((nut.facets.len(), nut.vertices.len()), (1046, 523));
        let v = polygon_mesh_volume(&nut);
        assert!((v - 32171.322236985983).abs() < 1e-9 * v, "{v}");
        // The same triangles as the `.glb` trimesh wrote of the nut.
        let glb = crate::read_mesh(
            &test_support::data_path("gltf/nut_unmerged.glb"),
            MeshReadOptions::default(),
            true,
        )
        .unwrap();
        assert_eq!(nut, glb);
        let path = test_support::data_path("gltf/scene_embedded.gltf");
        let scene = crate::read_mesh(&path, MeshReadOptions::default(), true).unwrap();
        assert_eq!(scene.facets.len(), 1886);
        let v = polygon_mesh_volume(&scene);
        assert!((v - 8457345.322236987).abs() < 1e-6 * v, "{v}");
        // Data URIs need no directory: the bytes alone read the same.
        let bytes = std::fs::read(&path).unwrap();
        let alone = parse_glb(&bytes, "scene.gltf").unwrap();
        assert_eq!(alone.to_polygon_mesh(), scene);
        // The nut's document without its directory names the file it needs.
        let bytes = std::fs::read(test_support::data_path("gltf/nut_external/nut.gltf")).unwrap();
        let e = message(parse_glb(&bytes, "nut.gltf"));
        assert!(
            e.contains("gltf_buffer_") && e.contains("read the document from its file"),
            "{e}"
        );
    }

    /// The writer's `.gltf` reads back to the `.glb`'s triangles, and its
    /// buffer is the `.glb`'s binary chunk.
    #[test]
    fn the_json_writer_embeds_the_binary_chunk() {
        let m = crate::uv_sphere(1.5, 12, 7).unwrap();
        let glb = crate::mesh_to_glb(&m).unwrap();
        let text = crate::mesh_to_gltf(&m).unwrap();
        let a = parse_glb(&glb, "m.glb").unwrap();
        let b = parse_glb(&text, "m.gltf").unwrap();
        assert_eq!(a, b);
        assert!(!a.triangles.is_empty());
        let doc: serde_json::Value = serde_json::from_slice(&text).unwrap();
        let uri = doc["buffers"][0]["uri"].as_str().unwrap();
        let data = uri
            .strip_prefix("data:application/octet-stream;base64,")
            .unwrap();
        let decoded = base64::engine::general_purpose::STANDARD
            .decode(data)
            .unwrap();
        let (_, blob) = split_container(&glb, "m.glb").unwrap();
        let blob = blob.unwrap();
        // The chunk is padded to four bytes; the buffer is not.
        assert_eq!(decoded.as_slice(), &blob[..decoded.len()]);
        assert_eq!(doc["buffers"][0]["byteLength"], json!(decoded.len()));
        // The empty mesh: a document with no buffer.
        let empty = crate::mesh_to_gltf(&PolygonMesh::default()).unwrap();
        assert_eq!(
            parse_glb(&empty, "e.gltf").unwrap(),
            TriangleMesh::default()
        );
    }

    /// A fresh directory under the system's temporary one.
    fn temp_dir(name: &str) -> std::path::PathBuf {
        let dir = std::env::temp_dir().join(format!("umbra-gltf-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        dir
    }

    /// Buffers in files: `%`-escaped names and subdirectories are found;
    /// URIs leaving the directory, schemes, absolute paths, missing files,
    /// directories and short files are named errors; data URIs decode with
    /// or without padding and refuse anything but base64.
    #[test]
    fn buffer_uris_are_resolved_inside_the_documents_directory_only() {
        let (bin, positions) = cube_bin();
        let dir = temp_dir("uris");
        std::fs::create_dir_all(dir.join("sub dir")).unwrap();
        std::fs::write(dir.join("sub dir").join("cube 1.bin"), &bin).unwrap();
        std::fs::write(dir.join("short.bin"), &bin[..positions]).unwrap();
        let read = |uri: &str| {
            let mut doc = cube_json(bin.len(), positions, 36);
            doc["buffers"][0]["uri"] = json!(uri);
            let path = dir.join("m.gltf");
            std::fs::write(&path, serde_json::to_vec(&doc).unwrap()).unwrap();
            crate::read_mesh(&path, MeshReadOptions::default(), true)
        };
        let cube = read("sub%20dir/cube%201.bin").unwrap();
        assert_eq!(cube.facets.len(), 12);
        assert_eq!(read("./sub%20dir//cube%201.bin").unwrap(), cube);
        let refused = [
            ("../sub%20dir/cube%201.bin", "'..'"),
            ("sub%20dir/%2E%2E/%2E%2E/x.bin", "'..'"),
            ("/etc/passwd", "absolute path"),
            ("http://example.com/cube.bin", "scheme"),
            ("file:///tmp/cube.bin", "scheme"),
            ("C:/cube.bin", "scheme or a drive"),
            ("sub%20dir%5Ccube%201.bin", "backslash"),
            ("cube.bin?x=1", "query"),
            ("%FF.bin", "UTF-8"),
            ("", "empty"),
            ("missing.bin", "missing.bin"),
            ("sub%20dir", "not a regular file"),
            ("short.bin", "beyond its buffer 0"),
            ("data:application/octet-stream,abc", "not base64"),
            (
                "data:application/octet-stream;base64,@@@@",
                "invalid base64",
            ),
            ("data:base64", "without a comma"),
        ];
        for (uri, want) in refused {
            let e = read(uri).unwrap_err().to_string();
            assert!(e.contains(want) && e.contains("m.gltf"), "{uri}: {e}");
        }
        // Base64 with and without its padding, any case of the scheme.
        let engine = base64::engine::general_purpose::STANDARD;
        let padded = engine.encode(&bin);
        let bare = padded.trim_end_matches('=').to_string();
        assert_eq!(
            read(&format!("data:application/gltf-buffer;base64,{padded}")).unwrap(),
            cube
        );
        assert_eq!(read(&format!("DATA:;base64,{bare}")).unwrap(), cube);
        let _ = std::fs::remove_dir_all(&dir);
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(test_support::cases(64)))]

        /// Random bytes and random edits of a valid file never panic.
        #[test]
        fn garbage_never_panics(
            bytes in proptest::collection::vec(any::<u8>(), 0..300),
            edits in proptest::collection::vec((any::<usize>(), any::<u8>()), 1..8),
        ) {
            let _ = parse_glb(&bytes, "g.glb");
            let mut prefixed = b"glTF\x02\0\0\0".to_vec();
            prefixed.extend_from_slice(&bytes);
            let _ = parse_glb(&prefixed, "g.glb");
            let mut good = cube_doc(
                json!([{"mesh": 0, "children": [1]}, {"mesh": 0, "scale": [1.0, -1.0, 1.0]}]),
                json!([{"nodes": [0]}]),
            );
            let n = good.len();
            for (at, byte) in edits {
                good[at % n] = byte;
            }
            if let Ok(m) = parse_glb(&good, "e.glb") {
                prop_assert!(m.triangles.len() <= 24);
            }
        }
    }
}
