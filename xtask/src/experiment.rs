//! `cargo xtask arith-experiment`: the experiment of section 8.3.
//!
//! Random segment pairs with end points uniform in `[-1, 1]^2` (so `L = 1`)
//! are drawn until the 2D pyramid deems them to intersect (`X11 != 0`,
//! `shadow_2d::x11`, Table 4.1). The point is computed by Table 7.1 then
//! Table 7.2 (`y_at_x` at the two ends of the x-overlap, then
//! `interpolate`), and checked to be the point `x11` returns. Its exact
//! distance from each segment (big-integer arithmetic) is compared with
//! `sqrt(153) u L` (eq. 8.17); the maximum over the farther segment, the
//! distribution, and the distance from the true intersection point (which
//! has no bound, section 8.2) are reported.

use rayon::prelude::*;
use robust_arith::{interpolate, y_at_x, INTERSECTION_ERROR_FACTOR, UNIT_ROUNDOFF};
use test_support::exact::{distance_to_line_intersection, distance_to_segment};
use test_support::rng::SplitMix64;

type P = [f64; 2];

/// Pairs per parallel chunk (each chunk its own random stream).
const CHUNK: usize = 1 << 14;

/// The figures of one run.
#[derive(Clone, Debug, Default)]
pub struct ExperimentReport {
    /// Intersecting pairs measured.
    pub pairs: usize,
    /// Pairs drawn in all (including non-intersecting ones).
    pub drawn: usize,
    /// Maximum distance (units of `u`) of the point from the farther
    /// segment.
    pub max_far: f64,
    /// The pair attaining `max_far`.
    pub worst: Option<([P; 2], [P; 2], P)>,
    /// Maximum distance from the segment of smaller absolute slope.
    pub max_flatter: f64,
    /// Maximum distance from the segment of larger absolute slope.
    pub max_steeper: f64,
    /// Pairs with the farther distance below `1 u`.
    pub below_1u: usize,
    /// Pairs with the farther distance below `1.5 u`.
    pub below_1_5u: usize,
    /// Pairs with the farther distance below `2 u`.
    pub below_2u: usize,
    /// Pairs beyond `sqrt(153) u` (eq. 8.17 violated: a bug).
    pub beyond_bound: usize,
    /// Maximum distance from the true intersection point of the lines.
    pub max_true: f64,
    /// Pairs where `x11` and the Table 7.1/7.2 path disagree (a bug).
    pub path_mismatches: usize,
}

impl ExperimentReport {
    fn merge(mut self, o: ExperimentReport) -> ExperimentReport {
        self.pairs += o.pairs;
        self.drawn += o.drawn;
        if o.max_far > self.max_far {
            self.max_far = o.max_far;
            self.worst = o.worst;
        }
        self.max_flatter = self.max_flatter.max(o.max_flatter);
        self.max_steeper = self.max_steeper.max(o.max_steeper);
        self.below_1u += o.below_1u;
        self.below_1_5u += o.below_1_5u;
        self.below_2u += o.below_2u;
        self.beyond_bound += o.beyond_bound;
        self.max_true = self.max_true.max(o.max_true);
        self.path_mismatches += o.path_mismatches;
        self
    }
}

/// The y of segment `p - q` (not vertical) at `x`, by Table 7.1.
fn y_on(p: P, q: P, x: f64) -> f64 {
    if p[0] < q[0] {
        y_at_x(p, q, x)
    } else {
        y_at_x(q, p, x)
    }
}

/// Table 7.1 at both ends of the x-overlap, then Table 7.2 with the end
/// where B shadows A (eq. 4.1) as "left".
pub fn table_7_2_point(a: [P; 2], b: [P; 2]) -> Option<P> {
    let x_l = a[0][0].min(a[1][0]).max(b[0][0].min(b[1][0]));
    let x_r = a[0][0].max(a[1][0]).min(b[0][0].max(b[1][0]));
    if x_l >= x_r {
        return None;
    }
    let (yal, yar) = (y_on(a[0], a[1], x_l), y_on(a[0], a[1], x_r));
    let (ybl, ybr) = (y_on(b[0], b[1], x_l), y_on(b[0], b[1], x_r));
    match (ybl >= yal, ybr >= yar) {
        (true, false) => Some(interpolate(x_l, yal, ybl, x_r, yar, ybr)),
        (false, true) => Some(interpolate(x_r, yar, ybr, x_l, yal, ybl)),
        _ => None,
    }
}

fn slope(s: [P; 2]) -> f64 {
    ((s[1][1] - s[0][1]) / (s[1][0] - s[0][0])).abs()
}

fn run_chunk(seed: u64, index: u64, pairs: usize) -> ExperimentReport {
    let mut rng = SplitMix64::stream(seed, index);
    let mut r = ExperimentReport::default();
    while r.pairs < pairs {
        r.drawn += 1;
        let a = [[rng.pm1(), rng.pm1()], [rng.pm1(), rng.pm1()]];
        let b = [[rng.pm1(), rng.pm1()], [rng.pm1(), rng.pm1()]];
        let hit = match shadow_2d::x11(&a[0], &a[1], &b[0], &b[1]) {
            Ok(h) => h,
            Err(_) => {
                r.path_mismatches += 1;
                continue;
            }
        };
        let own = table_7_2_point(a, b);
        let Some(h) = hit else {
            if own.is_some() {
                r.path_mismatches += 1;
            }
            continue;
        };
        let Some(p) = own else {
            r.path_mismatches += 1;
            continue;
        };
        if p != h.a || h.a != h.b {
            r.path_mismatches += 1;
        }
        r.pairs += 1;
        let da = distance_to_segment(p, a[0], a[1], 0) / UNIT_ROUNDOFF;
        let db = distance_to_segment(p, b[0], b[1], 0) / UNIT_ROUNDOFF;
        let far = da.max(db);
        let (flat, steep) = if slope(a) < slope(b) {
            (da, db)
        } else {
            (db, da)
        };
        r.max_flatter = r.max_flatter.max(flat);
        r.max_steeper = r.max_steeper.max(steep);
        if far > r.max_far {
            r.max_far = far;
            r.worst = Some((a, b, p));
        }
        r.below_1u += usize::from(far < 1.0);
        r.below_1_5u += usize::from(far < 1.5);
        r.below_2u += usize::from(far < 2.0);
        r.beyond_bound += usize::from(far > INTERSECTION_ERROR_FACTOR);
        let dt = distance_to_line_intersection(p, a[0], a[1], b[0], b[1], 0) / UNIT_ROUNDOFF;
        if dt.is_finite() {
            r.max_true = r.max_true.max(dt);
        }
    }
    r
}

/// Runs the experiment over `pairs` intersecting pairs from `seed`, in
/// parallel chunks (the result does not depend on the thread count).
pub fn run(pairs: usize, seed: u64) -> ExperimentReport {
    let chunks = pairs.div_ceil(CHUNK);
    (0..chunks)
        .into_par_iter()
        .map(|i| {
            let n = CHUNK.min(pairs - i * CHUNK);
            run_chunk(seed, i as u64, n)
        })
        .reduce(ExperimentReport::default, ExperimentReport::merge)
}

/// Prints the report in the form of section 8.3.
pub fn print(r: &ExperimentReport, seed: u64) {
    let pct = |n: usize| 100.0 * n as f64 / r.pairs.max(1) as f64;
    println!("section 8.3 experiment: segment pairs with end points uniform in [-1,1]^2 (L = 1, u = 2^-53), seed {seed}");
    println!(
        "  intersecting pairs (X11 != 0):        {} (of {} drawn)",
        r.pairs, r.drawn
    );
    println!(
        "  max distance from the farther segment: {:.3} u   (dissertation: 2.57 u over 10^7; bound sqrt(153) = {:.2} u)",
        r.max_far, INTERSECTION_ERROR_FACTOR
    );
    println!(
        "    from the flatter segment:           {:.3} u",
        r.max_flatter
    );
    println!(
        "    from the steeper segment:           {:.3} u",
        r.max_steeper
    );
    println!(
        "  share below 1 u:                      {:.4}%   (dissertation: 99.87%)",
        pct(r.below_1u)
    );
    println!(
        "  share below 1.5 u:                    {:.4}%   (dissertation: 99.99%)",
        pct(r.below_1_5u)
    );
    println!(
        "  share below 2 u:                      {:.5}%",
        pct(r.below_2u)
    );
    println!("  beyond sqrt(153) u (eq. 8.17 broken): {}", r.beyond_bound);
    println!(
        "  max distance from the true intersection point: {:.1} u   (unbounded; dissertation saw > 324 u)",
        r.max_true
    );
    println!(
        "  x11 / Table 7.1+7.2 path disagreements: {}",
        r.path_mismatches
    );
    if let Some((a, b, p)) = r.worst {
        println!("  worst pair: A {a:?}, B {b:?} -> {p:?}");
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn small_run_is_within_the_bound_and_deterministic() {
        let r = run(20_000, 7);
        assert_eq!(r.pairs, 20_000);
        assert_eq!(r.beyond_bound, 0);
        assert_eq!(r.path_mismatches, 0);
        assert!(r.max_far > 0.1 && r.max_far <= INTERSECTION_ERROR_FACTOR);
        assert!(r.below_1u <= r.below_1_5u && r.below_1_5u <= r.pairs);
        let again = run(20_000, 7);
        assert_eq!(again.max_far, r.max_far);
    }
}
