//! A real mesh nobody here made (PyVista's threaded hex nut, 1,046
//! triangles, closed 2-manifold, free of self-intersections; see
//! test-support's data README) combined with a copy of itself rotated
//! about the z axis (which also moves it: the nut lies about 115 away from
//! the axis), then smoothed: wherever the moved copy's displacement is
//! not within a few tolerances (the band the algorithm note measures), the
//! result has no intersecting facet pair by the exact test and is a closed
//! 2-manifold. The raw unions and differences have dozens to hundreds.

use boolean_3d::{boolean_triangles, BooleanOp};
use smooth::{sanity_check_triangles, smooth_triangles, SmoothOptions};
use topology::TriangleMesh;

/// The binary little-endian PLY of PyVista's examples: float x y z
/// vertices, then faces as a byte count (3) and three `int` indices.
fn read_ply(name: &str) -> TriangleMesh {
    let bytes = std::fs::read(test_support::data_path(name)).unwrap();
    let end = b"end_header\n";
    let at = bytes.windows(end.len()).position(|w| w == end).unwrap() + end.len();
    let header = std::str::from_utf8(&bytes[..at]).unwrap();
    let count = |what: &str| -> usize {
        header
            .lines()
            .find_map(|l| l.strip_prefix(what))
            .unwrap()
            .trim()
            .parse()
            .unwrap()
    };
    let (nv, nf) = (count("element vertex "), count("element face "));
    let mut p = at;
    let f32_at = |p: usize| f32::from_le_bytes(bytes[p..p + 4].try_into().unwrap()) as f64;
    let mut vertices = Vec::new();
    for _ in 0..nv {
        vertices.push([f32_at(p), f32_at(p + 4), f32_at(p + 8)]);
        p += 12;
    }
    let mut triangles = Vec::new();
    for _ in 0..nf {
        assert_eq!(bytes[p], 3);
        let i =
            |k: usize| u32::from_le_bytes(bytes[p + 1 + 4 * k..p + 5 + 4 * k].try_into().unwrap());
        triangles.push([i(0), i(1), i(2)]);
        p += 13;
    }
    TriangleMesh::new(vertices, triangles)
}

/// `m` rotated by `a` radians about the z axis.
fn rotate(m: &TriangleMesh, a: f64) -> TriangleMesh {
    let (s, c) = a.sin_cos();
    let mut r = m.clone();
    for p in &mut r.vertices {
        let (x, y) = (p[0], p[1]);
        p[0] = c * x - s * y;
        p[1] = s * x + c * y;
    }
    r
}

#[test]
fn nut_and_its_rotated_copy() {
    let nut = read_ply("pyvista/nut.ply");
    nut.check_topology().unwrap();
    assert_eq!(nut.triangles.len(), 1046);
    assert!(nut.self_intersections().unwrap().is_empty());
    let bb = nut.bounding_box().unwrap();
    let size = (0..3).map(|k| bb[1][k] - bb[0][k]).fold(0.0, f64::max);
    let ops = [
        BooleanOp::Union,
        BooleanOp::Intersection,
        BooleanOp::Difference,
    ];
    let mut raw_pairs = 0;
    // (rotation, operations, tolerance relative to the size): the moved
    // copy's displacement (about 115 x rotation) is far from every
    // tolerance here.
    for (a, rel) in [
        (1e-2, 1e-9),
        (1e-2, 1e-6),
        (1e-4, 1e-9),
        (1e-6, 1e-9),
        (1e-6, 1e-4),
    ] {
        let b = rotate(&nut, a);
        for op in ops {
            let raw = boolean_triangles(&nut, &b, op).unwrap().mesh;
            raw_pairs += raw.self_intersections().unwrap().len();
            let delta = rel * size;
            let out = smooth_triangles(&raw, &SmoothOptions::new(delta)).unwrap();
            sanity_check_triangles(&out.shape, delta).unwrap();
            let what = format!("rotation {a:e}, {op:?}, delta {rel:e} x size");
            assert!(out.shape.self_intersections().unwrap().is_empty(), "{what}");
            assert!(
                out.shape.manifold_report().unwrap().is_two_manifold(),
                "{what}"
            );
        }
    }
    assert!(
        raw_pairs > 100,
        "the raw results intersect themselves: {raw_pairs}"
    );
}
