//! Winding numbers and the rules that select cells by them (section 6.1):
//! the [`Winding`] trait (one integer per operand), [`FillRule`] for a single
//! input and [`BooleanOp`] for two.

use std::fmt;

/// A winding number, or a vector of them (one per operand when Booleans are
/// computed through simplification, section 6.1). An edge's multiplicity has
/// the same type: crossing the edge from its right to its left adds it.
///
/// All arithmetic wraps (is modulo `2^32` per component). That keeps every
/// input panic-free, and since wrapping integers still form a group the cell
/// structure stays consistent; the values are the true winding numbers
/// unless those exceed `i32` in magnitude.
pub trait Winding: Clone + PartialEq + fmt::Debug + Send {
    /// The zero value for `dims` operands.
    fn zero(dims: usize) -> Self;
    /// `self += other`.
    fn add_assign(&mut self, other: &Self);
    /// `-self`.
    fn negated(&self) -> Self;
    /// `true` when every component is zero.
    fn is_zero(&self) -> bool;
    /// The sum of the components (the winding number of the assembled
    /// operands).
    fn total(&self) -> i32;
}

impl Winding for i32 {
    #[inline]
    fn zero(_dims: usize) -> Self {
        0
    }
    #[inline]
    fn add_assign(&mut self, other: &Self) {
        *self = self.wrapping_add(*other);
    }
    #[inline]
    fn negated(&self) -> Self {
        self.wrapping_neg()
    }
    #[inline]
    fn is_zero(&self) -> bool {
        *self == 0
    }
    #[inline]
    fn total(&self) -> i32 {
        *self
    }
}

impl Winding for [i32; 2] {
    #[inline]
    fn zero(_dims: usize) -> Self {
        [0, 0]
    }
    #[inline]
    fn add_assign(&mut self, other: &Self) {
        self[0] = self[0].wrapping_add(other[0]);
        self[1] = self[1].wrapping_add(other[1]);
    }
    #[inline]
    fn negated(&self) -> Self {
        [self[0].wrapping_neg(), self[1].wrapping_neg()]
    }
    #[inline]
    fn is_zero(&self) -> bool {
        self[0] == 0 && self[1] == 0
    }
    #[inline]
    fn total(&self) -> i32 {
        self[0].wrapping_add(self[1])
    }
}

impl Winding for Vec<i32> {
    fn zero(dims: usize) -> Self {
        vec![0; dims]
    }
    fn add_assign(&mut self, other: &Self) {
        if self.len() < other.len() {
            self.resize(other.len(), 0);
        }
        for (a, b) in self.iter_mut().zip(other) {
            *a = a.wrapping_add(*b);
        }
    }
    fn negated(&self) -> Self {
        self.iter().map(|v| v.wrapping_neg()).collect()
    }
    fn is_zero(&self) -> bool {
        self.iter().all(|&v| v == 0)
    }
    fn total(&self) -> i32 {
        self.iter().fold(0i32, |a, &b| a.wrapping_add(b))
    }
}

/// Which cells of the arrangement form the simplified shape (section 6.1):
/// a cell is retained when the rule accepts its winding number.
#[derive(Clone, Copy, Debug, Default)]
pub enum FillRule {
    /// Winding number `> 0`: the standard form of simplification (Fortune's
    /// definition, section 6.1). Union when the inputs are assembled.
    #[default]
    Positive,
    /// Winding number `!= 0`.
    NonZero,
    /// Odd winding number (figure 6.2(d); symmetric difference).
    EvenOdd,
    /// Winding number `< 0` (the inside-out regions).
    Negative,
    /// Winding number `>= 2` (intersection of two assembled valid inputs,
    /// [For95, p.228]).
    AtLeast2,
    /// A caller's predicate on the winding number.
    Custom(fn(i32) -> bool),
}

impl FillRule {
    /// `true` when a cell of winding number `w` is part of the result.
    #[inline]
    pub fn contains(&self, w: i32) -> bool {
        match self {
            FillRule::Positive => w > 0,
            FillRule::NonZero => w != 0,
            FillRule::EvenOdd => w & 1 == 1,
            FillRule::Negative => w < 0,
            FillRule::AtLeast2 => w >= 2,
            FillRule::Custom(f) => f(w),
        }
    }

    /// The rule named as on the command line (`positive`, `nonzero`,
    /// `evenodd`, `negative`, `at-least-2`), or `None`.
    pub fn from_name(name: &str) -> Option<FillRule> {
        match name {
            "positive" => Some(FillRule::Positive),
            "nonzero" | "non-zero" => Some(FillRule::NonZero),
            "evenodd" | "even-odd" => Some(FillRule::EvenOdd),
            "negative" => Some(FillRule::Negative),
            "at-least-2" | "atleast2" => Some(FillRule::AtLeast2),
            _ => None,
        }
    }
}
