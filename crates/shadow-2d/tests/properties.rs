//! Property tests of level 2 (Table 4.1, eq. 4.1-4.6) over three input
//! generators: random floats in `[-1, 1]`, a small integer grid (exact ties:
//! shared x, collinear and coincident vertices, vertical and zero-length
//! edges) and garbage (random points of mixed magnitude `1e-300..1e300`
//! joined into closed loops).
//!
//! - Theorem 1 at level 2: `X11` never lacks a partner; `X02`/`X20` of a
//!   closed facet never do; re-derived here from the public level-1
//!   functions as well.
//! - Half-edge reversal negates `X11 S11 X02 X20 S02 S20` and keeps points.
//! - `X02` and `X20` equal the exact winding number (exact orientation in
//!   big integers, horizontal-ray crossing rule) in general position; `X11`
//!   equals the exact crossing sign in general position.
//! - On the integer grid every value equals the exact Table 4.1 sum with
//!   exact eq. 4.1 shadows (ties to B).
//! - The closure identities behind Theorem 2 hold for every input:
//!   `sum_h X11(e_A, h) = -(X02(v_e) - X02(v_s))` over a closed facet B and
//!   `sum_h X11(h, e_B) = X20(v_e) - X20(v_s)` over a closed facet A.
//! - The `X11` point lies in both bounding boxes (eq. 8.18-8.19), within
//!   `sqrt(153) u L` of both segments (eq. 8.17), and is the Table 7.2 point.

use num_traits::Signed;
use proptest::prelude::*;
use robust_arith::{interpolate, y_at_x, INTERSECTION_ERROR_FACTOR, UNIT_ROUNDOFF};
use shadow_1d::{x01, x10};
use shadow_2d::{s02, s11, s20, x02, x02_weighted, x11, x20, ShadowError};
use test_support::exact::{distance_to_segment, orient};
use test_support::strategies::{float_coord, garbage_coord, grid_coord};

type P = [f64; 2];
type Facet = Vec<(P, P)>;

// ---------------------------------------------------------------- inputs

#[derive(Clone, Copy, Debug, PartialEq)]
enum Kind {
    Float,
    Grid,
    Garbage,
}

fn coord(kind: Kind) -> BoxedStrategy<f64> {
    match kind {
        Kind::Float => float_coord(),
        Kind::Grid => grid_coord(3),
        Kind::Garbage => garbage_coord(),
    }
}

fn kind() -> impl Strategy<Value = Kind> {
    prop::sample::select(vec![Kind::Float, Kind::Grid, Kind::Garbage])
}

fn point(kind: Kind) -> BoxedStrategy<P> {
    [coord(kind), coord(kind)].boxed()
}

/// A closed facet: 1-3 loops of 1-7 points (a 1-point loop is a
/// zero-length edge; a 2-point loop goes there and back).
fn facet(kind: Kind) -> BoxedStrategy<Facet> {
    prop::collection::vec(prop::collection::vec(point(kind), 1..8), 1..4)
        .prop_map(|loops| {
            let mut f = Vec::new();
            for l in &loops {
                for i in 0..l.len() {
                    f.push((l[i], l[(i + 1) % l.len()]));
                }
            }
            f
        })
        .boxed()
}

/// A vertex, an edge and a closed facet of one generator.
fn case() -> impl Strategy<Value = (Kind, P, P, P, Facet)> {
    kind().prop_flat_map(|k| (Just(k), point(k), point(k), point(k), facet(k)))
}

/// Two edges of one generator.
fn edges() -> impl Strategy<Value = (Kind, [P; 4])> {
    kind().prop_flat_map(|k| (Just(k), [point(k), point(k), point(k), point(k)]))
}

fn reversed(f: &Facet) -> Facet {
    f.iter().map(|&(s, e)| (e, s)).collect()
}

fn lift(p: P, z: f64) -> [f64; 3] {
    [p[0], p[1], z]
}

// --------------------------------------------------------------- oracles

/// The exact winding number of `p` (not on the boundary) by the crossing
/// rule with a horizontal ray: upward edges with `p` strictly left count
/// +1, downward edges with `p` strictly right count -1.
fn winding(p: P, f: &Facet) -> i32 {
    let mut w = 0;
    for &(s, e) in f {
        if s[1] <= p[1] && p[1] < e[1] && orient(s, e, p) > 0 {
            w += 1;
        } else if e[1] <= p[1] && p[1] < s[1] && orient(s, e, p) < 0 {
            w -= 1;
        }
    }
    w
}

/// General position for a point and a facet: the point shares x with no
/// vertex and lies on no edge's line where the edge spans its x or y.
fn general_position(p: P, f: &Facet) -> bool {
    f.iter().all(|&(s, e)| {
        s[0] != p[0] && e[0] != p[0] && s[1] != p[1] && e[1] != p[1] && orient(s, e, p) != 0
    })
}

/// The exact crossing value of two edges in general position (all four
/// orientations non-zero): `+1` when `a0 -> a1` crosses `b0 -> b1` from
/// left to right, `-1` right to left, 0 when they do not cross.
fn exact_crossing(a0: P, a1: P, b0: P, b1: P) -> Option<i32> {
    let (o1, o2) = (orient(b0, b1, a0), orient(b0, b1, a1));
    let (o3, o4) = (orient(a0, a1, b0), orient(a0, a1, b1));
    if o1 == 0 || o2 == 0 || o3 == 0 || o4 == 0 {
        return None;
    }
    Some(if o1 != o2 && o3 != o4 { o1 } else { 0 })
}

/// Exact eq. 4.1 shadows on grid integers (`i128`).
fn gi(p: P) -> [i128; 2] {
    [p[0] as i128, p[1] as i128]
}

/// Exact `S01(v, s -> e)`.
fn exact_s01(v: P, s: P, e: P) -> i32 {
    let (v, s, e) = (gi(v), gi(s), gi(e));
    let x = i32::from(e[0] >= v[0]) - i32::from(s[0] >= v[0]);
    if x == 0 {
        return 0;
    }
    let dx = e[0] - s[0];
    let d = ((s[1] - v[1]) * dx + (v[0] - s[0]) * (e[1] - s[1])).signum() * dx.signum();
    if d >= 0 {
        x
    } else {
        0
    }
}

/// Exact `S10(s -> e, v)`.
fn exact_s10(s: P, e: P, v: P) -> i32 {
    let (v, s, e) = (gi(v), gi(s), gi(e));
    let x = -i32::from(v[0] >= e[0]) + i32::from(v[0] >= s[0]);
    if x == 0 {
        return 0;
    }
    let dx = e[0] - s[0];
    let d = ((s[1] - v[1]) * dx + (v[0] - s[0]) * (e[1] - s[1])).signum() * dx.signum();
    if d <= 0 {
        x
    } else {
        0
    }
}

/// The binary exponent of the power of two `L` bounding the coordinates.
fn l_exp(points: &[P]) -> i64 {
    let m = points.iter().flatten().fold(0.0f64, |m, c| m.max(c.abs()));
    i64::from(robust_arith::power_of_two_bound(m).log2().round() as i32)
}

fn value<const N: usize>(r: Result<Option<shadow_2d::Hit<N>>, ShadowError>) -> i32 {
    r.expect("Theorem 1: partners exist").map_or(0, |h| h.value)
}

/// Theorem 1 re-derived from the public level-1 functions: the lower pairs
/// of `X11(e_A, e_B)` include one where B shadows A and one where A shadows
/// B whenever the Table 4.1 sum is non-zero.
fn theorem_1_x11(a0: P, a1: P, b0: P, b1: P) -> Result<(), TestCaseError> {
    let hits = [
        x01(&a1, &b0, &b1),
        x01(&a0, &b0, &b1).map(|h| h.negated()),
        x10(&a0, &a1, &b1),
        x10(&a0, &a1, &b0).map(|h| h.negated()),
    ];
    let sum: i32 = hits.iter().flatten().map(|h| h.shadow(1)).sum();
    prop_assert_eq!(sum, value(x11(&a0, &a1, &b0, &b1)));
    if sum != 0 {
        prop_assert!(hits.iter().flatten().any(|h| h.delta(1) >= 0.0));
        prop_assert!(hits.iter().flatten().any(|h| h.delta(1) < 0.0));
    }
    Ok(())
}

// ----------------------------------------------------------------- tests

proptest! {
    #![proptest_config(ProptestConfig::with_cases(test_support::cases(512)))]

    /// Theorem 1 at level 2: X11 always, X02/X20 of a closed facet never
    /// report a missing partner, in 2D and 3D.
    #[test]
    fn theorem_1_at_level_2((_k, v, s, e, f) in case(), z in -1.0f64..1.0) {
        prop_assert!(x02(&v, f.iter().copied()).is_ok());
        prop_assert!(x20(f.iter().copied(), &v).is_ok());
        let f3: Vec<_> = f.iter().enumerate()
            .map(|(i, &(a, b))| (lift(a, i as f64 * z), lift(b, (i + 1) as f64 * z))).collect();
        prop_assert!(x02(&lift(v, z), f3.iter().copied()).is_ok());
        prop_assert!(x20(f3.iter().copied(), &lift(v, z)).is_ok());
        for &(hs, he) in &f {
            prop_assert!(x11(&s, &e, &hs, &he).is_ok());
            prop_assert!(x11(&hs, &he, &s, &e).is_ok());
            theorem_1_x11(s, e, hs, he)?;
        }
    }

    /// Section 4.5: reversing a half-edge (or every half-edge of a facet)
    /// negates the function and keeps the intersection points.
    #[test]
    fn reversal_negates((_k, v, s, e, f) in case(), zs in -1.0f64..1.0, ze in -1.0f64..1.0, zv in -1.0f64..1.0) {
        let r = reversed(&f);
        let (h, hr) = (x02(&v, f.iter().copied()).unwrap(), x02(&v, r.iter().copied()).unwrap());
        prop_assert_eq!(h.map(|h| (-h.value, h.a, h.b)), hr.map(|h| (h.value, h.a, h.b)));
        let (h, hr) = (x20(f.iter().copied(), &v).unwrap(), x20(r.iter().copied(), &v).unwrap());
        prop_assert_eq!(h.map(|h| (-h.value, h.a, h.b)), hr.map(|h| (h.value, h.a, h.b)));
        for &(hs, he) in f.iter().take(6) {
            let h = x11(&s, &e, &hs, &he).unwrap();
            for other in [x11(&e, &s, &hs, &he).unwrap(), x11(&s, &e, &he, &hs).unwrap()] {
                prop_assert_eq!(h.map(|h| (-h.value, h.a, h.b)), other.map(|h| (h.value, h.a, h.b)),
                    "X11({:?}->{:?}, {:?}->{:?})", s, e, hs, he);
            }
            // 3D: S11 negates too.
            let (a0, a1, b0, b1) = (lift(s, zs), lift(e, ze), lift(hs, zv), lift(he, -zv));
            prop_assert_eq!(s11(&a0, &a1, &b0, &b1).unwrap(), -s11(&a1, &a0, &b0, &b1).unwrap());
            prop_assert_eq!(s11(&a0, &a1, &b0, &b1).unwrap(), -s11(&a0, &a1, &b1, &b0).unwrap());
        }
        let f3: Vec<_> = f.iter().map(|&(a, b)| (lift(a, zs + a[0] * 0.25), lift(b, zs + b[0] * 0.25))).collect();
        let r3: Vec<_> = f3.iter().map(|&(a, b)| (b, a)).collect();
        prop_assert_eq!(s02(&lift(v, zv), f3.iter().copied()).unwrap(), -s02(&lift(v, zv), r3.iter().copied()).unwrap());
        prop_assert_eq!(s20(f3.iter().copied(), &lift(v, zv)).unwrap(), -s20(r3.iter().copied(), &lift(v, zv)).unwrap());
    }

    /// X02 and X20 are the winding number (Table 4.1 note) in general
    /// position, against an exact oracle, whenever the point is farther
    /// than `4 u L` from every edge (the guarantee of section 8.2/8.6).
    #[test]
    fn x02_x20_are_the_exact_winding_number((_k, v, _s, _e, f) in case()) {
        let mut pts: Vec<P> = f.iter().flat_map(|&(a, b)| [a, b]).collect();
        pts.push(v);
        let le = l_exp(&pts);
        let clear = f.iter().all(|&(a, b)| distance_to_segment(v, a, b, le) > 4.0 * UNIT_ROUNDOFF);
        if clear && general_position(v, &f) {
            let w = winding(v, &f);
            prop_assert_eq!(value(x02(&v, f.iter().copied())), w, "X02 of {:?}", v);
            prop_assert_eq!(value(x20(f.iter().copied(), &v)), w, "X20 of {:?}", v);
        }
    }

    /// X11 is the exact crossing sign in general position, whenever every
    /// end point is farther than `4 u L` from the other segment (then every
    /// Table 7.1 comparison at the ends of the x-overlap is decided
    /// correctly, section 8.2).
    #[test]
    fn x11_is_the_exact_crossing((_k, [a0, a1, b0, b1]) in edges()) {
        let le = l_exp(&[a0, a1, b0, b1]);
        let far = |p: P, s: P, e: P| distance_to_segment(p, s, e, le) > 4.0 * UNIT_ROUNDOFF;
        let clear = far(a0, b0, b1) && far(a1, b0, b1) && far(b0, a0, a1) && far(b1, a0, a1);
        if let Some(want) = exact_crossing(a0, a1, b0, b1).filter(|_| clear) {
            prop_assert_eq!(value(x11(&a0, &a1, &b0, &b1)), want, "{:?}", [a0, a1, b0, b1]);
        }
    }

    /// On the integer grid every level-2 value is the exact Table 4.1 sum of
    /// exact eq. 4.1 shadows (ties to B).
    #[test]
    fn exact_definitions_on_the_grid(v in point(Kind::Grid), s in point(Kind::Grid), e in point(Kind::Grid), f in facet(Kind::Grid)) {
        let want02: i32 = -f.iter().map(|&(hs, he)| exact_s01(v, hs, he)).sum::<i32>();
        prop_assert_eq!(value(x02(&v, f.iter().copied())), want02);
        let want20: i32 = f.iter().map(|&(hs, he)| exact_s10(hs, he, v)).sum();
        prop_assert_eq!(value(x20(f.iter().copied(), &v)), want20);
        for &(hs, he) in &f {
            let want = exact_s01(e, hs, he) - exact_s01(s, hs, he) + exact_s10(s, e, he) - exact_s10(s, e, hs);
            prop_assert_eq!(value(x11(&s, &e, &hs, &he)), want, "X11({:?}->{:?}, {:?}->{:?})", s, e, hs, he);
        }
    }

    /// The identities that make Theorem 2 hold, for any input: over a
    /// closed facet, `sum_h X11(e_A, h) = -(X02(v_e) - X02(v_s))` and
    /// `sum_h X11(h, e_B) = X20(v_e) - X20(v_s)`.
    #[test]
    fn closure_identities((_k, _v, s, e, f) in case()) {
        let sum_b: i32 = f.iter().map(|&(hs, he)| value(x11(&s, &e, &hs, &he))).sum();
        let w = |p: &P| value(x02(p, f.iter().copied()));
        prop_assert_eq!(sum_b, -(w(&e) - w(&s)));
        let sum_a: i32 = f.iter().map(|&(hs, he)| value(x11(&hs, &he, &s, &e))).sum();
        let w = |p: &P| value(x20(f.iter().copied(), p));
        prop_assert_eq!(sum_a, w(&e) - w(&s));
    }

    /// Multiplicities: a half-edge of multiplicity m counts as m copies
    /// (negative: reversed).
    #[test]
    fn weighted_x02_counts_copies((_k, v, _s, _e, f) in case(), m in -3i32..=3) {
        let w = value(x02_weighted(&v, f.iter().map(|&(s, e)| (s, e, m))));
        prop_assert_eq!(w, m * value(x02(&v, f.iter().copied())));
    }

    /// The X11 point: shared by A and B in 2D, inside both bounding boxes
    /// (eq. 8.18-8.19), within sqrt(153) u L of both segments (eq. 8.17),
    /// and in general position the Table 7.2 point from `y_at_x` at the
    /// ends of the x-overlap.
    #[test]
    fn x11_point((k, [a0, a1, b0, b1]) in edges()) {
        let Some(h) = x11(&a0, &a1, &b0, &b1).unwrap() else { return Ok(()) };
        prop_assert_eq!(h.a, h.b);
        let p = h.a;
        for (s, e) in [(a0, a1), (b0, b1)] {
            prop_assert!(s[0].min(e[0]) <= p[0] && p[0] <= s[0].max(e[0]), "x outside bbox: {:?}", p);
            prop_assert!(s[1].min(e[1]) <= p[1] && p[1] <= s[1].max(e[1]), "y outside bbox: {:?}", p);
        }
        let le = l_exp(&[a0, a1, b0, b1]);
        let (da, db) = (distance_to_segment(p, a0, a1, le) / UNIT_ROUNDOFF, distance_to_segment(p, b0, b1, le) / UNIT_ROUNDOFF);
        prop_assert!(da <= INTERSECTION_ERROR_FACTOR && db <= INTERSECTION_ERROR_FACTOR, "{} u L, {} u L", da, db);
        if k == Kind::Float {
            let y = |s: P, e: P, x: f64| if s[0] < e[0] { y_at_x(s, e, x) } else { y_at_x(e, s, x) };
            let x_l = a0[0].min(a1[0]).max(b0[0].min(b1[0]));
            let x_r = a0[0].max(a1[0]).min(b0[0].max(b1[0]));
            let (yal, yar, ybl, ybr) = (y(a0, a1, x_l), y(a0, a1, x_r), y(b0, b1, x_l), y(b0, b1, x_r));
            let want = if ybl >= yal { interpolate(x_l, yal, ybl, x_r, yar, ybr) } else { interpolate(x_r, yar, ybr, x_l, yal, ybl) };
            prop_assert_eq!(p, want);
        }
    }
}

/// A figure-eight (geometrically invalid, section 4.7): winding numbers +1
/// and -1 in its two lobes, exactly as the oracle says.
#[test]
fn figure_eight_has_opposite_lobes() {
    let pts = [[0.0, 0.0], [2.0, 2.0], [2.0, 0.0], [0.0, 2.0]];
    let f: Facet = (0..4).map(|i| (pts[i], pts[(i + 1) % 4])).collect();
    for p in [[0.25, 1.0], [1.75, 1.0], [1.0, 0.25], [1.0, 1.75]] {
        let w = winding(p, &f);
        assert_eq!(value(x02(&p, f.iter().copied())), w, "{p:?}");
    }
    assert_eq!(winding([0.25, 1.0], &f), -winding([1.75, 1.0], &f));
    assert_ne!(winding([0.25, 1.0], &f), 0);
}
