//! Where the two operands of a Boolean come close ([`Contacts`]): the
//! facets of each operand that lie within a distance of a facet of the
//! other, found by the broad phase's own hierarchies with the boxes grown
//! by that distance. A result facet far from every contact box is a piece
//! of one operand that the other neither cuts nor touches, which lets data
//! smoothing (chapter 5) look only where the Boolean made something new.

use crate::mesh::Flat;
use rayon::prelude::*;
use robust_arith::Point3;

/// The places where the operands of a Boolean come within
/// [`Contacts::proximity`] of each other.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Contacts {
    /// The distance asked for.
    pub proximity: f64,
    /// The exact bounding box (`[lo, hi]`) of every facet of either
    /// operand (in the triangle-mesh variant: of the merged coplanar
    /// facets the Boolean ran on) that may come within `proximity` of a
    /// facet of the other operand, grown by `proximity` on every side, in
    /// A's facet order then B's; in the triangle-mesh variant followed by
    /// the box of every region re-triangulated anew although its merged
    /// facet held several input triangles, grown alike (the result's
    /// triangles differ from the operands' there, also where a merge
    /// dropped a vertex that only subdivided a straight edge, away from
    /// the other operand). A facet pair counts when their boxes come
    /// within `proximity` and no plane of either facet separates them by
    /// more than `proximity` (a conservative test: never a pair that does
    /// come that close left out). Every point of either operand within
    /// `proximity` of the other operand, every intersection point, and so
    /// every vertex the Boolean created lies in one of them.
    pub boxes: Vec<[Point3; 2]>,
}

impl Contacts {
    /// Adds the exact boxes `changed` (regions the triangle variant's
    /// re-triangulation made anew), grown by the proximity, after those
    /// of the operands' facets.
    pub(crate) fn add_changed(&mut self, changed: Vec<[Point3; 2]>) {
        let p = self.proximity;
        self.boxes.extend(changed.into_iter().map(|b| grown(b, p)));
    }
}

/// The exact bounding box of `points` (`lo > hi` when there are none).
pub(crate) fn exact_box(points: impl IntoIterator<Item = Point3>) -> [Point3; 2] {
    let mut lo = [f64::INFINITY; 3];
    let mut hi = [f64::NEG_INFINITY; 3];
    for p in points {
        for c in 0..3 {
            lo[c] = lo[c].min(p[c]);
            hi[c] = hi[c].max(p[c]);
        }
    }
    [lo, hi]
}

/// Box `b` grown by `proximity` on every side.
fn grown([lo, hi]: [Point3; 2], proximity: f64) -> [Point3; 2] {
    [lo.map(|x| x - proximity), hi.map(|x| x + proximity)]
}

/// The single-precision margin of the broad phase for `proximity`: twice
/// the distance, rounded up. The subtraction in `Aabb::within` rounds to
/// nearest, and below half a unit in the last place the boxes' outward
/// rounding already covers the gap.
pub(crate) fn margin(proximity: f64) -> f32 {
    let m = (2.0 * proximity) as f32;
    if f64::from(m) < 2.0 * proximity {
        m.next_up()
    } else {
        m
    }
}

/// Whether a plane of facet `f` of `m` separates it from facet `g` of
/// `o` by more than `proximity`: the facet's Newell normal `n` (any
/// direction would do), the slab `|n.(x - p0)| <= t` holding the facet's
/// own vertices (t is 0 for an exactly planar facet, up to rounding), and
/// every vertex of `g` farther than `t + proximity` beyond one side of it,
/// with a margin of `64 u L` for the rounding of the signed distances
/// (`L` the largest coordinate involved). Then no point of `g` comes
/// within `proximity` of `f`. `false` when the facet has no normal.
fn separated(m: &Flat<'_>, f: u32, o: &Flat<'_>, g: u32, proximity: f64) -> bool {
    let edges = m.facet_half_edges(f);
    let Some((first, _)) = edges.clone().next() else {
        return false;
    };
    let mut n = [0.0f64; 3];
    for (s, e) in edges.clone() {
        let (p, q) = (m.pos[s as usize], m.pos[e as usize]);
        n[0] += (p[1] - q[1]) * (p[2] + q[2]);
        n[1] += (p[2] - q[2]) * (p[0] + q[0]);
        n[2] += (p[0] - q[0]) * (p[1] + q[1]);
    }
    let len = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
    if !(len > 0.0 && len.is_finite()) {
        return false;
    }
    let p0 = m.pos[first as usize];
    let mut big = 0.0f64;
    let mut dist = |x: &Point3| {
        big = big.max(x[0].abs()).max(x[1].abs()).max(x[2].abs());
        (n[0] * (x[0] - p0[0]) + n[1] * (x[1] - p0[1]) + n[2] * (x[2] - p0[2])) / len
    };
    let own = edges
        .map(|(s, _)| dist(&m.pos[s as usize]).abs())
        .fold(0.0, f64::max);
    let (mut above, mut below) = (f64::INFINITY, f64::NEG_INFINITY);
    for (s, _) in o.facet_half_edges(g) {
        let d = dist(&o.pos[s as usize]);
        above = above.min(d);
        below = below.max(d);
    }
    let t = own + proximity + 64.0 * f64::EPSILON * big.max(f64::MIN_POSITIVE);
    above > t || below < -t
}

/// The facets of A and of B (sorted, each once) in the facet pairs the
/// broad phase found within the margin that no plane of either facet
/// separates by more than `proximity` ([`separated`]).
pub(crate) fn near_facets(
    a: &Flat<'_>,
    b: &Flat<'_>,
    pairs: &[(u32, u32)],
    proximity: f64,
) -> [Vec<u32>; 2] {
    let near: Vec<(u32, u32)> = pairs
        .par_iter()
        .with_min_len(crate::par::min_len(1))
        .filter(|&&(fa, fb)| {
            !separated(a, fa, b, fb, proximity) && !separated(b, fb, a, fa, proximity)
        })
        .copied()
        .collect();
    let mut fa: Vec<u32> = near.iter().map(|p| p.0).collect();
    let mut fb: Vec<u32> = near.iter().map(|p| p.1).collect();
    for f in [&mut fa, &mut fb] {
        f.sort_unstable();
        f.dedup();
    }
    [fa, fb]
}

/// The exact boxes of `facets` of `m`, grown by `proximity`.
fn boxes_of(m: &Flat<'_>, facets: &[u32], proximity: f64, out: &mut Vec<[Point3; 2]>) {
    for &f in facets {
        let b = exact_box(m.facet_half_edges(f).map(|(s, _)| m.pos[s as usize]));
        if b[0][0] <= b[1][0] {
            out.push(grown(b, proximity));
        }
    }
}

/// The [`Contacts`] of the near facets of both operands.
pub(crate) fn contacts(
    a: &Flat<'_>,
    b: &Flat<'_>,
    near: &[Vec<u32>; 2],
    proximity: f64,
) -> Contacts {
    let mut boxes = Vec::with_capacity(near[0].len() + near[1].len());
    boxes_of(a, &near[0], proximity, &mut boxes);
    boxes_of(b, &near[1], proximity, &mut boxes);
    Contacts { proximity, boxes }
}
