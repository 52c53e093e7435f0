//! Theorems 1-4 (section 4.9) on random mesh topologies: each operand is a
//! random collection of shells (boxes, tetrahedra, octahedra and prisms,
//! randomly placed and rotated), some inside-out, some glued to earlier
//! shells at a vertex or along an edge (non-manifold contact) or with
//! vertices identified arbitrarily (zero-length edges). Every such mesh
//! satisfies the constraints of section 4.2, so every operation in both
//! variants must pass the audit, first with the placed coordinates (where
//! the winding-number identity of eq. 4.20 is checked too) and then with
//! every coordinate replaced by random garbage, after the dissertation's
//! claim that "even replacing the vertex position data with random data
//! would generate a topologically valid result".

use boolean_3d::{
    boolean_mesh, boolean_mesh_audit, boolean_triangles, boolean_triangles_audit, level3,
    level3_reference, triangulate_mesh, BooleanOp,
};
use proptest::prelude::*;
use test_support::measure::{distance_to_mesh, winding_number};
use test_support::rng::Lcg64;
use test_support::shapes::{box_mesh, CUBE_FACES};
use topology::{Facet, PolygonMesh, TriangleMesh};

/// One closed, outward-facing shell about the origin: vertices and facet
/// loops.
fn unit_shell(kind: u64) -> (Vec<[f64; 3]>, Vec<Vec<u32>>) {
    match kind {
        0 => (
            box_mesh([-0.5; 3], [0.5; 3]).vertices,
            CUBE_FACES.iter().map(|f| f.to_vec()).collect(),
        ),
        1 => {
            let v = vec![
                [-0.25, -0.25, -0.25],
                [0.75, -0.25, -0.25],
                [-0.25, 0.75, -0.25],
                [-0.25, -0.25, 0.75],
            ];
            let f = [[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2]];
            (v, f.iter().map(|t| t.to_vec()).collect())
        }
        2 => {
            // Vertices +x, -x, +y, -y, +z, -z; one triangle per octant,
            // reversed where the octant's sign product is negative.
            let v = vec![
                [0.6, 0.0, 0.0],
                [-0.6, 0.0, 0.0],
                [0.0, 0.6, 0.0],
                [0.0, -0.6, 0.0],
                [0.0, 0.0, 0.6],
                [0.0, 0.0, -0.6],
            ];
            let mut f = Vec::new();
            for o in 0..8u32 {
                let (x, y, z) = (o & 1, 2 + ((o >> 1) & 1), 4 + ((o >> 2) & 1));
                if (o & 1) ^ ((o >> 1) & 1) ^ ((o >> 2) & 1) == 0 {
                    f.push(vec![x, y, z]);
                } else {
                    f.push(vec![x, z, y]);
                }
            }
            (v, f)
        }
        _ => {
            // A triangular prism: two triangles and three quadrilaterals.
            let v = vec![
                [-0.5, -0.3, -0.4],
                [0.5, -0.3, -0.4],
                [0.0, 0.5, -0.4],
                [-0.5, -0.3, 0.4],
                [0.5, -0.3, 0.4],
                [0.0, 0.5, 0.4],
            ];
            let f = vec![
                vec![0, 2, 1],
                vec![3, 4, 5],
                vec![0, 1, 4, 3],
                vec![1, 2, 5, 4],
                vec![2, 0, 3, 5],
            ];
            (v, f)
        }
    }
}

/// `p` rotated about x, y and z by the three angles.
fn rotate3(p: [f64; 3], ang: [f64; 3]) -> [f64; 3] {
    let mut q = p;
    for (axis, &a) in ang.iter().enumerate() {
        let (s, c) = a.sin_cos();
        let (i, j) = ((axis + 1) % 3, (axis + 2) % 3);
        let (qi, qj) = (q[i], q[j]);
        q[i] = c * qi - s * qj;
        q[j] = s * qi + c * qj;
    }
    q
}

/// A random topologically valid mesh of `shells` shells. Gluing maps some
/// of a new shell's vertices onto existing vertices; renaming vertices
/// keeps every facet's loops closed and every half-edge paired with an
/// opposite one, so facet and shape boundary closure (section 4.2) hold
/// whatever is identified with what.
fn random_mesh(rng: &mut Lcg64, shells: usize) -> PolygonMesh {
    let mut m = PolygonMesh::default();
    for s in 0..shells {
        let (v, mut loops) = unit_shell(rng.below(4));
        let scale = rng.uniform(0.4, 1.2);
        let ang = [0; 3].map(|_| rng.uniform(0.0, std::f64::consts::TAU));
        let shift = [0; 3].map(|_| rng.uniform(-0.5, 0.5));
        // One shell in four is inside-out (winding number -1 inside,
        // section 4.7).
        if rng.below(4) == 0 {
            for l in &mut loops {
                l.reverse();
            }
        }
        let base = m.vertices.len() as u32;
        let mut map: Vec<u32> = (base..base + v.len() as u32).collect();
        if s > 0 && base > 0 {
            match rng.below(4) {
                // Touching an earlier shell at one vertex.
                0 => map[rng.below(v.len() as u64) as usize] = rng.below(u64::from(base)) as u32,
                // Sharing an edge with an earlier facet: the edge gets two
                // pairs of half-edges (a non-manifold edge).
                1 => {
                    let f = &m.facets[rng.below(m.facets.len() as u64) as usize];
                    let h = f.half_edges[rng.below(f.half_edges.len() as u64) as usize];
                    let l = &loops[rng.below(loops.len() as u64) as usize];
                    let k = rng.below(l.len() as u64) as usize;
                    let (a, b) = (l[k], l[(k + 1) % l.len()]);
                    map[a as usize] = h.end;
                    map[b as usize] = h.start;
                }
                // Arbitrary identifications, possibly of two vertices of
                // one facet (zero-length edges).
                2 => {
                    for _ in 0..1 + rng.below(3) {
                        let from = rng.below(v.len() as u64) as usize;
                        map[from] = rng.below(u64::from(base) + v.len() as u64) as u32;
                        if map[from] >= base {
                            map[from] = map[(map[from] - base) as usize];
                        }
                    }
                }
                _ => {}
            }
        }
        m.vertices.extend(v.iter().map(|&p| {
            let r = rotate3(p, ang);
            [0, 1, 2].map(|c| shift[c] + scale * r[c])
        }));
        for l in &loops {
            let l: Vec<u32> = l.iter().map(|&i| map[i as usize]).collect();
            m.facets.push(Facet::from_loop(&l));
        }
    }
    m
}

/// Random garbage of mixed magnitude, with small integers for exact ties.
fn garbage(rng: &mut Lcg64, m: &mut PolygonMesh) {
    for p in &mut m.vertices {
        for x in p.iter_mut() {
            *x = match rng.below(6) {
                0 => rng.uniform(-1e300, 1e300),
                1 => rng.uniform(-1e-300, 1e-300),
                2 | 3 => rng.below(3) as f64,
                _ => rng.uniform(-2.0, 2.0),
            };
        }
    }
}

/// Theorems 1-4 through the audit for every operation in both variants,
/// the plain paths against the audited ones, and the fast level 3 against
/// the brute-force Table 4.1 oracle.
fn check_theorems(a: &PolygonMesh, b: &PolygonMesh, what: &str) -> [TriangleMesh; 3] {
    assert_eq!(a.check_topology(), Ok(()), "{what}: generator broke A");
    assert_eq!(b.check_topology(), Ok(()), "{what}: generator broke B");
    let fast = level3(a, b).unwrap();
    let slow = level3_reference(a, b).unwrap();
    assert_eq!(
        (&fast.x12, &fast.x21, &fast.x03, &fast.x30),
        (&slow.x12, &slow.x21, &slow.x03, &slow.x30),
        "{what}: level 3"
    );
    let (ta, tb) = (triangulate_mesh(a), triangulate_mesh(b));
    assert_eq!(ta.check_topology(), Ok(()), "{what}: triangulated A");
    assert_eq!(tb.check_topology(), Ok(()), "{what}: triangulated B");
    BooleanOp::BASIC.map(|op| {
        let (out, audit) = boolean_mesh_audit(a, b, op).unwrap();
        audit
            .verify()
            .unwrap_or_else(|e| panic!("{what} {op:?} polygons: {e}"));
        assert_eq!(out.mesh.check_topology(), Ok(()), "{what} {op:?}");
        assert_eq!(boolean_mesh(a, b, op).unwrap(), out, "{what} {op:?}");
        let (tri, audit) = boolean_triangles_audit(&ta, &tb, op).unwrap();
        audit
            .verify()
            .unwrap_or_else(|e| panic!("{what} {op:?} triangles: {e}"));
        assert_eq!(tri.mesh.check_topology(), Ok(()), "{what} {op:?} triangles");
        assert_eq!(
            boolean_triangles(&ta, &tb, op).unwrap(),
            tri,
            "{what} {op:?}"
        );
        tri.mesh
    })
}

/// Eq. 4.20: at points away from both operands' surfaces, the result's
/// winding number is `c_A a + c_B b + c_I a b` of the operands' winding
/// numbers `a` and `b`, whatever they are (section 4.7). All three are
/// generalized winding numbers of the triangle meshes, computed in the
/// test.
fn check_winding_identity(
    rng: &mut Lcg64,
    a: &PolygonMesh,
    b: &PolygonMesh,
    outs: &[TriangleMesh; 3],
) {
    let (ta, tb) = (triangulate_mesh(a), triangulate_mesh(b));
    let mut checked = 0;
    while checked < 6 {
        let q = [0; 3].map(|_| rng.uniform(-1.6, 1.6));
        if distance_to_mesh(&ta, q).min(distance_to_mesh(&tb, q)) < 1e-3 {
            continue;
        }
        let (wa, wb) = (winding_number(&ta, q), winding_number(&tb, q));
        let (ia, ib) = (wa.round(), wb.round());
        assert!((wa - ia).abs() < 1e-6 && (wb - ib).abs() < 1e-6);
        for (op, out) in BooleanOp::BASIC.into_iter().zip(outs) {
            let want = op.result_winding(ia as i64, ib as i64) as f64;
            let got = winding_number(out, q);
            assert!(
                (got - want).abs() < 1e-6,
                "{op:?} at {q:?}: winding {got}, eq. 4.20 wants {want} (a = {ia}, b = {ib})"
            );
        }
        checked += 1;
    }
}

/// The generator's shells face outwards (positive volume), so reversing
/// one really makes it inside-out.
#[test]
fn unit_shells_face_outwards() {
    for kind in 0..4 {
        let (v, loops) = unit_shell(kind);
        let facets = loops.iter().map(|l| Facet::from_loop(l)).collect();
        let m = PolygonMesh::new(v, facets);
        assert_eq!(m.check_topology(), Ok(()), "shell {kind}");
        assert!(triangulate_mesh(&m).signed_volume() > 0.1, "shell {kind}");
    }
}

/// The generator is not vacuous: over a fixed run of seeds it produces
/// non-manifold edges (more than one pair of half-edges), zero-length
/// edges, inside-out regions (winding number -1) and multiply enclosed
/// regions (winding number 2, section 4.7).
#[test]
fn generator_covers_the_advertised_topologies() {
    let (mut non_manifold, mut zero_length, mut negative, mut double) = (0, 0, 0, 0);
    for seed in 0..200 {
        let mut rng = Lcg64::new(seed);
        let m = random_mesh(&mut rng, 4);
        let mut uses = std::collections::HashMap::new();
        for h in m.facets.iter().flat_map(|f| &f.half_edges) {
            *uses
                .entry((h.start.min(h.end), h.start.max(h.end)))
                .or_insert(0) += 1;
            zero_length += usize::from(h.start == h.end);
        }
        non_manifold += uses.values().filter(|&&n| n > 2).count();
        let t = triangulate_mesh(&m);
        for _ in 0..50 {
            let q = [0; 3].map(|_| rng.uniform(-1.0, 1.0));
            match winding_number(&t, q).round() as i64 {
                ..=-1 => negative += 1,
                2.. => double += 1,
                _ => {}
            }
        }
    }
    assert!(
        non_manifold > 10 && zero_length > 10 && negative > 10 && double > 10,
        "{non_manifold} {zero_length} {negative} {double}"
    );
}

proptest! {
    #![proptest_config(ProptestConfig { cases: test_support::cases(48), .. ProptestConfig::default() })]

    #[test]
    fn random_topologies_satisfy_theorems_1_to_4(
        na in 1usize..=4, nb in 1usize..=4, seed in any::<u64>()
    ) {
        let mut rng = Lcg64::new(seed);
        let mut a = random_mesh(&mut rng, na);
        let mut b = random_mesh(&mut rng, nb);
        let outs = check_theorems(&a, &b, "placed");
        check_winding_identity(&mut rng, &a, &b, &outs);
        garbage(&mut rng, &mut a);
        garbage(&mut rng, &mut b);
        check_theorems(&a, &b, "garbage");
    }
}
