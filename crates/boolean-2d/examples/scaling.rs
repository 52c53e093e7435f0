//! Scaling check of the fast path on the adversarial inputs of a
//! sort-and-sweep broad phase: many long edges that overlap in x but not in
//! y, and many connected components stacked in one column. Every family has
//! no crossing at all (`k = 0`), so the required cost of the Boolean,
//! `O((n + k) log n)` with the broad phase pruning every pair whose `X11`
//! (Table 4.1) is provably 0, must grow like `n log n`.
//!
//! * `comb`: two interleaved combs of long thin horizontal teeth that never
//!   touch (A's spine on the left, B's on the right);
//! * `column`: a column of small squares in A and another, interleaved in
//!   y, in B (one ray cast per square);
//! * `grid`: a checkerboard of unit cells, A's squares in one colour and
//!   B's in the other, each shrunk by an eighth on every side so that
//!   nothing touches.
//!
//! Prints, for `n` = 10^3, 10^4 and 10^5 edges per operand (or the sizes
//! given as arguments), the union's total time and its level-2 phases, and
//! flags a wrong area (nothing touches, so the union's area is the sum of
//! the operands'). Timings only: nothing is asserted.
//!
//! `cargo run --release -p boolean-2d --example scaling [-- [comb] [column] [grid] [SIZES...]]`

use boolean_2d::{boolean, BooleanOp};
use std::time::Instant;
use test_support::shapes::{comb, square};
use topology::PolygonSet2;

/// A comb of `teeth` long thin teeth of length `w - 1` on a spine; with
/// `mirrored`, its mirror image shifted up by 1 (spine on the right, teeth
/// interleaved with the first comb's and never touching them).
fn comb_set(teeth: usize, w: f64, mirrored: bool) -> PolygonSet2 {
    let mut set = PolygonSet2::new();
    set.add_loop(&comb(teeth, w, mirrored, 1.0));
    set
}

/// Axis-aligned squares `[x, x + s] x [y, y + s]`, counter-clockwise, one
/// per origin.
fn squares(origins: impl Iterator<Item = (f64, f64)>, s: f64) -> PolygonSet2 {
    let mut set = PolygonSet2::new();
    for (x, y) in origins {
        set.add_loop(&square(x, y, s));
    }
    set
}

fn family(name: &str, n: usize) -> (PolygonSet2, PolygonSet2) {
    match name {
        "comb" => {
            let teeth = (n / 4).max(1);
            (
                comb_set(teeth, 1000.0, false),
                comb_set(teeth, 1000.0, true),
            )
        }
        "column" => {
            let count = (n / 4).max(1);
            (
                squares((0..count).map(|i| (0.0, 2.0 * i as f64)), 0.75),
                squares((0..count).map(|i| (0.125, 2.0 * i as f64 + 1.0)), 0.75),
            )
        }
        _ => {
            let side = ((n / 2) as f64).sqrt().ceil() as usize;
            let cells = |parity: usize| {
                (0..side * side)
                    .map(move |c| (c / side, c % side))
                    .filter(move |(i, j)| (i + j) % 2 == parity)
                    .map(|(i, j)| (i as f64 + 0.125, j as f64 + 0.125))
            };
            (squares(cells(0), 0.75), squares(cells(1), 0.75))
        }
    }
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let mut sizes: Vec<usize> = args.iter().filter_map(|s| s.parse().ok()).collect();
    if sizes.is_empty() {
        sizes = vec![1_000, 10_000, 100_000];
    }
    let mut names: Vec<&str> = ["comb", "column", "grid"]
        .into_iter()
        .filter(|name| args.iter().any(|a| a == name))
        .collect();
    if names.is_empty() {
        names = vec!["comb", "column", "grid"];
    }
    for name in names {
        for &n in &sizes {
            let (a, b) = family(name, n);
            let clock = Instant::now();
            let out = boolean(&a, &b, BooleanOp::Union).expect("valid input");
            let wall = clock.elapsed().as_secs_f64() * 1e3;
            let t = out.timings;
            // Nothing touches, so the union's area is the sum of the areas.
            let area_ok = out.shape.signed_area() == a.signed_area() + b.signed_area();
            println!(
                "{name:>6} n = {:>6}+{:<6} k = {}{}: {wall:>10.2} ms (broad {:.2}, X11 {:.2}, winding {:.2}, construct {:.2})",
                a.edge_count(),
                b.edge_count(),
                out.intersections,
                if area_ok { "" } else { " (AREA WRONG)" },
                t.broad_phase,
                t.intersections,
                t.winding,
                t.construct,
            );
        }
    }
}
