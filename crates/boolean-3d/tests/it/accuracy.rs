//! Accuracy oracles: exact volumes of box Booleans, sphere Booleans against
//! independently computed volumes, and the winding-number identity of
//! eq. 4.20 checked with an independent generalized winding number.

use crate::common::volume;
use boolean_3d::{boolean_mesh_audit, boolean_triangles_audit, triangulate_mesh, BooleanOp};
use test_support::exact::triangle_mesh_volume as exact_volume;
use test_support::measure::{distance_to_mesh, winding_number};
use test_support::rng::Lcg64;
use test_support::shapes::{box_mesh, box_triangles, icosphere, tetra, uv_sphere};
use topology::TriangleMesh;

fn box_volume(lo: [f64; 3], hi: [f64; 3]) -> f64 {
    (0..3).map(|c| (hi[c] - lo[c]).max(0.0)).product()
}

fn overlap(alo: [f64; 3], ahi: [f64; 3], blo: [f64; 3], bhi: [f64; 3]) -> f64 {
    (0..3)
        .map(|c| (ahi[c].min(bhi[c]) - alo[c].max(blo[c])).max(0.0))
        .product()
}

#[test]
fn overlapping_boxes_have_exact_volumes() {
    // Dyadic coordinates in general position: every volume is exact.
    let (alo, ahi) = ([0.0, 0.0, 0.0], [2.0, 3.0, 4.0]);
    let (blo, bhi) = ([1.0, 1.5, -1.0], [3.5, 2.5, 2.25]);
    let a = box_mesh(alo, ahi);
    let b = box_mesh(blo, bhi);
    let va = box_volume(alo, ahi);
    let vb = box_volume(blo, bhi);
    let vi = overlap(alo, ahi, blo, bhi);
    for (op, want) in [
        (BooleanOp::Union, va + vb - vi),
        (BooleanOp::Intersection, vi),
        (BooleanOp::Difference, va - vi),
    ] {
        let (out, audit) = boolean_mesh_audit(&a, &b, op).unwrap();
        audit.verify().unwrap();
        assert_eq!(exact_volume(&triangulate_mesh(&out.mesh)), want, "{op:?}");
        let (tri, audit) =
            boolean_triangles_audit(&box_triangles(alo, ahi), &box_triangles(blo, bhi), op)
                .unwrap();
        audit.verify().unwrap();
        assert!(tri.mesh.check_topology().is_ok());
        assert_eq!(exact_volume(&tri.mesh), want, "{op:?} triangles");
    }
}

#[test]
fn random_box_pairs_have_the_inclusion_exclusion_volume() {
    let mut rng = Lcg64::new(7);
    for _ in 0..40 {
        let mut r = || (rng.uniform(-4.0, 4.0) * 8.0).round() / 8.0 + 1.0 / 64.0;
        let alo = [r(), r(), r()];
        let ahi = [alo[0] + 2.5, alo[1] + 1.75, alo[2] + 3.0];
        let blo = [r() + 1.0 / 256.0, r() + 1.0 / 256.0, r() + 1.0 / 256.0];
        let bhi = [blo[0] + 3.0, blo[1] + 2.0, blo[2] + 1.5];
        let (va, vb, vi) = (
            box_volume(alo, ahi),
            box_volume(blo, bhi),
            overlap(alo, ahi, blo, bhi),
        );
        for (op, want) in [
            (BooleanOp::Union, va + vb - vi),
            (BooleanOp::Intersection, vi),
            (BooleanOp::Difference, va - vi),
        ] {
            let (out, audit) =
                boolean_mesh_audit(&box_mesh(alo, ahi), &box_mesh(blo, bhi), op).unwrap();
            audit.verify().unwrap();
            let v = volume(&out.mesh);
            assert!(
                (v - want).abs() <= 1e-12 * want.abs().max(1.0),
                "{op:?} {v} {want}"
            );
        }
    }
}

/// Volume of the intersection of two balls (lens), radius r, distance d.
fn lens_volume(r: f64, d: f64) -> f64 {
    std::f64::consts::PI * (4.0 * r + d) * (2.0 * r - d).powi(2) / 12.0
}

#[test]
fn sphere_booleans_approach_the_analytic_volumes() {
    let r = 1.0;
    let d = 0.5;
    let a = icosphere([0.0; 3], r, 3);
    let b = icosphere([d, 0.01, 0.02], r, 3);
    let va = a.signed_volume();
    let vb = b.signed_volume();
    let lens = lens_volume(r, (d * d + 0.0001 + 0.0004f64).sqrt());
    for (op, analytic) in [
        (BooleanOp::Union, va + vb - lens),
        (BooleanOp::Intersection, lens),
        (BooleanOp::Difference, va - lens),
    ] {
        let (out, audit) = boolean_triangles_audit(&a, &b, op).unwrap();
        audit.verify().unwrap();
        assert!(out.mesh.check_topology().is_ok());
        let v = out.mesh.signed_volume();
        // The polyhedral spheres (1280 triangles) differ from the balls by
        // about 1% of their volume.
        assert!(
            (v - analytic).abs() < 0.03 * analytic,
            "{op:?}: {v} vs {analytic}"
        );
    }
    // Inclusion-exclusion holds for the polyhedra themselves up to rounding.
    let u = boolean_triangles_audit(&a, &b, BooleanOp::Union)
        .unwrap()
        .0
        .mesh
        .signed_volume();
    let i = boolean_triangles_audit(&a, &b, BooleanOp::Intersection)
        .unwrap()
        .0
        .mesh
        .signed_volume();
    let dif = boolean_triangles_audit(&a, &b, BooleanOp::Difference)
        .unwrap()
        .0
        .mesh
        .signed_volume();
    assert!((u + i - va - vb).abs() < 1e-12, "{u} + {i} vs {va} + {vb}");
    assert!((dif + i - va).abs() < 1e-12, "{dif} + {i} vs {va}");
}

/// Eq. 4.20 at random points at least `gap` away from both inputs' facets:
/// the generalized winding number of the result equals
/// `c_A a + c_B b + c_I a b` of the inputs' winding numbers.
fn check_winding_identity(a: &TriangleMesh, b: &TriangleMesh, seed: u64, samples: usize, gap: f64) {
    let mut rng = Lcg64::new(seed);
    let mut lo = [f64::INFINITY; 3];
    let mut hi = [f64::NEG_INFINITY; 3];
    for p in a.vertices.iter().chain(b.vertices.iter()) {
        for c in 0..3 {
            lo[c] = lo[c].min(p[c]);
            hi[c] = hi[c].max(p[c]);
        }
    }
    let outs: Vec<_> = BooleanOp::BASIC
        .iter()
        .map(|&op| (op, boolean_triangles_audit(a, b, op).unwrap()))
        .collect();
    for (_, (o, audit)) in &outs {
        audit.verify().unwrap();
        assert!(o.mesh.check_topology().is_ok());
    }
    let mut tested = 0;
    while tested < samples {
        let q = [
            rng.uniform(lo[0] - 0.2, hi[0] + 0.2),
            rng.uniform(lo[1] - 0.2, hi[1] + 0.2),
            rng.uniform(lo[2] - 0.2, hi[2] + 0.2),
        ];
        if distance_to_mesh(a, q) < gap || distance_to_mesh(b, q) < gap {
            continue;
        }
        tested += 1;
        let wa = winding_number(a, q).round() as i64;
        let wb = winding_number(b, q).round() as i64;
        for (op, (o, _)) in &outs {
            let w = winding_number(&o.mesh, q);
            let want = op.result_winding(wa, wb) as f64;
            assert!(
                (w - want).abs() < 1e-6,
                "{op:?} at {q:?}: {w} vs {want} (a {wa}, b {wb})"
            );
        }
    }
}

#[test]
fn winding_identity_eq_4_20_for_spheres() {
    let a = icosphere([0.0; 3], 1.0, 2);
    let b = uv_sphere([0.5, 0.1, -0.2], 0.8, 16, 10);
    check_winding_identity(&a, &b, 11, 150, 1e-3);
}

#[test]
fn winding_identity_eq_4_20_for_boxes_and_tetrahedra() {
    let a = box_triangles([0.0, 0.0, 0.0], [1.0, 1.0, 1.0]);
    let b = tetra([
        [0.3, 0.2, -0.5],
        [1.7, 0.4, 0.4],
        [0.1, 1.6, 0.3],
        [0.5, 0.5, 1.8],
    ]);
    check_winding_identity(&a, &b, 12, 150, 1e-3);
}

#[test]
fn winding_identity_with_multiply_enclosed_and_inside_out_input() {
    // A is two overlapping boxes in one mesh (winding 2 in the overlap);
    // B is an inside-out tetrahedron (winding -1 inside).
    let b1 = box_triangles([0.0; 3], [1.0; 3]);
    let b2 = box_triangles([0.5, 0.25, 0.3], [1.5, 1.2, 1.4]);
    let mut a = b1.clone();
    let off = a.vertices.len() as u32;
    a.vertices.extend(b2.vertices.iter());
    a.triangles
        .extend(b2.triangles.iter().map(|t| t.map(|i| i + off)));
    let mut b = tetra([
        [0.2, 0.1, -0.4],
        [1.8, 0.3, 0.5],
        [0.1, 1.7, 0.2],
        [0.6, 0.6, 1.9],
    ]);
    for t in &mut b.triangles {
        t.swap(1, 2);
    }
    check_winding_identity(&a, &b, 13, 150, 1e-3);
}

#[test]
fn polygon_variant_result_triangulates_to_the_same_volume() {
    let a = box_mesh([0.0; 3], [2.0; 3]);
    let b = box_mesh([0.5, 0.5, -1.0], [1.5, 1.5, 3.0]);
    // A box with a square tunnel: two facets gain holes.
    let (out, audit) = boolean_mesh_audit(&a, &b, BooleanOp::Difference).unwrap();
    audit.verify().unwrap();
    assert!(out.mesh.facets.iter().any(|f| f.loops().len() == 2));
    let tri = triangulate_mesh(&out.mesh);
    assert!(tri.check_topology().is_ok());
    assert_eq!(exact_volume(&tri), 8.0 - 2.0);
    // Every triangle of a valid facet faces the facet's way: the volume is
    // exact and the winding number inside the tunnel is 0.
    assert!(winding_number(&tri, [1.0, 1.0, 1.0]).abs() < 1e-9);
    assert!((winding_number(&tri, [0.25, 0.25, 1.0]) - 1.0).abs() < 1e-9);
}

mod random_placements {
    use super::*;
    use proptest::prelude::*;

    proptest! {
        #![proptest_config(ProptestConfig { cases: test_support::cases(32), .. ProptestConfig::default() })]

        /// Eq. 4.20 for random tetrahedra (either orientation, so winding
        /// numbers -1, 0, 1) against a random box or a second tetrahedron.
        #[test]
        fn winding_identity_for_random_solids(seed in any::<u64>(), kind in 0u32..2) {
            let mut rng = Lcg64::new(seed);
            let mut p = || [rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0)];
            let a = tetra([p(), p(), p(), p()]);
            let b = if kind == 0 {
                let lo = p();
                box_triangles(lo, [lo[0] + 0.9, lo[1] + 0.7, lo[2] + 0.8])
            } else {
                tetra([p(), p(), p(), p()])
            };
            check_winding_identity(&a, &b, seed ^ 0x5eed, 12, 1e-3);
        }
    }
}
