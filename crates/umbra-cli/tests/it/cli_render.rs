//! End-to-end tests of `umbra render`: pictures of meshes and polygon
//! files decoded back and judged by their pixels (size, coverage, the
//! highlight colour exactly when `umbra check` finds problems), SVG parsed
//! back, identical bytes across runs and thread counts, and bad options
//! and hostile sizes refused as usage errors (exit 2) without writing.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};
use std::sync::atomic::{AtomicUsize, Ordering};

static COUNTER: AtomicUsize = AtomicUsize::new(0);

/// The highlight colour of the pictures.
const HIGHLIGHT: [u8; 3] = [230, 20, 120];

fn temp_dir(tag: &str) -> PathBuf {
    let n = COUNTER.fetch_add(1, Ordering::SeqCst);
    let dir = std::env::temp_dir().join(format!("umbra-render-{}-{n}-{tag}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn umbra_env(args: &[&str], threads: Option<&str>) -> Output {
    let mut c = Command::new(env!("CARGO_BIN_EXE_umbra"));
    c.args(args);
    if let Some(t) = threads {
        c.env("RAYON_NUM_THREADS", t);
    }
    c.output().unwrap()
}

fn umbra(args: &[&str]) -> Output {
    umbra_env(args, None)
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// A closed box as OFF text, and the same with its top missing.
fn box_off(open: bool) -> String {
    let faces = [
        "4 0 3 2 1",
        "4 4 5 6 7",
        "4 0 1 5 4",
        "4 1 2 6 5",
        "4 2 3 7 6",
        "4 3 0 4 7",
    ];
    let faces: Vec<&str> = faces
        .iter()
        .enumerate()
        .filter(|&(i, _)| !(open && i == 1))
        .map(|(_, f)| *f)
        .collect();
    format!(
        "OFF\n8 {} 0\n0 0 0\n2 0 0\n2 1 0\n0 1 0\n0 0 1\n2 0 1\n2 1 1\n0 1 1\n{}\n",
        faces.len(),
        faces.join("\n")
    )
}

fn write(dir: &Path, name: &str, text: &str) -> PathBuf {
    let p = dir.join(name);
    std::fs::write(&p, text).unwrap();
    p
}

/// Decodes a PNG: width, height, RGB pixels.
fn decode(path: &Path) -> (u32, u32, Vec<[u8; 3]>) {
    let decoder = png::Decoder::new(std::io::BufReader::new(std::fs::File::open(path).unwrap()));
    let mut reader = decoder.read_info().unwrap();
    let mut buf = vec![0; reader.output_buffer_size().unwrap()];
    let info = reader.next_frame(&mut buf).unwrap();
    assert_eq!(info.color_type, png::ColorType::Rgb);
    let px = buf[..info.buffer_size()]
        .chunks(3)
        .map(|c| [c[0], c[1], c[2]])
        .collect();
    (info.width, info.height, px)
}

fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

#[test]
fn a_box_renders_in_every_view_at_the_size_asked() {
    let dir = temp_dir("views");
    let input = write(&dir, "box.off", &box_off(false));
    for view in ["iso", "front", "top", "side"] {
        let out = dir.join(format!("{view}.png"));
        let o = umbra(&[
            "render",
            s(&input),
            "-o",
            s(&out),
            "--view",
            view,
            "--size",
            "320x200",
        ]);
        assert!(o.status.success(), "{view}: {}", stderr(&o));
        let (w, h, px) = decode(&out);
        assert_eq!((w, h), (320, 200));
        let share = px.iter().filter(|&&c| c != [255; 3]).count() as f64 / 64_000.0;
        assert!((0.1..0.9).contains(&share), "{view}: {share}");
        assert!(!px.contains(&HIGHLIGHT));
    }
}

#[test]
fn highlight_is_present_exactly_when_check_finds_problems() {
    let dir = temp_dir("highlight");
    for (name, open) in [("closed.off", false), ("open.off", true)] {
        let input = write(&dir, name, &box_off(open));
        let check = umbra(&["check", s(&input)]);
        let out = dir.join(format!("{name}.png"));
        let o = umbra(&["render", s(&input), "-o", s(&out), "--highlight"]);
        assert!(o.status.success(), "{name}: {}", stderr(&o));
        let (_, _, px) = decode(&out);
        let marked = px.iter().filter(|&&c| c == HIGHLIGHT).count();
        assert_eq!(check.status.success(), marked == 0, "{name}: {marked}");
        let svg = dir.join(format!("{name}.svg"));
        let o = umbra(&["render", s(&input), "-o", s(&svg), "--highlight"]);
        assert!(o.status.success(), "{}", stderr(&o));
        let text = std::fs::read_to_string(&svg).unwrap();
        roxmltree::Document::parse(&text).unwrap();
        assert_eq!(check.status.success(), !text.contains("#e61478"), "{name}");
    }
}

#[test]
fn polygon_files_render_filled_and_in_topology_style() {
    let dir = temp_dir("2d");
    let input = write(
        &dir,
        "a.wkt",
        "POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0), (1 1, 1 3, 3 3, 3 1, 1 1))",
    );
    for style in ["filled", "topology"] {
        for ext in ["png", "svg"] {
            let out = dir.join(format!("{style}.{ext}"));
            let o = umbra(&[
                "render",
                s(&input),
                "-o",
                s(&out),
                "--style",
                style,
                "--size",
                "300x150",
            ]);
            assert!(o.status.success(), "{style}: {}", stderr(&o));
            if ext == "png" {
                let (w, h, px) = decode(&out);
                assert_eq!((w, h), (300, 150));
                // The centre (in the hole) is background; a point of the
                // ring is shaded.
                assert_eq!(px[75 * 300 + 150], [255; 3]);
                assert_ne!(px[75 * 300 + 150 - 55], [255; 3]);
            } else {
                let text = std::fs::read_to_string(&out).unwrap();
                let doc = roxmltree::Document::parse(&text).unwrap();
                assert_eq!(doc.root_element().attribute("width"), Some("300"));
            }
        }
    }
}

#[test]
fn keep_orientation_draws_the_rings_as_written() {
    // A clockwise square: by role it is an outer ring (winding +1, blue);
    // as written it winds -1 (orange).
    let dir = temp_dir("orientation");
    let input = write(&dir, "cw.wkt", "POLYGON ((0 0, 0 4, 4 4, 4 0, 0 0))");
    let centre = |extra: &[&str]| {
        let out = dir.join("out.png");
        let mut args = vec!["render", s(&input), "-o", s(&out), "--size", "50x50"];
        args.extend(extra);
        let o = umbra(&args);
        assert!(o.status.success(), "{}", stderr(&o));
        decode(&out).2[25 * 50 + 25]
    };
    let (by_role, as_written) = (centre(&[]), centre(&["--keep-orientation"]));
    assert!(by_role[2] > by_role[0], "{by_role:?}");
    assert!(as_written[0] > as_written[2], "{as_written:?}");
}

#[test]
fn output_is_the_same_bytes_across_runs_and_thread_counts() {
    let dir = temp_dir("determinism");
    let input = write(&dir, "box.off", &box_off(true));
    let mut outputs = Vec::new();
    for (i, threads) in [Some("1"), Some("2"), None].into_iter().enumerate() {
        let out = dir.join(format!("{i}.png"));
        let o = umbra_env(
            &[
                "render",
                s(&input),
                "-o",
                s(&out),
                "--highlight",
                "--style",
                "topology",
            ],
            threads,
        );
        assert!(o.status.success(), "{}", stderr(&o));
        outputs.push(std::fs::read(&out).unwrap());
    }
    assert_eq!(outputs[0], outputs[1]);
    assert_eq!(outputs[0], outputs[2]);
}

#[test]
fn bad_options_and_hostile_sizes_are_usage_errors_and_write_nothing() {
    let dir = temp_dir("bad");
    let mesh = write(&dir, "box.off", &box_off(false));
    let set = write(&dir, "a.wkt", "POLYGON ((0 0, 1 0, 1 1, 0 0))");
    let out = dir.join("out.png");
    let cases: Vec<(Vec<&str>, &str)> = vec![
        (vec!["--view", "diagonal"], "diagonal"),
        (vec!["--style", "sketchy"], "sketchy"),
        (vec!["--size", "0x0"], "0x0"),
        (vec!["--size", "100000x100000"], "100000x100000"),
        (vec!["--size", "16384x16384"], "8192"),
        (vec!["--size", "800"], "WxH"),
        (vec!["--size=-3x4"], "WxH"),
        (vec!["--size", "99999999999x1"], "WxH"),
    ];
    for (extra, needle) in cases {
        let start = std::time::Instant::now();
        let mut args = vec!["render", s(&mesh), "-o", s(&out)];
        args.extend(extra.iter());
        let o = umbra(&args);
        assert_eq!(o.status.code(), Some(2), "{extra:?}: {}", stderr(&o));
        assert!(stderr(&o).contains(needle), "{extra:?}: {}", stderr(&o));
        assert!(start.elapsed().as_secs() < 5);
        assert!(!out.exists());
    }
    // A picture is .png or .svg.
    let o = umbra(&["render", s(&mesh), "-o", s(&dir.join("out.jpg"))]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(stderr(&o).contains(".png or .svg"), "{}", stderr(&o));
    // Highlighting is for meshes.
    let o = umbra(&["render", s(&set), "-o", s(&out), "--highlight"]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    // The output may not be the input.
    let same = dir.join("same.svg");
    std::fs::write(&same, "x").unwrap();
    let o = umbra(&["render", s(&same), "-o", s(&same)]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert_eq!(std::fs::read(&same).unwrap(), b"x");
    // A missing input: exit 1, naming the file.
    let o = umbra(&["render", s(&dir.join("none.off")), "-o", s(&out)]);
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    assert!(stderr(&o).contains("none.off"));
    assert!(!out.exists());
}

#[test]
fn other_commands_point_a_png_output_to_render() {
    let dir = temp_dir("png-elsewhere");
    let a = write(&dir, "a.wkt", "POLYGON ((0 0, 1 0, 1 1, 0 0))");
    let o = umbra(&["simplify", s(&a), "-o", s(&dir.join("out.png"))]);
    assert_ne!(o.status.code(), Some(0));
    assert!(stderr(&o).contains("umbra render"), "{}", stderr(&o));
}
