//! Vertex merging (Appendix A, "vertex adjustment") on the working copy:
//! the crate's hash-grid merge, then the edges renamed, zero-length edges
//! removed and opposing edges cancelled. Afterwards every two vertices lie
//! farther than the tolerance apart.

use super::budget::Budget;
use super::work::Work;
use crate::{merge_vertices, SmoothCounts};

/// Merges the vertices within `tol` of an earlier accepted vertex.
pub fn merge_phase(w: &mut Work, tol: f64, counts: &mut SmoothCounts, budget: &mut Budget) {
    w.remove_unreferenced(counts);
    let m = merge_vertices(&w.pts, tol);
    if m.merged == 0 {
        return;
    }
    if !budget.spend(m.merged) {
        return;
    }
    counts.vertices_merged += m.merged;
    for (i, &r) in m.representative.iter().enumerate() {
        if r as usize != i {
            let ki = w.rec[i].k;
            let kr = &mut w.rec[r as usize].k;
            *kr = (*kr).max(ki.saturating_add(1));
        }
    }
    w.remap(&m.representative, counts);
    w.remove_unreferenced(counts);
}
