//! Where a mesh's vertices and faces came from in their file, so that a
//! violated constraint is reported in the file's own terms: 1-based face
//! numbers with their line or record, vertices in the file's numbering, and
//! an open edge by the positions of its two vertices.

use crate::UmbraError;
use robust_arith::Point3;
use topology::{PolygonMesh, TopologyError};

use super::mesh_text::MeshReadOptions;

/// The origin of each vertex and face of a mesh read from a file.
#[derive(Clone, Debug)]
pub(crate) struct Origins {
    /// The number the file gives its first vertex (1 for OBJ, 0 otherwise).
    pub vertex_base: u32,
    /// What the file calls a face (`"face"`, `"triangle"`).
    pub face_word: &'static str,
    /// What a place in the file is (`"line"`, `"record"`), or `""` for
    /// formats without one.
    pub place_word: &'static str,
    /// The place of each vertex (its line, or the first record naming it).
    pub vertex_places: Vec<u32>,
    /// The place of each face.
    pub face_places: Vec<u32>,
}

impl Origins {
    /// Origins with no places recorded yet.
    pub fn new(vertex_base: u32, face_word: &'static str, place_word: &'static str) -> Self {
        Origins {
            vertex_base,
            face_word,
            place_word,
            vertex_places: Vec::new(),
            face_places: Vec::new(),
        }
    }

    fn place(&self, places: &[u32], index: u32) -> String {
        match places.get(index as usize) {
            Some(p) if !self.place_word.is_empty() => format!(" ({} {p})", self.place_word),
            _ => String::new(),
        }
    }

    /// `face 3 (line 12)`, 1-based.
    fn face(&self, index: u32) -> String {
        format!(
            "{} {}{}",
            self.face_word,
            u64::from(index) + 1,
            self.place(&self.face_places, index)
        )
    }

    /// `vertex 7 (line 9)` in the file's numbering.
    fn vertex(&self, index: u32) -> String {
        format!(
            "vertex {}{}",
            u64::from(index) + u64::from(self.vertex_base),
            self.place(&self.vertex_places, index)
        )
    }
}

fn position(p: Option<&Point3>) -> String {
    match p {
        Some(p) => format!("({:?}, {:?}, {:?})", p[0], p[1], p[2]),
        None => "(?)".to_string(),
    }
}

/// The one-line description of `error` in the terms of the file.
pub(crate) fn describe(error: &TopologyError, mesh: &PolygonMesh, origins: &Origins) -> String {
    match *error {
        TopologyError::DanglingIndex {
            entity_index,
            vertex,
            vertex_count,
            ..
        } => format!(
            "dangling index: {} refers to vertex {}, but there are only {vertex_count} vertices",
            origins.face(entity_index),
            u64::from(vertex) + u64::from(origins.vertex_base),
        ),
        TopologyError::FacetClosure {
            facet,
            vertex,
            ending,
            starting,
        } => format!(
            "facet boundary closure violated in {} at {}: {ending} half-edge(s) end there but {starting} start there",
            origins.face(facet),
            origins.vertex(vertex)
        ),
        TopologyError::ShapeClosure3 {
            start,
            end,
            forward,
            backward,
        } => format!(
            "shape boundary closure violated: the edge from {} {} to {} {} has {forward} half-edge(s) one way and {backward} the other (open or inconsistently oriented mesh)",
            origins.vertex(start),
            position(mesh.vertices.get(start as usize)),
            origins.vertex(end),
            position(mesh.vertices.get(end as usize)),
        ),
        TopologyError::BadCoordinate {
            vertex,
            axis,
            ref source,
        } => {
            let name = ["x", "y", "z"].get(axis as usize).copied().unwrap_or("?");
            format!("{}: {name} {source}", origins.vertex(vertex))
        }
        ref other => other.to_string(),
    }
}

/// Refuses a file of vertices without a single face (a point cloud, an
/// OBJ of lines): [`UmbraError::Malformed`] naming the file, "no facets",
/// instead of an empty solid that would make every operation on it
/// silently empty. A file of neither vertices nor faces is the empty
/// solid, which the writers write for an empty result. (STL and glTF
/// cannot say it: their vertices are the corners of their triangles.)
pub(crate) fn refuse_vertices_alone(
    vertices: usize,
    faces: usize,
    origins: &Origins,
    file: &str,
    format: &'static str,
) -> Result<(), UmbraError> {
    if vertices == 0 || faces > 0 {
        return Ok(());
    }
    Err(UmbraError::Malformed {
        file: file.to_string(),
        format,
        message: format!(
            "no facets: {vertices} vertices but no {}s (a solid needs facets; a file of neither is the empty solid)",
            origins.face_word
        ),
    })
}

/// Validates the coordinates (if `options` asks) and checks the closure
/// constraints of section 4.2 (if `check`), reporting a violation in the
/// file's terms as [`UmbraError::InvalidMesh`].
pub(crate) fn finish(
    mesh: PolygonMesh,
    origins: &Origins,
    file: &str,
    options: MeshReadOptions,
    check: bool,
) -> Result<PolygonMesh, UmbraError> {
    let invalid = |source: TopologyError| UmbraError::InvalidMesh {
        file: file.to_string(),
        message: describe(&source, &mesh, origins),
        source,
    };
    if options.validate_coordinates {
        mesh.validate_coordinates().map_err(invalid)?;
    }
    if check {
        mesh.check_topology().map_err(invalid)?;
    }
    Ok(mesh)
}
