//! Hole elimination (section 4.8, step 3): every hole inside a region is
//! merged into an outer polygon by a bridge, an internal edge added as two
//! half-edges, from the hole's rightmost vertex to the boundary it sees
//! first along the +u ray (the scheme of Eberly's and the `earcut`
//! library's hole elimination), rightmost holes first.
//!
//! The polygons are linked lists, so a merge costs the hole's length, not
//! the outer polygon's. Each node carries an order label increasing along
//! its polygon from the polygon's first vertex (relabelled when a gap runs
//! out), so that ties between equally good candidates go, whatever the
//! order they are found in, to the first along the polygon. With
//! [`Search::Indexed`] the edges and vertices of the merged polygons are
//! also listed in a [`Grid`], and the ray and the bridge's triangle visit
//! only the cells they meet; [`Search::Linear`] visits them all. Both give
//! the same bridges.

use super::grid::{bounds, Grid};
use super::{in_box_and_triangle, orient, ring_area, Search, P2};

const NONE: u32 = u32::MAX;

/// Which edges with an end on the bridge's ray cross it.
#[derive(Clone, Copy)]
enum Ray {
    /// Every edge meeting the ray.
    Closed,
    /// The ray just above: edges ending on it from below miss it.
    Above,
    /// The ray just below: edges ending on it from above miss it.
    Below,
}

/// Merges every hole inside a region into an outer polygon by bridges
/// (two opposite half-edges each) and returns the outer polygons followed
/// by the holes left on their own (inside-out regions).
pub(super) fn bridge_holes(rings: Vec<Vec<(u32, P2)>>, search: Search) -> Vec<Vec<(u32, P2)>> {
    let areas: Vec<f64> = rings.iter().map(|r| ring_area(r)).collect();
    let mut outer_idx: Vec<usize> = (0..rings.len()).filter(|&i| areas[i] > 0.0).collect();
    if outer_idx.is_empty() {
        // An inside-out or degenerate facet: the loop of largest extent
        // plays the outer boundary.
        let mut best = 0;
        for i in 1..rings.len() {
            if areas[i].abs() > areas[best].abs() {
                best = i;
            }
        }
        outer_idx.push(best);
    }
    let mut is_outer = vec![false; rings.len()];
    for &i in &outer_idx {
        is_outer[i] = true;
    }
    let rightmost = |r: &[(u32, P2)]| {
        let mut k = 0;
        for i in 1..r.len() {
            let (p, q) = (r[i].1, r[k].1);
            if p[0] > q[0] || (p[0] == q[0] && p[1] > q[1]) {
                k = i;
            }
        }
        k
    };
    let mut holes: Vec<(usize, usize)> = (0..rings.len())
        .filter(|&i| !is_outer[i])
        .map(|i| (i, rightmost(&rings[i])))
        .collect();
    if holes.is_empty() {
        return outer_idx.iter().map(|&i| rings[i].clone()).collect();
    }
    // Rightmost holes first, so a hole further left may bridge into one
    // already merged (its edges are then part of the outer polygon).
    holes.sort_by(|&(i, ki), &(j, kj)| {
        let (p, q) = (rings[i][ki].1, rings[j][kj].1);
        q[0].total_cmp(&p[0])
            .then(q[1].total_cmp(&p[1]))
            .then(i.cmp(&j))
    });
    let mut lists = Lists::new(&rings, &outer_idx, holes.len(), search);
    let mut alone = Vec::new();
    for (h, k) in holes {
        let m = rings[h][k].1;
        match lists.find_bridge(m) {
            Some(x) => lists.merge(x, lists.ring_base[h], rings[h].len(), k),
            None => alone.push(rings[h].clone()),
        }
    }
    let mut out: Vec<Vec<(u32, P2)>> = (0..outer_idx.len()).map(|oi| lists.polygon(oi)).collect();
    out.extend(alone);
    out
}

/// The polygons being merged, as linked lists of nodes.
struct Lists {
    /// A node's vertex and position.
    node: Vec<(u32, P2)>,
    next: Vec<u32>,
    prev: Vec<u32>,
    /// The order label along the node's polygon.
    key: Vec<u64>,
    /// The outer polygon the node belongs to (`NONE`: an unmerged hole).
    owner: Vec<u32>,
    /// The first node of every ring (outer ones included).
    ring_base: Vec<u32>,
    /// The first node of each outer polygon.
    head: Vec<u32>,
    /// The number of nodes of each outer polygon.
    len: Vec<usize>,
    /// Label spacing when a polygon is relabelled.
    step: u64,
    /// Edges of the outer polygons, each by its start node (its end is
    /// the next node), and every node's outgoing edge.
    edge_start: Vec<u32>,
    node_edge: Vec<u32>,
    /// The edges and the nodes of the outer polygons, indexed.
    edges: Option<Grid>,
    points: Option<Grid>,
}

impl Lists {
    fn new(rings: &[Vec<(u32, P2)>], outer_idx: &[usize], holes: usize, search: Search) -> Lists {
        let total: usize = rings.iter().map(Vec::len).sum();
        let cap = total + 2 * holes;
        let step = u64::MAX / (cap as u64 + 2);
        let mut l = Lists {
            node: Vec::with_capacity(cap),
            next: Vec::with_capacity(cap),
            prev: Vec::with_capacity(cap),
            key: Vec::with_capacity(cap),
            owner: Vec::with_capacity(cap),
            ring_base: Vec::with_capacity(rings.len()),
            head: Vec::with_capacity(outer_idx.len()),
            len: Vec::with_capacity(outer_idx.len()),
            step,
            edge_start: Vec::with_capacity(cap + 2 * holes),
            node_edge: Vec::with_capacity(cap),
            edges: None,
            points: None,
        };
        for r in rings {
            let base = l.node.len() as u32;
            l.ring_base.push(base);
            for (i, &v) in r.iter().enumerate() {
                l.node.push(v);
                l.next.push(base + ((i + 1) % r.len()) as u32);
                l.prev.push(base + ((i + r.len() - 1) % r.len()) as u32);
                l.key.push(0);
                l.owner.push(NONE);
                l.node_edge.push(NONE);
            }
        }
        let finite = rings
            .iter()
            .flatten()
            .all(|(_, p)| p.iter().all(|c| c.is_finite()));
        if search == Search::Indexed && finite {
            if let Some((lo, hi)) = bounds(rings.iter().flatten().map(|v| v.1)) {
                l.edges = Some(Grid::new(lo, hi, cap));
                l.points = Some(Grid::new(lo, hi, cap));
            }
        }
        for (oi, &r) in outer_idx.iter().enumerate() {
            let base = l.ring_base[r];
            l.head.push(base);
            l.len.push(rings[r].len());
            for i in 0..rings[r].len() as u32 {
                let v = base + i;
                l.owner[v as usize] = oi as u32;
                l.key[v as usize] = (u64::from(i) + 1) * step;
                l.add_edge(v);
                l.add_point(v);
            }
        }
        l
    }

    #[inline]
    fn pos(&self, v: u32) -> P2 {
        self.node[v as usize].1
    }

    /// Records the edge from `v` to its next node.
    fn add_edge(&mut self, v: u32) {
        let e = self.edge_start.len() as u32;
        self.edge_start.push(v);
        self.node_edge[v as usize] = e;
        if let Some(g) = &mut self.edges {
            let p = self.node[v as usize].1;
            let q = self.node[self.next[v as usize] as usize].1;
            let (lo, hi) = bounds([p, q]).unwrap_or((p, p));
            g.insert(lo, hi, e);
        }
    }

    fn add_point(&mut self, v: u32) {
        if let Some(g) = &mut self.points {
            let p = self.node[v as usize].1;
            g.insert(p, p, v);
        }
    }

    /// A new node for the vertex of node `of`.
    fn copy(&mut self, of: u32) -> u32 {
        let v = self.node.len() as u32;
        self.node.push(self.node[of as usize]);
        self.next.push(NONE);
        self.prev.push(NONE);
        self.key.push(0);
        self.owner.push(self.owner[of as usize]);
        self.node_edge.push(NONE);
        v
    }

    /// The node a hole's rightmost point `m` is bridged to: the nearest
    /// boundary crossing of the ray from `m` in +u, its endpoint of larger
    /// u, or a vertex inside the triangle (m, crossing, endpoint) making
    /// the smallest angle with the ray. Ties go to the first outer polygon
    /// and the first node along it. `None` when `m` is not inside a
    /// region: the ray meets no boundary, or meets a boundary going down
    /// (entering a region from outside) strictly first.
    ///
    /// A boundary with a vertex on the ray is first met the closed way
    /// (both edges at the vertex cross the ray there). Where that finds
    /// `m` outside, the ray is also taken just above and just below `m`
    /// (an edge whose upper, resp. lower, end is on the ray misses it): a
    /// hole touching others or the outer polygon at its rightmost vertex
    /// can have a boundary running along the ray from `m` on that the
    /// closed way takes for an entry, while on one side of the ray it
    /// is plainly inside.
    fn find_bridge(&self, m: P2) -> Option<u32> {
        [Ray::Closed, Ray::Above, Ray::Below]
            .into_iter()
            .find_map(|ray| self.find_bridge_by(m, ray))
    }

    fn find_bridge_by(&self, m: P2, ray: Ray) -> Option<u32> {
        // (crossing u, outer, label, vertex)
        let mut best: Option<(f64, u32, u64, u32)> = None;
        let mut entering = f64::INFINITY;
        let visit = |best: &mut Option<(f64, u32, u64, u32)>, entering: &mut f64, e: u32| {
            let s = self.edge_start[e as usize];
            let t = self.next[s as usize];
            let (p, q) = (self.pos(s), self.pos(t));
            let (y0, y1) = (p[1].min(q[1]), p[1].max(q[1]));
            if p[1] == q[1] || m[1] < y0 || m[1] > y1 {
                return;
            }
            match ray {
                Ray::Closed => {}
                Ray::Above if m[1] == y1 => return,
                Ray::Below if m[1] == y0 => return,
                Ray::Above | Ray::Below => {}
            }
            // Exact at the endpoints, so that the two edges at a vertex on
            // the ray cross it at the same u; elsewhere interpolated from
            // the lower endpoint, so that a segment crosses at the same u
            // whichever way it runs (a bridge and its way back, or a merged
            // hole's edge and the outer's: a rounding difference between
            // the two would make the way down seem nearer and the hole be
            // taken for an inside-out region), and kept within the edge's
            // span (where the index finds it).
            let (lo, up) = if p[1] < q[1] { (p, q) } else { (q, p) };
            let x = if m[1] == p[1] {
                p[0]
            } else if m[1] == q[1] {
                q[0]
            } else {
                let x = lo[0] + (m[1] - lo[1]) * (up[0] - lo[0]) / (up[1] - lo[1]);
                let (a, b) = (p[0].min(q[0]), p[0].max(q[0]));
                if x < a {
                    a
                } else if x > b {
                    b
                } else {
                    x
                }
            };
            if x < m[0] {
                return;
            }
            if p[1] < q[1] {
                // Edges going up cross the +u ray on the right of an
                // anticlockwise outer boundary.
                let (oi, key) = (self.owner[s as usize], self.key[s as usize]);
                if best.is_none_or(|(bx, bo, bk, _)| (x, oi, key) < (bx, bo, bk)) {
                    let v = if p[0] > q[0] { s } else { t };
                    *best = Some((x, oi, key, v));
                }
            } else {
                *entering = entering.min(x);
            }
        };
        match &self.edges {
            Some(g) => {
                let row = g.row(m[1]);
                for col in g.col(m[0])..g.cols() {
                    for &e in g.cell(col, row) {
                        visit(&mut best, &mut entering, e);
                    }
                    // A crossing at u lies in its edge's box, so in the
                    // column of u: none further on is nearer.
                    if best.is_some_and(|b| col >= g.col(b.0)) {
                        break;
                    }
                }
            }
            None => {
                for e in 0..self.edge_start.len() as u32 {
                    visit(&mut best, &mut entering, e);
                }
            }
        }
        let (qx, oi, _, mut vi) = best?;
        if entering < qx {
            return None;
        }
        // Refine: a vertex inside the triangle (m, (qx, m.v), candidate) may
        // block the bridge; the one at the smallest angle to the ray does
        // not.
        let c = self.pos(vi);
        let (t0, t1, t2) = if m[1] < c[1] {
            (m, [qx, m[1]], c)
        } else {
            ([qx, m[1]], m, c)
        };
        // (tangent, u, label)
        let mut least: Option<(f64, f64, u64)> = None;
        let mut visit = |v: u32| {
            let p = self.pos(v);
            if self.owner[v as usize] == oi
                && p[0] >= m[0]
                && p[0] <= c[0]
                && p[0] != m[0]
                && p != c
                && in_box_and_triangle(t0, t1, t2, p)
            {
                let tan = (m[1] - p[1]).abs() / (p[0] - m[0]);
                let cand = (tan, p[0], self.key[v as usize]);
                if least.is_none_or(|l| cand < l) {
                    least = Some(cand);
                    vi = v;
                }
            }
        };
        match &self.points {
            Some(g) => {
                let lo = [m[0], m[1].min(c[1])];
                let hi = [c[0], m[1].max(c[1])];
                g.any_in(lo, hi, |v| {
                    visit(v);
                    false
                });
            }
            None => (0..self.node.len() as u32)
                .filter(|&v| self.owner[v as usize] != NONE)
                .for_each(&mut visit),
        }
        Some(self.facing_copy(oi, vi, m))
    }

    /// Of the nodes of outer polygon `oi` at the position of node `v` (a
    /// vertex a bridge reached before is there once per visit), the first
    /// along the polygon whose corner opens towards `m`: a bridge from
    /// another copy would leave the corner through the polygon's own
    /// edges and cross them. `v` when none does (a degenerate corner).
    fn facing_copy(&self, oi: u32, v: u32, m: P2) -> u32 {
        let c = self.pos(v);
        let mut best: Option<(u64, u32)> = None;
        let mut visit = |w: u32| {
            if self.owner[w as usize] == oi
                && self.pos(w) == c
                && best.is_none_or(|b| self.key[w as usize] < b.0)
                && self.opens_towards(w, m)
            {
                best = Some((self.key[w as usize], w));
            }
        };
        match &self.points {
            Some(g) => {
                g.any_in(c, c, |w| {
                    visit(w);
                    false
                });
            }
            None => (0..self.node.len() as u32).for_each(&mut visit),
        }
        best.map_or(v, |b| b.1)
    }

    /// Whether the direction from node `a` to `m` lies in `a`'s corner of
    /// the polygon (closed: along either side counts), the sweep
    /// anticlockwise from the way to the next node to the way back to the
    /// previous one.
    fn opens_towards(&self, a: u32, m: P2) -> bool {
        let pa = self.pos(a);
        let next = self.pos(self.next[a as usize]);
        let prev = self.pos(self.prev[a as usize]);
        let turn = orient(pa, next, prev);
        let (to_next, from_prev) = (orient(pa, next, m), orient(pa, m, prev));
        if turn > 0.0 {
            to_next >= 0.0 && from_prev >= 0.0
        } else if turn < 0.0 {
            to_next >= 0.0 || from_prev >= 0.0
        } else {
            // Straight on (the half-plane on the left), or a spike (the
            // corner is the full turn).
            let (u, w) = (
                [next[0] - pa[0], next[1] - pa[1]],
                [prev[0] - pa[0], prev[1] - pa[1]],
            );
            u[0] * w[0] + u[1] * w[1] > 0.0 || to_next >= 0.0
        }
    }

    /// Merges the hole of `len` nodes from node `base` into the polygon of
    /// node `x` by a bridge from `x` to the hole's node `k` and back.
    fn merge(&mut self, x: u32, base: u32, len: usize, k: usize) {
        let oi = self.owner[x as usize];
        let hk = base + k as u32;
        let before = base + ((k + len - 1) % len) as u32;
        let old_next = self.next[x as usize];
        let hk2 = self.copy(hk);
        let x2 = self.copy(x);
        self.owner[hk2 as usize] = oi;
        // x -> hk ... before -> hk2 -> x2 -> old next.
        self.next[x as usize] = hk;
        self.next[before as usize] = hk2;
        self.next[hk2 as usize] = x2;
        self.next[x2 as usize] = old_next;
        self.prev[hk as usize] = x;
        self.prev[hk2 as usize] = before;
        self.prev[x2 as usize] = hk2;
        self.prev[old_next as usize] = x2;
        // The edge x -> old next now starts at x2.
        let e = self.node_edge[x as usize];
        self.edge_start[e as usize] = x2;
        self.node_edge[x2 as usize] = e;
        self.add_edge(x);
        let mut v = hk;
        for _ in 0..len {
            self.owner[v as usize] = oi;
            self.add_edge(v);
            self.add_point(v);
            v = self.next[v as usize];
        }
        self.add_edge(hk2);
        self.add_point(hk2);
        self.add_point(x2);
        self.len[oi as usize] += len + 2;
        // Labels between x's and the old next's (the end of the polygon
        // when that is its first node).
        let lo = self.key[x as usize];
        let hi = if old_next == self.head[oi as usize] {
            u64::MAX
        } else {
            self.key[old_next as usize]
        };
        let gap = (hi - lo) / (len as u64 + 3);
        let mut v = hk;
        if gap > 0 {
            for i in 1..=len as u64 + 2 {
                self.key[v as usize] = lo + i * gap;
                v = self.next[v as usize];
            }
        } else {
            let mut v = self.head[oi as usize];
            for i in 1..=self.len[oi as usize] as u64 {
                self.key[v as usize] = i * self.step;
                v = self.next[v as usize];
            }
        }
    }

    /// The outer polygon `oi`, from its first vertex.
    fn polygon(&self, oi: usize) -> Vec<(u32, P2)> {
        let mut out = Vec::with_capacity(self.len[oi]);
        let mut v = self.head[oi];
        for _ in 0..self.len[oi] {
            out.push(self.node[v as usize]);
            v = self.next[v as usize];
        }
        out
    }
}
