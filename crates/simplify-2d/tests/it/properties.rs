//! Property tests over the corpus of section 7.7: random topological
//! polygons (cyclic sequences of random points in the unit disc) and
//! polygonal stars, undisplaced and displaced by 1.5*2^49 and 1.5*2^47 so
//! that the coordinate grid is coarse (figures 7.12-7.14).
//!
//! Random polygons of 4 to 120 vertices run many cases; those of 200 to
//! 1,000 vertices (the top of section 7.7's range) run a few.
//!
//! Always: valid cell structure, closure for every rule, `simplify` equal
//! to selecting from the complete cell structure, O(n^2) vertices,
//! every cell edge within the reported eps of its original edge (exact
//! rational distance behind a certified floating-point filter). In general
//! position (undisplaced): winding numbers
//! agree with the exact oracle at sampled points and the areas per winding
//! number sum to the exact signed area. Idempotence on clean results.

use crate::common::*;
use proptest::prelude::*;
use simplify_2d::*;
use test_support::rng::Xorshift64Star;
use topology::PolygonSet2;

const D49: f64 = 1.5 * 562_949_953_421_312.0; // 1.5 * 2^49
const D47: f64 = 1.5 * 140_737_488_355_328.0; // 1.5 * 2^47

fn displacement(i: u8) -> (f64, f64) {
    match i % 6 {
        0 => (0.0, 0.0),
        1 => (D49, 0.0),
        2 => (0.0, D49),
        3 => (D49, D49),
        4 => (D47, D47),
        _ => (-D47, D49),
    }
}

const RULES: [FillRule; 5] = [
    FillRule::Positive,
    FillRule::NonZero,
    FillRule::EvenOdd,
    FillRule::Negative,
    FillRule::AtLeast2,
];

/// Is the distance from `p` to segment `a b` at most `eps`? The same
/// verdict as the exact rational test `within_exact`, decided first by a
/// floating-point filter with certified error bounds (it accepts only when
/// the exact test would; everything else goes to the exact test), so that
/// the hundreds of thousands of cell vertices of a 1,000-vertex polygon are
/// checked in milliseconds instead of minutes.
fn within_certified(p: [f64; 2], a: [f64; 2], b: [f64; 2], eps: f64) -> bool {
    // Every product or sum below is rounded at most a few times, each with
    // relative error u = 2^-53; `R` (about 9u) bounds the relative error of
    // each computed quantity with room to spare.
    const R: f64 = 1e-15;
    let e2 = eps * eps * (1.0 - 4.0 * R);
    // Within eps of an end point: the segment is no further away.
    let near = |q: [f64; 2]| {
        let (x, y) = (p[0] - q[0], p[1] - q[1]);
        e2 > 1e-250 && (x * x + y * y) * (1.0 + 4.0 * R) <= e2
    };
    let (px, py) = (p[0] - a[0], p[1] - a[1]);
    let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
    let l2 = dx * dx + dy * dy;
    let cross = px * dy - py * dx;
    let cross_err = R * ((px * dy).abs() + (py * dx).abs());
    let dot = px * dx + py * dy;
    let dot_err = R * ((px * dx).abs() + (py * dy).abs());
    let l2_low = l2 * (1.0 - 4.0 * R);
    // The guard keeps every product far above the subnormal range, where
    // the relative bounds would not hold.
    let normal = e2 * l2_low > 1e-290;
    // The projection certainly falls on the segment (0 <= dot <= l2).
    let inside = dot - dot_err >= 0.0 && dot + dot_err <= l2_low;
    // The distance to the line, |cross| / sqrt(l2), is certainly <= eps.
    let c = (cross.abs() + cross_err) * (1.0 + R);
    let on_line = normal && inside && c * c * (1.0 + 4.0 * R) <= e2 * l2_low;
    let finite = [l2, c, dot, dot_err, e2].iter().all(|v| v.is_finite());
    (finite && (on_line || near(a) || near(b))) || within_exact(p, a, b, eps)
}

/// The invariants that hold for every input.
fn check_always(input: &PolygonSet2, n: usize) -> CellStructure<i32> {
    let cells = cell_structure(input).unwrap();
    cells.check_cells().unwrap();
    for rule in RULES {
        let out = cells.shape_with(|w| rule.contains(*w));
        out.check_topology().unwrap();
        out.validate_coordinates().unwrap();
        // `simplify` keeps only the boundary edges during the sweep: the
        // same shape, bounds and counters as selecting from every edge.
        // Larger inputs may be swept in vertical strips in
        // parallel: a valid shape selecting the same points.
        let simplified = simplify(input, rule).unwrap();
        if input.edge_count() < 64 {
            assert_eq!(simplified.shape, out, "{rule:?}");
            assert_eq!(simplified.k_max, cells.k_max(), "{rule:?}");
            assert_eq!(simplified.epsilon, cells.epsilon(), "{rule:?}");
            assert_eq!(simplified.stats, cells.stats(), "{rule:?}");
        } else {
            check_same_points(&simplified, &out, cells.epsilon(), rule);
        }
    }
    // A caller's predicate, which `simplify` calls through another path
    // than the named rules.
    let custom = simplify(input, FillRule::Custom(|w| w & 1 == 1)).unwrap();
    let odd = cells.shape_with(|w| w & 1 == 1);
    if input.edge_count() < 64 {
        assert_eq!(custom.shape, odd);
    } else {
        check_same_points(&custom, &odd, cells.epsilon(), FillRule::EvenOdd);
    }
    let nv = cells.vertices().len();
    assert!(nv <= 2 * n * n + 8, "{nv} vertices for n = {n}");
    // Provenance: each cell edge within eps of the input edge it came from.
    let eps = cells.epsilon();
    for e in cells.edges() {
        let orig = input.edges()[e.origin as usize];
        let (a, b) = input.edge_points(&orig);
        for v in [e.start, e.end] {
            let p = cells.vertices()[v as usize];
            assert!(
                within_certified(p, a, b, eps),
                "vertex {p:?} further than eps = {eps:e} from its edge {a:?} {b:?} (k = {})",
                e.k
            );
            // The per-edge bound of section 8.4 as well.
            assert!(within_certified(
                p,
                a,
                b,
                (f64::from(e.k) + 1.0) * cells.alpha()
            ));
        }
    }
    cells
}

/// A shape swept in strips against the one-sweep shape `want` (bound
/// `want_eps`): shape boundary closure, and the same winding verdict at
/// sample points of the bounding box farther than both bounds from both
/// boundaries.
fn check_same_points(got: &Simplified, want: &PolygonSet2, want_eps: f64, rule: FillRule) {
    got.shape.check_topology().unwrap();
    got.shape.validate_coordinates().unwrap();
    let segs = |s: &PolygonSet2| -> Vec<([f64; 2], [f64; 2])> {
        s.edges().iter().map(|e| s.edge_points(e)).collect()
    };
    let (a, b) = (segs(&got.shape), segs(want));
    let v = want.vertices();
    if v.is_empty() {
        assert!(got.shape.is_empty(), "{rule:?}");
        return;
    }
    let lo = v
        .iter()
        .fold([f64::INFINITY; 2], |m, p| [m[0].min(p[0]), m[1].min(p[1])]);
    let hi = v.iter().fold([f64::NEG_INFINITY; 2], |m, p| {
        [m[0].max(p[0]), m[1].max(p[1])]
    });
    let away = 2.0 * (got.epsilon + want_eps);
    let mut rng = Xorshift64Star::new(got.shape.vertex_count() as u64);
    for _ in 0..40 {
        let p = [
            lo[0] + (hi[0] - lo[0]) * rng.unit(),
            lo[1] + (hi[1] - lo[1]) * rng.unit(),
        ];
        if a.iter().chain(&b).any(|&(s, t)| dist_f64(p, s, t) <= away) {
            continue;
        }
        assert_eq!(
            winding_f64(&got.shape, p),
            winding_f64(want, p),
            "{rule:?} at {p:?}"
        );
    }
}

/// Oracle checks for data in general position (unit-disc coordinates).
fn check_oracle(input: &PolygonSet2, cells: &CellStructure<i32>, seed: u64) {
    let segs = cell_segments(cells);
    let shapes: Vec<PolygonSet2> = RULES
        .iter()
        .map(|r| cells.shape_with(|w| r.contains(*w)))
        .collect();
    let mut rng = Xorshift64Star::new(seed ^ 0xABCD);
    for _ in 0..40 {
        let p = rng.in_disc();
        if segs.iter().any(|&(a, b)| dist_f64(p, a, b) < 1e-9) {
            continue;
        }
        let w = winding_exact(input, p);
        for (rule, shape) in RULES.iter().zip(&shapes) {
            assert_eq!(
                winding_f64(shape, p),
                i32::from(rule.contains(w)),
                "{rule:?} at {p:?}, exact winding {w}"
            );
        }
    }
    // Sum over w of w * area(w) equals the exact signed area.
    let (lo, hi) = cells
        .edges()
        .iter()
        .flat_map(|e| [e.left, e.right])
        .fold((0, 0), |(lo, hi), w| (lo.min(w), hi.max(w)));
    let mut sum = 0.0;
    for w in lo..=hi {
        if w != 0 {
            sum += f64::from(w) * cells.shape_with(|&x| x == w).signed_area();
        }
    }
    let exact = num_traits::ToPrimitive::to_f64(&twice_area_exact(input)).unwrap() / 2.0;
    assert!((sum - exact).abs() < 1e-9, "{sum} vs exact {exact}");
}

/// Simplifying a computationally clean valid result again gives it back.
fn check_idempotent(out: &PolygonSet2) -> bool {
    if !computationally_clean(out) {
        return false;
    }
    let again = simplify(out, FillRule::Positive).unwrap();
    assert_eq!(
        EdgeCollection::from_polygon_set(&again.shape),
        EdgeCollection::from_polygon_set(out)
    );
    assert_eq!(again.k_max, 0);
    true
}

proptest! {
    #![proptest_config(ProptestConfig { cases: test_support::cases(64), ..ProptestConfig::default() })]

    #[test]
    fn random_polygons(n in 4usize..=120, seed in any::<u64>(), d in 0u8..6) {
        let (dx, dy) = displacement(d);
        let pts = displace(&random_polygon(n, seed), dx, dy);
        let input = polygon(&pts);
        let cells = check_always(&input, n);
        if d == 0 {
            check_oracle(&input, &cells, seed);
        }
    }

    #[test]
    fn stars(n in 5usize..=64, d in 0u8..6) {
        let (dx, dy) = displacement(d);
        let input = polygon(&displace(&star(n), dx, dy));
        let cells = check_always(&input, n);
        if d == 0 {
            check_oracle(&input, &cells, n as u64);
        }
    }

    #[test]
    fn several_loops_with_multiplicity(
        loops in proptest::collection::vec((3usize..=12, any::<u64>(), -2i32..=2), 1..=4),
        d in 0u8..6,
    ) {
        let (dx, dy) = displacement(d);
        let mut input = PolygonSet2::new();
        let mut n = 0;
        for &(k, seed, mult) in &loops {
            let pts = displace(&random_polygon(k, seed), dx, dy);
            let first = input.vertex_count() as u32;
            for &p in &pts {
                input.add_vertex(p);
            }
            for i in 0..k as u32 {
                input.add_edge_mult(first + i, first + (i + 1) % k as u32, mult);
            }
            n += k;
        }
        let cells = check_always(&input, n);
        if d == 0 {
            check_oracle(&input, &cells, n as u64);
        }
    }

    /// Integer-grid ties: vertices on a 4x4 grid give many coincident
    /// vertices, vertex-on-edge cases, collinear overlaps and verticals.
    #[test]
    fn grid_ties(pts in proptest::collection::vec((0i32..4, 0i32..4), 3..=24)) {
        let pts: Vec<[f64; 2]> = pts.iter().map(|&(x, y)| [f64::from(x), f64::from(y)]).collect();
        let input = polygon(&pts);
        let cells = check_always(&input, pts.len());
        // Grid data is exact: the sweep computes the exact arrangement.
        let segs = cell_segments(&cells);
        prop_assert_eq!(proper_crossings(&segs), 0);
        for w in -3..=3 {
            let p = [1.37, 2.21 + 0.01 * f64::from(w)];
            let exact = winding_exact(&input, p);
            let shape = cells.shape_with(|&x| x == exact);
            if exact != 0 {
                prop_assert_eq!(winding_exact(&shape, p), 1);
            }
        }
    }
}

proptest! {
    // Few cases: a 1,000-vertex polygon has about 10^5 crossings, and each
    // case costs up to a second or so in the `test` profile. Shrinking is
    // bounded for the same reason.
    #![proptest_config(ProptestConfig { cases: test_support::cases(8), max_shrink_iters: 32, ..ProptestConfig::default() })]

    /// Section 7.7's sizes up to 1,000 vertices: every case checks the
    /// polygon undisplaced and displaced by 1.5*2^49 or 1.5*2^47 (one of
    /// the five displacements of `displacement`), with the same checks as
    /// the small ones (valid cells, closure for every rule, the O(n^2)
    /// vertex bound, every vertex within eps of its original edge).
    #[test]
    fn large_random_polygons(n in 200usize..=1000, seed in any::<u64>(), d in 1u8..6) {
        let pts = random_polygon(n, seed);
        check_always(&polygon(&pts), n);
        let (dx, dy) = displacement(d);
        check_always(&polygon(&displace(&pts, dx, dy)), n);
    }
}

/// Idempotence over the undisplaced random corpus: every computationally
/// clean result simplifies to itself; most results are clean.
#[test]
fn idempotence_on_clean_results() {
    let mut clean = 0;
    let mut total = 0;
    for seed in 0..60u64 {
        for &n in &[4usize, 7, 12, 20] {
            let input = polygon(&random_polygon(n, seed));
            for rule in [FillRule::Positive, FillRule::EvenOdd] {
                let out = simplify(&input, rule).unwrap();
                total += 1;
                if check_idempotent(&out.shape) {
                    clean += 1;
                }
            }
        }
    }
    eprintln!("idempotence: {clean} of {total} results clean and reproduced exactly");
    assert!(clean * 10 >= total * 8, "{clean} of {total}");
}

/// Geometric validity of the cell structure (no two edges properly
/// crossing) measured over the random corpus and reported; on undisplaced
/// data it is asserted.
#[test]
fn geometric_validity_is_measured() {
    let mut report = Vec::new();
    for d in 0u8..5 {
        let (dx, dy) = displacement(d);
        let mut invalid = 0;
        let mut crossings = 0;
        let mut cases = 0;
        for seed in 0..40u64 {
            let n = 6 + (seed as usize % 20);
            let input = polygon(&displace(&random_polygon(n, seed), dx, dy));
            let cells = cell_structure(&input).unwrap();
            let c = proper_crossings(&cell_segments(&cells));
            cases += 1;
            crossings += c;
            if c > 0 {
                invalid += 1;
            }
        }
        if d == 0 {
            assert_eq!(invalid, 0);
        }
        report.push(format!(
            "displacement {:?}: {invalid}/{cases} cell structures with crossings ({crossings} crossing pairs)",
            displacement(d)
        ));
    }
    for r in report {
        eprintln!("{r}");
    }
}
