//! `Hit`: a non-zero intersection function value with its point pair.

/// A non-zero value of an intersection function `X_ij(o_A, o_B)` together
/// with its intersection point pair (section 4.5): `a` lies on `o_A`, `b` on
/// `o_B`, and they agree in the first `level` coordinates (where `level =
/// i + j` is the dimension of the subspace the intersection is decided in).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Hit<const N: usize> {
    /// The intersection function value (never 0 in a `Hit`).
    pub value: i32,
    /// The intersection point on the entity from A.
    pub a: [f64; N],
    /// The intersection point on the entity from B.
    pub b: [f64; N],
}

impl<const N: usize> Hit<N> {
    /// The shadow function of eq. 4.1 for a hit of level `level`: the value
    /// when B's coordinate `level` is `>=` A's (B shadows A, ties included),
    /// else 0.
    #[inline]
    pub fn shadow(&self, level: usize) -> i32 {
        if self.b[level] >= self.a[level] {
            self.value
        } else {
            0
        }
    }

    /// `Delta = xi_B - xi_A` in coordinate `level` (eq. 4.5-4.6): `>= 0`
    /// exactly when B shadows A.
    #[inline]
    pub fn delta(&self, level: usize) -> f64 {
        self.b[level] - self.a[level]
    }

    /// The same hit with the value negated (a reversed half-edge).
    #[inline]
    pub fn negated(self) -> Self {
        Hit {
            value: -self.value,
            ..self
        }
    }
}
