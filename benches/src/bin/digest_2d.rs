//! `digest-2d`: a digest of Umbra's 2D results on the bench inputs, so that
//! a speed change can show its outputs are unchanged bit for bit (run
//! before and after, compare the lines; `cargo xtask fingerprint` does the
//! same over the seeded verification corpora).
//!
//! ```text
//! cargo run --release -p umbra-benches --bin digest-2d -- [--max-random 2000] [--max-scaling 100000]
//! ```
//!
//! One line per input: the basic Boolean's union (and intersection and
//! difference) of every Table 7.4 row and of the scaling n-gons up to
//! `--max-scaling` vertices, and simplification of every row of
//! `perf-table-simplify` (random polygons up to `--max-random`
//! vertices). Each line hashes (64-bit FNV-1a) the `Debug` text of the
//! output shape, which prints every `f64` in its shortest round-trip form,
//! with the epsilon and counters of the result.

use boolean_2d::{boolean, BooleanOp};
use simplify_2d::simplify;
use topology::PolygonSet2;
use umbra_benches::sweep::sweep_cases;
use umbra_benches::{flag_value, rotated_ngon_pair, Case, Ring, TABLE_7_4};

/// 64-bit FNV-1a of `text`.
fn fnv(text: &str) -> u64 {
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    for &b in text.as_bytes() {
        h ^= u64::from(b);
        h = h.wrapping_mul(0x0000_0100_0000_01b3);
    }
    h
}

fn set_of(rings: &[&Ring]) -> PolygonSet2 {
    let mut set = PolygonSet2::new();
    for r in rings {
        set.add_loop(r);
    }
    set
}

fn boolean_lines(label: &str, case: Case) {
    let (a, b) = rotated_ngon_pair(case.n, case.alpha_deg);
    let (a, b) = (set_of(&[&a]), set_of(&[&b]));
    for op in BooleanOp::BASIC {
        let text = match boolean(&a, &b, op) {
            Ok(out) => format!("{:?} {:?} {}", out.shape, out.epsilon, out.intersections),
            Err(e) => e.to_string(),
        };
        println!("boolean {label} {op:?} {:016x}", fnv(&text));
    }
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let number = |name: &str, default: usize| -> usize {
        flag_value(&args, name)
            .and_then(|v| v.parse().ok())
            .unwrap_or(default)
    };
    let max_random = number("--max-random", 2000);
    let max_scaling = number("--max-scaling", 100_000);
    for case in TABLE_7_4 {
        boolean_lines(&format!("n={} alpha={}", case.n, case.alpha_deg), case);
    }
    for vertices in [1_000, 3_000, 10_000, 30_000, 100_000, 300_000, 1_000_000] {
        if vertices > max_scaling {
            continue;
        }
        let n = vertices / 2;
        let case = Case {
            n,
            alpha_deg: 0.1 * 360.0 / n as f64,
        };
        boolean_lines(&format!("scaling {vertices}"), case);
    }
    for case in sweep_cases(max_random) {
        let rings: Vec<&Ring> = case.rings.iter().collect();
        let set = set_of(&rings);
        let text = match simplify(&set, case.rule.umbra()) {
            Ok(out) => format!(
                "{:?} {} {:?} {:?}",
                out.shape, out.k_max, out.epsilon, out.stats
            ),
            Err(e) => e.to_string(),
        };
        println!("simplify {} {:016x}", case.label, fnv(&text));
    }
}
