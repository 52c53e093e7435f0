//! `scaling`: time against input size for the 3D and 2D Booleans beside
//! their peers, written as CSV and drawn as log-log PNG plots (`plotters`,
//! bitmap backend) for `docs/performance.md`.
//!
//! ```text
//! cargo run --release -p umbra-benches --bin scaling -- [--out docs/images] [--max-3d 2000000] [--max-2d 1000000] [--only 3d|2d] [--manifold3d docs/images/manifold3d.csv]
//! ```
//!
//! - 3D (`scaling-3d.csv`, `scaling-3d.png`): the sphere difference of
//!   `perf-table-3d` (`umbra_benches::solid::sphere_pair`) at 2k to 2M
//!   triangles per operand, on Umbra's triangle and polygon variants,
//!   `manifold-rust` and `boolmesh`, and the C++ Manifold's times from the
//!   CSV of `benches/manifold3d/run.py` when that file exists (the rows
//!   with the most CPUs).
//! - 2D (`scaling-2d.csv`, `scaling-2d.png`): the union of a regular
//!   `n`-gon with its copy rotated by a tenth of an edge's angle (the shape
//!   of a Table 7.4 row at every size), 1k to 1M vertices in all, on
//!   Umbra's basic Boolean, Umbra's sweep (the nonzero simplification of
//!   both rings), the C++ Clipper2, `clipper2-rust`, `i_overlay` and `geo`.
//!
//! Every cell is the best of up to 3 runs (one run when a run takes more
//! than a second); every result is checked (3D: the library's validity
//! check and the volume of Umbra's triangle variant to 1e-9 relative; 2D:
//! one ring of `4n` vertices of the exact area) and a wrong one is drawn
//! as a cross instead of a dot. All threads (rayon's default). The full
//! run took about a minute and a half on two shared cores with the fast
//! release profile; the caps keep it well under ten minutes.

use plotters::prelude::*;
use std::path::{Path, PathBuf};
use std::time::Instant;
use umbra_benches::solid::{
    sphere_pair, Boolmesh, ManifoldRust, SolidPeer, UmbraPolygons, UmbraTriangles,
};
use umbra_benches::sweep::{SweepCase, SweepPeer, SweepRule, UmbraSweep};
use umbra_benches::{
    rotated_ngon_pair, Case, Clipper2, Clipper2Rust, Geo, IOverlay, Peer, RingStats, Umbra,
};

/// One measured point.
#[derive(Clone, Debug)]
struct Point {
    peer: String,
    size: usize,
    ms: f64,
    correct: bool,
}

/// Best of up to 3 runs of `f` (one when a run takes over a second).
fn best<T>(mut f: impl FnMut() -> T) -> (f64, T) {
    let t = Instant::now();
    let mut out = f();
    let mut ms = t.elapsed().as_secs_f64() * 1e3;
    if ms < 1000.0 {
        for _ in 0..2 {
            drop(out);
            let t = Instant::now();
            out = f();
            ms = ms.min(t.elapsed().as_secs_f64() * 1e3);
        }
    }
    (ms, out)
}

fn solid_point<P: SolidPeer>(
    peer: &P,
    a: &topology::TriangleMesh,
    b: &topology::TriangleMesh,
    size: usize,
    reference: Option<f64>,
) -> (Point, f64) {
    let input = peer.prepare(a, b);
    let (ms, out) = best(|| peer.difference(&input));
    let s = peer.stats(&out);
    let correct = s.valid && reference.is_none_or(|v| (s.volume - v).abs() <= 1e-9 * v.abs());
    eprintln!("3d {size}: {} {ms:.1} ms ({s:?})", peer.name());
    (
        Point {
            peer: peer.name().into(),
            size,
            ms,
            correct,
        },
        s.volume,
    )
}

fn scaling_3d(max: usize) -> Vec<Point> {
    let mut points = Vec::new();
    for size in [2_000, 6_000, 20_000, 60_000, 200_000, 600_000, 2_000_000] {
        if size > max {
            continue;
        }
        let (a, b) = sphere_pair(size);
        let (p, volume) = solid_point(&UmbraTriangles, &a, &b, size, None);
        points.push(p);
        let reference = Some(volume);
        points.push(solid_point(&UmbraPolygons, &a, &b, size, reference).0);
        points.push(solid_point(&ManifoldRust, &a, &b, size, reference).0);
        points.push(solid_point(&Boolmesh, &a, &b, size, reference).0);
    }
    points
}

/// The C++ Manifold's sphere differences from the script's CSV, the rows
/// with the most CPUs (the last such row of a size wins).
fn manifold3d_points(path: &Path) -> Vec<Point> {
    let Ok(text) = std::fs::read_to_string(path) else {
        return Vec::new();
    };
    let mut lines = text.lines();
    let header: Vec<&str> = lines.next().unwrap_or("").split(',').collect();
    let col = |name: &str| header.iter().position(|h| *h == name);
    let (Some(op), Some(size), Some(cpus), Some(ms)) =
        (col("op"), col("size"), col("cpus"), col("ms"))
    else {
        return Vec::new();
    };
    let rows: Vec<Vec<&str>> = lines
        .map(|l| l.split(',').collect::<Vec<_>>())
        .filter(|r| r.get(op) == Some(&"sphere-difference"))
        .collect();
    let most = rows
        .iter()
        .filter_map(|r| r.get(cpus)?.parse::<usize>().ok())
        .max()
        .unwrap_or(0);
    let mut points: Vec<Point> = Vec::new();
    for r in rows {
        let (Some(s), Some(c), Some(t)) = (
            r.get(size).and_then(|v| v.parse().ok()),
            r.get(cpus).and_then(|v| v.parse::<usize>().ok()),
            r.get(ms).and_then(|v| v.parse().ok()),
        ) else {
            continue;
        };
        if c != most {
            continue;
        }
        points.retain(|p| p.size != s);
        points.push(Point {
            peer: "manifold3d (C++)".into(),
            size: s,
            ms: t,
            correct: true,
        });
    }
    points
}

fn ring_point<P: Peer>(peer: &P, case: &Case, vertices: usize) -> Point {
    let (a, b) = rotated_ngon_pair(case.n, case.alpha_deg);
    let input = peer.prepare(&[a], &[b]);
    let (ms, out) = best(|| peer.union(&input));
    let stats = peer.stats(&out).unwrap_or_default();
    eprintln!("2d {vertices}: {} {ms:.2} ms ({stats:?})", peer.name());
    Point {
        peer: peer.name().into(),
        size: vertices,
        ms,
        correct: stats.is_exact_union(case),
    }
}

fn sweep_point(case: &Case, vertices: usize) -> Point {
    let (a, b) = rotated_ngon_pair(case.n, case.alpha_deg);
    let sweep = SweepCase {
        label: String::new(),
        rule: SweepRule::NonZero,
        rings: vec![a, b],
        ngon: Some(*case),
        expected: None,
    };
    let Some(input) = UmbraSweep.prepare(&sweep) else {
        return Point {
            peer: "umbra-sweep".into(),
            size: vertices,
            ms: f64::NAN,
            correct: false,
        };
    };
    let (ms, out) = best(|| UmbraSweep.run(&input));
    let correct = UmbraSweep.stats(&out).is_ok_and(|s| {
        RingStats {
            rings: s.rings,
            vertices: s.vertices,
            zero_length_edges: s.zero_length_edges,
            area: s.area,
        }
        .is_exact_union(case)
    });
    eprintln!("2d {vertices}: umbra-sweep {ms:.2} ms (correct {correct})");
    Point {
        peer: "umbra-sweep".into(),
        size: vertices,
        ms,
        correct,
    }
}

fn scaling_2d(max: usize) -> Vec<Point> {
    let mut points = Vec::new();
    for vertices in [1_000, 3_000, 10_000, 30_000, 100_000, 300_000, 1_000_000] {
        if vertices > max {
            continue;
        }
        let n = vertices / 2;
        let case = Case {
            n,
            alpha_deg: 0.1 * 360.0 / n as f64,
        };
        let mut p = ring_point(&Umbra, &case, vertices);
        p.peer = "umbra-basic".into();
        points.push(p);
        points.push(sweep_point(&case, vertices));
        points.push(ring_point(&Clipper2, &case, vertices));
        points.push(ring_point(&Clipper2Rust, &case, vertices));
        points.push(ring_point(&IOverlay, &case, vertices));
        points.push(ring_point(&Geo, &case, vertices));
    }
    points
}

fn write_csv(path: &Path, points: &[Point]) -> Result<(), String> {
    let mut text = String::from("peer,size,ms,correct\n");
    for p in points {
        text.push_str(&format!(
            "{},{},{:.4},{}\n",
            p.peer, p.size, p.ms, p.correct
        ));
    }
    std::fs::write(path, text).map_err(|e| format!("{}: {e}", path.display()))
}

const COLORS: [RGBColor; 7] = [
    RGBColor(214, 39, 40),
    RGBColor(255, 127, 14),
    RGBColor(31, 119, 180),
    RGBColor(44, 160, 44),
    RGBColor(148, 103, 189),
    RGBColor(140, 86, 75),
    RGBColor(23, 190, 207),
];

fn plot(path: &Path, title: &str, x_desc: &str, points: &[Point]) -> Result<(), String> {
    let err = |e: &dyn std::fmt::Display| format!("{}: {e}", path.display());
    let good: Vec<&Point> = points
        .iter()
        .filter(|p| p.ms.is_finite() && p.ms > 0.0)
        .collect();
    let (x0, x1) = good.iter().fold((f64::MAX, 0.0f64), |(lo, hi), p| {
        (lo.min(p.size as f64), hi.max(p.size as f64))
    });
    let (y0, y1) = good.iter().fold((f64::MAX, 0.0f64), |(lo, hi), p| {
        (lo.min(p.ms), hi.max(p.ms))
    });
    if good.is_empty() {
        return Err(format!("{}: nothing to plot", path.display()));
    }
    let root = BitMapBackend::new(path, (960, 640)).into_drawing_area();
    root.fill(&WHITE).map_err(|e| err(&e))?;
    let mut chart = ChartBuilder::on(&root)
        .caption(title, ("sans-serif", 24))
        .margin(16)
        .x_label_area_size(48)
        .y_label_area_size(72)
        .build_cartesian_2d(
            (x0 / 1.3..x1 * 1.3).log_scale(),
            (y0 / 1.5..y1 * 1.5).log_scale(),
        )
        .map_err(|e| err(&e))?;
    chart
        .configure_mesh()
        .x_desc(x_desc)
        .y_desc("time (ms, log scale)")
        .label_style(("sans-serif", 15))
        .x_label_formatter(&|x| human(*x))
        .y_label_formatter(&|y| format!("{y}"))
        .draw()
        .map_err(|e| err(&e))?;
    let mut peers: Vec<&str> = Vec::new();
    for p in &good {
        if !peers.contains(&p.peer.as_str()) {
            peers.push(&p.peer);
        }
    }
    for (i, peer) in peers.iter().enumerate() {
        let color = COLORS[i % COLORS.len()];
        let mut series: Vec<&&Point> = good.iter().filter(|p| p.peer == *peer).collect();
        series.sort_by_key(|p| p.size);
        let line: Vec<(f64, f64)> = series.iter().map(|p| (p.size as f64, p.ms)).collect();
        chart
            .draw_series(LineSeries::new(line, color.stroke_width(2)))
            .map_err(|e| err(&e))?
            .label(*peer)
            .legend(move |(x, y)| {
                PathElement::new(vec![(x, y), (x + 24, y)], color.stroke_width(3))
            });
        for p in series {
            let at = (p.size as f64, p.ms);
            if p.correct {
                chart
                    .draw_series(std::iter::once(Circle::new(at, 4, color.filled())))
                    .map_err(|e| err(&e))?;
            } else {
                chart
                    .draw_series(std::iter::once(Cross::new(at, 7, color.stroke_width(2))))
                    .map_err(|e| err(&e))?;
            }
        }
    }
    chart
        .configure_series_labels()
        .position(SeriesLabelPosition::UpperLeft)
        .label_font(("sans-serif", 16))
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK)
        .draw()
        .map_err(|e| err(&e))?;
    root.present().map_err(|e| err(&e))?;
    Ok(())
}

/// `2k`, `20k`, `2M`.
fn human(x: f64) -> String {
    if x >= 1e6 {
        format!("{}M", x / 1e6)
    } else if x >= 1e3 {
        format!("{}k", x / 1e3)
    } else {
        format!("{x}")
    }
}

fn run() -> Result<(), String> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let value = |name: &str| umbra_benches::flag_value(&args, name);
    let number = |name: &str, default: usize| {
        value(name).map_or(Ok(default), |v| {
            v.parse().map_err(|e| format!("{name}: {e}"))
        })
    };
    let out = PathBuf::from(value("--out").unwrap_or_else(|| "docs/images".into()));
    let only = value("--only");
    let manifold3d = PathBuf::from(
        value("--manifold3d").unwrap_or_else(|| out.join("manifold3d.csv").display().to_string()),
    );
    let (max_3d, max_2d) = (
        number("--max-3d", 2_000_000)?,
        number("--max-2d", 1_000_000)?,
    );
    std::fs::create_dir_all(&out).map_err(|e| format!("{}: {e}", out.display()))?;
    plotters::style::register_font("sans-serif", FontStyle::Normal, dejavu::sans::regular())
        .map_err(|_| "the embedded DejaVu Sans font was refused".to_string())?;
    let threads = rayon::current_num_threads();
    if only.as_deref() != Some("2d") {
        let mut points = scaling_3d(max_3d);
        write_csv(&out.join("scaling-3d.csv"), &points)?;
        points.extend(manifold3d_points(&manifold3d));
        plot(
            &out.join("scaling-3d.png"),
            &format!("3D: sphere minus shifted sphere ({threads} threads)"),
            "triangles per operand (log scale)",
            &points,
        )?;
    }
    if only.as_deref() != Some("3d") {
        let points = scaling_2d(max_2d);
        write_csv(&out.join("scaling-2d.csv"), &points)?;
        plot(
            &out.join("scaling-2d.png"),
            &format!("2D: n-gon union, rotated by 1/10 edge ({threads} threads)"),
            "vertices in both operands (log scale)",
            &points,
        )?;
    }
    Ok(())
}

fn main() {
    if let Err(e) = run() {
        eprintln!("scaling: {e}");
        std::process::exit(1);
    }
}
