//! Primitive shapes for tests, benches and fuzzing: boxes, tetrahedra,
//! octahedra, UV spheres and icospheres as meshes, regular polygons and
//! squares as rings. Each keeps the exact arithmetic of the copies it
//! replaced, so the same arguments give the same coordinates bit for bit.

use topology::{Facet, PolygonMesh, TriangleMesh};

/// A ring of 2D points (implicitly closed).
pub type Ring = Vec<[f64; 2]>;

/// The six quadrilateral faces of a unit cube with vertex `i` at
/// `(i & 1, (i >> 1) & 1, (i >> 2) & 1)`, facing outwards.
pub const CUBE_FACES: [[u32; 4]; 6] = [
    [0, 2, 3, 1],
    [4, 5, 7, 6],
    [0, 1, 5, 4],
    [2, 6, 7, 3],
    [0, 4, 6, 2],
    [1, 3, 7, 5],
];

/// The four faces of a tetrahedron on vertices 0-3, outward when vertex
/// `i` is at the origin (0) or the unit point on axis `i - 1`.
pub const TETRA_FACES: [[u32; 3]; 4] = [[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2]];

/// The eight faces of an octahedron on vertices 0-5 (0 and 1 opposite on
/// the x axis, 2 and 3 on y, 4 and 5 on z).
pub const OCTA_FACES: [[u32; 3]; 8] = [
    [0, 2, 4],
    [2, 1, 4],
    [1, 3, 4],
    [3, 0, 4],
    [2, 0, 5],
    [1, 2, 5],
    [3, 1, 5],
    [0, 3, 5],
];

/// The eight corners of the box `[lo, hi]`, corner `i` taking `hi` on axis
/// `k` when bit `k` of `i` is set (the numbering of [`CUBE_FACES`]).
pub fn box_corners(lo: [f64; 3], hi: [f64; 3]) -> [[f64; 3]; 8] {
    std::array::from_fn(|i| {
        [
            if i & 1 == 0 { lo[0] } else { hi[0] },
            if i & 2 == 0 { lo[1] } else { hi[1] },
            if i & 4 == 0 { lo[2] } else { hi[2] },
        ]
    })
}

/// An axis-aligned box as a polygon mesh of 6 quadrilaterals.
pub fn box_mesh(lo: [f64; 3], hi: [f64; 3]) -> PolygonMesh {
    let (mut v, mut f) = (Vec::new(), Vec::new());
    push_box(&mut v, &mut f, lo, hi, false);
    PolygonMesh::new(v, f)
}

/// An axis-aligned box as a triangle mesh of 12 triangles (each face split
/// along its diagonal from its first corner).
pub fn box_triangles(lo: [f64; 3], hi: [f64; 3]) -> TriangleMesh {
    let tris = CUBE_FACES
        .iter()
        .flat_map(|f| [[f[0], f[1], f[2]], [f[0], f[2], f[3]]])
        .collect();
    TriangleMesh::new(box_corners(lo, hi).to_vec(), tris)
}

/// Appends the box `[lo, hi]` to a mesh under construction: its 8 corners
/// to `vertices`, its 6 outward quadrilaterals (inward when `flip`) to
/// `facets`.
pub fn push_box(
    vertices: &mut Vec<[f64; 3]>,
    facets: &mut Vec<Facet>,
    lo: [f64; 3],
    hi: [f64; 3],
    flip: bool,
) {
    let base = vertices.len() as u32;
    vertices.extend(box_corners(lo, hi));
    for q in CUBE_FACES {
        let mut l: Vec<u32> = q.iter().map(|k| k + base).collect();
        if flip {
            l.reverse();
        }
        facets.push(Facet::from_loop(&l));
    }
}

/// A tetrahedron on the four points, faces [`TETRA_FACES`] (outward when
/// the points are positively oriented).
pub fn tetra(p: [[f64; 3]; 4]) -> TriangleMesh {
    TriangleMesh::new(p.to_vec(), TETRA_FACES.to_vec())
}

/// A UV sphere with `slices` segments around and `stacks` bands
/// (`2 slices (stacks - 1)` triangles), outward facing.
pub fn uv_sphere(c: [f64; 3], r: f64, slices: u32, stacks: u32) -> TriangleMesh {
    let mut v = vec![[c[0], c[1], c[2] + r]];
    for i in 1..stacks {
        let th = std::f64::consts::PI * f64::from(i) / f64::from(stacks);
        for j in 0..slices {
            let ph = 2.0 * std::f64::consts::PI * f64::from(j) / f64::from(slices);
            v.push([
                c[0] + r * th.sin() * ph.cos(),
                c[1] + r * th.sin() * ph.sin(),
                c[2] + r * th.cos(),
            ]);
        }
    }
    v.push([c[0], c[1], c[2] - r]);
    let south = v.len() as u32 - 1;
    let ring = |i: u32, j: u32| 1 + (i - 1) * slices + (j % slices);
    let mut t = Vec::with_capacity(2 * (slices * (stacks - 1)) as usize);
    for j in 0..slices {
        t.push([0, ring(1, j), ring(1, j + 1)]);
        t.push([south, ring(stacks - 1, j + 1), ring(stacks - 1, j)]);
    }
    for i in 1..stacks - 1 {
        for j in 0..slices {
            let (a, b, c2, d) = (
                ring(i, j),
                ring(i, j + 1),
                ring(i + 1, j),
                ring(i + 1, j + 1),
            );
            t.push([a, c2, d]);
            t.push([a, d, b]);
        }
    }
    TriangleMesh::new(v, t)
}

/// The same sphere as [`uv_sphere`] with quadrilaterals between the bands
/// (triangles at the poles), on the same vertices.
pub fn uv_sphere_quads(c: [f64; 3], r: f64, slices: u32, stacks: u32) -> PolygonMesh {
    let t = uv_sphere(c, r, slices, stacks);
    let south = t.vertices.len() as u32 - 1;
    let ring = |i: u32, j: u32| 1 + (i - 1) * slices + (j % slices);
    let mut f = Vec::new();
    for j in 0..slices {
        f.push(Facet::from_loop(&[0, ring(1, j), ring(1, j + 1)]));
        f.push(Facet::from_loop(&[
            south,
            ring(stacks - 1, j + 1),
            ring(stacks - 1, j),
        ]));
    }
    for i in 1..stacks - 1 {
        for j in 0..slices {
            f.push(Facet::from_loop(&[
                ring(i, j),
                ring(i + 1, j),
                ring(i + 1, j + 1),
                ring(i, j + 1),
            ]));
        }
    }
    PolygonMesh::new(t.vertices, f)
}

/// An icosphere: an icosahedron subdivided `levels` times, projected on
/// the sphere.
pub fn icosphere(c: [f64; 3], r: f64, levels: u32) -> TriangleMesh {
    let p = (1.0 + 5f64.sqrt()) / 2.0;
    let mut v: Vec<[f64; 3]> = vec![
        [-1.0, p, 0.0],
        [1.0, p, 0.0],
        [-1.0, -p, 0.0],
        [1.0, -p, 0.0],
        [0.0, -1.0, p],
        [0.0, 1.0, p],
        [0.0, -1.0, -p],
        [0.0, 1.0, -p],
        [p, 0.0, -1.0],
        [p, 0.0, 1.0],
        [-p, 0.0, -1.0],
        [-p, 0.0, 1.0],
    ];
    let mut t: Vec<[u32; 3]> = vec![
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
    for _ in 0..levels {
        let mut mid = std::collections::HashMap::new();
        let mut nt = Vec::new();
        for tri in &t {
            let mut m = [0u32; 3];
            for k in 0..3 {
                let (a, b) = (tri[k], tri[(k + 1) % 3]);
                let key = (a.min(b), a.max(b));
                m[k] = *mid.entry(key).or_insert_with(|| {
                    let (pa, pb) = (v[a as usize], v[b as usize]);
                    v.push([
                        (pa[0] + pb[0]) / 2.0,
                        (pa[1] + pb[1]) / 2.0,
                        (pa[2] + pb[2]) / 2.0,
                    ]);
                    v.len() as u32 - 1
                });
            }
            nt.push([tri[0], m[0], m[2]]);
            nt.push([tri[1], m[1], m[0]]);
            nt.push([tri[2], m[2], m[1]]);
            nt.push([m[0], m[1], m[2]]);
        }
        t = nt;
    }
    for p in &mut v {
        let n = (p[0] * p[0] + p[1] * p[1] + p[2] * p[2]).sqrt();
        *p = [
            c[0] + r * p[0] / n,
            c[1] + r * p[1] / n,
            c[2] + r * p[2] / n,
        ];
    }
    TriangleMesh::new(v, t)
}

/// The regular `n`-gon of circumradius `radius` about the origin,
/// anticlockwise, vertex `k` at angle `2 pi k / n` plus `rotation_deg`
/// degrees. Fewer than three vertices give an empty ring.
pub fn regular_ngon(n: usize, radius: f64, rotation_deg: f64) -> Ring {
    if n < 3 {
        return Vec::new();
    }
    let rotation = rotation_deg.to_radians();
    (0..n)
        .map(|k| {
            let theta = std::f64::consts::TAU * (k as f64) / (n as f64) + rotation;
            [radius * theta.cos(), radius * theta.sin()]
        })
        .collect()
}

/// The axis-aligned square with lower-left corner `(x, y)` and side `s`,
/// anticlockwise.
pub fn square(x: f64, y: f64, s: f64) -> Ring {
    rect(x, y, s, s)
}

/// The rectangle `[x, x + w] x [y, y + h]`, anticlockwise from its lower
/// left corner.
pub fn rect(x: f64, y: f64, w: f64, h: f64) -> Ring {
    vec![[x, y], [x + w, y], [x + w, y + h], [x, y + h]]
}

/// A comb of `teeth` teeth `[1, w] x [2i, 2i + 1/2]` on the spine `[0, 1]`,
/// anticlockwise; with `mirrored`, its mirror image `x -> w + 2 - x`
/// shifted up by `shift` (spine on the right, the loop reversed so that it
/// stays anticlockwise). Shift 1: teeth interleaved with the unmirrored
/// comb's, never touching; 1/2: touching along whole edges; 1/4:
/// overlapping. The broad phases' worst case: every tooth spans the same
/// x range.
pub fn comb(teeth: usize, w: f64, mirrored: bool, shift: f64) -> Ring {
    let mut pts = vec![[0.0, 0.0]];
    for i in 0..teeth {
        let y = 2.0 * i as f64;
        pts.extend_from_slice(&[[w, y], [w, y + 0.5], [1.0, y + 0.5], [1.0, y + 2.0]]);
    }
    pts.truncate(pts.len() - 2);
    pts.push([0.0, 2.0 * teeth as f64 - 1.5]);
    if mirrored {
        pts = pts
            .iter()
            .rev()
            .map(|p| [w + 2.0 - p[0], p[1] + shift])
            .collect();
    }
    pts
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn closed_solids_with_analytic_volumes() {
        let b = box_mesh([0.0, 1.0, 2.0], [2.0, 4.0, 6.0]);
        assert!(b.check_topology().is_ok());
        let t = box_triangles([0.0, 1.0, 2.0], [2.0, 4.0, 6.0]);
        assert!(t.check_topology().is_ok());
        assert_eq!(t.signed_volume(), 24.0);
        assert_eq!(crate::measure::polygon_mesh_volume(&b), 24.0);
        let (mut v, mut f) = (Vec::new(), Vec::new());
        push_box(&mut v, &mut f, [0.0; 3], [1.0; 3], true);
        assert_eq!(
            crate::measure::polygon_mesh_volume(&PolygonMesh::new(v, f)),
            -1.0
        );
        let te = tetra([[0.0; 3], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]);
        assert!(te.check_topology().is_ok());
        assert_eq!(te.signed_volume(), 1.0 / 6.0);
        let oct: Vec<[f64; 3]> = vec![
            [1.0, 0.0, 0.0],
            [-1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
            [0.0, -1.0, 0.0],
            [0.0, 0.0, 1.0],
            [0.0, 0.0, -1.0],
        ];
        let o = TriangleMesh::new(oct, OCTA_FACES.to_vec());
        assert!(o.check_topology().is_ok());
        assert_eq!(o.signed_volume(), 4.0 / 3.0);
    }

    #[test]
    fn spheres_are_closed_and_near_the_ball() {
        let s = uv_sphere([1.0, 2.0, 3.0], 2.0, 64, 32);
        assert!(s.check_topology().is_ok());
        assert_eq!(s.triangles.len(), 2 * 64 * 31);
        let ball = 4.0 / 3.0 * std::f64::consts::PI * 8.0;
        assert!((s.signed_volume() - ball).abs() < 0.01 * ball);
        let q = uv_sphere_quads([1.0, 2.0, 3.0], 2.0, 64, 32);
        assert!(q.check_topology().is_ok());
        assert_eq!(q.vertices, s.vertices);
        let i = icosphere([0.0; 3], 1.0, 3);
        assert!(i.check_topology().is_ok());
        assert_eq!(i.triangles.len(), 20 * 64);
        let v = i.signed_volume();
        assert!(
            v > 0.97 * 4.0 / 3.0 * std::f64::consts::PI && v < 4.0 / 3.0 * std::f64::consts::PI
        );
    }

    #[test]
    fn polygons() {
        let n = regular_ngon(6, 2.0, 30.0);
        assert_eq!(n.len(), 6);
        for p in &n {
            assert!((p[0].hypot(p[1]) - 2.0).abs() < 1e-15);
        }
        assert!(regular_ngon(2, 1.0, 0.0).is_empty());
        assert_eq!(square(1.0, 2.0, 3.0)[2], [4.0, 5.0]);
        let area = |r: &Ring| {
            (0..r.len())
                .map(|i| {
                    let (p, q) = (r[i], r[(i + 1) % r.len()]);
                    p[0] * q[1] - q[0] * p[1]
                })
                .sum::<f64>()
                / 2.0
        };
        assert_eq!(area(&rect(1.0, 2.0, 3.0, 4.0)), 12.0);
        // Spine 1 x (2 teeth - 1.5), teeth (w - 1) x 1/2 each.
        let c = comb(5, 4.0, false, 0.0);
        assert_eq!(c.len(), 4 * 5);
        assert_eq!(area(&c), 8.5 + 5.0 * 1.5);
        assert_eq!(area(&comb(5, 4.0, true, 1.0)), 8.5 + 5.0 * 1.5);
    }
}
