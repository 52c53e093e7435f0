//! Smoothing in the facade (dissertation chapter 5 and Appendix A): the
//! tolerance rule front ends use when the user gives none, and smoothing
//! of a 3D result in the variant it came from (a triangle-variant result
//! stays a triangle mesh). Smoothing stays an explicit call in the library:
//! no Boolean of this crate smooths on its own. The front ends (command
//! line, Python) smooth 3D results with [`SmoothOptions::guarded`]: a
//! result with more intersecting facet pairs than the mesh had where
//! smoothing changed it, or as many and more non-manifold or open edges
//! and non-manifold vertices, is dropped for the mesh as it was at the
//! places where it is worse (or everywhere), and the report says so
//! ([`smooth::SmoothReport::reverted`]).

use crate::ops::{as_triangle_mesh, MeshVariant};
use crate::CsgResult;
use boolean_2d::{BooleanError, BooleanOutput, PlanarContacts};
use boolean_3d::Contacts;
use smooth::{
    smooth_mesh, smooth_mesh_near, smooth_polygon_set, smooth_polygon_set_near, smooth_triangles,
    smooth_triangles_near, SmoothError, SmoothOptions, Smoothed,
};
use topology::BooleanOp;
use topology::{PolygonMesh, PolygonSet2};

/// The default smoothing tolerance, relative to the largest extent of the
/// shape's bounding box: `1e-9`.
///
/// Why this value: the basic Boolean computes each intersection vertex
/// within about `12.4 u L` (section 8.2, `u = 2^-53`), that is about
/// `1.4e-15` of the coordinates' size, and the slivers, folds and gaps that
/// rounding and near-coincident input leave are of that size; `1e-9` is a
/// million times larger, so they all go. It is also far below any intended
/// feature: a nanometre on a one-metre part, a millimetre on a continent.
/// Parts meant to touch within a modeller's tolerance (`1e-6` of a unit
/// cube, say) need an explicit, larger tolerance.
pub const DEFAULT_RELATIVE_TOLERANCE: f64 = 1e-9;

/// The largest side of a bounding box, 0 when there is none or it is not
/// finite.
pub(crate) fn extent<const N: usize>(bb: Option<[[f64; N]; 2]>) -> f64 {
    let e = bb.map_or(0.0, |[lo, hi]| {
        (0..N).map(|k| hi[k] - lo[k]).fold(0.0, f64::max)
    });
    if e.is_finite() {
        e
    } else {
        0.0
    }
}

/// [`DEFAULT_RELATIVE_TOLERANCE`] times the largest extent of the mesh's
/// bounding box (0 for an empty mesh or non-finite coordinates, which
/// smoothing then refuses as input anyway).
///
/// ```
/// use umbra::{default_mesh_tolerance, Facet, PolygonMesh};
/// let m = PolygonMesh::new(vec![[0.0, 0.0, 0.0], [4.0, 1.0, 2.0], [1.0, 3.0, 0.0]],
///                          vec![Facet::from_loop(&[0, 1, 2]), Facet::from_loop(&[0, 2, 1])]);
/// assert_eq!(default_mesh_tolerance(&m), 4e-9);
/// ```
pub fn default_mesh_tolerance(mesh: &PolygonMesh) -> f64 {
    DEFAULT_RELATIVE_TOLERANCE * extent(mesh.bounding_box())
}

/// [`DEFAULT_RELATIVE_TOLERANCE`] times the largest extent of the set's
/// bounding box.
pub fn default_set_tolerance(set: &PolygonSet2) -> f64 {
    DEFAULT_RELATIVE_TOLERANCE * extent(set.bounding_box())
}

/// The tolerance at which a 2D Boolean of `sets` (two, or any number) is
/// smoothed unless the caller names one (`umbra boolean`, Python's
/// `boolean_2d` and `boolean_2d_all`): the largest
/// [`default_set_tolerance`] of them, which removes the zero-width
/// features the basic Boolean leaves where operands share boundary (rings
/// GEOS calls invalid); 0 (the raw result) when the ring orientation is
/// kept, since the winding numbers are then the result and smoothing, made
/// for regions of winding number 0 and 1, does not keep them.
pub fn default_boolean_set_tolerance<'a>(
    sets: impl IntoIterator<Item = &'a PolygonSet2>,
    keep_orientation: bool,
) -> f64 {
    if keep_orientation {
        0.0
    } else {
        sets.into_iter()
            .map(default_set_tolerance)
            .fold(0.0, f64::max)
    }
}

/// Smooths a 3D result in its variant: a triangle mesh (every facet one
/// loop of three half-edges) by [`smooth_triangles`], which re-triangulates
/// what it changes, so the result stays triangles; anything else by
/// [`smooth_mesh`]. `variant` says which the caller expects: asking for
/// [`MeshVariant::TriangleMesh`] on a mesh with other facets triangulates
/// it by internal edges (section 4.8) and smooths those triangles, so the
/// triangles returned are the ones smoothing cleaned (a polygon mesh
/// smoothed first and triangulated afterwards can fold where a smoothed
/// facet is no longer flat). Guarded when `options.guard` is set (see
/// the module header).
pub fn smooth_solid(
    mesh: &PolygonMesh,
    variant: MeshVariant,
    options: &SmoothOptions,
) -> Result<Smoothed<PolygonMesh>, SmoothError> {
    match (variant, as_triangle_mesh(mesh)) {
        (MeshVariant::TriangleMesh, Some(tri)) => {
            let out = smooth_triangles(&tri, options)?;
            Ok(Smoothed {
                shape: out.shape.to_polygon_mesh(),
                report: out.report,
            })
        }
        (MeshVariant::TriangleMesh, None) => {
            let out = smooth_triangles(&topology::triangulate_mesh(mesh), options)?;
            Ok(Smoothed {
                shape: out.shape.to_polygon_mesh(),
                report: out.report,
            })
        }
        (MeshVariant::PolygonMesh, _) => smooth_mesh(mesh, options),
    }
}

/// Smooths a 3D Boolean result only near the operands' [`Contacts`] (from
/// [`crate::boolean_solid_with_contacts`] at a proximity of at least the
/// tolerance), in its variant as [`smooth_solid`] does: where operands
/// that need no smoothing themselves cut or touch, the result equals
/// [`smooth_solid`]'s, at a cost proportional to what the Boolean changed
/// (`smooth::smooth_mesh_near`). This is how the command line smooths a
/// Boolean; [`smooth_solid`] also cleans what the operands brought.
pub fn smooth_solid_near(
    mesh: &PolygonMesh,
    variant: MeshVariant,
    options: &SmoothOptions,
    contacts: &Contacts,
) -> Result<Smoothed<PolygonMesh>, SmoothError> {
    match (variant, as_triangle_mesh(mesh)) {
        (MeshVariant::TriangleMesh, Some(tri)) => {
            let out = smooth_triangles_near(&tri, options, &contacts.boxes)?;
            Ok(Smoothed {
                shape: out.shape.to_polygon_mesh(),
                report: out.report,
            })
        }
        (MeshVariant::PolygonMesh, _) => smooth_mesh_near(mesh, options, &contacts.boxes),
        (MeshVariant::TriangleMesh, None) => smooth_solid(mesh, variant, options),
    }
}

/// Smooths a CSG result ([`crate::evaluate_csg`] with
/// [`crate::CsgOptions::contacts`]) in its variant, as `umbra csg` does:
/// near the gathered contacts ([`smooth_solid_near`]) when their proximity
/// reaches the tolerance, else the whole mesh ([`smooth_solid`]). Returns
/// the smoothed mesh and whether it looked near the contacts only.
pub fn smooth_csg_result(
    result: &CsgResult,
    variant: MeshVariant,
    options: &SmoothOptions,
) -> Result<(Smoothed<PolygonMesh>, bool), SmoothError> {
    let near = result
        .contacts
        .as_ref()
        .filter(|c| c.proximity >= options.tolerance);
    match near {
        Some(c) => smooth_solid_near(&result.mesh, variant, options, c).map(|s| (s, true)),
        None => smooth_solid(&result.mesh, variant, options).map(|s| (s, false)),
    }
}

/// Smooths a 2D Boolean result as `umbra boolean` and Python's
/// `boolean_2d` do: near the operands' contacts
/// ([`crate::boolean_with_contacts`], [`smooth_polygon_set_near`]) when
/// they are given at a proximity of at least the tolerance, else the whole
/// set ([`smooth_polygon_set`]). Where the operands need no smoothing
/// themselves the two give the same vertices and edges; near the contacts
/// costs what the Boolean changed plus one checking sweep.
///
/// ```
/// use umbra::{boolean_with_contacts, smooth_set_result, BooleanOp, PolygonSet2, SmoothOptions};
/// let mut a = PolygonSet2::new();
/// a.add_loop(&[[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]);
/// let mut b = PolygonSet2::new();
/// b.add_loop(&[[1.0, 1e-12], [2.0, 0.0], [2.0, 1.0], [1.0, 1.0]]);
/// let options = SmoothOptions::new(1e-9);
/// let (out, contacts) = boolean_with_contacts(&a, &b, BooleanOp::Union, 1e-9)?;
/// let smoothed = smooth_set_result(&out.shape, &options, Some(&contacts))?;
/// assert_eq!(smoothed.shape.edge_count(), 4); // one rectangle, no sliver
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn smooth_set_result(
    shape: &PolygonSet2,
    options: &SmoothOptions,
    contacts: Option<&PlanarContacts>,
) -> Result<Smoothed<PolygonSet2>, SmoothError> {
    match contacts.filter(|c| c.proximity >= options.tolerance) {
        Some(c) => smooth_polygon_set_near(shape, options, &c.boxes),
        None => smooth_polygon_set(shape, options),
    }
}

/// The basic 2D Boolean as the front ends run it before smoothing its
/// result at `tolerance`: with the operands' contacts at that proximity
/// ([`boolean_with_contacts`](crate::boolean_with_contacts)) when it is
/// positive and finite, so that [`smooth_set_result`] looks only near
/// them; the plain Boolean (no contacts: whole smoothing, or none)
/// otherwise.
///
/// ```
/// use umbra::{boolean_for_smoothing, BooleanOp, PolygonSet2};
/// let mut a = PolygonSet2::new();
/// a.add_loop(&[[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]);
/// let (out, contacts) = boolean_for_smoothing(&a, &a.clone(), BooleanOp::Union, 1e-9)?;
/// assert!(contacts.is_some_and(|c| !c.boxes.is_empty()));
/// let (_, none) = boolean_for_smoothing(&a, &a.clone(), BooleanOp::Union, 0.0)?;
/// assert!(none.is_none());
/// # let _ = out;
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn boolean_for_smoothing(
    a: &PolygonSet2,
    b: &PolygonSet2,
    op: BooleanOp,
    tolerance: f64,
) -> Result<(BooleanOutput, Option<PlanarContacts>), BooleanError> {
    if tolerance > 0.0 && tolerance.is_finite() {
        boolean_2d::boolean_with_contacts(a, b, op, tolerance).map(|(out, c)| (out, Some(c)))
    } else {
        boolean_2d::boolean(a, b, op).map(|out| (out, None))
    }
}
