//! Section 4.8 and figure 4.10: a geometrically invalid retained facet
//! (self-intersecting, doubly enclosed, inside-out) must still be
//! triangulated by internal edges into a closed set of triangles, and the
//! triangulation should "minimise how far any geometrically invalid region
//! is extended".
//!
//! The measure of extension used here is the total absolute area of the
//! triangles. The triangles' signed indicator functions add up to the
//! facet's winding number everywhere (the internal edges cancel), so that
//! total is never below the area of the winding-number regions weighted by
//! `|w|`, and everything above it is overlap of oppositely facing triangles,
//! i.e. extension of the invalid region (the shaded area of figure 4.10).
//! Figure 4.10 also shows that a self-intersecting loop cannot reach the
//! `|w|` bound, so for a single loop the oracle is the exact optimum over
//! every triangulation by internal edges; where loops can be triangulated
//! without any overlap the oracle is the `|w|`-weighted area itself.

use boolean_3d::triangulate_facet;
use proptest::prelude::*;
use std::collections::HashMap;
use test_support::rng::Lcg64;

type P2 = [f64; 2];

/// Twice the signed area of the triangle `(a, b, c)`.
fn orient(a: P2, b: P2, c: P2) -> f64 {
    (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
}

/// The total absolute area of triangles given as indices into `p`.
fn abs_area(p: &[P2], tris: &[[u32; 3]]) -> f64 {
    tris.iter()
        .map(|t| orient(p[t[0] as usize], p[t[1] as usize], p[t[2] as usize]).abs() / 2.0)
        .sum()
}

/// The half-edges of a facet bounded by the given loops.
fn half_edges(loops: &[Vec<u32>]) -> Vec<(u32, u32)> {
    loops
        .iter()
        .flat_map(|l| (0..l.len()).map(move |i| (l[i], l[(i + 1) % l.len()])))
        .collect()
}

/// The integral of `|w|` over the plane, where `w` is the winding number
/// of the half-edges (section 4.7), computed exactly up to rounding by a
/// slab decomposition: between consecutive x-coordinates of vertices and
/// edge crossings no two edges cross, so `w` is constant between
/// consecutive edges of a slab and each piece is a trapezoid.
fn winding_abs_area(p: &[P2], hes: &[(u32, u32)]) -> f64 {
    let edges: Vec<(P2, P2)> = hes
        .iter()
        .map(|&(s, e)| (p[s as usize], p[e as usize]))
        .filter(|(a, b)| a[0] != b[0])
        .collect();
    let mut xs: Vec<f64> = edges.iter().flat_map(|(a, b)| [a[0], b[0]]).collect();
    for (i, &(a, b)) in edges.iter().enumerate() {
        for &(c, d) in &edges[i + 1..] {
            let den = (b[0] - a[0]) * (d[1] - c[1]) - (b[1] - a[1]) * (d[0] - c[0]);
            if den != 0.0 {
                let t = ((c[0] - a[0]) * (d[1] - c[1]) - (c[1] - a[1]) * (d[0] - c[0])) / den;
                let u = ((c[0] - a[0]) * (b[1] - a[1]) - (c[1] - a[1]) * (b[0] - a[0])) / den;
                if (0.0..=1.0).contains(&t) && (0.0..=1.0).contains(&u) {
                    xs.push(a[0] + t * (b[0] - a[0]));
                }
            }
        }
    }
    xs.sort_by(f64::total_cmp);
    xs.dedup();
    let y_at = |a: P2, b: P2, x: f64| a[1] + (b[1] - a[1]) * (x - a[0]) / (b[0] - a[0]);
    let mut total = 0.0;
    for w in xs.windows(2) {
        let (x0, x1) = (w[0], w[1]);
        let xm = (x0 + x1) / 2.0;
        // (height at the middle for ordering, mean height, +1 rightwards).
        let mut crossing: Vec<(f64, f64, i32)> = edges
            .iter()
            .filter(|(a, b)| a[0].min(b[0]) <= x0 && a[0].max(b[0]) >= x1)
            .map(|&(a, b)| {
                let dir = if b[0] > a[0] { 1 } else { -1 };
                (y_at(a, b, xm), (y_at(a, b, x0) + y_at(a, b, x1)) / 2.0, dir)
            })
            .collect();
        crossing.sort_by(|a, b| a.0.total_cmp(&b.0));
        // A point's winding number is the sum of the directions of the
        // edges below it (an anticlockwise loop's lower edges run right).
        let mut wn = 0i32;
        for k in 1..crossing.len() {
            wn += crossing[k - 1].2;
            total += f64::from(wn.abs()) * (x1 - x0) * (crossing[k].1 - crossing[k - 1].1);
        }
    }
    total
}

/// The least total absolute area over every triangulation of one loop by
/// internal edges between its vertices (each internal edge splits a
/// polygon in two, so these are the triangulations of a convex polygon
/// with the loop's vertex sequence), by the classic O(n^3) recurrence.
fn optimal_abs_area(p: &[P2], l: &[u32]) -> f64 {
    let n = l.len();
    let mut best = vec![vec![0.0f64; n]; n];
    for len in 2..n {
        for i in 0..n - len {
            let j = i + len;
            best[i][j] = (i + 1..j)
                .map(|k| {
                    let t = orient(p[l[i] as usize], p[l[k] as usize], p[l[j] as usize]);
                    best[i][k] + best[k][j] + t.abs() / 2.0
                })
                .fold(f64::INFINITY, f64::min);
        }
    }
    best[0][n - 1]
}

/// The naive fan triangulation of every loop from its first vertex.
fn fan(loops: &[Vec<u32>]) -> Vec<[u32; 3]> {
    loops
        .iter()
        .flat_map(|l| (1..l.len() - 1).map(move |i| [l[0], l[i], l[i + 1]]))
        .collect()
}

/// Section 4.8's closure requirement: every half-edge of the facet is a
/// side of a triangle, and the remaining triangle sides (the internal
/// edges) come in opposite pairs.
fn closure(hes: &[(u32, u32)], tris: &[[u32; 3]]) -> Result<(), String> {
    let mut count: HashMap<(u32, u32), i64> = HashMap::new();
    for t in tris {
        for (s, e) in [(t[0], t[1]), (t[1], t[2]), (t[2], t[0])] {
            *count.entry((s, e)).or_default() += 1;
        }
    }
    for &(s, e) in hes {
        *count.entry((s, e)).or_default() -= 1;
    }
    for (&(s, e), &c) in &count {
        if s == e {
            continue; // a zero-length side balances itself
        }
        if c < 0 {
            return Err(format!("facet half-edge {s}->{e} is no triangle side"));
        }
        if c != count.get(&(e, s)).copied().unwrap_or(0) {
            return Err(format!("internal edge {s}->{e} is unpaired"));
        }
    }
    Ok(())
}

/// The facet in 3D: a plane over the coordinate plane normal to `axis`,
/// optionally mirrored (facing the other way). Every such plane is an
/// affine image of the 2D drawing, which scales all areas by one constant,
/// so areas are compared on the 2D drawing.
fn embed(p: &[P2], axis: usize, mirror: bool) -> Vec<[f64; 3]> {
    p.iter()
        .map(|&[x, y]| {
            let (u, v) = if mirror { (y, x) } else { (x, y) };
            let mut q = [0.0; 3];
            q[axis] = 1.0 + 0.5 * u - 0.25 * v;
            q[(axis + 1) % 3] = u;
            q[(axis + 2) % 3] = v;
            q
        })
        .collect()
}

/// What the triangulation of a case is held to.
#[derive(Clone, Copy, Debug)]
enum Bound {
    /// The exact optimum over all triangulations of each loop on its own
    /// (the best of figure 4.10's options, generalised).
    BestPerLoop,
    /// The `|w|`-weighted area: the loops can be triangulated without any
    /// overlap, so none may be introduced.
    Winding,
}

/// Checks one facet in every embedding and from every starting vertex:
/// closure, the `|w|` lower bound, and the "as little as possible" upper
/// bound, which the naive fan from the first vertex must break.
fn check_case(name: &str, p: &[P2], loops: &[Vec<u32>], bound: Bound) {
    let hes = half_edges(loops);
    let w = winding_abs_area(p, &hes);
    let best: f64 = loops.iter().map(|l| optimal_abs_area(p, l)).sum();
    let limit = match bound {
        Bound::BestPerLoop => best,
        Bound::Winding => w,
    };
    let tol = 1e-9 * w;
    assert!(
        best >= w - tol,
        "{name}: the optimum {best} is below |w| {w}"
    );
    let naive = abs_area(p, &fan(loops));
    closure(&hes, &fan(loops)).unwrap();
    assert!(
        naive > limit + 1e-3 * w,
        "{name}: the fan ({naive}) meets the bound ({limit}), so the case tests nothing"
    );
    for axis in 0..3 {
        for mirror in [false, true] {
            let v3 = embed(p, axis, mirror);
            for rot in 0..loops[0].len() {
                let mut rotated = loops.to_vec();
                rotated[0].rotate_left(rot);
                let hes = half_edges(&rotated);
                let mut tris = Vec::new();
                triangulate_facet(&v3, &hes, &mut tris);
                let at = format!("{name} (axis {axis}, mirror {mirror}, start {rot})");
                closure(&hes, &tris).unwrap_or_else(|e| panic!("{at}: {e}: {tris:?}"));
                // The closure check is not vacuous: one triangle fewer
                // breaks it.
                assert!(closure(&hes, &tris[1..]).is_err(), "{at}");
                let area = abs_area(p, &tris);
                assert!(area >= w - tol, "{at}: {area} is below |w| {w}");
                assert!(
                    area <= limit + tol,
                    "{at}: triangles cover {area}, more than the bound {limit} \
                     (|w| area {w}, fan {naive}): the invalid region is extended \
                     more than necessary"
                );
            }
        }
    }
}

/// A lemniscate (figure eight) of `n` vertices, none at the crossing, with
/// the right lobe (which runs clockwise, winding number -1) scaled by
/// `right` and everything stretched by `sx` in x.
fn lemniscate(n: usize, sx: f64, right: f64) -> Vec<P2> {
    (0..n)
        .map(|k| {
            let t = std::f64::consts::TAU * (k as f64 + 0.5) / n as f64;
            let d = 1.0 + t.sin().powi(2);
            let (x, y) = (3.0 * t.cos() / d, 3.0 * t.sin() * t.cos() / d);
            let s = if x > 0.0 { right } else { 1.0 };
            [x * s * sx, y * s]
        })
        .collect()
}

/// A five-pointed star (non-convex, so the fan from a tip overlaps
/// itself) of radii 4 and 1.6 about the origin, anticlockwise.
fn star() -> Vec<P2> {
    (0..10)
        .map(|i| {
            let a = std::f64::consts::PI * f64::from(i) / 5.0;
            let r = if i % 2 == 0 { 4.0 } else { 1.6 };
            [r * a.cos(), r * a.sin()]
        })
        .collect()
}

/// Appends `q` to `p` and returns the new vertices' indices in order.
fn add(p: &mut Vec<P2>, q: &[P2]) -> Vec<u32> {
    let base = p.len() as u32;
    p.extend_from_slice(q);
    (base..base + q.len() as u32).collect()
}

#[test]
fn figure_4_10_bow_tie_takes_the_smaller_overlap() {
    // The quadrilateral of figure 4.10: its two lobes have winding numbers
    // +1 and -1, the diagonal 0-2 covers 7.5 and the diagonal 1-3 only 3.5.
    let p = vec![[4.0, 0.0], [0.0, 1.0], [3.0, 2.0], [0.0, 0.0]];
    check_case("bow tie", &p, &[vec![0, 1, 2, 3]], Bound::BestPerLoop);
}

#[test]
fn figure_eight_facets_extend_the_invalid_region_as_little_as_possible() {
    for (n, sx, right) in [
        (8, 1.0, 1.0),
        (12, 1.3, 0.6),
        (16, 1.0, 0.7),
        (20, 1.0, 1.0),
        (24, 0.8, 0.5),
    ] {
        let p = lemniscate(n, sx, right);
        check_case(
            &format!("figure eight n={n} sx={sx} right={right}"),
            &p,
            &[(0..n as u32).collect()],
            Bound::BestPerLoop,
        );
    }
}

#[test]
fn figure_eight_through_a_vertex_covers_only_its_lobes() {
    // Two lobes sharing vertex 0, the right one clockwise (an inside-out
    // region, section 4.7): each lobe can be triangulated on its own
    // without overlap, so no extension is allowed.
    let p = vec![
        [0.0, 0.0],
        [-2.0, 2.0],
        [-2.5, 0.2],
        [-4.0, 0.0],
        [-2.0, -1.5],
        [2.0, 1.5],
        [4.0, 0.0],
        [2.5, -0.2],
        [2.0, -2.0],
    ];
    check_case(
        "figure eight through a vertex",
        &p,
        &[vec![2, 3, 4, 0, 5, 6, 7, 8, 0, 1]],
        Bound::Winding,
    );
}

#[test]
fn facets_with_inside_out_holes_are_not_extended() {
    let mut p = star();
    let outer: Vec<u32> = (0..10).collect();
    // An arrow-shaped loop inside the star running anticlockwise like the
    // outer boundary: a doubly enclosed region (w = 2) instead of a hole.
    let arrow = add(
        &mut p,
        &[
            [-0.5, -0.5],
            [0.6, -0.4],
            [0.0, 0.0],
            [0.5, 0.6],
            [-0.4, 0.5],
        ],
    );
    check_case(
        "star with an anticlockwise hole",
        &p,
        &[outer.clone(), arrow],
        Bound::Winding,
    );
    // A clockwise (hole-like) loop beside the star, to its right and to
    // its left: inside-out regions (w = -1) that no hole bridge may join
    // to the star.
    for (name, dx) in [("right", 0.0), ("left", -12.5)] {
        let mut p = star();
        let q: Vec<P2> = [[5.6, 1.0], [7.0, 0.6], [6.0, 0.0], [7.0, -0.5], [5.5, -1.0]]
            .iter()
            .map(|&[x, y]| [x + dx, y])
            .collect();
        let inside_out = add(&mut p, &q);
        check_case(
            &format!("star with an inside-out loop on its {name}"),
            &p,
            &[outer.clone(), inside_out],
            Bound::Winding,
        );
    }
    // A clockwise hole straddling the star's tip at (4, 0): w = 0 where it
    // overlaps the star and -1 beyond the tip. Triangulating each loop on
    // its own is one admissible triangulation, so no more may be covered.
    let mut p = star();
    let straddle = add(&mut p, &[[3.0, 0.5], [5.0, 0.5], [5.0, -0.5], [3.0, -0.5]]);
    check_case(
        "star with a hole straddling its tip",
        &p,
        &[outer, straddle],
        Bound::BestPerLoop,
    );
}

proptest! {
    #![proptest_config(ProptestConfig { cases: test_support::cases(64), .. ProptestConfig::default() })]

    /// Random loops (almost always self-intersecting): the triangulation is
    /// closed and covers no more than the best triangulation of the loop.
    #[test]
    fn random_loops_are_triangulated_optimally(seed in any::<u64>(), n in 4usize..24) {
        let mut rng = Lcg64::new(seed);
        let p: Vec<P2> = (0..n).map(|_| [rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0)]).collect();
        let l: Vec<u32> = (0..n as u32).collect();
        let hes = half_edges(std::slice::from_ref(&l));
        let mut tris = Vec::new();
        triangulate_facet(&embed(&p, 2, false), &hes, &mut tris);
        prop_assert_eq!(closure(&hes, &tris), Ok(()));
        let w = winding_abs_area(&p, &hes);
        let best = optimal_abs_area(&p, &l);
        let area = abs_area(&p, &tris);
        prop_assert!(area >= w - 1e-9, "{} below |w| {}", area, w);
        prop_assert!(area <= best * (1.0 + 1e-9) + 1e-12, "{} above the optimum {}", area, best);
    }
}
