//! N-ary 3D Booleans: the union, intersection or difference of any number
//! of solids in one call, as a balanced tree of binary Booleans whose
//! independent branches run in parallel (rayon). The tree's shape depends
//! only on the number of operands, so the output is the same bit for bit
//! whatever the thread count. The CSG evaluator reduces its n-ary nodes
//! with the same function ([`reduce_balanced`]).

use crate::ops::{as_triangle_mesh, MeshVariant};
use boolean_3d::{boolean_mesh, boolean_triangles, triangulate_mesh, Boolean3Error};
use rayon::prelude::*;
use std::borrow::Cow;
use std::fmt;
use std::ops::Range;
use std::time::Instant;
use topology::{BooleanOp, PolygonMesh, TopologyError, TriangleMesh};

/// The balanced reduction of `items` by `combine`, `None` for no items.
///
/// The tree puts the largest power of two below the count on the left
/// and recurses on both sides (for 7 items: `((0 1)(2 3))((4 5) 6)`),
/// which is the tree of combining neighbours round by round; the two sides
/// run in parallel (`rayon::join`). Every operand is combined: when both
/// sides fail, the left side's error is returned, so the error too does
/// not depend on the schedule.
pub(crate) fn reduce_balanced<T, E, F>(mut items: Vec<T>, combine: &F) -> Result<Option<T>, E>
where
    T: Send,
    E: Send,
    F: Fn(T, T) -> Result<T, E> + Sync,
{
    let n = items.len();
    if n <= 1 {
        return Ok(items.pop());
    }
    let left = if n.is_power_of_two() {
        n / 2
    } else {
        n.next_power_of_two() / 2
    };
    let right = items.split_off(left);
    let (l, r) = rayon::join(
        || reduce_balanced(items, combine),
        || reduce_balanced(right, combine),
    );
    match (l?, r?) {
        (Some(l), Some(r)) => combine(l, r).map(Some),
        (l, r) => Ok(l.or(r)),
    }
}

/// The n-ary form of `op` over `items` by the binary `boolean`: a union or
/// an intersection (or `Xor`, which the binary Boolean decides on) is the
/// balanced reduction of all items; a difference is the first item minus
/// the balanced union of the others. `None` for no items; a single item is
/// returned as it is.
pub(crate) fn reduce_op<T, E, F>(items: Vec<T>, op: BooleanOp, boolean: &F) -> Result<Option<T>, E>
where
    T: Send,
    E: Send,
    F: Fn(T, T, BooleanOp) -> Result<T, E> + Sync,
{
    match op {
        BooleanOp::Difference => {
            let mut it = items.into_iter();
            let Some(first) = it.next() else {
                return Ok(None);
            };
            let union = |a, b| boolean(a, b, BooleanOp::Union);
            match reduce_balanced(it.collect(), &union)? {
                None => Ok(Some(first)),
                Some(rest) => boolean(first, rest, BooleanOp::Difference).map(Some),
            }
        }
        BooleanOp::Union | BooleanOp::Intersection | BooleanOp::Xor => {
            reduce_balanced(items, &|a, b| boolean(a, b, op))
        }
    }
}

/// An error of an n-ary 3D Boolean ([`boolean_solids`]). Operands are
/// numbered in the order given (for [`difference_all_solids`], `a` is
/// operand 0 and `bs[i]` operand `i + 1`).
#[derive(Clone, Debug, PartialEq)]
pub enum SolidsError {
    /// An operand violates a constraint of section 4.2 or has a bad
    /// coordinate (section 8.5). Nothing was computed.
    InvalidOperand {
        /// The operand's position in the list.
        index: usize,
        /// The violated constraint and where.
        source: TopologyError,
    },
    /// The operation is not one the 3D Boolean builds (`Xor`).
    UnsupportedOperation(BooleanOp),
    /// A binary Boolean of the tree failed (a result too large for 32-bit
    /// indices, or an internal error, which is a bug).
    Boolean {
        /// The operands whose partial result the failing Boolean combined
        /// (a contiguous range of positions).
        operands: Range<usize>,
        /// The error of the 3D Boolean.
        source: Boolean3Error,
    },
}

impl fmt::Display for SolidsError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            SolidsError::InvalidOperand { index, source } => {
                write!(f, "operand {index}: {source}")
            }
            SolidsError::UnsupportedOperation(op) => write!(
                f,
                "the 3D Boolean supports union, intersection and difference, not {op}"
            ),
            SolidsError::Boolean { operands, source } => write!(
                f,
                "the Boolean of operands {}..{}: {source}",
                operands.start, operands.end
            ),
        }
    }
}

impl std::error::Error for SolidsError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            SolidsError::InvalidOperand { source, .. } => Some(source),
            SolidsError::Boolean { source, .. } => Some(source),
            SolidsError::UnsupportedOperation(_) => None,
        }
    }
}

/// The result of an n-ary 3D Boolean.
#[derive(Clone, Debug, PartialEq)]
pub struct SolidsOutput {
    /// The resulting shape, always topologically valid (triangles as
    /// facets for [`MeshVariant::TriangleMesh`]); the empty mesh for no
    /// operands.
    pub mesh: PolygonMesh,
    /// The number of binary Booleans run (one less than the operands).
    pub booleans: usize,
    /// The edge-facet intersection vertices summed over every Boolean.
    pub intersections: usize,
    /// The variant that ran.
    pub variant: MeshVariant,
    /// Milliseconds of the whole call.
    pub total_ms: f64,
}

/// A partial result: the operands it covers, the solid and its
/// intersection count so far.
struct Part<'a> {
    operands: Range<usize>,
    solid: Solid<'a>,
    intersections: usize,
}

/// A solid in the variant being run (borrowed until a Boolean made it).
enum Solid<'a> {
    Poly(Cow<'a, PolygonMesh>),
    Tri(Cow<'a, TriangleMesh>),
}

fn combine<'a>(a: Part<'a>, b: Part<'a>, op: BooleanOp) -> Result<Part<'a>, SolidsError> {
    let operands = a.operands.start..b.operands.end;
    let failed = |source| SolidsError::Boolean {
        operands: operands.clone(),
        source,
    };
    let (solid, intersections) = match (&a.solid, &b.solid) {
        (Solid::Poly(x), Solid::Poly(y)) => {
            let out = boolean_mesh(x, y, op).map_err(failed)?;
            (Solid::Poly(Cow::Owned(out.mesh)), out.intersections)
        }
        (Solid::Tri(x), Solid::Tri(y)) => {
            let out = boolean_triangles(x, y, op).map_err(failed)?;
            (Solid::Tri(Cow::Owned(out.mesh)), out.intersections)
        }
        _ => {
            return Err(failed(Boolean3Error::Internal(
                "n-ary Boolean: operands of different variants".into(),
            )))
        }
    };
    Ok(Part {
        solid,
        intersections: a.intersections + b.intersections + intersections,
        operands,
    })
}

/// The n-ary 3D Boolean `op` of `meshes` by `variant`: the union or the
/// intersection of all of them, or for [`BooleanOp::Difference`] the
/// first minus all of the others. It runs as a balanced tree of binary
/// Booleans (a difference: the first minus the balanced union of the
/// rest), independent branches in parallel on rayon's pool; the output is
/// the same bit for bit for any thread count, and its volume is that of
/// the sequential fold.
///
/// Every operand is checked first (coordinates, then the constraints of
/// section 4.2) and the first bad one is named by its position. No
/// operands give the empty mesh (the identity of the union; for the
/// intersection and the difference, the documented result of an empty
/// list); a single operand is returned as it is (triangulated by internal
/// edges for the triangle-mesh variant when it has other facets).
///
/// # Example
///
/// ```
/// use umbra::{boolean_solids, cuboid, BooleanOp, DVec3, MeshVariant};
///
/// let cube = |x: f64| {
///     let mut m = cuboid(DVec3::splat(1.0), false).unwrap();
///     m.vertices.iter_mut().for_each(|v| v[0] += x);
///     m
/// };
/// // Three unit cubes overlapping by half along x: volume 2.
/// let cubes = [cube(0.0), cube(0.5), cube(1.0)];
/// let out = boolean_solids(BooleanOp::Union, &cubes, MeshVariant::PolygonMesh)?;
/// assert_eq!(out.booleans, 2);
/// assert!((out.mesh.signed_volume() - 2.0).abs() < 1e-12);
/// # Ok::<(), umbra::SolidsError>(())
/// ```
pub fn boolean_solids(
    op: BooleanOp,
    meshes: &[PolygonMesh],
    variant: MeshVariant,
) -> Result<SolidsOutput, SolidsError> {
    boolean_refs(op, meshes.iter().collect(), variant)
}

/// The union of all of `meshes` in one call ([`boolean_solids`] with
/// [`BooleanOp::Union`]): the empty mesh for none.
pub fn union_all_solids(
    meshes: &[PolygonMesh],
    variant: MeshVariant,
) -> Result<SolidsOutput, SolidsError> {
    boolean_solids(BooleanOp::Union, meshes, variant)
}

/// `a` minus all of `bs` in one call: `a` minus the balanced union of
/// `bs` ([`boolean_solids`] with [`BooleanOp::Difference`]); `a` itself
/// when `bs` is empty. Errors number `a` as operand 0 and `bs[i]` as
/// operand `i + 1`.
pub fn difference_all_solids(
    a: &PolygonMesh,
    bs: &[PolygonMesh],
    variant: MeshVariant,
) -> Result<SolidsOutput, SolidsError> {
    let refs = std::iter::once(a).chain(bs).collect();
    boolean_refs(BooleanOp::Difference, refs, variant)
}

fn boolean_refs(
    op: BooleanOp,
    meshes: Vec<&PolygonMesh>,
    variant: MeshVariant,
) -> Result<SolidsOutput, SolidsError> {
    let start = Instant::now();
    if op == BooleanOp::Xor {
        return Err(SolidsError::UnsupportedOperation(op));
    }
    for (index, m) in meshes.iter().enumerate() {
        m.validate_coordinates()
            .and_then(|()| m.check_topology())
            .map_err(|source| SolidsError::InvalidOperand { index, source })?;
    }
    let booleans = meshes.len().saturating_sub(1);
    let parts: Vec<Part<'_>> = meshes
        .into_par_iter()
        .enumerate()
        .map(|(i, m)| Part {
            operands: i..i + 1,
            solid: match variant {
                MeshVariant::PolygonMesh => Solid::Poly(Cow::Borrowed(m)),
                MeshVariant::TriangleMesh => Solid::Tri(Cow::Owned(
                    as_triangle_mesh(m).unwrap_or_else(|| triangulate_mesh(m)),
                )),
            },
            intersections: 0,
        })
        .collect();
    let result = reduce_op(parts, op, &combine)?;
    let (mesh, intersections) = match result {
        None => (PolygonMesh::default(), 0),
        Some(part) => (
            match part.solid {
                Solid::Poly(m) => m.into_owned(),
                Solid::Tri(t) => t.to_polygon_mesh(),
            },
            part.intersections,
        ),
    };
    Ok(SolidsOutput {
        mesh,
        booleans,
        intersections,
        variant,
        total_ms: start.elapsed().as_secs_f64() * 1e3,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{cuboid, transform_mesh, uv_sphere};
    use glam::{DMat4, DVec3};
    use proptest::prelude::*;

    const VARIANTS: [MeshVariant; 2] = [MeshVariant::PolygonMesh, MeshVariant::TriangleMesh];

    fn moved(m: &PolygonMesh, at: [f64; 3]) -> PolygonMesh {
        transform_mesh(m, &DMat4::from_translation(DVec3::from_array(at)))
            .unwrap_or_else(|e| panic!("translation: {e}"))
    }

    fn boxed(size: [f64; 3], at: [f64; 3]) -> PolygonMesh {
        let b = cuboid(DVec3::from_array(size), false).unwrap_or_else(|e| panic!("box: {e}"));
        moved(&b, at)
    }

    fn run(op: BooleanOp, meshes: &[PolygonMesh], variant: MeshVariant) -> SolidsOutput {
        boolean_solids(op, meshes, variant).unwrap_or_else(|e| panic!("{op:?}: {e}"))
    }

    fn volume(out: &SolidsOutput) -> f64 {
        assert!(out.mesh.check_topology().is_ok(), "result not closed");
        out.mesh.signed_volume()
    }

    /// The left-to-right fold of the binary Booleans, the reference.
    fn fold(op: BooleanOp, meshes: &[PolygonMesh], variant: MeshVariant) -> PolygonMesh {
        let mut it = meshes.iter();
        let first = it.next().cloned().unwrap_or_default();
        it.fold(first, |acc, m| {
            crate::boolean_solid(&acc, m, op, variant)
                .unwrap_or_else(|e| panic!("fold: {e}"))
                .mesh
        })
    }

    fn bits(m: &PolygonMesh) -> (Vec<[u64; 3]>, Vec<topology::Facet>) {
        let v = m
            .vertices
            .iter()
            .map(|p| [p[0].to_bits(), p[1].to_bits(), p[2].to_bits()])
            .collect();
        (v, m.facets.clone())
    }

    #[test]
    fn the_tree_is_neighbours_round_by_round() {
        let show = |n: usize| {
            let items: Vec<String> = (0..n).map(|i| i.to_string()).collect();
            let joined = reduce_balanced(items, &|a: String, b: String| {
                Ok::<_, ()>(format!("({a} {b})"))
            });
            joined.ok().flatten().unwrap_or_default()
        };
        assert_eq!(show(0), "");
        assert_eq!(show(1), "0");
        assert_eq!(show(3), "((0 1) 2)");
        assert_eq!(show(6), "(((0 1) (2 3)) (4 5))");
        assert_eq!(show(7), "(((0 1) (2 3)) ((4 5) 6))");
        assert_eq!(show(9), "((((0 1) (2 3)) ((4 5) (6 7))) 8)");
    }

    #[test]
    fn the_leftmost_error_is_reported() {
        let items: Vec<u32> = (0..8).collect();
        let combine = |a: u32, b: u32| {
            if a >= 4 && a.is_multiple_of(2) {
                Err(a)
            } else {
                Ok(a + b)
            }
        };
        // Pairs (4 5) and (6 7) fail; the left one is reported.
        assert_eq!(reduce_balanced(items, &combine), Err(4));
        let diff = |a: u32, b: u32, op: BooleanOp| match op {
            BooleanOp::Difference => Ok::<u32, ()>(a * 100 + b),
            _ => Ok(a + b),
        };
        assert_eq!(
            reduce_op(vec![7, 1, 2, 3], BooleanOp::Difference, &diff),
            Ok(Some(706))
        );
        assert_eq!(
            reduce_op(vec![7], BooleanOp::Difference, &diff),
            Ok(Some(7))
        );
        assert_eq!(reduce_op(Vec::new(), BooleanOp::Union, &diff), Ok(None));
    }

    #[test]
    fn disjoint_boxes_add_up() {
        let boxes: Vec<PolygonMesh> = (0..7)
            .map(|i| {
                let s = 0.5 + 0.25 * f64::from(i);
                boxed(
                    [s, 1.0, 2.0 - 0.125 * f64::from(i)],
                    [3.0 * f64::from(i), 0.0, 0.0],
                )
            })
            .collect();
        let exact: f64 = (0..7)
            .map(|i| (0.5 + 0.25 * f64::from(i)) * (2.0 - 0.125 * f64::from(i)))
            .sum();
        for variant in VARIANTS {
            let out = run(BooleanOp::Union, &boxes, variant);
            assert_eq!(out.booleans, 6);
            assert_eq!(out.intersections, 0);
            assert_eq!(volume(&out), exact, "{variant:?}");
            // Disjoint operands have nothing in common.
            let out = run(BooleanOp::Intersection, &boxes, variant);
            assert_eq!(out.mesh.facets.len(), 0, "{variant:?}");
        }
    }

    #[test]
    fn nested_boxes() {
        let outer = boxed([4.0, 4.0, 4.0], [0.0; 3]);
        let middle = boxed([2.0, 2.0, 2.0], [1.0; 3]);
        let inner = boxed([1.0, 1.0, 1.0], [1.5; 3]);
        let all = [inner.clone(), outer.clone(), middle.clone()];
        for variant in VARIANTS {
            assert_eq!(volume(&run(BooleanOp::Union, &all, variant)), 64.0);
            assert_eq!(volume(&run(BooleanOp::Intersection, &all, variant)), 1.0);
            let out = difference_all_solids(&outer, &[middle.clone(), inner.clone()], variant)
                .unwrap_or_else(|e| panic!("{e}"));
            assert_eq!(volume(&out), 56.0, "{variant:?}");
            // The inner box minus everything is empty.
            let out = difference_all_solids(&inner, &[outer.clone(), middle.clone()], variant)
                .unwrap_or_else(|e| panic!("{e}"));
            assert_eq!(volume(&out), 0.0);
        }
    }

    #[test]
    fn slab_minus_a_grid_of_boxes() {
        // 6 x 4 holes of 0.5 x 0.5 through a 4 x 3 x 1 slab.
        let slab = boxed([4.0, 3.0, 1.0], [0.0; 3]);
        let holes: Vec<PolygonMesh> = (0..24)
            .map(|k| {
                let (i, j) = (f64::from(k % 6), f64::from(k / 6));
                boxed([0.5, 0.5, 2.0], [0.2 + 0.6 * i, 0.2 + 0.7 * j, -0.5])
            })
            .collect();
        for variant in VARIANTS {
            let out =
                difference_all_solids(&slab, &holes, variant).unwrap_or_else(|e| panic!("{e}"));
            assert_eq!(out.booleans, 24);
            let v = volume(&out);
            assert!((v - (12.0 - 24.0 * 0.25)).abs() < 1e-12, "{variant:?}: {v}");
        }
    }

    #[test]
    fn empty_and_single_operands() {
        for variant in VARIANTS {
            for op in [
                BooleanOp::Union,
                BooleanOp::Intersection,
                BooleanOp::Difference,
            ] {
                let out = run(op, &[], variant);
                assert_eq!(out.mesh, PolygonMesh::default());
                assert_eq!(out.booleans, 0);
            }
        }
        let b = boxed([1.0, 2.0, 3.0], [0.5, 0.0, 0.0]);
        let out = run(
            BooleanOp::Union,
            std::slice::from_ref(&b),
            MeshVariant::PolygonMesh,
        );
        assert_eq!(out.mesh, b);
        let out = difference_all_solids(&b, &[], MeshVariant::PolygonMesh);
        assert_eq!(out.map(|o| o.mesh), Ok(b.clone()));
        // The triangle variant triangulates the quadrilaterals.
        let out = run(
            BooleanOp::Union,
            std::slice::from_ref(&b),
            MeshVariant::TriangleMesh,
        );
        assert_eq!(out.mesh.facets.len(), 12);
        assert!(out.mesh.facets.iter().all(|f| f.half_edges.len() == 3));
        assert_eq!(volume(&out), 6.0);
    }

    #[test]
    fn bad_operands_are_named_by_position() {
        let good = boxed([1.0; 3], [0.0; 3]);
        let mut nan = good.clone();
        nan.vertices[3][1] = f64::NAN;
        let mut open = good.clone();
        open.facets.pop();
        let list = [good.clone(), good.clone(), nan.clone(), open.clone()];
        let before = list.clone();
        for variant in VARIANTS {
            let err = boolean_solids(BooleanOp::Union, &list, variant).err();
            assert!(
                matches!(err, Some(SolidsError::InvalidOperand { index: 2, .. })),
                "{err:?}"
            );
            let err = difference_all_solids(&good, &[good.clone(), open.clone()], variant).err();
            assert!(
                matches!(err, Some(SolidsError::InvalidOperand { index: 2, .. })),
                "{err:?}"
            );
            let msg = err.map(|e| e.to_string()).unwrap_or_default();
            assert!(msg.starts_with("operand 2: "), "{msg}");
            let err = difference_all_solids(&open, std::slice::from_ref(&good), variant).err();
            assert!(matches!(
                err,
                Some(SolidsError::InvalidOperand { index: 0, .. })
            ));
            // A single bad operand is refused too.
            let err = boolean_solids(BooleanOp::Union, std::slice::from_ref(&nan), variant).err();
            assert!(matches!(
                err,
                Some(SolidsError::InvalidOperand { index: 0, .. })
            ));
        }
        let same = list.iter().zip(&before).all(|(a, b)| bits(a) == bits(b));
        assert!(same, "the caller's data changed");
        let err = boolean_solids(BooleanOp::Xor, &before[..2], MeshVariant::PolygonMesh).err();
        assert_eq!(err, Some(SolidsError::UnsupportedOperation(BooleanOp::Xor)));
    }

    #[test]
    fn the_same_bits_on_one_and_three_threads() {
        let sphere = uv_sphere(1.0, 10, 5).unwrap_or_else(|e| panic!("{e}"));
        let spheres: Vec<PolygonMesh> = (0..11)
            .map(|i| {
                let t = f64::from(i);
                moved(
                    &sphere,
                    [0.7 * t, 0.3 * (t * 1.3).sin(), 0.2 * (t * 0.7).cos()],
                )
            })
            .collect();
        let slab = boxed([5.0, 2.0, 1.0], [-0.5, -1.0, -0.5]);
        for variant in VARIANTS {
            let on = |threads: usize| {
                let pool = rayon::ThreadPoolBuilder::new()
                    .num_threads(threads)
                    .build()
                    .unwrap_or_else(|e| panic!("pool: {e}"));
                pool.install(|| {
                    let u = run(BooleanOp::Union, &spheres, variant);
                    let d = difference_all_solids(&slab, &spheres, variant)
                        .unwrap_or_else(|e| panic!("{e}"));
                    (
                        bits(&u.mesh),
                        u.intersections,
                        bits(&d.mesh),
                        d.intersections,
                    )
                })
            };
            let one = on(1);
            assert!(one.1 > 0 && one.3 > 0, "the spheres must intersect");
            assert!(one == on(3), "{variant:?}: results differ by thread count");
        }
    }

    #[test]
    fn overlapping_spheres_match_the_fold() {
        let sphere = uv_sphere(1.0, 12, 6).unwrap_or_else(|e| panic!("{e}"));
        // Close enough that all six share a region (the intersection is
        // not empty), far enough apart that every pair crosses.
        let spheres: Vec<PolygonMesh> = (0..6)
            .map(|i| {
                let t = f64::from(i);
                moved(&sphere, [0.2 * t, 0.1 * t.sin(), -0.05 * t])
            })
            .collect();
        for variant in VARIANTS {
            for op in [
                BooleanOp::Union,
                BooleanOp::Intersection,
                BooleanOp::Difference,
            ] {
                let tree = volume(&run(op, &spheres, variant));
                let seq = fold(op, &spheres, variant).signed_volume();
                assert!(
                    (tree - seq).abs() <= 1e-9 * seq.abs().max(1.0),
                    "{variant:?} {op:?}: tree {tree} fold {seq}"
                );
                assert!(tree > 0.0, "{variant:?} {op:?}: empty");
            }
        }
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(test_support::cases(24)))]

        /// The slab minus boxes through it in one call, triangle variant:
        /// the lean re-triangulation keeps the count of the shape's real
        /// complexity, `20 k + 12` triangles for `k` holes (each face of
        /// `V` corners and `H` holes in `V + 2H - 2` triangles: top and
        /// bottom `6 k + 2` each, 8 on the sides, 8 per hole's walls), far
        /// below the bound of 1.5 times the C++ Manifold's count (20,020
        /// at `k = 1000`), with the exact volume.
        #[test]
        fn slab_minus_boxes_keeps_the_euler_count(
            cells in 1u16..(1 << 12),
            jitter in proptest::collection::vec((-12i32..=12, -12i32..=12), 12),
        ) {
            let slab = boxed([4.0, 3.0, 1.0], [0.0; 3]);
            let holes: Vec<PolygonMesh> = (0..12u16)
                .filter(|k| cells & (1 << k) != 0)
                .map(|k| {
                    let (jx, jy) = jitter[usize::from(k)];
                    let x = f64::from(k % 4) + 0.25 + f64::from(jx) / 64.0;
                    let y = f64::from(k / 4) + 0.25 + f64::from(jy) / 64.0;
                    boxed([0.5, 0.5, 2.0], [x, y, -0.5])
                })
                .collect();
            let k = holes.len();
            let out = difference_all_solids(&slab, &holes, MeshVariant::TriangleMesh)
                .unwrap_or_else(|e| panic!("{e}"));
            prop_assert!(out.mesh.check_topology().is_ok());
            prop_assert!(out.mesh.facets.iter().all(|f| f.half_edges.len() == 3));
            prop_assert_eq!(out.mesh.facets.len(), 20 * k + 12);
            prop_assert_eq!(out.mesh.signed_volume(), 12.0 - 0.25 * k as f64);
        }

        /// Random boxes: the tree's volume is the fold's, both variants.
        #[test]
        fn random_boxes_match_the_fold(
            boxes in proptest::collection::vec(
                ((0.1f64..2.0, 0.1f64..2.0, 0.1f64..2.0), (-1.0f64..1.0, -1.0f64..1.0, -1.0f64..1.0)),
                0..7,
            ),
            op in prop_oneof![
                Just(BooleanOp::Union),
                Just(BooleanOp::Intersection),
                Just(BooleanOp::Difference),
            ],
            triangles in any::<bool>(),
        ) {
            let variant = if triangles { MeshVariant::TriangleMesh } else { MeshVariant::PolygonMesh };
            let meshes: Vec<PolygonMesh> = boxes
                .iter()
                .map(|&((w, h, d), (x, y, z))| boxed([w, h, d], [x, y, z]))
                .collect();
            let out = run(op, &meshes, variant);
            prop_assert!(out.mesh.check_topology().is_ok());
            let tree = out.mesh.signed_volume();
            let seq = fold(op, &meshes, variant).signed_volume();
            prop_assert!((tree - seq).abs() <= 1e-9 * seq.abs().max(1.0), "tree {} fold {}", tree, seq);
        }
    }
}
