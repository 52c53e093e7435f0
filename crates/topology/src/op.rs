//! The one Boolean operation type of the workspace and the operand names
//! used in errors: the constants of eq. 4.11-4.13 and the winding function
//! of eq. 4.20.

use std::fmt;

/// A Boolean operation on two shapes.
///
/// The basic Boolean (chapter 4) builds the result from inclusion values
/// with the constants `(c_A, c_B, c_I)` of eq. 4.11-4.13; simplification
/// (section 6.1) selects the cells whose operand winding numbers the
/// operation accepts. `Xor` is the symmetric difference `(A \ B) ∪ (B \ A)`
/// of section 6.1.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum BooleanOp {
    /// `A ∪ B`: `c_A = 1, c_B = 1, c_I = -1` (eq. 4.11).
    Union,
    /// `A ∩ B`: `c_A = 0, c_B = 0, c_I = +1` (eq. 4.12).
    Intersection,
    /// `A − B`: `c_A = 1, c_B = 0, c_I = -1` (eq. 4.13).
    Difference,
    /// `(A \ B) ∪ (B \ A)`: `c_A = 1, c_B = 1, c_I = -2` in eq. 4.20 (one
    /// exactly of `a`, `b` is 1 for winding numbers 0 and 1).
    Xor,
}

impl BooleanOp {
    /// The three operations of eq. 4.11-4.13, which every engine supports.
    pub const BASIC: [BooleanOp; 3] = [
        BooleanOp::Union,
        BooleanOp::Intersection,
        BooleanOp::Difference,
    ];

    /// All four operations.
    pub const ALL: [BooleanOp; 4] = [
        BooleanOp::Union,
        BooleanOp::Intersection,
        BooleanOp::Difference,
        BooleanOp::Xor,
    ];

    /// The constants `(c_A, c_B, c_I)` of eq. 4.11-4.13 (and `(1, 1, -2)`
    /// for `Xor`).
    pub fn coefficients(self) -> (i32, i32, i32) {
        match self {
            BooleanOp::Union => (1, 1, -1),
            BooleanOp::Intersection => (0, 0, 1),
            BooleanOp::Difference => (1, 0, -1),
            BooleanOp::Xor => (1, 1, -2),
        }
    }

    /// The winding number of the result at a point with winding numbers `a`
    /// and `b` in the operands (eq. 4.20): `c_A a + c_B b + c_I a b`.
    pub fn result_winding(self, a: i64, b: i64) -> i64 {
        let (ca, cb, ci) = self.coefficients();
        i64::from(ca) * a + i64::from(cb) * b + i64::from(ci) * a * b
    }

    /// Whether a point inside `a` (of A) and `b` (of B) is in the result,
    /// the operands read in standard form (section 6.1).
    #[inline]
    pub fn selects(self, a: bool, b: bool) -> bool {
        match self {
            BooleanOp::Union => a || b,
            BooleanOp::Intersection => a && b,
            BooleanOp::Difference => a && !b,
            BooleanOp::Xor => a != b,
        }
    }

    /// The lower-case name (`union`, `intersection`, `difference`, `xor`).
    pub fn name(self) -> &'static str {
        match self {
            BooleanOp::Union => "union",
            BooleanOp::Intersection => "intersection",
            BooleanOp::Difference => "difference",
            BooleanOp::Xor => "xor",
        }
    }
}

impl fmt::Display for BooleanOp {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl std::str::FromStr for BooleanOp {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, String> {
        match s {
            "union" => Ok(BooleanOp::Union),
            "intersection" => Ok(BooleanOp::Intersection),
            "difference" => Ok(BooleanOp::Difference),
            "xor" => Ok(BooleanOp::Xor),
            other => Err(format!(
                "unknown operation '{other}' (expected union, intersection, difference or xor)"
            )),
        }
    }
}

/// Which operand of a Boolean (named in errors).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Operand {
    /// The first operand, A.
    A,
    /// The second operand, B.
    B,
}

impl fmt::Display for Operand {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Operand::A => "A",
            Operand::B => "B",
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn winding_function_matches_selection_on_standard_windings() {
        for op in BooleanOp::ALL {
            for a in 0..=1 {
                for b in 0..=1 {
                    let w = op.result_winding(a, b);
                    assert_eq!(w == 1, op.selects(a == 1, b == 1), "{op} {a} {b}");
                    assert!(w == 0 || w == 1, "{op} {a} {b}: {w}");
                }
            }
            assert_eq!(op.name().parse::<BooleanOp>(), Ok(op));
        }
        assert!("nand".parse::<BooleanOp>().is_err());
    }
}
