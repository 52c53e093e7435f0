//! The defects of the hostile-input probe, fixed: standard output that
//! cannot be written (`> /dev/full`, a closed pipe) is never a panic;
//! `--report` to a bad path or to the output path writes nothing; an
//! output that is also an input is refused; and the summary and the report
//! count the rings and points the output file actually holds (read back by
//! an independent reader here).

use crate::common::{examples, stderr, temp_dir, write};
use std::fs;
use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};

fn umbra(args: &[&Path]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_umbra"))
        .args(args)
        .output()
        .unwrap()
}

/// Runs the tool with standard output redirected to `stdout`.
fn umbra_to(args: &[&Path], stdout: Stdio) -> Output {
    Command::new(env!("CARGO_BIN_EXE_umbra"))
        .args(args)
        .stdout(stdout)
        .stderr(Stdio::piped())
        .output()
        .unwrap()
}

/// Runs the tool with standard output a pipe whose reading end is closed
/// before the tool writes.
fn umbra_closed_pipe(args: &[&Path]) -> Output {
    let mut child = Command::new(env!("CARGO_BIN_EXE_umbra"))
        .args(args)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    drop(child.stdout.take());
    child.wait_with_output().unwrap()
}

fn p(s: &str) -> &Path {
    Path::new(s)
}

/// The files of `dir`, sorted (to see that no temporary file is left).
fn listing(dir: &Path) -> Vec<String> {
    let mut v: Vec<String> = fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    v.sort();
    v
}

fn assert_one_clean_line(o: &Output, needle: &str) {
    let err = stderr(o);
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(err.contains(needle), "expected '{needle}' in {err}");
    assert!(
        !err.contains("panicked") && !err.contains("internal error"),
        "{err}"
    );
}

/// The three commands that print, with the output path (if any) they
/// write.
fn printing_commands(dir: &Path) -> Vec<(Vec<PathBuf>, Option<PathBuf>)> {
    let ex = examples();
    let out2 = dir.join("out.wkt");
    let out3 = dir.join("out.obj");
    let outs = dir.join("s.geojson");
    vec![
        (
            vec![p("check").into(), ex.join("a.wkt"), p("--json").into()],
            None,
        ),
        (vec![p("check").into(), ex.join("cube.obj")], None),
        (
            vec![
                p("boolean").into(),
                p("union").into(),
                ex.join("a.wkt"),
                ex.join("b.wkt"),
                p("-o").into(),
                out2.clone(),
                p("--report").into(),
                dir.join("r.json"),
            ],
            Some(out2),
        ),
        (
            vec![
                p("boolean").into(),
                p("difference").into(),
                ex.join("cube.obj"),
                ex.join("cube_shifted.off"),
                p("-o").into(),
                out3.clone(),
            ],
            Some(out3),
        ),
        (
            vec![
                p("simplify").into(),
                ex.join("figure_eight.wkt"),
                p("-o").into(),
                outs.clone(),
                p("--rule").into(),
                p("nonzero").into(),
                p("--keep-orientation").into(),
            ],
            Some(outs),
        ),
    ]
}

#[test]
#[cfg(target_os = "linux")]
fn full_standard_output_exits_1_with_one_line() {
    let dir = temp_dir("full");
    for (args, out) in printing_commands(&dir) {
        let args: Vec<&Path> = args.iter().map(PathBuf::as_path).collect();
        // The reference run, with a working standard output.
        let good = umbra(&args);
        assert!(good.status.success(), "{args:?}: {}", stderr(&good));
        let want = out.as_ref().map(|o| fs::read(o).unwrap());
        if let Some(o) = &out {
            fs::remove_file(o).unwrap();
        }
        let devfull = fs::OpenOptions::new()
            .write(true)
            .open("/dev/full")
            .unwrap();
        let o = umbra_to(&args, Stdio::from(devfull));
        assert_eq!(o.status.code(), Some(1), "{args:?}: {}", stderr(&o));
        assert_one_clean_line(&o, "standard output: cannot write");
        // The output file was written before the summary, and in full.
        if let Some(path) = &out {
            assert_eq!(fs::read(path).ok(), want, "{args:?}");
        }
    }
}

#[test]
fn closed_pipe_is_quiet_and_keeps_the_exit_code() {
    let dir = temp_dir("pipe");
    for (args, out) in printing_commands(&dir) {
        let args: Vec<&Path> = args.iter().map(PathBuf::as_path).collect();
        let o = umbra_closed_pipe(&args);
        assert_eq!(o.status.code(), Some(0), "{args:?}: {}", stderr(&o));
        assert_eq!(stderr(&o), "", "{args:?}");
        if let Some(path) = &out {
            assert!(path.exists(), "{args:?}");
        }
    }
    // An invalid shape still exits 1 with its one line on standard error.
    let huge = write(&dir, "huge.wkt", "POLYGON ((0 0, 1e308 0, 1 1, 0 0))");
    let o = umbra_closed_pipe(&[p("check"), &huge, p("--json")]);
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    assert_one_clean_line(&o, "huge.wkt");
}

const OLD: &str = "POLYGON ((5 5, 6 5, 6 6, 5 5))\n";

#[test]
fn a_report_that_cannot_be_written_leaves_the_output_untouched() {
    let dir = temp_dir("badreport");
    let ex = examples();
    let out = write(&dir, "out.wkt", OLD);
    let before = listing(&dir);
    let bad_reports = [
        dir.join("no/such/dir/r.json"),
        // A directory is not a file.
        {
            let d = dir.join("r.json");
            fs::create_dir_all(&d).unwrap();
            d
        },
    ];
    let before_with_dir = {
        let mut b = before.clone();
        b.push("r.json".into());
        b.sort();
        b
    };
    for report in &bad_reports {
        for args in [
            vec![
                p("boolean"),
                p("union"),
                &ex.join("a.wkt"),
                &ex.join("b.wkt"),
                p("-o"),
                &out,
                p("--report"),
                report,
            ],
            vec![
                p("simplify"),
                &ex.join("figure_eight.wkt"),
                p("-o"),
                &out,
                p("--report"),
                report,
            ],
        ] {
            let o = umbra(&args);
            assert_eq!(o.status.code(), Some(1), "{args:?}: {}", stderr(&o));
            assert_one_clean_line(&o, "r.json: cannot write");
            assert_eq!(fs::read_to_string(&out).unwrap(), OLD, "{args:?}");
            assert_eq!(listing(&dir), before_with_dir, "no temporary file left");
        }
    }
    // A 3D output with a bad report: the old mesh file stays.
    let out3 = write(&dir, "old.off", "OFF\n0 0 0\n");
    let o = umbra(&[
        p("boolean"),
        p("union"),
        &ex.join("cube.obj"),
        &ex.join("cube_shifted.off"),
        p("-o"),
        &out3,
        p("--report"),
        &bad_reports[0],
    ]);
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    assert_eq!(fs::read_to_string(&out3).unwrap(), "OFF\n0 0 0\n");
    // The same command with a good report path writes both.
    let report = dir.join("good.json");
    let o = umbra(&[
        p("boolean"),
        p("union"),
        &ex.join("a.wkt"),
        &ex.join("b.wkt"),
        p("-o"),
        &out,
        p("--report"),
        &report,
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert_ne!(fs::read_to_string(&out).unwrap(), OLD);
    let r: serde_json::Value = serde_json::from_slice(&fs::read(&report).unwrap()).unwrap();
    assert_eq!(r["topologically_valid"], true);
}

#[test]
fn an_output_that_is_an_input_or_the_report_is_refused() {
    let dir = temp_dir("clobber");
    let a = write(&dir, "a.wkt", "POLYGON ((0 0, 2 0, 2 2, 0 2, 0 0))\n");
    let b = write(&dir, "b.wkt", "POLYGON ((1 1, 3 1, 3 3, 1 3, 1 1))\n");
    let out = write(&dir, "out.wkt", OLD);
    let a_text = fs::read_to_string(&a).unwrap();
    // The same file under other names: with `.`, `..` and a symbolic link.
    let dotted = dir.join(".").join("sub").join("..").join("a.wkt");
    fs::create_dir_all(dir.join("sub")).unwrap();
    #[cfg(unix)]
    let linked = {
        let l = dir.join("link.wkt");
        std::os::unix::fs::symlink(&a, &l).unwrap();
        l
    };
    #[cfg(not(unix))]
    let linked = a.clone();
    // A hard link: another name, the same file.
    #[cfg(unix)]
    let hard = {
        let h = dir.join("hard.wkt");
        fs::hard_link(&b, &h).unwrap();
        h
    };
    #[cfg(not(unix))]
    let hard = b.clone();
    let cases: Vec<(Vec<&Path>, &str)> = vec![
        (
            vec![p("boolean"), p("union"), &a, &b, p("-o"), &a],
            "operand A",
        ),
        (
            vec![p("boolean"), p("union"), &a, &b, p("-o"), &b],
            "operand B",
        ),
        (
            vec![p("boolean"), p("union"), &b, &a, p("-o"), &dotted],
            "operand B",
        ),
        (
            vec![p("boolean"), p("union"), &b, &linked, p("-o"), &a],
            "operand B",
        ),
        (
            vec![
                p("boolean"),
                p("union"),
                &a,
                &b,
                p("-o"),
                &out,
                p("--report"),
                &out,
            ],
            "the output",
        ),
        (
            vec![
                p("boolean"),
                p("union"),
                &a,
                &b,
                p("-o"),
                &out,
                p("--report"),
                &a,
            ],
            "operand A",
        ),
        (
            vec![p("boolean"), p("union"), &a, &b, p("-o"), &hard],
            "operand B",
        ),
        (vec![p("simplify"), &a, p("-o"), &a], "the input"),
        (
            vec![p("simplify"), &a, p("-o"), &out, p("--report"), &dotted],
            "the input",
        ),
        (
            vec![p("simplify"), &a, p("-o"), &out, p("--report"), &out],
            "the output",
        ),
    ];
    let before = listing(&dir);
    for (args, needle) in cases {
        let o = umbra(&args);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {}", stderr(&o));
        assert_one_clean_line(&o, needle);
        assert!(stderr(&o).contains("nothing was written"), "{}", stderr(&o));
        assert_eq!(fs::read_to_string(&a).unwrap(), a_text);
        assert_eq!(fs::read_to_string(&out).unwrap(), OLD);
        assert_eq!(listing(&dir), before);
    }
    // The same input twice is fine.
    let o = umbra(&[p("boolean"), p("union"), &a, &a, p("-o"), &out]);
    assert!(o.status.success(), "{}", stderr(&o));
}

/// Rings of a WKT text as written (independent reader): every innermost
/// parenthesised group is one ring; points without the closing duplicate.
fn wkt_rings(text: &str) -> Vec<usize> {
    let mut out = Vec::new();
    let mut start = None;
    for (i, c) in text.char_indices() {
        match c {
            '(' => start = Some(i + 1),
            ')' => {
                if let Some(s) = start.take() {
                    let points: Vec<&str> = text[s..i].split(',').map(str::trim).collect();
                    assert!(points.len() >= 2 && points.first() == points.last());
                    out.push(points.len() - 1);
                }
            }
            _ => {}
        }
    }
    out
}

/// `(vertices, rings)` of a summary line `... N vertices, R rings, ...`.
fn summary_counts(stdout: &[u8]) -> (usize, usize) {
    let text = String::from_utf8_lossy(stdout);
    let number_before = |word: &str| -> usize {
        let i = text
            .find(word)
            .unwrap_or_else(|| panic!("{word} in {text}"));
        text[..i]
            .split_whitespace()
            .last()
            .unwrap()
            .parse()
            .unwrap()
    };
    (number_before(" vertices"), number_before(" rings"))
}

#[test]
fn summary_and_report_count_what_is_written() {
    let dir = temp_dir("counts");
    let square = |x: f64, y: f64| {
        format!(
            "POLYGON (({x} {y}, {} {y}, {} {}, {x} {}, {x} {y}))\n",
            x + 2.0,
            x + 2.0,
            y + 2.0,
            y + 2.0
        )
    };
    let a = write(&dir, "a.wkt", &square(0.0, 0.0));
    // Abutting along an edge: two loops, one ring once written.
    let side = write(&dir, "side.wkt", &square(2.0, 0.0));
    // Touching at a corner.
    let corner = write(&dir, "corner.wkt", &square(2.0, 2.0));
    // A hole touching the outer ring at a vertex, and a spike.
    let spiky = write(
        &dir,
        "spiky.wkt",
        "POLYGON ((0 0, 6 0, 6 6, 3 6, 3 8, 3 6, 0 6, 0 0), (0 0, 2 1, 1 2, 0 0))\n",
    );
    let ex = examples();
    let pairs = [
        (a.clone(), side.clone()),
        (a.clone(), corner.clone()),
        (side.clone(), corner.clone()),
        (spiky.clone(), a.clone()),
        (spiky.clone(), spiky.clone()),
        (ex.join("a.wkt"), ex.join("b.wkt")),
        (ex.join("double_cover.wkt"), ex.join("inside_out.wkt")),
        (ex.join("nested.wkt"), ex.join("b.wkt")),
    ];
    let out = dir.join("out.wkt");
    let report = dir.join("r.json");
    let mut differs = 0;
    for (x, y) in &pairs {
        for op in ["union", "intersection", "difference", "xor"] {
            for via in ["basic", "simplify"] {
                for keep in [false, true] {
                    let mut args = vec![
                        p("boolean"),
                        p(op),
                        x,
                        y,
                        p("-o"),
                        &out,
                        p("--report"),
                        &report,
                        p("--via"),
                        p(via),
                    ];
                    if keep {
                        args.push(p("--keep-orientation"));
                    }
                    let o = umbra(&args);
                    assert!(o.status.success(), "{args:?}: {}", stderr(&o));
                    let written = wkt_rings(&fs::read_to_string(&out).unwrap());
                    let points: usize = written.iter().sum();
                    let r: serde_json::Value =
                        serde_json::from_slice(&fs::read(&report).unwrap()).unwrap();
                    assert_eq!(r["output"]["rings"], written.len(), "{args:?}");
                    assert_eq!(r["output"]["vertices"], points, "{args:?}");
                    assert_eq!(
                        summary_counts(&o.stdout),
                        (points, written.len()),
                        "{args:?}"
                    );
                    // Two loops in the result, one ring once written (the
                    // summary used to say 2 rings here).
                    if op == "union" && x == &a && y == &side && !keep {
                        assert_eq!(written.len(), 1);
                        differs += 1;
                    }
                }
            }
        }
    }
    assert_eq!(differs, 2);
    // `check` names the rings of zero area, so its counts add up.
    let flat = write(
        &dir,
        "flat.wkt",
        "POLYGON ((0 0, 2 0, 2 2, 0 2, 0 0), (1 1, 1 1.5, 1 1))\n",
    );
    let o = umbra(&[p("check"), &flat]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = String::from_utf8_lossy(&o.stdout);
    assert!(
        text.contains("rings: 2 (1 counter-clockwise, 0 clockwise, 1 of zero area)"),
        "{text}"
    );
    let o = umbra(&[p("check"), &a]);
    let text = String::from_utf8_lossy(&o.stdout);
    assert!(
        text.contains("rings: 1 (1 counter-clockwise, 0 clockwise), "),
        "{text}"
    );
    // Simplify too.
    for rule in ["positive", "nonzero", "evenodd"] {
        let o = umbra(&[
            p("simplify"),
            &spiky,
            p("-o"),
            &out,
            p("--rule"),
            p(rule),
            p("--report"),
            &report,
        ]);
        assert!(o.status.success(), "{rule}: {}", stderr(&o));
        let written = wkt_rings(&fs::read_to_string(&out).unwrap());
        let r: serde_json::Value = serde_json::from_slice(&fs::read(&report).unwrap()).unwrap();
        assert_eq!(r["output"]["rings"], written.len());
        assert_eq!(
            summary_counts(&o.stdout),
            (written.iter().sum(), written.len())
        );
    }
}

#[test]
#[cfg(unix)]
fn outputs_through_links_and_to_devices() {
    let dir = temp_dir("links");
    let ex = examples();
    // The output is a symbolic link: the file it points at is replaced,
    // the link stays.
    let real = write(&dir, "real.wkt", OLD);
    let link = dir.join("link.wkt");
    std::os::unix::fs::symlink(&real, &link).unwrap();
    // The report goes to a device that is not a regular file.
    let o = umbra(&[
        p("boolean"),
        p("intersection"),
        &ex.join("a.wkt"),
        &ex.join("b.wkt"),
        p("-o"),
        &link,
        p("--report"),
        p("/dev/null"),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(fs::symlink_metadata(&link)
        .unwrap()
        .file_type()
        .is_symlink());
    let text = fs::read_to_string(&real).unwrap();
    assert!(text.starts_with("POLYGON") || text.starts_with("MULTIPOLYGON"));
    assert_ne!(text, OLD);
    assert_eq!(listing(&dir), ["link.wkt", "real.wkt"]);
}
