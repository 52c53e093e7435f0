//! Clean solids from the shipped CSG examples and the demo scene: their
//! parts overlap by a positive amount instead of touching or sharing
//! faces, so the basic Boolean (which resolves coincidences by symbolic
//! perturbation, leaving zero-thickness sheets and slivers) gives
//! 2-manifold output without self-intersecting facet pairs, in the
//! polygon variant and the triangle variant.

use std::path::{Path, PathBuf};
use std::time::Instant;
use umbra::{check_mesh, demo_plant, evaluate_csg, read_csg_file, CsgNode, CsgOptions, DemoDetail};

fn examples() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples")
}

/// Evaluates `tree` in both variants and asserts a valid, 2-manifold,
/// self-intersection-free solid; returns the volumes (polygon, triangle).
fn assert_clean(tree: &CsgNode, what: &str) -> [f64; 2] {
    let mut volumes = [0.0; 2];
    for (k, triangulate) in [false, true].into_iter().enumerate() {
        let t = Instant::now();
        let out = evaluate_csg(tree, CsgOptions { triangulate }).unwrap();
        let r = check_mesh(&out.mesh);
        eprintln!(
            "{what} (triangulate {triangulate}): {:.1} s, {} facets, 2-manifold {:?} ({:?} edges, {:?} vertices), self-intersecting pairs {:?}, volume {:?}",
            t.elapsed().as_secs_f64(),
            r.facets,
            r.two_manifold,
            r.non_manifold_edges,
            r.non_manifold_vertices,
            r.self_intersecting_facet_pairs,
            r.signed_volume,
        );
        assert!(r.is_valid(), "{what}: {:?}", r.topology_error);
        assert!(out.report.topologically_valid, "{what}");
        assert_eq!(r.non_manifold_edges, Some(0), "{what} ({triangulate})");
        assert_eq!(r.two_manifold, Some(true), "{what} ({triangulate})");
        assert_eq!(
            r.self_intersecting_facet_pairs,
            Some(0),
            "{what} ({triangulate})"
        );
        volumes[k] = r.signed_volume.unwrap();
        assert!(volumes[k] > 0.0);
    }
    volumes
}

#[test]
fn every_shipped_example_is_a_clean_solid() {
    let mut names = Vec::new();
    for entry in std::fs::read_dir(examples()).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().and_then(|e| e.to_str()) == Some("json") {
            names.push(path);
        }
    }
    names.sort();
    assert!(names.len() >= 4, "examples/*.json missing");
    for path in names {
        let tree = read_csg_file(&path).unwrap();
        let [p, t] = assert_clean(&tree, &path.display().to_string());
        assert!((p - t).abs() <= 1e-9 * p, "{}: {p} vs {t}", path.display());
    }
}

#[test]
fn the_coarse_demo_plant_is_a_clean_solid() {
    assert_clean(&demo_plant(DemoDetail::Coarse), "coarse demo");
}

#[test]
fn the_full_demo_plant_is_a_clean_solid() {
    assert_clean(&demo_plant(DemoDetail::Full), "full demo");
}

#[test]
#[ignore]
fn probe() {
    let path = std::env::var("PROBE").unwrap();
    let tree = read_csg_file(Path::new(&path)).unwrap();
    for triangulate in [false, true] {
        let out = evaluate_csg(&tree, CsgOptions { triangulate }).unwrap();
        let r = check_mesh(&out.mesh);
        eprintln!(
            "PROBE {path} tri={triangulate}: facets {}, nm edges {:?}, nm vertices {:?}, self {:?}, vol {:?}",
            r.facets, r.non_manifold_edges, r.non_manifold_vertices, r.self_intersecting_facet_pairs, r.signed_volume
        );
    }
}
