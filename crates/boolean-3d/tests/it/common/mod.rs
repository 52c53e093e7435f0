//! Shared helpers of the boolean-3d integration tests that need this crate
//! (rotations, the volume of a polygon mesh through its triangulation); the
//! generator, primitive meshes and oracles come from `test-support`.

#![allow(dead_code)]

use topology::PolygonMesh;

/// Rotation of `p` about the x, y and z axes by `ang` each, about `c`.
pub fn rotate(p: [f64; 3], c: [f64; 3], ang: f64) -> [f64; 3] {
    let (s, co) = ang.sin_cos();
    let mut q = [p[0] - c[0], p[1] - c[1], p[2] - c[2]];
    q = [q[0], co * q[1] - s * q[2], s * q[1] + co * q[2]];
    q = [co * q[0] + s * q[2], q[1], -s * q[0] + co * q[2]];
    q = [co * q[0] - s * q[1], s * q[0] + co * q[1], q[2]];
    [q[0] + c[0], q[1] + c[1], q[2] + c[2]]
}

/// Signed volume of a polygon mesh (triangulated by fans per loop; exact
/// enough for tests of planar facets).
pub fn volume(m: &PolygonMesh) -> f64 {
    boolean_3d::triangulate_mesh(m).signed_volume()
}
