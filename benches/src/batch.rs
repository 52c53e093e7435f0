//! N-ary 3D Booleans (issue 13): the union of many overlapping spheres and
//! a slab minus many boxes, each in one call, on Umbra's
//! `union_all_solids` / `difference_all_solids` (a balanced tree of binary
//! Booleans in parallel, both variants) beside the peers' batch
//! operations: `manifold-rust` 0.19, the union by rayon's parallel
//! `reduce_with` over `Manifold::union` (the port's own
//! `Manifold::batch_boolean` is a left fold, slower by far: the
//! `manifold-rust-fold` peer) and the slab as one `difference` with
//! `Manifold::compose` of the disjoint boxes, and
//! `boolmesh` 0.2, which has no batch operation, with rayon's parallel
//! `reduce_with` over `compute_boolean` (a tree of the same kind as
//! Umbra's). Conversions into each library's types are not timed.

use crate::solid::{boolmesh_of, boolmesh_stats, manifold_of, manifold_stats, SolidStats};
use boolmesh::prelude::{compute_boolean, Manifold as Boolmesh, OpType as BoolmeshOp};
use manifold_rust::manifold::Manifold;
use manifold_rust::types::OpType;
use rayon::prelude::*;
use test_support::rng::SplitMix64;
use test_support::shapes::{box_triangles, uv_sphere};
use topology::{PolygonMesh, TriangleMesh};
use umbra::{difference_all_solids, union_all_solids, MeshVariant};

/// The operands of a batch row.
#[derive(Clone, Debug)]
pub struct BatchCase {
    /// Row label.
    pub label: String,
    /// `Some(a)` for `a` minus all of `operands`, `None` for the union of
    /// `operands`.
    pub minuend: Option<TriangleMesh>,
    /// The operands (the union's, or those subtracted).
    pub operands: Vec<TriangleMesh>,
    /// The exact volume of the result when known (the slab: the boxes are
    /// disjoint and go through it).
    pub exact_volume: Option<f64>,
}

impl BatchCase {
    /// Input triangles over all operands.
    pub fn input_triangles(&self) -> usize {
        self.minuend
            .iter()
            .chain(&self.operands)
            .map(|m| m.triangles.len())
            .sum()
    }
}

/// `count` UV spheres of radius 0.6 with `slices` x `slices / 2` facets
/// (`2 slices (slices / 2 - 1)` triangles each) on a cubic grid of pitch 1
/// (`ceil(cbrt(count))` per side), each centre moved by up to 0.15 along
/// each axis (seeded), so that every sphere overlaps its neighbours and no
/// two meet in a symmetric way.
pub fn sphere_union_case(count: usize, slices: u32) -> BatchCase {
    let side = (1..).find(|k: &usize| k * k * k >= count).unwrap_or(1);
    let mut rng = SplitMix64::new(0x5eed_0001);
    let operands = (0..count)
        .map(|k| {
            let (i, j, l) = (k % side, (k / side) % side, k / (side * side));
            let c = [
                i as f64 + 0.3 * (rng.unit() - 0.5),
                j as f64 + 0.3 * (rng.unit() - 0.5),
                l as f64 + 0.3 * (rng.unit() - 0.5),
            ];
            uv_sphere(c, 0.6, slices, (slices / 2).max(2))
        })
        .collect();
    BatchCase {
        label: format!("union of {count} spheres ({slices} slices)"),
        minuend: None,
        operands,
        exact_volume: None,
    }
}

/// The slab `nx x ny x 1` minus `nx * ny` boxes of `0.5 x 0.5 x 2`, one
/// centred in each unit cell and through the slab: exact volume
/// `nx ny (1 - 0.25)`. The row is `nx = 40, ny = 25`.
pub fn slab_case(nx: usize, ny: usize) -> BatchCase {
    let slab = box_triangles([0.0; 3], [nx as f64, ny as f64, 1.0]);
    let operands = (0..nx * ny)
        .map(|k| {
            let (i, j) = ((k % nx) as f64, (k / nx) as f64);
            box_triangles([i + 0.25, j + 0.25, -0.5], [i + 0.75, j + 0.75, 1.5])
        })
        .collect();
    BatchCase {
        label: format!("slab {nx}x{ny}x1 minus {} boxes", nx * ny),
        minuend: Some(slab),
        operands,
        exact_volume: Some((nx * ny) as f64 * 0.75),
    }
}

/// A library's batch operation: `prepare` converts (not timed), `run`
/// computes the row (timed), `stats` reads the result.
pub trait BatchPeer {
    /// Prepared operands.
    type Input;
    /// Native result.
    type Output;
    /// A short name.
    fn name(&self) -> &'static str;
    /// Converts the operands; `None` when the library refuses them.
    fn prepare(&self, case: &BatchCase) -> Option<Self::Input>;
    /// Runs the batch operation.
    fn run(&self, input: &Self::Input) -> Self::Output;
    /// Facets, volume and validity of the result.
    fn stats(&self, out: &Self::Output) -> SolidStats;
}

/// Umbra's `union_all_solids` / `difference_all_solids` in one variant.
#[derive(Clone, Copy, Debug)]
pub struct UmbraBatch(pub MeshVariant);

impl BatchPeer for UmbraBatch {
    type Input = (Option<PolygonMesh>, Vec<PolygonMesh>);
    type Output = Option<PolygonMesh>;
    fn name(&self) -> &'static str {
        match self.0 {
            MeshVariant::PolygonMesh => "umbra-poly",
            MeshVariant::TriangleMesh => "umbra-tri",
        }
    }
    fn prepare(&self, case: &BatchCase) -> Option<Self::Input> {
        Some((
            case.minuend.as_ref().map(TriangleMesh::to_polygon_mesh),
            case.operands
                .iter()
                .map(TriangleMesh::to_polygon_mesh)
                .collect(),
        ))
    }
    fn run(&self, input: &Self::Input) -> Self::Output {
        let out = match &input.0 {
            Some(a) => difference_all_solids(a, &input.1, self.0),
            None => union_all_solids(&input.1, self.0),
        };
        out.ok().map(|o| o.mesh)
    }
    fn stats(&self, out: &Self::Output) -> SolidStats {
        out.as_ref().map_or(SolidStats::FAILED, SolidStats::of_mesh)
    }
}

/// `manifold-rust` 0.19: the union by rayon's parallel `reduce_with` over
/// `Manifold::union`, or with `fold` by the port's
/// `Manifold::batch_boolean(_, Add)` (a left fold); the difference as
/// `a.difference(&Manifold::compose(bs))` (valid here: the boxes are
/// disjoint, which is what the C++ Manifold's batch union exploits).
#[derive(Clone, Copy, Debug, Default)]
pub struct ManifoldRustBatch {
    /// Unite by `batch_boolean` (a left fold) instead of a parallel tree.
    pub fold: bool,
}

impl BatchPeer for ManifoldRustBatch {
    type Input = (Option<Manifold>, Vec<Manifold>);
    type Output = Manifold;
    fn name(&self) -> &'static str {
        if self.fold {
            "manifold-rust-fold"
        } else {
            "manifold-rust"
        }
    }
    fn prepare(&self, case: &BatchCase) -> Option<Self::Input> {
        Some((
            case.minuend.as_ref().map(manifold_of),
            case.operands.iter().map(manifold_of).collect(),
        ))
    }
    fn run(&self, input: &Self::Input) -> Self::Output {
        let out = match &input.0 {
            Some(a) => a.difference(&Manifold::compose(&input.1)),
            None if self.fold => Manifold::batch_boolean(&input.1, OpType::Add),
            None => input
                .1
                .par_iter()
                .cloned()
                .reduce_with(|a, b| a.union(&b))
                .unwrap_or_else(Manifold::empty),
        };
        std::hint::black_box(out.num_tri());
        out
    }
    fn stats(&self, out: &Self::Output) -> SolidStats {
        manifold_stats(out)
    }
}

/// `boolmesh` 0.2 (feature `rayon`): the operands united by rayon's
/// parallel `reduce_with` over `compute_boolean(_, _, Add)`, then, for the
/// slab, one `Subtract`.
#[derive(Clone, Copy, Debug, Default)]
pub struct BoolmeshBatch;

impl BatchPeer for BoolmeshBatch {
    type Input = (Option<Boolmesh>, Vec<Boolmesh>);
    type Output = Option<Boolmesh>;
    fn name(&self) -> &'static str {
        "boolmesh"
    }
    fn prepare(&self, case: &BatchCase) -> Option<Self::Input> {
        let minuend = match &case.minuend {
            Some(a) => Some(boolmesh_of(a).ok()?),
            None => None,
        };
        let operands = case
            .operands
            .iter()
            .map(|m| boolmesh_of(m).ok())
            .collect::<Option<Vec<_>>>()?;
        Some((minuend, operands))
    }
    fn run(&self, input: &Self::Input) -> Self::Output {
        let union = input
            .1
            .par_iter()
            .map(|m| Some(m.clone()))
            .reduce_with(|a, b| compute_boolean(&a?, &b?, BoolmeshOp::Add).ok())??;
        match &input.0 {
            Some(a) => compute_boolean(a, &union, BoolmeshOp::Subtract).ok(),
            None => Some(union),
        }
    }
    fn stats(&self, out: &Self::Output) -> SolidStats {
        out.as_ref().map_or(SolidStats::FAILED, boolmesh_stats)
    }
}
