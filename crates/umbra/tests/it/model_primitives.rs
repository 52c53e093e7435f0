//! Primitives, extrusion and transforms of the modelling module: every
//! mesh valid, 2-manifold, outward and without degenerate facets; volumes
//! against analytic values of the polyhedra (the polyhedral formulas, not
//! the smooth solids); bad parameters give errors; random transforms scale
//! the volume by the determinant.

use proptest::prelude::*;
use std::f64::consts::{PI, TAU};
use umbra::{
    circle, cuboid, cylinder, extrude, icosphere, mesh_signed_volume, regular_polygon, torus,
    transform_mesh, uv_sphere, DMat4, DVec3, Edge2, ModelError, PolygonMesh, PolygonSet2,
    Transform,
};

/// Closed, 2-manifold, every facet with a non-zero area (Newell normal)
/// and distinct vertex positions along each loop.
fn assert_solid(m: &PolygonMesh) {
    assert_eq!(m.check_topology(), Ok(()));
    assert_eq!(m.manifold_report().map(|r| r.is_two_manifold()), Ok(true));
    for (i, f) in m.facets.iter().enumerate() {
        let mut n = DVec3::ZERO;
        for h in &f.half_edges {
            let a = DVec3::from_array(m.vertices[h.start as usize]);
            let b = DVec3::from_array(m.vertices[h.end as usize]);
            assert_ne!(a, b, "facet {i} has a zero-length edge");
            n += a.cross(b);
        }
        assert!(n.length() > 0.0, "facet {i} is degenerate");
    }
    assert!(mesh_signed_volume(m) > 0.0, "not outward");
}

/// The signed volume by the divergence theorem over each facet's loops,
/// fanned from the facet's first vertex (independent of the library's
/// triangulation).
fn fan_volume(m: &PolygonMesh) -> f64 {
    let mut six = 0.0;
    for f in &m.facets {
        let o = DVec3::from_array(m.vertices[f.half_edges[0].start as usize]);
        for h in &f.half_edges {
            let a = DVec3::from_array(m.vertices[h.start as usize]);
            let b = DVec3::from_array(m.vertices[h.end as usize]);
            six += o.dot(a.cross(b));
        }
    }
    six / 6.0
}

fn close(a: f64, b: f64, rel: f64) -> bool {
    (a - b).abs() <= rel * a.abs().max(b.abs())
}

/// The area of a regular n-gon of circumradius r.
fn ngon(n: u32, r: f64) -> f64 {
    f64::from(n) / 2.0 * r * r * (TAU / f64::from(n)).sin()
}

#[test]
fn boxes_have_exact_volume() {
    let b = cuboid(DVec3::new(2.0, 3.0, 5.0), false).unwrap();
    assert_solid(&b);
    assert_eq!(mesh_signed_volume(&b), 30.0);
    assert_eq!(fan_volume(&b), 30.0);
    let c = cuboid(DVec3::new(2.0, 3.0, 5.0), true).unwrap();
    assert_solid(&c);
    assert_eq!(mesh_signed_volume(&c), 30.0);
    assert!(c
        .vertices
        .iter()
        .all(|v| v[0].abs() == 1.0 && v[1].abs() == 1.5));
}

#[test]
fn cylinders_and_cones_match_the_polyhedral_formula() {
    for n in [3, 4, 5, 7, 16, 33, 64] {
        for center in [false, true] {
            let c = cylinder(1.5, 1.5, 2.0, n, center).unwrap();
            assert_solid(&c);
            let want = ngon(n, 1.5) * 2.0;
            assert!(close(mesh_signed_volume(&c), want, 1e-12), "n {n}");
            assert!(close(fan_volume(&c), want, 1e-12));
            assert_eq!(c.vertices.len(), 2 * n as usize);

            let cone = cylinder(1.5, 0.0, 2.0, n, center).unwrap();
            assert_solid(&cone);
            assert_eq!(cone.vertices.len(), n as usize + 1, "apex is one vertex");
            assert!(close(
                mesh_signed_volume(&cone),
                ngon(n, 1.5) * 2.0 / 3.0,
                1e-12
            ));

            let frustum = cylinder(1.5, 0.5, 2.0, n, center).unwrap();
            assert_solid(&frustum);
            let (a0, a1) = (ngon(n, 1.5), ngon(n, 0.5));
            let want = 2.0 / 3.0 * (a0 + a1 + (a0 * a1).sqrt());
            assert!(close(mesh_signed_volume(&frustum), want, 1e-12));
        }
    }
}

#[test]
fn uv_spheres_match_the_frustum_sum_of_their_bands() {
    for (n, m) in [(3, 2), (4, 2), (8, 4), (12, 7), (32, 16), (64, 31)] {
        let r = 2.5;
        let s = uv_sphere(r, n, m).unwrap();
        assert_solid(&s);
        assert_eq!(s.vertices.len(), (n * (m - 1) + 2) as usize);
        // Every vertex on the sphere.
        for v in &s.vertices {
            assert!(close(DVec3::from_array(*v).length(), r, 1e-14));
        }
        // Independent: pyramids at the poles and frusta between rings of
        // similar, aligned regular n-gons.
        let ring = |i: u32| {
            let t = PI * f64::from(i) / f64::from(m);
            (r * t.cos(), r * t.sin())
        };
        let mut want = 0.0;
        for i in 0..m {
            let (z0, r0) = ring(i);
            let (z1, r1) = ring(i + 1);
            let (a0, a1) = (ngon(n, r0), ngon(n, r1));
            want += (z0 - z1) / 3.0 * (a0 + a1 + (a0 * a1).sqrt());
        }
        assert!(close(mesh_signed_volume(&s), want, 1e-12), "{n}x{m}");
        assert!(close(fan_volume(&s), want, 1e-12));
        assert!(want < 4.0 / 3.0 * PI * r * r * r);
    }
}

#[test]
fn icospheres_are_regular_at_level_zero_and_converge() {
    let r = 3.0;
    let ico = icosphere(r, 0).unwrap();
    assert_solid(&ico);
    assert_eq!((ico.vertices.len(), ico.facets.len()), (12, 20));
    let a = 4.0 * r / (10.0 + 2.0 * 5f64.sqrt()).sqrt();
    let want = 5.0 / 12.0 * (3.0 + 5f64.sqrt()) * a * a * a;
    assert!(close(mesh_signed_volume(&ico), want, 1e-12));
    let ball = 4.0 / 3.0 * PI * r * r * r;
    let mut last = mesh_signed_volume(&ico);
    for level in 1..=4 {
        let s = icosphere(r, level).unwrap();
        assert_solid(&s);
        assert_eq!(s.facets.len(), 20 * 4usize.pow(level));
        assert_eq!(s.vertices.len(), 10 * 4usize.pow(level) + 2);
        let v = mesh_signed_volume(&s);
        assert!(v > last && v < ball, "level {level}");
        last = v;
    }
    assert!(last > 0.99 * ball);
}

#[test]
fn tori_match_pappus_for_the_polygonal_section() {
    for (n, m) in [(3, 3), (4, 4), (12, 6), (48, 16)] {
        let t = torus(5.0, 1.5, [n, m]).unwrap();
        assert_solid(&t);
        // Each of the n wedges holds sin(2 pi / n) * area * centroid radius.
        let want = f64::from(n) * (TAU / f64::from(n)).sin() * 5.0 * ngon(m, 1.5);
        assert!(close(mesh_signed_volume(&t), want, 1e-12), "{n}x{m}");
        assert!(close(fan_volume(&t), want, 1e-12));
    }
}

#[test]
fn polygons_and_circles() {
    let p = regular_polygon(2.0, 6).unwrap();
    assert_eq!(p.check_topology(), Ok(()));
    assert!(close(p.signed_area(), ngon(6, 2.0), 1e-14));
    let c = circle(1.0, 64).unwrap();
    assert!(close(c.signed_area(), ngon(64, 1.0), 1e-14));
    assert_eq!(c.vertex(16), [0.0, 1.0], "quarter turns are exact");
}

#[test]
fn extrusions_of_sets_with_holes_and_multiplicities() {
    // A 4x4 square with a 2x2 hole: one cap facet with two loops.
    let mut s = PolygonSet2::new();
    s.add_loop(&[[0.0, 0.0], [4.0, 0.0], [4.0, 4.0], [0.0, 4.0]]);
    s.add_loop(&[[1.0, 1.0], [1.0, 3.0], [3.0, 3.0], [3.0, 1.0]]);
    let m = extrude(&s, 2.5).unwrap();
    assert_solid(&m);
    assert_eq!(m.facets.len(), 8 + 2);
    assert_eq!(mesh_signed_volume(&m), 12.0 * 2.5);
    assert_eq!(fan_volume(&m), 12.0 * 2.5);

    // Two separate regions in one set, and a circle.
    let mut two = regular_polygon(1.0, 5).unwrap();
    let mut far = PolygonSet2::new();
    far.add_loop(&[[10.0, 0.0], [12.0, 0.0], [12.0, 1.0], [10.0, 1.0]]);
    two.append(&far);
    let m = extrude(&two, 1.0).unwrap();
    assert_solid(&m);
    assert!(close(mesh_signed_volume(&m), ngon(5, 1.0) + 2.0, 1e-12));

    // A square given as two triangles sharing the diagonal (cancels), with
    // a duplicated vertex and a zero-length edge: welded to the square.
    let v = vec![[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0], [1.0, 1.0]];
    let e = |start, end, mult| Edge2 { start, end, mult };
    let set = PolygonSet2::from_parts(
        v,
        vec![
            e(0, 1, 1),
            e(1, 2, 1),
            e(2, 0, 1),
            e(0, 4, 1),
            e(4, 3, 1),
            e(3, 0, 1),
            e(2, 4, 1),
            e(4, 2, 1),
        ],
    );
    let m = extrude(&set, 3.0).unwrap();
    assert_solid(&m);
    assert_eq!(m.facets.len(), 4 + 2);
    assert_eq!(mesh_signed_volume(&m), 3.0);

    // Multiplicity 2 (a doubly covered square): volume counted twice.
    let set = PolygonSet2::from_parts(
        vec![[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]],
        vec![e(0, 1, 2), e(1, 2, 2), e(2, 3, 2), e(3, 0, 2)],
    );
    let m = extrude(&set, 1.0).unwrap();
    assert_eq!(m.check_topology(), Ok(()));
    assert_eq!(mesh_signed_volume(&m), 2.0);
}

#[test]
fn extrusion_rejects_bad_shapes() {
    let mut open = PolygonSet2::new();
    open.add_vertex([0.0, 0.0]);
    open.add_vertex([1.0, 0.0]);
    open.add_edge(0, 1);
    let msg = extrude(&open, 1.0).unwrap_err().to_string();
    assert!(msg.starts_with("extrude.shape is not valid"), "{msg}");
    let mut cancelled = PolygonSet2::new();
    cancelled.add_loop(&[[0.0, 0.0], [1.0, 0.0]]);
    let msg = extrude(&cancelled, 1.0).unwrap_err().to_string();
    assert!(msg.contains("empty"), "{msg}");
    assert!(extrude(&PolygonSet2::new(), 1.0).is_err());
    let mut nan = PolygonSet2::new();
    nan.add_loop(&[[0.0, 0.0], [f64::NAN, 0.0], [0.0, 1.0]]);
    assert!(extrude(&nan, 1.0).is_err());
    let sq = regular_polygon(1.0, 4).unwrap();
    for h in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        assert!(extrude(&sq, h).is_err());
    }
}

#[test]
fn bad_parameters_are_errors_naming_the_parameter() {
    let nan = f64::NAN;
    let cases: Vec<(Result<PolygonMesh, ModelError>, &str)> = vec![
        (
            cuboid(DVec3::new(1.0, 0.0, 1.0), false),
            "box.size[1] must be > 0, not 0",
        ),
        (
            cuboid(DVec3::new(-1.0, 1.0, 1.0), false),
            "box.size[0] must be > 0, not -1",
        ),
        (
            cuboid(DVec3::new(1.0, 1.0, nan), true),
            "box.size[2] must be finite, not NaN",
        ),
        (uv_sphere(1.0, 2, 4), "sphere.segments must be >= 3"),
        (uv_sphere(1.0, 8, 1), "sphere.rings must be >= 2"),
        (uv_sphere(0.0, 8, 4), "sphere.radius must be > 0, not 0"),
        (
            uv_sphere(1.0, 1 << 20, 4),
            "sphere.segments must be <= 65536, not 1048576",
        ),
        (
            uv_sphere(1.0, 60000, 60000),
            "sphere.segments and rings give 3600000000 facets, more than 16777216",
        ),
        (icosphere(1.0, 10), "icosphere.level must be <= 9, not 10"),
        (
            icosphere(f64::INFINITY, 1),
            "icosphere.radius must be finite, not inf",
        ),
        (
            cylinder(1.0, 1.0, 1.0, 0, false),
            "cylinder.segments must be >= 3",
        ),
        (
            cylinder(1.0, -0.5, 1.0, 8, false),
            "cylinder.radius_top must be finite and >= 0, not -0.5",
        ),
        (
            cylinder(0.0, 1.0, 1.0, 8, false),
            "cylinder.radius must be > 0, not 0",
        ),
        (
            cylinder(1.0, 1.0, -2.0, 8, false),
            "cylinder.height must be > 0, not -2",
        ),
        (
            torus(1.0, 1.0, [8, 8]),
            "torus.tube must be < torus.radius (1), not 1",
        ),
        (torus(1.0, 0.5, [8, 2]), "torus.segments[1] must be >= 3"),
        (torus(-1.0, 0.5, [8, 8]), "torus.radius must be > 0, not -1"),
        (
            cuboid(DVec3::splat(f64::MAX), false),
            "box give a bad coordinate",
        ),
    ];
    for (result, want) in cases {
        let msg = result.unwrap_err().to_string();
        assert!(msg.starts_with(want), "{msg:?} should start with {want:?}");
    }
    assert!(regular_polygon(1.0, 2).is_err());
    assert!(circle(-1.0, 8).is_err());
}

#[test]
fn transforms_flip_mirrors_and_refuse_singular_matrices() {
    let b = cuboid(DVec3::new(1.0, 2.0, 3.0), false).unwrap();
    let mirror = DMat4::from_scale(DVec3::new(-1.0, 1.0, 1.0));
    let m = transform_mesh(&b, &mirror).unwrap();
    assert_solid(&m);
    assert_eq!(mesh_signed_volume(&m), 6.0);
    let squash = DMat4::from_scale(DVec3::new(1.0, 0.0, 1.0));
    assert!(transform_mesh(&b, &squash)
        .unwrap_err()
        .to_string()
        .contains("invertible"));
    let mut nan = DMat4::IDENTITY;
    nan.x_axis.x = f64::NAN;
    assert!(transform_mesh(&b, &nan).is_err());
    let mut projective = DMat4::IDENTITY;
    projective.x_axis.w = 1.0;
    assert!(transform_mesh(&b, &projective)
        .unwrap_err()
        .to_string()
        .contains("affine"));
    let huge = DMat4::from_scale(DVec3::splat(1e308));
    assert!(transform_mesh(&b, &huge).is_err());
    // Quarter turns are exact.
    let t = Transform {
        rotate: Some([90.0, 180.0, 270.0]),
        ..Transform::default()
    };
    let r = transform_mesh(&b, &t.matrix()).unwrap();
    assert_eq!(mesh_signed_volume(&r), 6.0);
    assert!(r.vertices.iter().flatten().all(|c| c.fract() == 0.0));
}

#[test]
fn transform_order_is_scale_rotate_translate() {
    let t = Transform {
        translate: Some([10.0, 0.0, 0.0]),
        rotate: Some([0.0, 0.0, 90.0]),
        scale: Some(umbra::Scale::Axes([2.0, 1.0, 1.0])),
    };
    // (1, 0, 0) -> scale (2, 0, 0) -> rotate z 90 (0, 2, 0) -> (10, 2, 0).
    let p = t.matrix().transform_point3(DVec3::X);
    assert_eq!(p, DVec3::new(10.0, 2.0, 0.0));
    // Rotation about x first, then y: (0, 1, 0) -x90-> (0, 0, 1) -y90-> (1, 0, 0).
    let t = Transform {
        rotate: Some([90.0, 90.0, 0.0]),
        ..Transform::default()
    };
    assert_eq!(t.matrix().transform_point3(DVec3::Y), DVec3::X);
}

fn arb_transform() -> impl Strategy<Value = Transform> {
    let factor = (0.2f64..5.0, any::<bool>()).prop_map(|(s, neg)| if neg { -s } else { s });
    (
        prop::array::uniform3(-100.0f64..100.0),
        prop::array::uniform3(-360.0f64..360.0),
        prop::array::uniform3(factor),
    )
        .prop_map(|(t, r, s)| Transform {
            translate: Some(t),
            rotate: Some(r),
            scale: Some(umbra::Scale::Axes(s)),
        })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(test_support::cases(64)))]

    #[test]
    fn random_transforms_scale_volume_by_the_determinant(t in arb_transform(), which in 0usize..4) {
        let mesh = match which {
            0 => cuboid(DVec3::new(1.0, 2.0, 3.0), true).unwrap(),
            1 => cylinder(1.0, 0.4, 2.0, 11, false).unwrap(),
            2 => uv_sphere(1.5, 12, 6).unwrap(),
            _ => torus(2.0, 0.5, [12, 8]).unwrap(),
        };
        let m = t.matrix();
        let det = umbra::DMat3::from_mat4(m).determinant();
        let out = transform_mesh(&mesh, &m).unwrap();
        assert_solid(&out);
        let want = mesh_signed_volume(&mesh) * det.abs();
        prop_assert!(close(mesh_signed_volume(&out), want, 1e-9), "{} vs {}", mesh_signed_volume(&out), want);
    }

    #[test]
    fn garbage_parameters_never_panic(r in prop::num::f64::ANY, h in prop::num::f64::ANY, n in 0u32..70000, m in 0u32..10) {
        for mesh in [
            cuboid(DVec3::new(r, h, 1.0), false),
            uv_sphere(r, n.min(300), m),
            icosphere(r, m.min(4)),
            icosphere(r, m + 10),
            cylinder(r, h, r, n.min(5000), true),
            torus(r, h, [n.min(300), m]),
        ]
        .into_iter()
        .flatten()
        {
            prop_assert_eq!(mesh.check_topology(), Ok(()));
            prop_assert!(mesh.validate_coordinates().is_ok());
        }
    }
}
