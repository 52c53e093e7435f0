//! End-to-end tests of smoothing in the `umbra` binary: `umbra smooth` on
//! meshes and 2D files, `--smooth` on `boolean` and `csg`, the 3D
//! Boolean's default smoothing and `--smooth 0`, the stacked cubes of the
//! dissertation's figures 5.1-5.2, bad tolerances, and the real hex nut
//! combined with a rotated copy of itself.

use crate::common::{json, stderr, temp_dir, umbra, write};
use std::path::Path;

/// An OBJ unit-edge box from `lo` to `hi`.
fn box_obj(lo: [f64; 3], hi: [f64; 3]) -> String {
    let mut s = String::new();
    for i in 0..8 {
        let p = [
            if i & 1 == 0 { lo[0] } else { hi[0] },
            if i & 2 == 0 { lo[1] } else { hi[1] },
            if i & 4 == 0 { lo[2] } else { hi[2] },
        ];
        s += &format!("v {:?} {:?} {:?}\n", p[0], p[1], p[2]);
    }
    for f in [
        [1, 3, 4, 2],
        [5, 6, 8, 7],
        [1, 2, 6, 5],
        [3, 7, 8, 4],
        [1, 5, 7, 3],
        [2, 4, 8, 6],
    ] {
        s += &format!("f {} {} {} {}\n", f[0], f[1], f[2], f[3]);
    }
    s
}

fn check_json(path: &Path) -> serde_json::Value {
    let o = umbra(["check".as_ref(), path.as_os_str(), "--json".as_ref()]);
    assert!(o.status.success(), "{}", stderr(&o));
    serde_json::from_slice(&o.stdout).unwrap()
}

#[test]
fn stacked_cubes_union_is_one_closed_box_in_both_orders() {
    let dir = temp_dir("stacked");
    for gap in [0.0, 1e-12, -1e-9, 1e-7] {
        let lower = write(&dir, "lower.obj", &box_obj([0.0; 3], [1.0; 3]));
        let upper = write(
            &dir,
            "upper.obj",
            &box_obj([0.0, 0.0, 1.0 + gap], [1.0, 1.0, 2.0 + gap]),
        );
        for (a, b) in [(&lower, &upper), (&upper, &lower)] {
            for tri in [false, true] {
                let out = dir.join("out.obj");
                let report = dir.join("r.json");
                let mut args = vec![
                    "boolean".to_string(),
                    "union".into(),
                    a.display().to_string(),
                    b.display().to_string(),
                    "-o".into(),
                    out.display().to_string(),
                    "--smooth".into(),
                    "1e-5".into(),
                    "--report".into(),
                    report.display().to_string(),
                ];
                if tri {
                    args.push("--triangulate".into());
                }
                let o = umbra(&args);
                assert!(o.status.success(), "gap {gap}: {}", stderr(&o));
                let c = check_json(&out);
                let what = format!("gap {gap} tri {tri} a {}", a.display());
                assert_eq!(c["two_manifold"], true, "{what}: {c}");
                assert_eq!(c["self_intersecting_facet_pairs"], 0, "{what}");
                let v = c["signed_volume"].as_f64().unwrap();
                assert!((v - 2.0).abs() <= 1e-9 + gap.abs(), "{what}: volume {v}");
                let r = json(&report);
                assert_eq!(r["smoothing"]["tolerance"], 1e-5);
                assert_eq!(r["smoothing"]["budget_hit"], false);
                assert_eq!(r["topologically_valid"], true);
            }
        }
    }
}

#[test]
fn boolean_3d_smooths_by_default_and_smooth_zero_is_raw() {
    let dir = temp_dir("default-smooth");
    let a = write(&dir, "a.obj", &box_obj([0.0; 3], [2.0; 3]));
    let b = write(&dir, "b.obj", &box_obj([1.0; 3], [3.0; 3]));
    let out = dir.join("o.obj");
    let r = dir.join("r.json");
    let run = |extra: &[&str]| {
        let mut args = vec![
            "boolean",
            "union",
            a.to_str().unwrap(),
            b.to_str().unwrap(),
            "-o",
            out.to_str().unwrap(),
            "--report",
            r.to_str().unwrap(),
        ];
        args.extend_from_slice(extra);
        let o = umbra(&args);
        assert!(o.status.success(), "{}", stderr(&o));
        json(&r)
    };
    let smoothed = run(&[]);
    // 1e-9 of the larger operand's largest bounding-box extent (2).
    assert_eq!(smoothed["smoothing"]["tolerance"].as_f64(), Some(2e-9));
    assert_eq!(smoothed["output"]["signed_volume"].as_f64(), Some(15.0));
    let raw = run(&["--smooth", "0"]);
    assert!(raw["smoothing"].is_null());
    assert_eq!(raw["output"]["signed_volume"].as_f64(), Some(15.0));
}

#[test]
fn bad_tolerances_are_usage_errors() {
    let dir = temp_dir("bad-tol");
    let a = write(&dir, "a.obj", &box_obj([0.0; 3], [1.0; 3]));
    for bad in ["-1", "nan", "inf", "abc", ""] {
        let o = umbra([
            "smooth",
            a.to_str().unwrap(),
            "-o",
            dir.join("o.obj").to_str().unwrap(),
            "--tol",
            bad,
        ]);
        assert_eq!(o.status.code(), Some(2), "--tol {bad:?}: {}", stderr(&o));
        assert!(!dir.join("o.obj").exists());
    }
}

#[test]
fn smooth_command_on_a_mesh_with_a_sliver_gap() {
    // Two boxes 1e-7 apart: the gap goes at tolerance 1e-5 (one shell).
    let dir = temp_dir("smooth-mesh");
    let text = format!(
        "{}{}",
        box_obj([0.0; 3], [1.0; 3]),
        box_obj([1.0 + 1e-7, 0.0, 0.0], [2.0, 1.0, 1.0])
            .lines()
            .map(|l| if let Some(f) = l.strip_prefix("f ") {
                let idx: Vec<String> = f
                    .split_whitespace()
                    .map(|i| (i.parse::<usize>().unwrap() + 8).to_string())
                    .collect();
                format!("f {}\n", idx.join(" "))
            } else {
                format!("{l}\n")
            })
            .collect::<String>()
    );
    let input = write(&dir, "two.obj", &text);
    let out = dir.join("one.obj");
    let r = dir.join("r.json");
    let o = umbra([
        "smooth",
        input.to_str().unwrap(),
        "-o",
        out.to_str().unwrap(),
        "--tol",
        "1e-5",
        "--report",
        r.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let c = check_json(&out);
    assert_eq!(c["two_manifold"], true, "{c}");
    let rep = json(&r);
    assert_eq!(rep["operation"], "smooth");
    assert_eq!(rep["topologically_valid"], true);
    assert!(
        rep["smoothing"]["counts"]["facets_cancelled"]
            .as_u64()
            .unwrap()
            >= 1
    );
    let v = c["signed_volume"].as_f64().unwrap();
    assert!((v - 2.0).abs() < 1e-6, "volume {v}");
    assert!(rep["smoothing"]["max_displacement"].as_f64().unwrap() <= 1e-5 * 2.0);
}

#[test]
fn smooth_command_on_a_2d_file_leaves_no_short_edge() {
    let dir = temp_dir("smooth-2d");
    let input = write(
        &dir,
        "in.wkt",
        "MULTIPOLYGON(((0 0,1 0,1 1,0.5 1.0000001,0.5000001 1,0 1,0 0)),((1.0000002 0,2 0,2 1,1.0000002 1,1.0000002 0)))",
    );
    let out = dir.join("out.wkt");
    let r = dir.join("r.json");
    let o = umbra([
        "smooth",
        input.to_str().unwrap(),
        "-o",
        out.to_str().unwrap(),
        "--tol",
        "1e-5",
        "--report",
        r.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let rep = json(&r);
    assert_eq!(rep["topologically_valid"], true);
    let area = rep["output"]["signed_area"].as_f64().unwrap();
    assert!((area - 2.0).abs() < 1e-5 * 8.0, "area {area}");
    let text = std::fs::read_to_string(&out).unwrap();
    let nums: Vec<f64> = text
        .split(|c: char| !(c.is_ascii_digit() || c == '.' || c == '-' || c == 'e'))
        .filter_map(|t| t.parse().ok())
        .collect();
    let pts: Vec<[f64; 2]> = nums.chunks(2).map(|c| [c[0], c[1]]).collect();
    for w in pts.windows(2) {
        let d = (w[1][0] - w[0][0]).hypot(w[1][1] - w[0][1]);
        assert!(d == 0.0 || d >= 1e-5, "edge of length {d} in {text}");
    }
}

#[test]
fn hex_nut_union_rotated_copy_is_clean_by_default() {
    let dir = temp_dir("nut");
    let nut = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../test-support/data/pyvista/nut.ply");
    std::fs::copy(&nut, dir.join("nut.ply")).unwrap();
    let script = write(
        &dir,
        "nuts.json",
        r#"{"op": "union", "children": [{"file": "nut.ply"}, {"file": "nut.ply", "rotate": [0, 0, 3]}]}"#,
    );
    for tri in [true, false] {
        let out = dir.join("nuts.stl");
        let mut args = vec![
            "csg".to_string(),
            script.display().to_string(),
            "-o".into(),
            out.display().to_string(),
            "--ascii".into(),
            "--quiet".into(),
        ];
        if tri {
            args.push("--triangulate".into());
        }
        let o = umbra(&args);
        assert!(o.status.success(), "{}", stderr(&o));
        let c = check_json(&out);
        assert_eq!(
            c["self_intersecting_facet_pairs"], 0,
            "triangulate {tri}: {c}"
        );
    }
}
