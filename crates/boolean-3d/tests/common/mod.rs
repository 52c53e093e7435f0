//! Shared helpers of the boolean-3d integration tests: primitive meshes, a
//! deterministic random generator, rotations, and the independent oracles
//! (generalized winding number by solid angles, volumes).

#![allow(dead_code)]

use topology::{Facet, PolygonMesh, TriangleMesh};

/// A small deterministic generator (PCG-style LCG).
pub struct Rng(pub u64);

impl Rng {
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        let x = self.0;
        (x ^ (x >> 33)).wrapping_mul(0xff51afd7ed558ccd) ^ (x >> 29)
    }
    /// Uniform in [0, 1).
    pub fn f(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }
    /// Uniform in [lo, hi).
    pub fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.f()
    }
    pub fn int(&mut self, n: u64) -> u64 {
        self.next_u64() % n
    }
}

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

/// An axis-aligned box as a polygon mesh of 6 quadrilaterals.
pub fn box_mesh(lo: [f64; 3], hi: [f64; 3]) -> PolygonMesh {
    let v = (0..8u32)
        .map(|i| {
            [
                if i & 1 == 0 { lo[0] } else { hi[0] },
                if i & 2 == 0 { lo[1] } else { hi[1] },
                if i & 4 == 0 { lo[2] } else { hi[2] },
            ]
        })
        .collect();
    PolygonMesh::new(v, CUBE_FACES.iter().map(|f| Facet::from_loop(f)).collect())
}

/// An axis-aligned box as a triangle mesh of 12 triangles.
pub fn box_triangles(lo: [f64; 3], hi: [f64; 3]) -> TriangleMesh {
    let m = box_mesh(lo, hi);
    let tris = CUBE_FACES
        .iter()
        .flat_map(|f| [[f[0], f[1], f[2]], [f[0], f[2], f[3]]])
        .collect();
    TriangleMesh::new(m.vertices, tris)
}

/// A tetrahedron with outward-facing triangles.
pub fn tetra(p: [[f64; 3]; 4]) -> TriangleMesh {
    TriangleMesh::new(p.to_vec(), vec![[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2]])
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
    let mut t = Vec::new();
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

/// Rotation of `p` about the x, y and z axes by `ang` each, about `c`.
pub fn rotate(p: [f64; 3], c: [f64; 3], ang: f64) -> [f64; 3] {
    let (s, co) = ang.sin_cos();
    let mut q = [p[0] - c[0], p[1] - c[1], p[2] - c[2]];
    q = [q[0], co * q[1] - s * q[2], s * q[1] + co * q[2]];
    q = [co * q[0] + s * q[2], q[1], -s * q[0] + co * q[2]];
    q = [co * q[0] - s * q[1], s * q[0] + co * q[1], q[2]];
    [q[0] + c[0], q[1] + c[1], q[2] + c[2]]
}

/// Signed volume of a polygon mesh (triangulated by fans per loop; exact
/// enough for tests of planar facets).
pub fn volume(m: &PolygonMesh) -> f64 {
    boolean_3d::triangulate_mesh(m).signed_volume()
}

/// The signed volume of a triangle mesh in exact rational arithmetic
/// (divergence theorem), rounded to the nearest f64 once at the end.
pub fn exact_volume(m: &TriangleMesh) -> f64 {
    use num_rational::BigRational;
    use num_traits::{ToPrimitive, Zero};
    let q = |x: f64| BigRational::from_float(x).unwrap_or_else(BigRational::zero);
    let mut six = BigRational::zero();
    for t in &m.triangles {
        let [a, b, c] = t.map(|i| m.vertices[i as usize].map(q));
        let cross = [
            &b[1] * &c[2] - &b[2] * &c[1],
            &b[2] * &c[0] - &b[0] * &c[2],
            &b[0] * &c[1] - &b[1] * &c[0],
        ];
        six += &a[0] * &cross[0] + &a[1] * &cross[1] + &a[2] * &cross[2];
    }
    (six / BigRational::from_integer(6.into()))
        .to_f64()
        .unwrap_or(f64::NAN)
}

/// The generalized winding number of a closed triangle soup at `q`: the sum
/// of the signed solid angles of its triangles over 4 pi (Van Oosterom and
/// Strackee), independent of the Boolean's own predicates.
pub fn winding_number(m: &TriangleMesh, q: [f64; 3]) -> f64 {
    let mut total = 0.0;
    for t in &m.triangles {
        let [a, b, c] = t.map(|i| {
            let p = m.vertices[i as usize];
            [p[0] - q[0], p[1] - q[1], p[2] - q[2]]
        });
        let la = norm(a);
        let lb = norm(b);
        let lc = norm(c);
        let det = a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0])
            + a[2] * (b[0] * c[1] - b[1] * c[0]);
        let den = la * lb * lc + dot(a, b) * lc + dot(b, c) * la + dot(c, a) * lb;
        total += 2.0 * det.atan2(den);
    }
    total / (4.0 * std::f64::consts::PI)
}

fn norm(a: [f64; 3]) -> f64 {
    dot(a, a).sqrt()
}
fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// The distance from `q` to triangle `(a, b, c)`.
pub fn point_triangle_distance(q: [f64; 3], a: [f64; 3], b: [f64; 3], c: [f64; 3]) -> f64 {
    // Ericson, Real-Time Collision Detection, 5.1.5.
    let sub = |x: [f64; 3], y: [f64; 3]| [x[0] - y[0], x[1] - y[1], x[2] - y[2]];
    let ab = sub(b, a);
    let ac = sub(c, a);
    let ap = sub(q, a);
    let d1 = dot(ab, ap);
    let d2 = dot(ac, ap);
    let at = |s: f64, t: f64| {
        let p = [
            a[0] + s * ab[0] + t * ac[0],
            a[1] + s * ab[1] + t * ac[1],
            a[2] + s * ab[2] + t * ac[2],
        ];
        norm(sub(q, p))
    };
    if d1 <= 0.0 && d2 <= 0.0 {
        return norm(ap);
    }
    let bp = sub(q, b);
    let d3 = dot(ab, bp);
    let d4 = dot(ac, bp);
    if d3 >= 0.0 && d4 <= d3 {
        return norm(bp);
    }
    let vc = d1 * d4 - d3 * d2;
    if vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0 {
        return at(d1 / (d1 - d3), 0.0);
    }
    let cp = sub(q, c);
    let d5 = dot(ab, cp);
    let d6 = dot(ac, cp);
    if d6 >= 0.0 && d5 <= d6 {
        return norm(cp);
    }
    let vb = d5 * d2 - d1 * d6;
    if vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0 {
        return at(0.0, d2 / (d2 - d6));
    }
    let va = d3 * d6 - d5 * d4;
    if va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0 {
        let w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
        let p = [
            b[0] + w * (c[0] - b[0]),
            b[1] + w * (c[1] - b[1]),
            b[2] + w * (c[2] - b[2]),
        ];
        return norm(sub(q, p));
    }
    let denom = 1.0 / (va + vb + vc);
    at(vb * denom, vc * denom)
}

/// The distance from `q` to the nearest triangle of `m`.
pub fn distance_to_mesh(m: &TriangleMesh, q: [f64; 3]) -> f64 {
    m.triangles
        .iter()
        .map(|t| {
            let [a, b, c] = t.map(|i| m.vertices[i as usize]);
            point_triangle_distance(q, a, b, c)
        })
        .fold(f64::INFINITY, f64::min)
}
