//! Fuzz target: the 2D Boolean never panics, rejects bad coordinates with an
//! error, and on success returns a result satisfying shape boundary closure
//! (Theorem 2 and the closure of section 4.2).
#![no_main]

use boolean_2d::{boolean_reference, BooleanOp};
use libfuzzer_sys::fuzz_target;
use umbra_fuzz::BooleanInput;

fuzz_target!(|input: BooleanInput| {
    let a = input.a.to_set();
    let b = input.b.to_set();
    let op = match input.op % 3 {
        0 => BooleanOp::Union,
        1 => BooleanOp::Intersection,
        _ => BooleanOp::Difference,
    };
    let fast = boolean_2d::boolean(&a, &b, op);
    let coords_ok = a.validate_coordinates().is_ok() && b.validate_coordinates().is_ok();
    match fast {
        Ok(out) => {
            assert!(coords_ok, "bad coordinates were accepted");
            out.shape
                .check_topology()
                .expect("result violates shape boundary closure");
            let (reference, data) = boolean_reference(&a, &b, op).expect("reference failed");
            assert!(
                data.composite_counts.iter().all(|(s, e)| s == e),
                "Theorem 2 violated"
            );
            assert_eq!(
                reference.shape, out.shape,
                "fast path differs from reference"
            );
        }
        Err(boolean_2d::BooleanError::InvalidInput { .. }) => {
            assert!(!coords_ok, "valid input rejected");
        }
        Err(e) => panic!("internal error: {e}"),
    }
});
