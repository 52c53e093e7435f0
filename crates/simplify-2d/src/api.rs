//! The public entry points: simplification of one polygon set by a fill
//! rule, and Booleans of two or more through simplification (section 6.1).

use crate::cells::{CellStructure, SweepStats};
use crate::sweep::{run, InputEdge, Output};
use crate::winding::{FillRule, Winding};
use crate::SimplifyError;
use topology::BooleanOp;
use topology::PolygonSet2;

/// The result of a simplification or a Boolean through simplification.
#[derive(Clone, Debug)]
pub struct Simplified {
    /// The simplified shape: topologically valid (shape boundary closure)
    /// for every valid input; geometrically valid up to `epsilon`.
    pub shape: PolygonSet2,
    /// The largest adjustment count of the cell structure (section 8.4).
    pub k_max: u32,
    /// `(k_max + 1) * sqrt(153) * u * L` (section 8.4): every output edge
    /// lies within this distance of the input edge it originates from, and
    /// every decision is correct for some input perturbed by at most this.
    pub epsilon: f64,
    /// Counters of the sweep.
    pub stats: SweepStats,
}

impl Simplified {
    /// The shape `keep` selects from the cell structure that `cells`
    /// computes, the sweep keeping only the edges `keep` will select
    /// ([`Output::Boundary`]): the same shape, bounds and counters as
    /// selecting from the complete structure, without holding the rest of
    /// the arrangement.
    fn select<W: Winding>(
        keep: impl Fn(&W) -> bool + Sync,
        cells: impl FnOnce(Output<'_, W>) -> Result<CellStructure<W>, SimplifyError>,
    ) -> Result<Self, SimplifyError> {
        let cells = cells(Output::Boundary(&keep))?;
        let (k_max, epsilon, stats) = (cells.k_max(), cells.epsilon(), cells.stats());
        Ok(Simplified {
            shape: cells.into_shape_with(keep),
            k_max,
            epsilon,
            stats,
        })
    }
}

/// Validates coordinates first, then the data definitions and shape
/// boundary closure (section 4.2).
fn validate(set: &PolygonSet2, operand: usize) -> Result<(), SimplifyError> {
    set.validate_coordinates()
        .and_then(|()| set.check_topology())
        .map_err(|source| SimplifyError::InvalidInput { operand, source })
}

/// The edges of `set` with non-zero multiplicity as sweep input, their
/// provenance offset by `origin_offset`.
fn edges_of<'a, W>(
    set: &'a PolygonSet2,
    origin_offset: u32,
    mult: impl Fn(i32) -> W + 'a,
) -> impl Iterator<Item = InputEdge<W>> + 'a {
    let v = set.vertices();
    set.edges().iter().enumerate().filter_map(move |(i, e)| {
        if e.mult == 0 {
            return None;
        }
        let (&a, &b) = (v.get(e.start as usize)?, v.get(e.end as usize)?);
        Some(InputEdge {
            a,
            b,
            mult: mult(e.mult),
            origin: origin_offset.wrapping_add(i as u32),
        })
    })
}

/// The operands with their index and provenance offset (the edge counts
/// of the operands before them).
fn operands(sets: &[PolygonSet2]) -> impl Iterator<Item = (usize, &PolygonSet2, u32)> {
    sets.iter().enumerate().scan(0u32, |offset, (i, s)| {
        let at = *offset;
        *offset = offset.wrapping_add(s.edge_count() as u32);
        Some((i, s, at))
    })
}

/// The number of edges of all operands.
fn total_edges(sets: &[PolygonSet2]) -> usize {
    sets.iter().map(|s| s.edge_count()).sum()
}

/// The largest coordinate magnitude of the operands.
fn max_abs(sets: &[&PolygonSet2]) -> f64 {
    sets.iter()
        .map(|s| s.max_abs_coordinate())
        .fold(0.0f64, f64::max)
}

/// The cell structure of one polygon set (its boundary self-intersection
/// with the winding number on both sides of every edge, sections 6.2 and
/// 7.4.3), computed by the modified Bentley-Ottmann sweep of section 7.6.
///
/// ```
/// use simplify_2d::cell_structure;
/// use topology::PolygonSet2;
///
/// // A bow tie: two triangles of winding +1 and -1.
/// let mut s = PolygonSet2::new();
/// s.add_loop(&[[0.0, 0.0], [2.0, 2.0], [2.0, 0.0], [0.0, 2.0]]);
/// let cells = cell_structure(&s).unwrap();
/// cells.check_cells().unwrap();
/// assert_eq!(cells.vertices().len(), 5); // the crossing (1, 1) was added
/// ```
pub fn cell_structure(set: &PolygonSet2) -> Result<CellStructure<i32>, SimplifyError> {
    cells_of_one(set, Output::All)
}

/// The cell structure of one polygon set, with what `output` keeps.
fn cells_of_one(
    set: &PolygonSet2,
    output: Output<'_, i32>,
) -> Result<CellStructure<i32>, SimplifyError> {
    validate(set, 0)?;
    run(
        edges_of(set, 0, |m| m),
        set.edge_count(),
        1,
        max_abs(&[set]),
        output,
    )
}

/// Simplifies a polygon set: the cells whose winding number the rule
/// accepts, bounded by the edges of the cell structure that separate a
/// retained cell from a discarded one (sections 6.1 and 7.4.3).
///
/// ```
/// use simplify_2d::{simplify, FillRule};
/// use topology::PolygonSet2;
///
/// // Two overlapping squares drawn in one set: winding 2 where they overlap.
/// let mut s = PolygonSet2::new();
/// s.add_loop(&[[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]]);
/// s.add_loop(&[[1.0, 1.0], [3.0, 1.0], [3.0, 3.0], [1.0, 3.0]]);
/// let union = simplify(&s, FillRule::Positive).unwrap();
/// assert_eq!(union.shape.signed_area(), 7.0);
/// let both = simplify(&s, FillRule::AtLeast2).unwrap();
/// assert_eq!(both.shape.signed_area(), 1.0);
/// ```
pub fn simplify(set: &PolygonSet2, rule: FillRule) -> Result<Simplified, SimplifyError> {
    let cells = |out: Output<'_, i32>| cells_of_one(set, out);
    // One predicate per rule, each holding its rule as a constant, so that
    // `contains` folds to the rule's test: the sweep calls the predicate
    // twice per output edge, and the match on a rule held in the closure
    // cost more than the test.
    match rule {
        FillRule::Positive => Simplified::select(|w| FillRule::Positive.contains(*w), cells),
        FillRule::NonZero => Simplified::select(|w| FillRule::NonZero.contains(*w), cells),
        FillRule::EvenOdd => Simplified::select(|w| FillRule::EvenOdd.contains(*w), cells),
        FillRule::Negative => Simplified::select(|w| FillRule::Negative.contains(*w), cells),
        FillRule::AtLeast2 => Simplified::select(|w| FillRule::AtLeast2.contains(*w), cells),
        FillRule::Custom(f) => Simplified::select(move |w| f(*w), cells),
    }
}

/// The cell structure of two polygon sets assembled, with the winding
/// number of each operand tracked separately (`[a, b]`).
pub fn boolean_cells(
    a: &PolygonSet2,
    b: &PolygonSet2,
) -> Result<CellStructure<[i32; 2]>, SimplifyError> {
    cells_of_two(a, b, Output::All)
}

/// The cell structure of two polygon sets, with what `output` keeps.
fn cells_of_two(
    a: &PolygonSet2,
    b: &PolygonSet2,
    output: Output<'_, [i32; 2]>,
) -> Result<CellStructure<[i32; 2]>, SimplifyError> {
    validate(a, 0)?;
    validate(b, 1)?;
    let input = edges_of(a, 0, |m| [m, 0]).chain(edges_of(b, a.edge_count() as u32, |m| [0, m]));
    run(
        input,
        a.edge_count() + b.edge_count(),
        2,
        max_abs(&[a, b]),
        output,
    )
}

/// A Boolean operation through simplification (section 6.1): both
/// boundaries are assembled into one edge collection, the sweep computes
/// the cell structure with both winding numbers, and the cells the
/// operation selects form the result. Unlike the basic Boolean this also
/// resolves geometrically invalid operands.
///
/// ```
/// use simplify_2d::{boolean, BooleanOp};
/// use topology::PolygonSet2;
///
/// let mut a = PolygonSet2::new();
/// a.add_loop(&[[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]]);
/// let mut b = PolygonSet2::new();
/// b.add_loop(&[[1.0, 1.0], [3.0, 1.0], [3.0, 3.0], [1.0, 3.0]]);
/// assert_eq!(boolean(&a, &b, BooleanOp::Difference).unwrap().shape.signed_area(), 3.0);
/// assert_eq!(boolean(&a, &b, BooleanOp::Xor).unwrap().shape.signed_area(), 6.0);
/// ```
pub fn boolean(
    a: &PolygonSet2,
    b: &PolygonSet2,
    op: BooleanOp,
) -> Result<Simplified, SimplifyError> {
    let cells = |out: Output<'_, [i32; 2]>| cells_of_two(a, b, out);
    // One predicate per operation, as in `simplify`.
    let inside = |w: &[i32; 2]| (w[0] > 0, w[1] > 0);
    match op {
        BooleanOp::Union => Simplified::select(
            |w| {
                let (a, b) = inside(w);
                BooleanOp::Union.selects(a, b)
            },
            cells,
        ),
        BooleanOp::Intersection => Simplified::select(
            |w| {
                let (a, b) = inside(w);
                BooleanOp::Intersection.selects(a, b)
            },
            cells,
        ),
        BooleanOp::Difference => Simplified::select(
            |w| {
                let (a, b) = inside(w);
                BooleanOp::Difference.selects(a, b)
            },
            cells,
        ),
        BooleanOp::Xor => Simplified::select(
            |w| {
                let (a, b) = inside(w);
                BooleanOp::Xor.selects(a, b)
            },
            cells,
        ),
    }
}

/// The cell structure of any number of polygon sets assembled, with the
/// winding number of every operand tracked separately.
pub fn cell_structure_n(sets: &[PolygonSet2]) -> Result<CellStructure<Vec<i32>>, SimplifyError> {
    cells_of_many(sets, Output::All)
}

/// The cell structure of any number of polygon sets, with what `output`
/// keeps.
fn cells_of_many(
    sets: &[PolygonSet2],
    output: Output<'_, Vec<i32>>,
) -> Result<CellStructure<Vec<i32>>, SimplifyError> {
    for (i, s) in sets.iter().enumerate() {
        validate(s, i)?;
    }
    let n = sets.len();
    let input = operands(sets).flat_map(|(i, s, offset)| {
        edges_of(s, offset, move |m| {
            let mut w = vec![0; n];
            w[i] = m;
            w
        })
    });
    let refs: Vec<&PolygonSet2> = sets.iter().collect();
    run(input, total_edges(sets), n, max_abs(&refs), output)
}

/// An n-ary Boolean in one sweep: `keep` receives the winding number of
/// every operand for a cell and decides whether it is part of the result.
/// It may be called from several threads at once (a large input is swept
/// in vertical strips in parallel), hence `Sync`.
/// For example `|w| w.iter().filter(|&&x| x > 0).count() >= 2` selects the
/// points covered by at least two operands.
pub fn boolean_n(
    sets: &[PolygonSet2],
    keep: impl Fn(&[i32]) -> bool + Sync,
) -> Result<Simplified, SimplifyError> {
    Simplified::select(|w: &Vec<i32>| keep(w), |out| cells_of_many(sets, out))
}

/// The union of any number of polygon sets in one sweep (section 6.1: the
/// boundaries are assembled and simplified in standard form). Winding
/// numbers are summed over the operands, which is the union whenever no
/// operand has inside-out (negative winding) regions; use [`boolean_n`]
/// with `|w| w.iter().any(|&x| x > 0)` for the per-operand definition.
pub fn union_all(sets: &[PolygonSet2]) -> Result<Simplified, SimplifyError> {
    for (i, s) in sets.iter().enumerate() {
        validate(s, i)?;
    }
    let input = operands(sets).flat_map(|(_, s, offset)| edges_of(s, offset, |m| m));
    let refs: Vec<&PolygonSet2> = sets.iter().collect();
    Simplified::select(
        |w: &i32| *w > 0,
        |out| run(input, total_edges(sets), 1, max_abs(&refs), out),
    )
}

/// The n-ary form of `op` over `sets` in one sweep (section 6.1), a point
/// being inside an operand where that operand's winding number is
/// positive: the union keeps what is inside any operand, the intersection
/// what is inside every one, the difference what is inside the first and
/// no other, and `Xor` what is inside an odd number of them. For two sets
/// this selects what [`boolean`] selects; for one set, what its positive
/// winding covers (`Xor`, union and intersection alike). No sets give the
/// empty shape. Errors name the first invalid operand by its position.
///
/// ```
/// use simplify_2d::{boolean_sets, BooleanOp};
/// use topology::PolygonSet2;
///
/// let square = |x: f64| {
///     let mut s = PolygonSet2::new();
///     s.add_loop(&[[x, 0.0], [x + 2.0, 0.0], [x + 2.0, 2.0], [x, 2.0]]);
///     s
/// };
/// // Three 2 x 2 squares, each overlapping the next by half.
/// let sets = [square(0.0), square(1.0), square(2.0)];
/// let area = |op| boolean_sets(op, &sets).unwrap().shape.signed_area();
/// assert_eq!(area(BooleanOp::Union), 8.0);
/// assert_eq!(area(BooleanOp::Intersection), 0.0);
/// assert_eq!(area(BooleanOp::Difference), 2.0);
/// assert_eq!(area(BooleanOp::Xor), 4.0);
/// ```
pub fn boolean_sets(op: BooleanOp, sets: &[PolygonSet2]) -> Result<Simplified, SimplifyError> {
    boolean_n(sets, |w| selects_n(op, w))
}

/// Whether `op` over operands with winding numbers `w` selects a cell
/// ([`boolean_sets`]).
fn selects_n(op: BooleanOp, w: &[i32]) -> bool {
    let inside = w.iter().filter(|&&x| x > 0).count();
    match op {
        BooleanOp::Union => inside > 0,
        BooleanOp::Intersection => !w.is_empty() && inside == w.len(),
        BooleanOp::Difference => w.first().is_some_and(|&x| x > 0) && inside == 1,
        BooleanOp::Xor => inside % 2 == 1,
    }
}
