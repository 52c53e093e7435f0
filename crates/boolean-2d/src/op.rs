//! The operation constants of eq. 4.11-4.13.

/// A Boolean operation.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum BooleanOp {
    /// `A ∪ B`: `c_A = 1, c_B = 1, c_I = -1` (eq. 4.11).
    Union,
    /// `A ∩ B`: `c_A = 0, c_B = 0, c_I = +1` (eq. 4.12).
    Intersection,
    /// `A − B`: `c_A = 1, c_B = 0, c_I = -1` (eq. 4.13).
    Difference,
}

impl BooleanOp {
    /// The constants `(c_A, c_B, c_I)` of eq. 4.11-4.13.
    pub fn coefficients(self) -> (i32, i32, i32) {
        match self {
            BooleanOp::Union => (1, 1, -1),
            BooleanOp::Intersection => (0, 0, 1),
            BooleanOp::Difference => (1, 0, -1),
        }
    }

    /// The winding number of the result at a point with winding numbers `a`
    /// and `b` in the operands (eq. 4.20): `c_A a + c_B b + c_I a b`.
    pub fn result_winding(self, a: i64, b: i64) -> i64 {
        let (ca, cb, ci) = self.coefficients();
        i64::from(ca) * a + i64::from(cb) * b + i64::from(ci) * a * b
    }

    /// All three operations.
    pub const ALL: [BooleanOp; 3] = [
        BooleanOp::Union,
        BooleanOp::Intersection,
        BooleanOp::Difference,
    ];

    /// The lower-case name (`union`, `intersection`, `difference`).
    pub fn name(self) -> &'static str {
        match self {
            BooleanOp::Union => "union",
            BooleanOp::Intersection => "intersection",
            BooleanOp::Difference => "difference",
        }
    }
}

impl std::str::FromStr for BooleanOp {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, String> {
        match s {
            "union" => Ok(BooleanOp::Union),
            "intersection" => Ok(BooleanOp::Intersection),
            "difference" => Ok(BooleanOp::Difference),
            other => Err(format!(
                "unknown operation '{other}' (expected union, intersection or difference)"
            )),
        }
    }
}
