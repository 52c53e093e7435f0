//! 2D smoothing near contacts (`smooth_polygon_set_near`) against whole
//! smoothing as the oracle: on Boolean results of operands that need no
//! smoothing themselves, with the Boolean's own contacts
//! (`boolean_2d::boolean_with_contacts`), both give the same set, bit for
//! bit, and it is clean; a set that is not simple away from the
//! contacts is smoothed whole; no contacts, contacts over everything,
//! garbage boxes and bad input behave as documented.

use crate::planar_support::{exact_conflicts, set_of};
use boolean_2d::{boolean_with_contacts, BooleanOp};
use proptest::prelude::*;
use smooth::{
    sanity_check_polygon_set, smooth_polygon_set, smooth_polygon_set_near, SmoothError,
    SmoothOptions,
};
use test_support::canonical::set_edges;
use test_support::rng::Xorshift64Star;
use test_support::shapes::{square, Ring};
use topology::{Point2, PolygonSet2};

const OPS: [BooleanOp; 4] = [
    BooleanOp::Union,
    BooleanOp::Intersection,
    BooleanOp::Difference,
    BooleanOp::Xor,
];

/// A random star-shaped polygon of `n` vertices, radii in `[0.5, 1]`.
fn star(rng: &mut Xorshift64Star, n: usize, centre: Point2) -> Ring {
    (0..n)
        .map(|i| {
            let a = (i as f64 + 0.8 * rng.unit()) / n as f64 * std::f64::consts::TAU;
            let r = 0.5 + 0.5 * rng.unit();
            [centre[0] + r * a.cos(), centre[1] + r * a.sin()]
        })
        .collect()
}

/// Whether whole smoothing leaves `s` as it is (the operand needs no
/// smoothing itself).
fn needs_none(s: &PolygonSet2, tol: f64) -> bool {
    let out = smooth_polygon_set(s, &SmoothOptions::new(tol)).unwrap();
    set_edges(&out.shape) == set_edges(s)
}

/// Near and whole smoothing of `op(a, b)` at `tol`: the same edges, and a
/// clean result. Returns the whole result.
fn agree(a: &PolygonSet2, b: &PolygonSet2, op: BooleanOp, tol: f64) -> PolygonSet2 {
    let opts = SmoothOptions::new(tol);
    let (out, contacts) = boolean_with_contacts(a, b, op, tol).unwrap();
    let whole = smooth_polygon_set(&out.shape, &opts).unwrap();
    let near = smooth_polygon_set_near(&out.shape, &opts, &contacts.boxes).unwrap();
    near.shape.check_topology().unwrap();
    // Bit for bit: the same vertices and edges in the same canonical order.
    assert_eq!(
        near.shape,
        whole.shape,
        "{op:?} at {tol}: near {} edges, whole {}",
        near.shape.edge_count(),
        whole.shape.edge_count()
    );
    if whole.report.passes < smooth::MAX_PLANAR_PASSES {
        sanity_check_polygon_set(&near.shape, tol).unwrap();
    }
    assert!(near.report.max_displacement <= near.report.distortion_bound);
    whole.shape
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(test_support::cases(48)))]

    /// A star polygon and a copy jittered by less than the tolerance (a
    /// sliver or a gap along the whole boundary), and a second polygon
    /// beside them that only some operations touch.
    #[test]
    fn near_equals_whole_on_jittered_copies(
        seed in any::<u64>(),
        n in 4usize..40,
        tol in prop::sample::select(vec![1e-7, 1e-5, 1e-3]),
        amount in prop::sample::select(vec![0.125, 0.5, 0.7]),
    ) {
        let mut rng = Xorshift64Star::new(seed);
        let p = star(&mut rng, n, [0.0, 0.0]);
        let j: Ring = p
            .iter()
            .map(|q| {
                let d = tol * amount;
                [q[0] + d * (2.0 * rng.unit() - 1.0), q[1] + d * (2.0 * rng.unit() - 1.0)]
            })
            .collect();
        let far = star(&mut rng, n, [5.0, 0.0]);
        let (a, b) = (set_of(&[p, far]), set_of(&[j]));
        prop_assume!(needs_none(&a, tol) && needs_none(&b, tol));
        for op in OPS {
            agree(&a, &b, op, tol);
        }
    }

    /// Chains of Booleans of grid squares with nudged coincident edges,
    /// each result smoothed before the next step (so both operands are
    /// clean): near and whole smoothing agree at every step.
    #[test]
    fn near_equals_whole_on_square_chains(
        steps in prop::collection::vec(
            (0i32..6, 0i32..6, 1i32..4, 0usize..4, 0usize..6),
            1..7,
        ),
        tol in prop::sample::select(vec![1e-6, 1e-5]),
    ) {
        let nudges: [f64; 6] = [0.0, 1e-12, -1e-12, 3e-9, -1e-8, 2e-7];
        let mut s = set_of(&[square(0.0, 0.0, 2.0)]);
        for &(x, y, size, op, nudge) in &steps {
            let d = nudges[nudge];
            let b = set_of(&[square(f64::from(x) + d, f64::from(y) - d, f64::from(size))]);
            s = agree(&s, &b, OPS[op], tol);
        }
    }
}

/// Garbage contact boxes (inverted, NaN, infinite) never panic, and the
/// result is still checked: a clean set comes back with its edges.
#[test]
fn garbage_boxes_are_harmless() {
    let s = set_of(&[square(0.0, 0.0, 1.0), square(3.0, 0.0, 1.0)]);
    let opts = SmoothOptions::new(1e-6);
    for boxes in [
        vec![[[1.0, 1.0], [0.0, 0.0]]],
        vec![[[f64::NAN, 0.0], [1.0, f64::NAN]]],
        vec![[[f64::NEG_INFINITY; 2], [f64::INFINITY; 2]]],
        vec![[[0.5, 0.5], [0.5, 0.5]]],
        vec![],
    ] {
        let out = smooth_polygon_set_near(&s, &opts, &boxes).unwrap();
        assert_eq!(set_edges(&out.shape), set_edges(&s), "{boxes:?}");
    }
}

/// What lies away from every contact is kept as it is, even where whole
/// smoothing would change it, as long as the set stays simple; a set that
/// is not simple there (crossing edges) is smoothed whole.
#[test]
fn away_from_the_contacts_only_the_check_looks() {
    let opts = SmoothOptions::new(1e-6);
    // Two squares 1e-9 apart: whole smoothing closes the gap, near
    // smoothing with no contact there keeps it (the set is simple).
    let s = set_of(&[square(0.0, 0.0, 1.0), square(1.0 + 1e-9, 0.0, 1.0)]);
    let whole = smooth_polygon_set(&s, &opts).unwrap();
    assert_eq!(whole.shape.edge_count(), 4);
    let far = [[[10.0, 10.0], [11.0, 11.0]]];
    let near = smooth_polygon_set_near(&s, &opts, &far).unwrap();
    assert_eq!(set_edges(&near.shape), set_edges(&s));
    // With the contact where they meet, the gap closes as in whole
    // smoothing.
    let at = [[[1.0 - 1e-6, -1e-6], [1.0 + 1e-6, 1.0 + 1e-6]]];
    let near = smooth_polygon_set_near(&s, &opts, &at).unwrap();
    assert_eq!(set_edges(&near.shape), set_edges(&whole.shape));
    // A bow tie far from the contact: not simple, so smoothed whole.
    let mut t = s.clone();
    t.add_loop(&[[5.0, 0.0], [6.0, 1.0], [6.0, 0.0], [5.0, 1.0]]);
    let whole = smooth_polygon_set(&t, &opts).unwrap();
    let near = smooth_polygon_set_near(&t, &opts, &far).unwrap();
    assert_eq!(set_edges(&near.shape), set_edges(&whole.shape));
    assert_eq!(exact_conflicts(&near.shape), 0);
    sanity_check_polygon_set(&near.shape, 1e-6).unwrap();
}

/// A contact box over everything gives whole smoothing's edges on sets
/// whole smoothing cleans in one pass.
#[test]
fn a_contact_over_everything_is_whole_smoothing() {
    let mut rng = Xorshift64Star::new(3);
    let opts = SmoothOptions::new(1e-4);
    let all = [[[-10.0, -10.0], [10.0, 10.0]]];
    for _ in 0..40 {
        let p = star(&mut rng, 12, [0.0, 0.0]);
        let q: Ring = p
            .iter()
            .map(|v| [v[0] + 5e-5 * rng.unit(), v[1] - 5e-5 * rng.unit()])
            .collect();
        let mut s = set_of(&[p]);
        s.append(&set_of(&[q]).reversed());
        s.add_loop(&[[2.0, 2.0], [3.0, 2.0], [3.0, 3.0], [2.0, 3.0]]);
        let whole = smooth_polygon_set(&s, &opts).unwrap();
        let near = smooth_polygon_set_near(&s, &opts, &all).unwrap();
        assert_eq!(near.shape, whole.shape);
    }
}

/// Bad input gets the error whole smoothing gives, and no panic.
#[test]
fn bad_input_is_refused_as_whole_smoothing_refuses_it() {
    let boxes = [[[0.0, 0.0], [1.0, 1.0]]];
    let good = set_of(&[square(0.0, 0.0, 1.0)]);
    let mut nan = PolygonSet2::new();
    nan.add_loop(&[[0.0, 0.0], [f64::NAN, 0.0], [0.0, 1.0]]);
    let mut open = PolygonSet2::new();
    let v = open.add_vertex([0.0, 0.0]);
    let w = open.add_vertex([1.0, 0.0]);
    open.add_edge(v, w);
    let dangling = PolygonSet2::from_parts(
        vec![[0.0, 0.0]],
        vec![topology::Edge2 {
            start: 0,
            end: 7,
            mult: 1,
        }],
    );
    for (set, tol) in [
        (&nan, 1e-6),
        (&open, 1e-6),
        (&dangling, 1e-6),
        (&good, -1.0),
        (&good, f64::NAN),
        (&good, f64::INFINITY),
    ] {
        let opts = SmoothOptions::new(tol);
        let near = smooth_polygon_set_near(set, &opts, &boxes);
        let whole = smooth_polygon_set(set, &opts);
        assert!(near.is_err(), "{set:?} at {tol}");
        assert_eq!(
            near.err().map(|e: SmoothError| e.to_string()),
            whole.err().map(|e| e.to_string())
        );
    }
}

/// An operand's own exactly collinear vertex, far from every contact:
/// whole smoothing joins its two edges, and so does near smoothing (the
/// check for straight-through vertices left anywhere; New York's borough
/// map carries dozens), so both give the same set.
#[test]
fn straight_through_vertices_away_from_the_contacts_are_joined_as_whole_smoothing_joins_them() {
    let opts = SmoothOptions::new(1e-6);
    // A hexagon with a vertex in the middle of its far left side (whose
    // edges' boxes are far from every contact box), and a square touching
    // its right side across a gap below the tolerance.
    let a = set_of(&[vec![
        [0.0, 0.0],
        [3.0, -1.0],
        [4.0, 0.0],
        [4.0, 1.0],
        [3.0, 2.0],
        [0.0, 1.0],
        [0.0, 0.5],
    ]]);
    let b = set_of(&[square(4.0 + 1e-9, 0.0, 1.0)]);
    for op in OPS {
        let (out, contacts) = boolean_with_contacts(&a, &b, op, 1e-6).unwrap();
        let whole = smooth_polygon_set(&out.shape, &opts).unwrap();
        let near = smooth_polygon_set_near(&out.shape, &opts, &contacts.boxes).unwrap();
        assert_eq!(near.shape, whole.shape, "{op:?}");
        let left = |s: &PolygonSet2| s.vertices().iter().filter(|p| p[0] == 0.0).count();
        if op != BooleanOp::Intersection {
            assert_eq!(left(&near.shape), 2, "{op:?}: the left side is one edge");
        }
    }
}
