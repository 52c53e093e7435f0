//! The fast path (`boolean`, `boolean_audit`) against the brute-force
//! oracle (`boolean_reference`): the same level-2 data (Table 4.1: `X02`,
//! `X20`, every `X11` with its point) and the same shape, bit for bit, on
//! random, integer-grid (exact ties everywhere) and garbage inputs; and
//! Theorem 2 plus shape boundary closure (section 4.9) on every result.

use boolean_2d::{boolean, boolean_audit, boolean_reference, BooleanOp};
use proptest::prelude::*;
use test_support::shapes::{comb, rect};
use topology::{Edge2, PolygonSet2};

/// A polygon set from loops of points, each loop with a multiplicity.
fn set_from(loops: &[(Vec<[f64; 2]>, i32)]) -> PolygonSet2 {
    let mut vertices = Vec::new();
    let mut edges = Vec::new();
    for (pts, mult) in loops {
        let first = vertices.len() as u32;
        let n = pts.len() as u32;
        vertices.extend_from_slice(pts);
        for i in 0..n {
            edges.push(Edge2 {
                start: first + i,
                end: first + (i + 1) % n,
                mult: *mult,
            });
        }
    }
    PolygonSet2::from_parts(vertices, edges)
}

/// Runs every op both ways and compares fast with reference.
fn agree(a: &PolygonSet2, b: &PolygonSet2) -> Result<(), TestCaseError> {
    for op in BooleanOp::BASIC {
        for (p, q) in [(a, b), (b, a)] {
            let (fast, fast_data) = boolean_audit(p, q, op).expect("valid input");
            let (slow, slow_data) = boolean_reference(p, q, op).expect("valid input");
            prop_assert_eq!(&fast_data, &slow_data, "level data differ for {:?}", op);
            prop_assert_eq!(fast.shape.vertices(), slow.shape.vertices());
            prop_assert_eq!(fast.shape.edges(), slow.shape.edges());
            prop_assert_eq!(fast.intersections, slow.intersections);
            prop_assert!(fast.shape.check_topology().is_ok());
            for &(starts, ends) in &fast_data.composite_counts {
                prop_assert_eq!(starts, ends, "Theorem 2");
            }
            let plain = boolean(p, q, op).expect("valid input");
            // `boolean` records no composite counts; the shape is the same.
            prop_assert_eq!(plain.shape.vertices(), fast.shape.vertices());
            prop_assert_eq!(plain.shape.edges(), fast.shape.edges());
            prop_assert_eq!(plain.intersections, fast.intersections);
        }
    }
    Ok(())
}

fn unit_point() -> impl Strategy<Value = [f64; 2]> + Clone {
    (-1.0f64..1.0, -1.0f64..1.0).prop_map(|(x, y)| [x, y])
}

fn grid_point() -> impl Strategy<Value = [f64; 2]> + Clone {
    (-3i32..=3, -3i32..=3).prop_map(|(x, y)| [f64::from(x), f64::from(y)])
}

/// Garbage within the accepted range: any magnitude, any sign, zeros.
fn garbage_coord() -> impl Strategy<Value = f64> + Clone {
    prop_oneof![
        Just(0.0),
        Just(-0.0),
        (-1e300f64..1e300),
        (-1e-300f64..1e-300),
        (-1.0f64..1.0),
        (any::<i8>()).prop_map(f64::from),
    ]
}

fn garbage_point() -> impl Strategy<Value = [f64; 2]> + Clone {
    (garbage_coord(), garbage_coord()).prop_map(|(x, y)| [x, y])
}

fn loops_of(
    point: impl Strategy<Value = [f64; 2]> + Clone,
) -> impl Strategy<Value = Vec<(Vec<[f64; 2]>, i32)>> {
    proptest::collection::vec(
        (
            proptest::collection::vec(point, 2..12),
            prop_oneof![Just(1), Just(1), Just(-1), Just(2)],
        ),
        1..4,
    )
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(test_support::cases(64)))]

    #[test]
    fn random_loops(a in loops_of(unit_point()), b in loops_of(unit_point())) {
        agree(&set_from(&a), &set_from(&b))?;
    }

    #[test]
    fn integer_grid_ties(a in loops_of(grid_point()), b in loops_of(grid_point())) {
        agree(&set_from(&a), &set_from(&b))?;
    }

    #[test]
    fn garbage(a in loops_of(garbage_point()), b in loops_of(garbage_point())) {
        agree(&set_from(&a), &set_from(&b))?;
    }

    #[test]
    fn shared_vertices_and_collinear_edges(
        a in loops_of(grid_point()),
        shift in 0usize..4,
    ) {
        // B reuses A's own points (rotated loops and reversed), so vertices
        // coincide and edges overlap exactly.
        let b: Vec<_> = a
            .iter()
            .map(|(pts, m)| {
                let mut p = pts.clone();
                let k = shift % p.len();
                p.rotate_left(k);
                if shift % 2 == 1 {
                    p.reverse();
                }
                (p, *m)
            })
            .collect();
        agree(&set_from(&a), &set_from(&b))?;
    }
}

#[test]
fn isolated_vertices_and_zero_multiplicity_edges() {
    let mut a = set_from(&[(vec![[0.0, 0.0], [4.0, 0.0], [4.0, 4.0], [0.0, 4.0]], 1)]);
    a.add_vertex([1.0, 1.0]);
    let extra = a.add_vertex([9.0, 9.0]);
    a.add_edge_mult(0, extra, 0);
    a.add_edge_mult(extra, 0, 0);
    let b = set_from(&[(vec![[2.0, -1.0], [6.0, -1.0], [6.0, 2.0], [2.0, 2.0]], 1)]);
    agree(&a, &b).unwrap();
}

#[test]
fn many_components_and_long_edges() {
    // A checkerboard of small squares against one long thin strip and a big
    // square: many components, one ray cast each.
    let mut loops = Vec::new();
    for i in 0..12 {
        for j in 0..12 {
            if (i + j) % 2 == 0 {
                let (x, y) = (f64::from(i), f64::from(j));
                loops.push((
                    vec![[x, y], [x + 1.0, y], [x + 1.0, y + 1.0], [x, y + 1.0]],
                    1,
                ));
            }
        }
    }
    let a = set_from(&loops);
    let b = set_from(&[
        (
            vec![[-1.0, 5.5], [20.0, 5.25], [20.0, 5.75], [-1.0, 6.0]],
            1,
        ),
        (vec![[3.0, 3.0], [9.0, 3.0], [9.0, 9.0], [3.0, 9.0]], 1),
    ]);
    agree(&a, &b).unwrap();
}

// The adversarial families of a sort-and-sweep broad phase (many boxes
// sharing an x range without overlapping in y) and of per-component ray
// casts (many components in one column). Large enough that the fast path
// abandons its plain active lists for the interval sets over y and the
// Fenwick-tree ray casts, small enough for the quadratic reference.

#[test]
fn interleaved_combs() {
    for shift in [1.0, 0.5, 0.25] {
        let a = set_from(&[(comb(60, 50.0, false, 0.0), 1)]);
        let b = set_from(&[(comb(60, 50.0, true, shift), 1)]);
        agree(&a, &b).unwrap();
    }
    // Teeth of length 1 (the spine's x range is the teeth's): multiplicity
    // 2 against an inside-out comb.
    let a = set_from(&[(comb(60, 2.0, false, 0.0), 2)]);
    let b = set_from(&[(comb(60, 2.0, true, 1.0), -1)]);
    agree(&a, &b).unwrap();
}

#[test]
fn columns_of_squares() {
    // A: unit squares stacked with unit gaps. B: the same column shifted in
    // x by `dx` (0: exact ties in x; -1/2 and 1/2: the corners of one lie
    // inside the other's edges) with squares filling B's gaps exactly
    // (touching A along whole edges), leaving a margin, or overlapping A.
    for dx in [0.0, -0.5, 0.5] {
        for (lo, hi) in [(1.0, 2.0), (1.25, 1.75), (0.5, 1.5)] {
            let a: Vec<_> = (0..64)
                .map(|i| (rect(0.0, 2.0 * f64::from(i), 1.0, 1.0), 1))
                .collect();
            let b: Vec<_> = (0..64)
                .map(|i| (rect(dx, 2.0 * f64::from(i) + lo, 1.0, hi - lo), 1))
                .collect();
            agree(&set_from(&a), &set_from(&b)).unwrap();
        }
    }
    // Components with different multiplicities and orientations, one
    // column of tiny squares inside a big one of the other operand.
    let a: Vec<_> = (0..96)
        .map(|i| {
            let m = [1, -1, 2][i % 3];
            (rect(0.0, i as f64, 0.5, 0.5), m)
        })
        .collect();
    let b = vec![
        (rect(-1.0, -1.0, 3.0, 100.0), 1),
        (rect(0.25, -2.0, 0.125, 200.0), 1),
    ];
    agree(&set_from(&a), &set_from(&b)).unwrap();
}

#[test]
fn grids_of_squares() {
    let side = 16;
    let cells = |parity: usize, shrink: f64, offset: f64| {
        (0..side * side)
            .map(move |c| (c / side, c % side))
            .filter(move |(i, j)| (i + j) % 2 == parity)
            .map(move |(i, j)| {
                let (x, y) = (i as f64 + shrink + offset, j as f64 + shrink + offset);
                (rect(x, y, 1.0 - 2.0 * shrink, 1.0 - 2.0 * shrink), 1)
            })
            .collect::<Vec<_>>()
    };
    // A checkerboard against the other colour: touching at every edge and
    // corner (integer grid, exact ties), and shrunk apart.
    for shrink in [0.0, 0.25] {
        agree(
            &set_from(&cells(0, shrink, 0.0)),
            &set_from(&cells(1, shrink, 0.0)),
        )
        .unwrap();
    }
    // Against the same colour shifted by half a cell: crossings everywhere.
    agree(
        &set_from(&cells(0, 0.0, 0.0)),
        &set_from(&cells(0, 0.0, 0.5)),
    )
    .unwrap();
}
