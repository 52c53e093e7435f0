//! The 2D operations on polygons in their plain Python form: a list of
//! polygons, each a list of rings (the exterior first, then holes), each
//! ring an (k, 2) float64 array-like, closed or not. The Python layer turns
//! shapely geometries into this form and back.

use crate::arrays::{points, points_array};
use crate::ops::parse_op;
use crate::{error, run};
use geo_types::{Coord, LineString, MultiPolygon, Polygon};
use pyo3::prelude::*;
use pyo3::types::PyList;
use umbra::{
    boolean_for_smoothing, boolean_sets, boolean_via_simplify, default_boolean_set_tolerance,
    fill_rule_name, from_geo, layout_polygons, regularized_operands, simplify as simplify_set,
    smooth_set_result, FillRule, PlanarContacts, PolygonSet2, Polygons, RingOrientation,
    Simplified, SmoothOptions, UmbraError, Via,
};

/// The ring convention of `keep_orientation`.
pub fn orientation(keep: bool) -> RingOrientation {
    if keep {
        RingOrientation::AsWritten
    } else {
        RingOrientation::ByRole
    }
}

/// The polygons of a Python value as rings of points (`what` names it).
fn rings_of(obj: &Bound<'_, PyAny>, what: &str) -> PyResult<Vec<Vec<Vec<[f64; 2]>>>> {
    let expected = "a list of polygons, each a list of (k, 2) rings";
    let mut polys = Vec::new();
    let items = obj
        .try_iter()
        .map_err(|_| error(format!("{what}: expected {expected}")))?;
    for (i, p) in items.enumerate() {
        let p = p?;
        let mut rings = Vec::new();
        let ring_items = p
            .try_iter()
            .map_err(|_| error(format!("{what}[{i}]: expected a list of (k, 2) rings")))?;
        for (j, r) in ring_items.enumerate() {
            rings.push(points::<2>(&r?, &format!("{what}[{i}][{j}]"))?);
        }
        polys.push(rings);
    }
    Ok(polys)
}

/// Renames the facade's `<geo-types>` source in an error to `what`.
fn rename(e: UmbraError, what: &str) -> UmbraError {
    let file = what.to_string();
    match e {
        UmbraError::BadCoordinate {
            location,
            axis,
            source,
            ..
        } => UmbraError::BadCoordinate {
            file,
            location,
            axis,
            source,
        },
        UmbraError::InvalidShape { source, .. } => UmbraError::InvalidShape { file, source },
        UmbraError::Parse { message, .. } => UmbraError::Parse { file, message },
        other => other,
    }
}

/// A polygon set from rings (coordinates checked, rings oriented by role
/// or kept as written).
pub fn set_of(
    rings: &[Vec<Vec<[f64; 2]>>],
    orientation: RingOrientation,
    what: &str,
) -> Result<PolygonSet2, UmbraError> {
    let ls = |r: &Vec<[f64; 2]>| LineString(r.iter().map(|p| Coord { x: p[0], y: p[1] }).collect());
    let multi = MultiPolygon(
        rings
            .iter()
            .filter(|p| !p.is_empty())
            .map(|p| Polygon::new(ls(&p[0]), p[1..].iter().map(ls).collect()))
            .collect(),
    );
    from_geo(&multi, orientation).map_err(|e| rename(e, what))
}

/// The polygons of a Python value as a set, converted with the GIL held
/// (copies) and built without it.
pub fn input_set(
    py: Python<'_>,
    obj: &Bound<'_, PyAny>,
    keep: bool,
    what: &str,
) -> PyResult<PolygonSet2> {
    let rings = rings_of(obj, what)?;
    run(py, || set_of(&rings, orientation(keep), what))
}

/// The Python form of a set's polygons (open rings, no closing point).
pub fn polygons_to_py<'py>(py: Python<'py>, polygons: &Polygons) -> PyResult<Bound<'py, PyAny>> {
    let out = PyList::empty(py);
    for p in polygons {
        let rings = PyList::empty(py);
        for r in p {
            rings.append(points_array(py, r)?)?;
        }
        out.append(rings)?;
    }
    Ok(out.into_any())
}

/// The layout of a result in the requested ring convention: with `keep`
/// every loop as its own polygon as it runs, else by role (holes in their
/// exteriors). Results going to shapely, which has no ring direction, are
/// laid out by role whatever the input convention (`layout_by_role`): a
/// hole as a polygon of its own would be filled.
fn output<'py>(py: Python<'py>, set: PolygonSet2, keep: bool) -> PyResult<Bound<'py, PyAny>> {
    let layout = run(py, || layout_polygons(&set, orientation(keep), "<result>"))?;
    polygons_to_py(py, &layout.polygons)
}

/// The 2D Boolean of two polygon lists (see the Python docstring),
/// smoothed at `smooth` (by default the command line's tolerance, 1e-9
/// times the operands' largest extent; 0 for the raw output).
#[pyfunction]
#[pyo3(signature = (a, b, op, *, via = "basic", keep_orientation = false, smooth = None, layout_by_role = false))]
// The arguments are the Python keyword arguments, one each.
#[allow(clippy::too_many_arguments)]
pub fn boolean_2d<'py>(
    py: Python<'py>,
    a: &Bound<'py, PyAny>,
    b: &Bound<'py, PyAny>,
    op: &str,
    via: &str,
    keep_orientation: bool,
    smooth: Option<f64>,
    layout_by_role: bool,
) -> PyResult<Bound<'py, PyAny>> {
    let op = parse_op(op)?;
    let via = match via {
        "basic" => Via::Basic,
        "simplify" => Via::Simplify,
        other => {
            return Err(error(format!(
                "unknown algorithm '{other}' (expected basic or simplify)"
            )))
        }
    };
    let a = input_set(py, a, keep_orientation, "a")?;
    let b = input_set(py, b, keep_orientation, "b")?;
    let tolerance =
        smooth.unwrap_or_else(|| default_boolean_set_tolerance([&a, &b], keep_orientation));
    let shape = run(py, || {
        let (raw, contacts) = match via {
            Via::Basic => {
                // Operands read by role are made sets first, as the
                // command line does (`regularized_operand`).
                let regular = |r: Result<Simplified, _>| {
                    r.map(|r| r.shape).map_err(|source| UmbraError::Simplify {
                        file: String::new(),
                        source,
                    })
                };
                let (a, b) = if keep_orientation {
                    (a.clone(), b.clone())
                } else {
                    let [ra, rb] = regularized_operands(&a, &b);
                    (regular(ra)?, regular(rb)?)
                };
                // Smoothing looks only near the operands' contacts, found
                // beside the Boolean, as on the command line.
                boolean_for_smoothing(&a, &b, op, tolerance)
                    .map(|(o, c)| (o.shape, c))
                    .map_err(|source| UmbraError::Boolean {
                        file: String::new(),
                        source,
                    })
            }
            Via::Simplify => boolean_via_simplify(&a, &b, op)
                .map(|o| (o.shape, None))
                .map_err(|source| UmbraError::Simplify {
                    file: String::new(),
                    source,
                }),
        }?;
        smoothed_set(raw, tolerance, contacts.as_ref())
    })?;
    output(py, shape, keep_orientation && !layout_by_role)
}

/// `raw` smoothed at `tolerance` (Appendix A), near `contacts` when given
/// (`umbra::smooth_set_result`), itself at 0.
fn smoothed_set(
    raw: PolygonSet2,
    tolerance: f64,
    contacts: Option<&PlanarContacts>,
) -> Result<PolygonSet2, UmbraError> {
    if tolerance == 0.0 {
        return Ok(raw);
    }
    let opts = SmoothOptions::new(tolerance);
    let smooth_error = |source| UmbraError::Smooth {
        file: String::new(),
        source,
    };
    opts.validate().map_err(smooth_error)?;
    smooth_set_result(&raw, &opts, contacts)
        .map(|s| s.shape)
        .map_err(smooth_error)
}

/// The n-ary 2D Boolean of a list of polygon lists in one sweep
/// (`umbra::boolean_sets`; see the Python docstring), smoothed as
/// [`boolean_2d`] smooths: by default at 1e-9 times the operands' largest
/// extent, 0 for the raw output.
#[pyfunction]
#[pyo3(signature = (geoms, op, *, keep_orientation = false, smooth = None, layout_by_role = false))]
pub fn boolean_2d_all<'py>(
    py: Python<'py>,
    geoms: &Bound<'py, PyAny>,
    op: &str,
    keep_orientation: bool,
    smooth: Option<f64>,
    layout_by_role: bool,
) -> PyResult<Bound<'py, PyAny>> {
    let op = parse_op(op)?;
    let mut sets = Vec::new();
    for (i, geom) in geoms.try_iter()?.enumerate() {
        sets.push(input_set(
            py,
            &geom?,
            keep_orientation,
            &format!("geoms[{i}]"),
        )?);
    }
    let tolerance =
        smooth.unwrap_or_else(|| default_boolean_set_tolerance(&sets, keep_orientation));
    let shape = run(py, || {
        let raw =
            boolean_sets(op, &sets)
                .map(|o| o.shape)
                .map_err(|source| UmbraError::Simplify {
                    file: String::new(),
                    source,
                })?;
        smoothed_set(raw, tolerance, None)
    })?;
    output(py, shape, keep_orientation && !layout_by_role)
}

/// The fill rule named `rule`.
fn parse_rule(rule: &str) -> PyResult<FillRule> {
    [
        FillRule::Positive,
        FillRule::NonZero,
        FillRule::EvenOdd,
        FillRule::Negative,
        FillRule::AtLeast2,
    ]
    .into_iter()
    .find(|r| fill_rule_name(*r) == rule)
    .ok_or_else(|| {
        error(format!(
            "unknown fill rule '{rule}' (expected positive, nonzero, evenodd, negative or at-least-2)"
        ))
    })
}

/// The simplification of a polygon list by a fill rule (see the Python
/// docstring).
#[pyfunction]
#[pyo3(signature = (geom, rule = "positive", *, keep_orientation = false, layout_by_role = false))]
pub fn simplify<'py>(
    py: Python<'py>,
    geom: &Bound<'py, PyAny>,
    rule: &str,
    keep_orientation: bool,
    layout_by_role: bool,
) -> PyResult<Bound<'py, PyAny>> {
    let rule = parse_rule(rule)?;
    let set = input_set(py, geom, keep_orientation, "geom")?;
    let shape = run(py, || {
        simplify_set(&set, rule)
            .map(|o| o.shape)
            .map_err(|source| UmbraError::Simplify {
                file: String::new(),
                source,
            })
    })?;
    output(py, shape, keep_orientation && !layout_by_role)
}
