//! The guard of 3D smoothing ([`crate::SmoothOptions::guard`]): smoothing
//! is kept only where it leaves no more defects than the input had. The
//! operations of Appendix A move vertices by up to the tolerance and
//! split edges at created vertices; where two surfaces lie within the
//! tolerance of each other at an angle (a solid minus a copy of itself
//! turned by a few degrees), a merge or a crack on one surface can push a
//! facet through the other, which the raw Boolean (Theorem 2: exact
//! topology, no such pair where its operands had none) did not do. The
//! guard counts intersecting facet pairs, non-manifold edges and
//! vertices, and open edges near the facets smoothing changed, in the
//! result and, only when the result has some, in the input near the
//! facets they replaced; a result worse by
//! [`crate::MeshDefects::worse_than`] (more pairs, or as many and more
//! manifold defects) is dropped for the input. Outside the focus both
//! meshes are the same, so the comparison near it is the comparison of
//! the whole meshes.

use crate::mesh::region::Facets;
use crate::{MeshDefects, Reverted, SmoothReport};
use rayon::prelude::*;
use rustc_hash::FxHashMap;
use topology::{ManifoldReport, Point3, PolygonMesh, TriangleMesh};

/// A facet as the sorted list of its half-edges' end positions (bit
/// patterns): equal for the same facet in two meshes whatever the vertex
/// numbering and the order of its half-edges.
fn key<F: Facets + ?Sized>(pos: &[Point3], facets: &F, f: usize) -> Vec<[u64; 6]> {
    let bits = |v: u32| pos[v as usize].map(f64::to_bits);
    let mut k: Vec<[u64; 6]> = facets
        .half_edges(f)
        .map(|(s, e)| {
            let (a, b) = (bits(s), bits(e));
            [a[0], a[1], a[2], b[0], b[1], b[2]]
        })
        .collect();
    k.sort_unstable();
    k
}

/// The keys of the facets `f` with `mask[f]`, computed in parallel (each
/// a sort of a facet's half-edges).
fn keys<F: Facets + ?Sized>(
    pos: &[Point3],
    facets: &F,
    mask: &[bool],
) -> Vec<(usize, Vec<[u64; 6]>)> {
    let ids: Vec<usize> = (0..facets.count()).filter(|&f| mask[f]).collect();
    ids.into_par_iter()
        .map(|f| (f, key(pos, facets, f)))
        .collect()
}

/// The facets smoothing changed: of the candidates `before_in` of the
/// input and `after_in` of the result, those with no equal facet (same
/// half-edges at the same positions, counted with multiplicity) on the
/// other side. Unchanged facets are the same in both meshes, so the
/// defects that differ all touch these.
pub(crate) fn changed<B: Facets + ?Sized, A: Facets + ?Sized>(
    before: (&[Point3], &B, &[bool]),
    after: (&[Point3], &A, &[bool]),
) -> (Vec<bool>, Vec<bool>) {
    let (bp, bf, bin) = before;
    let (ap, af, ain) = after;
    let before_keys = keys(bp, bf, bin);
    let after_keys = keys(ap, af, ain);
    let mut count: FxHashMap<&[[u64; 6]], i64> = FxHashMap::default();
    for (_, k) in &before_keys {
        *count.entry(k.as_slice()).or_default() += 1;
    }
    // Matched facets of the result take one count each; what is left
    // over on the input side is the input's changed facets.
    let mut after_changed = vec![false; af.count()];
    for (f, k) in &after_keys {
        match count.get_mut(k.as_slice()) {
            Some(c) if *c > 0 => *c -= 1,
            _ => after_changed[*f] = true,
        }
    }
    let mut before_changed = vec![false; bf.count()];
    for (f, k) in &before_keys {
        if let Some(c) = count.get_mut(k.as_slice()) {
            if *c > 0 {
                *c -= 1;
                before_changed[*f] = true;
            }
        }
    }
    (before_changed, after_changed)
}

/// The counts of a manifold report and a pair list.
fn defects(pairs: Option<Vec<[u32; 2]>>, manifold: Option<ManifoldReport>) -> MeshDefects {
    let m = manifold.unwrap_or_default();
    MeshDefects {
        intersecting_pairs: pairs.map_or(0, |p| p.len()),
        non_manifold_edges: m.non_manifold_edges.len(),
        non_manifold_vertices: m.non_manifold_vertices.len(),
        open_edges: m.open_edges.len(),
    }
}

/// A mesh the guard inspects: its positions and facets, and its defects
/// near a focus (the exact tests of `topology`).
pub(crate) trait Guarded {
    /// The facets as the region code reads them.
    type Facets: Facets + ?Sized;
    /// The positions and the facets.
    fn parts(&self) -> (&[Point3], &Self::Facets);
    /// The defects near the facets `f` with `focus[f]`.
    fn defects_near(&self, focus: &[bool]) -> MeshDefects;
}

impl Guarded for PolygonMesh {
    type Facets = [topology::Facet];
    fn parts(&self) -> (&[Point3], &Self::Facets) {
        (&self.vertices, &self.facets)
    }
    fn defects_near(&self, focus: &[bool]) -> MeshDefects {
        defects(
            topology::self_intersecting_pairs_near(self, focus),
            self.manifold_report_near(focus),
        )
    }
}

impl Guarded for TriangleMesh {
    type Facets = [[u32; 3]];
    fn parts(&self) -> (&[Point3], &Self::Facets) {
        (&self.vertices, &self.triangles)
    }
    fn defects_near(&self, focus: &[bool]) -> MeshDefects {
        defects(
            topology::self_intersecting_triangle_pairs_near(self, focus),
            self.manifold_report_near(focus),
        )
    }
}

/// The guard on a mesh smoothed into `result`: the candidates `input_in`
/// of the input became the candidates `result_in` of the result (the
/// region and what replaced it, or everything). `Some` (the report of the
/// input handed back) when the result is worse.
pub(crate) fn guard<M: Guarded>(
    report: &SmoothReport,
    input: (&M, &[bool]),
    result: (&M, &[bool]),
) -> Option<SmoothReport> {
    let ((i, i_in), (r, r_in)) = (input, result);
    let ((ip, ifacets), (rp, rfacets)) = (i.parts(), r.parts());
    let (before, after) = changed((ip, ifacets, i_in), (rp, rfacets, r_in));
    if !after.contains(&true) {
        return None;
    }
    judge(
        report,
        || r.defects_near(&after),
        || i.defects_near(&before),
    )
}

/// The guard's decision on a smoothing run: `Some` (the report of the
/// input handed back) when the result's defects near what changed
/// (`smoothed`) are worse than the input's there (`input`, computed only
/// when the result has any).
fn judge(
    report: &SmoothReport,
    smoothed: impl FnOnce() -> MeshDefects,
    input: impl FnOnce() -> MeshDefects,
) -> Option<SmoothReport> {
    let smoothed = smoothed();
    if !smoothed.any() {
        return None;
    }
    let input = input();
    smoothed.worse_than(&input).then(|| SmoothReport {
        tolerance: report.tolerance,
        reverted: Some(Reverted {
            smoothed,
            input,
            counts: report.counts,
        }),
        ..SmoothReport::default()
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::SmoothCounts;

    #[test]
    fn a_clean_result_is_kept_without_looking_at_the_input() {
        let r = SmoothReport::default();
        let kept = judge(&r, MeshDefects::default, || {
            panic!("the input is not inspected when the result is clean")
        });
        assert_eq!(kept, None);
    }

    #[test]
    fn a_worse_result_is_reverted() {
        let r = SmoothReport {
            tolerance: 1e-9,
            counts: SmoothCounts {
                vertices_merged: 4,
                ..SmoothCounts::default()
            },
            distortion_bound: 1e-9,
            ..SmoothReport::default()
        };
        let pinch = MeshDefects {
            non_manifold_vertices: 1,
            ..MeshDefects::default()
        };
        let pairs = MeshDefects {
            intersecting_pairs: 2,
            ..MeshDefects::default()
        };
        // Fewer pairs than the input had: kept, also at the price of a
        // pinch.
        assert_eq!(
            judge(
                &r,
                || pairs,
                || MeshDefects {
                    intersecting_pairs: 5,
                    ..pairs
                }
            ),
            None
        );
        assert_eq!(judge(&r, || pinch, || pairs), None);
        // A pinch the clean input did not have: reverted.
        let back = judge(&r, || pinch, MeshDefects::default).unwrap();
        assert_eq!(back.tolerance, 1e-9);
        assert_eq!(back.counts, SmoothCounts::default());
        assert_eq!(back.distortion_bound, 0.0);
        let undone = back.reverted.unwrap();
        assert_eq!(
            (undone.smoothed, undone.input),
            (pinch, MeshDefects::default())
        );
        // More pairs: reverted even if the input had a pinch.
        let more = MeshDefects {
            intersecting_pairs: 1,
            ..MeshDefects::default()
        };
        assert!(judge(&r, || more, || pinch).is_some());
        assert_eq!(undone.counts.vertices_merged, 4);
    }

    #[test]
    fn changed_facets_are_found_by_position_whatever_the_numbering() {
        let before_pos = [
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
            [0.0, 0.0, 1.0],
        ];
        let before: Vec<[u32; 3]> = vec![[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2], [0, 1, 3]];
        // The same positions numbered backwards; the third triangle moved
        // to a new vertex, one copy of the doubled one gone.
        let after_pos = [
            [0.0, 0.0, 1.0],
            [0.0, 1.0, 0.0],
            [1.0, 0.0, 0.0],
            [0.0, 0.0, 0.0],
            [1.0, 1.0, 1.0],
        ];
        let after: Vec<[u32; 3]> = vec![[3, 1, 2], [2, 0, 3], [2, 1, 4], [0, 1, 3]];
        let all = |n: usize| vec![true; n];
        let (b, a) = changed(
            (&before_pos, before.as_slice(), &all(5)),
            (&after_pos, after.as_slice(), &all(4)),
        );
        assert_eq!(a, vec![false, false, true, false]);
        assert_eq!(b.iter().filter(|&&c| c).count(), 2);
        assert!(b[2] && (b[1] ^ b[4]));
        // Outside the candidates nothing is looked at.
        let (b, a) = changed(
            (
                &before_pos,
                before.as_slice(),
                &[false, false, true, false, false],
            ),
            (&after_pos, after.as_slice(), &[false, false, true, false]),
        );
        assert_eq!(
            (b, a),
            (
                vec![false, false, true, false, false],
                vec![false, false, true, false]
            )
        );
    }
}
