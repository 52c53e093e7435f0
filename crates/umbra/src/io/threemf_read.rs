//! 3MF reading (3D Manufacturing Format, core specification 1.4, and the
//! production extension's paths to other model parts).
//!
//! A 3MF file is a zip package (Open Packaging Conventions). The package
//! relationship part `_rels/.rels` names the root model part by a
//! relationship whose type ends in `/3dmodel` (its target may start with a
//! `/`; zip entry names are case-sensitive); without such a relationship
//! the reader takes `3D/3dmodel.model`, where every known producer puts it.
//! The model part is an XML document: `<model>` in the core namespace holds
//! `<resources>`, whose `<object id type>` elements each hold either a
//! `<mesh>` (`<vertices>` of `<vertex x y z>`, `<triangles>` of
//! `<triangle v1 v2 v3>`, 0-based indices into the object's own vertices)
//! or `<components>` (`<component objectid transform>`), and `<build>`,
//! whose `<item objectid transform>` elements are what is manufactured.
//! Elements are matched by namespace and local name; elements and
//! attributes of other namespaces (extensions), metadata, materials and
//! colours are ignored. A `requiredextensions` naming an extension other
//! than materials, production and triangle sets is refused, as the
//! specification requires (section 3.4).
//!
//! The mesh read is every build item expanded through its components,
//! transforms composed, concatenated into one triangle mesh (items and
//! instances are disjoint shells; nothing is welded, so a vertex used by
//! two instances is two vertices). A transform is the attribute's 12
//! numbers `m00 m01 m02 m10 m11 m12 m20 m21 m22 m30 m31 m32` in the row
//! vector convention of section 3.3 (`x' = m00 x + m10 y + m20 z + m30`).
//! The identity is never applied (so a coordinate comes back bit for bit,
//! `-0.0` and non-finite values included); any other transform is
//! evaluated in `f64` in the order of that formula. Section 3.3: "When
//! applying a transformation with a negative determinant, the resultant
//! shape MUST NOT change the sign of its volume", so the triangles of an
//! instance whose composed transform has a negative determinant are
//! reversed (`v1 v3 v2`). Coordinates are not rescaled: the model's `unit`
//! (millimetres by default) is kept as it is, as every other reader of
//! this crate keeps the file's numbers.
//!
//! Object types (section 4.1): meshes of type `model` (the default) and
//! `solidsupport` are solids the printer fills, and are read. Meshes of
//! type `support` (never filled, typically open), `surface` and `other`
//! (which a build item must not reference) are not solids: they are left
//! out, as the specification allows for supports ("MAY be ignored").
//! The type of an object with components is ignored, as the specification
//! says (its components' types decide). Forward references (an object
//! used before its definition, which producers must not write) are
//! accepted.
//!
//! Production extension paths (1.2, section 3): a `<component>` or
//! `<item>` of the root model part with a `p:path` names its object in
//! another model part of the package, as Bambu Studio, Orca Slicer and
//! lib3mf write them (`3D/3dmodel.model` of components whose meshes are in
//! `3D/Objects/object_1.model`). The path is the part's absolute name in
//! the package (its one leading `/` dropped, compared with the zip entry
//! names case-sensitively; a path equal to the root part's name refers to
//! the root part). It must end in `.model` (ASCII case aside), so a path
//! never makes the reader open a thumbnail, a relationship or a settings
//! entry; a part the package lacks is an error naming it. The relationship
//! part `3D/_rels/3dmodel.model.rels`, which should list the referenced
//! parts, is not read: the path alone decides (leniently, for producers
//! that forget it). Each part is read and parsed once, however many
//! references name it, with the same reader as the root part: its objects
//! have their own ids, its components without a path refer to its own
//! objects, and its `<build>` (empty, and optional here) is ignored, as the
//! build is the root part's alone. A `p:path` in a part other than the
//! root is refused, as section 3.2 requires ("Any consumer of a 3MF
//! package that contains path attributes in components in a non-root model
//! file MUST generate an error"), so references cross parts at most once,
//! from the root down; cycles and depth are checked over objects of all
//! parts alike (a root-part path naming the root part itself can close a
//! cycle, and is refused as any cycle is).
//!
//! Vertex and triangle places are the lines of their XML elements in the
//! model part that holds them (the part is not named in a closure
//! violation; errors of reading name it), so a closure violation names the
//! triangle and its line.
//! A triangle with a repeated index (forbidden by the specification) is
//! kept as read, for the closure check to judge, as the other readers do.
//! A well-formed model without triangles is the empty mesh.
//!
//! Hostile input: every model part is decompressed through `Read::take` to
//! at most [`part_cap`] bytes (a fixed floor, 64 times the package's size,
//! and an absolute ceiling: see there), and all the model parts read
//! together to at most the same number; component nesting is limited to
//! [`MAX_DEPTH`] levels and cycles are refused; the vertices and triangles
//! that instancing expands to are counted before any is produced and
//! refused past [`INSTANCE_BUDGET`] (unless the file spells that many out
//! itself). The XML parser (`roxmltree`) refuses DTDs, so no entity can
//! expand.

use super::mesh_text::MeshReadOptions;
use super::origin::{finish, refuse_vertices_alone, Origins};
use super::text::{decode, parse_number, shorten};
use crate::UmbraError;
use robust_arith::Point3;
use roxmltree::{Document, Node, ParsingOptions};
use std::collections::HashMap;
use std::io::{Cursor, Read};
use topology::{PolygonMesh, TriangleMesh};
use zip::result::ZipError;
use zip::ZipArchive;

const FORMAT: &str = "3MF";
/// The namespace of the core specification's model.
const CORE: &str = "http://schemas.microsoft.com/3dmanufacturing/core/2015/02";
/// The namespace of Open Packaging Conventions relationships.
const RELATIONSHIPS: &str = "http://schemas.openxmlformats.org/package/2006/relationships";
/// The production extension (its `path` attribute names another model
/// part).
const PRODUCTION: &str = "http://schemas.microsoft.com/3dmanufacturing/production/2015/06";
/// Extensions whose content this reader may ignore safely when a file
/// requires them: materials and colours, production (UUIDs are ignored;
/// a `path` is followed) and triangle sets.
const IGNORABLE_EXTENSIONS: [&str; 3] = [
    "http://schemas.microsoft.com/3dmanufacturing/material/2015/02",
    PRODUCTION,
    "http://schemas.microsoft.com/3dmanufacturing/trianglesets/2021/07",
];
/// The package relationship part.
const RELS_PART: &str = "_rels/.rels";
/// Where the model is when no relationship names it.
const DEFAULT_MODEL: &str = "3D/3dmodel.model";
/// How the name of a model part ends (ASCII case aside), the only parts a
/// production path may name.
const MODEL_SUFFIX: &str = ".model";

/// The smallest decompressed size allowed for any package: 16 MiB, so a
/// small package of very regular XML (which deflate compresses 100-fold
/// and more) always reads.
const PART_FLOOR: u64 = 16 << 20;
/// Decompressed bytes allowed per byte of package beyond the floor. The
/// XML of a mesh (decimal coordinates and indices) deflates 3 to 10
/// times; 64 leaves a wide margin for regular meshes while a deflate bomb
/// (about 1000 times) is caught early.
const PART_RATIO: u64 = 64;
/// The largest decompressed model part read at all: 1 GiB of XML is about
/// 15 million triangles, and its parsed document takes several times that
/// in memory.
const PART_CEILING: u64 = 1 << 30;
/// The largest relationship part: it holds a handful of short elements.
const RELS_CAP: u64 = 1 << 20;
/// The deepest component nesting read. Real files nest two or three
/// levels; the limit keeps the recursion's stack small.
pub(crate) const MAX_DEPTH: usize = 32;
/// The most vertices, and the most triangles, that build items and
/// components may expand to when the file itself spells out fewer: 2^24
/// (16.7 million) triangles make a mesh of a few GB in memory, beyond what
/// a Boolean handles usefully; a small file referencing an object many
/// times at many levels would otherwise expand to billions.
pub(crate) const INSTANCE_BUDGET: u64 = 1 << 24;

fn malformed(file: &str, message: impl Into<String>) -> UmbraError {
    UmbraError::Malformed {
        file: file.to_string(),
        format: FORMAT,
        message: message.into(),
    }
}

/// The decompressed size allowed for a model part of a package of
/// `package_len` bytes: [`PART_RATIO`] times its size, at least
/// [`PART_FLOOR`] and at most [`PART_CEILING`]. The package's own size
/// bounds the ratio (the sizes the zip directory declares could lie).
/// The same number bounds all the model parts of the package together
/// (the root and every part its production paths name): the ratio is one
/// of the package's bytes however they are split into parts, so a package
/// of thousands of small parts holds no more in memory than one of a
/// single part.
fn part_cap(package_len: usize) -> u64 {
    (package_len as u64)
        .saturating_mul(PART_RATIO)
        .clamp(PART_FLOOR, PART_CEILING)
}

/// Parses 3MF bytes into one triangle mesh of every build item (see the
/// module docs), unchecked; `file` names the source in errors.
///
/// ```
/// use umbra::{mesh_to_3mf, parse_3mf, TriangleMesh};
/// let tet = TriangleMesh::new(
///     vec![[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.1, 0.2, 1e-300]],
///     vec![[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2]],
/// );
/// let bytes = mesh_to_3mf(&tet.to_polygon_mesh()).unwrap();
/// let back = parse_3mf(&bytes, "tet.3mf").unwrap();
/// // The same vertices, bit for bit, and the same triangles.
/// assert_eq!(back, tet);
/// let e = parse_3mf(b"solid x", "x.3mf").unwrap_err().to_string();
/// assert!(e.starts_with("x.3mf: malformed 3MF: not a 3MF package"), "{e}");
/// ```
pub fn parse_3mf(bytes: &[u8], file: &str) -> Result<TriangleMesh, UmbraError> {
    let (mesh, _) = parse_3mf_with_origins(bytes, file)?;
    Ok(mesh)
}

/// Reads 3MF bytes into a polygon mesh of triangles: coordinates validated
/// if asked, closure checked if `check` (see [`crate::read_mesh`]).
pub(crate) fn read_3mf_bytes(
    bytes: &[u8],
    file: &str,
    options: MeshReadOptions,
    check: bool,
) -> Result<PolygonMesh, UmbraError> {
    let (mesh, origins) = parse_3mf_with_origins(bytes, file)?;
    finish(mesh.to_polygon_mesh(), &origins, file, options, check)
}

/// [`parse_3mf`] with the line of every vertex and triangle (in the model
/// part that holds it). A file of nothing but white space is
/// [`UmbraError::Empty`].
pub(crate) fn parse_3mf_with_origins(
    bytes: &[u8],
    file: &str,
) -> Result<(TriangleMesh, Origins), UmbraError> {
    if bytes.iter().all(u8::is_ascii_whitespace) {
        return Err(UmbraError::Empty {
            file: file.to_string(),
        });
    }
    let mut archive = ZipArchive::new(Cursor::new(bytes)).map_err(|e| {
        malformed(
            file,
            format!("not a 3MF package (a 3MF file is a zip archive): {e}"),
        )
    })?;
    let (root, named_by) = model_part_name(&mut archive, file)?;
    let mut budget = Budget::new(part_cap(bytes.len()));
    let Some(xml) = read_part(&mut archive, &root, &mut budget, file)? else {
        let by = match named_by {
            Some(line) => format!("named as the model by {RELS_PART} line {line}"),
            None => format!("the default, as {RELS_PART} names no model"),
        };
        return Err(malformed(
            file,
            format!(
                "the package has no model part '{}' ({by}); it holds {}",
                part_name(&root),
                entry_list(&archive)
            ),
        ));
    };
    let mut parts = Parts {
        names: vec![root.clone()],
        lines: vec![0],
        index: HashMap::from([(root, 0)]),
    };
    let mut models = vec![read_model_part(&xml, file, 0, &mut parts)?];
    drop(xml);
    // The parts the root model's paths name, each read once, in the order
    // first named (a non-root part names no further part).
    while let (Some(name), Some(&line)) = (
        parts.names.get(models.len()).cloned(),
        parts.lines.get(models.len()),
    ) {
        let Some(xml) = read_part(&mut archive, &name, &mut budget, file)? else {
            return Err(malformed(
                file,
                format!(
                    "{} line {line}: a production path names the part '/{}', which the package does not have; it holds {}",
                    part_name(parts.names.first().map_or("", String::as_str)),
                    part_name(&name),
                    entry_list(&archive)
                ),
            ));
        };
        let model = read_model_part(&xml, file, models.len(), &mut parts)?;
        models.push(model);
    }
    expand(&models, file)
}

/// Reads the model part `parts.names[index]` from its bytes `xml`.
fn read_model_part(
    xml: &[u8],
    file: &str,
    index: usize,
    parts: &mut Parts,
) -> Result<Model, UmbraError> {
    let part = parts.names.get(index).cloned().unwrap_or_default();
    let text = decode(xml, file, FORMAT).map_err(|e| in_part(e, &part))?;
    let doc = parse_xml(text, file, &part)?;
    let place = Place {
        file,
        part: &part,
        index,
        doc: &doc,
        lines: Lines::new(text),
    };
    read_model(&place, parts)
}

/// The model parts named so far: the root model part (index 0) and the
/// parts its production paths name, in the order first named.
struct Parts {
    /// Entry names (without a leading `/`).
    names: Vec<String>,
    /// The line of the root model's first reference to each part (0 for
    /// the root itself).
    lines: Vec<u32>,
    /// The index of each name.
    index: HashMap<String, usize>,
}

impl Parts {
    /// The index of the part that the production path `path` names (the
    /// root model's reference on `line`): an absolute name in the package
    /// (one leading `/` is dropped; one without is taken from the package's
    /// root alike), which must end in `.model` (a model part, never a
    /// thumbnail, relationship or settings entry).
    fn named(&mut self, path: &str, line: u32) -> Result<usize, String> {
        let trimmed = path.trim();
        let name = trimmed.strip_prefix('/').unwrap_or(trimmed);
        let is_model = name
            .len()
            .checked_sub(MODEL_SUFFIX.len())
            .and_then(|at| name.as_bytes().get(at..))
            .is_some_and(|end| end.eq_ignore_ascii_case(MODEL_SUFFIX.as_bytes()));
        if !is_model || name.len() == MODEL_SUFFIX.len() {
            return Err(format!(
                "the production path '{}' does not name a model part (a part whose name ends in {MODEL_SUFFIX})",
                part_name(path)
            ));
        }
        if let Some(&k) = self.index.get(name) {
            return Ok(k);
        }
        let k = self.names.len();
        self.names.push(name.to_string());
        self.lines.push(line);
        self.index.insert(name.to_string(), k);
        Ok(k)
    }
}

/// A part name for a message: at most 120 characters, escaped.
fn part_name(name: &str) -> String {
    let mut out: String = name
        .chars()
        .take(120)
        .flat_map(char::escape_debug)
        .collect();
    if name.chars().nth(120).is_some() {
        out.push_str("...");
    }
    out
}

/// The names of the package's entries for a message (at most 8).
fn entry_list(archive: &ZipArchive<Cursor<&[u8]>>) -> String {
    let names: Vec<String> = archive
        .file_names()
        .take(8)
        .map(|n| match n {
            Ok(n) => format!("'{}'", shorten(&n)),
            Err(_) => "(an unreadable name)".to_string(),
        })
        .collect();
    match (names.is_empty(), archive.len() > names.len()) {
        (true, _) => "no entries".to_string(),
        (false, true) => format!("{}, ... ({} entries)", names.join(", "), archive.len()),
        (false, false) => names.join(", "),
    }
}

/// Prefixes a [`UmbraError::Malformed`] message with the part it is about.
fn in_part(error: UmbraError, part: &str) -> UmbraError {
    match error {
        UmbraError::Malformed {
            file,
            format,
            message,
        } => UmbraError::Malformed {
            file,
            format,
            message: format!("{}: {message}", part_name(part)),
        },
        other => other,
    }
}

/// The decompressed bytes a package may still use: at most `part` bytes
/// for any one part, at most `left` more in all.
struct Budget {
    part: u64,
    left: u64,
}

impl Budget {
    /// `cap` bytes for one part and for all together.
    fn new(cap: u64) -> Self {
        Budget {
            part: cap,
            left: cap,
        }
    }
}

/// The decompressed bytes of the entry `name`, or `None` if the package
/// has no such entry; more than the `budget` allows is an error (a zip
/// bomb), and what is read is taken from it.
fn read_part(
    archive: &mut ZipArchive<Cursor<&[u8]>>,
    name: &str,
    budget: &mut Budget,
    file: &str,
) -> Result<Option<Vec<u8>>, UmbraError> {
    let shown = part_name(name);
    let entry = match archive.by_name(name) {
        Ok(entry) => entry,
        Err(ZipError::FileNotFound) => return Ok(None),
        Err(e) => {
            return Err(malformed(
                file,
                format!("{shown}: cannot open the part: {e}"),
            ))
        }
    };
    let cap = budget.part.min(budget.left);
    let mut out = Vec::new();
    entry
        .take(cap.saturating_add(1))
        .read_to_end(&mut out)
        .map_err(|e| malformed(file, format!("{shown}: cannot decompress the part: {e}")))?;
    let len = out.len() as u64;
    if len > cap {
        let what = if cap < budget.part {
            format!(
                "the model parts read so far and this one decompress to more than {} bytes together",
                budget.part
            )
        } else {
            format!("the part decompresses to more than {cap} bytes")
        };
        return Err(malformed(
            file,
            format!("{shown}: {what}, the limit for a package of this size (a zip bomb?)"),
        ));
    }
    budget.left -= len;
    Ok(Some(out))
}

/// Parses XML text (no DTD, so no entity expansion).
fn parse_xml<'a>(text: &'a str, file: &str, part: &str) -> Result<Document<'a>, UmbraError> {
    let options = ParsingOptions {
        allow_dtd: false,
        ..ParsingOptions::default()
    };
    Document::parse_with_options(text, options).map_err(|e| {
        malformed(
            file,
            format!(
                "{} line {}: malformed XML: {e}",
                part_name(part),
                e.pos().row
            ),
        )
    })
}

/// The root model part's name (without a leading `/`) and the line of the
/// relationship naming it, if one does.
fn model_part_name(
    archive: &mut ZipArchive<Cursor<&[u8]>>,
    file: &str,
) -> Result<(String, Option<u32>), UmbraError> {
    let Some(rels) = read_part(archive, RELS_PART, &mut Budget::new(RELS_CAP), file)? else {
        return Ok((DEFAULT_MODEL.to_string(), None));
    };
    let text = decode(&rels, file, FORMAT).map_err(|e| in_part(e, RELS_PART))?;
    let doc = parse_xml(text, file, RELS_PART)?;
    let found = doc
        .root_element()
        .children()
        .filter(|n| is(n, RELATIONSHIPS, "Relationship"))
        .find(|n| n.attribute("Type").is_some_and(|t| t.ends_with("/3dmodel")));
    Ok(match found {
        Some(node) => {
            let line = Lines::new(text).of(node);
            let target = node.attribute("Target").ok_or_else(|| {
                malformed(
                    file,
                    format!("{RELS_PART} line {line}: the model relationship has no Target"),
                )
            })?;
            (
                target.trim().trim_start_matches('/').to_string(),
                Some(line),
            )
        }
        None => (DEFAULT_MODEL.to_string(), None),
    })
}

/// `true` if `node` is the element `name` of `namespace`.
fn is(node: &Node<'_, '_>, namespace: &str, name: &str) -> bool {
    node.is_element()
        && node.tag_name().name() == name
        && node.tag_name().namespace() == Some(namespace)
}

/// The core-namespace element children of `node` named `name`.
fn core_children<'a, 'i>(
    node: Node<'a, 'i>,
    name: &'static str,
) -> impl Iterator<Item = Node<'a, 'i>> {
    node.children().filter(move |n| is(n, CORE, name))
}

/// The line starts of a text, for the line of a node in logarithmic time
/// (`Document::text_pos_at` scans the text from its start, which would
/// make naming every vertex's line quadratic).
struct Lines {
    /// The byte offset of every `\n`.
    newlines: Vec<usize>,
}

impl Lines {
    fn new(text: &str) -> Self {
        Lines {
            newlines: text
                .bytes()
                .enumerate()
                .filter(|&(_, b)| b == b'\n')
                .map(|(at, _)| at)
                .collect(),
        }
    }

    /// The 1-based line of a node's start.
    fn of(&self, node: Node<'_, '_>) -> u32 {
        let before = self.newlines.partition_point(|&at| at < node.range().start);
        u32::try_from(before).map_or(u32::MAX, |n| n.saturating_add(1))
    }
}

/// A namespace URI for a message: at most 200 characters, escaped.
fn uri(text: &str) -> String {
    text.chars()
        .take(200)
        .flat_map(char::escape_debug)
        .collect()
}

/// The model part being read: names places in errors.
struct Place<'a, 'i> {
    file: &'a str,
    part: &'a str,
    /// Its index in [`Parts`] (0 for the root model part).
    index: usize,
    doc: &'a Document<'i>,
    lines: Lines,
}

impl Place<'_, '_> {
    fn line(&self, node: Node<'_, '_>) -> u32 {
        self.lines.of(node)
    }

    /// `file: malformed 3MF: 3D/3dmodel.model line 12: message`.
    fn error(&self, node: Node<'_, '_>, message: impl std::fmt::Display) -> UmbraError {
        self.error_at(self.line(node), message)
    }

    fn error_at(&self, line: u32, message: impl std::fmt::Display) -> UmbraError {
        malformed(
            self.file,
            format!("{} line {line}: {message}", part_name(self.part)),
        )
    }

    /// The attribute `name` (no namespace) of an element, required.
    fn attribute<'n>(&self, node: Node<'n, '_>, name: &str) -> Result<&'n str, UmbraError> {
        node.attribute(name).ok_or_else(|| {
            self.error(
                node,
                format!("<{}> has no attribute '{name}'", node.tag_name().name()),
            )
        })
    }

    /// A resource id (a non-negative integer) in the attribute `name`.
    fn resource_id(&self, node: Node<'_, '_>, name: &str) -> Result<u32, UmbraError> {
        let text = self.attribute(node, name)?;
        text.trim().parse().map_err(|_| {
            self.error(
                node,
                format!(
                    "{name} = '{}' is not a resource id (a non-negative integer)",
                    shorten(text)
                ),
            )
        })
    }
}

/// An affine map in the row-vector convention of section 3.3: rows 0 to 2
/// the linear part, row 3 the translation.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Affine([[f64; 3]; 4]);

const IDENTITY: Affine = Affine([
    [1.0, 0.0, 0.0],
    [0.0, 1.0, 0.0],
    [0.0, 0.0, 1.0],
    [0.0, 0.0, 0.0],
]);

impl Affine {
    fn is_identity(&self) -> bool {
        *self == IDENTITY
    }

    fn is_finite(&self) -> bool {
        self.0.iter().flatten().all(|x| x.is_finite())
    }

    /// `p` mapped: `x' = m00 x + m10 y + m20 z + m30`, and so on.
    fn apply(&self, p: Point3) -> Point3 {
        if self.is_identity() {
            return p;
        }
        let m = &self.0;
        let column = |j: usize| p[0] * m[0][j] + p[1] * m[1][j] + p[2] * m[2][j] + m[3][j];
        [column(0), column(1), column(2)]
    }

    /// This map followed by `outer` (a component's transform followed by
    /// its parent's).
    fn then(&self, outer: &Affine) -> Affine {
        if self.is_identity() {
            return *outer;
        }
        if outer.is_identity() {
            return *self;
        }
        let (a, b) = (&self.0, &outer.0);
        let mut out = [[0.0; 3]; 4];
        for (i, row) in out.iter_mut().enumerate() {
            for (j, x) in row.iter_mut().enumerate() {
                *x = a[i][0] * b[0][j] + a[i][1] * b[1][j] + a[i][2] * b[2][j];
            }
        }
        for (j, x) in out[3].iter_mut().enumerate() {
            *x += b[3][j];
        }
        Affine(out)
    }

    /// The determinant of the linear part.
    fn determinant(&self) -> f64 {
        let m = &self.0;
        m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1])
            - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
            + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0])
    }
}

/// The vertices and triangles of one `<mesh>`, with their lines.
#[derive(Default)]
struct MeshPart {
    vertices: Vec<Point3>,
    vertex_lines: Vec<u32>,
    triangles: Vec<[u32; 3]>,
    triangle_lines: Vec<u32>,
}

/// A reference to an object with a transform: a component or build item.
struct Reference {
    /// The object's part (its index in [`Parts`]) and id.
    part: usize,
    object: u32,
    transform: Affine,
    line: u32,
}

/// What an object is made of.
enum Shape {
    /// A mesh, and whether it is a solid (type `model` or `solidsupport`);
    /// other meshes are left out.
    Mesh(MeshPart, bool),
    Components(Vec<Reference>),
}

struct Object {
    line: u32,
    shape: Shape,
}

/// A model part's objects by id and its build items (none but in the
/// root model part).
struct Model {
    /// The part's entry name.
    part: String,
    objects: HashMap<u32, Object>,
    items: Vec<Reference>,
    /// Vertices and triangles the file spells out.
    literal: Size,
}

/// Reads `<model>`: required extensions, resources and (in the root model
/// part) build; the parts that production paths name are added to `parts`.
fn read_model(place: &Place<'_, '_>, parts: &mut Parts) -> Result<Model, UmbraError> {
    let root = place.doc.root_element();
    if !is(&root, CORE, "model") {
        return Err(place.error(
            root,
            format!(
                "the root element is <{}> in namespace '{}', not <model> of the 3MF core namespace {CORE}",
                shorten(root.tag_name().name()),
                uri(root.tag_name().namespace().unwrap_or(""))
            ),
        ));
    }
    check_required_extensions(root, place)?;
    let mut model = Model {
        part: place.part.to_string(),
        objects: HashMap::new(),
        items: Vec::new(),
        literal: Size::default(),
    };
    for resources in core_children(root, "resources") {
        for node in core_children(resources, "object") {
            read_object(node, place, parts, &mut model)?;
        }
    }
    if place.index != 0 {
        // Production extension 3.2: the build is in the root model part
        // only; a non-root part's (empty, as producers write it) is ignored.
        return Ok(model);
    }
    let Some(build) = core_children(root, "build").next() else {
        return Err(place.error(root, "the model has no <build> element"));
    };
    for node in core_children(build, "item") {
        model.items.push(read_reference(node, place, parts)?);
    }
    Ok(model)
}

/// Refuses a `requiredextensions` this reader cannot honour.
fn check_required_extensions(root: Node<'_, '_>, place: &Place<'_, '_>) -> Result<(), UmbraError> {
    let Some(required) = root.attribute("requiredextensions") else {
        return Ok(());
    };
    for prefix in required.split_ascii_whitespace() {
        let namespace = root.lookup_namespace_uri(Some(prefix));
        if !namespace.is_some_and(|ns| IGNORABLE_EXTENSIONS.contains(&ns)) {
            return Err(place.error(
                root,
                format!(
                    "the model requires the extension '{}' ({}), which this reader does not support",
                    shorten(prefix),
                    namespace.map_or_else(|| "an undeclared prefix".to_string(), uri)
                ),
            ));
        }
    }
    Ok(())
}

/// Reads one `<object>` into `model`.
fn read_object(
    node: Node<'_, '_>,
    place: &Place<'_, '_>,
    parts: &mut Parts,
    model: &mut Model,
) -> Result<(), UmbraError> {
    let id = place.resource_id(node, "id")?;
    let line = place.line(node);
    if let Some(first) = model.objects.get(&id) {
        return Err(place.error(
            node,
            format!(
                "duplicate object id {id} (first defined on line {})",
                first.line
            ),
        ));
    }
    let solid = match node.attribute("type").map(str::trim) {
        None | Some("model") | Some("solidsupport") => true,
        Some("support") | Some("surface") | Some("other") => false,
        Some(other) => {
            return Err(place.error(
                node,
                format!(
                    "object {id}: type '{}' is not model, solidsupport, support, surface or other",
                    shorten(other)
                ),
            ))
        }
    };
    let mesh = core_children(node, "mesh").next();
    let components = core_children(node, "components").next();
    let shape = match (mesh, components) {
        (Some(mesh), None) => {
            let part = read_mesh(mesh, id, place)?;
            model.literal.add(Size::of(&part));
            Shape::Mesh(part, solid)
        }
        (None, Some(components)) => Shape::Components(
            core_children(components, "component")
                .map(|c| read_reference(c, place, parts))
                .collect::<Result<_, _>>()?,
        ),
        (Some(_), Some(_)) => {
            return Err(place.error(node, format!("object {id} has both a <mesh> and <components>")))
        }
        (None, None) => {
            return Err(place.error(
                node,
                format!("object {id} has neither a <mesh> nor <components> (a shape of an extension this reader does not support?)"),
            ))
        }
    };
    model.objects.insert(id, Object { line, shape });
    Ok(())
}

/// Reads a `<component>` or `<item>`: its object's part and id, and its
/// transform. A production path is followed from the root model part only
/// (production extension 3.1.2).
fn read_reference(
    node: Node<'_, '_>,
    place: &Place<'_, '_>,
    parts: &mut Parts,
) -> Result<Reference, UmbraError> {
    let object = place.resource_id(node, "objectid")?;
    let tag = node.tag_name().name();
    let part = match node.attribute((PRODUCTION, "path")) {
        None => place.index,
        Some(path) if place.index != 0 => {
            return Err(place.error(
                node,
                format!(
                    "<{tag}> refers to object {object} in the part '{}' (a production path) from a part other than the root model part, which the production extension forbids (section 3.1.2: a path is only valid in the root model file)",
                    part_name(path)
                ),
            ))
        }
        Some(path) => parts
            .named(path, place.line(node))
            .map_err(|m| place.error(node, format!("<{tag}> refers to object {object}: {m}")))?,
    };
    let transform = match node.attribute("transform") {
        None => IDENTITY,
        Some(text) => read_transform(text).map_err(|m| place.error(node, m))?,
    };
    Ok(Reference {
        part,
        object,
        transform,
        line: place.line(node),
    })
}

/// The 12 finite numbers of a transform attribute.
fn read_transform(text: &str) -> Result<Affine, String> {
    let numbers: Vec<&str> = text.split_ascii_whitespace().take(13).collect();
    if numbers.len() != 12 {
        return Err(format!(
            "transform '{}' does not have 12 numbers",
            shorten(text)
        ));
    }
    let mut m = [[0.0; 3]; 4];
    for (k, token) in numbers.iter().enumerate() {
        let value = parse_number(token).map_err(|e| format!("transform: {e}"))?;
        if !value.is_finite() {
            return Err(format!(
                "transform number {} is '{}', not finite",
                k + 1,
                shorten(token)
            ));
        }
        if let Some(x) = m.get_mut(k / 3).and_then(|row| row.get_mut(k % 3)) {
            *x = value;
        }
    }
    Ok(Affine(m))
}

/// Reads a `<mesh>`: its vertices and triangles, indices checked.
fn read_mesh(mesh: Node<'_, '_>, id: u32, place: &Place<'_, '_>) -> Result<MeshPart, UmbraError> {
    let mut part = MeshPart::default();
    for vertices in core_children(mesh, "vertices") {
        for node in core_children(vertices, "vertex") {
            part.vertices.push(read_vertex(node, place)?);
            part.vertex_lines.push(place.line(node));
        }
    }
    for triangles in core_children(mesh, "triangles") {
        for node in core_children(triangles, "triangle") {
            let number = part.triangles.len() + 1;
            let t = read_triangle(node, place)?;
            if let Some(&v) = t.iter().find(|&&v| v as usize >= part.vertices.len()) {
                return Err(place.error(
                    node,
                    format!(
                        "triangle {number} of object {id} refers to vertex {v}, but the object has {} vertices",
                        part.vertices.len()
                    ),
                ));
            }
            part.triangles.push(t);
            part.triangle_lines.push(place.line(node));
        }
    }
    Ok(part)
}

/// The coordinates of a `<vertex>`.
fn read_vertex(node: Node<'_, '_>, place: &Place<'_, '_>) -> Result<Point3, UmbraError> {
    let mut p = [0.0; 3];
    for (x, name) in p.iter_mut().zip(["x", "y", "z"]) {
        let text = place.attribute(node, name)?;
        *x = parse_number(text.trim())
            .map_err(|e| place.error(node, format!("<vertex> {name}: {e}")))?;
    }
    Ok(p)
}

/// The three vertex indices of a `<triangle>`.
fn read_triangle(node: Node<'_, '_>, place: &Place<'_, '_>) -> Result<[u32; 3], UmbraError> {
    let mut t = [0; 3];
    for (v, name) in t.iter_mut().zip(["v1", "v2", "v3"]) {
        let text = place.attribute(node, name)?;
        *v = text.trim().parse().map_err(|_| {
            place.error(
                node,
                format!(
                    "<triangle> {name} = '{}' is not a vertex index (an integer from 0 to {})",
                    shorten(text),
                    u32::MAX
                ),
            )
        })?;
    }
    Ok(t)
}

/// Vertex and triangle counts, saturating.
#[derive(Clone, Copy, Debug, Default)]
struct Size {
    vertices: u64,
    triangles: u64,
}

impl Size {
    fn of(part: &MeshPart) -> Size {
        Size {
            vertices: part.vertices.len() as u64,
            triangles: part.triangles.len() as u64,
        }
    }

    fn add(&mut self, other: Size) {
        self.vertices = self.vertices.saturating_add(other.vertices);
        self.triangles = self.triangles.saturating_add(other.triangles);
    }
}

/// An object: the index of its part in [`Parts`] and its id there.
type Key = (usize, u32);

/// The model parts read, for expanding the build and naming places.
struct Build<'a> {
    file: &'a str,
    /// The root model part first.
    models: &'a [Model],
}

impl Build<'_> {
    fn object(&self, (part, id): Key) -> Option<&Object> {
        self.models.get(part).and_then(|m| m.objects.get(&id))
    }

    fn part(&self, part: usize) -> &str {
        self.models.get(part).map_or("", |m| m.part.as_str())
    }

    /// `file: malformed 3MF: 3D/Objects/object_1.model line 12: message`.
    fn error_at(&self, part: usize, line: u32, message: impl std::fmt::Display) -> UmbraError {
        malformed(
            self.file,
            format!("{} line {line}: {message}", part_name(self.part(part))),
        )
    }

    /// Object `key` as named from a place in part `from`: its id, and its
    /// part if another.
    fn name(&self, (part, id): Key, from: usize) -> String {
        if part == from {
            id.to_string()
        } else {
            format!("{id} of the part '{}'", part_name(self.part(part)))
        }
    }
}

/// The size object `key` expands to and its height (1 for a mesh, one
/// more than its highest component otherwise), memoized in `sizes`; the
/// reference on `line` of part `from` names it. Refuses unknown objects,
/// cycles (`stack` holds the objects being expanded) and nesting deeper
/// than [`MAX_DEPTH`], also where a memoized object is reached again lower
/// down.
fn expanded_size(
    key: Key,
    from: usize,
    line: u32,
    build: &Build<'_>,
    sizes: &mut HashMap<Key, (Size, usize)>,
    stack: &mut Vec<Key>,
) -> Result<(Size, usize), UmbraError> {
    let too_deep = || {
        build.error_at(
            from,
            line,
            format!("components nest deeper than {MAX_DEPTH} levels"),
        )
    };
    if let Some(&(size, height)) = sizes.get(&key) {
        if stack.len() + height > MAX_DEPTH {
            return Err(too_deep());
        }
        return Ok((size, height));
    }
    let Some(object) = build.object(key) else {
        let (part, id) = key;
        let what = if part == from {
            "the model".to_string()
        } else {
            format!("the part '{}'", part_name(build.part(part)))
        };
        return Err(build.error_at(
            from,
            line,
            format!("objectid {id} names no object of {what}"),
        ));
    };
    if stack.contains(&key) {
        let chain: Vec<String> = stack
            .iter()
            .skip_while(|&&o| o != key)
            .chain([&key])
            .map(|&o| build.name(o, from))
            .collect();
        return Err(build.error_at(
            from,
            line,
            format!("component cycle: object {}", chain.join(" -> ")),
        ));
    }
    if stack.len() >= MAX_DEPTH {
        return Err(too_deep());
    }
    let expanded = match &object.shape {
        Shape::Mesh(part, true) => (Size::of(part), 1),
        Shape::Mesh(_, false) => (Size::default(), 1),
        Shape::Components(components) => {
            stack.push(key);
            let mut size = Size::default();
            let mut height = 1;
            for c in components {
                let (s, h) = expanded_size((c.part, c.object), key.0, c.line, build, sizes, stack)?;
                size.add(s);
                height = height.max(h + 1);
            }
            stack.pop();
            (size, height)
        }
    };
    sizes.insert(key, expanded);
    Ok(expanded)
}

/// The size of the whole build, refused past the instancing budget.
fn build_size(build: &Build<'_>) -> Result<Size, UmbraError> {
    let mut sizes = HashMap::new();
    let mut total = Size::default();
    let mut literal = Size::default();
    for model in build.models {
        literal.add(model.literal);
    }
    for item in build.models.iter().take(1).flat_map(|m| &m.items) {
        let mut stack = Vec::new();
        let (size, _) = expanded_size(
            (item.part, item.object),
            0,
            item.line,
            build,
            &mut sizes,
            &mut stack,
        )?;
        total.add(size);
    }
    let max_vertices = INSTANCE_BUDGET.max(literal.vertices);
    let max_triangles = INSTANCE_BUDGET.max(literal.triangles);
    if total.vertices > max_vertices || total.triangles > max_triangles {
        return Err(malformed(
            build.file,
            format!(
                "{}: the build items expand through their components to {} vertices and {} triangles, past the budget of {max_vertices} and {max_triangles} (the file spells out {} and {})",
                part_name(build.part(0)),
                total.vertices,
                total.triangles,
                literal.vertices,
                literal.triangles
            ),
        ));
    }
    Ok(total)
}

/// The mesh being produced, with its origins.
struct Output {
    vertices: Vec<Point3>,
    triangles: Vec<[u32; 3]>,
    origins: Origins,
}

/// Every build item of the root model part (`models[0]`) expanded into
/// one mesh (see the module docs).
fn expand(models: &[Model], file: &str) -> Result<(TriangleMesh, Origins), UmbraError> {
    let build = Build { file, models };
    let total = build_size(&build)?;
    let too_many = || {
        malformed(
            file,
            format!(
                "{}: more than {} vertices",
                part_name(build.part(0)),
                u32::MAX
            ),
        )
    };
    let vertices = usize::try_from(total.vertices).map_err(|_| too_many())?;
    u32::try_from(total.vertices).map_err(|_| too_many())?;
    let triangles = usize::try_from(total.triangles).map_err(|_| too_many())?;
    let mut out = Output {
        vertices: Vec::with_capacity(vertices),
        triangles: Vec::with_capacity(triangles),
        origins: Origins::new(0, "triangle", "line"),
    };
    out.origins.vertex_places.reserve(vertices);
    out.origins.face_places.reserve(triangles);
    for item in models.iter().take(1).flat_map(|m| &m.items) {
        emit(
            (item.part, item.object),
            &item.transform,
            0,
            item.line,
            &build,
            &mut out,
        )?;
    }
    refuse_vertices_alone(
        out.vertices.len(),
        out.triangles.len(),
        &out.origins,
        file,
        FORMAT,
    )?;
    let mesh = TriangleMesh::new(out.vertices, out.triangles);
    Ok((mesh, out.origins))
}

/// Appends object `key` under `transform`, named on `line` of part `from`
/// (the depth and the references were checked by [`build_size`]).
fn emit(
    key: Key,
    transform: &Affine,
    from: usize,
    line: u32,
    build: &Build<'_>,
    out: &mut Output,
) -> Result<(), UmbraError> {
    if !transform.is_finite() {
        return Err(build.error_at(
            from,
            line,
            "the transforms composed down to here overflow f64 (not finite)",
        ));
    }
    match build.object(key).map(|o| &o.shape) {
        Some(Shape::Mesh(part, true)) => emit_mesh(part, transform, out),
        Some(Shape::Components(components)) => {
            for c in components {
                emit(
                    (c.part, c.object),
                    &c.transform.then(transform),
                    key.0,
                    c.line,
                    build,
                    out,
                )?;
            }
        }
        Some(Shape::Mesh(_, false)) | None => {}
    }
    Ok(())
}

/// Appends one mesh under `transform`, triangles reversed if it mirrors.
fn emit_mesh(part: &MeshPart, transform: &Affine, out: &mut Output) {
    // Fits: the total was checked against u32::MAX.
    let base = out.vertices.len() as u32;
    out.vertices
        .extend(part.vertices.iter().map(|&p| transform.apply(p)));
    out.origins
        .vertex_places
        .extend_from_slice(&part.vertex_lines);
    let mirror = transform.determinant() < 0.0;
    out.triangles.extend(part.triangles.iter().map(|t| {
        let [a, b, c] = t.map(|v| base + v);
        if mirror {
            [a, c, b]
        } else {
            [a, b, c]
        }
    }));
    out.origins
        .face_places
        .extend_from_slice(&part.triangle_lines);
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh_to_3mf;
    use proptest::prelude::*;
    use std::io::Write;
    use test_support::measure::polygon_mesh_volume;
    use test_support::shapes::{box_triangles, icosphere, tetra, uv_sphere};
    use zip::write::SimpleFileOptions;
    use zip::{CompressionMethod, ZipWriter};

    const RELS: &str = r#"<?xml version="1.0" encoding="UTF-8"?>
<Relationships xmlns="http://schemas.openxmlformats.org/package/2006/relationships"><Relationship Target="/3D/3dmodel.model" Id="rel0" Type="http://schemas.microsoft.com/3dmanufacturing/2013/01/3dmodel"/></Relationships>
"#;

    /// A zip package of `entries` (deflated).
    fn package(entries: &[(&str, &str)]) -> Vec<u8> {
        let mut zip = ZipWriter::new(Cursor::new(Vec::new()));
        let options = SimpleFileOptions::default().compression_method(CompressionMethod::Deflated);
        for (name, text) in entries {
            zip.start_file(*name, options).unwrap();
            zip.write_all(text.as_bytes()).unwrap();
        }
        zip.finish().unwrap().into_inner()
    }

    /// A package with the usual relationship and `model` as the model part.
    fn simple(model: &str) -> Vec<u8> {
        package(&[("_rels/.rels", RELS), ("3D/3dmodel.model", model)])
    }

    /// A model document: `resources` and `build` are the contents of the
    /// two elements, one element a line.
    fn model(resources: &str, build: &str) -> String {
        format!(
            "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<model unit=\"millimeter\" xmlns=\"{CORE}\">\n<resources>\n{resources}</resources>\n<build>\n{build}</build>\n</model>\n"
        )
    }

    /// An `<object>` holding the mesh `m`, one element a line.
    fn mesh_object(id: u32, kind: &str, m: &TriangleMesh) -> String {
        let mut s = format!("<object id=\"{id}\" type=\"{kind}\">\n<mesh>\n<vertices>\n");
        for p in &m.vertices {
            s += &format!(
                "<vertex x=\"{:?}\" y=\"{:?}\" z=\"{:?}\"/>\n",
                p[0], p[1], p[2]
            );
        }
        s += "</vertices>\n<triangles>\n";
        for t in &m.triangles {
            s += &format!(
                "<triangle v1=\"{}\" v2=\"{}\" v3=\"{}\"/>\n",
                t[0], t[1], t[2]
            );
        }
        s + "</triangles>\n</mesh>\n</object>\n"
    }

    /// An `<object>` of components, each `(objectid, transform)`.
    fn components_object(id: u32, components: &[(u32, &str)]) -> String {
        let mut s = format!("<object id=\"{id}\">\n<components>\n");
        for (object, transform) in components {
            s += &format!("<component objectid=\"{object}\" transform=\"{transform}\"/>\n");
        }
        s + "</components>\n</object>\n"
    }

    fn item(id: u32, transform: &str) -> String {
        format!("<item objectid=\"{id}\" transform=\"{transform}\"/>\n")
    }

    fn unit_cube() -> TriangleMesh {
        box_triangles([0.0; 3], [1.0; 3])
    }

    const IDENTITY_TEXT: &str = "1 0 0 0 1 0 0 0 1 0 0 0";

    fn error_of(bytes: &[u8]) -> String {
        parse_3mf(bytes, "t.3mf").unwrap_err().to_string()
    }

    fn bits(m: &TriangleMesh) -> Vec<[u64; 3]> {
        m.vertices.iter().map(|p| p.map(f64::to_bits)).collect()
    }

    fn volume(m: &TriangleMesh) -> f64 {
        polygon_mesh_volume(&m.to_polygon_mesh())
    }

    fn bounds(m: &TriangleMesh) -> [[f64; 3]; 2] {
        let mut b = [[f64::INFINITY; 3], [f64::NEG_INFINITY; 3]];
        for p in &m.vertices {
            for k in 0..3 {
                b[0][k] = b[0][k].min(p[k]);
                b[1][k] = b[1][k].max(p[k]);
            }
        }
        b
    }

    #[test]
    fn written_meshes_read_back_bit_for_bit() {
        let odd = TriangleMesh::new(
            vec![
                [-0.0, 0.1, 1e-300],
                [1.0 / 3.0, -0.0, 5e-324],
                [0.2, 1e300, -7.25],
                [123456789012345680.0, 0.3, 2.0f64.sqrt()],
            ],
            vec![[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2]],
        );
        let meshes = [
            unit_cube(),
            box_triangles([-1.5, 2.0, 0.1], [3.0, 2.7, 9.0]),
            icosphere([0.1, 0.2, 0.3], 1.7, 2),
            uv_sphere([5.0, -3.0, 1.0], 0.3, 7, 5),
            tetra([[0.0; 3], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]),
            odd,
        ];
        for m in meshes {
            let bytes = mesh_to_3mf(&m.to_polygon_mesh()).unwrap();
            let back = parse_3mf(&bytes, "r.3mf").unwrap();
            assert_eq!(back.triangles, m.triangles);
            assert_eq!(bits(&back), bits(&m));
            let read = read_3mf_bytes(&bytes, "r.3mf", MeshReadOptions::default(), true).unwrap();
            assert_eq!(read.facets.len(), m.triangles.len());
        }
    }

    #[test]
    fn components_compose_transforms_as_computed_by_hand() {
        // Object 2 scales the cube by (2, 3, 4) and moves it by (10, 20,
        // 30); object 3 moves that by (100, 0, 0); the item turns it by 90
        // degrees about z (x' = -y, y' = x).
        let xml = model(
            &(mesh_object(1, "model", &unit_cube())
                + &components_object(2, &[(1, "2 0 0 0 3 0 0 0 4 10 20 30")])
                + &components_object(3, &[(2, "1 0 0 0 1 0 0 0 1 100 0 0")])),
            &item(3, "0 1 0 -1 0 0 0 0 1 0 0 0"),
        );
        let m = parse_3mf(&simple(&xml), "c.3mf").unwrap();
        let cube = unit_cube();
        assert_eq!(m.triangles, cube.triangles);
        for (p, q) in cube.vertices.iter().zip(&m.vertices) {
            let want = [-(20.0 + 3.0 * p[1]), 110.0 + 2.0 * p[0], 30.0 + 4.0 * p[2]];
            assert_eq!(*q, want, "corner {p:?}");
        }
        m.check_topology().unwrap();
        assert_eq!(volume(&m), 24.0);
    }

    #[test]
    fn a_mirroring_transform_keeps_the_volume_positive() {
        let cube = unit_cube();
        assert_eq!(volume(&cube), 1.0);
        let mirror = "-1 0 0 0 1 0 0 0 1 5 0 0";
        // Mirrored by the item; by a component; by both (no mirror).
        let cases = [
            (mesh_object(1, "model", &cube), item(1, mirror), true),
            (
                mesh_object(1, "model", &cube) + &components_object(2, &[(1, mirror)]),
                item(2, IDENTITY_TEXT),
                true,
            ),
            (
                mesh_object(1, "model", &cube) + &components_object(2, &[(1, mirror)]),
                item(2, mirror),
                false,
            ),
        ];
        for (resources, build, mirrored) in cases {
            let m = parse_3mf(&simple(&model(&resources, &build)), "m.3mf").unwrap();
            assert_eq!(volume(&m), 1.0, "{build}");
            m.check_topology().unwrap();
            let t = cube.triangles[0];
            let want = if mirrored { [t[0], t[2], t[1]] } else { t };
            assert_eq!(m.triangles[0], want);
            let x0 = if mirrored { 4.0 } else { 0.0 };
            assert_eq!(bounds(&m), [[x0, 0.0, 0.0], [x0 + 1.0, 1.0, 1.0]]);
        }
    }

    #[test]
    fn two_build_items_are_two_shells() {
        let xml = model(
            &mesh_object(1, "model", &unit_cube()),
            &(item(1, IDENTITY_TEXT) + &item(1, "1 0 0 0 1 0 0 0 1 0 0 3")),
        );
        let bytes = simple(&xml);
        let m = parse_3mf(&bytes, "two.3mf").unwrap();
        assert_eq!((m.vertices.len(), m.triangles.len()), (16, 24));
        assert_eq!(bounds(&m), [[0.0; 3], [1.0, 1.0, 4.0]]);
        assert_eq!(volume(&m), 2.0);
        read_3mf_bytes(&bytes, "two.3mf", MeshReadOptions::default(), true).unwrap();
    }

    #[test]
    fn support_objects_are_left_out_and_solid_supports_kept() {
        let cube = unit_cube();
        let xml = |kind: &str| {
            model(
                &(mesh_object(1, "model", &cube) + &mesh_object(2, kind, &cube)),
                &(item(1, IDENTITY_TEXT) + &item(2, "1 0 0 0 1 0 0 0 1 2 0 0")),
            )
        };
        for (kind, triangles) in [("support", 12), ("surface", 12), ("solidsupport", 24)] {
            let m = parse_3mf(&simple(&xml(kind)), "s.3mf").unwrap();
            assert_eq!(m.triangles.len(), triangles, "{kind}");
        }
        let e = error_of(&simple(&xml("lattice")));
        assert!(
            e.contains("line 32: object 2: type 'lattice' is not model"),
            "{e}"
        );
    }

    #[test]
    fn the_model_part_is_found_by_the_relationship_or_the_default() {
        let xml = model(
            &mesh_object(1, "model", &unit_cube()),
            &item(1, IDENTITY_TEXT),
        );
        let rels = |target: &str| {
            format!(
                "<Relationships xmlns=\"{RELATIONSHIPS}\"><Relationship Target=\"/Metadata/thumbnail.png\" Id=\"r1\" Type=\"http://schemas.openxmlformats.org/package/2006/relationships/metadata/thumbnail\"/><Relationship Target=\"{target}\" Id=\"rel0\" Type=\"http://schemas.microsoft.com/3dmanufacturing/2013/01/3dmodel\"/></Relationships>"
            )
        };
        let cases = [
            package(&[
                ("_rels/.rels", &rels("/3D/3dmodel.model")),
                ("3D/3dmodel.model", &xml),
            ]),
            package(&[
                ("_rels/.rels", &rels("3D/3dmodel.model")),
                ("3D/3dmodel.model", &xml),
            ]),
            package(&[
                ("_rels/.rels", &rels("/Models/Part One.model")),
                ("Models/Part One.model", &xml),
                ("3D/3dmodel.model", "garbage"),
            ]),
            package(&[("3D/3dmodel.model", &xml)]),
            package(&[
                (
                    "_rels/.rels",
                    &format!("<Relationships xmlns=\"{RELATIONSHIPS}\"/>"),
                ),
                ("3D/3dmodel.model", &xml),
            ]),
        ];
        for (k, bytes) in cases.iter().enumerate() {
            let m = parse_3mf(bytes, "p.3mf").unwrap_or_else(|e| panic!("case {k}: {e}"));
            assert_eq!(m.triangles.len(), 12, "case {k}");
        }
        // Entry names are case-sensitive.
        let e = error_of(&package(&[
            ("_rels/.rels", &rels("/3D/3DModel.model")),
            ("3D/3dmodel.model", &xml),
        ]));
        assert!(
            e.contains("the package has no model part '3D/3DModel.model' (named as the model by _rels/.rels line 1); it holds '_rels/.rels', '3D/3dmodel.model'"),
            "{e}"
        );
        let e = error_of(&package(&[("3D/other.model", &xml)]));
        assert!(
            e.contains(
                "no model part '3D/3dmodel.model' (the default, as _rels/.rels names no model)"
            ),
            "{e}"
        );
    }

    #[test]
    fn not_a_package_and_truncated_packages_are_errors() {
        let e = error_of(b"solid cube\nfacet normal 0 0 1\n");
        assert!(
            e.starts_with("t.3mf: malformed 3MF: not a 3MF package (a 3MF file is a zip archive)"),
            "{e}"
        );
        assert_eq!(error_of(b" \n"), "t.3mf: the file is empty (no geometry)");
        let bytes = mesh_to_3mf(&unit_cube().to_polygon_mesh()).unwrap();
        for cut in 0..bytes.len() {
            assert!(parse_3mf(&bytes[..cut], "t.3mf").is_err(), "cut at {cut}");
        }
        // A corrupted deflate stream or checksum is named.
        let mut bad = bytes.clone();
        let at = bytes.windows(5).position(|w| w == b"3dmod").unwrap();
        for b in &mut bad[at + 40..at + 80] {
            *b ^= 0x5a;
        }
        assert!(parse_3mf(&bad, "t.3mf").is_err());
    }

    #[test]
    fn malformed_model_text_names_its_line() {
        let cube = unit_cube();
        let good = model(&mesh_object(1, "model", &cube), &item(1, IDENTITY_TEXT));
        let cases: Vec<(String, &str)> = vec![
            (good.replace("</build>", ""), "3D/3dmodel.model line 36: malformed XML"),
            (good.replace("x=\"1.0\" y=\"0.0\"", "x=\"1.2.3\" y=\"0.0\""), "3D/3dmodel.model line 8: <vertex> x: '1.2.3' is not a number"),
            (good.replace("z=\"1e400\"", "").replacen("z=\"0.0\"/>", "z=\"1e400\"/>", 1), "line 7: <vertex> z: '1e400' overflows f64"),
            (good.replacen(" z=\"0.0\"", "", 1), "line 7: <vertex> has no attribute 'z'"),
            (good.replacen("v3=\"3\"", "v3=\"8\"", 1), "line 17: triangle 1 of object 1 refers to vertex 8, but the object has 8 vertices"),
            (good.replacen("v1=\"0\"", "v1=\"-1\"", 1), "line 17: <triangle> v1 = '-1' is not a vertex index"),
            (good.replacen("v1=\"0\"", "v1=\"99999999999\"", 1), "<triangle> v1 = '99999999999' is not a vertex index (an integer from 0 to 4294967295)"),
            (good.replace("objectid=\"1\"", "objectid=\"7\""), "line 34: objectid 7 names no object of the model"),
            (good.replace("objectid=\"1\"", "objectid=\"one\""), "line 34: objectid = 'one' is not a resource id"),
            (good.replace(IDENTITY_TEXT, "1 0 0 0 1 0 0 0 1 inf 0 0"), "line 34: transform number 10 is 'inf', not finite"),
            (good.replace(IDENTITY_TEXT, "1 0 0 0 1 0 0 0 1 0 0"), "line 34: transform '1 0 0 0 1 0 0 0 1 0 0' does not have 12 numbers"),
            (good.replace(IDENTITY_TEXT, "1 0 0 0 1 0 0 0 1 0 0 NaNa"), "line 34: transform: 'NaNa' is not a number"),
            (good.replace(CORE, "http://example.com/other"), "line 2: the root element is <model> in namespace 'http://example.com/other', not <model> of the 3MF core namespace"),
            (good.replace("<build>\n<item objectid=\"1\" transform=\"1 0 0 0 1 0 0 0 1 0 0 0\"/>\n</build>\n", ""), "line 2: the model has no <build> element"),
            (good.replace("<mesh>", "<mesh><vertices/></mesh><components/><mesh>"), "line 4: object 1 has both a <mesh> and <components>"),
            (good.replace("<mesh>", "<b:beamlattice xmlns:b=\"urn:b\"/><nomesh>").replace("</mesh>", "</nomesh>"), "line 4: object 1 has neither a <mesh> nor <components>"),
            (good.replace("<model ", "<model xmlns:b=\"http://schemas.microsoft.com/3dmanufacturing/beamlattice/2017/02\" requiredextensions=\"b\" "), "line 2: the model requires the extension 'b' (http://schemas.microsoft.com/3dmanufacturing/beamlattice/2017/02), which this reader does not support"),
            (good.replace("<model ", "<model requiredextensions=\"q\" "), "the model requires the extension 'q' (an undeclared prefix)"),
            (good.replace("<item ", &format!("<item xmlns:p=\"{PRODUCTION}\" p:path=\"/3D/Objects/o.model\" ")), "line 34: a production path names the part '/3D/Objects/o.model', which the package does not have; it holds '_rels/.rels', '3D/3dmodel.model'"),
            (good.replace("<object id=\"1\" type=\"model\">\n<mesh>", "<object id=\"1\" type=\"model\">\n<mesh>\n</mesh>\n</object>\n<object id=\"1\">\n<mesh>"), "line 8: duplicate object id 1 (first defined on line 4)"),
            (good.replace("<?xml", "<!DOCTYPE model [<!ENTITY a \"aaaa\">]>\n<?xml"), "malformed XML"),
        ];
        for (xml, want) in cases {
            let e = error_of(&simple(&xml));
            assert!(
                e.starts_with("t.3mf: malformed 3MF: 3D/3dmodel.model line ") && e.contains(want),
                "{want}\n{e}"
            );
        }
        // Not UTF-8.
        let e = error_of(&stored(b"<model>\n\xff</model>"));
        assert!(
            e.contains("3D/3dmodel.model: line 2: not UTF-8 text (invalid byte 0xff at offset 8)"),
            "{e}"
        );
    }

    #[test]
    fn allowed_extensions_are_read() {
        let resources =
            mesh_object(1, "model", &unit_cube()) + &components_object(2, &[(1, IDENTITY_TEXT)]);
        // Required production and materials, a UUID and colours: read.
        let xml = model(&resources, &item(2, IDENTITY_TEXT)).replace(
            "<model ",
            &format!("<model xmlns:p=\"{PRODUCTION}\" xmlns:m=\"http://schemas.microsoft.com/3dmanufacturing/material/2015/02\" requiredextensions=\"p m\" "),
        ).replace("<resources>\n", "<resources>\n<m:colorgroup id=\"9\"><m:color color=\"#FF0000\"/></m:colorgroup>\n<basematerials id=\"8\"><base name=\"red\" displaycolor=\"#FF0000\"/></basematerials>\n").replace("<item ", "<item p:UUID=\"1234\" ");
        assert_eq!(
            parse_3mf(&simple(&xml), "p.3mf").unwrap().triangles.len(),
            12
        );
    }

    /// Where Bambu Studio and Orca Slicer put an object's mesh.
    const OBJECT_PART: &str = "/3D/Objects/object_1.model";

    /// A model document declaring and requiring the production extension.
    fn production_model(resources: &str, build: &str) -> String {
        model(resources, build).replace(
            "<model ",
            &format!("<model xmlns:p=\"{PRODUCTION}\" requiredextensions=\"p\" "),
        )
    }

    /// An `<object>` of components, each `(path, objectid, transform)`.
    fn path_components_object(id: u32, components: &[(&str, u32, &str)]) -> String {
        let mut s = format!("<object id=\"{id}\" p:UUID=\"00000000-0000-4000-8000-00000000000{id}\">\n<components>\n");
        for (path, object, transform) in components {
            s += &format!(
                "<component p:path=\"{path}\" objectid=\"{object}\" p:UUID=\"00000000-0000-4000-8000-000000000001\" transform=\"{transform}\"/>\n"
            );
        }
        s + "</components>\n</object>\n"
    }

    /// The relationships of the root model part to `parts`.
    fn model_rels(parts: &[&str]) -> String {
        let mut s = format!(
            "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<Relationships xmlns=\"{RELATIONSHIPS}\">"
        );
        for (k, part) in parts.iter().enumerate() {
            s += &format!("<Relationship Target=\"{part}\" Id=\"rel-{k}\" Type=\"http://schemas.microsoft.com/3dmanufacturing/2013/01/3dmodel\"/>");
        }
        s + "</Relationships>\n"
    }

    /// A package laid out as Bambu Studio writes one: the root model, the
    /// `parts` (`(path, model)`), the root part's relationships to them,
    /// a thumbnail and a settings entry.
    fn bambu(root: &str, parts: &[(&str, &str)]) -> Vec<u8> {
        let names: Vec<&str> = parts.iter().map(|p| p.0).collect();
        let rels = model_rels(&names);
        let mut entries = vec![
            ("_rels/.rels", RELS),
            ("3D/3dmodel.model", root),
            ("3D/_rels/3dmodel.model.rels", &rels),
            ("Metadata/plate_1.png", "\u{89}PNG not really"),
            ("Metadata/model_settings.config", "<config/>"),
        ];
        for (path, text) in parts {
            entries.push((path.trim_start_matches('/'), text));
        }
        package(&entries)
    }

    #[test]
    fn a_bambu_style_package_reads_through_its_object_parts() {
        // The root model has its own object 1 (a tetrahedron no item
        // uses); the component's object 1 is the cube of the other part.
        // The component scales the cube by (2, 3, 4) and moves it by (10,
        // 20, 30); the item turns it by 90 degrees about z (x' = -y, y' =
        // x) and moves it by (0, 0, 5).
        let tet = tetra([[0.0; 3], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]);
        let root = production_model(
            &(mesh_object(1, "model", &tet)
                + &path_components_object(2, &[(OBJECT_PART, 1, "2 0 0 0 3 0 0 0 4 10 20 30")])),
            &item(2, "0 1 0 -1 0 0 0 0 1 0 0 5"),
        );
        let cube = unit_cube();
        let part = production_model(&mesh_object(1, "model", &cube), "");
        let bytes = bambu(&root, &[(OBJECT_PART, &part)]);
        let m = parse_3mf(&bytes, "b.3mf").unwrap();
        assert_eq!(m.triangles, cube.triangles);
        for (p, q) in cube.vertices.iter().zip(&m.vertices) {
            let want = [-(20.0 + 3.0 * p[1]), 10.0 + 2.0 * p[0], 35.0 + 4.0 * p[2]];
            assert_eq!(*q, want, "corner {p:?}");
        }
        assert_eq!(bounds(&m), [[-23.0, 10.0, 35.0], [-20.0, 12.0, 39.0]]);
        assert_eq!(volume(&m), 24.0);
        // Places are lines of the part holding the vertex.
        let (_, origins) = parse_3mf_with_origins(&bytes, "b.3mf").unwrap();
        assert_eq!(origins.vertex_places[0], 7);
        read_3mf_bytes(&bytes, "b.3mf", MeshReadOptions::default(), true).unwrap();
        // Without the root part's relationships, and with the path on the
        // build item itself (no leading '/' either): the same.
        let direct = production_model(
            "",
            &item(1, "0 1 0 -1 0 0 0 0 1 0 0 5")
                .replace("<item ", "<item p:path=\"3D/Objects/object_1.model\" "),
        );
        let bytes = package(&[
            ("_rels/.rels", RELS),
            ("3D/3dmodel.model", &direct),
            ("3D/Objects/object_1.model", &part),
        ]);
        let m = parse_3mf(&bytes, "b.3mf").unwrap();
        assert_eq!(bounds(&m), [[-1.0, 0.0, 5.0], [0.0, 1.0, 6.0]]);
        assert_eq!(volume(&m), 1.0);
        // An error inside the other part names that part and its line.
        let bad = part.replacen("x=\"0.0\"", "x=\"zero\"", 1);
        let e = error_of(&bambu(&root, &[(OBJECT_PART, &bad)]));
        assert!(
            e.starts_with("t.3mf: malformed 3MF: 3D/Objects/object_1.model line 7: <vertex> x: 'zero' is not a number"),
            "{e}"
        );
        let e = error_of(&bambu(&root, &[(OBJECT_PART, "<model")]));
        assert!(
            e.contains("3D/Objects/object_1.model line 1: malformed XML"),
            "{e}"
        );
        // An id the other part does not have (the root part has it).
        let e = error_of(&bambu(
            &root,
            &[(OBJECT_PART, &part.replace("id=\"1\"", "id=\"3\""))],
        ));
        assert!(
            e.contains("3D/3dmodel.model line 22: objectid 1 names no object of the part '3D/Objects/object_1.model'"),
            "{e}"
        );
    }

    #[test]
    fn components_of_another_part_resolve_in_that_part() {
        // The part's object 5 is two components of its object 1 (no path:
        // its own object 1, a cube), moved by (0, 0, 3); its object 2 is a
        // support, left out. The root part has no object 1 at all.
        let cube = unit_cube();
        let part = production_model(
            &(mesh_object(1, "model", &cube)
                + &mesh_object(2, "support", &cube)
                + &components_object(
                    5,
                    &[
                        (1, IDENTITY_TEXT),
                        (2, IDENTITY_TEXT),
                        (1, "1 0 0 0 1 0 0 0 1 0 0 3"),
                    ],
                )),
            "",
        );
        let root = production_model(
            &path_components_object(7, &[(OBJECT_PART, 5, "1 0 0 0 1 0 0 0 1 1 0 0")]),
            &item(7, IDENTITY_TEXT),
        );
        let m = parse_3mf(&bambu(&root, &[(OBJECT_PART, &part)]), "c.3mf").unwrap();
        assert_eq!((m.vertices.len(), m.triangles.len()), (16, 24));
        assert_eq!(bounds(&m), [[1.0, 0.0, 0.0], [2.0, 1.0, 4.0]]);
        assert_eq!(volume(&m), 2.0);
        // A part's own <build> items are not the build.
        let with_items = part.replace("<build>\n", &format!("<build>\n{}", item(1, IDENTITY_TEXT)));
        let m = parse_3mf(&bambu(&root, &[(OBJECT_PART, &with_items)]), "c.3mf").unwrap();
        assert_eq!(m.triangles.len(), 24);
        // Nor does a part need a <build>.
        let no_build = part.replace("<build>\n</build>\n", "");
        let m = parse_3mf(&bambu(&root, &[(OBJECT_PART, &no_build)]), "c.3mf").unwrap();
        assert_eq!(m.triangles.len(), 24);
    }

    #[test]
    fn the_same_part_twice_is_two_shells_read_once() {
        let cube = unit_cube();
        let part = production_model(&mesh_object(1, "model", &cube), "");
        let root = production_model(
            &path_components_object(
                2,
                &[
                    (OBJECT_PART, 1, IDENTITY_TEXT),
                    (OBJECT_PART, 1, "1 0 0 0 1 0 0 0 1 0 0 3"),
                ],
            ),
            &(item(2, IDENTITY_TEXT)
                + &item(1, "1 0 0 0 1 0 0 0 1 5 0 0")
                    .replace("<item ", &format!("<item p:path=\"{OBJECT_PART}\" "))),
        );
        let m = parse_3mf(&bambu(&root, &[(OBJECT_PART, &part)]), "t.3mf").unwrap();
        assert_eq!((m.vertices.len(), m.triangles.len()), (24, 36));
        assert_eq!(bounds(&m), [[0.0; 3], [6.0, 1.0, 4.0]]);
        assert_eq!(volume(&m), 3.0);
        m.check_topology().unwrap();
        // Padded to 6 MiB, the part is read once: three reads would pass
        // the package's 16 MiB.
        let padded = part.replace("</model>", &format!("{}</model>", " ".repeat(6 << 20)));
        let bytes = bambu(&root, &[(OBJECT_PART, &padded)]);
        assert!(bytes.len() < 100_000, "{}", bytes.len());
        assert_eq!(parse_3mf(&bytes, "t.3mf").unwrap().triangles.len(), 36);
    }

    #[test]
    fn a_mirror_across_parts_keeps_the_volume_positive() {
        let cube = unit_cube();
        let part = production_model(&mesh_object(1, "model", &cube), "");
        let mirror = "-1 0 0 0 1 0 0 0 1 5 0 0";
        // Mirrored by the item; by the component; by both (no mirror).
        for (component, build, mirrored) in [
            (IDENTITY_TEXT, mirror, true),
            (mirror, IDENTITY_TEXT, true),
            (mirror, mirror, false),
        ] {
            let root = production_model(
                &path_components_object(2, &[(OBJECT_PART, 1, component)]),
                &item(2, build),
            );
            let m = parse_3mf(&bambu(&root, &[(OBJECT_PART, &part)]), "m.3mf").unwrap();
            assert_eq!(volume(&m), 1.0, "{component} {build}");
            m.check_topology().unwrap();
            let t = cube.triangles[0];
            let want = if mirrored { [t[0], t[2], t[1]] } else { t };
            assert_eq!(m.triangles[0], want);
            let x0 = if mirrored { 4.0 } else { 0.0 };
            assert_eq!(bounds(&m), [[x0, 0.0, 0.0], [x0 + 1.0, 1.0, 1.0]]);
        }
    }

    #[test]
    fn cycles_depth_and_budget_hold_across_parts() {
        let cube = mesh_object(1, "model", &unit_cube());
        // A root path naming the root part itself closes a cycle.
        let root = production_model(
            &(cube.clone()
                + &path_components_object(2, &[("/3D/3dmodel.model", 2, IDENTITY_TEXT)])),
            &item(2, IDENTITY_TEXT),
        );
        let e = error_of(&bambu(&root, &[]));
        assert!(
            e.contains("3D/3dmodel.model line 34: component cycle: object 2 -> 2"),
            "{e}"
        );
        // A root path naming the root part is the root part.
        let root = production_model(
            &(cube.clone()
                + &path_components_object(2, &[("/3D/3dmodel.model", 1, IDENTITY_TEXT)])),
            &item(2, IDENTITY_TEXT),
        );
        assert_eq!(
            parse_3mf(&bambu(&root, &[]), "r.3mf")
                .unwrap()
                .triangles
                .len(),
            12
        );
        // A cycle inside the other part, entered from the root.
        let part = production_model(
            &(cube.clone()
                + &components_object(3, &[(4, IDENTITY_TEXT)])
                + &components_object(4, &[(1, IDENTITY_TEXT), (3, IDENTITY_TEXT)])),
            "",
        );
        let root = production_model(
            &path_components_object(2, &[(OBJECT_PART, 3, IDENTITY_TEXT)]),
            &item(2, IDENTITY_TEXT),
        );
        let e = error_of(&bambu(&root, &[(OBJECT_PART, &part)]));
        assert!(
            e.contains("3D/Objects/object_1.model line 40: component cycle: object 3 -> 4 -> 3"),
            "{e}"
        );
        // 20 levels in the root part above 20 in the other part.
        let mut resources = cube.clone();
        for k in 2..=20 {
            resources += &components_object(k, &[(k - 1, IDENTITY_TEXT)]);
        }
        let part = production_model(&resources, "");
        let mut resources = path_components_object(101, &[(OBJECT_PART, 20, IDENTITY_TEXT)]);
        for k in 102..=121 {
            resources += &components_object(k, &[(k - 1, IDENTITY_TEXT)]);
        }
        let e = error_of(&bambu(
            &production_model(&resources, &item(121, IDENTITY_TEXT)),
            &[(OBJECT_PART, &part)],
        ));
        assert!(
            e.contains(&format!("components nest deeper than {MAX_DEPTH} levels")),
            "{e}"
        );
        let m = parse_3mf(
            &bambu(
                &production_model(&resources, &item(112, IDENTITY_TEXT)),
                &[(OBJECT_PART, &part)],
            ),
            "d.3mf",
        )
        .unwrap();
        assert_eq!(m.triangles.len(), 12);
        // Ten copies at each of 4 levels in each part: 10^8 cubes.
        let mut resources = cube.clone();
        for k in 2..=5 {
            let copies: Vec<(u32, &str)> = (0..10).map(|_| (k - 1, IDENTITY_TEXT)).collect();
            resources += &components_object(k, &copies);
        }
        let part = production_model(&resources, "");
        let copies: Vec<(&str, u32, &str)> =
            (0..10).map(|_| (OBJECT_PART, 5, IDENTITY_TEXT)).collect();
        let mut resources = path_components_object(11, &copies);
        for k in 12..=14 {
            let copies: Vec<(u32, &str)> = (0..10).map(|_| (k - 1, IDENTITY_TEXT)).collect();
            resources += &components_object(k, &copies);
        }
        let e = error_of(&bambu(
            &production_model(&resources, &item(14, IDENTITY_TEXT)),
            &[(OBJECT_PART, &part)],
        ));
        assert!(
            e.contains("3D/3dmodel.model: the build items expand through their components to 800000000 vertices and 1200000000 triangles, past the budget of 16777216 and 16777216 (the file spells out 8 and 12)"),
            "{e}"
        );
    }

    #[test]
    fn paths_to_missing_or_non_model_parts_are_refused() {
        let part = production_model(&mesh_object(1, "model", &unit_cube()), "");
        let root_to = |path: &str| {
            production_model(
                &path_components_object(2, &[(path, 1, IDENTITY_TEXT)]),
                &item(2, IDENTITY_TEXT),
            )
        };
        // Entry names are case-sensitive.
        let e = error_of(&bambu(
            &root_to("/3D/Objects/Object_1.model"),
            &[(OBJECT_PART, &part)],
        ));
        assert_eq!(
            e,
            "t.3mf: malformed 3MF: 3D/3dmodel.model line 6: a production path names the part '/3D/Objects/Object_1.model', which the package does not have; it holds '_rels/.rels', '3D/3dmodel.model', '3D/_rels/3dmodel.model.rels', 'Metadata/plate_1.png', 'Metadata/model_settings.config', '3D/Objects/object_1.model'"
        );
        for path in [
            "/Metadata/plate_1.png",
            "/Metadata/model_settings.config",
            "/3D/_rels/3dmodel.model.rels",
            "/_rels/.rels",
            "/.model",
            "",
            "/3D/Objects/object_1.model/",
        ] {
            let e = error_of(&bambu(&root_to(path), &[(OBJECT_PART, &part)]));
            assert!(
                e.contains(&format!("3D/3dmodel.model line 6: <component> refers to object 1: the production path '{path}' does not name a model part (a part whose name ends in .model)")),
                "{e}"
            );
        }
        // A model part's suffix in other case is a model part.
        let m = parse_3mf(
            &bambu(
                &root_to("/3D/Objects/a.MODEL"),
                &[("/3D/Objects/a.MODEL", &part)],
            ),
            "a.3mf",
        )
        .unwrap();
        assert_eq!(m.triangles.len(), 12);
    }

    #[test]
    fn a_path_in_a_non_root_part_is_refused() {
        // Production extension 3.2: a consumer MUST generate an error.
        let cube = mesh_object(1, "model", &unit_cube());
        let nested = production_model(
            &(path_components_object(3, &[("/3D/Objects/object_2.model", 1, IDENTITY_TEXT)])),
            "",
        );
        let leaf = production_model(&cube, "");
        let root = production_model(
            &path_components_object(2, &[(OBJECT_PART, 3, IDENTITY_TEXT)]),
            &item(2, IDENTITY_TEXT),
        );
        let e = error_of(&bambu(
            &root,
            &[
                (OBJECT_PART, &nested),
                ("/3D/Objects/object_2.model", &leaf),
            ],
        ));
        assert!(
            e.contains("3D/Objects/object_1.model line 6: <component> refers to object 1 in the part '/3D/Objects/object_2.model' (a production path) from a part other than the root model part, which the production extension forbids (section 3.1.2"),
            "{e}"
        );
        // Back to the root part: refused alike (no cycle can form).
        let back = production_model(
            &(path_components_object(3, &[("/3D/3dmodel.model", 2, IDENTITY_TEXT)])),
            "",
        );
        let e = error_of(&bambu(&root, &[(OBJECT_PART, &back)]));
        assert!(
            e.contains("from a part other than the root model part"),
            "{e}"
        );
    }

    #[test]
    fn many_parts_past_the_package_budget_are_refused() {
        // 20 parts of 1 MiB each (mostly white space): each is within the
        // 16 MiB of a package of this size, together they are not.
        let cube = mesh_object(1, "model", &unit_cube());
        let pad = " ".repeat(1 << 20);
        let paths: Vec<String> = (1..=20)
            .map(|k| format!("/3D/Objects/object_{k}.model"))
            .collect();
        let part = production_model(&cube, "").replace("</model>", &format!("{pad}</model>"));
        let parts: Vec<(&str, &str)> = paths.iter().map(|p| (p.as_str(), part.as_str())).collect();
        let components: Vec<(&str, u32, &str)> = paths
            .iter()
            .map(|p| (p.as_str(), 1, IDENTITY_TEXT))
            .collect();
        let root = production_model(
            &path_components_object(2, &components),
            &item(2, IDENTITY_TEXT),
        );
        let bytes = bambu(&root, &parts);
        assert!(bytes.len() < 200_000, "{}", bytes.len());
        let e = error_of(&bytes);
        assert!(
            e.contains("3D/Objects/object_16.model: the model parts read so far and this one decompress to more than 16777216 bytes together, the limit for a package of this size (a zip bomb?)"),
            "{e}"
        );
        // 15 of them read.
        let root = production_model(
            &path_components_object(2, &components[..15]),
            &item(2, IDENTITY_TEXT),
        );
        let m = parse_3mf(&bambu(&root, &parts[..15]), "p.3mf").unwrap();
        assert_eq!(m.triangles.len(), 15 * 12);
    }

    #[test]
    fn cycles_depth_and_instancing_bombs_are_refused() {
        let cube = mesh_object(1, "model", &unit_cube());
        let cycle = model(
            &(cube.clone()
                + &components_object(2, &[(3, IDENTITY_TEXT)])
                + &components_object(3, &[(1, IDENTITY_TEXT), (2, IDENTITY_TEXT)])),
            &item(2, IDENTITY_TEXT),
        );
        let e = error_of(&simple(&cycle));
        assert!(e.contains("component cycle: object 2 -> 3 -> 2"), "{e}");
        let selfish = model(
            &(cube.clone() + &components_object(2, &[(2, IDENTITY_TEXT)])),
            &item(2, IDENTITY_TEXT),
        );
        let e = error_of(&simple(&selfish));
        assert!(e.contains("line 34: component cycle: object 2 -> 2"), "{e}");
        // A chain of 40 levels.
        let mut resources = cube.clone();
        for k in 2..=41 {
            resources += &components_object(k, &[(k - 1, IDENTITY_TEXT)]);
        }
        let e = error_of(&simple(&model(&resources, &item(41, IDENTITY_TEXT))));
        assert!(
            e.contains(&format!("components nest deeper than {MAX_DEPTH} levels")),
            "{e}"
        );
        // Nor when the lower 20 levels were expanded (and memoized) first.
        let e = error_of(&simple(&model(
            &resources,
            &(item(20, IDENTITY_TEXT) + &item(40, IDENTITY_TEXT)),
        )));
        assert!(
            e.contains(&format!("components nest deeper than {MAX_DEPTH} levels")),
            "{e}"
        );
        // 31 levels read.
        let m = parse_3mf(
            &simple(&model(&resources, &item(32, IDENTITY_TEXT))),
            "d.3mf",
        )
        .unwrap();
        assert_eq!(m.triangles.len(), 12);
        // Ten copies at each of 8 levels: 10^8 cubes from a 4 KB model,
        // refused before anything is expanded.
        let mut resources = cube.clone();
        for k in 2..=9 {
            let copies: Vec<(u32, &str)> = (0..10).map(|_| (k - 1, IDENTITY_TEXT)).collect();
            resources += &components_object(k, &copies);
        }
        let e = error_of(&simple(&model(&resources, &item(9, IDENTITY_TEXT))));
        assert!(
            e.contains("the build items expand through their components to 800000000 vertices and 1200000000 triangles, past the budget of 16777216 and 16777216 (the file spells out 8 and 12)"),
            "{e}"
        );
        // Three levels (12,000 triangles) read.
        let m = parse_3mf(
            &simple(&model(&resources, &item(4, IDENTITY_TEXT))),
            "i.3mf",
        )
        .unwrap();
        assert_eq!(m.triangles.len(), 12_000);
        // Transforms whose composition overflows.
        let big = model(
            &(cube + &components_object(2, &[(1, "1e200 0 0 0 1 0 0 0 1 0 0 0")])),
            &item(2, "1e200 0 0 0 1 0 0 0 1 0 0 0"),
        );
        let e = error_of(&simple(&big));
        assert!(
            e.contains("line 34: the transforms composed down to here overflow f64"),
            "{e}"
        );
    }

    #[test]
    fn a_zip_bomb_is_refused() {
        // 17 MiB of white space in the model part: a package of about
        // 17 KB, so the cap is the floor of 16 MiB.
        let mut zip = ZipWriter::new(Cursor::new(Vec::new()));
        let options = SimpleFileOptions::default().compression_method(CompressionMethod::Deflated);
        zip.start_file("3D/3dmodel.model", options).unwrap();
        let chunk = vec![b' '; 1 << 20];
        for _ in 0..17 {
            zip.write_all(&chunk).unwrap();
        }
        let bytes = zip.finish().unwrap().into_inner();
        assert!(bytes.len() < 100_000, "{}", bytes.len());
        let e = error_of(&bytes);
        assert!(
            e.contains("3D/3dmodel.model: the part decompresses to more than 16777216 bytes, the limit for a package of this size (a zip bomb?)"),
            "{e}"
        );
        assert_eq!(part_cap(0), PART_FLOOR);
        assert_eq!(part_cap(1 << 20), 64 << 20);
        assert_eq!(part_cap(usize::MAX), PART_CEILING);
    }

    #[test]
    fn non_finite_coordinates_are_kept_unless_validated() {
        let cube = unit_cube();
        let xml = model(&mesh_object(1, "model", &cube), &item(1, IDENTITY_TEXT))
            .replacen("x=\"0.0\"", "x=\"NaN\"", 1)
            .replacen("y=\"1.0\"", "y=\"-inf\"", 1);
        let bytes = simple(&xml);
        let m = parse_3mf(&bytes, "n.3mf").unwrap();
        assert!(m.vertices[0][0].is_nan());
        assert_eq!(m.vertices[2][1], f64::NEG_INFINITY);
        let e = read_3mf_bytes(&bytes, "n.3mf", MeshReadOptions::default(), true)
            .unwrap_err()
            .to_string();
        assert!(
            e.contains("vertex 0 (line 7): x coordinate NaN is not finite"),
            "{e}"
        );
        let keep = MeshReadOptions {
            validate_coordinates: false,
        };
        let m = read_3mf_bytes(&bytes, "n.3mf", keep, false).unwrap();
        assert!(m.vertices[0][0].is_nan());
    }

    #[test]
    fn closure_violations_name_the_triangle_and_its_line() {
        let mut cube = unit_cube();
        cube.triangles.pop();
        let bytes = simple(&model(
            &mesh_object(1, "model", &cube),
            &item(1, IDENTITY_TEXT),
        ));
        parse_3mf(&bytes, "o.3mf").unwrap();
        let e = read_3mf_bytes(&bytes, "o.3mf", MeshReadOptions::default(), true)
            .unwrap_err()
            .to_string();
        assert!(
            e.starts_with(
                "o.3mf: invalid shape: shape boundary closure violated: the edge from vertex"
            ) && e.contains("(line "),
            "{e}"
        );
        // A repeated index is kept as read.
        let xml = model(
            &mesh_object(1, "model", &unit_cube()),
            &item(1, IDENTITY_TEXT),
        )
        .replacen("v2=\"2\"", "v2=\"0\"", 1);
        let m = parse_3mf(&simple(&xml), "r.3mf").unwrap();
        assert_eq!(m.triangles[0], [0, 0, 3]);
        let e = read_3mf_bytes(&simple(&xml), "r.3mf", MeshReadOptions::default(), true)
            .unwrap_err()
            .to_string();
        assert!(e.contains("(line "), "{e}");
    }

    #[test]
    fn a_model_without_triangles_is_the_empty_mesh() {
        for (resources, build) in [
            (String::new(), String::new()),
            (components_object(1, &[]), item(1, IDENTITY_TEXT)),
            (
                mesh_object(1, "model", &TriangleMesh::default()),
                item(1, IDENTITY_TEXT),
            ),
            (mesh_object(1, "model", &unit_cube()), String::new()),
        ] {
            let bytes = simple(&model(&resources, &build));
            assert_eq!(parse_3mf(&bytes, "e.3mf").unwrap(), TriangleMesh::default());
            read_3mf_bytes(&bytes, "e.3mf", MeshReadOptions::default(), true).unwrap();
        }
    }

    /// A fixture of `tests/data/3mf` (see its README for who wrote it).
    fn fixture(name: &str) -> TriangleMesh {
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("tests/data/3mf")
            .join(name);
        let bytes = std::fs::read(&path).unwrap();
        let polygons = read_3mf_bytes(&bytes, name, MeshReadOptions::default(), true).unwrap();
        polygons.check_topology().unwrap();
        parse_3mf(&bytes, name).unwrap()
    }

    fn assert_close(got: f64, want: f64, what: &str) {
        assert!(
            (got - want).abs() <= 1e-9 * want.abs().max(1.0),
            "{what}: {got} != {want}"
        );
    }

    #[test]
    fn files_written_by_lib3mf_and_trimesh_read_as_they_measured() {
        // Figures of README.md: trimesh's reading of each file.
        let cases: [(&str, usize, f64, [[f64; 3]; 2]); 3] = [
            (
                "lib3mf_components.3mf",
                36,
                6.0,
                [[-3.0, 0.0, 0.0], [7.0, 22.0, 11.0]],
            ),
            (
                "trimesh_icosphere.3mf",
                320,
                13.658775794928614,
                [[-1.5; 3], [1.5; 3]],
            ),
            (
                "trimesh_scene.3mf",
                60,
                12.0,
                [[-1.0, -1.0, -1.5], [10.5, 6.0, 1.5]],
            ),
        ];
        for (name, triangles, want_volume, want_bounds) in cases {
            let m = fixture(name);
            assert_eq!(m.triangles.len(), triangles, "{name}");
            assert_close(volume(&m), want_volume, name);
            let b = bounds(&m);
            for k in 0..3 {
                assert_close(b[0][k], want_bounds[0][k], name);
                assert_close(b[1][k], want_bounds[1][k], name);
            }
        }
    }

    #[test]
    fn a_production_package_written_by_lib3mf_reads_as_lib3mf_measured() {
        // Figures of README.md: lib3mf's own reading of the file (trimesh
        // reads a part named twice twice over).
        let name = "lib3mf_production.3mf";
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("tests/data/3mf")
            .join(name);
        let bytes = std::fs::read(&path).unwrap();
        // Its meshes are in other parts, named by paths on components and
        // on a build item.
        let archive = ZipArchive::new(Cursor::new(&bytes[..])).unwrap();
        let names: Vec<String> = archive
            .file_names()
            .map(|n| n.unwrap().to_string())
            .collect();
        for part in ["3D/Objects/object_1.model", "3D/Objects/object_2.model"] {
            assert!(names.iter().any(|n| n == part), "{names:?}");
        }
        let m = fixture(name);
        assert_eq!(m.triangles.len(), 32);
        assert_close(volume(&m), 5.166666666666667, name);
        let b = bounds(&m);
        let want = [[-3.0, 0.0, 0.0], [21.0, 6.0, 16.0]];
        for k in 0..3 {
            assert_close(b[0][k], want[0][k], name);
            assert_close(b[1][k], want[1][k], name);
        }
    }

    /// `bytes` with `edits` applied: each `(position, value, kind)` sets,
    /// inserts or removes a byte.
    fn mutate(bytes: &[u8], edits: &[(usize, u8, u8)]) -> Vec<u8> {
        let mut out = bytes.to_vec();
        for &(at, value, kind) in edits {
            if out.is_empty() {
                out.push(value);
                continue;
            }
            let at = at % out.len();
            match kind % 3 {
                0 => out[at] = value,
                1 => out.insert(at, value),
                _ => {
                    out.remove(at);
                }
            }
        }
        out
    }

    /// A stored (uncompressed) package of `model`, so that mutations of
    /// the XML text survive.
    fn stored(model: &[u8]) -> Vec<u8> {
        let mut zip = ZipWriter::new(Cursor::new(Vec::new()));
        let options = SimpleFileOptions::default().compression_method(CompressionMethod::Stored);
        zip.start_file("3D/3dmodel.model", options).unwrap();
        zip.write_all(model).unwrap();
        zip.finish().unwrap().into_inner()
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(test_support::cases(256)))]

        #[test]
        fn random_bytes_never_panic(bytes in proptest::collection::vec(any::<u8>(), 0..600)) {
            let _ = parse_3mf(&bytes, "r.3mf");
            let mut zipped = b"PK\x03\x04".to_vec();
            zipped.extend_from_slice(&bytes);
            let _ = parse_3mf(&zipped, "r.3mf");
        }

        #[test]
        fn mutated_packages_never_panic(
            edits in proptest::collection::vec((any::<usize>(), any::<u8>(), any::<u8>()), 1..8),
            text_edits in proptest::collection::vec((any::<usize>(), any::<u8>(), any::<u8>()), 1..8),
        ) {
            let cube = unit_cube();
            let xml = model(
                &(mesh_object(1, "model", &cube) + &components_object(2, &[(1, "-1 0 0 0 1 0 0 0 1 0 0 0"), (1, IDENTITY_TEXT)])),
                &(item(2, IDENTITY_TEXT) + &item(1, "1 0 0 0 1 0 0 0 1 0 0 3")),
            );
            let good = simple(&xml);
            let _ = read_3mf_bytes(&mutate(&good, &edits), "m.3mf", MeshReadOptions::default(), true);
            let text = mutate(xml.as_bytes(), &text_edits);
            let _ = read_3mf_bytes(&stored(&text), "m.3mf", MeshReadOptions::default(), true);
            // A Bambu-style package: its bytes, its root's text and its
            // object part's text mutated.
            let root = production_model(
                &path_components_object(2, &[(OBJECT_PART, 1, "-1 0 0 0 1 0 0 0 1 0 0 0"), (OBJECT_PART, 1, IDENTITY_TEXT)]),
                &(item(2, IDENTITY_TEXT) + &item(1, IDENTITY_TEXT).replace("<item ", &format!("<item p:path=\"{OBJECT_PART}\" "))),
            );
            let part = production_model(&mesh_object(1, "model", &cube), "");
            let _ = read_3mf_bytes(&mutate(&bambu(&root, &[(OBJECT_PART, &part)]), &edits), "b.3mf", MeshReadOptions::default(), true);
            let mutated_root = String::from_utf8_lossy(&mutate(root.as_bytes(), &text_edits)).into_owned();
            let _ = read_3mf_bytes(&bambu(&mutated_root, &[(OBJECT_PART, &part)]), "b.3mf", MeshReadOptions::default(), true);
            let mutated_part = String::from_utf8_lossy(&mutate(part.as_bytes(), &text_edits)).into_owned();
            let _ = read_3mf_bytes(&bambu(&root, &[(OBJECT_PART, &mutated_part)]), "b.3mf", MeshReadOptions::default(), true);
        }
    }
}
