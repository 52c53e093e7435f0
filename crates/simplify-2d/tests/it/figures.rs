//! The examples of the dissertation: the octagon of figure 6.2, the
//! inconsistent configuration of figure 7.4 (points A-G of section 7.2), the
//! overlap cases of figure 6.7, and the rotated n-gon union of Table 7.4.

use crate::common::*;
use simplify_2d::*;
use std::collections::BTreeSet;
use test_support::rng::Xorshift64Star;
use test_support::shapes::regular_ngon;
use topology::PolygonSet2;

/// Samples points in the unit disc far from every cell edge and checks that
/// the shape for `rule` encloses exactly the points whose exact winding
/// number (with respect to `input`) the rule accepts.
fn assert_rule_matches_oracle(input: &PolygonSet2, rule: FillRule, seed: u64) {
    let cells = cell_structure(input).unwrap();
    let shape = cells.shape_with(|w| rule.contains(*w));
    let segs = cell_segments(&cells);
    let mut r = Xorshift64Star::new(seed);
    let mut tested = 0;
    for _ in 0..400 {
        let p = r.in_disc();
        if segs.iter().any(|&(a, b)| dist_f64(p, a, b) < 1e-9) {
            continue;
        }
        tested += 1;
        let w = winding_exact(input, p);
        let got = winding_exact(&shape, p);
        assert_eq!(got, i32::from(rule.contains(w)), "point {p:?}, winding {w}");
    }
    assert!(tested > 300);
}

/// Figure 6.2: an 8-sided random topological polygon with cells of winding
/// number -1, 0, 1 and 2; (c) keeps winding > 0, (d) odd winding.
#[test]
fn figure_6_2_octagon() {
    // Like the dissertation, take the first seeded random octagon whose
    // arrangement has winding numbers -1..2.
    let mut found = None;
    for seed in 0..500u64 {
        let s = polygon(&random_polygon(8, seed));
        let cells = cell_structure(&s).unwrap();
        let ws: BTreeSet<i32> = cells
            .edges()
            .iter()
            .flat_map(|e| [e.left, e.right])
            .collect();
        if ws == BTreeSet::from([-1, 0, 1, 2]) {
            found = Some((seed, s, cells));
            break;
        }
    }
    let (seed, s, cells) = found.expect("an octagon with winding numbers -1..2");
    cells.check_cells().unwrap();
    // (b): every crossing split; the cell structure has no proper crossing.
    assert_eq!(proper_crossings(&cell_segments(&cells)), 0);
    let area = |w: i32| cells.shape_with(|&x| x == w).signed_area();
    let (a_m1, a_1, a_2) = (area(-1), area(1), area(2));
    assert!(a_m1 > 0.0 && a_1 > 0.0 && a_2 > 0.0);
    // Sum of w * A_w is the input's signed area (exact rational value).
    let exact = twice_area_exact(&s);
    let exact = num_traits::ToPrimitive::to_f64(&exact).unwrap() / 2.0;
    assert!((-a_m1 + a_1 + 2.0 * a_2 - exact).abs() < 1e-12);
    // (c) standard form and (d) odd winding.
    let c = simplify(&s, FillRule::Positive).unwrap();
    c.shape.check_topology().unwrap();
    assert!((c.shape.signed_area() - (a_1 + a_2)).abs() < 1e-12);
    let d = simplify(&s, FillRule::EvenOdd).unwrap();
    d.shape.check_topology().unwrap();
    assert!((d.shape.signed_area() - (a_1 + a_m1)).abs() < 1e-12);
    assert_rule_matches_oracle(&s, FillRule::Positive, seed);
    assert_rule_matches_oracle(&s, FillRule::EvenOdd, seed + 1);
    assert_rule_matches_oracle(&s, FillRule::Negative, seed + 2);
    assert_rule_matches_oracle(&s, FillRule::AtLeast2, seed + 3);
    assert_rule_matches_oracle(&s, FillRule::NonZero, seed + 4);
}

const U: f64 = f64::EPSILON / 2.0;

fn fig_7_4_points() -> [[f64; 2]; 7] {
    [
        [0.5 + 9.0 * U, 0.5 + 23.0 * U],  // A
        [0.5 + 23.0 * U, 0.5 + 25.0 * U], // B
        [9.0, 0.5],                       // C
        [9.0, 9.0],                       // D
        [9.0, 32.0],                      // E
        [32.0, 32.0 - 32.0 * U],          // F
        [32.0, 32.0],                     // G
    ]
}

/// Figure 7.4 / section 7.2: the computed relations of the edges AF, AG,
/// BF, BG, CE and vertex D are inconsistent (no valid arrangement has
/// them), yet the sweep must produce a valid cell structure.
#[test]
fn figure_7_4_inconsistent_configuration() {
    let [a, b, c, d, e, f, g] = fig_7_4_points();
    // The relations stated in section 7.2, with the code of Table 7.1.
    let y = robust_arith::y_at_x;
    assert!(b[1] < y(a, f, b[0]) && b[1] < y(a, g, b[0]));
    assert!(f[1] < y(a, g, f[0]) && f[1] < y(b, g, f[0]));
    assert!(d[1] > y(a, f, d[0]) && d[1] > y(a, g, d[0]));
    assert!(d[1] < y(b, f, d[0]) && d[1] < y(b, g, d[0]));
    let far = [0.0, 40.0];
    let variants: Vec<Vec<Vec<[f64; 2]>>> = vec![
        // AF, BG and CE.
        vec![vec![a, f, g, b], vec![c, e, far]],
        // AG, BF and CE.
        vec![vec![a, g, f, b], vec![c, e, far]],
        // Both, with vertex D on CE.
        vec![vec![a, f, g, b], vec![a, g, f, b], vec![c, d, e, far]],
        // D as a separate vertex near the crossings.
        vec![
            vec![a, f, g, b],
            vec![c, e, far],
            vec![d, [20.0, 4.0], [20.0, 6.0]],
        ],
        vec![
            vec![a, f, b, g],
            vec![c, e, far],
            vec![d, [20.0, 4.0], [20.0, 6.0]],
        ],
    ];
    for (i, loops) in variants.iter().enumerate() {
        for reverse in [false, true] {
            let mut s = PolygonSet2::new();
            for l in loops {
                let mut l = l.clone();
                if reverse {
                    l.reverse();
                }
                s.add_loop(&l);
            }
            let cells = cell_structure(&s).unwrap();
            cells
                .check_cells()
                .unwrap_or_else(|err| panic!("variant {i}: {err}"));
            for rule in [
                FillRule::Positive,
                FillRule::NonZero,
                FillRule::EvenOdd,
                FillRule::Negative,
                FillRule::AtLeast2,
            ] {
                let out = cells.shape_with(|w| rule.contains(*w));
                out.check_topology().unwrap();
            }
            // Far from the cluster the winding numbers are exact.
            for p in [[20.0, 25.0], [5.0, 20.0], [30.0, 31.0], [8.0, 0.1]] {
                let w = winding_exact(&s, p);
                let out = cells.shape_with(|&x| x == w);
                if w != 0 {
                    assert_eq!(winding_exact(&out, p), 1, "variant {i} at {p:?}");
                }
            }
        }
    }
}

fn rect(x0: f64, y0: f64, x1: f64, y1: f64) -> Vec<[f64; 2]> {
    vec![[x0, y0], [x1, y0], [x1, y1], [x0, y1]]
}

/// Figure 6.7 (a)-(b): partially coinciding edges in opposite directions;
/// the longer is split at the vertex and the overlapping parts cancel.
#[test]
fn figure_6_7_opposite_overlap_cancels() {
    let mut s = PolygonSet2::new();
    s.add_loop(&rect(0.0, 0.0, 1.0, 1.0));
    s.add_loop(&rect(1.0, 0.5, 2.0, 1.5));
    let cells = cell_structure(&s).unwrap();
    cells.check_cells().unwrap();
    let arr = cells.arrangement();
    // The shared part x = 1, y in [0.5, 1] has cancelled.
    assert!(arr
        .iter()
        .all(|(l, r, _)| !(l == [1.0, 0.5] && r == [1.0, 1.0])));
    let out = simplify(&s, FillRule::Positive).unwrap();
    assert_eq!(out.shape.signed_area(), 2.0);
    assert_eq!(out.shape.loops().len(), 1);
    assert_eq!(out.k_max, 1);
}

/// Figure 6.7 (c): the second rectangle reversed; the overlapping edges go
/// the same way and merge into one edge of multiplicity 2.
#[test]
fn figure_6_7_same_direction_overlap_merges() {
    let mut s = PolygonSet2::new();
    s.add_loop(&rect(0.0, 0.0, 1.0, 1.0));
    let mut r = rect(1.0, 0.5, 2.0, 1.5);
    r.reverse();
    s.add_loop(&r);
    let cells = cell_structure(&s).unwrap();
    cells.check_cells().unwrap();
    let arr = cells.arrangement();
    let shared: Vec<_> = arr
        .iter()
        .filter(|(l, r, _)| *l == [1.0, 0.5] && *r == [1.0, 1.0])
        .collect();
    assert_eq!(shared.len(), 1);
    assert_eq!(shared[0].2, 2);
    let neg = simplify(&s, FillRule::Negative).unwrap();
    assert_eq!(neg.shape.signed_area(), 1.0);
    let nz = simplify(&s, FillRule::NonZero).unwrap();
    assert_eq!(nz.shape.signed_area(), 2.0);
}

/// Full coincidence: identical loops add (winding 2), opposite loops cancel.
#[test]
fn coincident_loops() {
    let sq = rect(0.0, 0.0, 1.0, 1.0);
    let mut s = PolygonSet2::new();
    s.add_loop(&sq);
    s.add_loop(&sq);
    let out = simplify(&s, FillRule::AtLeast2).unwrap();
    assert_eq!(out.shape.signed_area(), 1.0);
    let out = simplify(&s, FillRule::EvenOdd).unwrap();
    assert!(out.shape.is_empty());
    let mut rev = sq.clone();
    rev.reverse();
    s.add_loop(&rev);
    s.add_loop(&rev);
    let cells = cell_structure(&s).unwrap();
    assert!(cells.edges().is_empty());
}

fn ngon(n: usize, rot_deg: f64) -> PolygonSet2 {
    polygon(&regular_ngon(n, 1.0, rot_deg))
}

/// Table 7.4: the union of a regular n-gon and a copy rotated by alpha
/// degrees is one ring of 4n vertices.
#[test]
fn table_7_4_rotated_ngon_union() {
    for &(n, alpha) in &[
        (100, 1.0e-2),
        (100, 0.5e-2),
        (400, 1.0e-2),
        (1000, 1.0e-4),
        (1000, 1.0e-6),
        (5000, 1.581e-9),
    ] {
        let a = ngon(n, 0.0);
        let b = ngon(n, alpha);
        for out in [
            boolean(&a, &b, BooleanOp::Union).unwrap(),
            union_all(&[a.clone(), b.clone()]).unwrap(),
        ] {
            out.shape.check_topology().unwrap();
            let rings = out.shape.loops();
            assert_eq!(rings.len(), 1, "n = {n}, alpha = {alpha}");
            assert_eq!(out.shape.vertex_count(), 4 * n, "n = {n}, alpha = {alpha}");
            assert_eq!(rings[0].len(), 4 * n);
        }
    }
}
