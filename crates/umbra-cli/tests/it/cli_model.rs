//! End-to-end tests of `umbra csg` and `umbra demo`: every shipped script
//! evaluates to a valid closed solid whose report agrees with an
//! independent volume of the written OBJ, bad scripts exit 1 with one line
//! naming the script and the node, a destination that is the script is
//! refused, and the demo writes a valid model and its script, which `umbra
//! csg` reproduces bit for bit.

use crate::common::{examples, json, stderr, temp_dir, umbra, write};
use std::path::Path;

/// `check --json` of `path`, parsed (the file as a reader sees it).
fn check_json(path: &Path) -> serde_json::Value {
    let c = umbra(["check".as_ref(), path.as_os_str(), "--json".as_ref()]);
    assert!(c.status.success(), "{}", stderr(&c));
    serde_json::from_slice(&c.stdout).unwrap()
}

/// The faces of an OBJ file (its `f` lines), counted by hand.
fn obj_faces(path: &Path) -> usize {
    let text = std::fs::read_to_string(path).unwrap();
    text.lines().filter(|l| l.starts_with("f ")).count()
}

/// The 2-manifoldness fields, which `umbra csg --report` and `umbra check
/// --json` share.
const MANIFOLD: [&str; 4] = [
    "two_manifold",
    "open_edges",
    "non_manifold_edges",
    "non_manifold_vertices",
];

/// Two unit cubes sharing the edge x = y = 1. The Boolean leaves two
/// closed shells with coincident vertices at the edge's ends; welding
/// them (smoothing) would give the shared edge two half-edges each way, a
/// non-manifold edge the shells did not have, so the guard undoes it; an
/// ASCII STL is welded by position on reading, which makes that edge.
const EDGE_SHARING_CUBES: &str = r#"{"op": "union", "children": [
    {"box": {"size": [1, 1, 1]}},
    {"box": {"size": [1, 1, 1]}, "translate": [1, 1, 0]}]}"#;

/// A union of touching parts whose raw triangle-variant result has
/// non-manifold edges (the CSG report counted 1 of them, `umbra check` 3).
const TOUCHING_PARTS: &str = r#"{"op": "union", "children": [
    {"box": {"size": [1, 1.5, 1.5]}, "translate": [0, 2, 2]},
    {"cylinder": {"radius": 1, "height": 1, "segments": 8}, "translate": [2, 2, 0]},
    {"cylinder": {"radius": 0.5, "height": 1, "segments": 8}, "translate": [0.5, 2, 1.5]},
    {"box": {"size": [0.5, 0.5, 0.5]}, "translate": [1, 2, 0]}]}"#;

/// The CSG report and `umbra check` of the file written state the same
/// 2-manifoldness (one census: open edges, non-manifold edges and
/// vertices) and the same counts, on a clean solid and on results with
/// non-manifold edges, for OBJ (facets with holes written as triangles)
/// and ASCII STL (triangles welded by position on reading).
#[test]
fn csg_report_and_check_agree_on_the_file_written() {
    let dir = temp_dir("agree");
    let edge = write(&dir, "edge.json", EDGE_SHARING_CUBES);
    let touching = write(&dir, "touching.json", TOUCHING_PARTS);
    let bracket = examples().join("bracket.json");
    let cases: [(&Path, &[&str], &str); 6] = [
        (&bracket, &[], "obj"),
        (&bracket, &["--ascii"], "stl"),
        (&edge, &[], "obj"),
        (&edge, &["--smooth", "0", "--ascii"], "stl"),
        (&touching, &["--triangulate", "--smooth", "0"], "obj"),
        (&touching, &["--smooth", "0", "--ascii"], "stl"),
    ];
    for (script, extra, ext) in cases {
        let what = format!("{} {extra:?} .{ext}", script.display());
        let out = dir.join(format!("out.{ext}"));
        let report = dir.join("r.json");
        let mut args = vec![
            "csg",
            script.to_str().unwrap(),
            "-o",
            out.to_str().unwrap(),
            "--report",
            report.to_str().unwrap(),
            "--quiet",
        ];
        args.extend(extra);
        let o = umbra(&args);
        assert!(o.status.success(), "{what}: {}", stderr(&o));
        let r = json(&report);
        let c = check_json(&out);
        for key in MANIFOLD.iter().chain(&["vertices", "facets", "half_edges"]) {
            assert_eq!(r[key], c[key], "{what}: {key}");
        }
        if ext == "obj" {
            assert_eq!(r["facets"].as_u64(), Some(obj_faces(&out) as u64), "{what}");
        }
        let shells = script == edge.as_path() && ext == "obj";
        let clean = script == bracket.as_path() || shells;
        assert_eq!(r["two_manifold"], clean, "{what}");
        if shells {
            // Smoothed by default, and the weld undone by the guard: two
            // cubes of 8 vertices and 6 facets each, both closed
            // 2-manifolds, and the report says what was undone.
            assert_eq!(r["vertices"], 16, "{what}");
            assert_eq!(r["facets"], 12, "{what}");
            assert_eq!(r["non_manifold_edges"], 0, "{what}");
            let undone = &r["smoothing"]["reverted"];
            assert_eq!(undone["smoothed"]["non_manifold_edges"], 1, "{what}");
            assert_eq!(undone["input"]["non_manifold_edges"], 0, "{what}");
        } else if script == edge.as_path() {
            // As an STL, welded on reading: 8 + 8 - 2 vertices and twelve
            // triangles on them, the shared edge non-manifold.
            assert_eq!(r["vertices"], 14, "{what}");
            assert_eq!(r["facets"], 24, "{what}");
            assert_eq!(r["open_edges"], 0, "{what}");
            assert_eq!(r["non_manifold_edges"], 1, "{what}");
        }
        if script == touching.as_path() {
            assert!(r["non_manifold_edges"].as_u64() > Some(1), "{what}");
        }
    }
}

/// The signed volume of an OBJ file by an independent reader: `v` lines
/// and `f` lines (1-based, `i/t/n` forms), each face fanned from its first
/// vertex (the divergence theorem; exact for planar faces).
fn obj_volume(path: &Path) -> f64 {
    let text = std::fs::read_to_string(path).unwrap();
    let mut v: Vec<[f64; 3]> = Vec::new();
    let mut vol = 0.0;
    for line in text.lines() {
        let mut w = line.split_whitespace();
        match w.next() {
            Some("v") => {
                let c: Vec<f64> = w.take(3).map(|x| x.parse().unwrap()).collect();
                v.push([c[0], c[1], c[2]]);
            }
            Some("f") => {
                let idx: Vec<usize> = w
                    .map(|t| t.split('/').next().unwrap().parse::<usize>().unwrap() - 1)
                    .collect();
                for k in 1..idx.len() - 1 {
                    let (a, b, c) = (v[idx[0]], v[idx[k]], v[idx[k + 1]]);
                    vol += (a[0] * (b[1] * c[2] - b[2] * c[1])
                        - a[1] * (b[0] * c[2] - b[2] * c[0])
                        + a[2] * (b[0] * c[1] - b[1] * c[0]))
                        / 6.0;
                }
            }
            _ => {}
        }
    }
    vol
}

#[test]
fn every_shipped_script_gives_a_valid_solid_and_a_report() {
    let dir = temp_dir("scripts");
    let mut scripts = 0;
    for entry in std::fs::read_dir(examples()).unwrap() {
        let script = entry.unwrap().path();
        if script.extension().and_then(|e| e.to_str()) != Some("json") {
            continue;
        }
        scripts += 1;
        for triangulate in [false, true] {
            let out = dir.join("out.obj");
            let report = dir.join("r.json");
            let mut args = vec![
                "csg".to_string(),
                script.display().to_string(),
                "-o".into(),
                out.display().to_string(),
                "--report".into(),
                report.display().to_string(),
                "--quiet".into(),
            ];
            if triangulate {
                args.push("--triangulate".into());
            }
            let o = umbra(&args);
            assert!(o.status.success(), "{}: {}", script.display(), stderr(&o));
            assert!(o.stdout.is_empty(), "--quiet prints nothing");
            let r = json(&report);
            assert_eq!(r["topologically_valid"], true, "{}", script.display());
            assert!(r["timings_ms"]["total"].as_f64().unwrap() >= 0.0);
            assert_eq!(
                r["variant"],
                if triangulate { "triangle" } else { "polygon" }
            );
            let want = r["volume"].as_f64().unwrap();
            let got = obj_volume(&out);
            assert!(want > 0.0, "{}", script.display());
            assert!(
                (got - want).abs() <= 1e-9 * want,
                "{}: OBJ volume {got} vs report {want}",
                script.display()
            );
            let check = umbra(["check", out.to_str().unwrap()]);
            assert!(check.status.success(), "{}", stderr(&check));
        }
    }
    assert!(scripts >= 3, "examples/*.json");
}

#[test]
fn bad_scripts_exit_1_with_one_line_naming_the_script_and_node() {
    let dir = temp_dir("bad");
    let cases = [
        (
            r#"{"op": "union", "children": [{"sphere": {"radius": 1, "segments": 2}}]}"#,
            "segments",
        ),
        (r#"{"op": "nand", "children": []}"#, "op"),
        (r#"{"box": {"size": [1, 1]}}"#, "size"),
        (
            r#"{"op": "union", "children": [{"file": "missing.stl"}]}"#,
            "missing.stl",
        ),
        ("{\"box\": ", "script.json"),
        ("", "script.json"),
        // Errors of the evaluation (not of the script's form) name the
        // script too, then the node.
        (
            r#"{"box": {"size": [1, 1, 1]}, "translate": [1e308, 0, 0]}"#,
            "script.json: root: transform moves",
        ),
        (
            r#"{"box": {"size": [1, 1, 1]}, "scale": 1e-300}"#,
            "script.json: root: transform must be invertible (determinant 0: a zero scale",
        ),
        (
            r#"{"op": "union", "children": [{"box": {"size": [1, 1, 1]}}, {"file": "missing.stl"}]}"#,
            "script.json: children[1]",
        ),
    ];
    for (text, needle) in cases {
        let script = dir.join("script.json");
        std::fs::write(&script, text).unwrap();
        let out = dir.join("o.obj");
        let o = umbra(["csg", script.to_str().unwrap(), "-o", out.to_str().unwrap()]);
        assert_eq!(o.status.code(), Some(1), "{text}: {}", stderr(&o));
        let e = stderr(&o);
        assert_eq!(e.trim_end().lines().count(), 1, "{text}: {e}");
        assert!(e.contains(needle), "{text}: {e}");
        assert!(!out.exists(), "nothing written on error");
    }
    // A script that is not there: the cause said once.
    let o = umbra([
        "csg",
        dir.join("nothere.json").to_str().unwrap(),
        "-o",
        dir.join("o.obj").to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(1));
    let e = stderr(&o);
    assert!(e.contains("nothere.json: cannot read"), "{e}");
    assert_eq!(e.matches("os error").count(), 1, "{e}");
}

#[test]
fn a_destination_that_is_the_script_is_refused() {
    let dir = temp_dir("clobber");
    let script = dir.join("s.json");
    std::fs::copy(examples().join("bracket.json"), &script).unwrap();
    let before = std::fs::read(&script).unwrap();
    let o = umbra([
        "csg",
        script.to_str().unwrap(),
        "-o",
        "x.obj",
        "--report",
        script.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert_eq!(std::fs::read(&script).unwrap(), before);
}

#[test]
fn the_demo_writes_a_valid_model_that_its_script_reproduces() {
    let dir = temp_dir("demo");
    let o = umbra(["demo", "-o", dir.to_str().unwrap(), "--quiet"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = String::from_utf8_lossy(&o.stdout);
    assert!(text.contains("topologically valid: yes"), "{text}");
    let report = json(&dir.join("report.json"));
    assert_eq!(report["topologically_valid"], true);
    assert!(
        report["booleans"].as_u64().unwrap() >= 100,
        "some hundreds of Booleans"
    );
    let volume = report["volume"].as_f64().unwrap();
    let obj = dir.join("plant.obj");
    assert!((obj_volume(&obj) - volume).abs() <= 1e-9 * volume);
    let check = umbra(["check", obj.to_str().unwrap(), "--json"]);
    assert!(check.status.success(), "{}", stderr(&check));
    // The report describes every other file as written: its size, and for
    // a mesh the vertices and facets `umbra check` reads back from it.
    let files = report["files"].as_array().unwrap();
    let names: Vec<&str> = files
        .iter()
        .map(|f| f["format"].as_str().unwrap())
        .collect();
    assert_eq!(names, ["STL", "3MF", "OBJ", "PNG", "JSON"]);
    for f in files {
        let path = Path::new(f["file"].as_str().unwrap());
        assert!(path.starts_with(&dir), "{f}");
        let size = std::fs::metadata(path).unwrap().len();
        assert_eq!(f["bytes"].as_u64(), Some(size), "{f}");
        if ["PNG", "JSON"].contains(&f["format"].as_str().unwrap()) {
            assert!(
                f.get("vertices").is_none() && f.get("facets").is_none(),
                "{f}"
            );
            continue;
        }
        let c = check_json(path);
        assert_eq!(f["vertices"], c["vertices"], "{f}");
        assert_eq!(f["facets"], c["facets"], "{f}");
        let triangles = c["half_edges"].as_u64() == c["facets"].as_u64().map(|n| 3 * n);
        assert_eq!(f["triangles_only"], triangles, "{f}");
        assert_ne!(
            f["format"] == "OBJ",
            triangles,
            "STL and 3MF hold triangles: {f}"
        );
        let v = f["signed_volume"].as_f64().unwrap();
        assert!((v - volume).abs() <= 1e-6 * volume, "{f}");
    }
    // The OBJ holds the evaluated mesh's vertices; its facets with holes
    // are written as triangles, so it has more facets than the mesh.
    let obj_entry = &files[2];
    assert_eq!(obj_entry["vertices"], report["vertices"]);
    assert!(obj_entry["facets"].as_u64() > report["facets"].as_u64());
    // Its picture: an 800x600 PNG.
    let png = std::fs::read(dir.join("plant.png")).unwrap();
    assert!(png.starts_with(b"\x89PNG\r\n\x1a\n"));
    assert_eq!(&png[16..24], &[0, 0, 3, 32, 0, 0, 2, 88]);

    // The script the demo wrote evaluates to the same mesh, bit for bit.
    let again = dir.join("again.obj");
    let o = umbra([
        "csg",
        dir.join("plant.json").to_str().unwrap(),
        "-o",
        again.to_str().unwrap(),
        "--quiet",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert_eq!(std::fs::read(&again).unwrap(), std::fs::read(&obj).unwrap());
}

#[test]
fn a_destination_that_is_a_file_of_the_script_is_refused() {
    let dir = temp_dir("leaf");
    let mesh = dir.join("part.obj");
    std::fs::copy(examples().join("cube.obj"), &mesh).unwrap();
    let before = std::fs::read(&mesh).unwrap();
    let script = dir.join("s.json");
    std::fs::write(
        &script,
        r#"{"op": "union", "children": [{"file": "part.obj"}, {"box": {"size": [1, 1, 1]}, "translate": [0.5, 0.5, 0.5]}]}"#,
    )
    .unwrap();
    let o = umbra([
        "csg",
        script.to_str().unwrap(),
        "-o",
        mesh.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(
        stderr(&o).contains("a file of the script"),
        "{}",
        stderr(&o)
    );
    assert_eq!(std::fs::read(&mesh).unwrap(), before);
}

/// `umbra csg` smooths near the Booleans' contacts when a Boolean ran,
/// leaves a tree without a Boolean as it is unless a tolerance is given
/// (then smooths the whole mesh), says which in the report, and smooths
/// nothing with `--smooth 0`.
#[test]
fn csg_smooths_near_contacts_and_says_so() {
    let dir = temp_dir("near");
    let single = dir.join("single.json");
    std::fs::write(&single, r#"{"box": {"size": [1, 1, 1]}}"#).unwrap();
    let cases = [
        (examples().join("pipe_tee.json"), vec![], Some(true)),
        (
            examples().join("pipe_tee.json"),
            vec!["--smooth", "1e-3"],
            Some(true),
        ),
        (single.clone(), vec![], None),
        (single.clone(), vec!["--smooth", "1e-3"], Some(false)),
        (
            examples().join("pipe_tee.json"),
            vec!["--smooth", "0"],
            None,
        ),
    ];
    for (k, (script, extra, want)) in cases.into_iter().enumerate() {
        let out = dir.join(format!("out{k}.obj"));
        let report = dir.join(format!("r{k}.json"));
        let mut args = vec![
            "csg".as_ref(),
            script.as_os_str(),
            "-o".as_ref(),
            out.as_os_str(),
            "--report".as_ref(),
            report.as_os_str(),
            "--quiet".as_ref(),
        ];
        args.extend(extra.iter().map(std::ffi::OsStr::new));
        let o = umbra(args);
        assert!(o.status.success(), "{k}: {}", stderr(&o));
        let r = json(&report);
        match want {
            Some(near) => {
                assert_eq!(r["smoothed_near_contacts"], near, "{k}: {r}");
                assert!(r["smoothing"].is_object(), "{k}");
            }
            None => {
                assert!(r.get("smoothed_near_contacts").is_none(), "{k}: {r}");
                assert!(r["smoothing"].is_null(), "{k}");
            }
        }
        assert_eq!(r["topologically_valid"], true, "{k}");
    }
}
