//! Floating-point measures of shapes for test oracles: the signed volume of
//! a polygon mesh, the area of a triangle mesh, the generalized winding
//! number of a triangle soup and point-to-mesh distances. They are independent of the Boolean's own
//! predicates; the exact oracles are in [`crate::exact`].

use topology::{PolygonMesh, TriangleMesh};

/// The signed volume of a polygon mesh by the divergence theorem: the
/// tetrahedra from the origin over the fan of every facet loop from its
/// facet's first vertex (holes included, as half-edges).
pub fn polygon_mesh_volume(m: &PolygonMesh) -> f64 {
    let mut six = 0.0;
    for f in &m.facets {
        let Some(first) = f.half_edges.first() else {
            continue;
        };
        let c = m.vertices[first.start as usize];
        for h in &f.half_edges {
            let (a, b) = (m.vertices[h.start as usize], m.vertices[h.end as usize]);
            six += c[0] * (a[1] * b[2] - a[2] * b[1]) - c[1] * (a[0] * b[2] - a[2] * b[0])
                + c[2] * (a[0] * b[1] - a[1] * b[0]);
        }
    }
    six / 6.0
}

/// The surface area of a triangle mesh: half the length of each
/// triangle's cross product, summed (of a polygon mesh: triangulate it
/// first, by internal edges).
pub fn triangle_mesh_area(m: &TriangleMesh) -> f64 {
    m.triangles
        .iter()
        .map(|tr| {
            let [a, b, c] = tr.map(|i| m.vertices[i as usize]);
            let u = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
            let v = [c[0] - a[0], c[1] - a[1], c[2] - a[2]];
            let n = [
                u[1] * v[2] - u[2] * v[1],
                u[2] * v[0] - u[0] * v[2],
                u[0] * v[1] - u[1] * v[0],
            ];
            0.5 * (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt()
        })
        .sum()
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::shapes::{box_triangles, icosphere};

    #[test]
    fn winding_numbers_and_distances_of_a_box() {
        let b = box_triangles([0.0; 3], [2.0; 3]);
        assert!((winding_number(&b, [1.0, 1.0, 1.0]) - 1.0).abs() < 1e-12);
        assert!(winding_number(&b, [3.0, 1.0, 1.0]).abs() < 1e-12);
        assert_eq!(distance_to_mesh(&b, [1.0, 1.0, 5.0]), 3.0);
        assert_eq!(distance_to_mesh(&b, [1.0, 1.0, 1.5]), 0.5);
        let s = icosphere([0.0; 3], 1.0, 2);
        assert!((winding_number(&s, [0.1, 0.2, 0.3]) - 1.0).abs() < 1e-12);
    }
}
