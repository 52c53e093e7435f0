//! End-to-end tests of the `umbra` binary on 3D meshes (OBJ, OFF: Booleans
//! in both variants with exact volumes, `check` with manifoldness,
//! self-intersection and volume, bad input) and on 2D simplification
//! (`simplify` with every fill rule, `boolean --via simplify`, GeoJSON).
//!
//! Volumes and areas of output files are computed here by independent
//! minimal readers, not by the library under test.

use crate::common::{examples, json, stderr, temp_dir, umbra, write};
use std::path::Path;
use std::process::Output;

/// Vertices and faces of an OBJ or OFF file (independent reader for the
/// files umbra writes: plain `v`/`f` lines or a plain OFF body).
fn read_mesh(path: &Path) -> (Vec<[f64; 3]>, Vec<Vec<usize>>) {
    let text = std::fs::read_to_string(path).unwrap();
    let mut v = Vec::new();
    let mut f = Vec::new();
    if text.starts_with("OFF") {
        let mut lines = text.lines().skip(1).filter(|l| !l.starts_with('#'));
        let counts: Vec<usize> = lines
            .next()
            .unwrap()
            .split_whitespace()
            .map(|t| t.parse().unwrap())
            .collect();
        for _ in 0..counts[0] {
            let p: Vec<f64> = lines
                .next()
                .unwrap()
                .split_whitespace()
                .map(|t| t.parse().unwrap())
                .collect();
            v.push([p[0], p[1], p[2]]);
        }
        for _ in 0..counts[1] {
            let q: Vec<usize> = lines
                .next()
                .unwrap()
                .split_whitespace()
                .map(|t| t.parse().unwrap())
                .collect();
            f.push(q[1..].to_vec());
        }
    } else {
        for line in text.lines() {
            let t: Vec<&str> = line.split_whitespace().collect();
            match t.first() {
                Some(&"v") => v.push([t[1], t[2], t[3]].map(|s| s.parse().unwrap())),
                Some(&"f") => f.push(
                    t[1..]
                        .iter()
                        .map(|s| s.parse::<usize>().unwrap() - 1)
                        .collect(),
                ),
                _ => {}
            }
        }
    }
    (v, f)
}

/// Signed volume by the divergence theorem over fan triangles.
fn volume(path: &Path) -> f64 {
    let (v, f) = read_mesh(path);
    let mut six = 0.0;
    for face in &f {
        let a = v[face[0]];
        for k in 1..face.len() - 1 {
            let (b, c) = (v[face[k]], v[face[k + 1]]);
            six += a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0])
                + a[2] * (b[0] * c[1] - b[1] * c[0]);
        }
    }
    six / 6.0
}

/// Every directed edge has its reverse exactly as often (shape boundary
/// closure of a closed mesh, section 4.2).
fn closed(path: &Path) -> bool {
    let (_, f) = read_mesh(path);
    let mut count = std::collections::HashMap::new();
    for face in &f {
        for k in 0..face.len() {
            let (a, b) = (face[k], face[(k + 1) % face.len()]);
            *count.entry((a, b)).or_insert(0i64) += 1;
            *count.entry((b, a)).or_insert(0i64) -= 1;
        }
    }
    count.values().all(|&c| c == 0)
}

/// Runs `umbra boolean OP A B -o OUT --report REPORT [--triangulate]`.
fn boolean(op: &str, a: &Path, b: &Path, out: &Path, report: &Path, triangulate: bool) -> Output {
    let mut args = vec![
        "boolean".to_string(),
        op.to_string(),
        a.display().to_string(),
        b.display().to_string(),
        "-o".into(),
        out.display().to_string(),
        "--report".into(),
        report.display().to_string(),
    ];
    if triangulate {
        args.push("--triangulate".into());
    }
    umbra(&args)
}

#[test]
fn cube_booleans_in_both_variants_and_formats() {
    let dir = temp_dir("cubes");
    let a = examples().join("cube.obj");
    let b = examples().join("cube_shifted.off");
    // Cubes of volume 8 overlapping in a unit cube.
    for (op, want) in [("union", 15.0), ("intersection", 1.0), ("difference", 7.0)] {
        for (ext, tri) in [("obj", false), ("off", false), ("obj", true), ("off", true)] {
            let out = dir.join(format!("{op}-{tri}.{ext}"));
            let report = dir.join(format!("{op}-{tri}-{ext}.json"));
            let o = boolean(op, &a, &b, &out, &report, tri);
            assert!(o.status.success(), "{op}: {}", stderr(&o));
            assert_eq!(volume(&out), want, "{op} {ext} triangulate={tri}");
            assert!(closed(&out), "{op}: output not closed");
            if tri {
                assert!(read_mesh(&out).1.iter().all(|f| f.len() == 3));
            }
            let r = json(&report);
            assert_eq!(r["topologically_valid"], true);
            assert_eq!(r["output"]["signed_volume"], want);
            assert!(r["timings_ms"]["total"].as_f64().unwrap() >= 0.0);
            // The six edges of each cube that cross the other cube's faces;
            // the triangle variant runs on the triangulated quads, whose
            // diagonals add crossings of their own.
            let hits = r["intersections"].as_u64().unwrap();
            if tri {
                assert_eq!(r["variant"], "triangle mesh");
                assert!(hits >= 6, "{hits}");
            } else {
                assert_eq!(r["variant"], "polygon mesh");
                assert_eq!(hits, 6);
            }
        }
    }
    // A op A: union and intersection keep the volume, difference empties.
    for (op, want) in [("union", 8.0), ("intersection", 8.0), ("difference", 0.0)] {
        let out = dir.join(format!("self-{op}.off"));
        let o = umbra([
            "boolean",
            op,
            a.to_str().unwrap(),
            a.to_str().unwrap(),
            "-o",
            out.to_str().unwrap(),
        ]);
        assert!(o.status.success(), "{}", stderr(&o));
        assert_eq!(volume(&out), want, "A {op} A");
    }
}

#[test]
fn inward_facing_operands_are_turned_outward_unless_kept() {
    // cube_shifted.off written with every face reversed, as exporters with
    // the opposite convention write solids: signed volume -8.
    let dir = temp_dir("inward");
    let (v, f) = read_mesh(&examples().join("cube_shifted.off"));
    let reversed: Vec<Vec<usize>> = f
        .iter()
        .map(|q| q.iter().rev().copied().collect())
        .collect();
    let inward = write(&dir, "inward.obj", &obj_text(&v, &reversed));
    assert_eq!(volume(&inward), -8.0);
    let a = examples().join("cube.obj");
    for (op, want) in [("union", 15.0), ("intersection", 1.0), ("difference", 7.0)] {
        let out = dir.join(format!("{op}.obj"));
        let report = dir.join(format!("{op}.json"));
        let o = boolean(op, &a, &inward, &out, &report, false);
        assert!(o.status.success(), "{op}: {}", stderr(&o));
        let err = stderr(&o);
        assert!(
            err.contains("warning") && err.contains("inward.obj") && err.contains("face inward"),
            "{err}"
        );
        // The Boolean of the solid the file describes.
        assert_eq!(volume(&out), want, "{op}");
        assert!(closed(&out));
        // Kept as written: the inside-out operand of section 4.7 (all of
        // space but the cube), no warning, and a different solid.
        let kept = dir.join(format!("{op}-kept.obj"));
        let o = umbra([
            "boolean",
            op,
            a.to_str().unwrap(),
            inward.to_str().unwrap(),
            "-o",
            kept.to_str().unwrap(),
            "--keep-orientation",
        ]);
        assert!(o.status.success(), "{op}: {}", stderr(&o));
        assert!(!stderr(&o).contains("warning"), "{}", stderr(&o));
        assert!(closed(&kept));
        // As written, the cube's inside has winding number -1, which no
        // operation counts as inside: the union keeps all of A and the
        // cube's facets outside A as they face (8 - 7), the intersection
        // the cube's facets inside A (-1), the difference all of A and
        // the cube's facets inside A turned over (8 + 1).
        let as_written = match op {
            "union" => 1.0,
            "intersection" => -1.0,
            _ => 9.0,
        };
        assert_eq!(volume(&kept), as_written, "{op} kept");
    }
    // An outward operand is never touched: no warning.
    let out = dir.join("plain.obj");
    let b = examples().join("cube_shifted.off");
    let o = boolean("union", &a, &b, &out, &dir.join("plain.json"), false);
    assert!(o.status.success() && !stderr(&o).contains("warning"));
}

/// OBJ text of vertices and faces (1-based references).
fn obj_text(v: &[[f64; 3]], f: &[Vec<usize>]) -> String {
    let mut text = String::new();
    for p in v {
        text += &format!("v {} {} {}\n", p[0], p[1], p[2]);
    }
    for q in f {
        text += "f";
        for k in q {
            text += &format!(" {}", k + 1);
        }
        text += "\n";
    }
    text
}

#[test]
fn triangulate_runs_the_triangle_variant_on_quad_input() {
    let dir = temp_dir("tri");
    let a = examples().join("cube.obj");
    let b = examples().join("cube_shifted.off");
    assert!(read_mesh(&a).1.iter().all(|f| f.len() == 4));
    assert!(read_mesh(&b).1.iter().all(|f| f.len() == 4));
    let run = |op: &str, x: &Path, y: &Path, tag: &str, tri: bool| {
        let out = dir.join(format!("{op}-{tag}.obj"));
        let report = dir.join(format!("{op}-{tag}.json"));
        let o = boolean(op, x, y, &out, &report, tri);
        assert!(o.status.success(), "{op} {tag}: {}", stderr(&o));
        (out, json(&report))
    };
    for (op, want) in [("union", 15.0), ("intersection", 1.0), ("difference", 7.0)] {
        // Without --triangulate the polygon variant keeps quads.
        let (out, r) = run(op, &a, &b, "poly", false);
        assert_eq!(r["variant"], "polygon mesh");
        assert_eq!(r["inputs_triangulated"]["a"], false);
        assert!(read_mesh(&out).1.iter().any(|f| f.len() == 4), "{op}");
        // With it, the quads are triangulated and the triangle variant
        // runs: triangles only, closed, the exact volume.
        let (out, r) = run(op, &a, &b, "tri", true);
        assert_eq!(r["variant"], "triangle mesh", "{op}");
        assert_eq!(r["inputs_triangulated"]["a"], true);
        assert_eq!(r["inputs_triangulated"]["b"], true);
        assert!(r["timings_ms"]["triangulate_inputs"].as_f64().unwrap() >= 0.0);
        assert!(
            r["timings_ms"]["total"].as_f64().unwrap()
                >= r["timings_ms"]["triangulate_inputs"].as_f64().unwrap()
        );
        let (_, faces) = read_mesh(&out);
        assert!(faces.iter().all(|f| f.len() == 3), "{op}");
        assert_eq!(r["output"]["facets"], faces.len());
        assert!(closed(&out), "{op}");
        assert_eq!(volume(&out), want, "{op}");
        assert_eq!(r["topologically_valid"], true);
        // The result is a valid solid: 2-manifold, no self-intersection.
        let o = umbra(["check", out.to_str().unwrap(), "--json"]);
        assert!(o.status.success(), "{}", stderr(&o));
        let c: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
        assert_eq!(c["two_manifold"], true, "{op}");
        assert_eq!(c["self_intersecting_facet_pairs"], 0, "{op}");
        assert_eq!(c["signed_volume"], want, "{op}");
    }
    // Triangle operands go to the triangle variant as they are.
    let (v, f) = read_mesh(&a);
    let tris: Vec<Vec<usize>> = f
        .iter()
        .flat_map(|q| [vec![q[0], q[1], q[2]], vec![q[0], q[2], q[3]]])
        .collect();
    let ta = write(&dir, "cube_tri.obj", &obj_text(&v, &tris));
    let (out, r) = run("union", &ta, &ta, "self", true);
    assert_eq!(r["variant"], "triangle mesh");
    assert_eq!(r["inputs_triangulated"]["a"], false);
    assert_eq!(r["inputs_triangulated"]["b"], false);
    assert_eq!(volume(&out), 8.0);
}

#[test]
fn check_reports_manifold_self_intersections_and_volume() {
    let dir = temp_dir("check");
    let o = umbra([
        "check",
        examples().join("cube.obj").to_str().unwrap(),
        "--json",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let r: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(r["topologically_valid"], true);
    assert_eq!(r["two_manifold"], true);
    assert_eq!(r["self_intersecting_facet_pairs"], 0);
    assert_eq!(r["signed_volume"], 8.0);
    // Both cubes in one file: valid, 2-manifold (two shells), 6 crossing
    // facet pairs, volume 16 (the overlap counted twice).
    let (mut v, mut f) = read_mesh(&examples().join("cube.obj"));
    let (v2, f2) = read_mesh(&examples().join("cube_shifted.off"));
    let n = v.len();
    v.extend(v2);
    f.extend(
        f2.into_iter()
            .map(|q| q.into_iter().map(|k| k + n).collect::<Vec<_>>()),
    );
    let both = write(&dir, "both.obj", &obj_text(&v, &f));
    let o = umbra(["check", both.to_str().unwrap(), "--json"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let r: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(r["self_intersecting_facet_pairs"], 6);
    assert_eq!(r["signed_volume"], 16.0);
    assert_eq!(r["two_manifold"], true);
    // Human-readable output names the facts.
    let o = umbra(["check", both.to_str().unwrap()]);
    let s = String::from_utf8_lossy(&o.stdout);
    assert!(s.contains("self-intersecting facet pairs: 6"), "{s}");
}

#[test]
fn bad_meshes_exit_1_naming_file_and_constraint() {
    let dir = temp_dir("bad");
    let good = examples().join("cube.obj");
    // (file, contents, a phrase the one-line message must hold).
    let cases = [
        (
            "open.off",
            "OFF\n4 1 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n",
            "closure",
        ),
        (
            "dangling.off",
            "OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 2 9\n",
            "9",
        ),
        // OBJ reference 9 is vertex 8 counted from 0, of 3: `boolean` and
        // `check` both name it in the file's 1-based terms, with its line.
        (
            "dangling.obj",
            "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 3 9\n",
            "face 2 (line 5) refers to vertex 9, but there are only 3 vertices",
        ),
        (
            "dangling_relative.obj",
            "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 3 -7\n",
            "line 5: vertex reference -7 is out of range",
        ),
        (
            "nan.obj",
            "v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\nf 1 3 2\n",
            "NaN",
        ),
        (
            "nan_spelled.obj",
            "v 0 0 0\nv 1 NaN 0\nv 0 1 0\nf 1 2 3\nf 1 3 2\n",
            "y coordinate NaN is not finite",
        ),
        (
            "inf.obj",
            "v 0 0 0\nv inf 0 0\nv 0 1 0\nf 1 2 3\nf 1 3 2\n",
            "not finite",
        ),
        (
            "truncated.off",
            "OFF\n8 6 0\n0 0 0\n1 0 0\n",
            "truncated: expected 8 vertices, found 2",
        ),
        (
            "truncated_faces.off",
            "OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
            "truncated: expected 2 faces, found 1",
        ),
        ("garbage.obj", "v 1 2 three\n", "not a number"),
        ("empty.off", "", "empty"),
        // Valid UTF-8 with control bytes: binary data, not an OBJ whose
        // unknown statements could be skipped.
        (
            "binary.obj",
            "v 0 0 0\n\u{0}\u{1}\u{2}\n",
            "line 2: binary data (control byte 0x00)",
        ),
    ];
    let one_line_naming = |o: &Output, name: &str, want: &str| {
        let e = stderr(o);
        assert_eq!(o.status.code(), Some(1), "{name}: {e}");
        assert!(e.contains(name) && e.contains(want), "{name}: {e}");
        assert_eq!(e.trim().lines().count(), 1, "{name}: {e}");
        assert!(
            !e.contains("internal error") && !e.contains("panicked"),
            "{name}: {e}"
        );
    };
    for (name, text, want) in cases {
        let bad = write(&dir, name, text);
        let out = dir.join("out.obj");
        for (x, y) in [(&bad, &good), (&good, &bad)] {
            let o = umbra([
                "boolean",
                "union",
                x.to_str().unwrap(),
                y.to_str().unwrap(),
                "-o",
                out.to_str().unwrap(),
            ]);
            one_line_naming(&o, name, want);
        }
        let o = umbra(["check", bad.to_str().unwrap()]);
        one_line_naming(&o, name, want);
        let o = umbra(["check", bad.to_str().unwrap(), "--json"]);
        one_line_naming(&o, name, want);
    }
    let missing = dir.join("missing.off");
    let o = umbra(["check", missing.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(1));
    assert!(stderr(&o).contains("missing.off"));
}

#[test]
fn usage_errors_exit_2() {
    let a = examples().join("cube.obj");
    let w = examples().join("a.wkt");
    let runs: [&[&str]; 3] = [
        &[
            "boolean",
            "union",
            a.to_str().unwrap(),
            w.to_str().unwrap(),
            "-o",
            "x.obj",
        ],
        &[
            "boolean",
            "xor",
            a.to_str().unwrap(),
            a.to_str().unwrap(),
            "-o",
            "x.obj",
        ],
        &[
            "boolean",
            "union",
            w.to_str().unwrap(),
            w.to_str().unwrap(),
            "-o",
            "x.wkt",
            "--triangulate",
        ],
    ];
    for args in runs {
        let o = umbra(args);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {}", stderr(&o));
    }
}

/// Area by the shoelace formula over every ring of a GeoJSON geometry as
/// written (independent reader).
fn geojson_area(path: &Path) -> f64 {
    let v = json(path);
    let polys: Vec<serde_json::Value> = match v["type"].as_str().unwrap() {
        "Polygon" => vec![v["coordinates"].clone()],
        _ => v["coordinates"].as_array().unwrap().clone(),
    };
    let mut area = 0.0;
    for p in &polys {
        for ring in p.as_array().unwrap() {
            let pts: Vec<[f64; 2]> = ring
                .as_array()
                .unwrap()
                .iter()
                .map(|q| [q[0].as_f64().unwrap(), q[1].as_f64().unwrap()])
                .collect();
            for k in 0..pts.len() - 1 {
                area += pts[k][0] * pts[k + 1][1] - pts[k + 1][0] * pts[k][1];
            }
        }
    }
    area / 2.0
}

#[test]
fn simplify_figure_eight_by_every_rule() {
    // The bow tie (0 0, 4 4, 4 0, 0 4): two triangles of area 4 meeting at
    // (2, 2), winding +1 in one and -1 in the other when read as written.
    let dir = temp_dir("simplify");
    let input = write(&dir, "bowtie.wkt", "POLYGON ((0 0, 4 4, 4 0, 0 4, 0 0))\n");
    for (rule, area) in [
        ("positive", 4.0),
        ("nonzero", 8.0),
        ("evenodd", 8.0),
        ("negative", 4.0),
        ("at-least-2", 0.0),
    ] {
        let out = dir.join(format!("{rule}.geojson"));
        let report = dir.join(format!("{rule}.json"));
        let o = umbra([
            "simplify",
            input.to_str().unwrap(),
            "-o",
            out.to_str().unwrap(),
            "--rule",
            rule,
            "--keep-orientation",
            "--report",
            report.to_str().unwrap(),
        ]);
        assert!(o.status.success(), "{rule}: {}", stderr(&o));
        let got = geojson_area(&out);
        // The selected cells lie on the left of the output edges (section
        // 7.4.3), so even the negative rule's inside-out lobe comes out
        // counter-clockwise.
        assert_eq!(got, area, "{rule}");
        let r = json(&report);
        assert_eq!(r["topologically_valid"], true);
        assert!(r["epsilon"].as_f64().unwrap() > 0.0);
        assert!(r["k_max"].as_u64().is_some());
        assert!(r["timings_ms"]["total"].as_f64().is_some());
    }
}

#[test]
fn booleans_via_simplify_agree_with_the_basic_boolean() {
    let dir = temp_dir("via");
    let a = examples().join("a.wkt");
    let b = examples().join("b.wkt");
    let mut areas = std::collections::HashMap::new();
    for op in ["union", "intersection", "difference", "xor"] {
        for via in ["basic", "simplify"] {
            let out = dir.join(format!("{op}-{via}.geojson"));
            let report = dir.join(format!("{op}-{via}.json"));
            let o = umbra([
                "boolean",
                op,
                a.to_str().unwrap(),
                b.to_str().unwrap(),
                "-o",
                out.to_str().unwrap(),
                "--via",
                via,
                "--report",
                report.to_str().unwrap(),
            ]);
            assert!(o.status.success(), "{op} {via}: {}", stderr(&o));
            areas.insert((op, via), geojson_area(&out));
        }
    }
    for op in ["union", "intersection", "difference", "xor"] {
        let (x, y) = (areas[&(op, "basic")], areas[&(op, "simplify")]);
        assert!((x - y).abs() < 1e-9, "{op}: {x} vs {y}");
    }
    let xor = areas[&("xor", "simplify")];
    let want = areas[&("union", "basic")] - areas[&("intersection", "basic")];
    assert!((xor - want).abs() < 1e-9, "xor {xor} vs {want}");
}

#[test]
fn invalid_operands_read_by_role_get_set_semantics_in_both_algorithms() {
    // Files a GIS user has: a square given twice in one multipolygon, a
    // polygon whose two holes overlap, a hole outside its shell. As sets
    // (shapely's make_valid, the Boolean through simplification): areas
    // 100, 100 - 28 and 100. The basic Boolean on the rings as read counted
    // the doubled square twice (its union with itself was empty) and the
    // overlapping holes' -1 as inside.
    let dir = temp_dir("invalid-sets");
    let sq = "(0 0, 10 0, 10 10, 0 10, 0 0)";
    let cases = [
        ("twice", format!("MULTIPOLYGON (({sq}), ({sq}))"), 100.0),
        (
            "holes",
            format!("POLYGON ({sq}, (2 2, 2 6, 6 6, 6 2, 2 2), (4 4, 4 8, 8 8, 8 4, 4 4))"),
            72.0,
        ),
        (
            "stray",
            format!("POLYGON ({sq}, (20 20, 20 21, 21 21, 21 20, 20 20))"),
            100.0,
        ),
    ];
    for (name, text, area) in cases {
        let input = write(&dir, &format!("{name}.wkt"), &format!("{text}\n"));
        for op in ["union", "intersection"] {
            for via in ["basic", "simplify"] {
                let out = dir.join(format!("{name}-{op}-{via}.geojson"));
                let o = umbra([
                    "boolean",
                    op,
                    input.to_str().unwrap(),
                    input.to_str().unwrap(),
                    "-o",
                    out.to_str().unwrap(),
                    "--via",
                    via,
                ]);
                assert!(o.status.success(), "{name} {op} {via}: {}", stderr(&o));
                let got = geojson_area(&out);
                assert!((got - area).abs() < 1e-9, "{name} {op} {via}: {got}");
            }
        }
    }
}

#[test]
fn geojson_round_trip_and_bad_geojson() {
    let dir = temp_dir("geojson");
    let out = dir.join("copy.geojson");
    let o = umbra([
        "simplify",
        examples().join("a.geojson").to_str().unwrap(),
        "-o",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert_eq!(geojson_area(&out), 12.0);
    for (name, text, want) in [
        (
            "trunc.geojson",
            "{\"type\": \"Polygon\", \"coordinates\": [[[0, 0], [1,",
            "malformed GeoJSON",
        ),
        (
            "line.geojson",
            "{\"type\": \"LineString\", \"coordinates\": [[0, 0], [1, 1]]}",
            "LineString",
        ),
        ("nocoords.geojson", "{\"type\": \"Polygon\"}", "coordinates"),
    ] {
        let bad = write(&dir, name, text);
        let o = umbra([
            "simplify",
            bad.to_str().unwrap(),
            "-o",
            out.to_str().unwrap(),
        ]);
        assert_eq!(o.status.code(), Some(1), "{name}");
        let e = stderr(&o);
        assert!(e.contains(name) && e.contains(want), "{e}");
    }
}
