//! Fuzz target: the simplification sweep on any polygon set never panics,
//! rejects bad coordinates with an error, and otherwise yields a valid cell
//! structure (`check_cells`: winding numbers consistent across every edge)
//! and a closed result for every fill rule and every Boolean through
//! simplification.
#![no_main]

use libfuzzer_sys::fuzz_target;
use simplify_2d::{boolean, cell_structure, simplify, BooleanOp, FillRule, SimplifyError};
use umbra_fuzz::SimplifyInput;

fuzz_target!(|input: SimplifyInput| {
    let set = input.set.to_set();
    let coords_ok = set.validate_coordinates().is_ok();
    match cell_structure(&set) {
        Ok(cells) => {
            assert!(coords_ok, "bad coordinates were accepted");
            cells.check_cells().expect("invalid cell structure");
        }
        Err(SimplifyError::InvalidInput { .. }) => {
            assert!(!coords_ok, "valid input rejected");
            return;
        }
        Err(e) => panic!("{e}"),
    }
    let rule = match input.rule % 5 {
        0 => FillRule::Positive,
        1 => FillRule::NonZero,
        2 => FillRule::EvenOdd,
        3 => FillRule::Negative,
        _ => FillRule::AtLeast2,
    };
    let out = simplify(&set, rule).expect("simplify after a valid cell structure");
    out.shape
        .check_topology()
        .expect("simplified shape not closed");
    let other = input.other.to_set();
    if other.validate_coordinates().is_ok() {
        let op = match input.rule % 4 {
            0 => BooleanOp::Union,
            1 => BooleanOp::Intersection,
            2 => BooleanOp::Difference,
            _ => BooleanOp::Xor,
        };
        let out = boolean(&set, &other, op).expect("Boolean through simplification");
        out.shape
            .check_topology()
            .expect("Boolean result not closed");
    }
});
