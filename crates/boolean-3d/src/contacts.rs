//! Where the two operands of a Boolean come close ([`Contacts`]): the
//! facets of each operand that lie within a distance of a facet of the
//! other, found by the broad phase's own hierarchies with the boxes grown
//! by that distance. A result facet far from every contact box is a piece
//! of one operand that the other neither cuts nor touches, which lets data
//! smoothing (chapter 5) look only where the Boolean made something new.

use crate::bvh::{Aabb, Bvh};
use crate::mesh::Flat;
use robust_arith::Point3;

/// The places where the operands of a Boolean come within
/// [`Contacts::proximity`] of each other.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Contacts {
    /// The distance asked for.
    pub proximity: f64,
    /// The exact bounding box (`[lo, hi]`) of every facet of either
    /// operand whose box comes within `proximity` of a facet box of the
    /// other operand (in the triangle-mesh variant: of the merged coplanar
    /// facets the Boolean ran on), grown by `proximity` on every side, in
    /// A's facet order then B's. Every point of either operand within
    /// `proximity` of the other operand, every intersection point, and so
    /// every vertex the Boolean created lies in one of them.
    pub boxes: Vec<[Point3; 2]>,
}

/// The facets of A and of B (sorted, each once) whose boxes come within
/// `proximity` of a box of the other operand.
pub(crate) fn near_facets(
    bvh_a: &Bvh,
    boxes_a: &[Aabb],
    bvh_b: &Bvh,
    boxes_b: &[Aabb],
    proximity: f64,
) -> [Vec<u32>; 2] {
    // Twice the distance, rounded up to single precision: the subtraction
    // in `Aabb::within` rounds to nearest, and below half a unit in the
    // last place the boxes' outward rounding already covers the gap.
    let margin = (2.0 * proximity) as f32;
    let margin = if f64::from(margin) < 2.0 * proximity {
        margin.next_up()
    } else {
        margin
    };
    let pairs = bvh_a.pairs_within(boxes_a, bvh_b, boxes_b, margin);
    let mut fa: Vec<u32> = pairs.iter().map(|p| p.0).collect();
    let mut fb: Vec<u32> = pairs.iter().map(|p| p.1).collect();
    for f in [&mut fa, &mut fb] {
        f.sort_unstable();
        f.dedup();
    }
    [fa, fb]
}

/// The exact boxes of `facets` of `m`, grown by `proximity`.
fn boxes_of(m: &Flat<'_>, facets: &[u32], proximity: f64, out: &mut Vec<[Point3; 2]>) {
    for &f in facets {
        let mut lo = [f64::INFINITY; 3];
        let mut hi = [f64::NEG_INFINITY; 3];
        for &(s, _) in &m.he[m.facet_range(f)] {
            let p = &m.pos[s as usize];
            for c in 0..3 {
                lo[c] = lo[c].min(p[c]);
                hi[c] = hi[c].max(p[c]);
            }
        }
        if lo[0] <= hi[0] {
            out.push([lo.map(|x| x - proximity), hi.map(|x| x + proximity)]);
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
