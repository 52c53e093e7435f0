//! Primitive solids as closed, outward-oriented polygon meshes (box, UV
//! sphere, icosphere, cylinder and cone, torus), 2D regular polygons and
//! circles, and the linear extrusion of a 2D polygon set.
//!
//! Every mesh is topologically valid (section 4.2 of the dissertation
//! "Towards robust inexact geometric computation": facet and shape boundary
//! closure), 2-manifold, has no degenerate facet and faces outward (positive
//! signed volume). Bad parameters give [`ModelError::InvalidParameter`].

use super::error::ModelError;
use glam::DVec3;
use std::collections::{BTreeMap, HashMap};
use topology::{Facet, HalfEdge, PolygonMesh, PolygonSet2};

/// The most segments a primitive accepts around one circle.
pub const MAX_SEGMENTS: u32 = 1 << 16;
/// The most facets a primitive may have.
pub const MAX_PRIMITIVE_FACETS: u64 = 1 << 24;
/// The deepest icosphere subdivision (`20 * 4^9` triangles).
pub const MAX_ICOSPHERE_LEVEL: u32 = 9;

/// Checks that `value` is finite and positive.
pub(crate) fn check_positive(param: &str, value: f64) -> Result<(), ModelError> {
    if !value.is_finite() {
        return Err(ModelError::param(
            param,
            format!("must be finite, not {value}"),
        ));
    }
    if value <= 0.0 {
        return Err(ModelError::param(
            param,
            format!("must be > 0, not {value}"),
        ));
    }
    Ok(())
}

/// Checks a segment count: at least `min`, at most [`MAX_SEGMENTS`].
pub(crate) fn check_segments(param: &str, value: u32, min: u32) -> Result<(), ModelError> {
    if value < min {
        return Err(ModelError::param(param, format!("must be >= {min}")));
    }
    if value > MAX_SEGMENTS {
        return Err(ModelError::param(
            param,
            format!("must be <= {MAX_SEGMENTS}, not {value}"),
        ));
    }
    Ok(())
}

fn check_facets(param: &str, facets: u64) -> Result<(), ModelError> {
    if facets > MAX_PRIMITIVE_FACETS {
        return Err(ModelError::param(
            param,
            format!("give {facets} facets, more than {MAX_PRIMITIVE_FACETS}"),
        ));
    }
    Ok(())
}

/// Checks the built mesh's coordinates (finite, at most `f64::MAX / 4`).
fn finish(shape: &str, mesh: PolygonMesh) -> Result<PolygonMesh, ModelError> {
    mesh.validate_coordinates()
        .map_err(|e| ModelError::param(shape, format!("give a bad coordinate: {e}")))?;
    Ok(mesh)
}

/// The unit direction at angle `2 pi k / n` in the xy plane, exact at the
/// quarter turns.
fn unit_circle(k: u32, n: u32) -> (f64, f64) {
    let k = k % n;
    if (4 * u64::from(k)) % u64::from(n) == 0 {
        return match 4 * u64::from(k) / u64::from(n) {
            0 => (1.0, 0.0),
            1 => (0.0, 1.0),
            2 => (-1.0, 0.0),
            _ => (0.0, -1.0),
        };
    }
    let a = std::f64::consts::TAU * f64::from(k) / f64::from(n);
    (a.cos(), a.sin())
}

fn p(v: DVec3) -> [f64; 3] {
    [v.x, v.y, v.z]
}

/// An axis-aligned box of the given size, with a corner at the origin
/// (spanning `[0, size]`) or centred on the origin.
pub fn cuboid(size: DVec3, center: bool) -> Result<PolygonMesh, ModelError> {
    check_positive("box.size[0]", size.x)?;
    check_positive("box.size[1]", size.y)?;
    check_positive("box.size[2]", size.z)?;
    let (lo, hi) = if center {
        (-size / 2.0, size / 2.0)
    } else {
        (DVec3::ZERO, size)
    };
    let vertices = (0..8u32)
        .map(|i| {
            [
                if i & 1 == 0 { lo.x } else { hi.x },
                if i & 2 == 0 { lo.y } else { hi.y },
                if i & 4 == 0 { lo.z } else { hi.z },
            ]
        })
        .collect();
    let faces: [[u32; 4]; 6] = [
        [0, 2, 3, 1],
        [4, 5, 7, 6],
        [0, 1, 5, 4],
        [2, 6, 7, 3],
        [0, 4, 6, 2],
        [1, 3, 7, 5],
    ];
    finish(
        "box",
        PolygonMesh::new(
            vertices,
            faces.iter().map(|f| Facet::from_loop(f)).collect(),
        ),
    )
}

/// A UV sphere centred on the origin: `segments` meridians (at least 3) and
/// `rings` latitude bands (at least 2); triangles at the poles, planar
/// quadrilaterals elsewhere.
pub fn uv_sphere(radius: f64, segments: u32, rings: u32) -> Result<PolygonMesh, ModelError> {
    check_positive("sphere.radius", radius)?;
    check_segments("sphere.segments", segments, 3)?;
    check_segments("sphere.rings", rings, 2)?;
    check_facets(
        "sphere.segments and rings",
        u64::from(segments) * u64::from(rings),
    )?;
    let n = segments;
    let mut vertices = vec![[0.0, 0.0, radius]];
    for i in 1..rings {
        let theta = std::f64::consts::PI * f64::from(i) / f64::from(rings);
        let (z, r) = if 2 * i == rings {
            (0.0, radius)
        } else {
            (radius * theta.cos(), radius * theta.sin())
        };
        for j in 0..n {
            let (c, s) = unit_circle(j, n);
            vertices.push([r * c, r * s, z]);
        }
    }
    let south = vertices.len() as u32;
    vertices.push([0.0, 0.0, -radius]);
    let ring = |i: u32, j: u32| 1 + (i - 1) * n + j % n;
    let mut facets = Vec::new();
    for j in 0..n {
        facets.push(Facet::from_loop(&[0, ring(1, j), ring(1, j + 1)]));
    }
    for i in 1..rings - 1 {
        for j in 0..n {
            facets.push(Facet::from_loop(&[
                ring(i, j),
                ring(i + 1, j),
                ring(i + 1, j + 1),
                ring(i, j + 1),
            ]));
        }
    }
    for j in 0..n {
        facets.push(Facet::from_loop(&[
            south,
            ring(rings - 1, j + 1),
            ring(rings - 1, j),
        ]));
    }
    finish("sphere", PolygonMesh::new(vertices, facets))
}

/// An icosphere centred on the origin: the icosahedron with every triangle
/// split into four `level` times, new vertices pushed out to the sphere.
pub fn icosphere(radius: f64, level: u32) -> Result<PolygonMesh, ModelError> {
    check_positive("icosphere.radius", radius)?;
    if level > MAX_ICOSPHERE_LEVEL {
        return Err(ModelError::param(
            "icosphere.level",
            format!("must be <= {MAX_ICOSPHERE_LEVEL}, not {level}"),
        ));
    }
    let t = (1.0 + 5f64.sqrt()) / 2.0;
    let mut dirs: Vec<DVec3> = [
        [-1.0, t, 0.0],
        [1.0, t, 0.0],
        [-1.0, -t, 0.0],
        [1.0, -t, 0.0],
        [0.0, -1.0, t],
        [0.0, 1.0, t],
        [0.0, -1.0, -t],
        [0.0, 1.0, -t],
        [t, 0.0, -1.0],
        [t, 0.0, 1.0],
        [-t, 0.0, -1.0],
        [-t, 0.0, 1.0],
    ]
    .iter()
    .map(|&v| DVec3::from_array(v).normalize())
    .collect();
    let mut tris: Vec<[u32; 3]> = vec![
        [0, 11, 5],
        [0, 5, 1],
        [0, 1, 7],
        [0, 7, 10],
        [0, 10, 11],
        [1, 5, 9],
        [5, 11, 4],
        [11, 10, 2],
        [10, 7, 6],
        [7, 1, 8],
        [3, 9, 4],
        [3, 4, 2],
        [3, 2, 6],
        [3, 6, 8],
        [3, 8, 9],
        [4, 9, 5],
        [2, 4, 11],
        [6, 2, 10],
        [8, 6, 7],
        [9, 8, 1],
    ];
    for _ in 0..level {
        let mut mid: HashMap<(u32, u32), u32> = HashMap::new();
        let mut next = Vec::with_capacity(tris.len() * 4);
        for &[a, b, c] in &tris {
            let mut m = |u: u32, v: u32| {
                *mid.entry((u.min(v), u.max(v))).or_insert_with(|| {
                    dirs.push((dirs[u as usize] + dirs[v as usize]).normalize());
                    (dirs.len() - 1) as u32
                })
            };
            let (ab, bc, ca) = (m(a, b), m(b, c), m(c, a));
            next.extend_from_slice(&[[a, ab, ca], [b, bc, ab], [c, ca, bc], [ab, bc, ca]]);
        }
        tris = next;
    }
    // Orient every triangle outward (its normal along its centroid).
    for t in &mut tris {
        let [a, b, c] = t.map(|i| dirs[i as usize]);
        if (b - a).cross(c - a).dot(a + b + c) < 0.0 {
            t.swap(1, 2);
        }
    }
    let vertices = dirs.iter().map(|&d| p(d * radius)).collect();
    finish(
        "icosphere",
        PolygonMesh::new(vertices, tris.iter().map(|t| Facet::from_loop(t)).collect()),
    )
}

/// A cylinder or cone frustum on the z axis: bottom radius `radius`, top
/// radius `radius_top` (0 gives a cone whose apex is one vertex), height
/// `height`, from z = 0 or centred on the origin.
///
/// ```
/// use umbra::{cylinder, mesh_signed_volume};
///
/// let c = cylinder(1.0, 1.0, 2.0, 6, false)?;
/// assert!(c.check_topology().is_ok());
/// // The hexagonal prism: (n / 2) r^2 sin(2 pi / n) h.
/// let want = 3.0 * (std::f64::consts::TAU / 6.0).sin() * 2.0;
/// assert!((mesh_signed_volume(&c) - want).abs() < 1e-12);
/// let cone = cylinder(1.0, 0.0, 2.0, 6, true)?;
/// assert_eq!(cone.vertices.len(), 7);
/// assert!(cylinder(1.0, 1.0, 2.0, 2, false).is_err());
/// # Ok::<(), umbra::ModelError>(())
/// ```
pub fn cylinder(
    radius: f64,
    radius_top: f64,
    height: f64,
    segments: u32,
    center: bool,
) -> Result<PolygonMesh, ModelError> {
    check_positive("cylinder.radius", radius)?;
    if !radius_top.is_finite() || radius_top < 0.0 {
        return Err(ModelError::param(
            "cylinder.radius_top",
            format!("must be finite and >= 0, not {radius_top}"),
        ));
    }
    check_positive("cylinder.height", height)?;
    check_segments("cylinder.segments", segments, 3)?;
    let n = segments;
    let (z0, z1) = if center {
        (-height / 2.0, height / 2.0)
    } else {
        (0.0, height)
    };
    let mut vertices = Vec::with_capacity(2 * n as usize);
    for j in 0..n {
        let (c, s) = unit_circle(j, n);
        vertices.push([radius * c, radius * s, z0]);
    }
    let mut facets = Vec::with_capacity(n as usize + 2);
    let bottom: Vec<u32> = (0..n).rev().collect();
    facets.push(Facet::from_loop(&bottom));
    if radius_top == 0.0 {
        let apex = n;
        vertices.push([0.0, 0.0, z1]);
        for j in 0..n {
            facets.push(Facet::from_loop(&[j, (j + 1) % n, apex]));
        }
    } else {
        for j in 0..n {
            let (c, s) = unit_circle(j, n);
            vertices.push([radius_top * c, radius_top * s, z1]);
        }
        let top: Vec<u32> = (n..2 * n).collect();
        facets.push(Facet::from_loop(&top));
        for j in 0..n {
            let k = (j + 1) % n;
            facets.push(Facet::from_loop(&[j, k, n + k, n + j]));
        }
    }
    finish("cylinder", PolygonMesh::new(vertices, facets))
}

/// A torus on the z axis, centred on the origin: distance `radius` from
/// the axis to the tube's centre circle, tube radius `tube` (less than
/// `radius`), `segments[0]` steps around the axis and `segments[1]` around
/// the tube.
pub fn torus(radius: f64, tube: f64, segments: [u32; 2]) -> Result<PolygonMesh, ModelError> {
    check_positive("torus.radius", radius)?;
    check_positive("torus.tube", tube)?;
    if tube >= radius {
        return Err(ModelError::param(
            "torus.tube",
            format!("must be < torus.radius ({radius}), not {tube}"),
        ));
    }
    check_segments("torus.segments[0]", segments[0], 3)?;
    check_segments("torus.segments[1]", segments[1], 3)?;
    let [n, m] = segments;
    check_facets("torus.segments", u64::from(n) * u64::from(m))?;
    let mut vertices = Vec::with_capacity((n * m) as usize);
    for i in 0..n {
        let (cp, sp) = unit_circle(i, n);
        for j in 0..m {
            let (ct, st) = unit_circle(j, m);
            let r = radius + tube * ct;
            vertices.push([r * cp, r * sp, tube * st]);
        }
    }
    let id = |i: u32, j: u32| (i % n) * m + j % m;
    let mut facets = Vec::with_capacity((n * m) as usize);
    for i in 0..n {
        for j in 0..m {
            facets.push(Facet::from_loop(&[
                id(i, j),
                id(i + 1, j),
                id(i + 1, j + 1),
                id(i, j + 1),
            ]));
        }
    }
    finish("torus", PolygonMesh::new(vertices, facets))
}

/// A regular polygon with `sides` vertices on the circle of the given
/// radius about the origin (the first at `(radius, 0)`), anticlockwise.
pub fn regular_polygon(radius: f64, sides: u32) -> Result<PolygonSet2, ModelError> {
    check_positive("polygon.radius", radius)?;
    check_segments("polygon.sides", sides, 3)?;
    let points: Vec<[f64; 2]> = (0..sides)
        .map(|j| {
            let (c, s) = unit_circle(j, sides);
            [radius * c, radius * s]
        })
        .collect();
    let mut set = PolygonSet2::with_capacity(points.len(), points.len());
    set.add_loop(&points);
    set.validate_coordinates()
        .map_err(|e| ModelError::param("polygon", format!("gives a bad coordinate: {e}")))?;
    Ok(set)
}

/// A circle of the given radius about the origin, as a regular polygon
/// with `segments` sides.
pub fn circle(radius: f64, segments: u32) -> Result<PolygonSet2, ModelError> {
    check_positive("circle.radius", radius)?;
    check_segments("circle.segments", segments, 3)?;
    regular_polygon(radius, segments)
}

/// The linear extrusion of a 2D polygon set along z, from z = 0 to
/// `height`: a side quadrilateral per edge and two cap facets holding
/// every loop (a cap facet may have holes and several regions).
///
/// Any topologically valid set is accepted: vertices at the same position
/// are welded, zero-length edges dropped, and opposite edges cancelled
/// (multiplicities summed per vertex pair), so the caps hold the net
/// boundary. An edge of multiplicity `k` gives `k` side facets.
pub fn extrude(shape: &PolygonSet2, height: f64) -> Result<PolygonMesh, ModelError> {
    check_positive("extrude.height", height)?;
    shape
        .check_topology()
        .map_err(|e| ModelError::param("extrude.shape", format!("is not valid: {e}")))?;
    shape
        .validate_coordinates()
        .map_err(|e| ModelError::param("extrude.shape", format!("is not valid: {e}")))?;
    // Weld by exact position (-0 and +0 as one).
    let key = |v: [f64; 2]| ((v[0] + 0.0).to_bits(), (v[1] + 0.0).to_bits());
    let mut weld: HashMap<(u64, u64), u32> = HashMap::new();
    let mut positions: Vec<[f64; 2]> = Vec::new();
    let canon: Vec<u32> = shape
        .vertices()
        .iter()
        .map(|&v| {
            *weld.entry(key(v)).or_insert_with(|| {
                positions.push(v);
                (positions.len() - 1) as u32
            })
        })
        .collect();
    // Net multiplicity per vertex pair (low, high): + for low -> high.
    let mut net: BTreeMap<(u32, u32), i64> = BTreeMap::new();
    for e in shape.edges() {
        let (s, t) = (canon[e.start as usize], canon[e.end as usize]);
        if s == t || e.mult == 0 {
            continue;
        }
        let m = i64::from(e.mult);
        if s < t {
            *net.entry((s, t)).or_default() += m;
        } else {
            *net.entry((t, s)).or_default() -= m;
        }
    }
    let mut edges: Vec<(u32, u32)> = Vec::new();
    for (&(lo, hi), &m) in &net {
        let e = if m > 0 { (lo, hi) } else { (hi, lo) };
        for _ in 0..m.unsigned_abs() {
            edges.push(e);
        }
    }
    if edges.is_empty() {
        return Err(ModelError::param(
            "extrude.shape",
            "is empty (no edge after welding and cancelling)",
        ));
    }
    check_facets("extrude.shape", edges.len() as u64 + 2)?;
    // Used vertices, in index order: bottom 2k, top 2k + 1.
    let mut used: Vec<Option<u32>> = vec![None; positions.len()];
    let mut vertices = Vec::new();
    for &(s, t) in &edges {
        for v in [s, t] {
            if used[v as usize].is_none() {
                used[v as usize] = Some((vertices.len() / 2) as u32);
                let q = positions[v as usize];
                vertices.push([q[0], q[1], 0.0]);
                vertices.push([q[0], q[1], height]);
            }
        }
    }
    let id = |v: u32| used[v as usize].map_or(0, |k| 2 * k);
    let mut bottom = Facet::default();
    let mut top = Facet::default();
    let mut facets = Vec::with_capacity(edges.len() + 2);
    for &(s, t) in &edges {
        let (sb, tb) = (id(s), id(t));
        bottom.half_edges.push(HalfEdge { start: tb, end: sb });
        top.half_edges.push(HalfEdge {
            start: sb + 1,
            end: tb + 1,
        });
        facets.push(Facet::from_loop(&[sb, tb, tb + 1, sb + 1]));
    }
    facets.push(bottom);
    facets.push(top);
    finish("extrude", PolygonMesh::new(vertices, facets))
}
