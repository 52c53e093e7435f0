//! Tests of the simplification rows: fill rules and peers agreeing on small rows.

use test_support::shapes::square;
use umbra_benches::sweep::*;
use umbra_benches::{Case, Ring, TABLE_7_4};

fn run<P: SweepPeer>(peer: &P, case: &SweepCase) -> SweepStats {
    let input = peer.prepare(case).expect("the peer applies to the row");
    match peer.stats(&peer.run(&input)) {
        Ok(s) => s,
        Err(e) => panic!("{} on {}: {e}", peer.name(), case.label),
    }
}

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() < 1e-6 * a.abs().max(b.abs()).max(1.0)
}

#[test]
fn umbra_and_i_overlay_agree_on_small_rows() {
    let plain = |label: &str, rings: Vec<Ring>, expected| SweepCase {
        label: label.into(),
        rule: SweepRule::NonZero,
        rings,
        ngon: None,
        expected,
    };
    let cases = [
        plain("checker", checkerboards(6), None),
        plain("nested", nested_squares(10), Some((10, Some(40)))),
        plain("spiral", spirals(400), None),
    ];
    for case in &cases {
        let u = run(&UmbraSweep, case);
        let i = run(&IOverlaySweep { wide: true }, case);
        assert!(close(u.area, i.area), "{}: {u:?} {i:?}", case.label);
        let c = run(&Clipper2Sweep, case);
        let r = run(&Clipper2RustSweep, case);
        assert!(
            close(u.area.abs(), c.area.abs()),
            "{}: {u:?} {c:?}",
            case.label
        );
        assert!(
            close(u.area.abs(), r.area.abs()),
            "{}: {u:?} {r:?}",
            case.label
        );
        assert_eq!(
            (c.rings, c.vertices),
            (r.rings, r.vertices),
            "{}",
            case.label
        );
        if let Some((rings, vertices)) = case.expected {
            assert_eq!(u.rings, rings, "{}", case.label);
            if let Some(v) = vertices {
                assert_eq!(u.vertices, v, "{}", case.label);
            }
        }
    }
    // Two boards of 18 unit cells each, overlapping in part.
    let u = run(&UmbraSweep, &cases[0]);
    assert!(u.area > 18.0 && u.area < 36.0);
}

#[test]
fn the_rows_cover_table_7_4_and_three_fill_rules() {
    let rows = sweep_cases(1000);
    let ngons: Vec<Case> = rows.iter().filter_map(|r| r.ngon).collect();
    assert_eq!(ngons, TABLE_7_4.to_vec());
    for rule in [SweepRule::NonZero, SweepRule::EvenOdd, SweepRule::Positive] {
        assert!(rows.iter().any(|r| r.rule == rule), "{rule:?}");
    }
    let mut labels: Vec<&str> = rows.iter().map(|r| r.label.as_str()).collect();
    labels.sort_unstable();
    labels.dedup();
    assert_eq!(labels.len(), rows.len(), "labels are unique");
    // Random rows above `max_random` are left out, the rule rows with them.
    let small = sweep_cases(500);
    assert!(small
        .iter()
        .all(|r| !r.label.starts_with("random polygon n=1000")));
    assert!(small.iter().all(|r| r.rule == SweepRule::NonZero));
}

#[test]
fn the_fill_rules_mean_the_same_region_in_both_libraries() {
    // A counter-clockwise 4 x 4 square, a clockwise unit square inside
    // it (winding 0 there) and a counter-clockwise square overlapping
    // its corner: winding 2 on 2.25 of area and 1 on the 1.75 outside.
    let mut inner = square(1.0, 1.0, 1.0);
    inner.reverse();
    let rings = vec![square(0.0, 0.0, 4.0), inner, square(2.5, 2.5, 2.0)];
    for (rule, area) in [
        (SweepRule::NonZero, 16.0 - 1.0 + 1.75),
        (SweepRule::EvenOdd, 16.0 - 1.0 - 2.25 + 1.75),
        (SweepRule::Positive, 16.0 - 1.0 + 1.75),
    ] {
        let case = SweepCase {
            label: rule.name().into(),
            rule,
            rings: rings.clone(),
            ngon: None,
            expected: None,
        };
        let u = run(&UmbraSweep, &case);
        let i = run(&IOverlaySweep { wide: true }, &case);
        assert!(close(u.area, area), "umbra {rule:?}: {u:?}");
        assert!(close(i.area, area), "i_overlay {rule:?}: {i:?}");
        let c = run(&Clipper2Sweep, &case);
        let r = run(&Clipper2RustSweep, &case);
        assert!(close(c.area.abs(), area), "clipper2 {rule:?}: {c:?}");
        assert!(close(r.area.abs(), area), "clipper2-rust {rule:?}: {r:?}");
    }
    // Positive and nonzero differ once a loop is clockwise outside.
    let mut cw = square(10.0, 10.0, 1.0);
    cw.reverse();
    let case = SweepCase {
        label: "cw".into(),
        rule: SweepRule::Positive,
        rings: vec![square(0.0, 0.0, 1.0), cw],
        ngon: None,
        expected: None,
    };
    assert!(close(run(&UmbraSweep, &case).area, 1.0));
    assert!(close(run(&IOverlaySweep { wide: true }, &case).area, 1.0));
}

#[test]
fn the_boolean_peer_gets_the_n_gon_union() {
    let case = ngon_case(Case {
        n: 100,
        alpha_deg: 1.0e-2,
    });
    for wide in [false, true] {
        let s = run(&IOverlayBoolSweep { wide }, &case);
        assert_eq!((s.rings, s.vertices, s.zero_length_edges), (1, 400, 0));
    }
    let u = run(&UmbraSweep, &case);
    assert_eq!((u.rings, u.vertices, u.zero_length_edges), (1, 400, 0));
    assert!(IOverlayBoolSweep::default()
        .prepare(&random_case(10, SweepRule::NonZero))
        .is_none());
}
