//! Welding of triangle soups by exact position, shared by the readers of
//! formats that repeat or split corners (STL repeats every corner; glTF
//! exporters split vertices at normal and texture seams): two corners are
//! the same vertex when their coordinates are equal as numbers, bit for
//! bit, except that `-0.0` and `0.0` are the same coordinate (they compare
//! equal, and exporters write either on the two sides of one edge); the
//! vertex keeps the first spelling read and the place it was first read
//! at.

use super::origin::Origins;
use robust_arith::Point3;
use std::collections::HashMap;
use topology::TriangleMesh;

/// Welds triangle corners by exact position (see the module docs); the
/// place of a vertex is that of the first triangle naming it.
pub(crate) struct Welder {
    index: HashMap<[u64; 3], u32>,
    pub(crate) vertices: Vec<Point3>,
    pub(crate) triangles: Vec<[u32; 3]>,
    pub(crate) origins: Origins,
}

impl Welder {
    pub(crate) fn new(capacity: usize, place_word: &'static str) -> Self {
        Welder {
            index: HashMap::with_capacity(capacity),
            vertices: Vec::with_capacity(capacity),
            triangles: Vec::with_capacity(capacity),
            origins: Origins::new(0, "triangle", place_word),
        }
    }

    pub(crate) fn vertex(&mut self, p: Point3, place: u32) -> u32 {
        // Adding 0.0 turns -0.0 into 0.0 and leaves every other value
        // (NaN payloads included) as it is.
        let key = [
            (p[0] + 0.0).to_bits(),
            (p[1] + 0.0).to_bits(),
            (p[2] + 0.0).to_bits(),
        ];
        let next = self.vertices.len() as u32;
        let v = *self.index.entry(key).or_insert(next);
        if v == next {
            self.vertices.push(p);
            self.origins.vertex_places.push(place);
        }
        v
    }

    pub(crate) fn triangle(&mut self, corners: [Point3; 3], place: u32) {
        let t = corners.map(|p| self.vertex(p, place));
        self.triangles.push(t);
        self.origins.face_places.push(place);
    }
}

/// The mesh a reader that welds (STL, glTF) makes of `mesh`'s triangles
/// written in order: corners welded by exact position, unreferenced
/// vertices gone. A corner naming no vertex is skipped with its triangle
/// (no writer writes one).
pub(crate) fn welded(mesh: &TriangleMesh) -> TriangleMesh {
    let mut welder = Welder::new(mesh.vertices.len(), "triangle");
    for (place, t) in mesh.triangles.iter().enumerate() {
        let [Some(&a), Some(&b), Some(&c)] = t.map(|v| mesh.vertices.get(v as usize)) else {
            continue;
        };
        welder.triangle([a, b, c], u32::try_from(place).unwrap_or(u32::MAX));
    }
    TriangleMesh::new(welder.vertices, welder.triangles)
}
