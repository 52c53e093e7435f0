//! Iterated CSG (issue 13): a 40 x 25 x 1 slab carved by up to 1,000
//! boxes of 0.5 x 0.5 x 2, one difference at a time, each result feeding
//! the next, through the facade's `boolean_solid` in either mesh variant.
//!
//! The boxes stand on a 40 x 25 grid of unit cells, one per cell, centred
//! in the cell up to a deterministic jitter of at most 3/16 in x and y (a
//! multiple of 1/64, so every coordinate is a dyadic rational and the
//! volume after `k` boxes is exactly `1000 - k / 4`). They reach through
//! the slab (z from -0.5 to 1.5) and touch neither each other nor the
//! slab's sides. Boxes come column by column (x outer, y inner).

use std::time::Instant;
use test_support::rng::SplitMix64;
use test_support::shapes::box_mesh;
use umbra::{boolean_solid, mesh_signed_volume, BooleanOp, MeshVariant, PolygonMesh};

/// The slab `[0, 40] x [0, 25] x [0, 1]` (6 quadrilaterals).
pub fn slab() -> PolygonMesh {
    box_mesh([0.0, 0.0, 0.0], [40.0, 25.0, 1.0])
}

/// The largest number of boxes [`holes`] lays out (one per grid cell).
pub const MAX_BOXES: usize = 1000;

/// The first `n` of the chain's boxes (at most [`MAX_BOXES`]), each as 6
/// quadrilaterals.
pub fn holes(n: usize) -> Vec<PolygonMesh> {
    let mut rng = SplitMix64::new(0x5eed_51ab);
    (0..n.min(MAX_BOXES))
        .map(|k| {
            let (i, j) = ((k / 25) as f64, (k % 25) as f64);
            let jx = rng.range(-12, 12) as f64 / 64.0;
            let jy = rng.range(-12, 12) as f64 / 64.0;
            let (x, y) = (i + 0.25 + jx, j + 0.25 + jy);
            box_mesh([x, y, -0.5], [x + 0.5, y + 0.5, 1.5])
        })
        .collect()
}

/// The exact volume of the slab minus its first `k` boxes.
pub fn expected_volume(k: usize) -> f64 {
    1000.0 - 0.25 * k as f64
}

/// One step of the chain as measured.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ChainStep {
    /// The number of boxes subtracted so far (1-based).
    pub step: usize,
    /// Wall time of this difference alone (milliseconds).
    pub ms: f64,
    /// Facets of the result (triangles for the triangle-mesh variant).
    pub facets: usize,
    /// Vertices referenced by the result's facets.
    pub vertices: usize,
    /// The result's signed volume.
    pub volume: f64,
}

/// Runs the chain of `n` differences in `variant`, calling `on_step` after
/// each with its measurements and the result; returns the final mesh.
/// The volume is computed outside the timing.
pub fn run_chain(
    variant: MeshVariant,
    n: usize,
    mut on_step: impl FnMut(&ChainStep, &PolygonMesh),
) -> Result<PolygonMesh, umbra::Boolean3Error> {
    let mut shape = slab();
    for (k, hole) in holes(n).iter().enumerate() {
        let t = Instant::now();
        let out = boolean_solid(&shape, hole, BooleanOp::Difference, variant)?;
        let ms = t.elapsed().as_secs_f64() * 1e3;
        shape = out.mesh;
        let mut used = vec![false; shape.vertices.len()];
        for f in &shape.facets {
            for h in &f.half_edges {
                used[h.start as usize] = true;
            }
        }
        let step = ChainStep {
            step: k + 1,
            ms,
            facets: shape.facets.len(),
            vertices: used.iter().filter(|&&u| u).count(),
            volume: mesh_signed_volume(&shape),
        };
        on_step(&step, &shape);
    }
    Ok(shape)
}

/// The chain on triangle meshes straight through
/// `boolean_3d::boolean_triangles` (STL in, STL out, no conversion to
/// polygon meshes between steps): returns the summed time (milliseconds)
/// and the final mesh.
pub fn run_chain_triangles(
    n: usize,
) -> Result<(f64, topology::TriangleMesh), boolean_3d::Boolean3Error> {
    let mut shape = boolean_3d::triangulate_mesh(&slab());
    let mut total = 0.0;
    for hole in holes(n) {
        let hole = boolean_3d::triangulate_mesh(&hole);
        let t = Instant::now();
        let out = boolean_3d::boolean_triangles(&shape, &hole, BooleanOp::Difference)?;
        total += t.elapsed().as_secs_f64() * 1e3;
        shape = out.mesh;
    }
    Ok((total, shape))
}
