//! The clean-up of intermediate results in CSG chains
//! (`CsgOptions::raw_intermediates`): a cube whose corners are carved by
//! spheres centred on them, one difference at a time, first small ones
//! and then larger ones that take every earlier crater away. The spheres'
//! poles lie on the cube's edges and their meridians in its faces, so
//! every Boolean meets degenerate contacts, which symbolic perturbation
//! resolves with coincident vertices and zero-area facets.
//!
//! Oracles: the same shape computed directly (the cube minus only the
//! large spheres) has the real complexity of the result, and the raw
//! chain (every Boolean's output fed on as it is) has the same volume as
//! the cleaned one, since the clean-up moves no point by more than the
//! Boolean's own rounding.

use umbra::{check_mesh, evaluate_csg, parse_csg, CsgOptions, CsgResult};

/// The cube `[-1, 1]^3` minus spheres of the given radii centred on its
/// corners, one difference at a time: every radius at all eight corners
/// in turn.
fn carved_cube(radii: &[f64]) -> String {
    let mut node = r#"{"box": {"size": [2, 2, 2], "center": true}}"#.to_string();
    for r in radii {
        for corner in 0..8 {
            let c = |bit: i32| if corner & bit == 0 { -1 } else { 1 };
            node = format!(
                r#"{{"op": "difference", "children": [{node}, {{"sphere": {{"radius": {r}, "segments": 16}}, "translate": [{}, {}, {}]}}]}}"#,
                c(1),
                c(2),
                c(4)
            );
        }
    }
    node
}

fn evaluate(script: &str, triangulate: bool, raw_intermediates: bool) -> CsgResult {
    let tree = parse_csg(script).unwrap();
    let out = evaluate_csg(
        &tree,
        CsgOptions {
            triangulate,
            contacts: None,
            raw_intermediates,
        },
    )
    .unwrap();
    assert!(
        out.report.topologically_valid,
        "{:?}",
        out.report.topology_error
    );
    out
}

fn close(a: f64, b: f64, rel: f64) -> bool {
    (a - b).abs() <= rel * a.abs().max(b.abs())
}

#[test]
fn chains_over_degenerate_contacts_stay_as_small_as_the_shape() {
    let chain = carved_cube(&[0.2, 0.3, 0.4]);
    let direct = carved_cube(&[0.4]);
    for triangulate in [true, false] {
        let what = if triangulate { "triangles" } else { "polygons" };
        let cleaned = evaluate(&chain, triangulate, false);
        let raw = evaluate(&chain, triangulate, true);
        let shape = evaluate(&direct, triangulate, false);
        // The raw chain meets the degenerate contacts: the clean-up ran.
        assert!(cleaned.report.cleaned > 0, "{what}");
        assert_eq!(raw.report.cleaned, 0, "{what}");
        // No point moved: the three results are one solid.
        let v = cleaned.report.volume;
        assert!(
            close(v, raw.report.volume, 1e-12),
            "{what}: {v} vs {}",
            raw.report.volume
        );
        assert!(
            close(v, shape.report.volume, 1e-12),
            "{what}: {v} vs {}",
            shape.report.volume
        );
        // The chain's result is as large as the shape computed directly
        // (the last Boolean's own raw output, like the direct one's), and
        // smaller than the raw chain's, which grows with every step.
        let (c, r, s) = (
            cleaned.mesh.facets.len(),
            raw.mesh.facets.len(),
            shape.mesh.facets.len(),
        );
        assert!(
            c * 10 <= s * 11,
            "{what}: chain {c} facets, the shape alone {s}"
        );
        assert!(c < r, "{what}: cleaned {c} facets, raw {r}");
        let report = check_mesh(&cleaned.mesh);
        assert!(report.topologically_valid, "{what}");
    }
}

#[test]
fn chains_without_degenerate_contacts_are_not_touched() {
    // Spheres off the corners and off the faces' planes of symmetry: no
    // coincidences, so no clean-up, and the result is the raw chain's
    // bit for bit.
    let mut node = r#"{"box": {"size": [2, 2, 2], "center": true}}"#.to_string();
    for (k, at) in [[0.9, 0.7, 0.8], [-0.8, 0.85, -0.75], [0.7, -0.9, 0.65]]
        .iter()
        .enumerate()
    {
        node = format!(
            r#"{{"op": "difference", "children": [{node}, {{"sphere": {{"radius": {}, "segments": 13}}, "translate": [{}, {}, {}], "rotate": [11, 23, 37]}}]}}"#,
            0.3 + 0.05 * k as f64,
            at[0],
            at[1],
            at[2]
        );
    }
    for triangulate in [true, false] {
        let cleaned = evaluate(&node, triangulate, false);
        let raw = evaluate(&node, triangulate, true);
        assert_eq!(cleaned.report.cleaned, 0);
        assert_eq!(cleaned.mesh, raw.mesh);
    }
}

#[test]
fn parts_united_face_to_face_lose_their_touching_faces_between_booleans() {
    // A 4 x 4 grid of unit cubes, one union node: every Boolean of the
    // balanced tree unites parts that share faces, which the raw outputs
    // keep as separate shells with their touching faces.
    let cubes: Vec<String> = (0..16)
        .map(|k| {
            format!(
                r#"{{"box": {{"size": [1, 1, 1]}}, "translate": [{}, {}, 0]}}"#,
                k % 4,
                k / 4
            )
        })
        .collect();
    let script = format!(r#"{{"op": "union", "children": [{}]}}"#, cubes.join(", "));
    for triangulate in [true, false] {
        let cleaned = evaluate(&script, triangulate, false);
        let raw = evaluate(&script, triangulate, true);
        assert_eq!(cleaned.report.cleaned, 14, "every Boolean but the root's");
        assert_eq!(raw.mesh.facets.len(), 16 * if triangulate { 12 } else { 6 });
        // The root unites two cleaned 4 x 2 slabs, whose inner faces are
        // gone: at most two thirds of the raw tree's facets.
        let (c, r) = (cleaned.mesh.facets.len(), raw.mesh.facets.len());
        assert!(c * 3 <= r * 2, "cleaned {c}, raw {r}");
        assert_eq!(cleaned.report.volume, 16.0);
        assert_eq!(check_mesh(&cleaned.mesh).two_manifold, Some(true));
    }
}
