//! Levels 3 and 4 of the 2D Boolean: inclusion values (eq. 4.7-4.13),
//! composite edges (eq. 4.14-4.16) and the resulting shape.

use crate::composite::pair_along;
use crate::error::BooleanError;
use crate::level_data::LevelData;
use rayon::prelude::*;
use topology::BooleanOp;
use topology::{Edge2, PolygonSet2};

/// The output under construction: its vertices and edges, pushed here
/// (in the same order as `PolygonSet2::add_vertex` and `add_edge_mult`
/// would) and turned into a [`PolygonSet2`] once, at the end.
struct Output {
    vertices: Vec<[f64; 2]>,
    edges: Vec<Edge2>,
}

impl Output {
    #[inline]
    fn add_edge(&mut self, start: u32, end: u32, mult: i32) {
        self.edges.push(Edge2 { start, end, mult });
    }

    fn finish(self) -> PolygonSet2 {
        PolygonSet2::from_parts(self.vertices, self.edges)
    }
}

/// Lazily numbered output vertices.
struct Ids {
    map: Vec<u32>,
}

impl Ids {
    fn new(n: usize) -> Self {
        Ids {
            map: vec![u32::MAX; n],
        }
    }
    #[inline]
    fn get(&mut self, i: u32, pos: [f64; 2], out: &mut Output) -> u32 {
        let slot = &mut self.map[i as usize];
        if *slot == u32::MAX {
            *slot = out.vertices.len() as u32;
            out.vertices.push(pos);
        }
        *slot
    }
}

/// Edge counts (of both operands together) above which the composite
/// edges are paired on the rayon pool (when it has two threads or more),
/// in blocks of [`EDGES_PER_TASK`]; the output is the same either way (the
/// blocks are numbered in order).
const PARALLEL_EDGES: usize = 8192;

/// Edges per parallel task of [`construct`].
const EDGES_PER_TASK: usize = 4096;

/// The retained parts of a run of one operand's edges: `(start, end,
/// multiplicity)` with ids tagged as in [`resolve`], and the composite
/// edge counts of `LevelData::composite_counts`, both in edge order.
#[derive(Default)]
struct Block {
    pieces: Vec<(u32, u32, i32)>,
    counts: Vec<(u32, u32)>,
}

/// What every block of edges reads: the operands, the operation, the
/// level-2 data, and `data.x11` ordered by edge of B ([`order_by_b`]).
#[derive(Clone, Copy)]
struct Inputs<'a> {
    a: &'a PolygonSet2,
    b: &'a PolygonSet2,
    op: BooleanOp,
    data: &'a LevelData,
    by_b: &'a [u32],
    /// Whether to record `LevelData::composite_counts`.
    record_counts: bool,
}

/// Which operand a block of edges belongs to.
#[derive(Clone, Copy)]
enum Side {
    A,
    B,
}

/// Builds the result from level-2 data. `data.x11` must be sorted by edge
/// of A then edge of B; fills `data.composite_counts` when `record_counts`
/// (and leaves it empty otherwise).
///
/// Each edge's composite edge is paired on its own (eq. 4.14-4.16), in
/// blocks of consecutive edges (in parallel on long inputs); the output
/// vertices are then numbered in order of first use over A's edges, then
/// B's, and the edges added in that order.
pub(crate) fn construct(
    a: &PolygonSet2,
    b: &PolygonSet2,
    op: BooleanOp,
    data: &mut LevelData,
    record_counts: bool,
) -> Result<PolygonSet2, BooleanError> {
    let by_b = order_by_b(&data.x11, b.edge_count());
    let (na, nb) = (a.edge_count(), b.edge_count());
    let data_ref: &LevelData = data;
    let inputs = Inputs {
        a,
        b,
        op,
        data: data_ref,
        by_b: &by_b,
        record_counts,
    };
    let mut out = Output {
        vertices: Vec::with_capacity(a.vertex_count() + b.vertex_count() + data.x11.len()),
        edges: Vec::with_capacity(a.edge_count() + b.edge_count() + 2 * data.x11.len()),
    };
    let mut a_ids = Ids::new(a.vertex_count());
    let mut b_ids = Ids::new(b.vertex_count());
    let mut x_ids = Ids::new(data.x11.len());
    let mut counts = Vec::with_capacity(if record_counts { na + nb } else { 0 });

    if na + nb < PARALLEL_EDGES || rayon::current_num_threads() < 2 {
        // One pass: every retained part goes to the output at once.
        let mut sink = |own: &PolygonSet2, own_ids: &mut Ids, s: u32, e: u32, m: i32| {
            let s = resolve(s, own, own_ids, data_ref, &mut x_ids, &mut out);
            let e = resolve(e, own, own_ids, data_ref, &mut x_ids, &mut out);
            out.add_edge(s, e, m);
        };
        block_a(&inputs, 0, na, &mut counts, &mut |s, e, m| {
            sink(a, &mut a_ids, s, e, m)
        })?;
        block_b(&inputs, 0, nb, &mut counts, &mut |s, e, m| {
            sink(b, &mut b_ids, s, e, m)
        })?;
        data.composite_counts = counts;
        return Ok(out.finish());
    }

    let mut tasks: Vec<(Side, usize, usize)> = Vec::new();
    for (side, n) in [(Side::A, na), (Side::B, nb)] {
        let mut lo = 0;
        while lo < n {
            let hi = lo + EDGES_PER_TASK.min(n - lo);
            tasks.push((side, lo, hi));
            lo = hi;
        }
    }
    let run = |&(side, lo, hi): &(Side, usize, usize)| -> Result<Block, BooleanError> {
        let mut block = Block::default();
        let mut sink = |s, e, m| block.pieces.push((s, e, m));
        match side {
            Side::A => block_a(&inputs, lo, hi, &mut block.counts, &mut sink)?,
            Side::B => block_b(&inputs, lo, hi, &mut block.counts, &mut sink)?,
        }
        Ok(block)
    };
    let blocks: Vec<Result<Block, BooleanError>> = tasks.par_iter().map(run).collect();
    for (block, &(side, _, _)) in blocks.into_iter().zip(&tasks) {
        let block = block?;
        let (own, own_ids) = match side {
            Side::A => (a, &mut a_ids),
            Side::B => (b, &mut b_ids),
        };
        for &(s, e, m) in &block.pieces {
            let s = resolve(s, own, own_ids, data_ref, &mut x_ids, &mut out);
            let e = resolve(e, own, own_ids, data_ref, &mut x_ids, &mut out);
            out.add_edge(s, e, m);
        }
        counts.extend_from_slice(&block.counts);
    }
    data.composite_counts = counts;
    Ok(out.finish())
}

/// The retained parts of A's edges `lo..hi` (eq. 4.7-4.8 and section 4.6).
fn block_a(
    inputs: &Inputs<'_>,
    lo: usize,
    hi: usize,
    counts: &mut Vec<(u32, u32)>,
    sink: &mut impl FnMut(u32, u32, i32),
) -> Result<(), BooleanError> {
    let Inputs {
        a,
        b,
        op,
        data,
        record_counts,
        ..
    } = *inputs;
    let (ca, _, ci) = op.coefficients();
    let (a_points, b_edges) = (a.vertices(), b.edges());
    let mut edge = Ends::default();
    let mut pairs = Vec::new();
    let mut k = data.x11.partition_point(|h| (h.0 as usize) < lo);
    for (ia, ea) in a.edges().iter().enumerate().take(hi).skip(lo) {
        while k < data.x11.len() && (data.x11[k].0 as usize) < ia {
            k += 1;
        }
        if ea.mult == 0 {
            continue;
        }
        edge.clear();
        let i_e = ca + ci * data.x02[ea.end as usize]; // eq. 4.7 at v_e
        let i_s = ca + ci * data.x02[ea.start as usize]; // eq. 4.7 at v_s
        edge.assign(ea.end, a_points[ea.end as usize], i_e);
        edge.assign(ea.start, a_points[ea.start as usize], -i_s);
        let mut j = k;
        while j < data.x11.len() && data.x11[j].0 as usize == ia {
            let (_, ib, x, p) = data.x11[j];
            let mb = b_edges[ib as usize].mult;
            // eq. 4.8: I11 = c_I X11, once per unit of B's edge.
            edge.assign(j as u32 | TAG_X, p, ci * x * mb);
            j += 1;
        }
        emit(
            &mut edge,
            &mut pairs,
            record_counts.then_some(&mut *counts),
            ia,
            "A",
        )?;
        for &(s, e) in &pairs {
            sink(s, e, ea.mult);
        }
    }
    Ok(())
}

/// The retained parts of B's edges `lo..hi` (eq. 4.9-4.10): the 2D X11
/// counts enter with the opposite sign, since e_A crossing e_B left to
/// right means e_B entering A. `by_b` orders `data.x11` by edge of B.
fn block_b(
    inputs: &Inputs<'_>,
    lo: usize,
    hi: usize,
    counts: &mut Vec<(u32, u32)>,
    sink: &mut impl FnMut(u32, u32, i32),
) -> Result<(), BooleanError> {
    let Inputs {
        a,
        b,
        op,
        data,
        by_b,
        record_counts,
    } = *inputs;
    let (_, cb, ci) = op.coefficients();
    let (b_points, a_edges) = (b.vertices(), a.edges());
    let mut edge = Ends::default();
    let mut pairs = Vec::new();
    let mut k = by_b.partition_point(|&j| (data.x11[j as usize].1 as usize) < lo);
    for (ib, eb) in b.edges().iter().enumerate().take(hi).skip(lo) {
        while k < by_b.len() && (data.x11[by_b[k] as usize].1 as usize) < ib {
            k += 1;
        }
        if eb.mult == 0 {
            continue;
        }
        edge.clear();
        let mut j = k;
        while j < by_b.len() && data.x11[by_b[j] as usize].1 as usize == ib {
            let idx = by_b[j];
            let (ia, _, x, p) = data.x11[idx as usize];
            let ma = a_edges[ia as usize].mult;
            edge.assign(idx | TAG_X, p, -ci * x * ma);
            j += 1;
        }
        let i_e = cb + ci * data.x20[eb.end as usize]; // eq. 4.10 at v_e
        let i_s = cb + ci * data.x20[eb.start as usize];
        edge.assign(eb.end, b_points[eb.end as usize], i_e);
        edge.assign(eb.start, b_points[eb.start as usize], -i_s);
        emit(
            &mut edge,
            &mut pairs,
            record_counts.then_some(&mut *counts),
            ib,
            "B",
        )?;
        for &(s, e) in &pairs {
            sink(s, e, eb.mult);
        }
    }
    Ok(())
}

/// The indices of `x11` ordered by edge of B, then index: a counting sort
/// by edge of B (`b_edges` of them), which keeps the index order within
/// each edge.
fn order_by_b(x11: &[(u32, u32, i32, [f64; 2])], b_edges: usize) -> Vec<u32> {
    let mut fill = vec![0u32; b_edges + 1];
    for h in x11 {
        fill[h.1 as usize + 1] += 1;
    }
    for i in 0..b_edges {
        fill[i + 1] += fill[i];
    }
    let mut by_b = vec![0u32; x11.len()];
    for (j, h) in x11.iter().enumerate() {
        let slot = &mut fill[h.1 as usize];
        by_b[*slot as usize] = j as u32;
        *slot += 1;
    }
    by_b
}

/// Marks an id as an index into `data.x11` rather than an input vertex.
const TAG_X: u32 = 1 << 31;

fn resolve(
    id: u32,
    own: &PolygonSet2,
    own_ids: &mut Ids,
    data: &LevelData,
    x_ids: &mut Ids,
    out: &mut Output,
) -> u32 {
    if id & TAG_X != 0 {
        let j = id & !TAG_X;
        x_ids.get(j, data.x11[j as usize].3, out)
    } else {
        own_ids.get(id, own.vertex(id), out)
    }
}

/// A composite edge under construction (section 4.6): `(id, position)`
/// per start- and end-vertex, ids tagged as in [`resolve`]. The position
/// is copied in once, when assigned, so that ordering two or more pairs
/// (eq. 4.14-4.16) reads it without a second look-up.
#[derive(Default)]
struct Ends {
    starts: Vec<End>,
    ends: Vec<End>,
}

/// A start- or end-vertex of an [`Ends`]. The id is widened to 64 bits so
/// that the struct has no padding: a padded `(u32, [f64; 2])` was built on
/// the stack and copied with overlapping loads, which stalled every push.
#[derive(Clone, Copy)]
struct End {
    pos: [f64; 2],
    id: u64,
}

impl Ends {
    /// Assigns vertex `id` at `pos` a net end-vertex count `n`, as
    /// [`crate::CompositeEdge::assign`] does (a count of one, the common
    /// case, without the loop).
    #[inline]
    fn assign(&mut self, id: u32, pos: [f64; 2], n: i32) {
        match n {
            0 => {}
            1 => self.ends.push(End {
                pos,
                id: u64::from(id),
            }),
            -1 => self.starts.push(End {
                pos,
                id: u64::from(id),
            }),
            _ => {
                let list = if n > 0 {
                    &mut self.ends
                } else {
                    &mut self.starts
                };
                for _ in 0..n.unsigned_abs() {
                    list.push(End {
                        pos,
                        id: u64::from(id),
                    });
                }
            }
        }
    }

    fn clear(&mut self) {
        self.starts.clear();
        self.ends.clear();
    }
}

/// Pairs the composite edge of edge `index` of `operand`, recording
/// its counts in `counts` if given.
fn emit(
    edge: &mut Ends,
    pairs: &mut Vec<(u32, u32)>,
    counts: Option<&mut Vec<(u32, u32)>>,
    index: usize,
    operand: &str,
) -> Result<(), BooleanError> {
    pairs.clear();
    if let Some(counts) = counts {
        counts.push((edge.starts.len() as u32, edge.ends.len() as u32));
    }
    pair_along(&mut edge.starts, &mut edge.ends, |t| t.pos, |t| t.id as u32, pairs).ok_or_else(|| {
        BooleanError::Internal(format!(
            "Theorem 2 violated: composite edge of {operand}'s edge {index} has {} starts and {} ends",
            edge.starts.len(),
            edge.ends.len()
        ))
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use test_support::rng::Xorshift64;

    #[test]
    fn crossings_by_b_as_a_sort_by_edge_then_index() {
        let mut rng = Xorshift64::new(0x0dd_ba11_5eed);
        for round in 0..200 {
            let b_edges = 1 + rng.below(40) as usize;
            let x11: Vec<(u32, u32, i32, [f64; 2])> = (0..rng.below(200))
                .map(|i| (i as u32, rng.below(b_edges as u64) as u32, 1, [0.0; 2]))
                .collect();
            let mut want: Vec<u32> = (0..x11.len() as u32).collect();
            want.sort_by_key(|&j| (x11[j as usize].1, j));
            assert_eq!(order_by_b(&x11, b_edges), want, "round {round}");
        }
    }
}
