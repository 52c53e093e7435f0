//! Property tests of the triangulation of facets with many holes: the
//! indexed search against the linear one (the same triangles, exactly),
//! and the invariants of section 4.8 on random plates with grids of holes,
//! holes touching each other and the outer ring, collinear runs and
//! duplicate points: closure (internal edges in opposite pairs), the
//! triangles' signed area summing exactly to the facet's, `E + 2H - 2`
//! triangles for `E` half-edges and `H` holes, and, on strictly valid
//! plates, no triangle reversed (exact orientation).

use super::tests::balance;
use super::*;
use proptest::prelude::*;
use robust_arith::orient2d;
use std::cmp::Ordering;

/// A plate facet: its 3D positions, half-edges, the (u, v) coordinates of
/// every vertex, the number of holes and whether it is strictly valid
/// (holes disjoint from each other and from the outer ring).
#[derive(Debug)]
struct Plate {
    pts: Vec<Point3>,
    hes: Vec<(u32, u32)>,
    uv: Vec<P2>,
    holes: usize,
    strict: bool,
}

/// What a cell of the plate holds.
#[derive(Clone, Debug)]
enum Cell {
    Empty,
    /// A rectangle `x0..x1 x y0..y1` in sixteenths of the cell (touching
    /// the cell's side where a bound is 0 or 16), each side cut into
    /// `cuts` collinear pieces.
    Rect([u8; 4], u8),
    /// A diamond with corners at the middles of the sides of the
    /// rectangle `x0..x1 x y0..y1`.
    Diamond([u8; 4]),
}

fn cell() -> impl Strategy<Value = Cell> {
    let span = |touch: bool| {
        if touch {
            (0u8..=4, 12u8..=16).boxed()
        } else {
            (1u8..=6, 10u8..=15).boxed()
        }
    };
    prop_oneof![
        2 => Just(Cell::Empty),
        5 => (span(false), span(false), 1u8..=3)
            .prop_map(|((x0, x1), (y0, y1), c)| Cell::Rect([x0, x1, y0, y1], c)),
        2 => (span(true), span(true), 1u8..=2)
            .prop_map(|((x0, x1), (y0, y1), c)| Cell::Rect([x0, x1, y0, y1], c)),
        2 => (span(false), span(false)).prop_map(|((x0, x1), (y0, y1))| {
            // Even bounds: the diamond's corners stay on the grid.
            Cell::Diamond([(x0 + 1) & !1, x1 & !1, (y0 + 1) & !1, y1 & !1])
        }),
    ]
}

/// The corners of a ring cut into collinear pieces: `cuts` pieces per side.
fn cut(corners: &[[i64; 2]], cuts: u8) -> Vec<[i64; 2]> {
    let n = corners.len();
    let k = i64::from(cuts.max(1));
    let mut out = Vec::new();
    for i in 0..n {
        let (p, q) = (corners[i], corners[(i + 1) % n]);
        for t in 0..k {
            // Exact: every side's length is a multiple of 16 or of the
            // cell's sixteenths times 12 (see `plate`).
            out.push([p[0] + (q[0] - p[0]) * t / k, p[1] + (q[1] - p[1]) * t / k]);
        }
    }
    out
}

/// Builds the plate: `w x h` cells of 192 units, the outer ring's sides
/// cut into `outer_cuts` pieces, every ring starting at a vertex chosen by
/// `rot`, `dup` vertices of the outer ring doubled (a second vertex at
/// the same position), embedded in the plane `frame.0 = 7` (mirrored
/// when `frame.1`).
fn plate(
    w: i64,
    h: i64,
    cells: &[Cell],
    outer_cuts: u8,
    rot: usize,
    dup: &[usize],
    frame: (usize, bool),
) -> Plate {
    let (axis, flip) = frame;
    const S: i64 = 192; // the cell side: sixteenths times 12
    let mut uv: Vec<P2> = Vec::new();
    let mut loops: Vec<Vec<u32>> = Vec::new();
    let push_ring = |ring: Vec<[i64; 2]>, uv: &mut Vec<P2>, loops: &mut Vec<Vec<u32>>| {
        let base = uv.len() as u32;
        let n = ring.len();
        uv.extend(ring.iter().map(|p| [p[0] as f64, p[1] as f64]));
        let mut l: Vec<u32> = (0..n as u32).map(|i| base + i).collect();
        l.rotate_left(rot % n);
        loops.push(l);
    };
    let outer = cut(
        &[[0, 0], [w * S, 0], [w * S, h * S], [0, h * S]],
        outer_cuts,
    );
    push_ring(outer, &mut uv, &mut loops);
    // Doubled vertices: a second id at the same position, right after.
    for &d in dup {
        let l = &mut loops[0];
        let at = d % l.len();
        let id = uv.len() as u32;
        uv.push(uv[l[at] as usize]);
        l.insert(at + 1, id);
    }
    let mut holes = 0;
    let mut strict = dup.is_empty();
    for (i, c) in cells.iter().enumerate().take((w * h) as usize) {
        let (ox, oy) = ((i as i64 % w) * S, (i as i64 / w) * S);
        let at = |x: u8, y: u8| [ox + i64::from(x) * 12, oy + i64::from(y) * 12];
        // Clockwise: the facet's interior on the left.
        let ring = match *c {
            Cell::Empty => continue,
            Cell::Rect([x0, x1, y0, y1], cuts) => {
                if [x0, y0].contains(&0) || [x1, y1].contains(&16) {
                    strict = false;
                }
                cut(&[at(x0, y0), at(x0, y1), at(x1, y1), at(x1, y0)], cuts)
            }
            Cell::Diamond([x0, x1, y0, y1]) => {
                let (mx, my) = ((x0 + x1) / 2, (y0 + y1) / 2);
                vec![at(mx, y0), at(x0, my), at(mx, y1), at(x1, my)]
            }
        };
        push_ring(ring, &mut uv, &mut loops);
        holes += 1;
    }
    let mut hes = Vec::new();
    for l in &loops {
        for i in 0..l.len() {
            let (s, e) = (l[i], l[(i + 1) % l.len()]);
            hes.push(if flip { (e, s) } else { (s, e) });
        }
    }
    let pts = uv
        .iter()
        .map(|&[u, v]| match axis {
            0 => [7.0, u, v],
            1 => [v, 7.0, u],
            _ => [u, v, 7.0],
        })
        .collect();
    Plate {
        pts,
        hes,
        uv,
        holes,
        strict,
    }
}

fn plate_strategy() -> impl Strategy<Value = Plate> {
    (1i64..=7, 1i64..=6)
        .prop_flat_map(|(w, h)| {
            (
                Just(w),
                Just(h),
                prop::collection::vec(cell(), (w * h) as usize),
                1u8..=4,
                0usize..64,
                prop::collection::vec(0usize..64, 0..3),
                0usize..3,
                any::<bool>(),
            )
        })
        .prop_map(|(w, h, cells, oc, rot, dup, axis, flip)| {
            plate(w, h, &cells, oc, rot, &dup, (axis, flip))
        })
}

/// Twice the signed area, exact on these integer coordinates.
fn twice_area(uv: &[P2], tris: &[[u32; 3]]) -> f64 {
    tris.iter()
        .map(|t| orient(uv[t[0] as usize], uv[t[1] as usize], uv[t[2] as usize]))
        .sum()
}

fn twice_facet_area(uv: &[P2], hes: &[(u32, u32)]) -> f64 {
    hes.iter()
        .map(|&(s, e)| {
            let (p, q) = (uv[s as usize], uv[e as usize]);
            p[0] * q[1] - p[1] * q[0]
        })
        .sum()
}

fn run(p: &Plate, search: Search) -> Vec<[u32; 3]> {
    let mut t = Vec::new();
    triangulate_facet_by(&p.pts, &p.hes, search, &mut t);
    t
}

/// Asserts the invariants of a plate's triangulation.
fn check(p: &Plate, tris: &[[u32; 3]]) -> Result<(), TestCaseError> {
    prop_assert!(balance(tris, &p.hes));
    prop_assert!(tris
        .iter()
        .all(|t| t[0] != t[1] && t[1] != t[2] && t[2] != t[0]));
    // At most V + 2H - 2 (the ear count of the bridged polygon, whose
    // bridge ends appear twice): a zero-area ear over a repeated vertex (a
    // spike along a bridge, or where a hole touches the boundary) is
    // dropped; the balance above and the exact area below hold either way.
    prop_assert!(tris.len() <= p.hes.len() + 2 * p.holes - 2);
    let want = twice_facet_area(&p.uv, &p.hes);
    prop_assert_eq!(twice_area(&p.uv, tris), want);
    if p.strict {
        let way = if want > 0.0 {
            Ordering::Greater
        } else {
            Ordering::Less
        };
        for t in tris {
            let [a, b, c] = t.map(|i| p.uv[i as usize]);
            let o = orient2d(a, b, c);
            prop_assert!(o == way || o == Ordering::Equal, "reversed {:?}", t);
        }
    }
    Ok(())
}

/// Random loops of garbage coordinates (huge, tiny, repeated, crossing).
fn garbage() -> impl Strategy<Value = (Vec<Point3>, Vec<(u32, u32)>)> {
    let coord = prop_oneof![
        3 => (-40i32..=40).prop_map(f64::from),
        1 => prop::sample::select(vec![1e300, -1e300, 1e-300, 0.5, 1e12, -7.25]),
        1 => -1.0f64..1.0,
    ];
    prop::collection::vec(prop::collection::vec((coord.clone(), coord), 3..40), 1..6).prop_map(
        |loops| {
            let mut pts = Vec::new();
            let mut hes = Vec::new();
            for l in loops {
                let base = pts.len() as u32;
                let n = l.len() as u32;
                pts.extend(l.iter().map(|&(u, v)| [u, v, 0.0]));
                hes.extend((0..n).map(|i| (base + i, base + (i + 1) % n)));
            }
            (pts, hes)
        },
    )
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(test_support::cases(200)))]

    #[test]
    fn plates_keep_the_invariants_and_both_searches_agree(p in plate_strategy()) {
        let indexed = run(&p, Search::Indexed);
        check(&p, &indexed)?;
        prop_assert_eq!(&indexed, &run(&p, Search::Linear));
    }

    #[test]
    fn garbage_is_closed_and_both_searches_agree((pts, hes) in garbage()) {
        let indexed = {
            let mut t = Vec::new();
            triangulate_facet_by(&pts, &hes, Search::Indexed, &mut t);
            t
        };
        let mut linear = Vec::new();
        triangulate_facet_by(&pts, &hes, Search::Linear, &mut linear);
        prop_assert!(balance(&indexed, &hes));
        prop_assert_eq!(indexed, linear);
    }
}

#[test]
fn a_plate_of_1000_holes_keeps_the_invariants() {
    // 40 x 25 cells, a hole in each, some cut into collinear runs, some
    // diamonds: the indexed path, against the linear one on its first
    // rows.
    let cells: Vec<Cell> = (0..1000u32)
        .map(|i| match i % 5 {
            0 => Cell::Diamond([2, 14, 4, 12]),
            1 => Cell::Rect([3, 13, 2, 11], 2),
            _ => Cell::Rect([1 + (i % 3) as u8, 12 + (i % 4) as u8, 2, 14], 1),
        })
        .collect();
    let p = plate(40, 25, &cells, 3, 5, &[], (2, false));
    assert_eq!(p.holes, 1000);
    assert!(p.strict);
    let tris = run(&p, Search::Indexed);
    check(&p, &tris).unwrap();
    let small = plate(40, 4, &cells, 3, 5, &[], (2, false));
    assert_eq!(run(&small, Search::Indexed), run(&small, Search::Linear));
}
