//! Contacts gathered by a CSG evaluation ([`CsgOptions::contacts`]) and
//! smoothing near them: on the shipped examples, the demo scene, trees
//! under rotated, non-uniformly scaled and translated nodes, a chain over
//! PyVista's nut and sphere as file leaves, and random trees of
//! primitives, smoothing the result near the gathered contacts
//! (what `umbra csg` and `umbra demo` run) gives the same mesh (up to the
//! order of facets and vertices) and the same counts as smoothing it
//! whole, at the default tolerance and at a coarse one that makes
//! smoothing work (random trees: see their test for the one exception);
//! the reached proximity is at least the one asked for; smoothing that
//! changes nothing gives the mesh back as it is.

use std::path::{Path, PathBuf};
use test_support::canonical;
use test_support::rng::Xorshift64Star;
use umbra::{
    default_mesh_tolerance, demo_plant, evaluate_csg, parse_csg, read_csg_file, smooth_solid,
    smooth_solid_near, CsgNode, CsgOptions, DemoDetail, MeshVariant, SmoothOptions,
};

fn examples() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples")
}

/// Evaluates `tree` in both variants with contacts gathered at `coarse`
/// (and at the default), smooths near the contacts and whole, and asserts
/// the same result. Returns the number of smoothing adjustments seen, so
/// that callers can check the comparison was not vacuous.
fn near_equals_whole(tree: &CsgNode, coarse: Option<f64>, what: &str) -> usize {
    let mut adjustments = 0;
    for triangulate in [false, true] {
        let variant = if triangulate {
            MeshVariant::TriangleMesh
        } else {
            MeshVariant::PolygonMesh
        };
        let options = CsgOptions {
            triangulate,
            contacts: Some(coarse.unwrap_or(0.0)),
            raw_intermediates: false,
        };
        let out = evaluate_csg(tree, options).unwrap();
        let what = format!("{what} (triangulate {triangulate})");
        let contacts = out.contacts.as_ref().expect("a Boolean ran");
        let tol = coarse.unwrap_or_else(|| default_mesh_tolerance(&out.mesh));
        assert!(
            contacts.proximity >= tol,
            "{what}: proximity {} below the tolerance {tol}",
            contacts.proximity
        );
        let opts = SmoothOptions::new(tol);
        let whole = smooth_solid(&out.mesh, variant, &opts).unwrap();
        let near = smooth_solid_near(&out.mesh, variant, &opts, contacts).unwrap();
        assert_eq!(near.shape.check_topology(), Ok(()), "{what}");
        assert_eq!(
            canonical::mesh_facets(&near.shape),
            canonical::mesh_facets(&whole.shape),
            "{what}"
        );
        // The same work, but for which of the two kinds of crack splits an
        // edge: in a chain the operands of later Booleans carry unsmoothed
        // slivers of earlier ones, and the region's order can reach an edge
        // by a vertex first where the whole mesh's order reaches it by a
        // crossing edge (the mesh is the same).
        let (mut n, mut w) = (near.report.counts, whole.report.counts);
        assert_eq!(
            n.edges_cracked_by_vertex + n.edges_cracked_between_edges,
            w.edges_cracked_by_vertex + w.edges_cracked_between_edges,
            "{what}"
        );
        (n.edges_cracked_by_vertex, n.edges_cracked_between_edges) = (0, 0);
        (w.edges_cracked_by_vertex, w.edges_cracked_between_edges) = (0, 0);
        assert_eq!(n, w, "{what}");
        if near.report.counts == Default::default() {
            // Nothing to do: the mesh comes back as it is, facets in
            // their order (as whole smoothing gives it).
            assert_eq!(near.shape, out.mesh, "{what}");
        }
        adjustments += whole.report.max_adjustments as usize;
    }
    adjustments
}

/// The largest extent of a tree's result, unsmoothed.
fn extent(tree: &CsgNode) -> f64 {
    let out = evaluate_csg(tree, CsgOptions::default()).unwrap();
    let [lo, hi] = out.mesh.bounding_box().unwrap();
    (0..3).map(|k| hi[k] - lo[k]).fold(0.0, f64::max)
}

#[test]
fn shipped_examples_smooth_near_contacts_as_whole() {
    for name in [
        "bracket.json",
        "flange.json",
        "pipe_tee.json",
        "rounded_die.json",
    ] {
        let tree = read_csg_file(&examples().join(name)).unwrap();
        near_equals_whole(&tree, None, name);
        // A coarse tolerance that merges and cracks.
        let coarse = 2e-3 * extent(&tree);
        near_equals_whole(&tree, Some(coarse), &format!("{name} at {coarse:e}"));
    }
}

#[test]
fn the_demo_scene_smooths_near_contacts_as_whole() {
    let tree = demo_plant(DemoDetail::Coarse);
    near_equals_whole(&tree, None, "demo");
}

/// Booleans under rotated, non-uniformly scaled and translated nodes, and
/// a transformed Boolean inside another Boolean: the contact boxes travel
/// through every transform to the root's frame.
const TRANSFORMED: &str = r#"{"op": "union",
  "rotate": [10, 20, 30], "scale": [1.5, 0.75, 2], "translate": [3, -2, 1],
  "children": [
    {"op": "difference", "rotate": [0, 0, 37], "scale": [0.5, 2, 1],
     "children": [
       {"box": {"size": [2, 2, 2], "center": true}},
       {"cylinder": {"radius": 0.6, "height": 3, "segments": 12, "center": true}, "rotate": [90, 0, 0]}]},
    {"op": "intersection", "translate": [0.8, 0.1, 0.2], "scale": 0.5,
     "children": [
       {"sphere": {"radius": 1.2, "segments": 12}},
       {"box": {"size": [2, 2, 2], "center": true}, "rotate": [45, 45, 0]}]},
    {"torus": {"radius": 1, "tube": 0.25, "segments": [12, 8]}, "translate": [0, 0, 0.9]}]}"#;

#[test]
fn contacts_travel_through_transforms() {
    let tree = parse_csg(TRANSFORMED).unwrap();
    near_equals_whole(&tree, None, "transformed");
    let coarse = 5e-3 * extent(&tree);
    let moved = near_equals_whole(&tree, Some(coarse), "transformed, coarse");
    assert!(moved > 0, "the coarse tolerance should make smoothing work");
}

/// Real meshes nobody here made as file leaves (PyVista's threaded nut
/// and sphere): a chain of Booleans under transforms, near against whole.
#[test]
fn file_leaves_of_real_meshes_smooth_near_contacts_as_whole() {
    let nut = test_support::data_path("pyvista/nut.ply");
    let sphere = test_support::data_path("pyvista/sphere.ply");
    let text = format!(
        r#"{{"op": "difference", "rotate": [5, 10, 15], "children": [
          {{"op": "union", "children": [
            {{"file": {nut:?}}},
            {{"file": {nut:?}, "rotate": [0, 0, 17], "translate": [0.05, -0.03, 0.1]}}]}},
          {{"file": {sphere:?}, "scale": [0.4, 0.4, 2.0]}},
          {{"box": {{"size": [0.3, 0.3, 0.3], "center": true}}, "translate": [0.35, 0, 0]}}]}}"#
    );
    let tree = parse_csg(&text).unwrap();
    near_equals_whole(&tree, None, "nut chain");
    let coarse = 2e-3 * extent(&tree);
    let moved = near_equals_whole(&tree, Some(coarse), "nut chain, coarse");
    assert!(moved > 0, "the coarse tolerance should make smoothing work");
}

#[test]
fn proximity_reaches_what_is_asked_and_small_parts_say_so() {
    let tree = parse_csg(TRANSFORMED).unwrap();
    for want in [1e-9, 1e-3, 0.2] {
        let out = evaluate_csg(
            &tree,
            CsgOptions {
                triangulate: false,
                contacts: Some(want),
                raw_intermediates: false,
            },
        )
        .unwrap();
        assert!(out.contacts.unwrap().proximity >= want, "{want}");
    }
    // No Boolean, or no contacts asked: none gathered.
    let leaf = parse_csg(r#"{"box": {"size": [1, 1, 1]}}"#).unwrap();
    let opts = CsgOptions {
        triangulate: false,
        contacts: Some(0.0),
        raw_intermediates: false,
    };
    assert!(evaluate_csg(&leaf, opts).unwrap().contacts.is_none());
    assert!(evaluate_csg(&tree, CsgOptions::default())
        .unwrap()
        .contacts
        .is_none());
    // A Boolean of parts a hundred-thousandth of the result's size
    // reaches only its own relative proximity, below the result's default
    // tolerance: the caller then smooths the whole mesh.
    let small = parse_csg(
        r#"{"op": "union", "children": [
          {"box": {"size": [1000, 1000, 1000]}},
          {"op": "difference", "translate": [2000, 0, 0], "children": [
            {"box": {"size": [0.01, 0.01, 0.01]}},
            {"box": {"size": [0.01, 0.01, 0.01]}, "translate": [0.005, 0.005, 0.005]}]}]}"#,
    )
    .unwrap();
    let out = evaluate_csg(&small, opts).unwrap();
    assert!(out.contacts.unwrap().proximity < default_mesh_tolerance(&out.mesh));
}

/// A random tree of coarse primitives, overlapping near the origin, with
/// random transforms on some nodes.
fn random_tree(rng: &mut Xorshift64Star, depth: u32) -> String {
    let mut r = |n: u64| rng.next_u64() % n;
    let transform = {
        let mut t = String::new();
        if r(3) == 0 {
            t += &format!(", \"rotate\": [{}, {}, {}]", r(90), r(90), r(90));
        }
        if r(3) == 0 {
            t += &format!(
                ", \"scale\": [{}, {}, {}]",
                0.5 + r(4) as f64 * 0.25,
                0.5 + r(4) as f64 * 0.25,
                0.5 + r(4) as f64 * 0.25
            );
        }
        if r(2) == 0 {
            t += &format!(
                ", \"translate\": [{}, {}, {}]",
                r(9) as f64 * 0.1 - 0.4,
                r(9) as f64 * 0.1 - 0.4,
                r(9) as f64 * 0.1 - 0.4
            );
        }
        t
    };
    if depth == 0 || r(4) == 0 {
        let shape = match r(4) {
            0 => format!(
                "\"box\": {{\"size\": [{}, {}, {}], \"center\": true}}",
                1.0 + r(4) as f64 * 0.25,
                1.0 + r(4) as f64 * 0.25,
                1.0 + r(4) as f64 * 0.25
            ),
            1 => format!(
                "\"sphere\": {{\"radius\": {}, \"segments\": {}}}",
                0.6 + r(4) as f64 * 0.1,
                6 + 2 * r(4)
            ),
            2 => format!(
                "\"cylinder\": {{\"radius\": {}, \"height\": 2, \"segments\": {}, \"center\": true}}",
                0.3 + r(4) as f64 * 0.1,
                5 + r(6)
            ),
            _ => format!(
                "\"torus\": {{\"radius\": 0.7, \"tube\": {}, \"segments\": [{}, 6]}}",
                0.2 + r(3) as f64 * 0.05,
                6 + 2 * r(3)
            ),
        };
        return format!("{{{shape}{transform}}}");
    }
    let op = ["union", "intersection", "difference"][r(3) as usize];
    let n = 2 + r(2);
    let children: Vec<String> = (0..n).map(|_| random_tree(rng, depth - 1)).collect();
    format!(
        "{{\"op\": \"{op}\", \"children\": [{}]{transform}}}",
        children.join(", ")
    )
}

/// Random trees (fixed seeds; `UMBRA_PROPTEST_SCALE` runs more): at the
/// default tolerance, near equals whole in both variants; at a coarse
/// tolerance it does in the polygon variant, while in the triangle
/// variant the order in which the region meets a chain's overlapping
/// slivers can, rarely, resolve them otherwise (one case in about two
/// thousand, at 2% of the extent): there the result is checked to be a
/// valid smoothing whose volume is within both distortion bounds of the
/// whole smoothing's.
#[test]
fn random_trees_smooth_near_contacts_as_whole() {
    let mut seen = 0;
    for seed in 1..=u64::from(test_support::cases(16)) {
        let mut rng = Xorshift64Star::new(seed);
        let text = random_tree(&mut rng, 2);
        let tree = parse_csg(&text).unwrap();
        let raw = evaluate_csg(&tree, CsgOptions::default()).unwrap();
        // An empty result (an intersection of parts that miss) has
        // nothing to smooth.
        if raw.mesh.facets.is_empty() || raw.report.booleans == 0 {
            continue;
        }
        seen += 1;
        near_equals_whole(&tree, None, &text);
        let coarse = 3e-3 * extent(&tree);
        let opts = SmoothOptions::new(coarse);
        for triangulate in [false, true] {
            let (variant, what) = if triangulate {
                (
                    MeshVariant::TriangleMesh,
                    format!("{text} (triangles at {coarse:e})"),
                )
            } else {
                (
                    MeshVariant::PolygonMesh,
                    format!("{text} (polygons at {coarse:e})"),
                )
            };
            let out = evaluate_csg(
                &tree,
                CsgOptions {
                    triangulate,
                    contacts: Some(coarse),
                    raw_intermediates: false,
                },
            )
            .unwrap();
            let contacts = out.contacts.as_ref().unwrap();
            assert!(contacts.proximity >= coarse, "{what}");
            let whole = smooth_solid(&out.mesh, variant, &opts).unwrap();
            let near = smooth_solid_near(&out.mesh, variant, &opts, contacts).unwrap();
            assert_eq!(near.shape.check_topology(), Ok(()), "{what}");
            let same = canonical::mesh_facets(&near.shape) == canonical::mesh_facets(&whole.shape);
            if !triangulate {
                assert!(same, "{what}");
            } else if !same {
                let bound = (near.report.distortion_bound + whole.report.distortion_bound)
                    * test_support::measure::triangle_mesh_area(&umbra::triangulate_mesh(
                        &out.mesh,
                    ));
                let gap = (umbra::mesh_signed_volume(&near.shape)
                    - umbra::mesh_signed_volume(&whole.shape))
                .abs();
                assert!(
                    gap <= bound,
                    "{what}: volumes {gap:e} apart, bound {bound:e}"
                );
            }
        }
    }
    assert!(seen >= 8, "only {seen} trees with a Boolean and a result");
}
