//! What the facade adds over the lower crates' entry points: the 2D
//! Boolean's algorithm as a value ([`Via`]) and the 3D Boolean by variant
//! ([`MeshVariant`], [`boolean_solid`]), which triangulates operands that
//! are not triangle meshes when the triangle-mesh variant is asked for,
//! and the triangle-mesh variant on triangle meshes with no conversion
//! ([`boolean_solid_triangles`], for chains of operations: STL in, STL
//! out).

use boolean_3d::{
    boolean_mesh, boolean_mesh_with_contacts, boolean_triangles, boolean_triangles_with_contacts,
    triangulate_mesh, Boolean3Error, Contacts,
};
use std::time::Instant;
use topology::{BooleanOp, PolygonMesh, PolygonSet2, TriangleMesh};

/// The operand turned outward when its facets face inward: a mesh of
/// negative signed volume (written with the opposite orientation
/// convention, or turned over by mistake) is [`PolygonMesh::reversed`];
/// `None` when its volume is 0 or positive (facing outward, or a solid
/// whose inner shells bound voids and face inward on purpose), and for a
/// mesh that violates the closure constraints (whose "volume" means
/// nothing; the Boolean refuses it with the violation named).
///
/// The basic Boolean tolerates an inward-facing operand as an inside-out
/// one (section 4.7): the result is topologically valid, but it is not
/// the Boolean of the solid the file describes. The command-line tool and
/// the Python package therefore turn such operands outward unless told to
/// keep the orientation as written, as they read 2D rings by role.
///
/// ```
/// use umbra::{turned_outward, Facet, PolygonMesh};
/// let tetra = PolygonMesh::new(
///     vec![[0., 0., 0.], [1., 0., 0.], [0., 1., 0.], [0., 0., 1.]],
///     [[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2]].iter().map(|t| Facet::from_loop(t)).collect(),
/// );
/// assert!(turned_outward(&tetra).is_none());
/// let inward = tetra.reversed();
/// assert_eq!(turned_outward(&inward), Some(tetra));
/// ```
pub fn turned_outward(mesh: &PolygonMesh) -> Option<PolygonMesh> {
    // The volume first: the closure check is the dearer test, and only an
    // operand about to be turned needs it.
    (mesh.signed_volume() < 0.0 && mesh.check_topology().is_ok()).then(|| mesh.reversed())
}

/// A 2D operand read by role made a set for the basic Boolean: winding
/// number 1 where `set`'s is positive, 0 elsewhere (the simplification
/// sweep with the positive rule, chapters 6-7).
///
/// The basic Boolean combines winding numbers by eq. 4.20, `c_A a + c_B b +
/// c_I a b`, which is the Boolean of the sets only when both are 0 or 1.
/// Rings read by role from a valid file give exactly that, but an invalid
/// one does not: two overlapping parts of a multipolygon cover their
/// overlap twice (the union of such an operand with itself was empty), a
/// hole outside its shell or two overlapping holes leave winding number
/// -1 (which the intersection counted as inside). The command-line tool
/// and the Python package therefore pass operands read by role through
/// this first: a valid operand has no crossing, so it comes back as the
/// same set (no vertex moves); an invalid one as the region GIS tools
/// mean by it (`make_valid`'s, for overlapping parts and holes), the
/// result the Boolean through simplification gives. The sweep's
/// [`simplify_2d::Simplified::epsilon`] bounds how far the operand's
/// boundary moved (0 in effect for a valid one, which has no crossing to
/// round): a report adds it to the Boolean's own.
///
/// ```
/// use umbra::{boolean, regularized_operand, BooleanOp, PolygonSet2};
/// let mut twice = PolygonSet2::new(); // one square given twice
/// for _ in 0..2 {
///     twice.add_loop(&[[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]);
/// }
/// assert_eq!(boolean(&twice, &twice, BooleanOp::Union).unwrap().shape.signed_area(), 0.0);
/// let set = regularized_operand(&twice).unwrap().shape;
/// assert_eq!(boolean(&set, &set, BooleanOp::Union).unwrap().shape.signed_area(), 1.0);
/// ```
pub fn regularized_operand(
    set: &PolygonSet2,
) -> Result<simplify_2d::Simplified, simplify_2d::SimplifyError> {
    simplify_2d::simplify(set, simplify_2d::FillRule::Positive)
}

/// [`regularized_operand`] of both operands of a binary Boolean, side by
/// side on two threads (each is one sweep, tens of milliseconds on a map
/// of 100,000 vertices, and a map without crossings sweeps on one
/// thread). The results are those of two calls, in operand order.
///
/// ```
/// use umbra::{regularized_operand, regularized_operands, PolygonSet2};
/// let mut a = PolygonSet2::new();
/// a.add_loop(&[[0.0, 0.0], [2.0, 2.0], [2.0, 0.0], [0.0, 2.0]]); // a bow tie
/// let mut b = PolygonSet2::new();
/// b.add_loop(&[[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]);
/// let [ra, rb] = regularized_operands(&a, &b);
/// assert_eq!(ra.unwrap().shape, regularized_operand(&a).unwrap().shape);
/// assert_eq!(rb.unwrap().shape, regularized_operand(&b).unwrap().shape);
/// ```
pub fn regularized_operands(
    a: &PolygonSet2,
    b: &PolygonSet2,
) -> [Result<simplify_2d::Simplified, simplify_2d::SimplifyError>; 2] {
    let (ra, rb) = rayon::join(|| regularized_operand(a), || regularized_operand(b));
    [ra, rb]
}

/// The algorithm of a 2D Boolean.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Via {
    /// The basic Boolean of chapter 4 ([`crate::boolean`]): tolerant of
    /// self-intersecting and inside-out operands (section 4.7).
    #[default]
    Basic,
    /// The Boolean through simplification of chapter 6
    /// ([`crate::boolean_via_simplify`]): both boundaries assembled and
    /// simplified, which resolves self-intersecting operands.
    Simplify,
}

impl Via {
    /// The algorithm as a report names it.
    pub fn algorithm(self) -> &'static str {
        match self {
            Via::Basic => "basic Boolean (chapter 4)",
            Via::Simplify => "Boolean through simplification (chapter 6)",
        }
    }
}

/// The variant of the 3D Boolean (section 4.8).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum MeshVariant {
    /// [`crate::boolean_mesh`]: polygon facets in and out (facets may
    /// gain holes or several regions).
    #[default]
    PolygonMesh,
    /// [`crate::boolean_triangles`]: triangles in, every retained facet
    /// triangulated by internal edges only.
    TriangleMesh,
}

impl MeshVariant {
    /// The variant as a report names it (`"polygon mesh"`, `"triangle
    /// mesh"`).
    pub fn name(self) -> &'static str {
        match self {
            MeshVariant::PolygonMesh => "polygon mesh",
            MeshVariant::TriangleMesh => "triangle mesh",
        }
    }
}

/// The result of [`boolean_solid`].
#[derive(Clone, Debug, PartialEq)]
pub struct SolidOutput {
    /// The resulting shape, always topologically valid (triangles as
    /// facets for [`MeshVariant::TriangleMesh`]).
    pub mesh: PolygonMesh,
    /// The number of edge-facet intersection vertices.
    pub intersections: usize,
    /// The variant that ran.
    pub variant: MeshVariant,
    /// For A and B: whether the operand was triangulated first (only for
    /// the triangle-mesh variant, when it had facets other than single
    /// triangles).
    pub inputs_triangulated: [bool; 2],
    /// Milliseconds spent triangulating the operands (triangle-mesh
    /// variant only).
    pub triangulate_ms: Option<f64>,
    /// Milliseconds of the whole call.
    pub total_ms: f64,
}

/// The result of [`boolean_solid_triangles`].
#[derive(Clone, Debug, PartialEq)]
pub struct TriangleSolidOutput {
    /// The resulting shape, always topologically valid.
    pub mesh: TriangleMesh,
    /// The number of edge-facet intersection vertices.
    pub intersections: usize,
    /// Milliseconds of the whole call.
    pub total_ms: f64,
}

/// The triangle-mesh variant of the 3D Boolean on triangle meshes,
/// straight through [`crate::boolean_triangles`]: no operand is converted
/// to or from a polygon mesh, so a chain of operations (each result
/// feeding the next) pays only for the Booleans. The triangles are those
/// of [`boolean_solid`] with [`MeshVariant::TriangleMesh`] on the same
/// triangles given as one-triangle facets.
///
/// ```
/// use umbra::{boolean_solid_triangles, cuboid, triangulate_mesh, BooleanOp, DVec3};
/// let a = triangulate_mesh(&cuboid(DVec3::splat(2.0), false).unwrap());
/// let mut b = a.clone();
/// b.vertices.iter_mut().for_each(|v| v[0] += 1.0);
/// let out = boolean_solid_triangles(&a, &b, BooleanOp::Difference).unwrap();
/// assert_eq!(out.mesh.signed_volume(), 4.0);
/// ```
pub fn boolean_solid_triangles(
    a: &TriangleMesh,
    b: &TriangleMesh,
    op: BooleanOp,
) -> Result<TriangleSolidOutput, Boolean3Error> {
    let start = Instant::now();
    let out = boolean_triangles(a, b, op)?;
    Ok(TriangleSolidOutput {
        mesh: out.mesh,
        intersections: out.intersections,
        total_ms: ms(start),
    })
}

/// The operand as a triangle mesh when every facet is one loop of three
/// half-edges, `None` otherwise.
///
/// ```
/// use umbra::{as_triangle_mesh, Facet, PolygonMesh};
/// let quad = PolygonMesh {
///     vertices: vec![[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [1.0, 1.0, 0.0], [0.0, 1.0, 0.0]],
///     facets: vec![Facet::from_loop(&[0, 1, 2, 3])],
/// };
/// assert!(as_triangle_mesh(&quad).is_none());
/// ```
pub fn as_triangle_mesh(mesh: &PolygonMesh) -> Option<TriangleMesh> {
    let mut tris = Vec::with_capacity(mesh.facets.len());
    for f in &mesh.facets {
        let h = &f.half_edges;
        if h.len() != 3
            || h[0].end != h[1].start
            || h[1].end != h[2].start
            || h[2].end != h[0].start
        {
            return None;
        }
        tris.push([h[0].start, h[1].start, h[2].start]);
    }
    Some(TriangleMesh::new(mesh.vertices.clone(), tris))
}

fn ms(since: Instant) -> f64 {
    since.elapsed().as_secs_f64() * 1e3
}

/// The 3D Boolean `op` of `a` and `b` by `variant`. The triangle-mesh
/// variant first triangulates (by internal edges, which keeps a closed
/// operand closed) any operand that is not already a triangle mesh, so
/// both variants run on any valid input, and returns the triangles as
/// one-triangle facets; on triangle meshes, [`boolean_solid_triangles`]
/// gives the same triangles without either conversion. Errors are those
/// of the 3D Boolean, naming the operand.
pub fn boolean_solid(
    a: &PolygonMesh,
    b: &PolygonMesh,
    op: BooleanOp,
    variant: MeshVariant,
) -> Result<SolidOutput, Boolean3Error> {
    solid(a, b, op, variant, None).map(|(out, _)| out)
}

/// [`boolean_solid`] together with the operands' [`Contacts`] at
/// `proximity` (finite, not negative): where the operands cut or come
/// within `proximity` of each other, the only places smoothing a result
/// of clean operands has anything to do
/// ([`crate::smooth_solid_near`]). The result is [`boolean_solid`]'s.
pub fn boolean_solid_with_contacts(
    a: &PolygonMesh,
    b: &PolygonMesh,
    op: BooleanOp,
    variant: MeshVariant,
    proximity: f64,
) -> Result<(SolidOutput, Contacts), Boolean3Error> {
    let (out, contacts) = solid(a, b, op, variant, Some(proximity))?;
    Ok((out, contacts.unwrap_or_default()))
}

/// The Boolean of both variants, with the contacts when asked for.
fn solid(
    a: &PolygonMesh,
    b: &PolygonMesh,
    op: BooleanOp,
    variant: MeshVariant,
    proximity: Option<f64>,
) -> Result<(SolidOutput, Option<Contacts>), Boolean3Error> {
    let start = Instant::now();
    match variant {
        MeshVariant::PolygonMesh => {
            let (out, contacts) = match proximity {
                Some(p) => boolean_mesh_with_contacts(a, b, op, p).map(|(o, c)| (o, Some(c)))?,
                None => (boolean_mesh(a, b, op)?, None),
            };
            let out = SolidOutput {
                mesh: out.mesh,
                intersections: out.intersections,
                variant,
                inputs_triangulated: [false, false],
                triangulate_ms: None,
                total_ms: ms(start),
            };
            Ok((out, contacts))
        }
        MeshVariant::TriangleMesh => {
            let ta = as_triangle_mesh(a);
            let tb = as_triangle_mesh(b);
            let inputs_triangulated = [ta.is_none(), tb.is_none()];
            let ta = ta.unwrap_or_else(|| triangulate_mesh(a));
            let tb = tb.unwrap_or_else(|| triangulate_mesh(b));
            let triangulate_ms = Some(ms(start));
            let (out, contacts) = match proximity {
                Some(p) => {
                    boolean_triangles_with_contacts(&ta, &tb, op, p).map(|(o, c)| (o, Some(c)))?
                }
                None => (boolean_triangles(&ta, &tb, op)?, None),
            };
            let out = SolidOutput {
                mesh: out.mesh.to_polygon_mesh(),
                intersections: out.intersections,
                variant,
                inputs_triangulated,
                triangulate_ms,
                total_ms: ms(start),
            };
            Ok((out, contacts))
        }
    }
}
