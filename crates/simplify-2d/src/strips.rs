//! A simplification's sweep in vertical strips, run in parallel: the input
//! is cut at vertical lines `x = c`, the modified Bentley-Ottmann sweep of
//! section 7.6 runs on each strip by itself, and the strips' boundaries
//! are joined along the cut lines.
//!
//! **Cutting.** The cut lines lie strictly between two consecutive
//! distinct x-values of the input's vertices, at quantiles of them. An edge
//! that crosses a line is split there at `(c, y_at_x(l, r, c))`, the
//! y-value of Table 7.1 on the original segment (within `4 u L` of it,
//! Table 8.1, so well inside the `alpha` of one computed intersection).
//! Each strip receives the pieces between its lines, with the edge's
//! multiplicity and provenance. The union of the strips' input is the
//! input with these points inserted: a perturbation of one adjustment,
//! which the reported bound counts (`k_max + 1`, section 8.4).
//!
//! **Why the joined boundary is valid.** A strip's winding numbers are
//! those of the whole input, since the winding number at a point counts
//! the edges below it at its x (section 7.4.3), and only the strip's edges
//! are there. The join requires of every strip's sweep that every point it
//! processed (the vertices of its whole arrangement, kept edges or not)
//! lies in the closed strip, that no edge of its arrangement lies on a cut
//! line, and that it processed its points in lexicographic order (no
//! backward step of section 7.6.1, so that its output vertices are in
//! order); the sweep records these (`cells::Extent`). Then the edges of two
//! strips meet only at shared vertices on the line between them, and the
//! multiplicity arriving at a point of the line from the left equals the
//! one leaving it to the right (the two pieces of one edge; the
//! arrangement's other points on the line balance by themselves). So the
//! winding number is continuous across the line, every vertex keeps shape
//! boundary closure, and no edge of one strip crosses one of another. If a
//! check fails, the whole input is swept in one strip instead.
//!
//! **Joining.** A cut point through which the boundary passes straight on
//! (one edge `A -> P` from the left, one `P -> B` to the right, in the
//! same direction, and `P` the end of exactly one strip input edge on each
//! side, so that both come from one input edge) is removed, and the two
//! edges become `A -> B`, when the closed triangle `A P B` holds no other
//! vertex of the strips' outputs (exact orientations). Then, when no edge
//! crosses `A P` or `P B` (the sweep's output in general position; on
//! coarse grids it may leave crossings within its bound, section 7.7, and
//! the new edge stays within the same bound), no edge can cross `A B`: it
//! would have to enter the triangle through `A B` and leave through `A P`
//! or `P B` or end inside it. The test runs against every vertex, removed cut points included,
//! so that two new edges cannot cross either. A cut point whose triangle
//! holds a vertex, or whose candidates exceed a budget, stays: the output
//! is valid either way, with one vertex more.
//!
//! **Determinism.** The number of strips and the cut lines depend on the
//! input alone, never on the thread count, so the result is the same on
//! any machine.

use crate::cells::{CellStructure, Extent, Keyed, SweepStats};
use crate::point::Pt;
use crate::sweep::{run_with, InputEdge, Output};
use crate::winding::Winding;
use crate::SimplifyError;
use robust_arith::{orient2d, y_at_x};
use std::cmp::Ordering;

/// The number of strips for these input edges: two when the sweep's work
/// is dominated by crossings and large enough, else one. The crossings are
/// bounded first by the edges times a quarter of the mean number of edges
/// over a vertical line (their summed x-extent over the input's width;
/// about right for random polygons); when that bound reaches
/// [`STRIP_MIN_EVENTS`], they are estimated from [`CROSSING_SAMPLES`] pairs
/// of edges drawn by a fixed sequence (exact tests). Two strips when the
/// estimated crossings are at least the edges and, with the edges, reach
/// [`STRIP_MIN_EVENTS`]. Inputs with few crossings stay in one strip:
/// there each cut edge adds an event to both strips whose line is as long
/// as the whole sweep's (nested squares were twice as slow in strips), and
/// the gain measured on the n-gon unions and checkerboards was within the
/// noise. A function of the input alone (see the module documentation,
/// "Determinism").
pub(crate) fn strip_count<W>(input: &[InputEdge<W>]) -> usize {
    let n = input.len();
    if n < STRIP_MIN_EDGES {
        return 1;
    }
    let (mut lo, mut hi, mut spans) = (f64::INFINITY, f64::NEG_INFINITY, 0.0);
    for e in input {
        lo = lo.min(e.a[0]);
        hi = hi.max(e.a[0]);
        spans += (e.b[0] - e.a[0]).abs();
    }
    let line = if hi > lo { spans / (hi - lo) } else { 0.0 };
    let bound = n as f64 * (line / 4.0).max(1.0);
    if bound.is_nan() || bound < STRIP_MIN_EVENTS {
        return 1;
    }
    // Sampled pairs (a splitmix64 sequence): the share that cross.
    let mut state = n as u64;
    let mut next = |m: usize| {
        state = state.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = state;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        ((z ^ (z >> 31)) % m as u64) as usize
    };
    let mut hits = 0usize;
    for _ in 0..CROSSING_SAMPLES {
        let (i, j) = (next(n), next(n));
        if i != j && segments_cross(&input[i], &input[j]) {
            hits += 1;
        }
    }
    let pairs = n as f64 * (n as f64 - 1.0) / 2.0;
    let crossings = pairs * hits as f64 / CROSSING_SAMPLES as f64;
    if crossings >= n as f64 && n as f64 + crossings >= STRIP_MIN_EVENTS {
        2
    } else {
        1
    }
}

/// Pairs of edges the estimate of [`strip_count`] tests.
const CROSSING_SAMPLES: usize = 256;

/// Do the two edges cross at a point inside both (exact)?
fn segments_cross<W>(e: &InputEdge<W>, f: &InputEdge<W>) -> bool {
    let opposite =
        |x: Ordering, y: Ordering| x != Ordering::Equal && y != Ordering::Equal && x != y;
    opposite(orient2d(e.a, e.b, f.a), orient2d(e.a, e.b, f.b))
        && opposite(orient2d(f.a, f.b, e.a), orient2d(f.a, f.b, e.b))
}

/// Inputs with fewer edges are swept in one strip without an estimate.
pub(crate) const STRIP_MIN_EDGES: usize = 64;

/// Inputs whose estimated events are fewer are swept in one strip: below
/// a few milliseconds of sweeping, handing a strip to the thread pool and
/// waking its threads cost about what the second thread saves (the
/// 4,000-edge n-gon unions of Table 7.4 were slower in strips).
const STRIP_MIN_EVENTS: f64 = 15_000.0;

/// The most vertices the triangle test of one cut point looks at before it
/// keeps the point (see "Joining").
const TRIANGLE_BUDGET: usize = 4096;

/// The boundary of the cells `keep` selects, as the sweep's
/// [`Output::Boundary`] gives it, computed in `strips` vertical strips in
/// parallel (one strip: the plain sweep). Falls back to one strip when no
/// cut line can be placed or a strip's output breaks a condition of the
/// module documentation.
pub(crate) fn run_in_strips<W: Winding + Sync>(
    input: Vec<InputEdge<W>>,
    strips: usize,
    dims: usize,
    max_abs: f64,
    keep: &(dyn Fn(&W) -> bool + Sync),
) -> Result<CellStructure<W>, SimplifyError> {
    let n = input.len();
    let cuts = if strips > 1 {
        cut_lines(&input, strips)
    } else {
        Vec::new()
    };
    if cuts.is_empty() {
        return run_with(input, n, dims, max_abs, Output::Boundary(keep), true);
    }
    let Cut { strips, on_line } = cut(&input, &cuts);
    let sweep = |p: Vec<InputEdge<W>>| {
        let len = p.len();
        run_with(p, len, dims, max_abs, Output::Boundary(keep), true)
    };
    // The first strip on the calling thread, the others on the pool (on
    // one thread, all here): where a strip runs changes nothing it
    // computes, and the caller neither waits idle nor hops to the pool.
    let mut outputs: Vec<Option<Result<CellStructure<W>, SimplifyError>>> =
        strips.iter().map(|_| None).collect();
    let mut strips = strips.into_iter();
    if rayon::current_num_threads() < 2 {
        for (slot, p) in outputs.iter_mut().zip(strips) {
            *slot = Some(sweep(p));
        }
    } else if let (Some((first, rest)), Some(p0)) = (outputs.split_first_mut(), strips.next()) {
        rayon::in_place_scope(|scope| {
            for (slot, p) in rest.iter_mut().zip(strips) {
                let sweep = &sweep;
                scope.spawn(move |_| *slot = Some(sweep(p)));
            }
            *first = Some(sweep(p0));
        });
    }
    let outputs: Vec<Result<CellStructure<W>, SimplifyError>> = outputs
        .into_iter()
        .map(|o| o.unwrap_or_else(|| Err(SimplifyError::Internal("a strip was not swept".into()))))
        .collect();
    let mut parts = Vec::with_capacity(outputs.len());
    for o in outputs {
        match o.ok().and_then(CellStructure::into_boundary_parts) {
            Some(p) => parts.push(p),
            None => {
                #[cfg(test)]
                tests::FALLBACKS.with(|c| c.set(c.get() + 1));
                return run_with(input, n, dims, max_abs, Output::Boundary(keep), true);
            }
        }
    }
    let j = join(parts, &cuts, &on_line, n);
    #[cfg(test)]
    if j.is_none() {
        tests::FALLBACKS.with(|c| c.set(c.get() + 1));
    }
    match j {
        Some(j) => Ok(CellStructure::new(
            j.vertices,
            Vec::new(),
            None,
            Some(j.edges),
            j.k_max,
            max_abs,
            dims,
            j.stats,
        )),
        None => run_with(input, n, dims, max_abs, Output::Boundary(keep), true),
    }
}

/// Up to `strips - 1` cut lines, increasing, each strictly between two
/// consecutive distinct x-values of the edges' first points (the input's
/// vertices, for closed input) at the quantiles `j / strips`. Lines that
/// cannot be placed (every x equal beyond a quantile, or two adjacent
/// floating-point numbers) are left out.
fn cut_lines<W>(input: &[InputEdge<W>], strips: usize) -> Vec<f64> {
    let mut xs: Vec<f64> = input.iter().map(|e| e.a[0] + 0.0).collect();
    let len = xs.len();
    let mut cuts: Vec<f64> = Vec::with_capacity(strips - 1);
    // Each selection runs on the part right of the previous quantile.
    let mut from = 0;
    for j in 1..strips {
        let at = j * len / strips;
        if at < from || at >= len {
            continue;
        }
        let rest = &mut xs[from..];
        let (_, &mut x, above) = rest.select_nth_unstable_by(at - from, f64::total_cmp);
        let next = above
            .iter()
            .copied()
            .filter(|&v| v > x)
            .fold(f64::INFINITY, f64::min);
        from = at + 1;
        if !next.is_finite() {
            break;
        }
        let c = x * 0.5 + next * 0.5;
        if x < c && c < next && cuts.last().is_none_or(|&last| last < c) {
            cuts.push(c);
        }
    }
    cuts
}

/// The strip of a point with this x: the number of cut lines left of it
/// (a point on a line belongs to the strip on its left).
fn strip_of(cuts: &[f64], x: f64) -> usize {
    cuts.partition_point(|&c| c < x)
}

/// The strips' input, and for each cut line the y-values of the points on
/// it where strip input edges end, sorted, once per input edge (a cut
/// point of one edge appears once).
struct Cut<W> {
    strips: Vec<Vec<InputEdge<W>>>,
    on_line: Vec<Vec<f64>>,
}

/// The input of each strip: whole edges, and the pieces of the edges that
/// cross cut lines (split at Table 7.1's point of the original segment on
/// each line, in the edge's direction).
fn cut<W: Winding>(input: &[InputEdge<W>], cuts: &[f64]) -> Cut<W> {
    let k = cuts.len() + 1;
    let mut out: Vec<Vec<InputEdge<W>>> = (0..k)
        .map(|_| Vec::with_capacity(input.len() / k + 16))
        .collect();
    let mut on_line: Vec<Vec<f64>> = vec![Vec::new(); cuts.len()];
    let note = |on_line: &mut Vec<Vec<f64>>, p: [f64; 2]| {
        let j = strip_of(cuts, p[0]);
        if cuts.get(j) == Some(&p[0]) {
            on_line[j].push(p[1] + 0.0);
        }
    };
    for e in input {
        let (sa, sb) = (strip_of(cuts, e.a[0]), strip_of(cuts, e.b[0]));
        if sa == sb {
            note(&mut on_line, e.a);
            note(&mut on_line, e.b);
            out[sa].push(e.clone());
            continue;
        }
        // Lexicographic ends: `l[0] < c < r[0]` for every line between, so
        // Table 7.1's preconditions hold.
        let forward = sa < sb;
        let (l, r) = if forward { (e.a, e.b) } else { (e.b, e.a) };
        let (lo, hi) = (sa.min(sb), sa.max(sb));
        let mut prev = l;
        let mut pts: Vec<([f64; 2], [f64; 2], usize)> = Vec::with_capacity(hi - lo + 1);
        note(&mut on_line, l);
        note(&mut on_line, r);
        for (j, &c) in cuts.iter().enumerate().take(hi).skip(lo) {
            let p = [c, y_at_x(l, r, c)];
            on_line[j].push(p[1] + 0.0);
            pts.push((prev, p, j));
            prev = p;
        }
        pts.push((prev, r, hi));
        for (p, q, s) in pts {
            if p == q {
                continue;
            }
            let (a, b) = if forward { (p, q) } else { (q, p) };
            out[s].push(InputEdge {
                a,
                b,
                mult: e.mult.clone(),
                origin: e.origin,
            });
        }
    }
    for ys in &mut on_line {
        ys.sort_unstable_by(f64::total_cmp);
    }
    Cut {
        strips: out,
        on_line,
    }
}

/// One strip's boundary structure, taken apart.
pub(crate) struct Part {
    /// The ends of the selected edges.
    pub(crate) vertices: Vec<[f64; 2]>,
    /// The selected edges, keyed on the vertices.
    pub(crate) edges: Keyed,
    /// The largest adjustment count.
    pub(crate) k_max: u32,
    /// The sweep's counters.
    pub(crate) stats: SweepStats,
    /// Where the whole arrangement lies.
    pub(crate) extent: Extent,
}

/// The joined boundary of the strips.
struct Joined {
    vertices: Vec<[f64; 2]>,
    edges: Keyed,
    k_max: u32,
    stats: SweepStats,
}

/// A vertex of one strip's output: (strip, id in the strip).
type Local = (usize, u32);

/// The vertices of one cut line, from the strips on both sides, merged
/// by y (shared points once), and the joining decisions on them.
struct Line {
    /// The points, increasing.
    points: Vec<[f64; 2]>,
    /// For the strip on the left, the index in `points` of each of its
    /// vertices on the line (its last ones); for the strip on the right,
    /// of its first ones.
    from_left: Vec<u32>,
    from_right: Vec<u32>,
    /// Per point: the number of edges at it, the edge arriving from the
    /// left (index in the left strip's edges) and the edge leaving to the
    /// right (in the right strip's).
    edges_at: Vec<(u32, u32, u32)>,
    /// Per point: removed (joined away).
    removed: Vec<bool>,
    /// Per point: its global id when kept.
    gid: Vec<u32>,
}

/// Joins the strips' boundaries along the cut lines (module documentation,
/// "Joining"), or `None` when a strip's output breaks a condition of "Why
/// the joined boundary is valid" or was not in lexicographic order.
fn join(parts: Vec<Part>, cuts: &[f64], on_line: &[Vec<f64>], n: usize) -> Option<Joined> {
    let k = parts.len();
    let lower = |s: usize| {
        if s == 0 {
            f64::NEG_INFINITY
        } else {
            cuts[s - 1]
        }
    };
    let upper = |s: usize| cuts.get(s).copied().unwrap_or(f64::INFINITY);
    // The whole arrangement of each strip (kept edges or not) in its
    // closed strip, no edge of it on a cut line, its points in order.
    for (s, part) in parts.iter().enumerate() {
        let (lo, hi) = (lower(s), upper(s));
        let x = &part.extent;
        if !x.ordered
            || x.x_min < lo
            || x.x_max > hi
            || x.vertical_min == lo
            || x.vertical_max == hi
        {
            return None;
        }
    }
    // Each strip's vertices: those on its left line first, those on its
    // right line last (the order is lexicographic).
    let head: Vec<usize> = (0..k)
        .map(|s| {
            let lo = lower(s);
            parts[s].vertices.iter().take_while(|p| p[0] == lo).count()
        })
        .collect();
    let tail: Vec<usize> = (0..k)
        .map(|s| {
            let hi = upper(s);
            let v = &parts[s].vertices;
            v.len() - v.iter().rev().take_while(|p| p[0] == hi).count()
        })
        .collect();
    let mut lines: Vec<Line> = (0..k - 1)
        .map(|j| {
            let left = &parts[j].vertices[tail[j]..];
            let right = &parts[j + 1].vertices[..head[j + 1]];
            merge_line(left, right)
        })
        .collect();
    // The edges at the points of each line.
    for (s, part) in parts.iter().enumerate() {
        for (i, &(a, b, _)) in part.edges.iter().enumerate() {
            if (b as usize) >= tail[s] {
                let line = &mut lines[s];
                let at = line.from_left[b as usize - tail[s]] as usize;
                line.edges_at[at].0 += 1;
                line.edges_at[at].1 = i as u32;
            }
            if (a as usize) < head[s] {
                let line = &mut lines[s - 1];
                let at = line.from_right[a as usize] as usize;
                line.edges_at[at].0 += 1;
                line.edges_at[at].2 = i as u32;
            }
        }
    }
    // Joining, line by line from the left: `start` is where the boundary
    // through a removed point comes from (a chain may cross several
    // lines).
    let mut start: Vec<Vec<Local>> = lines.iter().map(|l| vec![(0, 0); l.points.len()]).collect();
    for j in 0..lines.len() {
        for at in 0..lines[j].points.len() {
            let (count, ein, eout) = lines[j].edges_at[at];
            if count != 2 || ein == NONE || eout == NONE {
                continue;
            }
            let p = lines[j].points[at];
            if !single(&on_line[j], p[1]) {
                continue;
            }
            #[cfg(test)]
            if tests::KEEP_CUT_POINTS.with(|c| c.get()) {
                continue;
            }
            let (a, _, m1) = parts[j].edges[ein as usize];
            let (_, b, m2) = parts[j + 1].edges[eout as usize];
            if m1 != m2 {
                continue;
            }
            // The chain's start: `a`, or where the removed point it is
            // on the left line comes from.
            let mut from: Local = (j, a);
            if (a as usize) < head[j] {
                let at_left = lines[j - 1].from_right[a as usize] as usize;
                if lines[j - 1].removed[at_left] {
                    from = start[j - 1][at_left];
                }
            }
            if triangle_is_empty(&parts, from, p, (j + 1, b)) {
                lines[j].removed[at] = true;
                start[j][at] = from;
            }
        }
    }
    // Global ids: for each strip its vertices strictly inside, in its
    // order, then the kept points of the line on its right. Lexicographic.
    let total: usize = parts.iter().map(|p| p.vertices.len()).sum();
    let mut vertices: Vec<[f64; 2]> = Vec::with_capacity(total);
    let mut base: Vec<usize> = Vec::with_capacity(k);
    for s in 0..k {
        base.push(vertices.len());
        vertices.extend_from_slice(&parts[s].vertices[head[s]..tail[s]]);
        if let Some(line) = lines.get_mut(s) {
            for at in 0..line.points.len() {
                if !line.removed[at] {
                    line.gid[at] = vertices.len() as u32;
                    vertices.push(line.points[at]);
                }
            }
        }
    }
    let gid = |lines: &[Line], s: usize, v: u32| -> u32 {
        let v = v as usize;
        if v < head[s] {
            let line = &lines[s - 1];
            line.gid[line.from_right[v] as usize]
        } else if v >= tail[s] {
            let line = &lines[s];
            line.gid[line.from_left[v - tail[s]] as usize]
        } else {
            (base[s] + v - head[s]) as u32
        }
    };
    // Where the boundary arriving at a removed point finally ends: lines
    // from the right, so that a chain's later points are known.
    let mut end: Vec<Vec<u32>> = lines.iter().map(|l| vec![NONE; l.points.len()]).collect();
    for j in (0..lines.len()).rev() {
        for at in 0..lines[j].points.len() {
            if !lines[j].removed[at] {
                continue;
            }
            let eout = lines[j].edges_at[at].2 as usize;
            let b = parts[j + 1].edges[eout].1;
            let mut e = gid(&lines, j + 1, b);
            if (b as usize) >= tail[j + 1] {
                let at_right = lines[j + 1].from_left[b as usize - tail[j + 1]] as usize;
                if lines[j + 1].removed[at_right] {
                    e = end[j + 1][at_right];
                }
            }
            end[j][at] = e;
        }
    }
    let mut edges: Keyed = Vec::with_capacity(parts.iter().map(|p| p.edges.len()).sum());
    let mut k_max = 0;
    let mut stats = SweepStats {
        input_edges: n,
        ..SweepStats::default()
    };
    for (s, part) in parts.iter().enumerate() {
        for &(a, b, m) in &part.edges {
            // The edge leaving a removed point is part of the edge that
            // arrives there.
            if (a as usize) < head[s] {
                let line = &lines[s - 1];
                if line.removed[line.from_right[a as usize] as usize] {
                    continue;
                }
            }
            let gb = if (b as usize) >= tail[s] {
                let line = &lines[s];
                let at = line.from_left[b as usize - tail[s]] as usize;
                if line.removed[at] {
                    end[s][at]
                } else {
                    line.gid[at]
                }
            } else {
                gid(&lines, s, b)
            };
            edges.push((gid(&lines, s, a), gb, m));
        }
        let st = part.stats;
        k_max = k_max.max(part.k_max);
        stats.merged_input_edges += st.merged_input_edges;
        stats.events += st.events;
        stats.intersections += st.intersections;
        stats.vertex_on_edge_splits += st.vertex_on_edge_splits;
        stats.through_splits += st.through_splits;
        stats.misgrouped_splits += st.misgrouped_splits;
        stats.full_scans += st.full_scans;
        stats.max_sweep_len = stats.max_sweep_len.max(st.max_sweep_len);
    }
    let kept = lines
        .iter()
        .map(|l| l.removed.iter().filter(|&&r| !r).count())
        .sum::<usize>();
    // Section 8.4 with the cut points counted as one adjustment: every
    // output edge then lies within `(k + 1) alpha` of its input edge. When
    // no strip adjusted anything (`k = 0`: every output edge is a whole
    // strip input edge) and no cut point is left, every output edge is an
    // input edge, pieces joined back, and the count stays zero.
    let cut_any = on_line.iter().any(|ys| !ys.is_empty());
    let k_max = if k_max == 0 && kept == 0 {
        0
    } else {
        k_max + u32::from(cut_any)
    };
    Some(Joined {
        vertices,
        edges,
        k_max,
        stats,
    })
}

/// No edge (in `Line::edges_at`).
const NONE: u32 = u32::MAX;

/// The points of one line from the vertices on it of the strips on its
/// left and right (each increasing in y), shared ones once.
fn merge_line(left: &[[f64; 2]], right: &[[f64; 2]]) -> Line {
    let mut points: Vec<[f64; 2]> = Vec::with_capacity(left.len() + right.len());
    let mut from_left = Vec::with_capacity(left.len());
    let mut from_right = Vec::with_capacity(right.len());
    let (mut i, mut j) = (0, 0);
    while i < left.len() || j < right.len() {
        let order = match (left.get(i), right.get(j)) {
            (Some(a), Some(b)) => Pt::new(*a).cmp(&Pt::new(*b)),
            (Some(_), None) => Ordering::Less,
            _ => Ordering::Greater,
        };
        let at = points.len() as u32;
        match order {
            Ordering::Less => {
                points.push(left[i]);
                from_left.push(at);
                i += 1;
            }
            Ordering::Greater => {
                points.push(right[j]);
                from_right.push(at);
                j += 1;
            }
            Ordering::Equal => {
                points.push(left[i]);
                from_left.push(at);
                from_right.push(at);
                i += 1;
                j += 1;
            }
        }
    }
    let m = points.len();
    Line {
        points,
        from_left,
        from_right,
        edges_at: vec![(0, NONE, NONE); m],
        removed: vec![false; m],
        gid: vec![NONE; m],
    }
}

/// Is `y` the end of exactly one strip input edge on each side of its line
/// (`ys`: the line's end points, sorted)? Then the two output edges at the
/// point come from that input edge: any other edge through the point would
/// end there too, or leave it along the line (which [`join`] refuses).
fn single(ys: &[f64], y: f64) -> bool {
    let y = y + 0.0;
    let from = ys.partition_point(|&v| v < y);
    ys.get(from) == Some(&y) && ys.get(from + 1) != Some(&y)
}

/// Does the closed triangle `a p b` hold no vertex of the strips' outputs
/// but its corners? `a` lies left of `p`'s line, `b` right of it. Exact
/// (orientation signs); `false` when more than [`TRIANGLE_BUDGET`]
/// vertices lie between `a` and `b` in lexicographic order (the strips'
/// outputs in turn), which is where the triangle's points are.
fn triangle_is_empty(parts: &[Part], a: Local, p: [f64; 2], b: Local) -> bool {
    let pa = parts[a.0].vertices[a.1 as usize];
    let pb = parts[b.0].vertices[b.1 as usize];
    let ylo = pa[1].min(p[1]).min(pb[1]);
    let yhi = pa[1].max(p[1]).max(pb[1]);
    let turn = orient2d(pa, p, pb);
    if turn == Ordering::Equal {
        // `p` on `a b` (strictly between in x): the new edge is the same
        // point set as the two it replaces.
        return true;
    }
    let mut budget = TRIANGLE_BUDGET;
    for (s, part) in parts.iter().enumerate().take(b.0 + 1).skip(a.0) {
        let v = &part.vertices;
        let from = if s == a.0 { a.1 as usize + 1 } else { 0 };
        let to = if s == b.0 { b.1 as usize } else { v.len() };
        if to <= from {
            continue;
        }
        if to - from > budget {
            return false;
        }
        budget -= to - from;
        for &q in &v[from..to] {
            if q[1] < ylo || q[1] > yhi || q == p || q == pa || q == pb {
                continue;
            }

            let side = |o: Ordering| o == turn || o == Ordering::Equal;
            if side(orient2d(pa, p, q)) && side(orient2d(p, pb, q)) && side(orient2d(pb, pa, q)) {
                return false;
            }
        }
    }
    true
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::FillRule;
    use proptest::prelude::*;
    use test_support::rng::Xorshift64Star;
    use topology::PolygonSet2;

    thread_local! {
        /// The joins given up on this thread (one strip swept instead).
        pub(super) static FALLBACKS: std::cell::Cell<usize> = const { std::cell::Cell::new(0) };
        /// Set: [`join`] keeps every cut point (to tell the edges it
        /// makes from those of the strips).
        pub(super) static KEEP_CUT_POINTS: std::cell::Cell<bool> = const { std::cell::Cell::new(false) };
    }

    const RULES: [FillRule; 5] = [
        FillRule::Positive,
        FillRule::NonZero,
        FillRule::EvenOdd,
        FillRule::Negative,
        FillRule::AtLeast2,
    ];

    fn input_of(set: &PolygonSet2) -> Vec<InputEdge<i32>> {
        let v = set.vertices();
        set.edges()
            .iter()
            .enumerate()
            .map(|(i, e)| InputEdge {
                a: v[e.start as usize],
                b: v[e.end as usize],
                mult: e.mult,
                origin: i as u32,
            })
            .collect()
    }

    /// The shape and reported epsilon of `set` simplified by `rule` in
    /// `strips` strips.
    fn in_strips(set: &PolygonSet2, rule: FillRule, strips: usize) -> (PolygonSet2, f64, u32) {
        let keep = move |w: &i32| rule.contains(*w);
        let c = run_in_strips(input_of(set), strips, 1, set.max_abs_coordinate(), &keep).unwrap();
        let (eps, k) = (c.epsilon(), c.k_max());
        (c.into_shape_with(keep), eps, k)
    }

    fn segments(s: &PolygonSet2) -> Vec<([f64; 2], [f64; 2])> {
        s.edges().iter().map(|e| s.edge_points(e)).collect()
    }

    /// Pairs of segments that cross properly, or where an end point of one
    /// lies inside the other (exact orientations).
    fn crossings(segs: &[([f64; 2], [f64; 2])]) -> usize {
        let mut n = 0;
        let on = |p: [f64; 2], (a, b): ([f64; 2], [f64; 2])| {
            p != a
                && p != b
                && orient2d(a, b, p) == Ordering::Equal
                && a[0].min(b[0]) <= p[0]
                && p[0] <= a[0].max(b[0])
                && a[1].min(b[1]) <= p[1]
                && p[1] <= a[1].max(b[1])
        };
        for (i, &s) in segs.iter().enumerate() {
            for &t in &segs[i + 1..] {
                let (o1, o2) = (orient2d(s.0, s.1, t.0), orient2d(s.0, s.1, t.1));
                let (o3, o4) = (orient2d(t.0, t.1, s.0), orient2d(t.0, t.1, s.1));
                let proper = o1 != Ordering::Equal
                    && o2 != Ordering::Equal
                    && o1 != o2
                    && o3 != Ordering::Equal
                    && o4 != Ordering::Equal
                    && o3 != o4;
                if proper || on(t.0, s) || on(t.1, s) || on(s.0, t) || on(s.1, t) {
                    n += 1;
                }
            }
        }
        n
    }

    /// Do the two segments cross at a point inside both (exact)?
    fn proper(e: ([f64; 2], [f64; 2]), f: ([f64; 2], [f64; 2])) -> bool {
        let o = |p, q, r| orient2d(p, q, r);
        let opposite =
            |x: Ordering, y: Ordering| x != Ordering::Equal && y != Ordering::Equal && x != y;
        opposite(o(e.0, e.1, f.0), o(e.0, e.1, f.1)) && opposite(o(f.0, f.1, e.0), o(f.0, f.1, e.1))
    }

    /// Distance from `p` to segment `a b` (floating point; the callers
    /// allow for its rounding).
    fn dist(p: [f64; 2], a: [f64; 2], b: [f64; 2]) -> f64 {
        let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
        let l2 = dx * dx + dy * dy;
        let t = if l2 > 0.0 {
            (((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / l2).clamp(0.0, 1.0)
        } else {
            0.0
        };
        let (x, y) = (a[0] + t * dx - p[0], a[1] + t * dy - p[1]);
        (x * x + y * y).sqrt()
    }

    /// Winding number of `p` (not on an edge) by the crossing rule.
    fn winding(set: &PolygonSet2, p: [f64; 2]) -> i32 {
        let mut w = 0;
        for e in set.edges() {
            let (a, b) = set.edge_points(e);
            if (a[1] <= p[1]) != (b[1] <= p[1]) {
                let o = orient2d(a, b, p);
                if a[1] <= p[1] && o == Ordering::Greater {
                    w += e.mult;
                } else if b[1] <= p[1] && o == Ordering::Less {
                    w -= e.mult;
                }
            }
        }
        w
    }

    /// Everything the module documentation promises, for `strips` strips
    /// against the one-strip sweep: shape boundary closure; the same
    /// winding verdict at sample points away from both boundaries; every
    /// output vertex within the reported epsilon of an input edge; no edge
    /// made by the join crossing an edge or passing through a vertex; for
    /// random polygons in the unit disc (`fine`), where the one-strip sweep
    /// is geometrically valid too, no crossing or touching at all (section
    /// 7.7: elsewhere the sweep's own output may cross within its bound);
    /// and no thread count dependence.
    fn check(set: &PolygonSet2, strips: usize, seed: u64, fine: bool) {
        let lo = set
            .vertices()
            .iter()
            .fold([f64::INFINITY; 2], |m, p| [m[0].min(p[0]), m[1].min(p[1])]);
        let hi = set.vertices().iter().fold([f64::NEG_INFINITY; 2], |m, p| {
            [m[0].max(p[0]), m[1].max(p[1])]
        });
        let input = segments(set);
        let mut rng = Xorshift64Star::new(seed);
        for rule in RULES {
            let (one, one_eps, _) = in_strips(set, rule, 1);
            let (got, eps, _) = in_strips(set, rule, strips);
            got.check_topology().unwrap();
            got.validate_coordinates().unwrap();
            let segs = segments(&got);
            let slack = 16.0 * f64::EPSILON * set.max_abs_coordinate().max(1e-300);
            for p in got.vertices() {
                assert!(
                    input.iter().any(|&(a, b)| dist(*p, a, b) <= eps + slack),
                    "{p:?} further than {eps:e} from the input ({rule:?}, {strips} strips)"
                );
            }
            let one_segs = segments(&one);
            if fine {
                assert_eq!(crossings(&segs), 0, "{rule:?}, {strips} strips");
            }
            // The edges the join made (absent when it keeps every cut
            // point) cross no edge and pass through no vertex, whenever no
            // two edges of the strips' outputs cross (the join's premise;
            // on coarse grids the sweep may leave crossings within its
            // bound, section 7.7). Their ends are old vertices: one may
            // already lie on another edge where the output merged vertical
            // edges (section 7.6.1).
            KEEP_CUT_POINTS.with(|c| c.set(true));
            let (unjoined, _, _) = in_strips(set, rule, strips);
            KEEP_CUT_POINTS.with(|c| c.set(false));
            let unjoined_segs = segments(&unjoined);
            let premise = unjoined_segs
                .iter()
                .enumerate()
                .all(|(i, &e)| unjoined_segs[i + 1..].iter().all(|&f| !proper(e, f)));
            let key = |(a, b): ([f64; 2], [f64; 2])| {
                [
                    a[0].to_bits(),
                    a[1].to_bits(),
                    b[0].to_bits(),
                    b[1].to_bits(),
                ]
            };
            let before: std::collections::HashSet<[u64; 4]> =
                unjoined_segs.into_iter().map(key).collect();
            for &e in segs.iter().filter(|_| premise) {
                if before.contains(&key(e)) {
                    continue;
                }
                for &f in &segs {
                    assert!(
                        !proper(e, f),
                        "joined edge {e:?} crosses {f:?} ({rule:?}, {strips} strips)"
                    );
                }
                for &v in got.vertices() {
                    assert!(
                        v == e.0 || v == e.1 || crossings(&[e, (v, v)]) == 0,
                        "joined edge {e:?} passes through {v:?} ({rule:?}, {strips} strips)"
                    );
                }
            }
            let away = 2.0 * (eps + one_eps) + slack;
            for _ in 0..30 {
                let p = [
                    lo[0] + (hi[0] - lo[0]) * rng.unit(),
                    lo[1] + (hi[1] - lo[1]) * rng.unit(),
                ];
                if segs
                    .iter()
                    .chain(&one_segs)
                    .any(|&(a, b)| dist(p, a, b) <= away)
                {
                    continue;
                }
                assert_eq!(
                    winding(&got, p),
                    winding(&one, p),
                    "{p:?} ({rule:?}, {strips} strips)"
                );
            }
            // The same on one thread and on four.
            for threads in [1, 4] {
                let pool = rayon::ThreadPoolBuilder::new()
                    .num_threads(threads)
                    .build()
                    .unwrap();
                let again = pool.install(|| in_strips(set, rule, strips));
                assert_eq!(again.0, got);
                assert_eq!(again.1, eps);
            }
        }
    }

    fn ring_set(rings: &[Vec<[f64; 2]>]) -> Option<PolygonSet2> {
        let mut s = PolygonSet2::new();
        for r in rings {
            s.add_loop(r);
        }
        (s.validate_coordinates().is_ok() && s.check_topology().is_ok() && s.edge_count() > 0)
            .then_some(s)
    }

    /// Integer points offset by `o`, cut into two rings at `split` (rings
    /// of fewer than three points left out).
    fn grid_set(pts: &[(i32, i32)], split: usize, o: f64) -> Option<PolygonSet2> {
        let p: Vec<[f64; 2]> = pts
            .iter()
            .map(|&(x, y)| [o + f64::from(x), o + f64::from(y)])
            .collect();
        let at = split.min(p.len());
        let rings: Vec<Vec<[f64; 2]>> = [&p[..at], &p[at..]]
            .into_iter()
            .filter(|r| r.len() >= 3)
            .map(<[[f64; 2]]>::to_vec)
            .collect();
        ring_set(&rings)
    }

    fn random_ring(rng: &mut Xorshift64Star, n: usize, d: [f64; 2]) -> Vec<[f64; 2]> {
        (0..n)
            .map(|_| {
                let p = rng.in_disc();
                [p[0] + d[0], p[1] + d[1]]
            })
            .collect()
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(test_support::cases(48)))]

        /// Random polygons in the unit disc, also displaced onto a coarse
        /// grid (section 7.7), in two to five strips.
        #[test]
        fn random_polygons_in_strips(n in 4usize..=48, seed in any::<u64>(), d in 0u8..3, strips in 2usize..=5) {
            let shift = [[0.0, 0.0], [1.5 * 2f64.powi(49), 0.0], [1.5 * 2f64.powi(47), 1.5 * 2f64.powi(47)]][d as usize];
            let mut rng = Xorshift64Star::new(seed);
            let rings = vec![random_ring(&mut rng, n, shift), random_ring(&mut rng, n / 2 + 3, shift)];
            if let Some(set) = ring_set(&rings) {
                check(&set, strips, seed, d == 0);
            }
        }

        /// Integer grids at 2^52, where the unit is one ulp: crossings
        /// round onto the cut lines, cut points sit up to half a unit off
        /// their edges, and the joins' triangles are wide.
        #[test]
        fn coarse_grids_in_strips(
            pts in proptest::collection::vec((0i32..12, 0i32..12), 3..=40),
            split in 3usize..=37,
            strips in 2usize..=5,
        ) {
            if let Some(set) = grid_set(&pts, split, 2f64.powi(52)) {
                check(&set, strips, 5, false);
            }
        }

        /// Small integer grids: many vertices share an x, crossings fall on
        /// the half-integer cut lines, edges overlap.
        #[test]
        fn grid_rings_in_strips(
            pts in proptest::collection::vec((0i32..6, 0i32..6), 3..=30),
            split in 3usize..=27,
            strips in 2usize..=5,
        ) {
            if let Some(set) = grid_set(&pts, split, 0.0) {
                check(&set, strips, 7, false);
            }
        }
    }

    /// In general position the strips are joined: the one-strip fallback
    /// is the exception (the property tests above would otherwise test
    /// mostly the plain sweep).
    #[test]
    fn general_position_joins_strips() {
        let mut rng = Xorshift64Star::new(11);
        let mut runs = 0;
        FALLBACKS.with(|c| c.set(0));
        for i in 0..120 {
            let rings = vec![random_ring(&mut rng, 20 + i % 40, [0.0, 0.0])];
            let Some(set) = ring_set(&rings) else {
                continue;
            };
            for rule in [FillRule::Positive, FillRule::EvenOdd] {
                in_strips(&set, rule, 2 + i % 4);
                runs += 1;
            }
        }
        let fell = FALLBACKS.with(|c| c.get());
        assert!(fell * 50 <= runs, "{fell} of {runs} joins given up");
    }

    /// Table 7.4's rotated n-gon unions stay one ring of `4 n` vertices in
    /// any number of strips: every cut point is joined away.
    #[test]
    fn ngon_unions_lose_every_cut_point() {
        for &(n, alpha) in &[
            (100, 1.0e-2),
            (400, 1.0e-2),
            (1000, 1.0e-6),
            (5000, 1.581e-9),
        ] {
            let mut s = PolygonSet2::new();
            s.add_loop(&test_support::shapes::regular_ngon(n, 1.0, 0.0));
            s.add_loop(&test_support::shapes::regular_ngon(n, 1.0, alpha));
            for strips in [2, 3, 8] {
                let (shape, _, _) = in_strips(&s, FillRule::Positive, strips);
                shape.check_topology().unwrap();
                assert_eq!(
                    shape.loops().len(),
                    1,
                    "n = {n}, alpha = {alpha}, {strips} strips"
                );
                assert_eq!(
                    shape.vertex_count(),
                    4 * n,
                    "n = {n}, alpha = {alpha}, {strips} strips"
                );
            }
        }
    }

    /// A clean polygon comes back unchanged with adjustment count zero:
    /// its pieces are joined back into its own edges.
    #[test]
    fn clean_polygons_come_back_exactly() {
        let ring = test_support::shapes::regular_ngon(300, 1.0, 0.3);
        let mut s = PolygonSet2::new();
        s.add_loop(&ring);
        for strips in [2, 5] {
            let (shape, _, k) = in_strips(&s, FillRule::Positive, strips);
            assert_eq!(k, 0);
            assert_eq!(
                crate::EdgeCollection::from_polygon_set(&shape),
                crate::EdgeCollection::from_polygon_set(&s)
            );
        }
    }

    /// Cut lines avoid every vertex x and come in increasing order; a set
    /// whose vertices share one x gets none.
    #[test]
    fn cut_lines_avoid_vertices() {
        let mut rng = Xorshift64Star::new(3);
        let mut s = PolygonSet2::new();
        s.add_loop(&random_ring(&mut rng, 200, [0.0, 0.0]));
        let input = input_of(&s);
        for strips in 2..=8 {
            let cuts = cut_lines(&input, strips);
            assert_eq!(cuts.len(), strips - 1);
            assert!(cuts.windows(2).all(|w| w[0] < w[1]));
            assert!(cuts
                .iter()
                .all(|c| input.iter().all(|e| e.a[0] != *c && e.b[0] != *c)));
        }
        let flat = vec![
            InputEdge {
                a: [1.0, 0.0],
                b: [1.0, 2.0],
                mult: 1,
                origin: 0,
            },
            InputEdge {
                a: [1.0, 2.0],
                b: [1.0, 0.0],
                mult: 1,
                origin: 1,
            },
        ];
        assert!(cut_lines(&flat, 4).is_empty());
    }
}
