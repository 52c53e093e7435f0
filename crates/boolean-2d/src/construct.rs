//! Levels 3 and 4 of the 2D Boolean: inclusion values (eq. 4.7-4.13),
//! composite edges (eq. 4.14-4.16) and the resulting shape.

use crate::composite::{pair_composite_edge, CompositeEdge};
use crate::error::BooleanError;
use crate::level_data::LevelData;
use topology::BooleanOp;
use topology::PolygonSet2;

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
    fn get(&mut self, i: u32, pos: [f64; 2], out: &mut PolygonSet2) -> u32 {
        let slot = &mut self.map[i as usize];
        if *slot == u32::MAX {
            *slot = out.add_vertex(pos);
        }
        *slot
    }
}

/// Builds the result from level-2 data. `data.x11` must be sorted by edge
/// of A then edge of B; fills `data.composite_counts`.
pub(crate) fn construct(
    a: &PolygonSet2,
    b: &PolygonSet2,
    op: BooleanOp,
    data: &mut LevelData,
) -> Result<PolygonSet2, BooleanError> {
    let (ca, cb, ci) = op.coefficients();
    let mut out = PolygonSet2::with_capacity(
        a.vertex_count() + b.vertex_count() + data.x11.len(),
        a.edge_count() + b.edge_count() + 2 * data.x11.len(),
    );
    let mut a_ids = Ids::new(a.vertex_count());
    let mut b_ids = Ids::new(b.vertex_count());
    let mut x_ids = Ids::new(data.x11.len());
    let mut edge = CompositeEdge::default();
    let mut pairs = Vec::new();
    data.composite_counts.clear();

    // Retained parts of A's edges (eq. 4.7-4.8 and section 4.6).
    let mut k = 0;
    for (ia, ea) in a.edges().iter().enumerate() {
        while k < data.x11.len() && (data.x11[k].0 as usize) < ia {
            k += 1;
        }
        if ea.mult == 0 {
            continue;
        }
        edge.clear();
        let i_e = ca + ci * data.x02[ea.end as usize]; // eq. 4.7 at v_e
        let i_s = ca + ci * data.x02[ea.start as usize]; // eq. 4.7 at v_s
        edge.assign(ea.end, a.vertex(ea.end), i_e);
        edge.assign(ea.start, a.vertex(ea.start), -i_s);
        let mut j = k;
        while j < data.x11.len() && data.x11[j].0 as usize == ia {
            let (_, ib, x, p) = data.x11[j];
            let mb = b.edges()[ib as usize].mult;
            // eq. 4.8: I11 = c_I X11, once per unit of B's edge.
            edge.assign(j as u32 | TAG_X, p, ci * x * mb);
            j += 1;
        }
        emit(&mut edge, &mut pairs, data, ia, "A")?;
        for &(s, e) in &pairs {
            let s = resolve(s, a, &mut a_ids, data, &mut x_ids, &mut out);
            let e = resolve(e, a, &mut a_ids, data, &mut x_ids, &mut out);
            out.add_edge_mult(s, e, ea.mult);
        }
    }

    // Retained parts of B's edges (eq. 4.9-4.10): the 2D X11 counts enter
    // with the opposite sign, since e_A crossing e_B left to right means
    // e_B entering A.
    let by_b = order_by_b(&data.x11, b.edge_count());
    let mut k = 0;
    for (ib, eb) in b.edges().iter().enumerate() {
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
            let ma = a.edges()[ia as usize].mult;
            edge.assign(idx | TAG_X, p, -ci * x * ma);
            j += 1;
        }
        let i_e = cb + ci * data.x20[eb.end as usize]; // eq. 4.10 at v_e
        let i_s = cb + ci * data.x20[eb.start as usize];
        edge.assign(eb.end, b.vertex(eb.end), i_e);
        edge.assign(eb.start, b.vertex(eb.start), -i_s);
        emit(&mut edge, &mut pairs, data, ib, "B")?;
        for &(s, e) in &pairs {
            let s = resolve(s, b, &mut b_ids, data, &mut x_ids, &mut out);
            let e = resolve(e, b, &mut b_ids, data, &mut x_ids, &mut out);
            out.add_edge_mult(s, e, eb.mult);
        }
    }
    Ok(out)
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
    out: &mut PolygonSet2,
) -> u32 {
    if id & TAG_X != 0 {
        let j = id & !TAG_X;
        x_ids.get(j, data.x11[j as usize].3, out)
    } else {
        own_ids.get(id, own.vertex(id), out)
    }
}

fn emit(
    edge: &mut CompositeEdge,
    pairs: &mut Vec<(u32, u32)>,
    data: &mut LevelData,
    index: usize,
    operand: &str,
) -> Result<(), BooleanError> {
    pairs.clear();
    data.composite_counts
        .push((edge.starts.len() as u32, edge.ends.len() as u32));
    pair_composite_edge(edge, pairs).ok_or_else(|| {
        BooleanError::Internal(format!(
            "Theorem 2 violated: composite edge of {operand}'s edge {index} has {} starts and {} ends",
            edge.starts.len(),
            edge.ends.len()
        ))
    })
}
