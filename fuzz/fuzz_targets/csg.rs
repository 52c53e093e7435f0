//! Fuzz target: CSG trees of coarse primitives under arbitrary rotations,
//! scales (non-uniform, mirroring, zero: refused) and translations. The
//! evaluation with contacts gathered never panics and refuses only bad
//! scripts (a zero scale, xor in 3D); a result is topologically valid in
//! both variants, its contacts reach the asked proximity, and smoothing
//! it near them at the default tolerance (what `umbra csg` runs) keeps it
//! closed, gives back a mesh it has nothing to do on unchanged, and
//! agrees with whole smoothing on every facet.
#![no_main]

use libfuzzer_sys::fuzz_target;
use umbra::{
    default_mesh_tolerance, evaluate_csg, parse_csg, smooth_solid, smooth_solid_near, CsgOptions,
    MeshVariant, SmoothOptions,
};
use umbra_fuzz::CsgInput;

fuzz_target!(|input: CsgInput| {
    let text = input.json(3);
    let Ok(tree) = parse_csg(&text) else {
        return;
    };
    if tree.boolean_count() > 8 {
        return;
    }
    for triangulate in [false, true] {
        let options = CsgOptions {
            triangulate,
            contacts: Some(0.0),
            raw_intermediates: false,
        };
        let Ok(out) = evaluate_csg(&tree, options) else {
            return;
        };
        assert!(out.report.topologically_valid, "{text}");
        let Some(contacts) = &out.contacts else {
            continue;
        };
        let tol = default_mesh_tolerance(&out.mesh);
        if tol <= 0.0 || contacts.proximity < tol {
            continue;
        }
        let variant = if triangulate {
            MeshVariant::TriangleMesh
        } else {
            MeshVariant::PolygonMesh
        };
        let opts = SmoothOptions::new(tol);
        let near = smooth_solid_near(&out.mesh, variant, &opts, contacts).expect("near smoothing");
        assert_eq!(near.shape.check_topology(), Ok(()), "{text}");
        if near.report.counts == Default::default() {
            assert_eq!(near.shape, out.mesh, "{text}");
        }
        let whole = smooth_solid(&out.mesh, variant, &opts).expect("whole smoothing");
        assert_eq!(
            test_support::canonical::mesh_facets(&near.shape),
            test_support::canonical::mesh_facets(&whole.shape),
            "{text}"
        );
    }
});
