//! End-to-end tests of the mesh formats through the binary: a Boolean from
//! STL and PLY operands to every mesh format, with the volume read back
//! independently where the format is text, and hostile files (truncated,
//! huge counts, NaN, bad indices, a byte-order mark, non-UTF-8 text, an
//! open soup): exit 1 and one line naming the file, never a panic; one
//! mesh as ASCII STL, binary STL and OBJ checks alike (STL welded).

use crate::common::{examples, json, stderr, temp_dir, umbra};
use std::path::{Path, PathBuf};
use test_support::shapes::{box_corners, CUBE_FACES};

/// An ASCII STL of the axis-aligned box `[lo, hi]`, outward triangles.
pub(crate) fn box_stl(lo: [f64; 3], hi: [f64; 3]) -> String {
    let corners = box_corners(lo, hi);
    let mut s = String::from("solid box\n");
    for q in CUBE_FACES {
        for t in [[q[0], q[1], q[2]], [q[0], q[2], q[3]]] {
            s.push_str("facet normal 0 0 0\nouter loop\n");
            for v in t {
                let c = corners[v as usize];
                s.push_str(&format!("vertex {} {} {}\n", c[0], c[1], c[2]));
            }
            s.push_str("endloop\nendfacet\n");
        }
    }
    s.push_str("endsolid box\n");
    s
}

/// The signed volume of an ASCII STL by an independent reader.
fn stl_volume(text: &str) -> f64 {
    let v: Vec<[f64; 3]> = text
        .lines()
        .filter_map(|l| l.trim().strip_prefix("vertex "))
        .map(|r| {
            let c: Vec<f64> = r.split_whitespace().map(|x| x.parse().unwrap()).collect();
            [c[0], c[1], c[2]]
        })
        .collect();
    v.chunks(3)
        .map(|t| {
            let (a, b, c) = (t[0], t[1], t[2]);
            (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0])
                + a[2] * (b[0] * c[1] - b[1] * c[0]))
                / 6.0
        })
        .sum()
}

#[test]
fn a_boolean_from_stl_to_every_mesh_format() {
    let dir = temp_dir("every");
    let a = dir.join("a.stl");
    let b = dir.join("b.stl");
    std::fs::write(&a, box_stl([0.0; 3], [2.0; 3])).unwrap();
    std::fs::write(&b, box_stl([1.0; 3], [3.0; 3])).unwrap();
    for ext in ["stl", "ply", "obj", "off", "3mf", "glb"] {
        let out = dir.join(format!("out.{ext}"));
        let report = dir.join(format!("r-{ext}.json"));
        let o = umbra([
            "boolean".as_ref(),
            "difference".as_ref(),
            a.as_os_str(),
            b.as_os_str(),
            "-o".as_ref(),
            out.as_os_str(),
            "--report".as_ref(),
            report.as_os_str(),
        ]);
        assert!(o.status.success(), "{ext}: {}", stderr(&o));
        let r: serde_json::Value =
            serde_json::from_slice(&std::fs::read(&report).unwrap()).unwrap();
        assert_eq!(r["topologically_valid"], true, "{ext}");
        assert!(std::fs::metadata(&out).unwrap().len() > 0);
        if matches!(ext, "stl" | "ply" | "obj" | "off" | "3mf" | "glb") {
            // Readable formats read back, valid, with the exact volume 7.
            let c = umbra(["check".as_ref(), out.as_os_str(), "--json".as_ref()]);
            assert!(c.status.success(), "{ext}: {}", stderr(&c));
            let j: serde_json::Value = serde_json::from_slice(&c.stdout).unwrap();
            assert_eq!(j["signed_volume"], 7.0, "{ext}: {j}");
            assert_eq!(j["topologically_valid"], true, "{ext}");
            if !matches!(ext, "stl" | "glb") {
                // STL has no vertex indices, and glTF's are welded by
                // position on reading too: welding merges the
                // Boolean's coincident intersection vertices (an X12 and an
                // X21 vertex at one point), which leaves edges shared by
                // more than two triangles until smoothing merges them
                // topologically; the indexed formats keep the 2-manifold.
                assert_eq!(j["two_manifold"], true, "{ext}");
            }
        }
    }
    // The operands' volumes by the independent reader.
    assert!((stl_volume(&std::fs::read_to_string(&a).unwrap()) - 8.0).abs() < 1e-12);
}

/// The empty result of a Boolean (disjoint boxes intersected), written in
/// every readable mesh format and both STL and PLY encodings, reads back:
/// `check` finds the empty mesh valid, and it serves as an operand (its
/// union with a box is the box).
#[test]
fn an_empty_result_reads_back_in_every_mesh_format() {
    let dir = temp_dir("empty");
    let a = dir.join("a.stl");
    let b = dir.join("b.stl");
    std::fs::write(&a, box_stl([0.0; 3], [1.0; 3])).unwrap();
    std::fs::write(&b, box_stl([5.0; 3], [6.0; 3])).unwrap();
    for (ext, ascii) in [
        ("stl", false),
        ("stl", true),
        ("ply", false),
        ("ply", true),
        ("obj", false),
        ("off", false),
        ("glb", false),
    ] {
        let out = dir.join(format!("empty-{ascii}.{ext}"));
        let mut args = vec![
            "boolean".as_ref(),
            "intersection".as_ref(),
            a.as_os_str(),
            b.as_os_str(),
            "-o".as_ref(),
            out.as_os_str(),
        ];
        if ascii {
            args.push("--ascii".as_ref());
        }
        let o = umbra(args);
        assert!(o.status.success(), "{ext}: {}", stderr(&o));
        let c = umbra(["check".as_ref(), out.as_os_str(), "--json".as_ref()]);
        assert!(c.status.success(), "{ext} {ascii}: {}", stderr(&c));
        let j: serde_json::Value = serde_json::from_slice(&c.stdout).unwrap();
        assert_eq!(j["topologically_valid"], true, "{ext}: {j}");
        assert_eq!(j["facets"], 0, "{ext}: {j}");
        assert_eq!(j["signed_volume"], 0.0, "{ext}: {j}");
        let union = dir.join(format!("union-{ascii}.off"));
        let o = umbra([
            "boolean".as_ref(),
            "union".as_ref(),
            out.as_os_str(),
            a.as_os_str(),
            "-o".as_ref(),
            union.as_os_str(),
        ]);
        assert!(o.status.success(), "{ext}: {}", stderr(&o));
        let c = umbra(["check".as_ref(), union.as_os_str(), "--json".as_ref()]);
        let j: serde_json::Value = serde_json::from_slice(&c.stdout).unwrap();
        assert_eq!(j["signed_volume"], 1.0, "{ext}: {j}");
    }
    // A file of nothing but white space is still refused.
    let blank = dir.join("blank.stl");
    std::fs::write(&blank, "  \n").unwrap();
    assert_bad_input(&blank, "empty");
}

fn assert_bad_input(path: &Path, needle: &str) {
    let o = umbra(["check".as_ref(), path.as_os_str()]);
    assert_eq!(
        o.status.code(),
        Some(1),
        "{}: {}",
        path.display(),
        stderr(&o)
    );
    let e = stderr(&o);
    assert_eq!(e.trim_end().lines().count(), 1, "{}: {e}", path.display());
    let name = path.file_name().unwrap().to_str().unwrap();
    assert!(e.contains(name), "{e}");
    assert!(
        e.contains(needle),
        "{}: wanted {needle:?} in {e}",
        path.display()
    );
}

#[test]
fn hostile_mesh_files_exit_1_with_one_line() {
    let dir = temp_dir("hostile");
    let w = |name: &str, bytes: &[u8]| {
        let p = dir.join(name);
        std::fs::write(&p, bytes).unwrap();
        p
    };
    let good = box_stl([0.0; 3], [1.0; 3]);
    // An open soup: the last facet dropped.
    let cut = good.rfind("facet normal").unwrap();
    let open = format!("{}endsolid box\n", &good[..cut]);
    let mut huge = vec![0u8; 80];
    huge.extend_from_slice(&u32::MAX.to_le_bytes());
    huge.extend_from_slice(&[0u8; 50]);
    let cases: Vec<(PathBuf, &str)> = vec![
        (w("open.stl", open.as_bytes()), "open"),
        (w("nan.stl", good.replacen("vertex 0 0 0", "vertex NaN 0 0", 1).as_bytes()), "NaN"),
        (w("big.stl", good.replacen("vertex 0 0 0", "vertex 1e400 0 0", 1).as_bytes()), "1e400"),
        (w("huge.stl", &huge), "STL"),
        (w("truncated.stl", &good.as_bytes()[..good.len() / 2]), "STL"),
        (
            w("huge.ply", b"ply\nformat ascii 1.0\nelement vertex 4000000000\nproperty float x\nproperty float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n"),
            "PLY",
        ),
        (
            w("index.ply", b"ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n"),
            "7",
        ),
        (w("latin1.ply", b"ply\nformat ascii 1.0\ncomment \xe9\xff\nend_header\n"), "PLY"),
        (w("huge.off", b"OFF\n999999999 999999999 0\n0 0 0\n"), "OFF"),
        (w("bom.off", "\u{feff}OFF\n3 1 0\n0 0 0\n1 0 0\n".as_bytes()), "OFF"),
        (w("latin1.obj", b"v 0 0 0\nv 1 0 0 \xe9\n"), "UTF-8"),
    ];
    for (path, needle) in &cases {
        assert_bad_input(path, needle);
    }
}

#[test]
fn an_obj_with_a_byte_order_mark_reads_like_one_without() {
    let dir = temp_dir("bom");
    let text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
    let plain = dir.join("plain.obj");
    let bom = dir.join("bom.obj");
    std::fs::write(&plain, text).unwrap();
    std::fs::write(&bom, format!("\u{feff}{text}")).unwrap();
    let a = umbra(["check".as_ref(), plain.as_os_str(), "--json".as_ref()]);
    let b = umbra(["check".as_ref(), bom.as_os_str(), "--json".as_ref()]);
    assert!(a.status.success() && b.status.success(), "{}", stderr(&b));
    let ja: serde_json::Value = serde_json::from_slice(&a.stdout).unwrap();
    let jb: serde_json::Value = serde_json::from_slice(&b.stdout).unwrap();
    assert_eq!(ja["signed_volume"], jb["signed_volume"]);
    assert_eq!(ja["vertices"], 4);
    assert_eq!(jb["vertices"], 4);
}

#[test]
fn ascii_stl_and_ply_keep_every_f64() {
    let dir = temp_dir("ascii");
    let script = examples().join("bracket.json");
    for ext in ["stl", "ply"] {
        let out = dir.join(format!("b.{ext}"));
        let report = dir.join(format!("b-{ext}.json"));
        let o = umbra([
            "csg".as_ref(),
            script.as_os_str(),
            "-o".as_ref(),
            out.as_os_str(),
            "--report".as_ref(),
            report.as_os_str(),
            "--ascii".as_ref(),
            "--quiet".as_ref(),
        ]);
        assert!(o.status.success(), "{ext}: {}", stderr(&o));
        let text = std::fs::read_to_string(&out).unwrap();
        assert!(text.starts_with(if ext == "stl" {
            "solid"
        } else {
            "ply\nformat ascii"
        }));
        let want = json(&report)["volume"].as_f64().unwrap();
        if ext == "stl" {
            let got = stl_volume(&text);
            assert!((got - want).abs() <= 1e-9 * want, "{got} vs {want}");
        }
        let c = umbra(["check".as_ref(), out.as_os_str(), "--json".as_ref()]);
        assert!(c.status.success(), "{}", stderr(&c));
        let j: serde_json::Value = serde_json::from_slice(&c.stdout).unwrap();
        let got = j["signed_volume"].as_f64().unwrap();
        assert!((got - want).abs() <= 1e-12 * want, "{ext}: {got} vs {want}");
    }
}

/// A UV sphere of `s` slices and `s / 2` stacks as OFF text (every `f64`
/// in its shortest round-trip form).
fn uv_sphere_off(c: [f64; 3], s: usize) -> String {
    let t = s / 2;
    let mut v = vec![[c[0], c[1], c[2] + 1.0]];
    for i in 1..t {
        let th = std::f64::consts::PI * i as f64 / t as f64;
        for j in 0..s {
            let ph = 2.0 * std::f64::consts::PI * j as f64 / s as f64;
            v.push([
                c[0] + th.sin() * ph.cos(),
                c[1] + th.sin() * ph.sin(),
                c[2] + th.cos(),
            ]);
        }
    }
    v.push([c[0], c[1], c[2] - 1.0]);
    let south = v.len() - 1;
    let mut f = Vec::new();
    for j in 0..s {
        f.push([0, 1 + j, 1 + (j + 1) % s]);
    }
    for i in 0..t - 2 {
        for j in 0..s {
            let (a, b) = (1 + i * s + j, 1 + i * s + (j + 1) % s);
            f.push([a, a + s, b + s]);
            f.push([a, b + s, b]);
        }
    }
    let base = 1 + (t - 2) * s;
    for j in 0..s {
        f.push([base + j, south, base + (j + 1) % s]);
    }
    let mut text = format!("OFF\n{} {} 0\n", v.len(), f.len());
    for p in &v {
        text.push_str(&format!("{:?} {:?} {:?}\n", p[0], p[1], p[2]));
    }
    for t in &f {
        text.push_str(&format!("3 {} {} {}\n", t[0], t[1], t[2]));
    }
    text
}

#[test]
fn a_triangle_format_output_runs_the_triangle_variant() {
    // A sphere minus a shifted copy: the polygon variant's result,
    // triangulated on writing, folds where the pieces of the two surfaces
    // meet (11 intersecting facet pairs at this resolution when written as
    // STL); the triangle variant's smoothing leaves none, so STL, 3MF and
    // glTF outputs run it without `--triangulate`.
    let dir = temp_dir("tri-variant");
    let d = 0.5 / 3f64.sqrt();
    let a = dir.join("a.off");
    let b = dir.join("b.off");
    std::fs::write(&a, uv_sphere_off([0.0; 3], 40)).unwrap();
    std::fs::write(&b, uv_sphere_off([d, d * 1.1, d * 0.9], 40)).unwrap();
    let run = |out: &Path, extra: &[&str]| -> serde_json::Value {
        let report = dir.join("r.json");
        let mut args: Vec<&std::ffi::OsStr> = vec![
            "boolean".as_ref(),
            "difference".as_ref(),
            a.as_os_str(),
            b.as_os_str(),
            "-o".as_ref(),
            out.as_os_str(),
            "--report".as_ref(),
            report.as_os_str(),
        ];
        args.extend(extra.iter().map(|s| std::ffi::OsStr::new(*s)));
        let o = umbra(args);
        assert!(o.status.success(), "{}", stderr(&o));
        serde_json::from_slice(&std::fs::read(&report).unwrap()).unwrap()
    };
    let implied = dir.join("implied.stl");
    let asked = dir.join("asked.stl");
    let r = run(&implied, &["--ascii"]);
    assert_eq!(r["variant"], "triangle mesh", "{r}");
    run(&asked, &["--ascii", "--triangulate"]);
    assert_eq!(
        std::fs::read(&implied).unwrap(),
        std::fs::read(&asked).unwrap()
    );
    let c = umbra(["check".as_ref(), implied.as_os_str(), "--json".as_ref()]);
    let j: serde_json::Value = serde_json::from_slice(&c.stdout).unwrap();
    assert_eq!(j["self_intersecting_facet_pairs"], 0, "{j}");
    assert_eq!(j["two_manifold"], true, "{j}");
    for ext in ["3mf", "glb", "gltf"] {
        let r = run(&dir.join(format!("out.{ext}")), &[]);
        assert_eq!(r["variant"], "triangle mesh", "{ext}: {r}");
    }
    // Formats of polygons keep the polygon variant unless asked.
    let r = run(&dir.join("out.obj"), &[]);
    assert_eq!(r["variant"], "polygon mesh", "{r}");
    let r = run(&dir.join("out_t.obj"), &["--triangulate"]);
    assert_eq!(r["variant"], "triangle mesh", "{r}");
}

/// `check --json` of `path`, parsed (the file as a reader sees it).
fn check_json(path: &Path) -> serde_json::Value {
    let c = umbra(["check".as_ref(), path.as_os_str(), "--json".as_ref()]);
    assert!(c.status.success(), "{}", stderr(&c));
    serde_json::from_slice(&c.stdout).unwrap()
}

/// Runs `umbra` with `args` and asserts success; its standard error.
fn run_ok(args: &[&std::ffi::OsStr]) -> String {
    let o = umbra(args);
    assert!(o.status.success(), "{args:?}: {}", stderr(&o));
    stderr(&o)
}

/// A 3D Boolean written to binary STL (`f32` coordinates) is reported as
/// written: the output counts and volume of `--report` are those `umbra
/// check` reads back from the file (the result rounded to `f32`, repaired
/// and welded as the reader welds), the `f32_rounding` section says what
/// rounding did, and `timings_ms.total` includes it. The same run to OFF
/// (every f64 kept) has no such section.
#[test]
fn a_boolean_to_stl_is_reported_as_written() {
    let dir = temp_dir("f32-report");
    let a = dir.join("a.stl");
    let b = dir.join("b.stl");
    // Coordinates that are not f32 values: every result vertex moves.
    std::fs::write(&a, box_stl([0.1, 0.2, 0.3], [1.1, 1.2, 1.3])).unwrap();
    std::fs::write(&b, box_stl([0.55, 0.65, 0.75], [1.7, 1.8, 1.9])).unwrap();
    let out = dir.join("u.stl");
    let report = dir.join("u.json");
    let err = run_ok(&[
        "boolean".as_ref(),
        "union".as_ref(),
        a.as_os_str(),
        b.as_os_str(),
        "-o".as_ref(),
        out.as_os_str(),
        "--report".as_ref(),
        report.as_os_str(),
    ]);
    assert_eq!(err, "", "no defect left, no warning");
    let r = json(&report);
    let c = check_json(&out);
    assert_eq!(r["output"]["vertices"], 20, "{r}");
    assert_eq!(r["output"]["vertices"], c["vertices"]);
    assert_eq!(r["output"]["facets"], 36, "{r}");
    assert_eq!(r["output"]["facets"], c["facets"]);
    // Bit for bit the volume of the file, not of the f64 result
    // (1 + 1.15^3 - 0.55^3 = 2.3545 before rounding).
    assert_eq!(r["output"]["signed_volume"], c["signed_volume"], "{r} {c}");
    assert_eq!(r["output"]["signed_volume"], 2.354499980866906, "{r}");
    let f = &r["f32_rounding"];
    assert_eq!(f["moved_vertices"], 20, "{r}");
    assert_eq!(f["pairs_from_rounding"], 0, "{r}");
    assert_eq!(f["pairs_left"], 0, "{r}");
    assert_eq!(f["collisions_left"], 0, "{r}");
    let t = &r["timings_ms"];
    let (total, round) = (
        t["total"].as_f64().unwrap(),
        t["round_f32"].as_f64().unwrap(),
    );
    let smooth = t["smooth"].as_f64().unwrap();
    assert!(round > 0.0 && total >= round + smooth, "{t}");

    let off = dir.join("u.off");
    let report = dir.join("off.json");
    run_ok(&[
        "boolean".as_ref(),
        "union".as_ref(),
        a.as_os_str(),
        b.as_os_str(),
        "-o".as_ref(),
        off.as_os_str(),
        "--report".as_ref(),
        report.as_os_str(),
    ]);
    let r = json(&report);
    assert!(r.get("f32_rounding").is_none(), "{r}");
    assert!(r["timings_ms"].get("round_f32").is_none(), "{r}");
    assert_eq!(
        r["output"]["signed_volume"],
        check_json(&off)["signed_volume"]
    );
}

/// The CSG of the user's report, scaled down (a plate minus four
/// countersink cones poking 1e-4 above its top: plain rounding folds 71
/// facet pairs, which the corner pass repairs), and a sphere minus a copy
/// shifted by 1e-6, unsmoothed, whose f64 result has two vertices at one
/// point (valid there; one vertex once an STL reader welds them): the
/// report describes the STL as `check` reads it, vertex for vertex.
#[test]
fn a_csg_to_stl_is_reported_as_written() {
    let dir = temp_dir("f32-csg");
    let cone = |x: f64, y: f64| {
        format!(
            r#"{{"cylinder": {{"radius": 2, "radius_top": 5, "height": 3.0001, "segments": 16}}, "translate": [{x}, {y}, 7]}}"#
        )
    };
    let plate = format!(
        r#"{{"op": "difference", "children": [{{"box": {{"size": [80, 50, 10]}}}}, {}, {}, {}, {}]}}"#,
        cone(8.0, 10.0),
        cone(72.0, 10.0),
        cone(8.0, 40.0),
        cone(72.0, 40.0)
    );
    let spheres = r#"{"op": "difference", "children": [{"sphere": {"radius": 1, "segments": 12}}, {"sphere": {"radius": 1, "segments": 12}, "translate": [1e-6, 2e-6, 3e-6]}]}"#;
    // (script, smoothing, vertices and facets written, pairs rounding made)
    let cases = [
        (plate.as_str(), None, 199, 394, 71),
        (spheres, Some("0"), 124, 246, 15),
    ];
    for (i, (script, smooth, vertices, facets, pairs)) in cases.into_iter().enumerate() {
        let path = dir.join(format!("s{i}.json"));
        std::fs::write(&path, script).unwrap();
        let out = dir.join(format!("s{i}.stl"));
        let report = dir.join(format!("r{i}.json"));
        let mut args: Vec<&std::ffi::OsStr> = vec![
            "csg".as_ref(),
            path.as_os_str(),
            "-o".as_ref(),
            out.as_os_str(),
            "--report".as_ref(),
            report.as_os_str(),
            "--quiet".as_ref(),
        ];
        if let Some(t) = smooth {
            args.extend([std::ffi::OsStr::new("--smooth"), t.as_ref()]);
        }
        let err = run_ok(&args);
        assert_eq!(err, "", "{i}");
        let r = json(&report);
        let c = check_json(&out);
        assert_eq!(r["vertices"], vertices, "{i}: {r}");
        assert_eq!(r["vertices"], c["vertices"], "{i}");
        assert_eq!(r["facets"], facets, "{i}: {r}");
        assert_eq!(r["facets"], c["facets"], "{i}");
        assert_eq!(r["volume"], c["signed_volume"], "{i}");
        assert_eq!(r["topologically_valid"], true, "{i}");
        let f = &r["f32_rounding"];
        assert_eq!(f["pairs_from_rounding"], pairs, "{i}: {r}");
        assert_eq!(f["pairs_left"], 0, "{i}: {r}");
        assert_eq!(f["collisions_left"], 0, "{i}: {r}");
        let t = &r["timings_ms"];
        assert!(
            t["total"].as_f64().unwrap() >= t["round_f32"].as_f64().unwrap(),
            "{i}: {t}"
        );
    }
}

/// Where rounding to `f32` cannot remove every defect (a sphere minus a
/// copy shifted by 3e-7, features below the f32 spacing), the report
/// counts what is left and the command warns on standard error naming
/// the file; written as OFF the same result has nothing to warn about.
#[test]
fn defects_left_by_f32_rounding_are_warned() {
    let dir = temp_dir("f32-warn");
    let script = dir.join("s.json");
    std::fs::write(
        &script,
        r#"{"op": "difference", "children": [{"sphere": {"radius": 1, "segments": 24}}, {"sphere": {"radius": 1, "segments": 24}, "translate": [3e-7, 3e-7, 3e-7]}]}"#,
    )
    .unwrap();
    let out = dir.join("s.stl");
    let report = dir.join("r.json");
    let err = run_ok(&[
        "csg".as_ref(),
        script.as_os_str(),
        "-o".as_ref(),
        out.as_os_str(),
        "--report".as_ref(),
        report.as_os_str(),
        "--quiet".as_ref(),
    ]);
    assert_eq!(
        err,
        format!(
            "umbra: warning: {}: rounding to f32 left 0 intersecting facet pair(s) and 1 pair(s) of coinciding vertices (features thinner than the f32 spacing); write .obj, .off, .ply, .3mf or --ascii .stl to keep every f64\n",
            out.display()
        )
    );
    let r = json(&report);
    assert_eq!(r["f32_rounding"]["collisions_left"], 1, "{r}");
    assert_eq!(r["f32_rounding"]["pairs_left"], 0, "{r}");
    // The vertices that coincide are one in the file, and in the report.
    assert_eq!(r["vertices"], 419, "{r}");
    assert_eq!(r["vertices"], check_json(&out)["vertices"]);
    let off = dir.join("s.off");
    let err = run_ok(&[
        "csg".as_ref(),
        script.as_os_str(),
        "-o".as_ref(),
        off.as_os_str(),
        "--triangulate".as_ref(),
        "--quiet".as_ref(),
    ]);
    assert_eq!(err, "");
}

/// One closed mesh (the box `[-0.5, 0.25] x [0, 1.5] x [-2, 0]`, twelve
/// outward triangles on eight corners, every coordinate an `f32`) as an
/// exporter's ASCII STL (CRLF lines, `%e` spellings, `-0` on one side of
/// an edge and `0` on the other, two solids), as binary STL and as an OBJ
/// of the same triangles: STL has no indices, so its readers weld corners
/// at bitwise-equal positions, and `umbra check` describes one closed
/// 2-manifold solid in all three files alike.
#[test]
fn ascii_stl_binary_stl_and_obj_of_one_mesh_check_alike() {
    let dir = temp_dir("weld");
    let (lo, hi) = ([-0.5f32, 0.0, -2.0], [0.25f32, 1.5, 0.0]);
    let corner = |i: usize| [0, 1, 2].map(|a| if i >> a & 1 == 0 { lo[a] } else { hi[a] });
    let tris: Vec<[usize; 3]> = CUBE_FACES
        .iter()
        .map(|q| q.map(|v| v as usize))
        .flat_map(|q| [[q[0], q[1], q[2]], [q[0], q[2], q[3]]])
        .collect();
    // ASCII: zero written `-0.000000e+00` in odd triangles.
    let mut ascii = String::from("solid part one\r\n");
    for (k, t) in tris.iter().enumerate() {
        if k == 6 {
            ascii.push_str("endsolid part one\r\nsolid part two\r\n");
        }
        ascii.push_str(
            "  facet normal 0.000000e+00 0.000000e+00 0.000000e+00\r\n    outer loop\r\n",
        );
        for &v in t {
            let c = corner(v).map(|x| {
                if x == 0.0 && k % 2 == 1 {
                    "-0.000000e+00".to_string()
                } else {
                    format!("{x:e}")
                }
            });
            ascii.push_str(&format!("      vertex {} {} {}\r\n", c[0], c[1], c[2]));
        }
        ascii.push_str("    endloop\r\n  endfacet\r\n");
    }
    ascii.push_str("endsolid part two\r\n");
    let mut binary = vec![b' '; 80];
    binary.extend((tris.len() as u32).to_le_bytes());
    for t in &tris {
        binary.extend([0u8; 12]);
        for &v in t {
            for x in corner(v) {
                binary.extend(x.to_le_bytes());
            }
        }
        binary.extend([0, 0]);
    }
    let mut obj = String::new();
    for i in 0..8 {
        let c = corner(i);
        obj.push_str(&format!("v {} {} {}\n", c[0], c[1], c[2]));
    }
    for t in &tris {
        obj.push_str(&format!("f {} {} {}\n", t[0] + 1, t[1] + 1, t[2] + 1));
    }
    let files = [
        (dir.join("ascii.stl"), ascii.into_bytes()),
        (dir.join("binary.stl"), binary),
        (dir.join("mesh.obj"), obj.into_bytes()),
    ];
    let mut reports = Vec::new();
    for (path, bytes) in &files {
        std::fs::write(path, bytes).unwrap();
        let mut c = check_json(path);
        c.as_object_mut().unwrap().remove("file");
        reports.push(c);
    }
    let c = &reports[0];
    assert_eq!(c["vertices"], 8, "{c}");
    assert_eq!(
        (c["facets"].as_u64(), c["edges"].as_u64()),
        (Some(12), Some(18))
    );
    assert_eq!(c["two_manifold"], true, "{c}");
    assert_eq!(
        (c["open_edges"].as_u64(), c["non_manifold_edges"].as_u64()),
        (Some(0), Some(0))
    );
    assert_eq!(c["signed_volume"], 0.75 * 1.5 * 2.0, "{c}");
    assert_eq!(reports[1], reports[0], "binary STL");
    assert_eq!(reports[2], reports[0], "OBJ");
}
