//! The invariant checker of 3D smoothing, in the manner of the
//! `sanity_check` of spatial-index crates: the closure constraints of
//! section 4.2 (through `check_topology`), valid coordinates, and the
//! postconditions smoothing guarantees (no zero-length half-edge, no empty
//! facet, no unreferenced vertex, no opposing half-edge pair inside a
//! facet, no two vertices within the tolerance). Tests, `xtask` and the
//! fuzz target call it on results; debug builds run the closure part after
//! every pass.

use crate::{merge_vertices, SmoothError};
use topology::{PolygonMesh, TriangleMesh};

fn fail(what: String) -> Result<(), SmoothError> {
    Err(SmoothError::Internal(what))
}

fn vertices_apart(vertices: &[[f64; 3]], tolerance: f64) -> Result<(), SmoothError> {
    // At magnitudes beyond 2^200 squared distances overflow: check at the
    // power-of-two scale smoothing itself works at there.
    let m = match crate::mesh::range_scale(vertices, tolerance) {
        None => merge_vertices(vertices, tolerance),
        Some((down, _)) => {
            let scaled: Vec<[f64; 3]> = vertices.iter().map(|p| p.map(|x| x * down)).collect();
            merge_vertices(&scaled, crate::mesh::scaled_tolerance(tolerance, down))
        }
    };
    if let Some((i, &r)) = m
        .representative
        .iter()
        .enumerate()
        .find(|&(i, &r)| r as usize != i)
    {
        return fail(format!(
            "vertices {r} and {i} lie within the tolerance {tolerance} of each other"
        ));
    }
    Ok(())
}

fn all_referenced(n: usize, used: impl Iterator<Item = u32>) -> Result<(), SmoothError> {
    let mut seen = vec![false; n];
    for v in used {
        seen[v as usize] = true;
    }
    match seen.iter().position(|&s| !s) {
        Some(v) => fail(format!("vertex {v} is referenced by no half-edge")),
        None => Ok(()),
    }
}

/// Checks that `mesh` is what [`crate::smooth_mesh`] at `tolerance`
/// guarantees: topologically valid (facet and shape boundary closure, no
/// dangling index), valid coordinates, no empty facet, no zero-length
/// half-edge, no facet holding a half-edge and its reverse, no
/// unreferenced vertex, and no two vertices within `tolerance`. A
/// failure on a smoothing result is a bug ([`SmoothError::Internal`],
/// naming the entity).
///
/// ```
/// use topology::{Facet, PolygonMesh};
/// let v = vec![[0.0; 3], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
/// let loops = [[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2]];
/// let tetra = PolygonMesh::new(v, loops.iter().map(|l| Facet::from_loop(l)).collect());
/// assert!(smooth::sanity_check_mesh(&tetra, 1e-6).is_ok());
/// assert!(smooth::sanity_check_mesh(&tetra, 2.0).is_err()); // vertices within 2
/// ```
pub fn sanity_check_mesh(mesh: &PolygonMesh, tolerance: f64) -> Result<(), SmoothError> {
    mesh.check_topology()
        .map_err(|e| SmoothError::Internal(format!("closure: {e}")))?;
    mesh.validate_coordinates()
        .map_err(|e| SmoothError::Internal(format!("coordinates: {e}")))?;
    for (fi, f) in mesh.facets.iter().enumerate() {
        if f.half_edges.is_empty() {
            return fail(format!("facet {fi} is empty"));
        }
        for (k, h) in f.half_edges.iter().enumerate() {
            if h.start == h.end {
                return fail(format!(
                    "facet {fi} has a zero-length half-edge at {}",
                    h.start
                ));
            }
            if f.half_edges[k + 1..]
                .iter()
                .any(|g| g.start == h.end && g.end == h.start)
            {
                return fail(format!(
                    "facet {fi} holds opposing half-edges {} -> {} and back",
                    h.start, h.end
                ));
            }
        }
    }
    all_referenced(
        mesh.vertices.len(),
        mesh.facets
            .iter()
            .flat_map(|f| &f.half_edges)
            .map(|h| h.start),
    )?;
    vertices_apart(&mesh.vertices, tolerance)
}

/// [`sanity_check_mesh`] for the results of [`crate::smooth_triangles`]:
/// topologically valid, valid coordinates, no triangle repeating a
/// vertex, no unreferenced vertex, no two vertices within `tolerance`.
pub fn sanity_check_triangles(mesh: &TriangleMesh, tolerance: f64) -> Result<(), SmoothError> {
    mesh.check_topology()
        .map_err(|e| SmoothError::Internal(format!("closure: {e}")))?;
    mesh.validate_coordinates()
        .map_err(|e| SmoothError::Internal(format!("coordinates: {e}")))?;
    if let Some(ti) = mesh
        .triangles
        .iter()
        .position(|t| t[0] == t[1] || t[1] == t[2] || t[2] == t[0])
    {
        return fail(format!("triangle {ti} repeats a vertex"));
    }
    all_referenced(
        mesh.vertices.len(),
        mesh.triangles.iter().flatten().copied(),
    )?;
    vertices_apart(&mesh.vertices, tolerance)
}
