//! Theorems 1-4 (section 4.9) as property tests: random topologically valid
//! meshes with random-garbage, integer-grid (exact ties) and near-degenerate
//! coordinates must always give a topologically valid result, the audit
//! must confirm every theorem, and the fast level 3 (broad phase, winding
//! propagation) must equal the brute-force Table 4.1 oracle exactly. Both
//! variants must also give bit-identical output for every thread count.

use boolean_3d::{
    boolean_mesh, boolean_mesh_audit, boolean_triangles, boolean_triangles_audit, level3,
    level3_reference, BooleanOp, MeshOutput, TriangleOutput,
};
use proptest::prelude::*;
use test_support::rng::Lcg64;
use test_support::shapes::{box_mesh, icosphere, tetra, uv_sphere};
use topology::{Facet, PolygonMesh, TriangleMesh};

/// Topologies: every one satisfies the constraints of section 4.2.
fn topology_of(kind: u32) -> PolygonMesh {
    match kind % 7 {
        0 => box_mesh([0.0; 3], [1.0; 3]),
        1 => tetra([[0.0; 3], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]).to_polygon_mesh(),
        2 => icosphere([0.0; 3], 1.0, 1).to_polygon_mesh(),
        3 => two_cubes_sharing_an_edge(),
        4 => {
            // A tetrahedron with a zero-length half-edge and a duplicated
            // (coincident) vertex in one facet: 0 -> 0 and vertex 4 at the
            // position of vertex 1 but a different index.
            let v = vec![[0.0; 3], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
            let f = vec![
                Facet::from_loop(&[0, 0, 2, 1]),
                Facet::from_loop(&[0, 1, 3]),
                Facet::from_loop(&[1, 2, 3]),
                Facet::from_loop(&[0, 3, 2]),
            ];
            PolygonMesh::new(v, f)
        }
        5 => {
            // A box with a square tunnel: facets with holes.
            let a = box_mesh([0.0; 3], [2.0; 3]);
            let b = box_mesh([0.5, 0.5, -1.0], [1.5, 1.5, 3.0]);
            boolean_mesh(&a, &b, BooleanOp::Difference).unwrap().mesh
        }
        _ => {
            // Two shells in one mesh.
            let mut m = box_mesh([0.0; 3], [1.0; 3]);
            let t = tetra([[2.0; 3], [3.0, 2.0, 2.0], [2.0, 3.0, 2.0], [2.0, 2.0, 3.0]])
                .to_polygon_mesh();
            let off = m.vertices.len() as u32;
            m.vertices.extend(t.vertices);
            for mut f in t.facets {
                for h in &mut f.half_edges {
                    h.start += off;
                    h.end += off;
                }
                m.facets.push(f);
            }
            m
        }
    }
}

/// Two unit cubes sharing one edge, as a single non-manifold mesh: the
/// edge (1,1,0)-(1,1,1) has two pairs of half-edges.
pub fn two_cubes_sharing_an_edge() -> PolygonMesh {
    let mut m = box_mesh([0.0; 3], [1.0; 3]);
    let c2 = box_mesh([1.0, 1.0, 0.0], [2.0, 2.0, 1.0]);
    // c2's vertices 0 (1,1,0) and 4 (1,1,1) are m's vertices 3 and 7.
    let mut map = Vec::new();
    for (i, p) in c2.vertices.iter().enumerate() {
        match i {
            0 => map.push(3),
            4 => map.push(7),
            _ => {
                map.push(m.vertices.len() as u32);
                m.vertices.push(*p);
            }
        }
    }
    for mut f in c2.facets {
        for h in &mut f.half_edges {
            h.start = map[h.start as usize];
            h.end = map[h.end as usize];
        }
        m.facets.push(f);
    }
    m
}

/// Replaces the coordinates: 0 = garbage of mixed magnitude, 1 = integer
/// grid {0, 1, 2} (exact ties everywhere), 2 = a valid shape perturbed by
/// a few ulps (near-degenerate), 3 = garbage in [-1, 1].
fn recoordinate(m: &mut PolygonMesh, mode: u32, rng: &mut Lcg64, shift: [f64; 3]) {
    for p in &mut m.vertices {
        for (c, x) in p.iter_mut().enumerate() {
            *x = match mode % 4 {
                0 => match rng.below(5) {
                    0 => rng.uniform(-1e300, 1e300),
                    1 => rng.uniform(-1e-300, 1e-300),
                    2 => rng.below(3) as f64,
                    _ => rng.uniform(-10.0, 10.0),
                },
                1 => rng.below(3) as f64,
                2 => {
                    let v = *x + shift[c];
                    v + v * f64::EPSILON * (rng.below(5) as f64 - 2.0)
                }
                _ => rng.uniform(-1.0, 1.0),
            };
        }
    }
}

fn check_all(a: &PolygonMesh, b: &PolygonMesh) {
    // The fast level 3 equals the brute-force oracle exactly.
    let fast = level3(a, b).unwrap();
    let slow = level3_reference(a, b).unwrap();
    assert_eq!(fast.x12, slow.x12);
    assert_eq!(fast.x21, slow.x21);
    assert_eq!(fast.x03, slow.x03);
    assert_eq!(fast.x30, slow.x30);
    for op in BooleanOp::BASIC {
        let (out, audit) = boolean_mesh_audit(a, b, op).unwrap();
        audit.verify().unwrap();
        // The plain path (with its fast path for unintersected edges) gives
        // exactly the audited result.
        assert_eq!(boolean_mesh(a, b, op).unwrap(), out);
        assert_eq!(out.mesh.check_topology(), Ok(()), "{op:?}");
        // Theorem 3 counted here independently of the audit.
        for f in &out.mesh.facets {
            let mut bal = std::collections::HashMap::new();
            for h in &f.half_edges {
                *bal.entry(h.end).or_insert(0i64) += 1;
                *bal.entry(h.start).or_insert(0i64) -= 1;
            }
            assert!(bal.values().all(|&v| v == 0), "{op:?}: open facet {f:?}");
        }
        let tri = boolean_3d::triangulate_mesh(&out.mesh);
        assert_eq!(tri.check_topology(), Ok(()), "{op:?} triangulated");
    }
}

fn triangles_of(m: &PolygonMesh) -> TriangleMesh {
    boolean_3d::triangulate_mesh(m)
}

proptest! {
    #![proptest_config(ProptestConfig { cases: test_support::cases(64), .. ProptestConfig::default() })]

    #[test]
    fn garbage_grid_and_near_degenerate_coordinates_give_valid_results(
        ka in 0u32..7, kb in 0u32..7, mode in 0u32..4, seed in any::<u64>()
    ) {
        let mut rng = Lcg64::new(seed);
        let mut a = topology_of(ka);
        let mut b = topology_of(kb);
        let shift = [rng.uniform(-0.7, 0.7), rng.uniform(-0.7, 0.7), rng.uniform(-0.7, 0.7)];
        recoordinate(&mut a, mode, &mut rng, [0.0; 3]);
        recoordinate(&mut b, mode, &mut rng, shift);
        check_all(&a, &b);
    }

    #[test]
    fn triangle_variant_is_valid_on_garbage(
        ka in 0u32..7, kb in 0u32..7, mode in 0u32..4, seed in any::<u64>()
    ) {
        let mut rng = Lcg64::new(seed);
        let mut a = topology_of(ka);
        let mut b = topology_of(kb);
        recoordinate(&mut a, mode, &mut rng, [0.0; 3]);
        recoordinate(&mut b, mode, &mut rng, [0.3, 0.2, 0.1]);
        let (ta, tb) = (triangles_of(&a), triangles_of(&b));
        for op in BooleanOp::BASIC {
            let (out, audit) = boolean_triangles_audit(&ta, &tb, op).unwrap();
            audit.verify().unwrap();
            prop_assert_eq!(out.mesh.check_topology(), Ok(()));
        }
    }
}

/// Every bit of a polygon-mesh result: coordinates by `to_bits` (so that
/// `-0.0` and `0.0` differ, unlike with `==`), then the facets, the facet
/// sources and the intersection count.
fn mesh_bits(o: &MeshOutput) -> (Vec<[u64; 3]>, String, usize) {
    let bits = o
        .mesh
        .vertices
        .iter()
        .map(|p| p.map(f64::to_bits))
        .collect();
    let rest = format!("{:?} {:?}", o.mesh.facets, o.sources);
    (bits, rest, o.intersections)
}

/// Every bit of a triangle-mesh result.
fn triangle_bits(o: &TriangleOutput) -> (Vec<[u64; 3]>, Vec<[u32; 3]>, usize) {
    let bits = o
        .mesh
        .vertices
        .iter()
        .map(|p| p.map(f64::to_bits))
        .collect();
    (bits, o.mesh.triangles.clone(), o.intersections)
}

/// Runs `f` in a rayon pool of exactly `threads` threads.
fn in_pool<T: Send>(threads: usize, f: impl FnOnce() -> T + Send) -> T {
    rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .unwrap()
        .install(|| {
            assert_eq!(rayon::current_num_threads(), threads);
            f()
        })
}

/// The determinism requirement (the same input gives the same
/// output bit for bit, whatever the thread count): the level-3 pair work
/// and the level-5 facet assembly run on rayon (section 4.4's values are
/// independent per pair), so results must be gathered in an order that
/// does not depend on how the work was split. Two UV spheres of 2976
/// triangles each, one shifted by half its radius, give rayon thousands of
/// items to split; both variants and all three operations are compared
/// with pools of 1, 2 and 4 threads.
#[test]
fn output_is_identical_for_any_thread_count() {
    let ta = uv_sphere([0.0; 3], 1.0, 48, 32);
    let tb = uv_sphere([0.5, 0.013, 0.029], 1.0, 48, 32);
    assert_eq!(ta.triangles.len(), 2976);
    let (pa, pb) = (ta.to_polygon_mesh(), tb.to_polygon_mesh());
    for op in BooleanOp::BASIC {
        let polygons =
            |threads| in_pool(threads, || mesh_bits(&boolean_mesh(&pa, &pb, op).unwrap()));
        let triangles = |threads| {
            in_pool(threads, || {
                triangle_bits(&boolean_triangles(&ta, &tb, op).unwrap())
            })
        };
        let (p1, t1) = (polygons(1), triangles(1));
        assert!(p1.2 > 100 && t1.2 > 100, "{op:?}: too few intersections");
        for threads in [2, 4] {
            assert!(
                polygons(threads) == p1,
                "{op:?}: polygon variant differs on {threads} threads"
            );
            assert!(
                triangles(threads) == t1,
                "{op:?}: triangle variant differs on {threads} threads"
            );
        }
    }
}

#[test]
fn level3_fast_path_matches_the_oracle_on_spheres() {
    let a = icosphere([0.0; 3], 1.0, 2).to_polygon_mesh();
    let b = uv_sphere([0.5, 0.0, 0.0], 1.0, 12, 8).to_polygon_mesh();
    let fast = level3(&a, &b).unwrap();
    let slow = level3_reference(&a, &b).unwrap();
    assert!(!fast.x12.is_empty() && !fast.x21.is_empty());
    assert_eq!(fast.x12, slow.x12);
    assert_eq!(fast.x21, slow.x21);
    assert_eq!(fast.x03, slow.x03);
    assert_eq!(fast.x30, slow.x30);
    // One ray cast per connected component (one shell each).
    assert_eq!(fast.ray_casts, 2);
}
