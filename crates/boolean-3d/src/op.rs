//! The operation constants of eq. 4.11-4.13.

/// A 3D Boolean operation.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum BooleanOp3 {
    /// `A ∪ B`: `c_A = 1, c_B = 1, c_I = -1` (eq. 4.11).
    Union,
    /// `A ∩ B`: `c_A = 0, c_B = 0, c_I = +1` (eq. 4.12).
    Intersection,
    /// `A − B`: `c_A = 1, c_B = 0, c_I = -1` (eq. 4.13).
    Difference,
}

impl BooleanOp3 {
    /// All three operations.
    pub const ALL: [BooleanOp3; 3] = [
        BooleanOp3::Union,
        BooleanOp3::Intersection,
        BooleanOp3::Difference,
    ];

    /// The constants `(c_A, c_B, c_I)` of eq. 4.11-4.13.
    pub fn coefficients(self) -> (i32, i32, i32) {
        match self {
            BooleanOp3::Union => (1, 1, -1),
            BooleanOp3::Intersection => (0, 0, 1),
            BooleanOp3::Difference => (1, 0, -1),
        }
    }

    /// The winding number of the result at a point with winding numbers `a`
    /// and `b` in the operands (eq. 4.20): `c_A a + c_B b + c_I a b`.
    pub fn result_winding(self, a: i64, b: i64) -> i64 {
        let (ca, cb, ci) = self.coefficients();
        i64::from(ca) * a + i64::from(cb) * b + i64::from(ci) * a * b
    }

    /// The lower-case name (`union`, `intersection`, `difference`).
    pub fn name(self) -> &'static str {
        match self {
            BooleanOp3::Union => "union",
            BooleanOp3::Intersection => "intersection",
            BooleanOp3::Difference => "difference",
        }
    }
}

impl std::str::FromStr for BooleanOp3 {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, String> {
        match s {
            "union" => Ok(BooleanOp3::Union),
            "intersection" => Ok(BooleanOp3::Intersection),
            "difference" => Ok(BooleanOp3::Difference),
            other => Err(format!(
                "unknown operation '{other}' (expected union, intersection or difference)"
            )),
        }
    }
}
