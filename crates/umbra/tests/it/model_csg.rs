//! CSG scripts: parsing (with a table of bad scripts and their messages),
//! evaluation against exact and polyhedral volumes, determinism across
//! runs and thread counts, progress and report, file leaves, the shipped
//! examples and the demo scene.

use std::f64::consts::TAU;
use std::path::{Path, PathBuf};
use std::sync::Mutex;
use umbra::{
    demo_plant, evaluate_csg, evaluate_csg_with_progress, mesh_signed_volume, parse_csg,
    read_csg_file, CsgNode, CsgOptions, DemoDetail, PolygonMesh,
};

fn eval(script: &str) -> PolygonMesh {
    let tree = parse_csg(script).unwrap();
    let out = evaluate_csg(&tree, CsgOptions::default()).unwrap();
    assert!(
        out.report.topologically_valid,
        "{:?}",
        out.report.topology_error
    );
    out.mesh
}

fn ngon(n: u32, r: f64) -> f64 {
    f64::from(n) / 2.0 * r * r * (TAU / f64::from(n)).sin()
}

fn close(a: f64, b: f64, rel: f64) -> bool {
    (a - b).abs() <= rel * a.abs().max(b.abs())
}

fn examples() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples")
}

const TWO_BOXES: &str = r#"{"op": "OP", "children": [
    {"box": {"size": [2, 2, 2]}},
    {"box": {"size": [2, 2, 2]}, "translate": [1, 1, 1]}]}"#;

#[test]
fn box_booleans_are_exact() {
    for (op, want) in [("union", 15.0), ("intersection", 1.0), ("difference", 7.0)] {
        let m = eval(&TWO_BOXES.replace("OP", op));
        assert_eq!(mesh_signed_volume(&m), want, "{op}");
        assert_eq!(m.manifold_report().map(|r| r.is_two_manifold()), Ok(true));
    }
    // A row of five overlapping unit-height bars (balanced 5-way union),
    // intersected with a slab, minus two boxes.
    let row: Vec<String> = (0..5)
        .map(|i| {
            format!(
                r#"{{"box": {{"size": [2, 1, 1]}}, "translate": [{}, 0, 0]}}"#,
                i
            )
        })
        .collect();
    let script = format!(
        r#"{{"op": "difference", "children": [
            {{"op": "intersection", "children": [
                {{"op": "union", "children": [{}]}},
                {{"box": {{"size": [10, 10, 0.5]}}, "translate": [-1, -1, 0.25]}}]}},
            {{"box": {{"size": 1}}, "translate": [0.5, -0.5, 0]}},
            {{"box": {{"size": [1, 3, 3]}}, "translate": [4, -1, -1]}}]}}"#,
        row.join(",")
    );
    // Union: [0, 6] x [0, 1] x [0, 1]; slab: z in [0.25, 0.75]: 6 * 0.5 = 3;
    // minus [0.5, 1.5] x [0, 0.5] x [0.25, 0.75] (0.25) and x in [4, 5] (0.5).
    assert_eq!(mesh_signed_volume(&eval(&script)), 3.0 - 0.25 - 0.5);
}

#[test]
fn transforms_apply_to_subtrees_in_scale_rotate_translate_order() {
    // The union of two boxes, scaled by 2 then moved: volume * 8.
    let script = r#"{"op": "union", "scale": 2, "rotate": [0, 0, 90], "translate": [5, 0, 0],
        "children": [{"box": {"size": [1, 1, 1]}}, {"box": {"size": [1, 1, 1]}, "translate": [1, 0, 0]}]}"#;
    let m = eval(script);
    assert_eq!(mesh_signed_volume(&m), 16.0);
    // x extent [0, 4] rotated to y in [0, 4], then x shifted by 5.
    let xs: Vec<f64> = m.vertices.iter().map(|v| v[0]).collect();
    let ys: Vec<f64> = m.vertices.iter().map(|v| v[1]).collect();
    assert_eq!(xs.iter().cloned().fold(f64::INFINITY, f64::min), 3.0);
    assert_eq!(ys.iter().cloned().fold(f64::NEG_INFINITY, f64::max), 4.0);
    // A mirror keeps the volume positive.
    let m = eval(r#"{"box": {"size": [1, 2, 3]}, "scale": [-1, 1, 1]}"#);
    assert_eq!(mesh_signed_volume(&m), 6.0);
}

#[test]
fn polygonal_primitives_through_csg_match_the_polyhedral_formula() {
    // A box minus a cylinder running through it.
    let m = eval(
        r#"{"op": "difference", "children": [
            {"box": {"size": [4, 4, 2], "center": true}},
            {"cylinder": {"radius": 1, "height": 4, "segments": 20, "center": true}}]}"#,
    );
    assert!(close(
        mesh_signed_volume(&m),
        32.0 - ngon(20, 1.0) * 2.0,
        1e-12
    ));
    // A cylinder cut to half height by a box: the polyhedral prism.
    let m = eval(
        r#"{"op": "intersection", "children": [
            {"cylinder": {"radius": 2, "height": 4, "segments": 12}},
            {"box": {"size": [10, 10, 1]}, "translate": [-5, -5, 1]}]}"#,
    );
    assert!(close(mesh_signed_volume(&m), ngon(12, 2.0), 1e-12));
    // Two disjoint spheres: the sum of the frusta of their bands.
    let sphere = umbra::uv_sphere(1.0, 16, 8).unwrap();
    let m = eval(
        r#"{"op": "union", "children": [
            {"sphere": {"radius": 1, "segments": 16}},
            {"sphere": {"radius": 1, "segments": 16}, "translate": [5, 0, 0]}]}"#,
    );
    assert!(close(
        mesh_signed_volume(&m),
        2.0 * mesh_signed_volume(&sphere),
        1e-12
    ));
}

#[test]
fn the_bracket_example_has_its_polyhedral_volume() {
    let tree = read_csg_file(&examples().join("bracket.json")).unwrap();
    let out = evaluate_csg(&tree, CsgOptions::default()).unwrap();
    assert!(out.report.topologically_valid);
    assert_eq!(out.report.booleans, 4);
    // The plate [0, 80] x [0, 40] x [0, 6] and the upright [1, 7] x [1, 39] x
    // [3, 56] (sunk 3 into the plate, so 50 of its height stands above it),
    // minus two vertical holes through the plate and one horizontal hole
    // through the upright's thickness of 6.
    let want =
        80.0 * 40.0 * 6.0 + 6.0 * 38.0 * 50.0 - 2.0 * ngon(32, 4.0) * 6.0 - ngon(32, 5.0) * 6.0;
    assert!(
        close(out.report.volume, want, 1e-12),
        "{} vs {want}",
        out.report.volume
    );
    assert_eq!(
        out.mesh.manifold_report().map(|r| r.is_two_manifold()),
        Ok(true)
    );
}

#[test]
fn every_shipped_example_evaluates_to_a_valid_closed_solid() {
    let mut seen = 0;
    for entry in std::fs::read_dir(examples()).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().and_then(|e| e.to_str()) != Some("json") {
            continue;
        }
        seen += 1;
        let tree = read_csg_file(&path).unwrap_or_else(|e| panic!("{e}"));
        for triangulate in [false, true] {
            let out = evaluate_csg(
                &tree,
                CsgOptions {
                    triangulate,
                    contacts: None,
                    raw_intermediates: false,
                },
            )
            .unwrap();
            assert!(out.report.topologically_valid, "{}", path.display());
            assert_eq!(out.mesh.check_topology(), Ok(()));
            assert!(out.report.volume > 0.0, "{}", path.display());
            assert_eq!(out.report.booleans, tree.boolean_count());
        }
        // The JSON form round-trips.
        assert!(
            parse_csg(&tree.to_json_string()).unwrap() == tree,
            "JSON round trip differs"
        );
    }
    assert!(seen >= 4, "examples/*.json missing");
}

#[test]
fn triangle_variant_agrees_with_the_polygon_variant() {
    let tree = read_csg_file(&examples().join("pipe_tee.json")).unwrap();
    let poly = evaluate_csg(&tree, CsgOptions::default()).unwrap();
    let tri = evaluate_csg(
        &tree,
        CsgOptions {
            triangulate: true,
            contacts: None,
            raw_intermediates: false,
        },
    )
    .unwrap();
    assert_eq!(tri.report.variant, "triangle");
    assert!(tri.mesh.facets.iter().all(|f| f.half_edges.len() == 3));
    assert!(close(poly.report.volume, tri.report.volume, 1e-9));
}

#[test]
fn file_leaves_resolve_relative_to_the_script() {
    let dir = std::env::temp_dir().join(format!("umbra-model-{}", std::process::id()));
    std::fs::create_dir_all(dir.join("parts")).unwrap();
    let cube = umbra::cuboid(umbra::DVec3::splat(2.0), false).unwrap();
    umbra::write_mesh(&dir.join("parts/cube.obj"), &cube).unwrap();
    let script = dir.join("scene.json");
    std::fs::write(
        &script,
        r#"{"op": "difference", "children": [{"file": "parts/cube.obj"},
            {"box": {"size": 1}}]}"#,
    )
    .unwrap();
    let out = evaluate_csg(&read_csg_file(&script).unwrap(), CsgOptions::default()).unwrap();
    assert_eq!(out.report.volume, 7.0);
    // The same cube written with its facets facing inward is the same
    // leaf: turned outward (as an inside-out solid the difference would
    // be the unit box's complement inside the cube's complement).
    umbra::write_mesh(&dir.join("parts/cube.obj"), &cube.reversed()).unwrap();
    let out = evaluate_csg(&read_csg_file(&script).unwrap(), CsgOptions::default()).unwrap();
    assert_eq!(out.report.volume, 7.0);
    std::fs::write(
        &script,
        r#"{"op": "union", "children": [{"box": {"size": 1}}, {"file": "parts/missing.obj"}]}"#,
    )
    .unwrap();
    let err = evaluate_csg(&read_csg_file(&script).unwrap(), CsgOptions::default()).unwrap_err();
    let msg = err.to_string();
    assert!(
        msg.starts_with("children[1]: ") && msg.contains("missing.obj"),
        "{msg}"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn bad_scripts_give_located_messages() {
    let table: &[(&str, &str)] = &[
        (
            "",
            "<string>: invalid JSON: EOF while parsing a value at line 1 column 0",
        ),
        (
            "{\"op\": \"union\",",
            "<string>: invalid JSON: EOF while parsing",
        ),
        (
            "[]",
            "<string>: root: a node must be an object, not an array",
        ),
        (
            "{}",
            "<string>: root: no shape (expected one of op, box, sphere, cylinder, torus, file)",
        ),
        (
            r#"{"box": {"size": 1}, "sphere": {"radius": 1}}"#,
            "<string>: root: several shapes (box, sphere); a node has exactly one",
        ),
        (
            r#"{"box": {"size": 1}, "colour": "red"}"#,
            "<string>: root: unknown key \"colour\" (expected op, children, box",
        ),
        (
            r#"{"box": {"size": 1, "centre": true}}"#,
            "<string>: root: box: unknown key \"centre\" (expected size, center)",
        ),
        (
            r#"{"box": {"center": true}}"#,
            "<string>: root: box.size is missing",
        ),
        (
            r#"{"box": {"size": [1, 2]}}"#,
            "<string>: root: box.size must be an array of 3 numbers",
        ),
        (
            r#"{"box": {"size": [1, "2", 3]}}"#,
            "<string>: root: box.size[1] must be a number, not a string",
        ),
        (
            r#"{"box": {"size": [1, 0, 3]}}"#,
            "<string>: root: box.size[1] must be > 0, not 0",
        ),
        (
            r#"{"box": {"size": 1, "center": 1}}"#,
            "<string>: root: box.center must be true or false, not a number",
        ),
        (
            r#"{"box": [1, 2, 3]}"#,
            "<string>: root: box must be an object, not an array",
        ),
        (
            r#"{"op": "xor", "children": [{"box": {"size": 1}}]}"#,
            "<string>: root: op must be \"union\", \"intersection\" or \"difference\", not \"xor\"",
        ),
        (
            r#"{"op": 3, "children": []}"#,
            "<string>: root: op must be a string, not a number",
        ),
        (
            r#"{"op": "union"}"#,
            "<string>: root: union needs \"children\"",
        ),
        (
            r#"{"op": "union", "children": []}"#,
            "<string>: root: union needs at least one child",
        ),
        (
            r#"{"op": "union", "children": {}}"#,
            "<string>: root: children must be an array, not an object",
        ),
        (
            r#"{"box": {"size": 1}, "children": []}"#,
            "<string>: root: \"children\" given to a box (only an op has children)",
        ),
        (
            r#"{"op": "union", "children": [{"box": {"size": 1}}, {"box": {"size": 1}},
                {"op": "difference", "children": [{"sphere": {"radius": 1, "segments": 2}}]}]}"#,
            "<string>: children[2].children[0]: sphere.segments must be >= 3",
        ),
        (
            r#"{"sphere": {"radius": -1}}"#,
            "<string>: root: sphere.radius must be > 0, not -1",
        ),
        (
            r#"{"sphere": {"radius": 1, "segments": 3.5}}"#,
            "<string>: root: sphere.segments must be a non-negative integer, not 3.5",
        ),
        (
            r#"{"sphere": {"radius": 1, "segments": -4}}"#,
            "<string>: root: sphere.segments must be a non-negative integer, not -4",
        ),
        (
            r#"{"sphere": {"radius": 1, "segments": 99999999999}}"#,
            "<string>: root: sphere.segments is too large (99999999999)",
        ),
        (
            r#"{"sphere": {"radius": 1, "segments": 60000}}"#,
            "<string>: root: sphere.segments gives 1800000000 facets, more than 16777216",
        ),
        (
            r#"{"cylinder": {"radius": 1}}"#,
            "<string>: root: cylinder.height is missing",
        ),
        (
            r#"{"cylinder": {"radius": 1, "height": 1, "radius_top": -1}}"#,
            "<string>: root: cylinder.radius_top must be finite and >= 0, not -1",
        ),
        (
            r#"{"torus": {"radius": 1, "tube": 2}}"#,
            "<string>: root: torus.tube must be < torus.radius (1), not 2",
        ),
        (
            r#"{"torus": {"radius": 2, "tube": 1, "segments": [8]}}"#,
            "<string>: root: torus.segments must be an array of 2 integers",
        ),
        (
            r#"{"torus": {"radius": 2, "tube": 1, "segments": [8, 2]}}"#,
            "<string>: root: torus.segments[1] must be >= 3",
        ),
        (
            r#"{"file": 7}"#,
            "<string>: root: file must be a string, not a number",
        ),
        (r#"{"file": ""}"#, "<string>: root: file must not be empty"),
        (
            r#"{"box": {"size": 1}, "translate": [1, 2]}"#,
            "<string>: root: translate must be an array of 3 numbers",
        ),
        (
            r#"{"box": {"size": 1}, "rotate": "x"}"#,
            "<string>: root: rotate must be an array of 3 numbers",
        ),
        (
            r#"{"box": {"size": 1}, "scale": 0}"#,
            "<string>: root: scale must be non-zero",
        ),
        (
            r#"{"box": {"size": 1}, "scale": [1, 0, 1]}"#,
            "<string>: root: scale must be non-zero",
        ),
        (
            r#"{"box": {"size": 1}, "scale": [1, 1]}"#,
            "<string>: root: scale must be a number or an array of 3 numbers",
        ),
        (
            r#"{"box": {"size": 1}, "scale": null}"#,
            "<string>: root: scale must be a number or an array of 3 numbers, not null",
        ),
        (
            r#"{"box": {"size": 1e400}}"#,
            "<string>: invalid JSON: number out of range",
        ),
    ];
    for (script, want) in table {
        let msg = parse_csg(script).unwrap_err().to_string();
        assert!(
            msg.starts_with(want),
            "script {script}\n got {msg:?}\nwant {want:?}"
        );
    }
}

#[test]
fn deep_and_garbage_scripts_do_not_panic() {
    let mut s = String::from(r#"{"box": {"size": 1}}"#);
    for _ in 0..300 {
        s = format!(r#"{{"op": "union", "children": [{s}]}}"#);
    }
    // Refused by the JSON parser's depth limit, with what to do instead.
    let msg = parse_csg(&s).unwrap_err().to_string();
    assert!(
        msg.contains("recursion limit") && msg.contains("one operation with many children"),
        "{msg}"
    );
    for junk in [
        "null",
        "1",
        "\"x\"",
        "{\"op\": null}",
        "{\"box\": null}",
        "{\"file\": []}",
    ] {
        assert!(parse_csg(junk).is_err(), "{junk}");
    }
    let bytes = std::env::temp_dir().join(format!("umbra-model-bad-{}.json", std::process::id()));
    std::fs::write(&bytes, b"{\"box\": \xff}").unwrap();
    let msg = read_csg_file(&bytes).unwrap_err().to_string();
    assert!(msg.contains("not UTF-8"), "{msg}");
    std::fs::remove_file(&bytes).unwrap();
    assert!(read_csg_file(Path::new("/nonexistent/x.json"))
        .unwrap_err()
        .to_string()
        .contains("cannot read"));
}

fn bits(m: &PolygonMesh) -> (Vec<u64>, Vec<Vec<(u32, u32)>>) {
    (
        m.vertices.iter().flatten().map(|c| c.to_bits()).collect(),
        m.facets
            .iter()
            .map(|f| f.half_edges.iter().map(|h| (h.start, h.end)).collect())
            .collect(),
    )
}

#[test]
fn evaluation_is_deterministic_across_runs_and_thread_counts() {
    let tree = demo_plant(DemoDetail::Coarse);
    let a = evaluate_csg(&tree, CsgOptions::default()).unwrap();
    let b = evaluate_csg(&tree, CsgOptions::default()).unwrap();
    assert_eq!(bits(&a.mesh), bits(&b.mesh));
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()
        .unwrap();
    let c = pool.install(|| evaluate_csg(&tree, CsgOptions::default()).unwrap());
    assert_eq!(c.report.threads, 1);
    assert_eq!(bits(&a.mesh), bits(&c.mesh));
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(3)
        .build()
        .unwrap();
    let d = pool.install(|| evaluate_csg(&tree, CsgOptions::default()).unwrap());
    assert_eq!(bits(&a.mesh), bits(&d.mesh));
}

#[test]
fn progress_and_report() {
    let tree = read_csg_file(&examples().join("flange.json")).unwrap();
    let calls = Mutex::new(Vec::new());
    let progress = |done: usize, total: usize| calls.lock().unwrap().push((done, total));
    let out = evaluate_csg_with_progress(&tree, CsgOptions::default(), Some(&progress)).unwrap();
    let mut calls = calls.into_inner().unwrap();
    let total = tree.boolean_count();
    assert_eq!(total, 9);
    calls.sort_unstable();
    assert_eq!(calls, (1..=total).map(|d| (d, total)).collect::<Vec<_>>());
    let r = &out.report;
    assert_eq!((r.booleans, r.leaves), (9, 10));
    assert_eq!(r.nodes.len(), 17);
    assert_eq!(r.nodes[0].path, "root");
    assert_eq!(r.nodes[0].kind, "difference");
    assert_eq!(r.nodes[0].booleans, 8);
    assert_eq!(r.nodes[0].operand_facets.len(), 9);
    assert_eq!(r.nodes[1].path, "children[0]");
    assert_eq!(r.nodes[2].path, "children[0].children[0]");
    assert_eq!(r.nodes[0].facets, out.mesh.facets.len());
    assert_eq!(r.facets, out.mesh.facets.len());
    assert_eq!(r.two_manifold, Some(true));
    assert_eq!((r.open_edges, r.non_manifold_edges), (Some(0), Some(0)));
    let b = r.bounds.unwrap();
    assert_eq!((b[0][2], b[1][2]), (0.0, 42.0));
    let json = serde_json::to_value(r).unwrap();
    assert_eq!(json["booleans"], 9);
    assert_eq!(json["nodes"][3]["kind"], "cylinder");
}

#[test]
fn builders_and_serde() {
    let tree = CsgNode::difference(vec![
        CsgNode::cuboid([2.0, 2.0, 2.0], true),
        CsgNode::cylinder(0.5, 3.0, 16, true).rotated([0.0, 90.0, 0.0]),
        CsgNode::sphere(0.5, 12)
            .translated([1.0, 1.0, 1.0])
            .rotated([0.0, 0.0, 45.0]),
    ]);
    let text = serde_json::to_string(&tree).unwrap();
    let back: CsgNode = serde_json::from_str(&text).unwrap();
    assert_eq!(back, tree);
    let bad: Result<CsgNode, _> = serde_json::from_str(r#"{"box": 1}"#);
    assert!(bad
        .unwrap_err()
        .to_string()
        .contains("box must be an object"));
    let out = evaluate_csg(&tree, CsgOptions::default()).unwrap();
    assert!(out.report.topologically_valid && out.report.volume > 0.0 && out.report.volume < 8.0);
}

#[test]
fn the_demo_plant_is_a_valid_closed_solid() {
    let tree = demo_plant(DemoDetail::Coarse);
    assert_eq!(
        tree.boolean_count(),
        demo_plant(DemoDetail::Full).boolean_count()
    );
    assert!(tree.boolean_count() >= 300, "{}", tree.boolean_count());
    let out = evaluate_csg(&tree, CsgOptions::default()).unwrap();
    assert_eq!(out.mesh.check_topology(), Ok(()));
    assert!(out.report.topologically_valid);
    assert_eq!(out.report.two_manifold, Some(true));
    assert!(
        out.report.volume > 30.0 && out.report.volume < 60.0,
        "{}",
        out.report.volume
    );
    let b = out.report.bounds.unwrap();
    assert_eq!(b[0], [0.0, -3.0, 0.0]);
    assert!(b[1][0] >= 14.0 && b[1][2] > 9.0);
    // The tree's JSON form round-trips (the CLI can write it as a script).
    assert!(
        parse_csg(&tree.to_json_string()).unwrap() == tree,
        "JSON round trip differs"
    );
}

#[test]
fn bad_trees_built_in_code_are_errors() {
    let mut deep = CsgNode::cuboid([1.0; 3], false);
    for _ in 0..300 {
        deep = CsgNode::union(vec![deep]);
    }
    let msg = evaluate_csg(&deep, CsgOptions::default())
        .unwrap_err()
        .to_string();
    assert!(msg.starts_with("root: nesting deeper than 256"), "{msg}");
    let empty = CsgNode::union(vec![CsgNode::difference(Vec::new())]);
    let msg = evaluate_csg(&empty, CsgOptions::default())
        .unwrap_err()
        .to_string();
    assert_eq!(msg, "children[0]: an operation needs at least one child");
    let bad = CsgNode::union(vec![
        CsgNode::cuboid([1.0; 3], false),
        CsgNode::sphere(1.0, 2),
    ]);
    let msg = evaluate_csg(&bad, CsgOptions::default())
        .unwrap_err()
        .to_string();
    assert_eq!(msg, "children[1]: sphere.segments must be >= 3");
    let nan = CsgNode::cuboid([1.0; 3], false).translated([f64::NAN, 0.0, 0.0]);
    assert!(evaluate_csg(&nan, CsgOptions::default()).is_err());
    let flat = CsgNode::cuboid([1.0; 3], false).scaled(umbra::Scale::Axes([1.0, 0.0, 1.0]));
    let msg = evaluate_csg(&flat, CsgOptions::default())
        .unwrap_err()
        .to_string();
    assert!(msg.contains("invertible"), "{msg}");
}

/// The exact volume of an operation on integer boxes by a grid oracle: the
/// distinct coordinates cut space into cells, each wholly in or out.
fn grid_volume(boxes: &[([i32; 3], [i32; 3])], op: &str) -> f64 {
    let mut cuts: [Vec<i32>; 3] = Default::default();
    for (lo, hi) in boxes {
        for k in 0..3 {
            cuts[k].push(lo[k]);
            cuts[k].push(hi[k]);
        }
    }
    for c in &mut cuts {
        c.sort_unstable();
        c.dedup();
    }
    let mut total = 0i64;
    for x in cuts[0].windows(2) {
        for y in cuts[1].windows(2) {
            for z in cuts[2].windows(2) {
                let c = [x[0] + x[1], y[0] + y[1], z[0] + z[1]]; // twice the centre
                let inside: Vec<bool> = boxes
                    .iter()
                    .map(|(lo, hi)| (0..3).all(|k| 2 * lo[k] < c[k] && c[k] < 2 * hi[k]))
                    .collect();
                let keep = match op {
                    "union" => inside.iter().any(|&b| b),
                    "intersection" => inside.iter().all(|&b| b),
                    _ => inside[0] && !inside[1..].iter().any(|&b| b),
                };
                if keep {
                    total += i64::from((x[1] - x[0]) * (y[1] - y[0]) * (z[1] - z[0]));
                }
            }
        }
    }
    total as f64
}

proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig::with_cases(test_support::cases(48)))]

    #[test]
    fn random_box_operations_match_the_grid_oracle(
        raw in proptest::collection::vec((proptest::array::uniform3(0i32..6), proptest::array::uniform3(1i32..5)), 1..6),
        which in 0usize..3,
    ) {
        let op = ["union", "intersection", "difference"][which];
        let boxes: Vec<([i32; 3], [i32; 3])> = raw
            .iter()
            .map(|(o, s)| (*o, [o[0] + s[0], o[1] + s[1], o[2] + s[2]]))
            .collect();
        let children: Vec<String> = boxes
            .iter()
            .map(|(lo, hi)| {
                format!(
                    r#"{{"box": {{"size": [{}, {}, {}]}}, "translate": [{}, {}, {}]}}"#,
                    hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2], lo[0], lo[1], lo[2]
                )
            })
            .collect();
        let script = format!(r#"{{"op": "{op}", "children": [{}]}}"#, children.join(","));
        let tree = parse_csg(&script).unwrap();
        for triangulate in [false, true] {
            let out = evaluate_csg(&tree, CsgOptions { triangulate, contacts: None, raw_intermediates: false }).unwrap();
            proptest::prop_assert!(out.report.topologically_valid);
            // Intersection points are interpolated in f64 (eq. 4.2-4.6), so
            // the volume may differ from the exact one in the last bits.
            let want = grid_volume(&boxes, op);
            let got = out.report.volume;
            proptest::prop_assert!((got - want).abs() <= 1e-12 * want.max(1.0), "{} vs {}", got, want);
        }
    }
}
