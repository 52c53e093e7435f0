//! Rounding a mesh to `f32` coordinates for the formats that store them
//! (binary STL, glTF) without adding self-intersections.
//!
//! A Boolean result is computed and checked in `f64`. Its new vertices
//! (the intersection points) are generally not `f32` values, and where the
//! result has features closer than an `f32` spacing (the thin triangles
//! along an intersection curve) rounding every coordinate to the nearest
//! `f32` can fold a triangle over its neighbour or push one through
//! another: the 1M-triangle sphere difference of the benchmarks, free of
//! intersecting facet pairs in `f64`, had 40 such pairs once written as
//! binary STL, and one pair of its vertices, apart in `f64`, rounded to
//! one point (which a reader welds into a pinch, so the file read back was
//! not a 2-manifold). So rounding is repaired where it breaks something:
//!
//! 1. The mesh is triangulated by internal edges (section 4.8) if it is
//!    not a triangle mesh (the formats store triangles), and every
//!    coordinate is rounded to the nearest `f32`.
//! 2. Only facets with a vertex that moved can meet another facet anew, so
//!    the exact self-intersection test runs on their neighbourhood alone
//!    ([`topology::self_intersecting_triangle_pairs_near`]); a mesh whose
//!    coordinates were all `f32` values (read from STL or glTF and not
//!    cut) costs one pass over its vertices. Vertices apart in `f64` that
//!    round to one point are found by hashing the rounded positions.
//! 3. The moved vertices of the facets of every pair found, and the
//!    vertices that coincide, are rounded to
//!    other corners of their `f32` grid cells where that removes pairs
//!    (each vertex in turn takes the best of its cell's eight corners, by
//!    the exact test on the facets around it, counted on the facets whose
//!    boxes can meet theirs wherever it lies in its cell, and its own
//!    coincidences), up to three passes while each removes some: no
//!    vertex merges, so a 2-manifold stays one, and each coordinate stays
//!    within one `f32` spacing of its `f64` value. This removes the folds
//!    of thin triangles, which are what rounding makes (every case
//!    measured needed one pass).
//! 4. While pairs remain, the triangles are smoothed near them
//!    ([`smooth::smooth_triangles_near`]: the boxes of the facets of every
//!    pair, grown by the tolerance) at a tolerance of twice the `f32`
//!    spacing at the mesh's largest coordinate, four times larger on each
//!    of at most [`MAX_PASSES`] passes, and rounded again; the test then
//!    covers the facets near the smoothed boxes and those whose vertices
//!    moved.
//!
//! The closure constraints hold throughout (smoothing keeps them). If
//! pairs remain after the last pass, or a smoothing pass refuses the
//! rounded mesh, the mesh with the fewest is returned and the report says
//! how many are left: this happens only where the `f64` result has
//! features a few `f32` spacings thin (a solid minus itself moved by
//! 10^-6 of its size: 319 pairs from plain rounding, 21 left), which have
//! no faithful `f32` form; from features of 10^-4 of the size up nothing
//! was ever left (the property test). A pair already
//! present in the `f64` mesh among facets that rounding does not move is
//! not looked for (it is not rounding's doing). A mesh that is not a
//! closed solid is rounded plainly (a writer writes what it is given).
//!
//! Cost, on the 1M-triangle sphere difference (`umbra boolean difference
//! A B -o d.stl`, release build): with operands read from STL (only the
//! new vertices move) 0.64 s beside the Boolean's 0.6 s; with operands of
//! `f64` coordinates (every vertex moves, so the whole mesh is tested)
//! writing `d.stl` takes 1.4-1.55 s more than writing `d.ply` (2.5-2.6 s
//! before the whole-mesh test skipped its neighbourhood search and each
//! corner was judged by the pairs around its own vertex).

use crate::{as_triangle_mesh, SmoothOptions};
use robust_arith::Point3;
use serde::Serialize;
use topology::{self_intersecting_triangle_pairs_near, PolygonMesh, TriangleMesh};

/// The most smoothing passes: the last tolerance is `2 * 4^7 = 32768`
/// `f32` spacings (about 0.4% of the largest coordinate).
const MAX_PASSES: u32 = 8;

/// What [`round_to_f32`] did.
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct F32Rounding {
    /// Vertices whose coordinates were not all `f32` values.
    pub moved_vertices: usize,
    /// Facet pairs that plain rounding made intersect.
    pub pairs_from_rounding: usize,
    /// Pairs of vertices, apart in `f64`, that plain rounding made
    /// coincide (a reader of the file would weld them into one).
    pub collisions_from_rounding: usize,
    /// Passes that rounded the moved vertices of those facets and vertices
    /// to other corners of their `f32` grid cells, before any smoothing.
    pub corner_passes: u32,
    /// Smoothing passes run to remove the pairs left.
    pub passes: u32,
    /// The tolerance of the last pass (0 when none ran).
    pub tolerance: f64,
    /// Intersecting facet pairs left (0 unless every pass failed).
    pub pairs_left: usize,
    /// Coinciding vertex pairs left in the mesh returned (0 unless the
    /// corner passes failed and smoothing, when it ran for pairs, did not
    /// merge them).
    pub collisions_left: usize,
}

/// A mesh of `f32` coordinates and how it was made.
#[derive(Clone, Debug)]
pub struct RoundedToF32 {
    /// Triangles only, every coordinate an `f32` value.
    pub mesh: TriangleMesh,
    /// What rounding and repairing did.
    pub report: F32Rounding,
}

/// What rounding to `f32` wrote in place of the mesh given (`EncodedMesh::rounded` with
/// the feature `io`).
#[derive(Clone, Debug)]
pub struct RoundedMesh {
    /// The mesh the file holds: triangles, every coordinate an `f32`
    /// value, welded by exact position as the format's reader welds it.
    pub mesh: PolygonMesh,
    /// What [`round_to_f32`] did (its `pairs_left` and
    /// `collisions_left` are the defects the file keeps).
    pub report: F32Rounding,
    /// Wall-clock milliseconds of the rounding and its repair.
    pub ms: f64,
}

/// `x` rounded to the nearest `f32`, as `f64`; non-finite values and
/// values beyond the `f32` range are kept (the writers refuse them).
fn round(x: f64) -> f64 {
    let r = x as f32;
    if r.is_finite() {
        f64::from(r)
    } else {
        x
    }
}

/// Rounds every vertex; returns which vertices moved.
fn round_vertices(vertices: &mut [Point3]) -> Vec<bool> {
    vertices
        .iter_mut()
        .map(|p| {
            let q = p.map(round);
            let moved = q != *p;
            *p = q;
            moved
        })
        .collect()
}

/// The facets with a moved vertex.
fn facets_touching(mesh: &TriangleMesh, moved: &[bool]) -> Vec<bool> {
    mesh.triangles
        .iter()
        .map(|t| {
            t.iter()
                .any(|&v| moved.get(v as usize).copied().unwrap_or(false))
        })
        .collect()
}

/// The box of triangle `t`, grown by `d` on every side.
fn grown_box(mesh: &TriangleMesh, t: [u32; 3], d: f64) -> [Point3; 2] {
    let mut b = [[f64::INFINITY; 3], [f64::NEG_INFINITY; 3]];
    for v in t {
        if let Some(p) = mesh.vertices.get(v as usize) {
            for k in 0..3 {
                b[0][k] = b[0][k].min(p[k] - d);
                b[1][k] = b[1][k].max(p[k] + d);
            }
        }
    }
    b
}

/// `true` when the closed boxes meet.
fn overlap(a: &[Point3; 2], b: &[Point3; 2]) -> bool {
    (0..3).all(|k| a[0][k] <= b[1][k] && b[0][k] <= a[1][k])
}

/// The intersecting facet pairs holding a facet of `focus` (`None` for a
/// mesh the test cannot take: non-finite coordinates).
fn pairs(mesh: &TriangleMesh, focus: &[bool]) -> Option<Vec<[u32; 2]>> {
    if !focus.contains(&true) {
        return Some(Vec::new());
    }
    self_intersecting_triangle_pairs_near(mesh, focus)
}

/// The pairs of vertices whose rounded positions coincide although their
/// `f64` positions differ: a file of `f32` positions cannot tell them
/// apart, and its reader welds them into one (a pinch where the mesh was
/// a 2-manifold).
fn collisions(exact: &[Point3], rounded: &[Point3]) -> Vec<[u32; 2]> {
    let mut first: std::collections::HashMap<[u64; 3], u32> =
        std::collections::HashMap::with_capacity(rounded.len());
    let mut out = Vec::new();
    for (v, p) in rounded.iter().enumerate() {
        let key = p.map(|x| (x + 0.0).to_bits());
        match first.entry(key) {
            std::collections::hash_map::Entry::Vacant(e) => {
                e.insert(v as u32);
            }
            std::collections::hash_map::Entry::Occupied(e) => {
                let u = *e.get();
                if exact[u as usize] != exact[v] {
                    out.push([u, v as u32]);
                }
            }
        }
    }
    out
}

/// The pairs of vertices at one position (each vertex paired with the
/// first at its position; `-0.0` and `0.0` alike, as readers weld and as
/// smoothing merges). Also the CSG clean-up's trigger (`model/clean.rs`).
pub(crate) fn coincident_pairs(vertices: &[Point3]) -> usize {
    let mut seen: rustc_hash::FxHashSet<[u64; 3]> =
        rustc_hash::FxHashSet::with_capacity_and_hasher(vertices.len(), Default::default());
    vertices
        .iter()
        .filter(|p| !seen.insert(p.map(|x| (x + 0.0).to_bits())))
        .count()
}

/// The facets sharing a vertex with a facet of `set`, and those of `set`.
fn grow_by_vertex(mesh: &TriangleMesh, set: &[bool]) -> Vec<bool> {
    let mut at = vec![false; mesh.vertices.len()];
    for (t, _) in mesh.triangles.iter().zip(set).filter(|(_, &s)| s) {
        for &v in t {
            if let Some(a) = at.get_mut(v as usize) {
                *a = true;
            }
        }
    }
    mesh.triangles
        .iter()
        .zip(set)
        .map(|(t, &s)| {
            s || t
                .iter()
                .any(|&v| at.get(v as usize).copied().unwrap_or(false))
        })
        .collect()
}

/// The two `f32` values around `x` (equal when `x` is one), as `f64`.
fn f32_around(x: f64) -> [f64; 2] {
    let r = x as f32;
    let (lo, hi) = if f64::from(r) > x {
        (r.next_down(), r)
    } else if f64::from(r) < x {
        (r, r.next_up())
    } else {
        (r, r)
    };
    if lo.is_finite() && hi.is_finite() {
        [f64::from(lo), f64::from(hi)]
    } else {
        [round(x); 2]
    }
}

/// Grows box `b` to hold point `p`.
fn include(b: &mut [Point3; 2], p: &Point3) {
    for k in 0..3 {
        b[0][k] = b[0][k].min(p[k]);
        b[1][k] = b[1][k].max(p[k]);
    }
}

/// The empty box (every [`include`] makes it the point's).
const EMPTY_BOX: [Point3; 2] = [[f64::INFINITY; 3], [f64::NEG_INFINITY; 3]];

/// The box of the corners of `t` in `m`, vertex `v` taken anywhere in
/// `cell`.
fn box_with_cell(m: &TriangleMesh, t: [u32; 3], v: u32, cell: &[Point3; 2]) -> [Point3; 2] {
    let mut b = EMPTY_BOX;
    for w in t {
        if w == v {
            include(&mut b, &cell[0]);
            include(&mut b, &cell[1]);
        } else {
            include(&mut b, &m.vertices[w as usize]);
        }
    }
    b
}

/// The facets `f` of `m` with `keep(f)` as a mesh of their own vertices
/// (numbered in order of first use): the mesh, the index in `m` of each of
/// its vertices, and the index in it of each vertex of `m` (`u32::MAX` for
/// a vertex no kept facet uses).
fn sub_mesh(m: &TriangleMesh, keep: impl Fn(usize) -> bool) -> (TriangleMesh, Vec<u32>, Vec<u32>) {
    let mut index = vec![u32::MAX; m.vertices.len()];
    let mut global = Vec::new();
    let mut sub = TriangleMesh::default();
    for (f, t) in m.triangles.iter().enumerate() {
        if !keep(f) {
            continue;
        }
        sub.triangles.push(t.map(|w| {
            let at = &mut index[w as usize];
            if *at == u32::MAX {
                *at = global.len() as u32;
                global.push(w);
                sub.vertices.push(m.vertices[w as usize]);
            }
            *at
        }));
    }
    (sub, global, index)
}

/// The facets of `m` that [`self_intersecting_triangle_pairs_near`] looks
/// at for the facets around vertex `v`, wherever `v` lies in the box
/// `cell`, as a mesh of its own: the facets whose boxes meet the box of
/// the facets around `v` (`v` anywhere in its cell), and those whose boxes
/// meet the box of all of these. That holds both box rings of the test
/// for every position of `v` in the cell, so the pairs of the facets
/// around `v` are the same on it as on `m`. Returns the mesh, the index
/// of `v` in it and its facets around `v`.
fn corner_neighbourhood(
    m: &TriangleMesh,
    v: u32,
    cell: [Point3; 2],
) -> (TriangleMesh, u32, Vec<bool>) {
    let boxes: Vec<[Point3; 2]> = m
        .triangles
        .iter()
        .map(|&t| box_with_cell(m, t, v, &cell))
        .collect();
    let union = |pick: &dyn Fn(usize) -> bool| {
        let mut u = EMPTY_BOX;
        for (_, b) in boxes.iter().enumerate().filter(|&(f, _)| pick(f)) {
            include(&mut u, &b[0]);
            include(&mut u, &b[1]);
        }
        u
    };
    let star_box = union(&|f| m.triangles[f].contains(&v));
    let first: Vec<bool> = boxes.iter().map(|b| overlap(b, &star_box)).collect();
    let first_box = union(&|f| first[f]);
    let (near, _, index) = sub_mesh(m, |f| overlap(&boxes[f], &first_box));
    let at = index[v as usize];
    let around = near.triangles.iter().map(|t| t.contains(&at)).collect();
    (near, at, around)
}

/// Rounds the vertices of the facets in `found` to other corners of their
/// `f32` grid cells where that removes intersecting pairs: each moved
/// vertex of those facets in turn takes the corner of its cell (of the
/// eight) that leaves the fewest pairs among the facets two vertex-rings
/// around them, twice over. Nothing merges, so the mesh keeps its
/// topology (a 2-manifold stays one); every vertex stays within one `f32`
/// spacing of its `f64` position. Returns the facets whose vertices
/// changed.
fn choose_corners(
    exact: &[Point3],
    mesh: &mut TriangleMesh,
    found: &[[u32; 2]],
    collided: &[[u32; 2]],
) -> Vec<bool> {
    let mut seed = vec![false; mesh.triangles.len()];
    for &f in found.iter().flatten() {
        if let Some(s) = seed.get_mut(f as usize) {
            *s = true;
        }
    }
    let mut hit = vec![false; mesh.vertices.len()];
    for &v in collided.iter().flatten() {
        hit[v as usize] = true;
    }
    for (f, t) in mesh.triangles.iter().enumerate() {
        if t.iter().any(|&v| hit[v as usize]) {
            seed[f] = true;
        }
    }
    let region = grow_by_vertex(mesh, &grow_by_vertex(mesh, &seed));
    // The region as a mesh of its own vertices.
    let (mut sub, global, local) = sub_mesh(mesh, |f| region[f]);
    let mut is_movable = vec![false; sub.vertices.len()];
    let mut movable: Vec<u32> = Vec::new();
    for (t, _) in mesh.triangles.iter().zip(&seed).filter(|(_, &s)| s) {
        for v in t {
            let (g, l) = (*v as usize, local[*v as usize]);
            if exact[g] != mesh.vertices[g] && !is_movable[l as usize] {
                is_movable[l as usize] = true;
                movable.push(l);
            }
        }
    }
    let sub_exact: Vec<Point3> = global.iter().map(|&g| exact[g as usize]).collect();
    // The vertices, apart from `v` in `f64`, at its rounded position.
    let coincident = |m: &TriangleMesh, v: u32| {
        let (p, e) = (m.vertices[v as usize], sub_exact[v as usize]);
        m.vertices
            .iter()
            .zip(&sub_exact)
            .filter(|&(q, x)| *q == p && *x != e)
            .count()
    };
    for _ in 0..2 {
        let mut left = 0;
        for &v in &movable {
            let p = exact[global[v as usize] as usize];
            let [xs, ys, zs] = [f32_around(p[0]), f32_around(p[1]), f32_around(p[2])];
            let cell = [[xs[0], ys[0], zs[0]], [xs[1], ys[1], zs[1]]];
            // Moving `v` changes only the pairs holding one of its facets
            // and the coincidences of `v` itself, so the corners of its
            // cell are ranked by those alone (the rest of the region's
            // count is the same for all eight), the pairs counted on the
            // facets that can take part in them wherever `v` lies in its
            // cell (`corner_neighbourhood`).
            let (mut near, at, around) = corner_neighbourhood(&sub, v, cell);
            let local = |near: &TriangleMesh, sub: &TriangleMesh| {
                pairs(near, &around).map_or(usize::MAX, |found| found.len()) + coincident(sub, v)
            };
            let mut keep = sub.vertices[v as usize];
            let mut best = local(&near, &sub);
            let corners = xs
                .into_iter()
                .flat_map(|x| ys.into_iter().flat_map(move |y| zs.map(|z| [x, y, z])));
            for corner in corners {
                if best == 0 {
                    break;
                }
                sub.vertices[v as usize] = corner;
                near.vertices[at as usize] = corner;
                let k = local(&near, &sub);
                if k < best {
                    best = k;
                    keep = corner;
                }
            }
            sub.vertices[v as usize] = keep;
            left += best;
        }
        if left == 0 {
            break;
        }
    }
    let mut changed = vec![false; mesh.vertices.len()];
    for &v in &movable {
        let g = global[v as usize] as usize;
        if mesh.vertices[g] != sub.vertices[v as usize] {
            mesh.vertices[g] = sub.vertices[v as usize];
            changed[g] = true;
        }
    }
    facets_touching(mesh, &changed)
}

/// Rounds `mesh` to `f32` coordinates, triangulated, smoothing away any
/// self-intersection that rounding creates (see the module docs).
///
/// ```
/// use umbra::{boolean_solid, round_to_f32, uv_sphere, BooleanOp, MeshVariant};
/// use umbra::{transform_mesh, DMat4, DVec3};
/// let a = uv_sphere(1.0, 48, 24).unwrap();
/// let b = transform_mesh(&a, &DMat4::from_translation(DVec3::new(0.3, 0.2, 0.1))).unwrap();
/// let d = boolean_solid(&a, &b, BooleanOp::Difference, MeshVariant::TriangleMesh).unwrap();
/// let r = round_to_f32(&d.mesh);
/// assert!(r.report.moved_vertices > 0);
/// assert_eq!(r.report.pairs_left, 0);
/// assert!(r.mesh.vertices.iter().flatten().all(|&x| f64::from(x as f32) == x));
/// assert!(r.mesh.to_polygon_mesh().check_topology().is_ok());
/// ```
pub fn round_to_f32(mesh: &PolygonMesh) -> RoundedToF32 {
    let mut current = match as_triangle_mesh(mesh) {
        Some(t) => t,
        None => topology::triangulate_mesh(mesh),
    };
    let exact = current.vertices.clone();
    let moved = round_vertices(&mut current.vertices);
    let mut report = F32Rounding {
        moved_vertices: moved.iter().filter(|&&m| m).count(),
        ..F32Rounding::default()
    };
    let Some(mut found) = pairs(&current, &facets_touching(&current, &moved)) else {
        return RoundedToF32 {
            mesh: current,
            report,
        };
    };
    report.pairs_from_rounding = found.len();
    let mut collided = if report.moved_vertices > 0 {
        collisions(&exact, &current.vertices)
    } else {
        Vec::new()
    };
    report.collisions_from_rounding = collided.len();
    // Repairs need a closed solid; any other mesh is rounded plainly (a
    // writer writes what it is given).
    if (!found.is_empty() || !collided.is_empty()) && current.check_topology().is_err() {
        report.pairs_left = found.len();
        report.collisions_left = collided.len();
        return RoundedToF32 {
            mesh: current,
            report,
        };
    }
    for _ in 0..3 {
        if found.is_empty() && collided.is_empty() {
            break;
        }
        report.corner_passes += 1;
        let before = found.len() + collided.len();
        let changed = choose_corners(&exact, &mut current, &found, &collided);
        // Pairs anywhere near the moved corners, and those left.
        let mut focus = changed;
        for &f in found.iter().flatten() {
            focus[f as usize] = true;
        }
        found = pairs(&current, &focus).unwrap_or_default();
        collided = collisions(&exact, &current.vertices);
        if found.len() + collided.len() >= before {
            // A pass that removed nothing leaves the next one the same
            // choices (a countersunk plate: 46 pairs and 2 coincidences
            // after the second pass and the third, 2 s each); smoothing
            // takes what is left.
            break;
        }
    }
    report.collisions_left = collided.len();
    let max_abs = current
        .vertices
        .iter()
        .flatten()
        .fold(0.0f64, |a, &x| a.max(x.abs()));
    // The spacing of `f32` values at the largest coordinate (its ulp).
    let spacing = if max_abs > 0.0 {
        let e = max_abs.log2().floor();
        f64::from(f32::EPSILON) * e.exp2()
    } else {
        f64::from(f32::MIN_POSITIVE)
    };
    // The fewest pairs, the mesh, and whether smoothing made it.
    let mut best = (found.len(), current.clone(), false);
    let mut tolerance = 2.0 * spacing;
    while !found.is_empty() && report.passes < MAX_PASSES {
        report.passes += 1;
        report.tolerance = tolerance;
        let boxes: Vec<[Point3; 2]> = found
            .iter()
            .flat_map(|p| p.map(|f| grown_box(&current, current.triangles[f as usize], tolerance)))
            .collect();
        // A smoothing that fails (its own checks refuse the rounded mesh)
        // ends the repair: the best mesh so far is written, and the report
        // says what is left.
        let Ok(smoothed) =
            smooth::smooth_triangles_near(&current, &SmoothOptions::new(tolerance), &boxes)
        else {
            break;
        };
        let mut next = smoothed.shape;
        let moved = round_vertices(&mut next.vertices);
        let mut focus = facets_touching(&next, &moved);
        for (f, t) in next.triangles.iter().enumerate() {
            if !focus[f] {
                let b = grown_box(&next, *t, 0.0);
                focus[f] = boxes.iter().any(|c| overlap(&b, c));
            }
        }
        current = next;
        found = pairs(&current, &focus).unwrap_or_default();
        if found.len() < best.0 {
            best = (found.len(), current.clone(), true);
        }
        tolerance *= 4.0;
    }
    report.pairs_left = best.0;
    if best.2 {
        // Smoothing merged and renumbered vertices, so the coincidences
        // left are counted again on the mesh returned: those beyond the
        // `f64` mesh's own (which a reader of any format welds alike).
        // Smoothing near the pairs merges those it reaches (the
        // countersunk plate: 2 after the corner passes, none after).
        report.collisions_left =
            coincident_pairs(&best.1.vertices).saturating_sub(coincident_pairs(&exact));
    }
    RoundedToF32 {
        mesh: best.1,
        report,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{boolean_solid, uv_sphere, BooleanOp, MeshVariant};
    use proptest::strategy::Strategy;
    use topology::check_mesh;

    /// PyVista's mesh `name` and a copy turned by 1, 2 and 3 degrees about
    /// x, y and z and shifted by (0.37, 0.21, 0.13).
    fn with_turned_copy(name: &str) -> (PolygonMesh, PolygonMesh) {
        let path = test_support::data_path(&format!("pyvista/{name}.ply"));
        let a = crate::read_mesh(&path, crate::MeshReadOptions::default(), true).unwrap();
        let turn = glam::DMat4::from_translation(glam::DVec3::new(0.37, 0.21, 0.13))
            * glam::DMat4::from_euler(
                glam::EulerRot::XYZ,
                1f64.to_radians(),
                2f64.to_radians(),
                3f64.to_radians(),
            );
        let b = crate::transform_mesh(&a, &turn).unwrap();
        (a, b)
    }

    /// Coincidences are counted as a welding reader merges: each vertex
    /// after the first at a position, `-0.0` and `0.0` alike.
    #[test]
    fn coincident_pairs_count_what_a_reader_welds() {
        let v = [
            [0.0, 1.0, 2.0],
            [-0.0, 1.0, 2.0],
            [0.0, 1.0, 2.0],
            [3.0, 1.0, 2.0],
            [3.0, 1.0, 2.5],
            [3.0, 1.0, 2.5],
        ];
        assert_eq!(coincident_pairs(&v), 3);
        assert_eq!(coincident_pairs(&v[3..5]), 0);
        assert_eq!(coincident_pairs(&[]), 0);
    }

    /// PyVista's nut and sphere (real meshes of `f32` coordinates) minus
    /// and united with copies of themselves turned a few degrees and
    /// shifted, in either variant: rounding the `f64` results to `f32`
    /// plainly gives intersecting facet pairs (the case this module exists
    /// for: 31 in the nut's union); rounded here they have none by the
    /// whole exact test, stay closed and two-manifold, and keep their
    /// volume to rounding.
    #[test]
    fn rounding_boolean_results_adds_no_intersecting_pair() {
        let mut plain_pairs = 0;
        for name in ["nut", "sphere"] {
            let (a, b) = with_turned_copy(name);
            for op in [BooleanOp::Union, BooleanOp::Difference] {
                for variant in [MeshVariant::TriangleMesh, MeshVariant::PolygonMesh] {
                    let d = boolean_solid(&a, &b, op, variant).unwrap().mesh;
                    let mut plain = topology::triangulate_mesh(&d);
                    round_vertices(&mut plain.vertices);
                    plain_pairs += check_mesh(&plain.to_polygon_mesh())
                        .self_intersecting_facet_pairs
                        .unwrap();
                    let r = round_to_f32(&d);
                    let m = r.mesh.to_polygon_mesh();
                    let c = check_mesh(&m);
                    let what = format!("{name} {op:?} {variant:?}: {:?}", r.report);
                    assert_eq!(c.self_intersecting_facet_pairs, Some(0), "{what}");
                    assert_eq!(r.report.pairs_left, 0, "{what}");
                    assert_eq!(r.report.collisions_left, 0, "{what}");
                    // Written as binary STL and read back (welded): the
                    // same triangles, still a clean 2-manifold.
                    let stl = crate::mesh_to_stl(&m, false).unwrap();
                    let back = crate::parse_stl(&stl, "r.stl").unwrap().to_polygon_mesh();
                    let cb = check_mesh(&back);
                    assert_eq!(cb.self_intersecting_facet_pairs, Some(0), "{what}");
                    assert_eq!(cb.two_manifold, Some(true), "{what}");
                    assert_eq!(back.vertices.len(), m.vertices.len(), "{what}");
                    assert!(
                        c.topologically_valid && c.two_manifold == Some(true),
                        "{what}"
                    );
                    assert!(r
                        .mesh
                        .vertices
                        .iter()
                        .flatten()
                        .all(|&x| f64::from(x as f32) == x));
                    let (v0, v1) = (
                        topology::mesh_signed_volume(&d),
                        topology::mesh_signed_volume(&m),
                    );
                    assert!((v0 - v1).abs() < 1e-6 * v0.abs(), "{what}: {v0} {v1}");
                }
            }
        }
        assert!(plain_pairs > 0, "the inputs should exercise the repair");
    }

    /// The pairs of the facets around a vertex, counted on its corner
    /// neighbourhood, are those counted on the whole mesh, at every corner
    /// of the vertex's `f32` cell: the nut's union with a turned copy,
    /// plainly rounded (so that some corners make pairs), every vertex of
    /// a facet of a pair and a spread of others.
    #[test]
    fn corner_neighbourhoods_count_the_pairs_of_the_whole_mesh() {
        let (a, b) = with_turned_copy("nut");
        let d = boolean_solid(&a, &b, BooleanOp::Union, MeshVariant::TriangleMesh)
            .unwrap()
            .mesh;
        let mut m = topology::triangulate_mesh(&d);
        let exact = m.vertices.clone();
        round_vertices(&mut m.vertices);
        let all: Vec<bool> = vec![true; m.triangles.len()];
        let found = pairs(&m, &all).unwrap();
        assert!(!found.is_empty(), "plain rounding should make pairs here");
        let mut vs: Vec<u32> = found
            .iter()
            .flatten()
            .flat_map(|&f| m.triangles[f as usize])
            .collect();
        vs.extend((0..m.vertices.len() as u32).step_by(97));
        vs.sort_unstable();
        vs.dedup();
        let mut nonzero = 0;
        for v in vs {
            let p = exact[v as usize];
            let [xs, ys, zs] = [f32_around(p[0]), f32_around(p[1]), f32_around(p[2])];
            let cell = [[xs[0], ys[0], zs[0]], [xs[1], ys[1], zs[1]]];
            let (mut near, at, around) = corner_neighbourhood(&m, v, cell);
            let star: Vec<bool> = m.triangles.iter().map(|t| t.contains(&v)).collect();
            let keep = m.vertices[v as usize];
            for x in xs {
                for y in ys {
                    for z in zs {
                        m.vertices[v as usize] = [x, y, z];
                        near.vertices[at as usize] = [x, y, z];
                        let whole = pairs(&m, &star).unwrap().len();
                        let local = pairs(&near, &around).unwrap().len();
                        assert_eq!(local, whole, "vertex {v} at {:?}", [x, y, z]);
                        nonzero += usize::from(whole > 0);
                    }
                }
            }
            m.vertices[v as usize] = keep;
        }
        assert!(nonzero > 0, "some corners should make pairs");
    }

    /// A mesh of `f32` coordinates comes back as it is, at the cost of one
    /// pass: nothing moved, nothing tested.
    #[test]
    fn f32_meshes_are_kept_bit_for_bit() {
        let s = uv_sphere(2.0, 16, 8).unwrap();
        let t = topology::triangulate_mesh(&s);
        let mut f = t.clone();
        round_vertices(&mut f.vertices);
        let r = round_to_f32(&f.to_polygon_mesh());
        assert_eq!(r.mesh, f);
        assert_eq!(r.report, F32Rounding::default());
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(test_support::cases(12)))]

        /// Booleans of randomly turned and shifted spheres and boxes (`f64`
        /// coordinates everywhere, thin triangles along every
        /// intersection curve, and with `tiny` an operand against itself
        /// moved by 10^-tiny of its size): rounded, the result is valid,
        /// its report counts the pairs left exactly, and where its
        /// features are 10^-4 of its size or more it has no intersecting
        /// facet pair and no coinciding vertices that the `f64` result
        /// did not have, and a 2-manifold stays one unless smoothing ran.
        #[test]
        fn rounding_random_booleans_keeps_them_clean(
            angles in proptest::array::uniform3(-3.2f64..3.2),
            shift in proptest::array::uniform3(-0.6f64..0.6),
            tiny in 0i32..7,
            scale in 0.001f64..1000.0,
            op in 0usize..3,
            sphere in proptest::bool::ANY,
        ) {
            let a = if sphere {
                uv_sphere(scale, 24, 12).unwrap()
            } else {
                crate::cuboid(glam::DVec3::splat(scale), true).unwrap()
            };
            // The second operand: a smaller sphere turned and shifted, or
            // (`tiny > 0`) the first operand itself turned by 10^-tiny
            // radians and shifted by 10^-tiny of its size: surfaces that
            // nearly coincide, cut into slivers along long curves.
            let f = 10f64.powi(-tiny);
            let m = glam::DMat4::from_translation(glam::DVec3::from_array(shift) * scale * f)
                * glam::DMat4::from_euler(glam::EulerRot::XYZ, angles[0] * f, angles[1] * f, angles[2] * f);
            let base = if tiny > 0 { a.clone() } else { uv_sphere(0.8 * scale, 20, 10).unwrap() };
            let b = crate::transform_mesh(&base, &m).unwrap();
            let op = [BooleanOp::Union, BooleanOp::Intersection, BooleanOp::Difference][op];
            let d = boolean_solid(&a, &b, op, MeshVariant::TriangleMesh).unwrap().mesh;
            let before = check_mesh(&d);
            proptest::prop_assume!(before.self_intersecting_facet_pairs == Some(0));
            let r = round_to_f32(&d);
            let m = r.mesh.to_polygon_mesh();
            let after = check_mesh(&m);
            proptest::prop_assert!(after.topologically_valid);
            let left = after.self_intersecting_facet_pairs;
            proptest::prop_assert_eq!(left, Some(r.report.pairs_left), "{:?}", r.report);
            if tiny <= 4 {
                // Features of at least 10^-4 of the size (hundreds of
                // `f32` spacings): nothing is left.
                proptest::prop_assert_eq!(left, Some(0), "{:?}", r.report);
                proptest::prop_assert_eq!(r.report.collisions_left, 0);
            } else {
                // Surfaces a few spacings apart: never worse than plain
                // rounding (a shell that thin has no faithful `f32` form).
                proptest::prop_assert!(r.report.pairs_left <= r.report.pairs_from_rounding, "{:?}", r.report);
            }
            if before.two_manifold == Some(true) && r.report.passes == 0 {
                proptest::prop_assert_eq!(after.two_manifold, Some(true), "{:?}", r.report);
            }
            proptest::prop_assert!(r.mesh.vertices.iter().flatten().all(|&x| f64::from(x as f32) == x));
        }

        /// Garbage never panics: dangling indices, repeated corners,
        /// non-finite and huge coordinates, open meshes.
        #[test]
        fn garbage_never_panics(
            v in proptest::collection::vec(proptest::array::uniform3(proptest::prop_oneof![
                proptest::strategy::Just(f64::NAN),
                proptest::strategy::Just(f64::INFINITY),
                proptest::strategy::Just(1e39),
                proptest::strategy::Just(1.0 + f64::EPSILON),
                (-3i32..3).prop_map(f64::from),
                -2.0f64..2.0,
            ]), 0..12),
            t in proptest::collection::vec(proptest::array::uniform3(0u32..14), 0..16),
        ) {
            let mesh = TriangleMesh::new(v, t).to_polygon_mesh();
            let _ = round_to_f32(&mesh);
        }
    }
}
