//! The facade's own additions: the report structs serialize to exactly the
//! JSON keys the command-line tool has always written; `encode_*` produce
//! the bytes the file writers write and count the rings as written;
//! `boolean_solid` runs both 3D variants (volumes against analytic values);
//! and the simplify-2d entry points are reachable through the facade.

use serde_json::Value;
use std::collections::BTreeSet;
use umbra::{
    as_triangle_mesh, boolean, boolean_n, boolean_solid, boolean_via_simplify, encode_mesh,
    encode_polygon_set, fill_rule_name, mesh_signed_volume, mesh_to_obj, mesh_to_off, simplify,
    union_all, write_geojson_string, write_wkt_string, Boolean2Report, Boolean3Report, BooleanOp,
    Facet, FileKind, FileReport, FillRule, MeshCounts, MeshVariant, Operands, PolygonMesh,
    PolygonSet2, RingOrientation, SetCounts, SimplifyReport,
};

fn square(x: f64, y: f64, s: f64) -> PolygonSet2 {
    let mut set = PolygonSet2::new();
    set.add_loop(&[[x, y], [x + s, y], [x + s, y + s], [x, y + s]]);
    set
}

/// An axis-aligned box with outward quad facets.
fn cube(o: [f64; 3], s: f64) -> PolygonMesh {
    let mut vertices = Vec::new();
    for i in 0..8 {
        vertices.push([
            o[0] + if i & 1 != 0 { s } else { 0.0 },
            o[1] + if i & 2 != 0 { s } else { 0.0 },
            o[2] + if i & 4 != 0 { s } else { 0.0 },
        ]);
    }
    let faces: [[u32; 4]; 6] = [
        [0, 2, 3, 1],
        [4, 5, 7, 6],
        [0, 1, 5, 4],
        [2, 6, 7, 3],
        [0, 4, 6, 2],
        [1, 3, 7, 5],
    ];
    PolygonMesh::new(
        vertices,
        faces.iter().map(|f| Facet::from_loop(f)).collect(),
    )
}

fn keys(v: &Value) -> BTreeSet<String> {
    v.as_object().unwrap().keys().cloned().collect()
}

fn set_of(names: &[&str]) -> BTreeSet<String> {
    names.iter().map(|s| s.to_string()).collect()
}

#[test]
fn reports_have_the_keys_the_tool_writes() {
    let (a, b) = (square(0.0, 0.0, 2.0), square(1.0, 1.0, 2.0));
    let inputs = Operands {
        a: SetCounts::of_set("a.wkt", &a),
        b: SetCounts::of_set("b.wkt", &b),
    };
    let out = boolean(&a, &b, BooleanOp::Union).unwrap();
    let enc =
        encode_polygon_set(FileKind::Wkt, &out.shape, RingOrientation::ByRole, "o.wkt").unwrap();
    let r = Boolean2Report::basic(
        BooleanOp::Union,
        false,
        inputs.clone(),
        enc.counts("o.wkt"),
        &out,
        1.5,
    );
    let v = serde_json::to_value(&r).unwrap();
    assert_eq!(
        keys(&v),
        set_of(&[
            "operation",
            "algorithm",
            "keep_orientation",
            "inputs",
            "output",
            "intersections",
            "topologically_valid",
            "topology_error",
            "epsilon",
            "smoothing",
            "timings_ms"
        ])
    );
    assert_eq!(
        keys(&v["timings_ms"]),
        set_of(&[
            "total",
            "validate",
            "broad_phase",
            "intersections",
            "winding_numbers",
            "construct"
        ])
    );
    assert_eq!(
        keys(&v["output"]),
        set_of(&["file", "vertices", "edges", "rings", "signed_area"])
    );
    assert_eq!(v["operation"], "union");
    assert_eq!(v["output"]["signed_area"], 7.0);
    assert_eq!(v["output"]["rings"], 1);
    assert_eq!(v["output"]["vertices"], 8);
    assert_eq!(v["intersections"], 2);
    assert_eq!(v["topology_error"], Value::Null);
    assert_eq!(v["timings_ms"]["total"], 1.5);

    let sw = boolean_via_simplify(&a, &b, BooleanOp::Xor).unwrap();
    let enc =
        encode_polygon_set(FileKind::Wkt, &sw.shape, RingOrientation::ByRole, "o.wkt").unwrap();
    let r =
        Boolean2Report::via_simplify(BooleanOp::Xor, true, inputs, enc.counts("o.wkt"), &sw, 2.0);
    let v = serde_json::to_value(&r).unwrap();
    assert_eq!(
        keys(&v),
        set_of(&[
            "operation",
            "algorithm",
            "keep_orientation",
            "inputs",
            "output",
            "topologically_valid",
            "topology_error",
            "epsilon",
            "k_max",
            "sweep",
            "smoothing",
            "timings_ms"
        ])
    );
    assert_eq!(keys(&v["timings_ms"]), set_of(&["total"]));
    assert_eq!(
        keys(&v["sweep"]),
        set_of(&[
            "input_edges",
            "merged_input_edges",
            "events",
            "intersections",
            "vertex_on_edge_splits",
            "misgrouped_splits",
            "full_scans",
            "max_sweep_len"
        ])
    );
    assert_eq!(v["output"]["signed_area"], 6.0);
    assert_eq!(v["algorithm"], "Boolean through simplification (chapter 6)");

    let fig = {
        let mut s = PolygonSet2::new();
        s.add_loop(&[[0.0, 0.0], [2.0, 2.0], [2.0, 0.0], [0.0, 2.0]]);
        s
    };
    let out = simplify(&fig, FillRule::NonZero).unwrap();
    let enc =
        encode_polygon_set(FileKind::GeoJson, &out.shape, RingOrientation::ByRole, "s").unwrap();
    let r = SimplifyReport::new(
        FillRule::NonZero,
        false,
        SetCounts::of_set("f.wkt", &fig),
        enc.counts("s.geojson"),
        &out,
        0.5,
    );
    let v = serde_json::to_value(&r).unwrap();
    assert_eq!(
        keys(&v),
        set_of(&[
            "operation",
            "rule",
            "keep_orientation",
            "input",
            "output",
            "topologically_valid",
            "topology_error",
            "epsilon",
            "k_max",
            "sweep",
            "timings_ms"
        ])
    );
    assert_eq!(v["rule"], "nonzero");
    // Two triangles of area 1 each, meeting at (1, 1).
    assert_eq!(v["output"]["signed_area"], 2.0);
    assert_eq!(v["output"]["rings"], 2);

    let r = FileReport {
        file: "x.wkt".to_string(),
        report: umbra::check_polygon_set(&fig),
    };
    let v = serde_json::to_value(&r).unwrap();
    assert_eq!(v["file"], "x.wkt");
    assert_eq!(v["crossing_edge_pairs"], 1);
}

#[test]
fn fill_rules_are_named_as_on_the_command_line() {
    let names: Vec<&str> = [
        FillRule::Positive,
        FillRule::NonZero,
        FillRule::EvenOdd,
        FillRule::Negative,
        FillRule::AtLeast2,
        FillRule::Custom(|w| w == 3),
    ]
    .into_iter()
    .map(fill_rule_name)
    .collect();
    assert_eq!(
        names,
        [
            "positive",
            "nonzero",
            "evenodd",
            "negative",
            "at-least-2",
            "custom"
        ]
    );
}

#[test]
fn encoding_matches_the_writers_and_counts_written_rings() {
    // Abutting squares (two loops, one ring by role), squares touching at
    // a corner, and a square with a hole.
    let mut cases = Vec::new();
    let mut abut = square(0.0, 0.0, 1.0);
    abut.add_loop(&[[1.0, 0.0], [2.0, 0.0], [2.0, 1.0], [1.0, 1.0]]);
    cases.push((abut, 2, 1, 2));
    let mut corner = square(0.0, 0.0, 1.0);
    corner.add_loop(&[[1.0, 1.0], [2.0, 1.0], [2.0, 2.0], [1.0, 2.0]]);
    cases.push((corner, 2, 2, 2));
    let mut holed = square(0.0, 0.0, 4.0);
    holed.add_loop(&[[1.0, 1.0], [1.0, 2.0], [2.0, 2.0], [2.0, 1.0]]);
    cases.push((holed, 2, 2, 2));
    for (set, loops, by_role, as_written) in cases {
        assert_eq!(set.loops().len(), loops);
        for (orientation, rings) in [
            (RingOrientation::ByRole, by_role),
            (RingOrientation::AsWritten, as_written),
        ] {
            let wkt = encode_polygon_set(FileKind::Wkt, &set, orientation, "o.wkt").unwrap();
            assert_eq!(
                wkt.bytes,
                write_wkt_string(&set, orientation).unwrap().into_bytes()
            );
            assert_eq!(wkt.rings, rings, "{orientation:?}");
            // Independent count: every innermost parenthesised group is
            // a ring, its points listed with one closing duplicate.
            let text = String::from_utf8(wkt.bytes.clone()).unwrap();
            let groups: Vec<usize> = text
                .split('(')
                .filter_map(|t| t.split_once(')').map(|(ring, _)| ring.split(',').count()))
                .collect();
            assert_eq!(groups.len(), rings, "{text}");
            assert_eq!(groups.iter().sum::<usize>(), wkt.points + rings, "{text}");
            let counts = wkt.counts("o.wkt");
            assert_eq!((counts.rings, counts.vertices), (wkt.rings, wkt.points));
            assert_eq!(counts.signed_area, set.signed_area());
            let gj = encode_polygon_set(FileKind::GeoJson, &set, orientation, "o.geojson").unwrap();
            assert_eq!(
                gj.bytes,
                write_geojson_string(&set, orientation)
                    .unwrap()
                    .into_bytes()
            );
            assert_eq!((gj.rings, gj.points), (wkt.rings, wkt.points));
        }
    }
    // Wrong dimension and invalid shapes are errors naming the file.
    let set = square(0.0, 0.0, 1.0);
    let err = encode_polygon_set(FileKind::Obj, &set, RingOrientation::ByRole, "x.obj")
        .unwrap_err()
        .to_string();
    assert!(err.starts_with("x.obj: unsupported file type"), "{err}");
    let mut open = PolygonSet2::new();
    let (p, q) = (open.add_vertex([0.0, 0.0]), open.add_vertex([1.0, 0.0]));
    open.add_edge(p, q);
    let err = encode_polygon_set(FileKind::Wkt, &open, RingOrientation::ByRole, "y.wkt")
        .unwrap_err()
        .to_string();
    assert!(err.starts_with("y.wkt: invalid shape"), "{err}");
    let c = cube([0.0; 3], 1.0);
    assert_eq!(
        encode_mesh(FileKind::Obj, &c, "c.obj").unwrap(),
        mesh_to_obj(&c).into_bytes()
    );
    assert_eq!(
        encode_mesh(FileKind::Off, &c, "c.off").unwrap(),
        mesh_to_off(&c).into_bytes()
    );
    assert!(encode_mesh(FileKind::Wkt, &c, "c.wkt").is_err());
}

#[test]
fn boolean_solid_runs_both_variants() {
    let a = cube([0.0; 3], 2.0);
    let b = cube([1.0, 1.0, 1.0], 2.0);
    assert!(as_triangle_mesh(&a).is_none());
    // Volumes: 8 + 8 - 1, 1, 8 - 1 (exact: integer boxes).
    for (op, want) in [
        (BooleanOp::Union, 15.0),
        (BooleanOp::Intersection, 1.0),
        (BooleanOp::Difference, 7.0),
    ] {
        for variant in [MeshVariant::PolygonMesh, MeshVariant::TriangleMesh] {
            let out = boolean_solid(&a, &b, op, variant).unwrap();
            assert!(out.mesh.check_topology().is_ok());
            assert_eq!(mesh_signed_volume(&out.mesh), want, "{op:?} {variant:?}");
            assert_eq!(out.variant, variant);
            let tri = variant == MeshVariant::TriangleMesh;
            assert_eq!(out.inputs_triangulated, [tri, tri]);
            assert_eq!(out.triangulate_ms.is_some(), tri);
            if tri {
                let t = as_triangle_mesh(&out.mesh).expect("triangles out");
                // A triangle mesh passes through as is.
                let again =
                    boolean_solid(&t.to_polygon_mesh(), &b, BooleanOp::Union, variant).unwrap();
                assert_eq!(again.inputs_triangulated, [false, true]);
            }
            let r = Boolean3Report::new(
                op,
                Operands {
                    a: MeshCounts::of_mesh("a.obj", &a),
                    b: MeshCounts::of_mesh("b.off", &b),
                },
                "o.obj",
                &out,
            );
            let v = serde_json::to_value(&r).unwrap();
            assert_eq!(
                keys(&v),
                set_of(&[
                    "operation",
                    "variant",
                    "inputs_triangulated",
                    "inputs",
                    "output",
                    "intersections",
                    "topologically_valid",
                    "topology_error",
                    "smoothing",
                    "timings_ms"
                ])
            );
            assert_eq!(v["variant"], variant.name());
            assert_eq!(v["output"]["signed_volume"], want);
            assert_eq!(v["inputs"]["a"]["signed_volume"], 8.0);
            assert_eq!(v["timings_ms"].get("triangulate_inputs").is_some(), tri);
        }
    }
    let err = boolean_solid(&a, &b, BooleanOp::Xor, MeshVariant::PolygonMesh).unwrap_err();
    assert!(err.to_string().contains("xor"), "{err}");
}

#[test]
fn n_ary_forms_through_the_facade() {
    let sets = [
        square(0.0, 0.0, 2.0),
        square(1.0, 0.0, 2.0),
        square(2.0, 0.0, 2.0),
    ];
    assert_eq!(union_all(&sets).unwrap().shape.signed_area(), 8.0);
    let twice = boolean_n(&sets, |w| w.iter().filter(|&&x| x > 0).count() >= 2).unwrap();
    assert_eq!(twice.shape.signed_area(), 4.0);
}

mod triangle_path {
    //! The facade's triangle path on triangle meshes
    //! (`boolean_solid_triangles`) gives the same triangles, bit for bit,
    //! as `boolean_triangles` and as `boolean_solid` with the triangle-mesh
    //! variant on the same triangles as one-triangle facets, over chains of
    //! operations where each result feeds the next.

    use proptest::prelude::*;
    use test_support::shapes::{box_triangles, uv_sphere};
    use umbra::{
        as_triangle_mesh, boolean_solid, boolean_solid_triangles, boolean_triangles, BooleanOp,
        MeshVariant, TriangleMesh,
    };

    fn bits(m: &TriangleMesh) -> (Vec<[u64; 3]>, Vec<[u32; 3]>) {
        let v = m.vertices.iter().map(|p| p.map(f64::to_bits)).collect();
        (v, m.triangles.clone())
    }

    /// Runs the chain `shape op_k operand_k` three ways and checks that
    /// every step agrees; returns the final shape.
    fn chain(start: TriangleMesh, steps: &[(BooleanOp, TriangleMesh)]) -> TriangleMesh {
        let mut direct = start.clone();
        let mut facade = start.clone();
        let mut poly = start.to_polygon_mesh();
        for (k, (op, b)) in steps.iter().enumerate() {
            direct = boolean_triangles(&direct, b, *op).unwrap().mesh;
            let out = boolean_solid_triangles(&facade, b, *op).unwrap();
            assert!(out.total_ms >= 0.0);
            facade = out.mesh;
            let via =
                boolean_solid(&poly, &b.to_polygon_mesh(), *op, MeshVariant::TriangleMesh).unwrap();
            assert_eq!(via.inputs_triangulated, [false, false], "step {k}");
            poly = via.mesh;
            assert!(bits(&direct) == bits(&facade), "step {k}: facade differs");
            let back = as_triangle_mesh(&poly).expect("triangles as facets");
            assert!(
                bits(&direct) == bits(&back),
                "step {k}: boolean_solid differs"
            );
            assert!(facade.check_topology().is_ok(), "step {k}");
        }
        facade
    }

    #[test]
    fn a_slab_carved_by_boxes_and_a_sphere() {
        let slab = box_triangles([0.0; 3], [4.0, 3.0, 1.0]);
        let mut steps: Vec<(BooleanOp, TriangleMesh)> = (0..6)
            .map(|k| {
                let (x, y) = (0.25 + f64::from(k % 3), 0.25 + f64::from(k / 3));
                let b = box_triangles([x, y, -0.5], [x + 0.5, y + 0.5, 1.5]);
                (BooleanOp::Difference, b)
            })
            .collect();
        steps.push((BooleanOp::Union, uv_sphere([2.0, 1.5, 1.0], 0.7, 12, 6)));
        steps.push((
            BooleanOp::Intersection,
            box_triangles([0.5, -1.0, -1.0], [3.5, 4.0, 3.0]),
        ));
        let out = chain(slab, &steps);
        assert!(out.signed_volume() > 0.0);
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(test_support::cases(16)))]

        #[test]
        fn random_box_chains_agree(
            boxes in proptest::collection::vec(
                ((0i32..16, 0i32..12, -4i32..8), (1i32..8, 1i32..8, 1i32..8), 0u8..3),
                1..6,
            ),
        ) {
            // Coordinates on a grid of 1/4: coplanar faces and shared
            // edges are frequent, and volumes are exact.
            let start = box_triangles([0.0; 3], [4.0, 3.0, 1.0]);
            let q = |v: i32| f64::from(v) / 4.0;
            let steps: Vec<(BooleanOp, TriangleMesh)> = boxes
                .iter()
                .map(|&((x, y, z), (w, h, d), op)| {
                    let op = [BooleanOp::Difference, BooleanOp::Union, BooleanOp::Intersection]
                        [usize::from(op)];
                    (op, box_triangles([q(x), q(y), q(z)], [q(x + w), q(y + h), q(z + d)]))
                })
                .collect();
            let out = chain(start, &steps);
            prop_assert!(out.check_topology().is_ok());
        }
    }
}
