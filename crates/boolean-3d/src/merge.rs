//! The coplanar merge of the triangle-mesh variant: edge-adjacent input
//! triangles that are exactly coplanar and face the same way are merged
//! into one polygon facet before the Boolean, so that a planar region is
//! cut and re-triangulated as a whole (section 4.8), not piece by piece.
//!
//! Two triangles `(u, v, c1)` and `(v, u, c2)` sharing the edge `{u, v}`
//! are merged across it when the edge has exactly these two half-edges
//! (one each way, `u != v`), both triangles are non-degenerate, the four
//! points are coplanar by the exact `orient3d`, and `c1`, `c2` lie strictly
//! on opposite sides of the line `uv` in the plane (exact `orient2d` in a
//! coordinate projection where the first triangle is non-degenerate, which
//! maps the common plane affinely and so keeps both signs). A merged facet
//! holds every half-edge of its triangles except the merged pairs. Each
//! triangle is closed and a merged pair is a half-edge and its opposite,
//! so facet boundary closure holds for every merged facet and shape
//! boundary closure is unchanged (section 4.2), whatever the geometry:
//! the exact tests only decide where merging keeps the facets planar.

use crate::mesh::Flat;
use crate::par;
use rayon::prelude::*;
use robust_arith::{coplanar, orient2d, power_of_two_bound, Point3, UNIT_ROUNDOFF};
use std::cmp::Ordering;
use topology::TopologyError;

/// No partner / no facet.
pub(crate) const NONE: u32 = u32::MAX;

/// A triangle mesh's triangles grouped into merged facets. When nothing
/// merges (a curved mesh, the usual case at a million triangles), facet
/// `f` is input triangle `f` and the tables below are left empty: they
/// would be a quarter of the operand's memory for an identity.
pub(crate) struct Merged {
    /// `tri_off[f]..tri_off[f + 1]` index `tris`: the input triangles of
    /// facet `f`, in input order.
    tri_off: Vec<u32>,
    /// Input triangle indices grouped by facet.
    tris: Vec<u32>,
    /// For every input triangle, its place in its facet's list
    /// (`tris[tri_off[f] + tri_pos[t]] == t`).
    tri_pos: Vec<u32>,
    /// For every input half-edge `3t + k`, the half-edge it was merged
    /// with, or [`NONE`].
    partner: Vec<u32>,
    /// Whether any two triangles were merged.
    pub any: bool,
}

/// Whether the triangle `a, b, c` is non-degenerate, and then a
/// coordinate plane (dropping axis 0, 1 or 2) in which it is, with the
/// sign of its orientation there. The planes are tried in the order of
/// the approximate normal's components, largest first, so that the exact
/// `orient2d` is decided by its fast filter in the usual case; the answer
/// is exact whatever the order.
fn plane_of(a: Point3, b: Point3, c: Point3) -> Option<(usize, Ordering)> {
    let (d, e) = (
        [b[0] - a[0], b[1] - a[1], b[2] - a[2]],
        [c[0] - a[0], c[1] - a[1], c[2] - a[2]],
    );
    let n = [
        (d[1] * e[2] - d[2] * e[1]).abs(),
        (d[2] * e[0] - d[0] * e[2]).abs(),
        (d[0] * e[1] - d[1] * e[0]).abs(),
    ];
    let mut order = [0usize, 1, 2];
    order.sort_by(|&i, &j| n[j].total_cmp(&n[i]));
    order.into_iter().find_map(|axis| {
        let o = orient2d(drop_axis(a, axis), drop_axis(b, axis), drop_axis(c, axis));
        (o != Ordering::Equal).then_some((axis, o))
    })
}

#[inline]
fn drop_axis(p: Point3, axis: usize) -> [f64; 2] {
    match axis {
        0 => [p[1], p[2]],
        1 => [p[2], p[0]],
        _ => [p[0], p[1]],
    }
}

/// The first axis on which the three points share their coordinate
/// exactly (an axis-aligned triangle, the common case of CAD and CSG
/// inputs), decided without arithmetic; `None` otherwise.
#[inline]
fn constant_axis(a: Point3, b: Point3, c: Point3) -> Option<usize> {
    (0..3).find(|&k| a[k] == b[k] && a[k] == c[k])
}

/// A static filter for `orient3d` on the points of one mesh: with every
/// coordinate at most `L` in magnitude (`L` a power of two), every
/// difference is at most `2L`, every product at most `4L^2`, and the
/// permanent that Shewchuk's first-stage error bound multiplies at most
/// `48 L^3` (each rounding monotone, each bound representable), so a
/// determinant computed in his operation order beyond `errbound_A * 48 L^3`
/// has the exact sign. Within `[2^-200, 2^200]` no product can overflow,
/// and underflow errors (absolute, a few `2^-1074`) stay far below the
/// bound. Outside that range, or near zero, the exact `orient3d` decides.
#[derive(Clone, Copy, Debug)]
struct StaticOrient3d {
    bound: f64,
}

impl StaticOrient3d {
    #[cfg(test)]
    fn new(points: &[Point3]) -> StaticOrient3d {
        StaticOrient3d::with_max(crate::mesh::max_abs(points))
    }

    /// The filter for points whose coordinates are at most `max` in
    /// magnitude.
    fn with_max(max: f64) -> StaticOrient3d {
        let l = power_of_two_bound(max);
        let bound = if (2f64.powi(-200)..=2f64.powi(200)).contains(&l) {
            // Shewchuk's o3derrboundA, (7 + 56 eps) eps, on 48 L^3, and a
            // margin of 2^-40 for the rounding of the bound itself.
            let eps = UNIT_ROUNDOFF;
            (7.0 + 56.0 * eps) * eps * (48.0 * l * l * l) * (1.0 + 2f64.powi(-40))
        } else {
            f64::INFINITY
        };
        StaticOrient3d { bound }
    }

    /// Whether `orient3d(a, b, c, d)` is certainly not zero (`false`:
    /// undecided).
    #[inline]
    fn certainly_nonzero(&self, a: Point3, b: Point3, c: Point3, d: Point3) -> bool {
        let (adx, bdx, cdx) = (a[0] - d[0], b[0] - d[0], c[0] - d[0]);
        let (ady, bdy, cdy) = (a[1] - d[1], b[1] - d[1], c[1] - d[1]);
        let (adz, bdz, cdz) = (a[2] - d[2], b[2] - d[2], c[2] - d[2]);
        let det = adz * (bdx * cdy - cdx * bdy)
            + bdz * (cdx * ady - adx * cdy)
            + cdz * (adx * bdy - bdx * ady);
        det.abs() > self.bound
    }
}

/// Whether the triangles of half-edges `h1 = u->v` and `h2 = v->u` of a
/// triangle mesh's flat form may be merged across their edge.
fn mergeable(flat: &Flat<'_>, filter: &StaticOrient3d, h1: u32, h2: u32) -> bool {
    let (t1, t2) = (h1 / 3, h2 / 3);
    if t1 == t2 {
        return false;
    }
    let opposite = |h: u32| flat.he(3 * (h / 3) + (h % 3 + 2) % 3).0;
    let (u, v) = flat.he(h1);
    let (c1, c2) = (opposite(h1), opposite(h2));
    let p = |i: u32| flat.pos[i as usize];
    let (pu, pv, p1, p2) = (p(u), p(v), p(c1), p(c2));
    // Both triangles constant on one axis each ([`constant_axis`]). The
    // same first axis `k`: the four points share coordinate `k` (the
    // edge's two vertices are common), `k` is the first axis they all
    // share, and the orientations in that plane are the triangles' own
    // (`(u, v, c1)` and `(v, u, c2)` are cyclic rotations of the
    // triangles, which keep the exact sign), so the general test below
    // reduces to this comparison (a zero orientation is a degenerate
    // triangle, never merged). Different axes: the triangles are coplanar
    // only if one is constant on two axes, i.e. degenerate, and the
    // general test says no.
    if let (Some(k1), Some(k2)) = (constant_axis(pu, pv, p1), constant_axis(pv, pu, p2)) {
        if k1 != k2 {
            return false;
        }
        let o1 = orient2d(drop_axis(pu, k1), drop_axis(pv, k1), drop_axis(p1, k1));
        let o2 = orient2d(drop_axis(pv, k1), drop_axis(pu, k1), drop_axis(p2, k1));
        return o1 != Ordering::Equal && o1 == o2;
    }
    // Coplanar: the same coordinate on one axis (the common case of
    // axis-aligned facets, decided without arithmetic; that axis's
    // coordinate plane is then the one to project on), else the static
    // filter or the exact `coplanar` (`orient3d == Equal`; its residue
    // certificate decides the rounded coplanar quadrilaterals of a curved
    // mesh without the exact stage).
    let shared = (0..3).find(|&k| pu[k] == pv[k] && pu[k] == p1[k] && pu[k] == p2[k]);
    if shared.is_none() && (filter.certainly_nonzero(pu, pv, p1, p2) || !coplanar(pu, pv, p1, p2)) {
        return false;
    }
    let first = shared.and_then(|axis| {
        let o = orient2d(
            drop_axis(pu, axis),
            drop_axis(pv, axis),
            drop_axis(p1, axis),
        );
        (o != Ordering::Equal).then_some((axis, o))
    });
    let Some((axis, s1)) = first.or_else(|| plane_of(pu, pv, p1)) else {
        return false;
    };
    // Triangle 2 is (v, u, c2): the same orientation as triangle 1 in the
    // common plane means c2 on the other side of u->v.
    orient2d(
        drop_axis(pv, axis),
        drop_axis(pu, axis),
        drop_axis(p2, axis),
    ) == s1
}

impl Merged {
    /// Merges the triangles of `flat` (the flat form of a triangle mesh);
    /// returns the merge and the merged facets' flat form (`flat` itself
    /// when nothing merges).
    pub fn new(flat: Flat<'_>) -> Result<(Merged, Flat<'_>), TopologyError> {
        let n_he = flat.he_count();
        let n_t = n_he / 3;
        let filter = StaticOrient3d::with_max(flat.max_abs());
        // Candidate edges: exactly two half-edges, one each way.
        let pairs: Vec<(u32, u32)> = (0..flat.edges.len() as u32)
            .into_par_iter()
            .with_min_len(par::min_len(1))
            .filter_map(|e| {
                let hs = flat.edge_half_edges(e);
                if hs.len() != 2 {
                    return None;
                }
                let (h1, h2) = (hs[0], hs[1]);
                let (s1, e1) = flat.he(h1);
                let (s2, e2) = flat.he(h2);
                if s1 == e1 || s1 != e2 || e1 != s2 {
                    return None;
                }
                mergeable(&flat, &filter, h1, h2).then_some((h1, h2))
            })
            .collect();
        if pairs.is_empty() {
            let identity = Merged {
                tri_off: Vec::new(),
                tris: Vec::new(),
                tri_pos: Vec::new(),
                partner: Vec::new(),
                any: false,
            };
            return Ok((identity, flat));
        }
        let mut partner = vec![NONE; n_he];
        for &(h1, h2) in &pairs {
            partner[h1 as usize] = h2;
            partner[h2 as usize] = h1;
        }
        // Facets: the connected components of the triangles under merged
        // pairs, numbered by their first triangle (a flood fill from each
        // triangle not yet reached, in input order); triangles grouped by
        // a counting sort, in input order within a facet.
        let mut facet_of = vec![NONE; n_t];
        let mut n_f = 0u32;
        let mut stack: Vec<u32> = Vec::new();
        for t in 0..n_t as u32 {
            if facet_of[t as usize] != NONE {
                continue;
            }
            facet_of[t as usize] = n_f;
            stack.push(t);
            while let Some(u) = stack.pop() {
                for &p in &partner[3 * u as usize..3 * u as usize + 3] {
                    if p != NONE && facet_of[(p / 3) as usize] == NONE {
                        facet_of[(p / 3) as usize] = n_f;
                        stack.push(p / 3);
                    }
                }
            }
            n_f += 1;
        }
        let mut tri_off = vec![0u32; n_f as usize + 1];
        for &f in &facet_of {
            tri_off[f as usize + 1] += 1;
        }
        for f in 0..n_f as usize {
            tri_off[f + 1] += tri_off[f];
        }
        let mut fill = tri_off.clone();
        let mut tris = vec![0u32; n_t];
        let mut tri_pos = vec![0u32; n_t];
        for (t, &f) in facet_of.iter().enumerate() {
            tris[fill[f as usize] as usize] = t as u32;
            tri_pos[t] = fill[f as usize] - tri_off[f as usize];
            fill[f as usize] += 1;
        }
        let merged = Merged {
            tri_off,
            tris,
            tri_pos,
            partner,
            any: true,
        };
        let (tri_off, tris, partner) = (&merged.tri_off, &merged.tris, &merged.partner);
        let mut he = Vec::with_capacity(n_he - 2 * pairs.len());
        let mut old = Vec::with_capacity(n_he - 2 * pairs.len());
        let mut facet_off = Vec::with_capacity(n_f as usize + 1);
        facet_off.push(0u32);
        for f in 0..n_f as usize {
            for &t in &tris[tri_off[f] as usize..tri_off[f + 1] as usize] {
                for h in 3 * t..3 * t + 3 {
                    if partner[h as usize] == NONE {
                        he.push(flat.he(h));
                        old.push(h);
                    }
                }
            }
            facet_off.push(he.len() as u32);
        }
        let (he, facet_off, dropped) = drop_straight_vertices(flat.pos, he, facet_off);
        // Without dropped vertices the merged facets hold whole edges of
        // the triangles (a merged edge loses both of its half-edges), and
        // their edge grouping follows from the triangles' own.
        let derived = if dropped {
            Err((he, facet_off))
        } else {
            Flat::from_subset(&flat, he, facet_off, &old)
        };
        let out = match derived {
            Ok(d) => {
                debug_assert!(
                    {
                        let (he, off) = d.to_parts();
                        Flat::from_merged(flat.pos, he, off).as_ref() == Ok(&d)
                    },
                    "derived edge grouping differs"
                );
                d
            }
            Err((he, facet_off)) => Flat::from_merged(flat.pos, he, facet_off)?,
        };
        Ok((merged, out))
    }

    /// The input triangles of merged facet `f`, in input order; empty
    /// when nothing merged (facet `f` is then input triangle `f` alone).
    pub fn triangles(&self, f: u32) -> &[u32] {
        if !self.any {
            return &[];
        }
        &self.tris[self.tri_off[f as usize] as usize..self.tri_off[f as usize + 1] as usize]
    }

    /// The place of input triangle `t` in its merged facet's
    /// [`Merged::triangles`] (0 when nothing merged).
    pub fn tri_pos(&self, t: u32) -> u32 {
        self.tri_pos.get(t as usize).copied().unwrap_or(0)
    }

    /// The input half-edge that half-edge `h` was merged with, or
    /// [`NONE`].
    pub fn partner(&self, h: u32) -> u32 {
        self.partner.get(h as usize).copied().unwrap_or(NONE)
    }
}

/// Whether `v` lies strictly inside the segment `u w` exactly: the three
/// points collinear by the exact `orient2d` in every coordinate plane, and
/// `v` between `u` and `w` on every axis, not at either end.
fn strictly_between(u: Point3, v: Point3, w: Point3) -> bool {
    if v == u || v == w {
        return false;
    }
    (0..3).all(|k| u[k].min(w[k]) <= v[k] && v[k] <= u[k].max(w[k]))
        && (0..3).all(|axis| {
            orient2d(drop_axis(u, axis), drop_axis(v, axis), drop_axis(w, axis)) == Ordering::Equal
        })
}

/// Drops the vertices that only subdivide a straight edge: a vertex `v`
/// whose only half-edges are `u->v`, `v->w` in one facet and `w->v`,
/// `v->u` in another, with `v` strictly inside the segment `u w`. The two
/// pairs become `u->w` and `w->u`: each facet loses one half-edge ending
/// and one starting at `v` and keeps its balance at `u` and `w` (facet
/// boundary closure), and the shape loses `u->v, v->u, v->w, w->v` and
/// gains `u->w, w->u` (shape boundary closure), so the constraints of
/// section 4.2 hold whatever the test decides; the exact test keeps the
/// geometry (the facets' regions are unchanged). Runs of such vertices on
/// one segment go one after another, in vertex order. Also returns whether
/// any vertex was dropped.
fn drop_straight_vertices(
    pos: &[Point3],
    mut he: Vec<(u32, u32)>,
    facet_off: Vec<u32>,
) -> (Vec<(u32, u32)>, Vec<u32>, bool) {
    let n_v = pos.len();
    // Half-edges starting and ending at each vertex (saturating at 3).
    let mut starts = vec![0u8; n_v];
    let mut ends = vec![0u8; n_v];
    for &(s, e) in &he {
        starts[s as usize] = starts[s as usize].saturating_add(1).min(3);
        ends[e as usize] = ends[e as usize].saturating_add(1).min(3);
    }
    let candidate = |v: usize| starts[v] == 2 && ends[v] == 2;
    if !(0..n_v).any(candidate) {
        return (he, facet_off, false);
    }
    let mut facet = vec![0u32; he.len()];
    for f in 0..facet_off.len() - 1 {
        for h in facet_off[f]..facet_off[f + 1] {
            facet[h as usize] = f as u32;
        }
    }
    // The two incoming and two outgoing half-edges of each candidate.
    let mut inc = vec![[NONE; 2]; n_v];
    let mut out = vec![[NONE; 2]; n_v];
    let put = |slot: &mut [u32; 2], h: u32| {
        if slot[0] == NONE {
            slot[0] = h;
        } else {
            slot[1] = h;
        }
    };
    for (h, &(s, e)) in he.iter().enumerate() {
        if candidate(s as usize) {
            put(&mut out[s as usize], h as u32);
        }
        if candidate(e as usize) {
            put(&mut inc[e as usize], h as u32);
        }
    }
    let mut alive = vec![true; he.len()];
    let mut dropped = false;
    for v in 0..n_v {
        if !candidate(v) {
            continue;
        }
        let [o1, o2] = out[v];
        let [a, b] = inc[v];
        // i1: the incoming half-edge in o1's facet.
        let (i1, i2) = if facet[a as usize] == facet[o1 as usize] {
            (a, b)
        } else {
            (b, a)
        };
        let (f1, f2) = (facet[o1 as usize], facet[o2 as usize]);
        if f1 == f2 || facet[i1 as usize] != f1 || facet[i2 as usize] != f2 {
            continue;
        }
        let u = he[i1 as usize].0;
        let w = he[o1 as usize].1;
        let v32 = v as u32;
        if u == w
            || u == v32
            || w == v32
            || he[i2 as usize].0 != w
            || he[o2 as usize].1 != u
            || !strictly_between(pos[u as usize], pos[v], pos[w as usize])
        {
            continue;
        }
        // f1: u->v, v->w becomes u->w (kept in i1); f2: w->v, v->u becomes
        // w->u (kept in i2).
        he[i1 as usize] = (u, w);
        he[i2 as usize] = (w, u);
        alive[o1 as usize] = false;
        alive[o2 as usize] = false;
        dropped = true;
        // w's incoming o1 is now i1; u's incoming o2 is now i2 (when they
        // are candidates still to come).
        for (x, old, new) in [(w, o1, i1), (u, o2, i2)] {
            for slot in &mut inc[x as usize] {
                if *slot == old {
                    *slot = new;
                }
            }
        }
    }
    if !dropped {
        return (he, facet_off, false);
    }
    let mut kept = Vec::with_capacity(he.len());
    let mut off = Vec::with_capacity(facet_off.len());
    off.push(0u32);
    for f in 0..facet_off.len() - 1 {
        for h in facet_off[f]..facet_off[f + 1] {
            if alive[h as usize] {
                kept.push(he[h as usize]);
            }
        }
        off.push(kept.len() as u32);
    }
    (kept, off, true)
}

#[cfg(test)]
mod tests {
    use super::*;
    use robust_arith::orient3d;
    use topology::TriangleMesh;

    fn merged(v: Vec<Point3>, t: Vec<[u32; 3]>) -> (bool, usize, Vec<u32>) {
        let m = TriangleMesh::new(v, t);
        let flat = Flat::from_triangle_mesh(&m).unwrap();
        let n_he = 3 * m.triangles.len() as u32;
        let (merge, f) = Merged::new(flat).unwrap();
        let partner = (0..n_he).map(|h| merge.partner(h)).collect();
        (merge.any, f.facet_count(), partner)
    }

    /// A square pyramid whose base (facing down) is split along 0-2, base
    /// corner 3 at `p`: 6 triangles.
    fn pyramid_mesh(p: Point3) -> TriangleMesh {
        let v = vec![
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [1.0, 1.0, 0.0],
            p,
            [0.5, 0.5, 1.0],
        ];
        let t = vec![
            [0, 2, 1],
            [0, 3, 2],
            [0, 1, 4],
            [1, 2, 4],
            [2, 3, 4],
            [3, 0, 4],
        ];
        TriangleMesh::new(v, t)
    }

    /// [`merged`] of [`pyramid_mesh`].
    fn pyramid(p: Point3) -> (bool, usize, Vec<u32>) {
        let m = pyramid_mesh(p);
        merged(m.vertices, m.triangles)
    }

    proptest::proptest! {
        #![proptest_config(proptest::test_runner::Config::with_cases(test_support::cases(256)))]

        /// The static filter is never certain of a zero `orient3d`: random
        /// points, points on slanted lattice planes (exactly coplanar),
        /// such points moved by a few units in the last place, and points
        /// with random mantissas on the planes z = x and z = -y (exactly
        /// coplanar, rounding noise in the computed determinant), at scales
        /// from 2^-190 to 2^190, with the filter built on the points (and
        /// on a larger cloud, whose bound is looser).
        #[test]
        fn the_static_filter_only_decides_nonzero_signs(
            grid in proptest::collection::vec((-30i64..30, -30i64..30), 4),
            k in -4i64..4,
            nudge in proptest::collection::vec(-3i32..=3, 12),
            random in proptest::collection::vec(-1.0f64..1.0, 12),
            exp in -190i32..190,
            kind in 0u8..5,
            wide in proptest::bool::ANY,
        ) {
            let scale = 2f64.powi(exp);
            let ulps = |x: f64, n: i32| {
                let mut x = x;
                for _ in 0..n.unsigned_abs() {
                    x = if n > 0 { x.next_up() } else { x.next_down() };
                }
                x
            };
            let p: Vec<Point3> = (0..4)
                .map(|i| {
                    let (x, y) = grid[i];
                    let x = x - (x + 2 * y - k).rem_euclid(3);
                    let z = (k - x - 2 * y) / 3;
                    let lattice = [x as f64, y as f64, z as f64].map(|c| c * scale / 32.0);
                    match kind {
                        0 => lattice,
                        1 => [0, 1, 2].map(|c| ulps(lattice[c], nudge[3 * i + c])),
                        // The plane z = x (or z = -y), exactly, with random
                        // mantissas: the differences and products round,
                        // so the computed determinant is rounding noise.
                        2 => {
                            let (x, y) = (random[3 * i] * scale, random[3 * i + 1] * scale);
                            [x, y, x]
                        }
                        3 => {
                            let (x, y) = (random[3 * i] * scale, random[3 * i + 1] * scale);
                            [x, y, -y]
                        }
                        _ => [0, 1, 2].map(|c| random[3 * i + c] * scale),
                    }
                })
                .collect();
            let mut cloud = p.clone();
            if wide {
                cloud.push([scale * 7.0, 0.0, 0.0]);
            }
            let filter = StaticOrient3d::new(&cloud);
            if filter.certainly_nonzero(p[0], p[1], p[2], p[3]) {
                proptest::prop_assert_ne!(orient3d(p[0], p[1], p[2], p[3]), Ordering::Equal);
            }
        }
    }

    #[test]
    fn the_static_filter_decides_a_fine_sphere_and_stays_out_of_range() {
        // Most edges of a fine sphere are decided without the exact test.
        let m = test_support::shapes::uv_sphere([0.1, 0.2, 0.3], 1.0, 200, 100);
        let flat = Flat::from_triangle_mesh(&m).unwrap();
        let filter = StaticOrient3d::new(flat.pos);
        let (mut decided, mut pairs) = (0usize, 0usize);
        for e in 0..flat.edges.len() as u32 {
            let hs = flat.edge_half_edges(e);
            if hs.len() == 2 {
                let opposite = |h: u32| flat.pos[flat.he(3 * (h / 3) + (h % 3 + 2) % 3).0 as usize];
                let (u, v) = flat.he(hs[0]);
                let (pu, pv) = (flat.pos[u as usize], flat.pos[v as usize]);
                let (c1, c2) = (opposite(hs[0]), opposite(hs[1]));
                pairs += 1;
                if filter.certainly_nonzero(pu, pv, c1, c2) {
                    decided += 1;
                    assert_ne!(orient3d(pu, pv, c1, c2), Ordering::Equal);
                }
            }
        }
        assert!(decided * 2 > pairs, "{decided} of {pairs}");
        // Beyond 2^200 (or below 2^-200) nothing is decided statically.
        for l in [2f64.powi(230), 2f64.powi(-230)] {
            let f = StaticOrient3d::new(&[[l, 0.0, 0.0]]);
            assert!(!f.certainly_nonzero([0.0; 3], [l, 0.0, 0.0], [0.0, l, 0.0], [0.0, 0.0, l]));
        }
    }

    #[test]
    fn the_derived_edge_grouping_is_the_built_one() {
        // Two exactly coplanar pairs (the base, and a side split in two)
        // merge and no vertex is dropped: the merged facets' grouping is
        // derived from the triangles', and must equal a fresh build.
        let m = pyramid_mesh([0.0, 1.0, 0.0]);
        let flat = Flat::from_triangle_mesh(&m).unwrap();
        let (merge, out) = Merged::new(flat).unwrap();
        assert!(merge.any);
        let (he, off) = out.to_parts();
        let built = Flat::from_merged(&m.vertices, he, off);
        assert_eq!(built.as_ref(), Ok(&out));
        // A parent whose edge would keep one half-edge of two is refused.
        let flat = Flat::from_triangle_mesh(&m).unwrap();
        let old: Vec<u32> = (1..18).collect();
        let he: Vec<(u32, u32)> = old.iter().map(|&h| flat.he(h)).collect();
        assert!(Flat::from_subset(&flat, he, vec![0, 17], &old).is_err());
    }

    #[test]
    fn exactly_coplanar_co_oriented_triangles_merge() {
        let (any, facets, partner) = pyramid([0.0, 1.0, 0.0]);
        assert!(any);
        assert_eq!(facets, 5);
        // Half-edge 0 (0->2) of triangle 0 and half-edge 5 (2->0) of
        // triangle 1.
        assert_eq!(partner[0], 5);
        assert_eq!(partner[5], 0);
        assert_eq!(partner.iter().filter(|&&p| p != NONE).count(), 2);
    }

    #[test]
    fn bent_folded_or_degenerate_triangles_do_not_merge() {
        // Bent by the smallest subnormal out of the plane.
        assert!(!pyramid([0.0, 1.0, f64::from_bits(1)]).0);
        // The second base triangle degenerate (corner 3 on the diagonal):
        // the base does not merge (two sides, now in the plane x = y, do).
        let (_, facets, partner) = pyramid([0.5, 0.5, 0.0]);
        assert_eq!((partner[0], partner[5]), (NONE, NONE));
        assert_eq!(facets, 5);
        // A triangle and its reverse (a closed two-sided sheet): every edge
        // joins coplanar triangles folded onto each other.
        let v = vec![[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]];
        assert!(!merged(v, vec![[0, 1, 2], [1, 0, 2]]).0);
    }

    #[test]
    fn a_non_manifold_edge_is_not_merged_across() {
        // Four coplanar triangles on the edge 0-1 (two sheets).
        let v = vec![
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
            [0.5, -1.0, 0.0],
        ];
        let t = vec![
            [0, 1, 2],
            [1, 0, 3],
            [0, 2, 1],
            [1, 3, 0],
            [0, 1, 2],
            [1, 0, 3],
            [0, 2, 1],
            [1, 3, 0],
        ];
        let (any, facets, _) = merged(v, t);
        assert!(!any);
        assert_eq!(facets, 8);
    }
}
