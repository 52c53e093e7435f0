//! Fuzz target: the 3D Boolean on topologically valid meshes with any
//! coordinates never panics, rejects bad coordinates with an error, and on
//! success passes the audit of Theorems 1-4 (`Audit::verify`) in both the
//! polygon-mesh and triangle-mesh variants.
#![no_main]

use boolean_3d::{boolean_mesh_audit, boolean_triangles_audit, Boolean3Error, BooleanOp};
use libfuzzer_sys::fuzz_target;
use umbra_fuzz::SolidInput;

fuzz_target!(|input: SolidInput| {
    let (a, b) = (input.a.to_mesh(), input.b.to_mesh());
    assert!(a.check_topology().is_ok() && b.check_topology().is_ok());
    let op = match input.op % 3 {
        0 => BooleanOp::Union,
        1 => BooleanOp::Intersection,
        _ => BooleanOp::Difference,
    };
    let coords_ok = a.validate_coordinates().is_ok() && b.validate_coordinates().is_ok();
    match boolean_mesh_audit(&a, &b, op) {
        Ok((out, audit)) => {
            assert!(coords_ok, "bad coordinates were accepted");
            out.mesh
                .check_topology()
                .expect("Theorem 4: result not closed");
            audit.verify().expect("audit of Theorems 1-4");
        }
        Err(Boolean3Error::InvalidInput { .. }) => assert!(!coords_ok, "valid input rejected"),
        Err(Boolean3Error::TooLarge { .. }) => {}
        Err(e) => panic!("internal error: {e}"),
    }
    if let (Some(ta), Some(tb)) = (input.a.to_triangles(), input.b.to_triangles()) {
        match boolean_triangles_audit(&ta, &tb, op) {
            Ok((out, audit)) => {
                out.mesh
                    .check_topology()
                    .expect("triangle result not closed");
                audit.verify().expect("audit of Theorems 1-4 (triangles)");
            }
            Err(Boolean3Error::InvalidInput { .. }) => assert!(!coords_ok),
            Err(Boolean3Error::TooLarge { .. }) => {}
            Err(e) => panic!("internal error: {e}"),
        }
    }
});
