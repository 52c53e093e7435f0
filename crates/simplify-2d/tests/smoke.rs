//! Temporary smoke test.
mod common;
use common::*;
use simplify_2d::*;

#[test]
fn smoke_random() {
    for seed in 0..200u64 {
        for &n in &[4usize, 8, 16, 40] {
            for &(dx, dy) in &[
                (0.0, 0.0),
                (1.5 * 2f64.powi(49), 1.5 * 2f64.powi(49)),
                (1.5 * 2f64.powi(47), 0.0),
            ] {
                let pts = displace(&random_polygon(n, seed), dx, dy);
                let s = polygon(&pts);
                let c = cell_structure(&s).unwrap_or_else(|e| panic!("seed {seed} n {n}: {e}"));
                c.check_cells()
                    .unwrap_or_else(|e| panic!("seed {seed} n {n} d {dx}: {e}"));
                let out = c.shape_with(|w| *w > 0);
                out.check_topology().unwrap();
            }
        }
    }
}

#[test]
fn smoke_oracle() {
    let mut bad = 0;
    let mut total = 0;
    for seed in 0..100u64 {
        for &n in &[5usize, 12, 30] {
            let pts = if seed.is_multiple_of(2) {
                random_polygon(n, seed)
            } else {
                star(n)
            };
            let s = polygon(&pts);
            let c = cell_structure(&s).unwrap();
            c.check_cells().unwrap();
            let out = c.shape_with(|w| *w > 0);
            let mut r = Rng::new(seed + 1000);
            for _ in 0..100 {
                let p = r.in_disc();
                let segs = cell_segments(&c);
                if segs.iter().any(|&(a, b)| dist_f64(p, a, b) < 1e-9) {
                    continue;
                }
                let w = winding_exact(&s, p);
                let wo = winding_f64(&out, p);
                total += 1;
                if (w > 0) as i32 != wo {
                    bad += 1;
                    eprintln!("seed {seed} n {n} p {p:?} w {w} out {wo}");
                }
            }
        }
    }
    assert_eq!(bad, 0, "{bad} of {total}");
}

#[test]
fn smoke_stars() {
    for &n in &[12usize, 64, 101] {
        for &(dx, dy) in &[
            (0.0, 0.0),
            (1.5 * 2f64.powi(49), 0.0),
            (0.0, 1.5 * 2f64.powi(49)),
            (1.5 * 2f64.powi(49), 1.5 * 2f64.powi(49)),
            (1.5 * 2f64.powi(47), 1.5 * 2f64.powi(47)),
        ] {
            let s = polygon(&displace(&star(n), dx, dy));
            let c = cell_structure(&s).unwrap();
            c.check_cells().unwrap();
            eprintln!(
                "n {n} d ({dx},{dy}) verts {} edges {} kmax {} eps {} stats {:?}",
                c.vertices().len(),
                c.edges().len(),
                c.k_max(),
                c.epsilon(),
                c.stats()
            );
            for rule in [
                FillRule::Positive,
                FillRule::EvenOdd,
                FillRule::NonZero,
                FillRule::AtLeast2,
            ] {
                c.shape_with(|w| rule.contains(*w))
                    .check_topology()
                    .unwrap();
            }
        }
    }
}
