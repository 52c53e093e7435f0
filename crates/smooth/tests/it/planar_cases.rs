//! The named cases of 2D smoothing: touching and nearly touching squares
//! through the basic Boolean in both operand orders, a square minus an
//! (almost) identical square, slivers from near-coincident edges.

use crate::planar_support::{set_of, smooth_checked, smooth_checked_area};
use boolean_2d::{boolean, BooleanOp};
use test_support::shapes::{rect, square};

const TOL: f64 = 1e-5;

/// One rectangle `[0, 2 + gap] x [0, 1]` of four edges: the union of the
/// squares `[0, 1]` and `[1 + gap, 2 + gap]` with the gap closed or the
/// overlap merged, and no vertex left on its straight sides.
fn assert_one_box(s: &topology::PolygonSet2, gap: f64) {
    assert_eq!(s.loops().len(), 1, "one ring: {s:?}");
    assert_eq!(s.edge_count(), 4, "a rectangle: {s:?}");
    let want = 2.0 + gap;
    assert!(
        (s.signed_area() - want).abs() < 1e-12,
        "area {} want {want}",
        s.signed_area()
    );
    let bb = s.bounding_box().unwrap();
    for (c, want) in [
        (bb[0][0], 0.0),
        (bb[0][1], 0.0),
        (bb[1][0], 2.0),
        (bb[1][1], 1.0),
    ] {
        assert!((c - want).abs() <= 1e-5, "{bb:?}");
    }
}

#[test]
fn touching_squares_union_both_orders_is_one_box() {
    let a = set_of(&[square(0.0, 0.0, 1.0)]);
    for gap in [0.0, 1e-12, -1e-12, 1e-9, -1e-9, 1e-6, -1e-6] {
        let b = set_of(&[square(1.0 + gap, 0.0, 1.0)]);
        for (x, y) in [(&a, &b), (&b, &a)] {
            let u = boolean(x, y, BooleanOp::Union).unwrap().shape;
            let out = smooth_checked_area(&u, TOL);
            assert_one_box(&out.shape, gap);
        }
        // Also the two squares assembled without a Boolean.
        let mut both = a.clone();
        both.append(&b);
        assert_one_box(&smooth_checked_area(&both, TOL).shape, gap);
    }
}

#[test]
fn square_minus_identical_or_almost_identical_square_is_empty() {
    let a = set_of(&[square(0.0, 0.0, 1.0)]);
    for off in [0.0, 1e-10, -1e-10, 1e-7] {
        for b in [
            set_of(&[square(off, 0.0, 1.0)]),
            set_of(&[square(off, off, 1.0)]),
            set_of(&[rect(0.0, 0.0, 1.0 + off, 1.0)]),
        ] {
            let d = boolean(&a, &b, BooleanOp::Difference).unwrap().shape;
            let out = smooth_checked(&d, TOL);
            assert!(out.shape.is_empty(), "offset {off}: {:?}", out.shape);
            assert_eq!(out.shape.vertex_count(), 0);
        }
    }
}

#[test]
fn slivers_from_near_coincident_edges_vanish() {
    // A 3 x 1 rectangle minus a rectangle sharing its top edge up to 1e-9:
    // the Boolean leaves a sliver of height 1e-9 along the top.
    let a = set_of(&[rect(0.0, 0.0, 3.0, 1.0)]);
    let b = set_of(&[rect(-1.0, 0.5, 5.0, 0.5 + 1e-9)]);
    let d = boolean(&a, &b, BooleanOp::Difference).unwrap().shape;
    let out = smooth_checked_area(&d, TOL);
    assert_eq!(out.shape.loops().len(), 1);
    assert!((out.shape.signed_area() - 1.5).abs() < 1e-8);
    // A slanted sliver: the other operand's edge crosses at a tiny angle.
    let c = set_of(&[vec![
        [-1.0, 0.5],
        [4.0, 0.5],
        [4.0, 1.0 + 1e-8],
        [-1.0, 1.0 - 1e-8],
    ]]);
    let d = boolean(&a, &c, BooleanOp::Difference).unwrap().shape;
    let out = smooth_checked_area(&d, TOL);
    assert_eq!(out.shape.loops().len(), 1, "{:?}", out.shape);
}

#[test]
fn stacked_rows_of_squares_union_to_one_ring() {
    let mut acc = set_of(&[square(0.0, 0.0, 1.0)]);
    for i in 1..6 {
        let nudge = [0.0, 3e-9, -2e-9, 1e-12, -4e-7][i - 1];
        let b = set_of(&[square(f64::from(i as u32) + nudge, 0.0, 1.0)]);
        acc = boolean(&acc, &b, BooleanOp::Union).unwrap().shape;
    }
    let out = smooth_checked_area(&acc, TOL);
    assert_eq!(out.shape.loops().len(), 1);
    assert!((out.shape.signed_area() - 6.0).abs() < 1e-5);
    assert_eq!(out.shape.edge_count(), 4, "{:?}", out.shape);
}

#[test]
fn zero_tolerance_keeps_exact_operations_only() {
    let a = set_of(&[square(0.0, 0.0, 1.0)]);
    let b = set_of(&[square(1.0, 0.0, 1.0)]);
    let mut both = a.clone();
    both.append(&b);
    let out = smooth_checked_area(&both, 0.0);
    assert_eq!(out.shape.loops().len(), 1);
    assert_eq!(out.report.counts.vertices_merged, 2);
    assert_eq!(out.report.counts.half_edges_cancelled, 1);
    assert_eq!(out.report.distortion_bound, 0.0);
}

#[test]
fn dense_clusters_of_near_copies_end_quickly() {
    // 20 copies of a polygon, each moved by less than tol / 4, alternately
    // reversed: they cancel to nothing; with one more copy, one copy is left.
    let base = test_support::shapes::regular_ngon(9, 1.0, 7.0);
    let mut rng = test_support::rng::Xorshift64Star::new(0x5eed);
    let mut cluster = topology::PolygonSet2::new();
    for i in 0..21 {
        let ring: Vec<[f64; 2]> = base
            .iter()
            .map(|p| {
                [
                    p[0] + TOL / 4.0 * (rng.unit() - 0.5),
                    p[1] + TOL / 4.0 * (rng.unit() - 0.5),
                ]
            })
            .collect();
        let s = set_of(&[ring]);
        cluster.append(&if i % 2 == 0 { s } else { s.reversed() });
        if i == 19 {
            let out = smooth_checked(&cluster, TOL);
            assert!(out.shape.is_empty(), "{:?}", out.shape);
        }
    }
    let out = smooth_checked(&cluster, TOL);
    assert_eq!(out.shape.edge_count(), 9);
    let want = set_of(&[base]).signed_area();
    assert!((out.shape.signed_area() - want).abs() < 1e-4);
    assert!(out.report.passes <= 2, "{:?}", out.report);
}

#[test]
fn a_comb_of_vertices_near_an_edge_drifts_within_the_bound() {
    // Figure 6.1: vertices just below a long top edge, each within tol of
    // the edge as it stands after the previous crack.
    let n = 40;
    let mut ring = vec![
        [0.0, 0.0],
        [f64::from(n) + 1.0, 0.0],
        [f64::from(n) + 1.0, 1.0],
    ];
    for i in (1..=n).rev() {
        ring.push([f64::from(i), 1.0 - 0.9 * TOL * f64::from(i % 3)]);
    }
    ring.push([0.0, 1.0]);
    let mut s = set_of(&[ring]);
    // The top edge of a second region right above, drawn as one edge.
    s.add_loop(&[
        [0.0, 1.0 + 0.5 * TOL],
        [f64::from(n) + 1.0, 1.0 + 0.5 * TOL],
        [f64::from(n) + 1.0, 2.0],
        [0.0, 2.0],
    ]);
    let out = smooth_checked_area(&s, TOL);
    // The two regions became one (one anticlockwise ring); what is left of
    // the gap are holes deeper than the tolerance (the checker found no
    // vertex within it of an edge), where the comb dips 1.8 tol.
    let areas: Vec<f64> = out
        .shape
        .loops()
        .iter()
        .map(|l| {
            let p: Vec<[f64; 2]> = l.iter().map(|&v| out.shape.vertex(v)).collect();
            set_of(&[p]).signed_area()
        })
        .collect();
    assert_eq!(areas.iter().filter(|&&a| a > 0.0).count(), 1, "{areas:?}");
    assert!(areas.iter().all(|&a| a > -2.0 * TOL), "{areas:?}");
    assert!(out.report.counts.edges_cracked_by_vertex > 0);
}

#[test]
fn crossings_are_cracked_and_inside_out_parts_dropped() {
    // A bow tie: winding +1 on the left triangle, -1 on the right one.
    let bow = set_of(&[vec![[0.0, 0.0], [2.0, 2.0], [2.0, 0.0], [0.0, 2.0]]]);
    let out = smooth_checked(&bow, TOL);
    let c = out.report.counts;
    assert_eq!(
        (c.edges_cracked_between_edges, c.vertices_created),
        (1, 1),
        "{c:?}"
    );
    assert_eq!(out.shape.edge_count(), 3);
    assert!((out.shape.signed_area() - 1.0).abs() < 1e-15);
    // A pentagram: winding 2 in the centre; the result is its outline.
    let star: Vec<[f64; 2]> = (0..5)
        .map(|i| {
            let a = std::f64::consts::TAU * f64::from(2 * i) / 5.0;
            [a.cos(), a.sin()]
        })
        .collect();
    let star = set_of(&[star]);
    let out = smooth_checked(&star, TOL);
    assert_eq!(out.report.counts.edges_cracked_between_edges, 5);
    assert_eq!(out.shape.vertex_count(), 10);
    let outline = simplify_2d::simplify(&star, simplify_2d::FillRule::Positive).unwrap();
    assert!((out.shape.signed_area() - outline.shape.signed_area()).abs() < 1e-12);
}
