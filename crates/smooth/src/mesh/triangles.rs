//! The triangle-mesh variant of 3D smoothing: the triangles are smoothed
//! as a polygon mesh and every facet smoothing changed (no longer one
//! loop of three half-edges) is re-triangulated by internal edges only,
//! by the rules of section 4.8 (`topology::triangulate_facet`), so the
//! output stays a triangle mesh satisfying shape boundary closure.

use crate::mesh::run;
use crate::{SmoothError, SmoothOptions, Smoothed};
use topology::{triangulate_facet, TriangleMesh};

/// Smooths a triangle mesh ([`crate::smooth_mesh`] on its triangles) and
/// re-triangulates the facets smoothing changed (section 4.8), counting
/// them in `facets_retriangulated`. The input is validated first and
/// never modified; the result satisfies [`crate::sanity_check_triangles`].
pub fn smooth_triangles(
    mesh: &TriangleMesh,
    options: &SmoothOptions,
) -> Result<Smoothed<TriangleMesh>, SmoothError> {
    options.validate()?;
    mesh.check_topology()?;
    mesh.validate_coordinates()?;
    let (poly, mut report) = run(&mesh.to_polygon_mesh(), options)?;
    let mut triangles = Vec::with_capacity(poly.facets.len());
    let mut pairs = Vec::new();
    for f in &poly.facets {
        let h = &f.half_edges;
        if h.len() == 3
            && h[0].end == h[1].start
            && h[1].end == h[2].start
            && h[2].end == h[0].start
        {
            triangles.push([h[0].start, h[1].start, h[2].start]);
            continue;
        }
        pairs.clear();
        pairs.extend(h.iter().map(|h| (h.start, h.end)));
        triangulate_facet(&poly.vertices, &pairs, &mut triangles);
        report.counts.facets_retriangulated += 1;
    }
    // A triangle repeating a vertex holds a zero-length half-edge and a
    // half-edge with its reverse: dropping it keeps shape closure.
    triangles.retain(|t| t[0] != t[1] && t[1] != t[2] && t[2] != t[0]);
    // Vertices only such triangles used are dropped too.
    let mut used = vec![false; poly.vertices.len()];
    for &v in triangles.iter().flatten() {
        used[v as usize] = true;
    }
    let mut map = vec![0u32; poly.vertices.len()];
    let mut vertices = Vec::with_capacity(poly.vertices.len());
    for (i, &u) in used.iter().enumerate() {
        if u {
            map[i] = vertices.len() as u32;
            vertices.push(poly.vertices[i]);
        } else {
            report.counts.unreferenced_vertices_removed += 1;
        }
    }
    for t in &mut triangles {
        *t = t.map(|v| map[v as usize]);
    }
    let shape = TriangleMesh::new(vertices, triangles);
    #[cfg(debug_assertions)]
    crate::sanity_check_triangles(&shape, options.tolerance)?;
    Ok(Smoothed { shape, report })
}
