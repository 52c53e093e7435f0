//! End-to-end tests of the `umbra` binary: each Boolean on analytic cases,
//! the report, bad input (exit 1, one line naming the file), usage errors
//! (exit 2), winding-number preservation with `--keep-orientation` and the
//! output orientation convention.
//!
//! Output files are parsed by an independent minimal WKT reader below (not
//! the library under test), and winding numbers are computed here by the
//! crossing rule.

use crate::common::{examples, stderr, temp_dir, umbra, write};
use std::path::{Path, PathBuf};

/// Rings of a WKT text as written (independent reader): every innermost
/// parenthesised group is one ring of `x y` pairs.
fn rings(text: &str) -> Vec<Vec<[f64; 2]>> {
    let mut out = Vec::new();
    let mut start = None;
    for (i, c) in text.char_indices() {
        match c {
            '(' => start = Some(i + 1),
            ')' => {
                if let Some(s) = start.take() {
                    let ring = text[s..i]
                        .split(',')
                        .map(|pair| {
                            let v: Vec<f64> = pair
                                .split_whitespace()
                                .map(|t| t.parse().unwrap())
                                .collect();
                            assert_eq!(v.len(), 2, "{pair}");
                            [v[0], v[1]]
                        })
                        .collect();
                    out.push(ring);
                }
            }
            _ => {}
        }
    }
    out
}

/// Rings grouped by polygon: `(outer, holes)` in writing order (the
/// independent reader again: depth 2 or 3 groups).
fn polygons(text: &str) -> Vec<Vec<Vec<[f64; 2]>>> {
    let mut polys: Vec<Vec<Vec<[f64; 2]>>> = Vec::new();
    let multi = text.trim_start().starts_with("MULTIPOLYGON");
    let poly_depth = if multi { 2 } else { 1 };
    let mut depth = 0;
    let mut ring_start = 0;
    for (i, c) in text.char_indices() {
        match c {
            '(' => {
                depth += 1;
                if depth == poly_depth {
                    polys.push(Vec::new());
                }
                ring_start = i;
            }
            ')' => {
                if depth == poly_depth + 1 {
                    let r = rings(&text[ring_start..=i]);
                    polys.last_mut().unwrap().extend(r);
                }
                depth -= 1;
            }
            _ => {}
        }
    }
    polys
}

fn ring_area(r: &[[f64; 2]]) -> f64 {
    let mut s = 0.0;
    for w in r.windows(2) {
        s += w[0][0] * w[1][1] - w[1][0] * w[0][1];
    }
    s / 2.0
}

/// The winding number of closed rings (as written) around `p`.
fn winding(rings: &[Vec<[f64; 2]>], p: [f64; 2]) -> i64 {
    let mut w = 0;
    for r in rings {
        for e in r.windows(2) {
            let (a, b) = (e[0], e[1]);
            let side = (b[0] - a[0]) * (p[1] - a[1]) - (p[0] - a[0]) * (b[1] - a[1]);
            if a[1] <= p[1] && b[1] > p[1] && side > 0.0 {
                w += 1;
            } else if a[1] > p[1] && b[1] <= p[1] && side < 0.0 {
                w -= 1;
            }
        }
    }
    w
}

fn assert_closed(rings: &[Vec<[f64; 2]>]) {
    for r in rings {
        assert!(r.len() >= 2, "{r:?}");
        assert_eq!(r.first(), r.last(), "ring not closed: {r:?}");
    }
}

const A_SQUARE: &str = "POLYGON ((0 0, 2 0, 2 2, 0 2, 0 0))\n";
const B_SQUARE: &str = "POLYGON ((1 1, 3 1, 3 3, 1 3, 1 1))\n";

#[test]
fn each_operation_on_two_squares() {
    let dir = temp_dir("ops");
    let a = write(&dir, "a.wkt", A_SQUARE);
    let b = write(&dir, "b.wkt", B_SQUARE);
    for (op, area) in [("union", 7.0), ("intersection", 1.0), ("difference", 3.0)] {
        let out = dir.join(format!("{op}.wkt"));
        let o = umbra([
            "boolean".as_ref(),
            op.as_ref(),
            a.as_os_str(),
            b.as_os_str(),
            "-o".as_ref(),
            out.as_os_str(),
        ]);
        assert!(o.status.success(), "{op}: {}", stderr(&o));
        assert!(String::from_utf8_lossy(&o.stdout).starts_with(op));
        let text = std::fs::read_to_string(&out).unwrap();
        assert!(text.starts_with("POLYGON (("), "{op}: {text}");
        let rs = rings(&text);
        assert_closed(&rs);
        let total: f64 = rs.iter().map(|r| ring_area(r)).sum();
        assert_eq!(total, area, "{op}: {text}");
    }
}

#[test]
fn disjoint_and_empty_results() {
    let dir = temp_dir("empty");
    let a = write(&dir, "a.wkt", A_SQUARE);
    let far = write(&dir, "far.wkt", "POLYGON ((10 10, 11 10, 11 11, 10 10))");
    let out = dir.join("out.wkt");
    let o = umbra([
        "boolean".as_ref(),
        "intersection".as_ref(),
        a.as_os_str(),
        far.as_os_str(),
        "-o".as_ref(),
        out.as_os_str(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert_eq!(
        std::fs::read_to_string(&out).unwrap(),
        "MULTIPOLYGON EMPTY\n"
    );
    let o = umbra([
        "boolean".as_ref(),
        "union".as_ref(),
        a.as_os_str(),
        far.as_os_str(),
        "-o".as_ref(),
        out.as_os_str(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = std::fs::read_to_string(&out).unwrap();
    assert!(text.starts_with("MULTIPOLYGON ((("), "{text}");
    assert_eq!(polygons(&text).len(), 2);
}

#[test]
fn example_files_satisfy_the_area_identity() {
    // area(A u B) + area(A n B) = area(A) + area(B), and A - B = (A u B) - B.
    let dir = temp_dir("examples");
    let a = examples().join("a.wkt");
    let b = examples().join("b.wkt");
    let area_of = |p: &Path| -> f64 {
        rings(&std::fs::read_to_string(p).unwrap())
            .iter()
            .map(|r| ring_area(r))
            .sum()
    };
    let mut areas = std::collections::HashMap::new();
    for op in ["union", "intersection", "difference"] {
        let out = dir.join(format!("{op}.wkt"));
        let o = umbra([
            "boolean".as_ref(),
            op.as_ref(),
            a.as_os_str(),
            b.as_os_str(),
            "-o".as_ref(),
            out.as_os_str(),
        ]);
        assert!(o.status.success(), "{op}: {}", stderr(&o));
        assert_closed(&rings(&std::fs::read_to_string(&out).unwrap()));
        areas.insert(op, area_of(&out));
    }
    // The example files are written with their outer rings
    // counter-clockwise and holes clockwise, so ring areas add up.
    let (aa, ab) = (area_of(&a), area_of(&b));
    assert!(aa > 0.0 && ab > 0.0);
    let tol = 1e-9 * (aa + ab);
    assert!(
        (areas["union"] + areas["intersection"] - aa - ab).abs() < tol,
        "{areas:?}"
    );
    assert!(
        (areas["difference"] - (aa - areas["intersection"])).abs() < tol,
        "{areas:?}"
    );
    assert!(
        areas["intersection"] > 1.0 && areas["union"] > aa,
        "{areas:?}"
    );
}

#[test]
fn report_has_the_contract_fields() {
    let dir = temp_dir("report");
    let a = examples().join("a.wkt");
    let b = examples().join("b.wkt");
    let out = dir.join("out.wkt");
    let report = dir.join("r.json");
    let o = umbra([
        "boolean".as_ref(),
        "union".as_ref(),
        a.as_os_str(),
        b.as_os_str(),
        "-o".as_ref(),
        out.as_os_str(),
        "--report".as_ref(),
        report.as_os_str(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let r: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&report).unwrap()).unwrap();
    assert_eq!(r["operation"], "union");
    for side in ["a", "b"] {
        for k in ["vertices", "edges", "rings"] {
            assert!(
                r["inputs"][side][k].as_u64().unwrap() > 0,
                "{side}.{k}: {r}"
            );
        }
    }
    assert_eq!(r["inputs"]["a"]["rings"], 2);
    assert_eq!(r["inputs"]["b"]["vertices"], 10);
    for k in ["vertices", "edges", "rings"] {
        assert!(r["output"][k].as_u64().unwrap() > 0, "output.{k}: {r}");
    }
    assert!(r["intersections"].as_u64().unwrap() > 0);
    assert_eq!(r["topologically_valid"], true);
    let eps = r["epsilon"].as_f64().unwrap();
    assert!(eps > 0.0 && eps < 1e-12, "{eps}");
    let total = r["timings_ms"]["total"].as_f64().unwrap();
    assert!(total >= 0.0);
    // Every phase timing is a number; each phase is part of the total.
    for (k, v) in r["timings_ms"].as_object().unwrap() {
        let ms = v.as_f64().unwrap_or_else(|| panic!("{k}: {v}"));
        assert!(
            ms >= 0.0 && ms <= total * 1.01 + 1e-3,
            "{k}: {ms} > {total}"
        );
    }
}

/// Runs `umbra boolean union` with `bad` as operand A (then B) and checks
/// the bad-input contract: exit 1, one stderr line naming the file and
/// containing `needle`.
fn assert_bad_input(bad: &Path, needle: &str) {
    let dir = temp_dir("bad-out");
    let good = write(&dir, "good.wkt", A_SQUARE);
    let out = dir.join("out.wkt");
    for swap in [false, true] {
        let (a, b) = if swap {
            (&good, &bad.to_path_buf())
        } else {
            (&bad.to_path_buf(), &good)
        };
        let o = umbra([
            "boolean".as_ref(),
            "union".as_ref(),
            a.as_os_str(),
            b.as_os_str(),
            "-o".as_ref(),
            out.as_os_str(),
        ]);
        let err = stderr(&o);
        assert_eq!(o.status.code(), Some(1), "{bad:?}: {err}");
        assert_eq!(err.lines().count(), 1, "{bad:?}: {err}");
        assert!(err.contains(&bad.display().to_string()), "{bad:?}: {err}");
        assert!(
            err.contains(needle),
            "{bad:?}: expected '{needle}' in {err}"
        );
        assert!(
            !err.contains("panicked") && !err.contains("internal error"),
            "{err}"
        );
        assert!(!out.exists(), "no output on bad input");
    }
    // `check` refuses unparsable files the same way.
    let o = umbra(["check".as_ref(), bad.as_os_str()]);
    let err = stderr(&o);
    assert_eq!(o.status.code(), Some(1), "check {bad:?}: {err}");
    assert_eq!(err.lines().count(), 1, "check {bad:?}: {err}");
    assert!(
        err.contains(&bad.display().to_string()),
        "check {bad:?}: {err}"
    );
}

#[test]
fn bad_input_exits_1_with_one_line_naming_the_file() {
    let dir = temp_dir("bad");
    let valid = std::fs::read_to_string(examples().join("a.wkt")).unwrap();
    let half = &valid[..valid.len() / 2];
    let cases: Vec<(PathBuf, &str)> = vec![
        (dir.join("missing.wkt"), "cannot read"),
        (
            {
                let d = dir.join("directory.wkt");
                std::fs::create_dir_all(&d).unwrap();
                d
            },
            "cannot read",
        ),
        (write(&dir, "empty.wkt", ""), "empty"),
        (write(&dir, "blank.wkt", " \n\t\n"), "empty"),
        (
            write(&dir, "malformed.wkt", "POLYGON ((0 0, 1 0, one 1, 0 0))"),
            "malformed",
        ),
        (write(&dir, "garbage.wkt", "hello world"), "malformed"),
        (write(&dir, "truncated.wkt", half), "truncated"),
        (
            write(&dir, "line.wkt", "LINESTRING (0 0, 1 1, 2 0)"),
            "LINESTRING",
        ),
        (write(&dir, "point.wkt", "POINT (0 0)"), "POINT"),
        (
            write(
                &dir,
                "gc.wkt",
                "GEOMETRYCOLLECTION (LINESTRING (0 0, 1 1), POINT (1 1))",
            ),
            "member 1 is a LINESTRING",
        ),
        (
            write(&dir, "nan.wkt", "POLYGON ((0 0, NaN 0, 1 1, 0 0))"),
            "not a finite",
        ),
        (
            write(&dir, "inf.wkt", "POLYGON ((0 0, 1 0, 1 inf, 0 0))"),
            "not a finite",
        ),
        (
            write(&dir, "neginf.wkt", "POLYGON ((0 0, -inf 0, 1 1, 0 0))"),
            "not finite",
        ),
        (
            write(&dir, "overflow.wkt", "POLYGON ((0 0, 1e999 0, 1 1, 0 0))"),
            "not finite",
        ),
        (
            write(&dir, "huge.wkt", "POLYGON ((0 0, 1e308 0, 1 1, 0 0))"),
            "exceeds",
        ),
        (
            write(&dir, "two.wkt", &format!("{A_SQUARE}{B_SQUARE}")),
            "one geometry per file",
        ),
        (
            write(&dir, "z.wkt", "POLYGON Z ((0 0 0, 1 0 0, 1 1, 0 0 0))"),
            "this geometry's coordinates have 3",
        ),
        (write(&dir, "shape.txt", A_SQUARE), "unsupported file type"),
        (
            write(&dir, "shape.geojson", "{}"),
            "malformed GeoJSON: the document has no \"type\"",
        ),
        (write(&dir, "noext", A_SQUARE), "unsupported file type"),
    ];
    for (path, needle) in &cases {
        assert_bad_input(path, needle);
    }
    // Bytes that are not UTF-8.
    let latin = dir.join("latin1.wkt");
    std::fs::write(&latin, b"POLYGON ((0 0, 1 0, 1 1, 0 0)) \xe9").unwrap();
    assert_bad_input(&latin, "UTF-8");
}

#[test]
fn unsupported_output_type_fails_before_work() {
    let dir = temp_dir("outtype");
    let a = write(&dir, "a.wkt", A_SQUARE);
    let out = dir.join("out.xyz");
    let o = umbra([
        "boolean".as_ref(),
        "union".as_ref(),
        a.as_os_str(),
        a.as_os_str(),
        "-o".as_ref(),
        out.as_os_str(),
    ]);
    assert_eq!(o.status.code(), Some(1));
    assert!(
        stderr(&o).contains("out.xyz: unsupported file type"),
        "{}",
        stderr(&o)
    );
    // An output path in a missing directory is a write error naming it.
    let out = dir.join("no/such/dir/out.wkt");
    let o = umbra([
        "boolean".as_ref(),
        "union".as_ref(),
        a.as_os_str(),
        a.as_os_str(),
        "-o".as_ref(),
        out.as_os_str(),
    ]);
    assert_eq!(o.status.code(), Some(1));
    let err = stderr(&o);
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(err.contains("out.wkt: cannot write"), "{err}");
}

#[test]
fn usage_errors_exit_2() {
    let dir = temp_dir("usage");
    let a = write(&dir, "a.wkt", A_SQUARE);
    let a = a.to_str().unwrap();
    let cube = examples().join("cube.obj");
    let cube = cube.to_str().unwrap();
    let cases: Vec<Vec<&str>> = vec![
        vec![],
        vec!["frobnicate"],
        vec!["boolean"],
        vec!["boolean", "xor", cube, cube, "-o", "o.obj"],
        vec!["boolean", "union", a, a],
        vec!["boolean", "union", a, "-o", "o.wkt"],
        vec!["boolean", "union", a, a, "-o", "o.wkt", "--bogus"],
        vec!["check"],
        vec!["check", a, "--report"],
    ];
    for args in cases {
        let o = umbra(&args);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {}", stderr(&o));
    }
    assert!(umbra(["--help"]).status.success());
    assert!(umbra(["boolean", "--help"]).status.success());
}

/// Sample points on a grid offset from every integer coordinate.
fn samples(lo: f64, hi: f64) -> Vec<[f64; 2]> {
    let mut v = Vec::new();
    let mut x = lo + 0.137;
    while x < hi {
        let mut y = lo + 0.291;
        while y < hi {
            v.push([x, y]);
            y += 0.5;
        }
        x += 0.5;
    }
    v
}

#[test]
fn keep_orientation_preserves_winding_numbers() {
    let dir = temp_dir("keep");
    // Inside-out, doubly covered, a figure-eight and a hole stored the
    // "wrong" way round: winding numbers -1, 2, +-1 and 0 somewhere.
    let a_text = "MULTIPOLYGON (((0 0, 0 4, 4 4, 4 0, 0 0)), ((1 1, 7 1, 7 7, 1 7, 1 1)), ((2 2, 6 2, 6 6, 2 6, 2 2)), ((5 -2, 9 2, 9 -2, 5 2, 5 -2)))\n";
    let b_text = "POLYGON ((3 -3, 10 -3, 10 3, 3 3, 3 -3), (4 -1, 8 -1, 8 1, 4 1, 4 -1))\n";
    let a = write(&dir, "a.wkt", a_text);
    let b = write(&dir, "b.wkt", b_text);
    let empty = write(&dir, "empty.wkt", "MULTIPOLYGON EMPTY\n");
    let ra = rings(a_text);
    let rb = rings(b_text);
    let pts = samples(-4.0, 11.0);
    assert!(pts.iter().any(|&p| winding(&ra, p) == -1));
    assert!(pts.iter().any(|&p| winding(&ra, p) == 2));

    // Identity round trip: A u {} keeps A's winding numbers everywhere.
    let out = dir.join("same.wkt");
    let o = umbra([
        "boolean".as_ref(),
        "union".as_ref(),
        a.as_os_str(),
        empty.as_os_str(),
        "-o".as_ref(),
        out.as_os_str(),
        "--keep-orientation".as_ref(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let ro = rings(&std::fs::read_to_string(&out).unwrap());
    assert_closed(&ro);
    for &p in &pts {
        assert_eq!(winding(&ro, p), winding(&ra, p), "at {p:?}");
    }

    // Each operation obeys eq. 4.20: w = cA a + cB b + cI a b pointwise.
    for (op, (ca, cb, ci)) in [
        ("union", (1, 1, -1)),
        ("intersection", (0, 0, 1)),
        ("difference", (1, 0, -1)),
    ] {
        let out = dir.join(format!("{op}.wkt"));
        let o = umbra([
            "boolean".as_ref(),
            op.as_ref(),
            a.as_os_str(),
            b.as_os_str(),
            "-o".as_ref(),
            out.as_os_str(),
            "--keep-orientation".as_ref(),
        ]);
        assert!(o.status.success(), "{op}: {}", stderr(&o));
        let ro = rings(&std::fs::read_to_string(&out).unwrap());
        assert_closed(&ro);
        for &p in &pts {
            let (wa, wb) = (winding(&ra, p), winding(&rb, p));
            assert_eq!(
                winding(&ro, p),
                ca * wa + cb * wb + ci * wa * wb,
                "{op} at {p:?}"
            );
        }
        // Written again (read and written as is), the file is unchanged.
        let again = dir.join(format!("{op}-again.wkt"));
        let o = umbra([
            "boolean".as_ref(),
            "union".as_ref(),
            out.as_os_str(),
            empty.as_os_str(),
            "-o".as_ref(),
            again.as_os_str(),
            "--keep-orientation".as_ref(),
        ]);
        assert!(o.status.success(), "{op}: {}", stderr(&o));
        let ra2 = rings(&std::fs::read_to_string(&again).unwrap());
        for &p in &pts {
            assert_eq!(winding(&ra2, p), winding(&ro, p), "{op} again at {p:?}");
        }
    }
}

#[test]
fn default_output_has_outer_rings_ccw_and_holes_cw() {
    let dir = temp_dir("orient");
    // Outer ring stored clockwise and hole counter-clockwise: read by role.
    let a = write(
        &dir,
        "a.wkt",
        "POLYGON ((0 0, 0 10, 10 10, 10 0, 0 0), (2 2, 5 2, 5 5, 2 5, 2 2), (6 6, 8 6, 8 8, 6 8, 6 6))\n",
    );
    let b = write(
        &dir,
        "b.wkt",
        "MULTIPOLYGON (((20 0, 30 0, 30 10, 20 10, 20 0)), ((9 4, 20 4, 20 5, 9 5, 9 4)))\n",
    );
    for op in ["union", "intersection", "difference"] {
        let out = dir.join(format!("{op}.wkt"));
        let o = umbra([
            "boolean".as_ref(),
            op.as_ref(),
            a.as_os_str(),
            b.as_os_str(),
            "-o".as_ref(),
            out.as_os_str(),
        ]);
        assert!(o.status.success(), "{op}: {}", stderr(&o));
        assert!(stderr(&o).is_empty(), "{op}: {}", stderr(&o));
        let text = std::fs::read_to_string(&out).unwrap();
        let polys = polygons(&text);
        assert!(!polys.is_empty(), "{op}: {text}");
        let mut holes = 0;
        for poly in &polys {
            assert!(
                ring_area(&poly[0]) > 0.0,
                "{op}: outer ring not CCW: {text}"
            );
            for hole in &poly[1..] {
                holes += 1;
                assert!(ring_area(hole) < 0.0, "{op}: hole not CW: {text}");
                // The hole lies inside its polygon's outer ring.
                let p = hole[0];
                let q = hole[1];
                let mid = [(p[0] + q[0]) / 2.0, (p[1] + q[1]) / 2.0];
                assert_eq!(winding(&poly[..1], mid), 1, "{op}: {text}");
            }
        }
        let expected_holes = if op == "intersection" { 0 } else { 2 };
        assert_eq!(holes, expected_holes, "{op}: {text}");
        let area: f64 = polys.iter().flatten().map(|r| ring_area(r)).sum();
        let expected = match op {
            "union" => 100.0 - 9.0 - 4.0 + 100.0 + 10.0,
            "intersection" => 1.0,
            _ => 100.0 - 9.0 - 4.0 - 1.0,
        };
        assert_eq!(area, expected, "{op}: {text}");
    }
}

#[test]
fn check_reports_validity_and_crossings() {
    let ex = examples();
    let o = umbra(["check".as_ref(), ex.join("a.wkt").as_os_str()]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = String::from_utf8_lossy(&o.stdout);
    assert!(text.contains("topologically valid"), "{text}");
    assert!(text.contains("crossing edge pairs: 0"), "{text}");

    let o = umbra([
        "check".as_ref(),
        ex.join("figure_eight.wkt").as_os_str(),
        "--json".as_ref(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let r: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(r["topologically_valid"], true);
    assert_eq!(r["coordinates_valid"], true);
    assert_eq!(r["crossing_edge_pairs"], 1);
    assert_eq!(r["rings"], 1);
    assert_eq!(r["vertices"], 4);
    assert_eq!(r["signed_area"], 0.0);

    let o = umbra([
        "check".as_ref(),
        ex.join("inside_out.wkt").as_os_str(),
        "--json".as_ref(),
        "--keep-orientation".as_ref(),
    ]);
    let r: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(r["signed_area"], -16.0);
    assert_eq!(r["cw_rings"], 1);
    let o = umbra([
        "check".as_ref(),
        ex.join("inside_out.wkt").as_os_str(),
        "--json".as_ref(),
    ]);
    let r: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(r["signed_area"], 16.0);

    // Out-of-range coordinates: reported (stdout) and exit 1 with one line.
    let dir = temp_dir("check");
    let huge = write(&dir, "huge.wkt", "POLYGON ((0 0, 1e308 0, 1 1, 0 0))");
    let o = umbra(["check".as_ref(), huge.as_os_str(), "--json".as_ref()]);
    assert_eq!(o.status.code(), Some(1));
    let r: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(r["coordinates_valid"], false);
    assert_eq!(r["crossing_edge_pairs"], serde_json::Value::Null);
    let err = stderr(&o);
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(err.contains("huge.wkt") && err.contains("exceeds"), "{err}");
}

/// The first lines of `umbra --help` name every extension the format
/// dispatch accepts (`FileKind::ALL`, which `FileKind::from_path` reads
/// by), 3D glTF and 3MF included.
#[test]
fn the_top_level_help_lists_every_supported_format() {
    let o = umbra(["--help"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let help = String::from_utf8(o.stdout).unwrap();
    let about = help.split("Usage:").next().unwrap();
    // The words of the description, without the punctuation around them.
    let words: Vec<&str> = about
        .split_whitespace()
        .map(|w| w.trim_matches(|c| "();,".contains(c)).trim_end_matches('.'))
        .collect();
    for kind in umbra::FileKind::ALL {
        let ext = format!(".{}", kind.extension());
        let path = PathBuf::from(format!("x{ext}"));
        assert_eq!(umbra::FileKind::from_path(&path).unwrap(), kind);
        assert!(words.contains(&ext.as_str()), "{ext} missing from: {about}");
    }
    assert!(
        about.contains(
            "2D: .wkt .geojson (.svg written only); 3D: .obj .off .stl .ply .3mf .glb .gltf."
        ),
        "{about}"
    );
}

/// The points and lines of a WKT `GEOMETRYCOLLECTION` and the line
/// features of a GeoJSON `FeatureCollection` (what GEOS and shapely
/// overlays return beside polygons) are skipped with one warning per file
/// naming how many; the polygons are read (4x4 union 4x4 overlapping by
/// 2x2: area 28). A file of lines alone is still refused (exit 1).
#[test]
fn points_and_lines_beside_polygons_are_skipped_with_a_warning() {
    let dir = temp_dir("non-areal");
    let a = write(
        &dir,
        "a.wkt",
        "GEOMETRYCOLLECTION (POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0)), LINESTRING (4 0, 9 0), POINT EMPTY)",
    );
    let b = write(
        &dir,
        "b.geojson",
        r#"{"type": "FeatureCollection", "features": [
            {"type": "Feature", "geometry": {"type": "Polygon", "coordinates": [[[2, 2], [6, 2], [6, 6], [2, 6], [2, 2]]]}},
            {"type": "Feature", "geometry": {"type": "LineString", "coordinates": [[0, 0], [1, 1]]}}]}"#,
    );
    let out = dir.join("u.wkt");
    let report = dir.join("u.json");
    let o = umbra([
        "boolean".as_ref(),
        "union".as_ref(),
        a.as_os_str(),
        b.as_os_str(),
        "-o".as_ref(),
        out.as_os_str(),
        "--report".as_ref(),
        report.as_os_str(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert_eq!(
        stderr(&o),
        format!(
            "umbra: warning: {}: 2 non-areal part(s) (points, lines) skipped; only polygons are read\n\
             umbra: warning: {}: 1 non-areal part(s) (points, lines) skipped; only polygons are read\n",
            a.display(),
            b.display()
        )
    );
    let r: serde_json::Value = serde_json::from_slice(&std::fs::read(&report).unwrap()).unwrap();
    assert_eq!(r["output"]["signed_area"], 28.0, "{r}");
    assert_eq!(r["inputs"]["a"]["signed_area"], 16.0, "{r}");
    assert_eq!(r["inputs"]["b"]["signed_area"], 16.0, "{r}");
    assert_eq!(
        std::fs::read_to_string(&out).unwrap(),
        "POLYGON ((0 0, 4 0, 4 2, 6 2, 6 6, 2 6, 2 4, 0 4, 0 0))\n"
    );
    // Nothing areal at all: refused, naming the first part.
    let lines = write(
        &dir,
        "lines.wkt",
        "GEOMETRYCOLLECTION (LINESTRING (0 0, 1 1), POINT (2 2))",
    );
    let o = umbra(["check".as_ref(), lines.as_os_str()]);
    assert_eq!(o.status.code(), Some(1));
    assert_eq!(
        stderr(&o),
        format!(
            "umbra: {}: unsupported geometry: GEOMETRYCOLLECTION member 1 is a LINESTRING (expected POLYGON or MULTIPOLYGON)\n",
            lines.display()
        )
    );
}

/// Runs `umbra boolean OP FILES... -o OUT [extra...]`.
fn boolean_of(op: &str, files: &[PathBuf], out: &Path, extra: &[&str]) -> std::process::Output {
    let mut args: Vec<std::ffi::OsString> = vec!["boolean".into(), op.into()];
    args.extend(files.iter().map(|f| f.clone().into_os_string()));
    args.extend(["-o".into(), out.as_os_str().to_owned()]);
    args.extend(extra.iter().map(Into::into));
    umbra(&args)
}

/// Whether `op` over operands of winding numbers `w` covers a point:
/// inside any (union), every (intersection), the first and no other
/// (difference), an odd number (xor); inside meaning a positive winding
/// number.
fn selects(op: &str, w: &[i64]) -> bool {
    let inside = w.iter().filter(|&&x| x > 0).count();
    match op {
        "union" => inside > 0,
        "intersection" => inside == w.len(),
        "difference" => w[0] > 0 && inside == 1,
        "xor" => inside % 2 == 1,
        _ => unreachable!("{op}"),
    }
}

#[test]
fn more_than_two_2d_operands_select_by_every_operands_winding_number() {
    let dir = temp_dir("nary-2d");
    // Two squares, a band across both and a bow tie (winding +1 and -1
    // in its two lobes).
    let texts = [
        A_SQUARE,
        B_SQUARE,
        "POLYGON ((0 1, 4 1, 4 2, 0 2, 0 1))\n",
        "POLYGON ((2 -1, 4 1, 4 -1, 2 1, 2 -1))\n",
    ];
    let files: Vec<PathBuf> = texts
        .iter()
        .enumerate()
        .map(|(i, t)| write(&dir, &format!("op{i}.wkt"), t))
        .collect();
    let pts = samples(-2.0, 5.0);
    // As written (the bow tie's negative lobe is outside it), and read by
    // role (the simple operands only: by role they are as written too).
    for (keep, n) in [(true, 4), (false, 3)] {
        let inputs: Vec<Vec<Vec<[f64; 2]>>> = texts[..n].iter().map(|t| rings(t)).collect();
        for op in ["union", "intersection", "difference", "xor"] {
            let out = dir.join(format!("{op}-{keep}.wkt"));
            let report = dir.join(format!("{op}-{keep}.json"));
            let mut extra = vec!["--report", report.to_str().unwrap()];
            if keep {
                extra.push("--keep-orientation");
            }
            let o = boolean_of(op, &files[..n], &out, &extra);
            assert!(o.status.success(), "{op}: {}", stderr(&o));
            assert!(String::from_utf8_lossy(&o.stdout).starts_with(&format!("{op} (via simplify)")));
            let written = rings(&std::fs::read_to_string(&out).unwrap());
            assert_closed(&written);
            for &p in &pts {
                let w: Vec<i64> = inputs.iter().map(|r| winding(r, p)).collect();
                assert_eq!(
                    winding(&written, p),
                    i64::from(selects(op, &w)),
                    "{op} (keep {keep}) at {p:?}, operands' winding numbers {w:?}"
                );
            }
            let r = crate::common::json(&report);
            assert_eq!(r["operation"], op);
            assert_eq!(r["inputs"]["b"]["file"], files[1].display().to_string());
            let more = r["more_inputs"].as_array().unwrap();
            assert_eq!(more.len(), n - 2);
            assert_eq!(more[0]["file"], files[2].display().to_string());
            assert_eq!(r["topologically_valid"], true);
        }
    }
    // Two operands write no `more_inputs`.
    let report = dir.join("two.json");
    let o = boolean_of(
        "union",
        &files[..2],
        &dir.join("two.wkt"),
        &["--report", report.to_str().unwrap()],
    );
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(crate::common::json(&report).get("more_inputs").is_none());
}

#[test]
fn more_than_two_3d_operands_are_one_csg_node() {
    let dir = temp_dir("nary-3d");
    // Three bars along x, [0, 2], [1, 3] and [1.5, 3.5], of section 1 x 1
    // (coplanar sides: the symbolic perturbation decides them).
    let files: Vec<PathBuf> = [[0.0, 2.0], [1.0, 3.0], [1.5, 3.5]]
        .iter()
        .enumerate()
        .map(|(i, &[lo, hi])| {
            let text = crate::cli_formats::box_stl([lo, 0.0, 0.0], [hi, 1.0, 1.0]);
            write(&dir, &format!("bar{i}.stl"), &text)
        })
        .collect();
    for (op, volume, ext) in [
        ("union", 3.5, "obj"),
        ("intersection", 0.5, "stl"),
        ("difference", 1.0, "obj"),
        ("difference", 1.0, "stl"),
    ] {
        let out = dir.join(format!("{op}.{ext}"));
        let report = dir.join(format!("{op}-{ext}.json"));
        let o = boolean_of(op, &files, &out, &["--report", report.to_str().unwrap()]);
        assert!(o.status.success(), "{op} {ext}: {}", stderr(&o));
        let r = crate::common::json(&report);
        assert_eq!(r["booleans"], 2, "{op} {ext}");
        assert_eq!(r["leaves"], 3);
        let variant = if ext == "stl" { "triangle" } else { "polygon" };
        assert_eq!(r["variant"], variant, "{op} {ext}");
        assert_eq!(r["topologically_valid"], true);
        assert_eq!(r["two_manifold"], true, "{op} {ext}");
        let v = r["volume"].as_f64().unwrap();
        assert!((v - volume).abs() < 1e-9, "{op} {ext}: volume {v}");
        // The file read back agrees (`check`: its own reader and counts).
        let o = umbra(["check".as_ref(), out.as_os_str(), "--json".as_ref()]);
        assert!(o.status.success(), "{}", stderr(&o));
        let c: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
        assert_eq!(c["facets"], r["facets"], "{op} {ext}");
        let cv = c["signed_volume"].as_f64().unwrap();
        assert!((cv - volume).abs() < 1e-6, "{op} {ext}: file volume {cv}");
    }
    // The same as two binary Booleans in turn.
    let ab = dir.join("ab.obj");
    let o = boolean_of("union", &files[..2], &ab, &[]);
    assert!(o.status.success(), "{}", stderr(&o));
    let abc = dir.join("abc.obj");
    let o = boolean_of(
        "union",
        &[ab, files[2].clone()],
        &abc,
        &["--report", dir.join("abc.json").to_str().unwrap()],
    );
    assert!(o.status.success(), "{}", stderr(&o));
    let chained = crate::common::json(&dir.join("abc.json"));
    let v = chained["output"]["signed_volume"].as_f64().unwrap();
    assert!((v - 3.5).abs() < 1e-9, "chained union volume {v}");
}

#[test]
fn more_than_two_operands_usage_errors_exit_2_and_write_nothing() {
    let dir = temp_dir("nary-usage");
    let w: Vec<PathBuf> = (0..3)
        .map(|i| write(&dir, &format!("s{i}.wkt"), A_SQUARE))
        .collect();
    let m: Vec<PathBuf> = (0..3)
        .map(|i| {
            write(
                &dir,
                &format!("m{i}.stl"),
                &crate::cli_formats::box_stl([0.0; 3], [1.0; 3]),
            )
        })
        .collect();
    let mixed = [w[0].clone(), w[1].clone(), m[0].clone()];
    for (op, files, out, extra) in [
        ("union", &w[..], "o.wkt", vec!["--via", "basic"]),
        ("union", &m[..], "o.obj", vec!["--keep-orientation"]),
        ("xor", &m[..], "o.obj", vec![]),
        ("union", &m[..], "o.obj", vec!["--via", "simplify"]),
        ("union", &w[..], "o.wkt", vec!["--triangulate"]),
        ("union", &mixed[..], "o.obj", vec![]),
        ("union", &mixed[..], "o.wkt", vec![]),
    ] {
        let out = dir.join(out);
        let o = boolean_of(op, files, &out, &extra);
        assert_eq!(
            o.status.code(),
            Some(2),
            "{op} {files:?} {extra:?}: {}",
            stderr(&o)
        );
        assert!(!out.exists(), "{op} {extra:?}");
    }
    // An output that is the third operand is refused, and left as it was.
    let o = boolean_of("union", &w, &w[2], &[]);
    assert!(!o.status.success());
    assert!(stderr(&o).contains("operand C"), "{}", stderr(&o));
    assert_eq!(std::fs::read_to_string(&w[2]).unwrap(), A_SQUARE);
}
