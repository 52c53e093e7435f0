//! The triangle-mesh variant stays lean over chains of operations
//! (issue 13): coplanar input triangles are merged before the Boolean and
//! untouched regions keep their triangles, so a slab carved by `k`
//! through-holes has exactly the triangle count of its real complexity,
//! the topology holds after every step, and volumes stay exact.
//!
//! The count is derived, not tuned: a planar region with `V` boundary
//! vertices and `H` holes, triangulated by internal edges only (no Steiner
//! points), has `V + 2H - 2` triangles (Euler). The slab's top and bottom
//! faces after `k` box holes have `V = 4 + 4k`, `H = k`, so `6k + 2`
//! triangles each; its four sides 2 each; each hole 4 rectangular walls of
//! 2 triangles. Total `20k + 12`. A cavity left by a polyhedron wholly
//! inside the slab adds exactly the polyhedron's own triangles.

use boolean_3d::{boolean_triangles, boolean_triangles_audit, triangulate_mesh, BooleanOp};
use proptest::prelude::*;
use test_support::exact::triangle_mesh_volume as exact_volume;
use test_support::shapes::{box_mesh, box_triangles, icosphere};
use topology::TriangleMesh;

/// Checks what every step of a chain must satisfy: shape boundary closure,
/// every triangle on three distinct vertices facing its way (non-zero
/// area), and the exact volume.
fn check_step(m: &TriangleMesh, volume: f64, what: &str) {
    assert_eq!(m.check_topology(), Ok(()), "{what}");
    for t in &m.triangles {
        assert!(
            t[0] != t[1] && t[1] != t[2] && t[2] != t[0],
            "{what}: triangle {t:?} repeats a vertex"
        );
        let [a, b, c] = t.map(|i| m.vertices[i as usize]);
        let cross = [
            (b[1] - a[1]) * (c[2] - a[2]) - (b[2] - a[2]) * (c[1] - a[1]),
            (b[2] - a[2]) * (c[0] - a[0]) - (b[0] - a[0]) * (c[2] - a[2]),
            (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]),
        ];
        assert!(
            cross.iter().any(|&x| x != 0.0),
            "{what}: degenerate triangle {t:?}"
        );
    }
    let v = exact_volume(m);
    assert!(
        (v - volume).abs() <= 1e-12 * volume.abs().max(1.0),
        "{what}: volume {v} vs {volume}"
    );
}

/// A box hole through the slab `[0, w] x [0, h] x [0, 1]` in grid cell
/// `(i, j)`, 0.5 x 0.5 x 2, shifted by a dyadic jitter.
fn through_box(i: u32, j: u32, jx: i32, jy: i32) -> TriangleMesh {
    let x = f64::from(i) + 0.25 + f64::from(jx) / 64.0;
    let y = f64::from(j) + 0.25 + f64::from(jy) / 64.0;
    box_triangles([x, y, -0.5], [x + 0.5, y + 0.5, 1.5])
}

#[test]
fn slab_chain_of_50_holes_has_exactly_20k_plus_12_triangles() {
    let mut shape = triangulate_mesh(&box_mesh([0.0; 3], [10.0, 5.0, 1.0]));
    for k in 0..50u32 {
        let jitter = ((k * 7) % 13) as i32 - 6;
        let hole = through_box(k / 5, k % 5, jitter, -jitter / 2);
        let (out, audit) = boolean_triangles_audit(&shape, &hole, BooleanOp::Difference).unwrap();
        audit.verify().unwrap();
        let holes = k as usize + 1;
        check_step(
            &out.mesh,
            50.0 - 0.25 * holes as f64,
            &format!("step {holes}"),
        );
        assert_eq!(out.mesh.triangles.len(), 20 * holes + 12, "step {holes}");
        shape = out.mesh;
    }
}

#[test]
fn an_untouched_operand_keeps_its_triangles() {
    // Disjoint operands: the union is both inputs' triangles, unchanged.
    let a = box_triangles([0.0; 3], [1.0; 3]);
    let b = box_triangles([2.0; 3], [3.0; 3]);
    let out = boolean_triangles(&a, &b, BooleanOp::Union).unwrap();
    assert_eq!(out.mesh.triangles.len(), 24);
    check_step(&out.mesh, 2.0, "disjoint union");
}

#[test]
fn interior_vertices_are_dropped_where_the_boolean_cut_and_kept_elsewhere() {
    // A box whose every face is split into 4 triangles around the centre
    // (an interior vertex per face): the merge hides the centres, so the
    // three faces the corner box cuts are triangulated without theirs,
    // while the three it leaves untouched keep their own triangles.
    let c = test_support::shapes::box_corners([0.0; 3], [2.0; 3]);
    let mut v = c.to_vec();
    let mut tris = Vec::new();
    for q in test_support::shapes::CUBE_FACES {
        let mut m = [0.0; 3];
        for &i in &q {
            for (k, mk) in m.iter_mut().enumerate() {
                *mk += c[i as usize][k] / 4.0;
            }
        }
        let centre = v.len() as u32;
        v.push(m);
        for s in 0..4 {
            tris.push([q[s], q[(s + 1) % 4], centre]);
        }
    }
    let a = TriangleMesh::new(v, tris);
    assert_eq!(a.check_topology(), Ok(()));
    let b = box_triangles([-1.0; 3], [0.5; 3]);
    let (out, audit) = boolean_triangles_audit(&a, &b, BooleanOp::Difference).unwrap();
    audit.verify().unwrap();
    check_step(&out.mesh, 8.0 - 0.125, "corner cut");
    let centres: Vec<[f64; 3]> = (8..14).map(|i| a.vertices[i]).collect();
    let used: Vec<[f64; 3]> = out
        .mesh
        .triangles
        .iter()
        .flatten()
        .map(|&i| out.mesh.vertices[i as usize])
        .collect();
    for c in &centres {
        // The corner box cuts the faces at x = 0, y = 0 and z = 0.
        let cut = c.contains(&0.0);
        assert_eq!(used.contains(c), !cut, "face centre {c:?}");
    }
    // By Euler per face: 3 untouched faces as they were (4 triangles
    // each), 3 faces with the corner notch, hexagons (4 each), the
    // notch's 3 squares (2).
    assert_eq!(out.mesh.triangles.len(), 3 * 4 + 3 * 4 + 3 * 2);
}

#[test]
fn vertices_that_only_subdivide_a_straight_edge_are_dropped_where_cut() {
    // A 2 x 1 x 1 box whose four long faces are each two unit squares (the
    // vertices at x = 1 subdivide the long edges): 20 triangles. Their
    // faces merge into rectangles, which hides the four middle vertices.
    // A union with a disjoint cube keeps both operands as they were (20 +
    // 12 triangles); a union with a box over the far end cuts every long
    // face, and the middle vertices go.
    let mut v = Vec::new();
    for x in [0.0, 1.0, 2.0] {
        for (y, z) in [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)] {
            v.push([x, y, z]);
        }
    }
    // Vertex 4 i + k: x = i, (y, z) corner k going round the x axis.
    let mut tris = Vec::new();
    for i in 0..2u32 {
        for k in 0..4u32 {
            let (a, b) = (4 * i + k, 4 * i + (k + 1) % 4);
            let (c, d) = (a + 4, b + 4);
            tris.push([a, b, d]);
            tris.push([a, d, c]);
        }
    }
    tris.extend([[0, 3, 2], [0, 2, 1], [8, 9, 10], [8, 10, 11]]);
    let a = TriangleMesh::new(v, tris);
    assert_eq!(a.check_topology(), Ok(()));
    assert_eq!(exact_volume(&a), 2.0);
    let b = box_triangles([5.0; 3], [6.0; 3]);
    let (out, audit) = boolean_triangles_audit(&a, &b, BooleanOp::Union).unwrap();
    audit.verify().unwrap();
    check_step(&out.mesh, 3.0, "disjoint union");
    assert_eq!(out.mesh.triangles.len(), 20 + 12);
    assert_eq!(out.mesh.vertices.len(), 12 + 8);
    let end = box_triangles([1.5, -0.5, -0.5], [2.5, 1.5, 1.5]);
    let (out, audit) = boolean_triangles_audit(&a, &end, BooleanOp::Union).unwrap();
    audit.verify().unwrap();
    check_step(&out.mesh, 2.0 + 4.0 - 0.5, "union over the end");
    for t in &out.mesh.triangles {
        for &i in t {
            assert_ne!(out.mesh.vertices[i as usize][0], 1.0, "{t:?}");
        }
    }
}

/// One step of a random chain: a through-box or an icosphere cavity in
/// grid cell `cell` of the 8 x 4 slab.
#[derive(Clone, Debug)]
enum Cut {
    Box { jx: i32, jy: i32 },
    Sphere { jx: i32, jy: i32, r: f64 },
}

fn cut_mesh(cut: &Cut, cell: u32) -> TriangleMesh {
    let (i, j) = (cell % 8, cell / 8);
    match *cut {
        Cut::Box { jx, jy } => through_box(i, j, jx, jy),
        Cut::Sphere { jx, jy, r } => {
            let c = [
                f64::from(i) + 0.5 + f64::from(jx) / 64.0,
                f64::from(j) + 0.5 + f64::from(jy) / 64.0,
                0.5,
            ];
            icosphere(c, r, 1)
        }
    }
}

fn cut_strategy() -> impl Strategy<Value = Cut> {
    prop_oneof![
        (-12i32..=12, -12i32..=12).prop_map(|(jx, jy)| Cut::Box { jx, jy }),
        (-8i32..=8, -8i32..=8, 0.1f64..0.35).prop_map(|(jx, jy, r)| Cut::Sphere { jx, jy, r }),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(test_support::cases(24)))]

    /// Random chains of box holes and sphere cavities in distinct cells:
    /// closure after every step, the exact volume (the slab's minus each
    /// hole's 1/4 and each polyhedral sphere's own exact volume), and the
    /// exact derived triangle count.
    #[test]
    fn random_chains_stay_closed_exact_and_lean(
        cuts in prop::collection::vec(cut_strategy(), 1..10),
        order in Just((0u32..32).collect::<Vec<u32>>()).prop_shuffle(),
    ) {
        let mut shape = triangulate_mesh(&box_mesh([0.0; 3], [8.0, 4.0, 1.0]));
        let mut volume = 32.0;
        let mut count = 12;
        for (step, (cut, &cell)) in cuts.iter().zip(&order).enumerate() {
            let b = cut_mesh(cut, cell);
            match cut {
                Cut::Box { .. } => {
                    volume -= 0.25;
                    count += 20;
                }
                Cut::Sphere { .. } => {
                    volume -= exact_volume(&b);
                    count += b.triangles.len();
                }
            }
            let out = boolean_triangles(&shape, &b, BooleanOp::Difference).unwrap();
            check_step(&out.mesh, volume, &format!("step {step} {cut:?} in {cell}"));
            prop_assert_eq!(out.mesh.triangles.len(), count);
            shape = out.mesh;
        }
    }
}

/// The box `[0, n]^3` with every face split into `n x n` unit squares of
/// two triangles each: vertices inside the faces and on the box's edges
/// that the coplanar merge hides.
fn grid_box(n: u32) -> TriangleMesh {
    use std::collections::HashMap;
    let mut id: HashMap<[u32; 3], u32> = HashMap::new();
    let mut vertices = Vec::new();
    let mut at = |p: [u32; 3]| {
        *id.entry(p).or_insert_with(|| {
            vertices.push(p.map(f64::from));
            vertices.len() as u32 - 1
        })
    };
    let mut triangles = Vec::new();
    // Face `axis = side * n`, spanned by the other two axes (u, w), with
    // the orientation that faces outwards.
    for axis in 0..3 {
        let (u, w) = ((axis + 1) % 3, (axis + 2) % 3);
        for side in [0, 1] {
            for i in 0..n {
                for j in 0..n {
                    let mut corner = |di: u32, dj: u32| {
                        let mut p = [0; 3];
                        p[axis] = side * n;
                        p[u] = i + di;
                        p[w] = j + dj;
                        at(p)
                    };
                    let (a, b, c, d) = (corner(0, 0), corner(1, 0), corner(1, 1), corner(0, 1));
                    if side == 1 {
                        triangles.extend([[a, b, c], [a, c, d]]);
                    } else {
                        triangles.extend([[a, c, b], [a, d, c]]);
                    }
                }
            }
        }
    }
    TriangleMesh::new(vertices, triangles)
}

/// The triangles of `m` by their corners' positions, sorted.
fn triangles_by_position(m: &TriangleMesh) -> Vec<[[f64; 3]; 3]> {
    let mut t: Vec<[[f64; 3]; 3]> = m
        .triangles
        .iter()
        .map(|t| t.map(|v| m.vertices[v as usize]))
        .collect();
    t.sort_by(|a, b| a.partial_cmp(b).unwrap());
    t
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(test_support::cases(24)))]

    /// A box with grid-subdivided faces and a box on the half-integer grid:
    /// with the other box apart, every operation leaves the grid box's
    /// own triangles (the hidden vertices given back); cutting it, the
    /// result is closed and has the exact volume.
    #[test]
    fn untouched_grid_faces_keep_their_triangles(
        n in 1u32..4,
        lo in prop::array::uniform3(-2i32..6),
        size in prop::array::uniform3(1i32..5),
        op in 0u8..3,
    ) {
        let a = grid_box(n);
        prop_assert_eq!(a.check_topology(), Ok(()));
        let lo = lo.map(|x| f64::from(x) / 2.0);
        let hi = [0, 1, 2].map(|k| lo[k] + f64::from(size[k]) / 2.0);
        let b = box_triangles(lo, hi);
        let op = [BooleanOp::Union, BooleanOp::Intersection, BooleanOp::Difference][op as usize];
        let out = boolean_triangles(&a, &b, op).unwrap();
        let nf = f64::from(n);
        let overlap: f64 = (0..3)
            .map(|k| (hi[k].min(nf) - lo[k].max(0.0)).max(0.0))
            .product();
        let (va, vb) = (nf * nf * nf, (0..3).map(|k| hi[k] - lo[k]).product::<f64>());
        let volume = match op {
            BooleanOp::Union => va + vb - overlap,
            BooleanOp::Intersection => overlap,
            _ => va - overlap,
        };
        // Closed with the exact volume (boxes touching in a plane may
        // leave zero-area triangles in the raw result, which smoothing
        // removes, so non-degeneracy is not asked here).
        let what = format!("{op:?} {lo:?} {hi:?} n {n}");
        prop_assert_eq!(out.mesh.check_topology(), Ok(()), "{}", what);
        prop_assert_eq!(exact_volume(&out.mesh), volume, "{}", what);
        let apart = (0..3).any(|k| hi[k] < 0.0 || lo[k] > nf);
        if apart && op != BooleanOp::Intersection {
            let mut want = triangles_by_position(&a);
            if op == BooleanOp::Union {
                want.extend(triangles_by_position(&b));
                want.sort_by(|x, y| x.partial_cmp(y).unwrap());
            }
            prop_assert_eq!(triangles_by_position(&out.mesh), want);
        }
    }
}

/// A chain the random test found (fourth session): a box in cell 4 after
/// boxes and sphere cavities in the cells around it left a retained facet
/// whose loop repeats a vertex; its triangulation must not repeat one.
#[test]
fn chain_with_a_repeated_vertex_loop_stays_valid() {
    let cuts = [
        (Cut::Box { jx: 0, jy: 0 }, 24),
        (
            Cut::Sphere {
                jx: 0,
                jy: 0,
                r: 0.1,
            },
            8,
        ),
        (Cut::Box { jx: 0, jy: -8 }, 2),
        (
            Cut::Sphere {
                jx: 0,
                jy: 0,
                r: 0.1,
            },
            5,
        ),
        (Cut::Box { jx: 0, jy: 0 }, 9),
        (Cut::Box { jx: 0, jy: -8 }, 4),
    ];
    let mut shape = triangulate_mesh(&box_mesh([0.0; 3], [8.0, 4.0, 1.0]));
    let mut volume = 32.0;
    for (step, (cut, cell)) in cuts.iter().enumerate() {
        let b = cut_mesh(cut, *cell);
        volume -= match cut {
            Cut::Box { .. } => 0.25,
            Cut::Sphere { .. } => exact_volume(&b),
        };
        let out = boolean_triangles(&shape, &b, BooleanOp::Difference).unwrap();
        check_step(&out.mesh, volume, &format!("step {step} {cut:?} in {cell}"));
        shape = out.mesh;
    }
}
