//! Iterated CSG (issue 13): a 40 x 25 x 1 slab carved by up to 1,000
//! boxes of 0.5 x 0.5 x 2, one difference at a time, each result feeding
//! the next, through the facade in either mesh variant (`boolean_solid`
//! on polygon meshes, `boolean_solid_triangles` on triangle meshes).
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
use umbra::{
    boolean_solid, boolean_solid_triangles, mesh_signed_volume, triangulate_mesh, BooleanOp,
    MeshVariant, PolygonMesh, TopologyError, TriangleMesh,
};

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

/// The shape of the chain between steps, in the variant's own form: the
/// triangle-mesh variant keeps a [`TriangleMesh`] from step to step
/// (`boolean_solid_triangles`, no conversion), the polygon-mesh variant a
/// [`PolygonMesh`].
#[derive(Clone, Debug, PartialEq)]
pub enum ChainMesh {
    /// The polygon-mesh variant's shape.
    Polygons(PolygonMesh),
    /// The triangle-mesh variant's shape.
    Triangles(TriangleMesh),
}

impl ChainMesh {
    /// Facets (triangles for the triangle-mesh variant).
    pub fn facet_count(&self) -> usize {
        match self {
            ChainMesh::Polygons(m) => m.facets.len(),
            ChainMesh::Triangles(m) => m.triangles.len(),
        }
    }

    /// Vertices referenced by some facet.
    pub fn used_vertices(&self) -> usize {
        let (n, starts): (usize, Vec<u32>) = match self {
            ChainMesh::Polygons(m) => (
                m.vertices.len(),
                m.facets
                    .iter()
                    .flat_map(|f| f.half_edges.iter().map(|h| h.start))
                    .collect(),
            ),
            ChainMesh::Triangles(m) => (
                m.vertices.len(),
                m.triangles.iter().flatten().copied().collect(),
            ),
        };
        let mut used = vec![false; n];
        for v in starts {
            used[v as usize] = true;
        }
        used.iter().filter(|&&u| u).count()
    }

    /// The signed volume.
    pub fn volume(&self) -> f64 {
        match self {
            ChainMesh::Polygons(m) => mesh_signed_volume(m),
            ChainMesh::Triangles(m) => m.signed_volume(),
        }
    }

    /// Topological validity (section 4.2).
    pub fn check_topology(&self) -> Result<(), TopologyError> {
        match self {
            ChainMesh::Polygons(m) => m.check_topology(),
            ChainMesh::Triangles(m) => m.check_topology(),
        }
    }
}

/// Runs the chain of `n` differences in `variant`, calling `on_step` after
/// each with its measurements and the result; returns the final mesh.
/// The polygon-mesh variant runs `boolean_solid`, the triangle-mesh
/// variant `boolean_solid_triangles` on the triangulated slab and boxes
/// (the boxes are triangulated before the chain, outside the timing, as
/// an STL file would bring them). Counts and volume are computed outside
/// the timing.
pub fn run_chain(
    variant: MeshVariant,
    n: usize,
    mut on_step: impl FnMut(&ChainStep, &ChainMesh),
) -> Result<ChainMesh, umbra::Boolean3Error> {
    let tri = variant == MeshVariant::TriangleMesh;
    let mut shape = if tri {
        ChainMesh::Triangles(triangulate_mesh(&slab()))
    } else {
        ChainMesh::Polygons(slab())
    };
    let boxes = holes(n);
    let tri_boxes: Vec<TriangleMesh> = if tri {
        boxes.iter().map(triangulate_mesh).collect()
    } else {
        Vec::new()
    };
    for (k, hole) in boxes.iter().enumerate() {
        let t = Instant::now();
        let next = match (&shape, tri_boxes.get(k)) {
            (ChainMesh::Triangles(a), Some(b)) => {
                ChainMesh::Triangles(boolean_solid_triangles(a, b, BooleanOp::Difference)?.mesh)
            }
            (ChainMesh::Triangles(a), None) => ChainMesh::Polygons(
                boolean_solid(&a.to_polygon_mesh(), hole, BooleanOp::Difference, variant)?.mesh,
            ),
            (ChainMesh::Polygons(a), _) => {
                ChainMesh::Polygons(boolean_solid(a, hole, BooleanOp::Difference, variant)?.mesh)
            }
        };
        let ms = t.elapsed().as_secs_f64() * 1e3;
        // The previous shape is freed outside the timing, as in
        // `run_chain_triangles`.
        shape = next;
        let step = ChainStep {
            step: k + 1,
            ms,
            facets: shape.facet_count(),
            vertices: shape.used_vertices(),
            volume: shape.volume(),
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
