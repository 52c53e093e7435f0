//! 3D inputs and peers: sphere minus a sphere shifted by half its radius
//! (the 3D bench of issue 3), as UV spheres in two variants (triangles;
//! quadrilaterals with triangle fans at the poles), run on Umbra's
//! triangle-mesh Boolean (triangles), its polygon-mesh Boolean (on the
//! triangles, and on the quadrilaterals), on `manifold-rust` 0.19 (a
//! Rust port of Manifold) and on `boolmesh` 0.2 (a pure-Rust mesh Boolean
//! after Manifold's design) with identical coordinates. Every peer is handed
//! the triangle spheres; the quadrilateral peer merges them back into the
//! quadrilaterals they split ([`quads_of_uv_sphere`]), so that all run on
//! the same vertices and the same surface.

use boolean_3d::{boolean_mesh, boolean_prepared, boolean_triangles, BooleanOp, PreparedTriangles};
use manifold_rust::manifold::Manifold;
use manifold_rust::types::MeshGL64;
pub use test_support::measure::polygon_mesh_volume as polygon_volume;
pub use test_support::shapes::{uv_sphere, uv_sphere_quads};
use topology::{Facet, PolygonMesh, TriangleMesh};

/// The quadrilateral form of a sphere made by [`uv_sphere`]: each band's
/// triangle pair `(a, c, d)`, `(a, d, b)` merged back into the
/// quadrilateral `(a, c, d, b)` it splits, the pole triangles kept, the
/// vertices shared. This is [`uv_sphere_quads`] of the same sphere (tested);
/// a triangle pair not of that form is kept as two triangles.
pub fn quads_of_uv_sphere(m: &TriangleMesh) -> PolygonMesh {
    let south = (m.vertices.len() as u32).saturating_sub(1);
    let poles = m
        .triangles
        .iter()
        .take_while(|t| t[0] == 0 || t[0] == south)
        .count();
    let mut f: Vec<Facet> = m.triangles[..poles]
        .iter()
        .map(|t| Facet::from_loop(t))
        .collect();
    for pair in m.triangles[poles..].chunks(2) {
        match pair {
            [[a, c, d], [a2, d2, b]] if a == a2 && d == d2 => {
                f.push(Facet::from_loop(&[*a, *c, *d, *b]));
            }
            _ => f.extend(pair.iter().map(|t| Facet::from_loop(t))),
        }
    }
    PolygonMesh::new(m.vertices.clone(), f)
}

/// Slices and stacks giving about `triangles` triangles (`slices = 2
/// stacks`).
pub fn sphere_resolution(triangles: usize) -> (u32, u32) {
    let stacks = ((triangles as f64 / 4.0).sqrt().round() as u32).max(3);
    (2 * stacks, stacks)
}

/// The two operands of a row: the unit sphere at the origin and the unit
/// sphere shifted by half its radius along a direction off every axis (so
/// that no vertex of one lies on the other's facet planes by symmetry).
pub fn sphere_pair(triangles: usize) -> (TriangleMesh, TriangleMesh) {
    let (s, t) = sphere_resolution(triangles);
    let d = 0.5 / 3f64.sqrt();
    (
        uv_sphere([0.0; 3], 1.0, s, t),
        uv_sphere([d, d * 1.1, d * 0.9], 1.0, s, t),
    )
}

/// The quadrilateral variant of [`sphere_pair`].
pub fn sphere_pair_quads(triangles: usize) -> (PolygonMesh, PolygonMesh) {
    let (s, t) = sphere_resolution(triangles);
    let d = 0.5 / 3f64.sqrt();
    (
        uv_sphere_quads([0.0; 3], 1.0, s, t),
        uv_sphere_quads([d, d * 1.1, d * 0.9], 1.0, s, t),
    )
}

/// The analytic volume of a unit ball minus a unit ball at distance
/// `d = 0.5` from it: `4/3 pi - pi (4 + d)(2 - d)^2 / 12` (the lens).
pub fn analytic_difference_volume() -> f64 {
    let d = 0.5 * (1.0f64 + 1.21 + 0.81).sqrt() / 3f64.sqrt();
    let pi = std::f64::consts::PI;
    4.0 / 3.0 * pi - pi * (4.0 + d) * (2.0 - d) * (2.0 - d) / 12.0
}

/// Signed volume of a triangle mesh (divergence theorem).
pub fn triangle_volume(m: &TriangleMesh) -> f64 {
    m.signed_volume()
}

/// What one run produced: triangle (or facet) count, volume, and whether
/// the result is closed (shape boundary closure for Umbra, Manifold's own
/// status for the peer).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SolidStats {
    /// Facets (Umbra's polygon variant) or triangles of the result.
    pub facets: usize,
    /// The enclosed volume.
    pub volume: f64,
    /// The result passed its library's validity check.
    pub valid: bool,
}

impl SolidStats {
    /// What a library that returned no result gets: no facets, a NaN
    /// volume, not valid.
    pub const FAILED: SolidStats = SolidStats {
        facets: 0,
        volume: f64::NAN,
        valid: false,
    };

    /// The statistics of a polygon-mesh result: facets, volume and shape
    /// closure (section 4.2).
    pub fn of_mesh(m: &PolygonMesh) -> SolidStats {
        SolidStats {
            facets: m.facets.len(),
            volume: polygon_volume(m),
            valid: m.check_topology().is_ok(),
        }
    }
}

/// A 3D library under test: `prepare` converts (not timed), `difference`
/// runs `A - B` (timed), `stats` reads the result (not timed).
pub trait SolidPeer {
    /// The prepared operands.
    type Input;
    /// The native result.
    type Output;
    /// A short name.
    fn name(&self) -> &'static str;
    /// Converts the triangle operands.
    fn prepare(&self, a: &TriangleMesh, b: &TriangleMesh) -> Self::Input;
    /// `A - B`.
    fn difference(&self, input: &Self::Input) -> Self::Output;
    /// Facet count, volume and validity of the result.
    fn stats(&self, out: &Self::Output) -> SolidStats;
}

/// Umbra's triangle-mesh variant on operands prepared before the timing
/// (`PreparedTriangles`, then `boolean_prepared`): the protocol of the
/// C++ Manifold's `a - b`, whose `Manifold`s are built (edge pairing,
/// sorting, collider) before it is timed. The same result as
/// [`UmbraTriangles`].
#[derive(Clone, Copy, Debug, Default)]
pub struct UmbraPrepared;

impl SolidPeer for UmbraPrepared {
    type Input = Option<(PreparedTriangles<'static>, PreparedTriangles<'static>)>;
    type Output = Option<TriangleMesh>;
    fn name(&self) -> &'static str {
        "umbra-tri-prepared"
    }
    fn prepare(&self, a: &TriangleMesh, b: &TriangleMesh) -> Self::Input {
        // A prepared operand borrows its mesh; a bench child runs one
        // table cell and exits, so the two meshes live as long as it.
        let a: &'static TriangleMesh = Box::leak(Box::new(a.clone()));
        let b: &'static TriangleMesh = Box::leak(Box::new(b.clone()));
        Some((
            PreparedTriangles::new(a).ok()?,
            PreparedTriangles::new(b).ok()?,
        ))
    }
    fn difference(&self, input: &Self::Input) -> Self::Output {
        let (a, b) = input.as_ref()?;
        boolean_prepared(a, b, BooleanOp::Difference)
            .ok()
            .map(|o| o.mesh)
    }
    fn stats(&self, out: &Self::Output) -> SolidStats {
        UmbraTriangles.stats(out)
    }
}

/// Umbra's triangle-mesh variant (`boolean_triangles`).
#[derive(Clone, Copy, Debug, Default)]
pub struct UmbraTriangles;

impl SolidPeer for UmbraTriangles {
    type Input = (TriangleMesh, TriangleMesh);
    type Output = Option<TriangleMesh>;
    fn name(&self) -> &'static str {
        "umbra-tri"
    }
    fn prepare(&self, a: &TriangleMesh, b: &TriangleMesh) -> Self::Input {
        (a.clone(), b.clone())
    }
    fn difference(&self, input: &Self::Input) -> Self::Output {
        boolean_triangles(&input.0, &input.1, BooleanOp::Difference)
            .ok()
            .map(|o| o.mesh)
    }
    fn stats(&self, out: &Self::Output) -> SolidStats {
        match out {
            Some(m) => SolidStats {
                facets: m.triangles.len(),
                volume: triangle_volume(m),
                valid: m.check_topology().is_ok(),
            },
            None => SolidStats::FAILED,
        }
    }
}

/// Umbra's polygon-mesh variant (`boolean_mesh`) on the same triangles.
#[derive(Clone, Copy, Debug, Default)]
pub struct UmbraPolygons;

impl SolidPeer for UmbraPolygons {
    type Input = (PolygonMesh, PolygonMesh);
    type Output = Option<PolygonMesh>;
    fn name(&self) -> &'static str {
        "umbra-poly"
    }
    fn prepare(&self, a: &TriangleMesh, b: &TriangleMesh) -> Self::Input {
        (a.to_polygon_mesh(), b.to_polygon_mesh())
    }
    fn difference(&self, input: &Self::Input) -> Self::Output {
        boolean_mesh(&input.0, &input.1, BooleanOp::Difference)
            .ok()
            .map(|o| o.mesh)
    }
    fn stats(&self, out: &Self::Output) -> SolidStats {
        match out {
            Some(m) => SolidStats::of_mesh(m),
            None => SolidStats::FAILED,
        }
    }
}

/// Umbra's polygon-mesh variant (`boolean_mesh`) on the quadrilateral
/// spheres ([`quads_of_uv_sphere`] of the triangle operands: the same
/// vertices, half as many facets away from the poles).
#[derive(Clone, Copy, Debug, Default)]
pub struct UmbraQuads;

impl SolidPeer for UmbraQuads {
    type Input = (PolygonMesh, PolygonMesh);
    type Output = Option<PolygonMesh>;
    fn name(&self) -> &'static str {
        "umbra-quads"
    }
    fn prepare(&self, a: &TriangleMesh, b: &TriangleMesh) -> Self::Input {
        (quads_of_uv_sphere(a), quads_of_uv_sphere(b))
    }
    fn difference(&self, input: &Self::Input) -> Self::Output {
        UmbraPolygons.difference(input)
    }
    fn stats(&self, out: &Self::Output) -> SolidStats {
        UmbraPolygons.stats(out)
    }
}

/// `manifold-rust` 0.19 (feature `parallel`): `Manifold::from_mesh_gl64`
/// of each operand (not timed), then `difference` (timed; the Boolean is
/// evaluated eagerly).
#[derive(Clone, Copy, Debug, Default)]
pub struct ManifoldRust;

/// Triangle count, volume and status of a `manifold-rust` result.
pub fn manifold_stats(m: &Manifold) -> SolidStats {
    SolidStats {
        facets: m.num_tri(),
        volume: m.volume(),
        valid: format!("{:?}", m.status()) == "NoError",
    }
}

/// A triangle mesh as a `manifold-rust` manifold (through `MeshGL64`).
pub fn manifold_of(m: &TriangleMesh) -> Manifold {
    Manifold::from_mesh_gl64(&MeshGL64 {
        num_prop: 3,
        vert_properties: m.vertices.iter().flatten().copied().collect(),
        tri_verts: m
            .triangles
            .iter()
            .flatten()
            .map(|&v| u64::from(v))
            .collect(),
        ..MeshGL64::default()
    })
}

impl SolidPeer for ManifoldRust {
    type Input = (Manifold, Manifold);
    type Output = Manifold;
    fn name(&self) -> &'static str {
        "manifold-rust"
    }
    fn prepare(&self, a: &TriangleMesh, b: &TriangleMesh) -> Self::Input {
        (manifold_of(a), manifold_of(b))
    }
    fn difference(&self, input: &Self::Input) -> Self::Output {
        let out = input.0.difference(&input.1);
        // Force any deferred work so that the timing covers the Boolean.
        std::hint::black_box(out.num_tri());
        out
    }
    fn stats(&self, out: &Self::Output) -> SolidStats {
        manifold_stats(out)
    }
}

/// `boolmesh` 0.2 (feature `rayon`): `Manifold::new` of each operand (not
/// timed; it welds, sorts and checks the mesh), then `compute_boolean`
/// with `OpType::Subtract` (timed).
#[derive(Clone, Copy, Debug, Default)]
pub struct Boolmesh;

/// A triangle mesh as a `boolmesh` manifold, or its refusal.
pub fn boolmesh_of(m: &TriangleMesh) -> Result<boolmesh::prelude::Manifold, String> {
    let pos: Vec<f64> = m.vertices.iter().flatten().copied().collect();
    let idx: Vec<usize> = m.triangles.iter().flatten().map(|&v| v as usize).collect();
    boolmesh::prelude::Manifold::new(&pos, &idx)
}

/// Triangle count, volume and closedness of a `boolmesh` result.
pub fn boolmesh_stats(m: &boolmesh::prelude::Manifold) -> SolidStats {
    let p = |i: usize| {
        let v = m.ps[i];
        [v.x, v.y, v.z]
    };
    let volume =
        m.hs.chunks(3)
            .map(|t| {
                let (a, b, c) = (p(t[0].tail), p(t[1].tail), p(t[2].tail));
                (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0])
                    + a[2] * (b[0] * c[1] - b[1] * c[0]))
                    / 6.0
            })
            .sum();
    SolidStats {
        facets: m.hs.len() / 3,
        volume,
        valid: m.is_manifold(),
    }
}

impl SolidPeer for Boolmesh {
    type Input = Option<(boolmesh::prelude::Manifold, boolmesh::prelude::Manifold)>;
    type Output = Option<boolmesh::prelude::Manifold>;
    fn name(&self) -> &'static str {
        "boolmesh"
    }
    fn prepare(&self, a: &TriangleMesh, b: &TriangleMesh) -> Self::Input {
        Some((boolmesh_of(a).ok()?, boolmesh_of(b).ok()?))
    }
    fn difference(&self, input: &Self::Input) -> Self::Output {
        let (a, b) = input.as_ref()?;
        boolmesh::compute_boolean(a, b, boolmesh::prelude::OpType::Subtract).ok()
    }
    fn stats(&self, out: &Self::Output) -> SolidStats {
        out.as_ref().map_or(SolidStats::FAILED, boolmesh_stats)
    }
}
