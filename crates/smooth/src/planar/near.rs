//! 2D smoothing near contacts: the phases of Appendix A on only the edges
//! of a polygon set that lie near given boxes, such as the places where
//! the two operands of a 2D Boolean come close (`boolean_2d`'s
//! `PlanarContacts`). Away from them a Boolean's result is made of
//! untouched pieces of one operand, which smoothing leaves as they are
//! when the operands need no smoothing themselves; looking only near the
//! contacts makes the phases cost what the Boolean changed, not the size
//! of the result. The 2D counterpart of `mesh/region.rs`, whose region
//! selection it shares (edges are two-vertex facets to it).
//!
//! The region is every edge whose box comes within `REACH * delta` of a
//! contact box, widened by one ring (every edge sharing a vertex with
//! it). It is cut out as an open edge set over its own vertices, run
//! through the neighbourhood phases of a whole pass (merging, straight-
//! through removal, both crackings) and put back. Putting back is
//! checked, not assumed: the vertices are matched by position, and at
//! every vertex the smoothed region's edges must carry the net flow (out
//! minus in, with multiplicity) that the region's edges carried before,
//! so that with the untouched rest every vertex is balanced again (shape
//! boundary closure, section 4.2). When it is not (smoothing reached the
//! cut), the region grows by a ring, and after [`MAX_GROWTHS`] growths
//! the whole set is smoothed.
//!
//! When the contacts or the region are most of a large set (operands in
//! contact along their whole boundary, such as a map and a copy moved by
//! less than the tolerance), the whole set is smoothed at once instead.
//!
//! The whole result then gets the exact check that ends every pass of
//! whole smoothing (`resolve.rs`: no two edges that cross, touch or
//! overlap, unit multiplicities, every edge with winding number 1 on its
//! left and 0 on its right). A result that fails it, because the
//! operands were not simple themselves or smoothing near the contacts
//! left a conflict with the rest, is smoothed whole instead: the output
//! is always a set that whole smoothing would accept as clean or whole
//! smoothing's own output.

use super::budget::Budget;
use super::resolve::is_simple;
use super::work::Work;
use super::{geom, local_phases, report, smooth_in_range};
use crate::mesh::region::{near_facets, widen, Facets};
use crate::mesh::{MAX_GROWTHS, REACH};
use crate::{SmoothCounts, SmoothError, SmoothOptions, SmoothReport, Smoothed};
use rustc_hash::FxHashMap;
use topology::{Edge2, Point2, Point3, PolygonSet2};

/// Beyond one contact box or one region edge per this many edges of a set
/// of at least [`WHOLE_MIN_EDGES`] edges, the whole set is smoothed
/// instead: the same result where the operands need no smoothing
/// themselves, without the overhead of cutting and putting back (on New
/// York's boroughs against a copy scaled by `1 + 1e-7`, 1.3-1.5 times
/// whole smoothing's time). Smaller sets always take the region, whose
/// overhead is small there.
const WHOLE_FRACTION: usize = 2;

/// See [`WHOLE_FRACTION`].
const WHOLE_MIN_EDGES: usize = 1_000;

/// Whether `count` contact boxes or region edges are most of `edges`.
fn most_of(count: usize, edges: usize) -> bool {
    edges >= WHOLE_MIN_EDGES && count > edges / WHOLE_FRACTION
}

impl Facets for [Edge2] {
    fn count(&self) -> usize {
        self.len()
    }
    fn starts(&self, f: usize) -> impl Iterator<Item = u32> {
        [self[f].start, self[f].end].into_iter()
    }
    fn half_edges(&self, f: usize) -> impl Iterator<Item = (u32, u32)> {
        std::iter::once((self[f].start, self[f].end))
    }
}

/// `e` with its vertices renamed by `to`.
fn renamed(e: &Edge2, to: impl Fn(u32) -> u32) -> Edge2 {
    Edge2 {
        start: to(e.start),
        end: to(e.end),
        mult: e.mult,
    }
}

/// The net flow (out minus in, with multiplicity) of `edges` at every
/// vertex they use; zero entries dropped.
fn flows(edges: impl Iterator<Item = (u32, u32, i64)>) -> FxHashMap<u32, i64> {
    let mut f: FxHashMap<u32, i64> = FxHashMap::default();
    for (s, e, m) in edges {
        *f.entry(s).or_insert(0) += m;
        *f.entry(e).or_insert(0) -= m;
    }
    f.retain(|_, m| *m != 0);
    f
}

/// A region cut out of a set: its edges over its own vertices, and the
/// global index of each of them (local indices in global order, so that
/// merging's "earlier vertex" is the same vertex as in the whole set).
struct Cut {
    sub: PolygonSet2,
    global: Vec<u32>,
}

fn cut(set: &PolygonSet2, region: &[bool]) -> Cut {
    let n = set.vertex_count();
    let mut local = vec![u32::MAX; n];
    for (e, _) in set.edges().iter().zip(region).filter(|(_, &r)| r) {
        local[e.start as usize] = 0;
        local[e.end as usize] = 0;
    }
    let mut global = Vec::new();
    for (v, l) in local.iter_mut().enumerate() {
        if *l == 0 {
            *l = global.len() as u32;
            global.push(v as u32);
        }
    }
    let edges = set
        .edges()
        .iter()
        .zip(region)
        .filter(|(_, &r)| r)
        .map(|(e, _)| renamed(e, |v| local[v as usize]))
        .collect();
    let pts = global.iter().map(|&v| set.vertex(v)).collect();
    Cut {
        sub: PolygonSet2::from_parts(pts, edges),
        global,
    }
}

/// The global index of the region's vertex at each position, or `None`
/// when two of them share a position (then positions do not name the
/// region's vertices, and the whole set is smoothed: checked before any
/// work, since raw maps with borders drawn twice have such pairs
/// everywhere).
fn positions(c: &Cut) -> Option<FxHashMap<(u64, u64), u32>> {
    let mut at: FxHashMap<(u64, u64), u32> = FxHashMap::default();
    at.reserve(c.global.len());
    for (i, p) in c.sub.vertices().iter().enumerate() {
        if at.insert(key(p), c.global[i]).is_some() {
            return None;
        }
    }
    Some(at)
}

fn key(p: &Point2) -> (u64, u64) {
    (p[0].to_bits(), p[1].to_bits())
}

/// The global index of every vertex of the smoothed region: the region's
/// vertex at the same position (smoothing keeps a surviving vertex where
/// it was), or a new index from `next` for a created one.
fn place(out: &[Point2], at: &FxHashMap<(u64, u64), u32>, next: &mut u32) -> Vec<u32> {
    out.iter()
        .map(|p| {
            at.get(&key(p)).copied().unwrap_or_else(|| {
                *next += 1;
                *next - 1
            })
        })
        .collect()
}

/// What smoothing the region gave: its edges in global indices (positive
/// multiplicities), the created vertices (global indices from the input's
/// vertex count on), and the region's report.
struct Region {
    edges: Vec<Edge2>,
    created: Vec<Point2>,
    region: Vec<bool>,
    report: SmoothReport,
}

/// Smooths the region near `contacts`; `None` when the whole set should
/// be smoothed instead: the region is most of it, smoothing reached the
/// cut at every growth, or positions do not name the region's vertices.
fn smooth_region(
    set: &PolygonSet2,
    options: &SmoothOptions,
    contacts: &[[Point2; 2]],
    also: Option<&[bool]>,
) -> Result<Option<Region>, SmoothError> {
    let delta = options.tolerance;
    let lifted: Vec<Point3> = set.vertices().iter().map(|p| [p[0], p[1], 0.0]).collect();
    let boxes: Vec<[Point3; 2]> = contacts
        .iter()
        .map(|b| [[b[0][0], b[0][1], 0.0], [b[1][0], b[1][1], 0.0]])
        .collect();
    let edges = set.edges();
    let mut region = near_facets(&lifted, edges, &boxes, REACH * delta);
    drop(lifted);
    if let Some(also) = also {
        for (r, &a) in region.iter_mut().zip(also) {
            *r |= a;
        }
    }
    let count = region.iter().filter(|&&r| r).count();
    if most_of(count, edges.len()) {
        return Ok(None);
    }
    if count == 0 {
        return Ok(Some(Region {
            edges: Vec::new(),
            created: Vec::new(),
            region,
            report: SmoothReport {
                tolerance: delta,
                passes: 1,
                ..SmoothReport::default()
            },
        }));
    }
    for growth in 0..=MAX_GROWTHS {
        if growth > 0 {
            region = widen(set.vertex_count(), edges, &region);
        }
        let c = cut(set, &region);
        let Some(at) = positions(&c) else {
            return Ok(None);
        };
        let mut counts = SmoothCounts::default();
        let mut budget = Budget::new(options.budget_for(c.sub.vertex_count(), c.sub.edge_count()));
        let mut w = Work::from_set(&c.sub);
        w.normalize(&mut counts);
        let crossing_error = local_phases(&mut w, delta, &mut counts, &mut budget, false)?;
        let mut next = set.vertex_count() as u32;
        let global = place(&w.pts, &at, &mut next);
        let smoothed = w.to_set();
        let new_edges: Vec<Edge2> = smoothed
            .edges()
            .iter()
            .map(|e| renamed(e, |v| global[v as usize]))
            .collect();
        let before = flows(c.sub.edges().iter().map(|e| {
            let g = renamed(e, |v| c.global[v as usize]);
            (g.start, g.end, i64::from(g.mult))
        }));
        let after = flows(
            new_edges
                .iter()
                .map(|e| (e.start, e.end, i64::from(e.mult))),
        );
        if before != after {
            continue;
        }
        let mut created = vec![[0.0; 2]; next as usize - set.vertex_count()];
        for (i, &g) in global.iter().enumerate() {
            if let Some(slot) = (g as usize).checked_sub(set.vertex_count()) {
                created[slot] = w.pts[i];
            }
        }
        let k = w.k_max();
        let max_displacement = w
            .tracked
            .iter()
            .enumerate()
            .filter_map(|(i, t)| t.map(|v| (c.sub.vertex(i as u32), w.pts[v as usize])))
            .map(|(p, q)| geom::dist2(&p, &q).sqrt())
            .fold(0.0f64, f64::max);
        return Ok(Some(Region {
            edges: new_edges,
            created,
            region,
            report: report(
                delta,
                counts,
                1,
                &budget,
                k,
                crossing_error,
                max_displacement,
            ),
        }));
    }
    Ok(None)
}

/// The set with the region's edges replaced by the smoothed ones, the
/// vertices no edge uses dropped (the rest keep their order, created ones
/// follow).
fn put_back(set: &PolygonSet2, r: &Region) -> PolygonSet2 {
    let n = set.vertex_count();
    let mut used = vec![false; n + r.created.len()];
    let kept = set
        .edges()
        .iter()
        .zip(&r.region)
        .filter(|(e, &inside)| !inside && e.mult != 0)
        .map(|(e, _)| *e);
    let edges: Vec<Edge2> = kept.chain(r.edges.iter().copied()).collect();
    for e in &edges {
        used[e.start as usize] = true;
        used[e.end as usize] = true;
    }
    let mut map = vec![u32::MAX; used.len()];
    let mut pts = Vec::with_capacity(used.len());
    for (i, &u) in used.iter().enumerate() {
        if u {
            map[i] = pts.len() as u32;
            pts.push(if i < n {
                set.vertex(i as u32)
            } else {
                r.created[i - n]
            });
        }
    }
    let edges = edges
        .iter()
        .map(|e| renamed(e, |v| map[v as usize]))
        .collect();
    PolygonSet2::from_parts(pts, edges)
}

/// The vertices of `set` that straight-through removal looks at: two
/// edges, one in and one out with the same multiplicity, and the vertex
/// exactly on the open segment between the two neighbours.
fn straight_through(set: &PolygonSet2) -> Vec<u32> {
    let n = set.vertex_count();
    // Per vertex: edge count, and the (neighbour, signed multiplicity) of
    // its first two edges (positive: out of the vertex).
    let mut count = vec![0u8; n];
    let mut ends = vec![[(u32::MAX, 0i32); 2]; n];
    for e in set.edges() {
        for (v, o, m) in [(e.start, e.end, e.mult), (e.end, e.start, -e.mult)] {
            let c = &mut count[v as usize];
            if let Some(slot) = ends[v as usize].get_mut(usize::from(*c)) {
                *slot = (o, m);
            }
            *c = c.saturating_add(1);
        }
    }
    (0..n)
        .filter(|&v| {
            let [(a, ma), (b, mb)] = ends[v];
            count[v] == 2
                && ma == -mb
                && ma != 0
                && geom::on_open_segment(set.vertex(v as u32), set.vertex(a), set.vertex(b))
        })
        .map(|v| v as u32)
        .collect()
}

/// Smooths a polygon set only near `contacts` (boxes `[lo, hi]`, such as
/// `boolean_2d::PlanarContacts::boxes`): the edges whose box comes within
/// [`REACH`]` * tolerance` of a contact box, and their neighbours, go
/// through the phases of [`crate::smooth_polygon_set`]; every other edge
/// is kept as it is. Then the whole result gets whole smoothing's exact
/// check (no crossing, touching or overlapping edges, winding numbers 0
/// and 1), and a result that fails it is smoothed whole instead.
///
/// On a Boolean result of operands that need no smoothing themselves,
/// with the contacts at a proximity of at least the tolerance, the
/// result is whole smoothing's, bit for bit (the same canonical order of
/// vertices and edges), at a cost of the region's size plus one sweep of
/// the result for the check and one parallel sort of it.
/// The input is validated as [`crate::smooth_polygon_set`] validates it.
///
/// ```
/// use smooth::{smooth_polygon_set, smooth_polygon_set_near, SmoothOptions};
/// use topology::PolygonSet2;
///
/// // Two unit squares sharing the edge x = 1, drawn separately: the
/// // place where they meet is the contact.
/// let mut s = PolygonSet2::new();
/// s.add_loop(&[[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]);
/// s.add_loop(&[[1.0, 1e-9], [2.0, 0.0], [2.0, 1.0], [1.0, 1.0]]);
/// let contact = [[1.0 - 1e-6, -1e-6], [1.0 + 1e-6, 1.0 + 1e-6]];
/// let options = SmoothOptions::new(1e-6);
/// let out = smooth_polygon_set_near(&s, &options, &[contact]).unwrap();
/// assert_eq!(out.shape.edge_count(), 4); // one rectangle
/// assert_eq!(out.shape.signed_area(), 2.0);
/// ```
pub fn smooth_polygon_set_near(
    set: &PolygonSet2,
    options: &SmoothOptions,
    contacts: &[[Point2; 2]],
) -> Result<Smoothed<PolygonSet2>, SmoothError> {
    options.validate()?;
    set.validate_coordinates()?;
    set.check_topology()?;
    let coordinates = set.vertices().iter().flatten().copied();
    if options.tolerance == 0.0
        || crate::mesh::range_scale_of(coordinates, options.tolerance).is_some()
    {
        return super::smooth_polygon_set(set, options);
    }
    // Operands in contact along most of their boundary (a copy moved by
    // less than the tolerance, say): the region would be most of the set,
    // and whole smoothing does the same work without cutting and putting
    // back.
    if most_of(contacts.len(), set.edge_count()) {
        return smooth_in_range(set, options);
    }
    let Some(region) = smooth_region(set, options, contacts, None)? else {
        return smooth_in_range(set, options);
    };
    let mut shape = put_back(set, &region);
    let mut report = region.report;
    // Straight-through removal also joins an operand's own straight sides
    // wherever they are, far from the contacts or across the region's
    // cut: such vertices left in the result send their edges through the
    // phases once more, on the result.
    let loose = straight_through(&shape);
    if !loose.is_empty() {
        let mut mark = vec![false; shape.vertex_count()];
        for v in loose {
            mark[v as usize] = true;
        }
        let also: Vec<bool> = shape
            .edges()
            .iter()
            .map(|e| mark[e.start as usize] || mark[e.end as usize])
            .collect();
        let Some(second) = smooth_region(&shape, options, &[], Some(&also))? else {
            return smooth_in_range(set, options);
        };
        shape = put_back(&shape, &second);
        report.counts.add(&second.report.counts);
        report.budget_hit |= second.report.budget_hit;
        report.max_adjustments += second.report.max_adjustments;
        report.distortion_bound += second.report.distortion_bound;
        report.max_displacement += second.report.max_displacement;
        report.epsilon = report.distortion_bound;
    }
    if !is_simple(&shape, shape.vertex_count())? {
        return smooth_in_range(set, options);
    }
    // Whole smoothing's canonical order (every vertex is referenced, so
    // nothing is counted).
    let (shape, _) = Work::from_set(&shape).into_canonical(&mut SmoothCounts::default());
    Ok(Smoothed { shape, report })
}
