//! Booleans through simplification (section 6.1): two operands with
//! separately tracked winding numbers, and n operands in one sweep, checked
//! against the exact per-operand winding-number oracle (every operation
//! over n operands too, `boolean_sets`), including
//! geometrically invalid (self-intersecting, multiply enclosed) operands.

use crate::common::*;
use proptest::prelude::*;
use simplify_2d::*;
use test_support::rng::Xorshift64Star;
use topology::PolygonSet2;

const OPS: [BooleanOp; 4] = [
    BooleanOp::Union,
    BooleanOp::Intersection,
    BooleanOp::Difference,
    BooleanOp::Xor,
];

fn offset(pts: &[[f64; 2]], dx: f64, dy: f64, s: f64) -> Vec<[f64; 2]> {
    pts.iter().map(|p| [p[0] * s + dx, p[1] * s + dy]).collect()
}

#[test]
fn squares() {
    let sq = |x: f64, y: f64| polygon(&[[x, y], [x + 2.0, y], [x + 2.0, y + 2.0], [x, y + 2.0]]);
    let (a, b) = (sq(0.0, 0.0), sq(1.0, 1.0));
    let area = |op| boolean(&a, &b, op).unwrap().shape.signed_area();
    assert_eq!(area(BooleanOp::Union), 7.0);
    assert_eq!(area(BooleanOp::Intersection), 1.0);
    assert_eq!(area(BooleanOp::Difference), 3.0);
    assert_eq!(area(BooleanOp::Xor), 6.0);
    // Touching squares share an edge: the union is one ring, no inner edge.
    let c = sq(2.0, 0.0);
    let u = boolean(&a, &c, BooleanOp::Union).unwrap();
    assert_eq!(u.shape.signed_area(), 8.0);
    assert_eq!(u.shape.loops().len(), 1);
    assert!(boolean(&a, &c, BooleanOp::Intersection)
        .unwrap()
        .shape
        .is_empty());
    // A \ A is empty, A ∪ A is A.
    assert!(boolean(&a, &a, BooleanOp::Difference)
        .unwrap()
        .shape
        .is_empty());
    assert_eq!(
        EdgeCollection::from_polygon_set(&boolean(&a, &a, BooleanOp::Union).unwrap().shape),
        EdgeCollection::from_polygon_set(&a)
    );
}

proptest! {
    #![proptest_config(ProptestConfig { cases: test_support::cases(48), ..ProptestConfig::default() })]

    /// Random (generally self-intersecting) operands: each result cell is
    /// selected by the per-operand exact winding numbers.
    #[test]
    fn binary_ops_match_oracle(na in 3usize..=24, nb in 3usize..=24, sa in any::<u64>(), sb in any::<u64>()) {
        let a = polygon(&random_polygon(na, sa));
        let b = polygon(&offset(&random_polygon(nb, sb), 0.2, -0.1, 0.8));
        let cells = boolean_cells(&a, &b).unwrap();
        cells.check_cells().unwrap();
        let segs = cell_segments(&cells);
        let mut rng = Xorshift64Star::new(sa ^ sb);
        let pts: Vec<[f64; 2]> = (0..40)
            .map(|_| rng.in_disc())
            .filter(|&p| segs.iter().all(|&(s, t)| dist_f64(p, s, t) > 1e-9))
            .collect();
        for op in OPS {
            let out = boolean(&a, &b, op).unwrap();
            out.shape.check_topology().unwrap();
            prop_assert!(out.epsilon > 0.0);
            // The sweep kept only the boundary edges: the same shape and
            // bound as selecting from the complete cell structure.
            prop_assert_eq!(&out.shape, &cells.shape_with(|w| op.selects(w[0] > 0, w[1] > 0)));
            prop_assert_eq!(out.k_max, cells.k_max());
            for &p in &pts {
                let w = [winding_exact(&a, p), winding_exact(&b, p)];
                prop_assert_eq!(winding_f64(&out.shape, p), i32::from(op.selects(w[0] > 0, w[1] > 0)), "{:?} at {:?} w {:?}", op, p, w);
            }
        }
    }

    /// n operands in one sweep: per-operand tracking and the summed union.
    #[test]
    fn n_ary_matches_oracle(specs in proptest::collection::vec((3usize..=10, any::<u64>()), 1..=6)) {
        let sets: Vec<PolygonSet2> = specs
            .iter()
            .enumerate()
            .map(|(i, &(n, s))| polygon(&offset(&random_polygon(n, s), 0.1 * i as f64 - 0.2, 0.0, 0.7)))
            .collect();
        let cells = cell_structure_n(&sets).unwrap();
        cells.check_cells().unwrap();
        let any_pos = boolean_n(&sets, |w| w.iter().any(|&x| x > 0)).unwrap();
        let two = boolean_n(&sets, |w| w.iter().filter(|&&x| x > 0).count() >= 2).unwrap();
        let summed = union_all(&sets).unwrap();
        let by_op: Vec<Simplified> = OPS.iter().map(|&op| boolean_sets(op, &sets).unwrap()).collect();
        for out in [&any_pos, &two, &summed].into_iter().chain(&by_op) {
            out.shape.check_topology().unwrap();
        }
        // Boundary-only sweeps against selecting from every edge.
        prop_assert_eq!(&any_pos.shape, &cells.shape_with(|w| w.iter().any(|&x| x > 0)));
        prop_assert_eq!(&two.shape, &cells.shape_with(|w| w.iter().filter(|&&x| x > 0).count() >= 2));
        prop_assert_eq!(any_pos.k_max, cells.k_max());
        let segs = cell_segments(&cells);
        let mut rng = Xorshift64Star::new(specs[0].1);
        for _ in 0..40 {
            let p = rng.in_disc();
            if segs.iter().any(|&(s, t)| dist_f64(p, s, t) < 1e-9) {
                continue;
            }
            let ws: Vec<i32> = sets.iter().map(|s| winding_exact(s, p)).collect();
            let covered = ws.iter().filter(|&&x| x > 0).count();
            prop_assert_eq!(winding_f64(&any_pos.shape, p), i32::from(covered >= 1));
            prop_assert_eq!(winding_f64(&two.shape, p), i32::from(covered >= 2));
            let total: i32 = ws.iter().sum();
            prop_assert_eq!(winding_f64(&summed.shape, p), i32::from(total > 0));
            for (op, out) in OPS.iter().zip(&by_op) {
                let expected = match op {
                    BooleanOp::Union => covered >= 1,
                    BooleanOp::Intersection => covered == ws.len(),
                    BooleanOp::Difference => ws[0] > 0 && covered == 1,
                    BooleanOp::Xor => covered % 2 == 1,
                };
                prop_assert_eq!(winding_f64(&out.shape, p), i32::from(expected), "{:?} at {:?} w {:?}", op, p, ws);
            }
        }
    }

    /// The n-ary Boolean by operation on two operands is the binary one:
    /// the same shape, bound and adjustment count.
    #[test]
    fn boolean_sets_of_two_is_the_binary_boolean(na in 3usize..=16, nb in 3usize..=16, sa in any::<u64>(), sb in any::<u64>()) {
        let a = polygon(&random_polygon(na, sa));
        let b = polygon(&offset(&random_polygon(nb, sb), 0.2, -0.1, 0.8));
        let sets = [a.clone(), b.clone()];
        for op in OPS {
            let (two, n) = (boolean(&a, &b, op).unwrap(), boolean_sets(op, &sets).unwrap());
            prop_assert_eq!(&two.shape, &n.shape, "{:?}", op);
            prop_assert_eq!(two.k_max, n.k_max);
            prop_assert_eq!(two.epsilon, n.epsilon);
        }
    }

    /// Displaced to the coarse grid: always topologically valid.
    #[test]
    fn binary_ops_on_coarse_grid(na in 3usize..=30, nb in 3usize..=30, sa in any::<u64>(), sb in any::<u64>()) {
        let d = 1.5 * 562_949_953_421_312.0;
        let a = polygon(&displace(&random_polygon(na, sa), d, d));
        let b = polygon(&displace(&random_polygon(nb, sb), d, d));
        boolean_cells(&a, &b).unwrap().check_cells().unwrap();
        for op in OPS {
            boolean(&a, &b, op).unwrap().shape.check_topology().unwrap();
        }
    }
}

/// Union of many disjoint-or-overlapping squares (a checkerboard with
/// overlaps) in one sweep: area by inclusion, exact on this grid.
#[test]
fn union_all_of_grid_squares() {
    let mut sets = Vec::new();
    for i in 0..10 {
        for j in 0..10 {
            let (x, y) = (f64::from(i), f64::from(j));
            sets.push(polygon(&[
                [x, y],
                [x + 1.5, y],
                [x + 1.5, y + 1.5],
                [x, y + 1.5],
            ]));
        }
    }
    let u = union_all(&sets).unwrap();
    u.shape.check_topology().unwrap();
    assert_eq!(u.shape.signed_area(), 10.5 * 10.5);
    assert_eq!(u.shape.loops().len(), 1);
    assert!(u.k_max >= 1 && u.epsilon > 0.0);
    let per = boolean_n(&sets, |w| w.iter().any(|&x| x > 0)).unwrap();
    assert_eq!(
        EdgeCollection::from_polygon_set(&per.shape),
        EdgeCollection::from_polygon_set(&u.shape)
    );
}
