//! Tests of the Clipper2 grid: both engines see the same points.

use umbra_benches::clipper::*;

#[test]
fn both_engines_see_the_same_grid_points() {
    let rings = vec![vec![[0.1, -0.25], [1000.0, 3.0], [-999.5, 0.3]]];
    let cpp = cpp_paths(&rings);
    let rust = rust_paths(&rings);
    let a: Vec<(i64, i64)> = cpp
        .iter()
        .flat_map(|p| p.iter().map(|q| (q.x_scaled(), q.y_scaled())))
        .collect();
    let b: Vec<(i64, i64)> = rust.iter().flatten().map(|q| (q.x, q.y)).collect();
    assert_eq!(a, b);
    // Back to within half a grid unit.
    for (r, s) in rings[0].iter().zip(&rust_rings(&rust)[0]) {
        assert!((r[0] - s[0]).abs() <= 0.5 / SCALE * 1.0001);
        assert!((r[1] - s[1]).abs() <= 0.5 / SCALE * 1.0001);
    }
    assert_eq!(cpp_rings(&cpp), rust_rings(&rust));
}
