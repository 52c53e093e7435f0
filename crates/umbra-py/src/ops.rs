//! The 3D operations: the Boolean of two meshes (optionally smoothed),
//! smoothing, the union of many and one minus many (the facade's n-ary
//! Booleans), and CSG trees in the JSON form of `umbra csg`.

use crate::mesh::Mesh;
use crate::{error, run};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use std::borrow::Cow;
use umbra::{
    as_triangle_mesh, boolean_solid, boolean_solid_with_contacts, default_mesh_tolerance,
    difference_all_solids, evaluate_csg, parse_csg, smooth_csg_result, smooth_solid,
    smooth_solid_near, turned_outward, union_all_solids, BooleanOp, CsgOptions, MeshVariant,
    PolygonMesh, SmoothOptions, SmoothReport, SolidsError, UmbraError,
};

/// A result and the report of its smoothing, if it was smoothed.
type MaybeSmoothed = (PolygonMesh, Option<SmoothReport>);

/// A `UserWarning` when the smoothing guard handed the mesh back as it
/// was (`SmoothReport::reverted`), with the command line's sentence.
fn warn_if_undone(py: Python<'_>, report: Option<&SmoothReport>) -> PyResult<()> {
    match report.and_then(|r| r.reverted.as_ref()) {
        Some(undone) => crate::warn_user(py, &undone.to_string()),
        None => Ok(()),
    }
}

/// The operation named `op`: every name of the facade (`union`,
/// `intersection`, `difference`, `xor`), with its message otherwise.
pub fn parse_op(op: &str) -> PyResult<BooleanOp> {
    op.parse::<BooleanOp>().map_err(error)
}

/// The variant of `triangulate`.
fn variant(triangulate: bool) -> MeshVariant {
    if triangulate {
        MeshVariant::TriangleMesh
    } else {
        MeshVariant::PolygonMesh
    }
}

/// A result and the operands turned outward on the way in: each one's
/// name and its signed volume as given.
type WithTurned<'py> = (Bound<'py, Mesh>, Vec<(String, f64)>);

/// `mesh` turned outward when its facets face inward
/// ([`turned_outward`]), noting its name and signed volume in `turned`.
fn outward<'m>(
    mesh: &'m PolygonMesh,
    name: &str,
    turned: &mut Vec<(String, f64)>,
) -> Cow<'m, PolygonMesh> {
    match turned_outward(mesh) {
        Some(t) => {
            turned.push((name.to_string(), mesh.signed_volume()));
            Cow::Owned(t)
        }
        None => Cow::Borrowed(mesh),
    }
}

/// One binary Boolean with the command-line tool's message on failure.
fn solid(
    a: &PolygonMesh,
    b: &PolygonMesh,
    op: BooleanOp,
    variant: MeshVariant,
) -> Result<PolygonMesh, UmbraError> {
    boolean_solid(a, b, op, variant)
        .map(|out| out.mesh)
        .map_err(|source| UmbraError::Boolean3 {
            file: String::new(),
            source,
        })
}

/// Smooths `mesh` in `variant` at `tolerance` (Appendix A), with the
/// command-line tool's message on failure.
fn smoothed(
    mesh: &PolygonMesh,
    variant: MeshVariant,
    tolerance: f64,
) -> Result<umbra::Smoothed<PolygonMesh>, UmbraError> {
    smooth_solid(mesh, variant, &SmoothOptions::new(tolerance).guarded()).map_err(|source| {
        UmbraError::Smooth {
            file: String::new(),
            source,
        }
    })
}

/// The 3D Boolean ``op`` ("union", "intersection" or "difference") of
/// two meshes (section 4 of the dissertation): the result is always
/// topologically valid. ``triangulate=True`` runs the triangle-mesh variant
/// (section 4.8): operands are triangulated first and the output is
/// triangles. ``smooth=T`` smooths the result at tolerance ``T``
/// (Appendix A: vertices closer than ``T`` merge, slivers and coincident
/// opposing facets go) where the operands cut or come within ``T`` of
/// each other, as the command line does; ``None`` (the default) or 0 returns the basic
/// Boolean's raw output. Both operands must be valid (``Mesh.is_valid()``).
/// An operand whose facets face inward (negative volume) is turned
/// outward unless ``keep_orientation``. Returns the result and the
/// signed volumes of the operands that were turned, by name.
#[pyfunction]
#[pyo3(signature = (a, b, op, *, triangulate = false, smooth = None, keep_orientation = false))]
pub fn boolean<'py>(
    py: Python<'py>,
    a: &Bound<'py, Mesh>,
    b: &Bound<'py, Mesh>,
    op: &str,
    triangulate: bool,
    smooth: Option<f64>,
    keep_orientation: bool,
) -> PyResult<WithTurned<'py>> {
    let op = parse_op(op)?;
    let (a, b) = (&a.get().mesh, &b.get().mesh);
    let variant = variant(triangulate);
    let mut turned = Vec::new();
    let (a, b) = if keep_orientation {
        (Cow::Borrowed(a), Cow::Borrowed(b))
    } else {
        (outward(a, "a", &mut turned), outward(b, "b", &mut turned))
    };
    let (a, b) = (a.as_ref(), b.as_ref());
    let out = run(py, || match smooth {
        Some(t) if t != 0.0 => {
            // As the command line does: the operands' contacts at the
            // tolerance, and smoothing only there (`smooth_solid_near`).
            let opts = SmoothOptions::new(t).guarded();
            opts.validate().map_err(|source| UmbraError::Smooth {
                file: String::new(),
                source,
            })?;
            let (raw, contacts) =
                boolean_solid_with_contacts(a, b, op, variant, t).map_err(|source| {
                    UmbraError::Boolean3 {
                        file: String::new(),
                        source,
                    }
                })?;
            smooth_solid_near(&raw.mesh, variant, &opts, &contacts)
                .map(|out| (out.shape, Some(out.report)))
                .map_err(|source| UmbraError::Smooth {
                    file: String::new(),
                    source,
                })
        }
        _ => solid(a, b, op, variant).map(|m| (m, None)),
    })?;
    warn_if_undone(py, out.1.as_ref())?;
    Ok((Mesh::wrap(py, out.0)?, turned))
}

/// Smooths a mesh (Appendix A) at ``tolerance``, by default 1e-9 times
/// the largest extent of its bounding box (the rule of ``umbra smooth``).
/// A triangle mesh stays a triangle mesh. The mesh must be valid.
#[pyfunction]
#[pyo3(signature = (mesh, tolerance = None))]
pub fn smooth<'py>(
    py: Python<'py>,
    mesh: &Bound<'py, Mesh>,
    tolerance: Option<f64>,
) -> PyResult<Bound<'py, Mesh>> {
    let mesh = &mesh.get().mesh;
    let out = run(py, || {
        let tol = tolerance.unwrap_or_else(|| default_mesh_tolerance(mesh));
        let variant = if as_triangle_mesh(mesh).is_some() {
            MeshVariant::TriangleMesh
        } else {
            MeshVariant::PolygonMesh
        };
        smoothed(mesh, variant, tol)
    })?;
    warn_if_undone(py, Some(&out.report))?;
    Mesh::wrap(py, out.shape)
}

/// The meshes of the Python iterable `meshes`, named `{name}[i]` in
/// messages, each turned outward (noted in `turned`) unless
/// `keep_orientation`.
fn meshes_of(
    meshes: &Bound<'_, PyAny>,
    name: &str,
    keep_orientation: bool,
    turned: &mut Vec<(String, f64)>,
) -> PyResult<Vec<PolygonMesh>> {
    let mut items = Vec::new();
    for (i, m) in meshes.try_iter()?.enumerate() {
        let m = m?;
        let m = m
            .cast_into::<Mesh>()
            .map_err(|_| error(format!("{name}[{i}]: expected an umbra.Mesh")))?;
        let mesh = &m.get().mesh;
        items.push(if keep_orientation {
            mesh.clone()
        } else {
            outward(mesh, &format!("{name}[{i}]"), turned).into_owned()
        });
    }
    Ok(items)
}

/// An n-ary Boolean's error with the bad operand named as the Python
/// argument (`operand(index)`).
fn solids_error(e: SolidsError, operand: impl Fn(usize) -> String) -> String {
    match e {
        SolidsError::InvalidOperand { index, source } => UmbraError::InvalidShape {
            file: operand(index),
            source,
        }
        .to_string(),
        other => other.to_string(),
    }
}

/// The union of every mesh of ``meshes`` in one call
/// (`umbra::union_all_solids`): a balanced tree of binary Booleans whose
/// independent branches run in parallel, the same result whatever the
/// thread count; one mesh is returned as it is, none gives the empty mesh.
/// A mesh whose facets face inward is turned outward unless
/// ``keep_orientation``. Returns the result and the signed volumes of the
/// meshes that were turned, by name.
#[pyfunction]
#[pyo3(signature = (meshes, *, triangulate = false, keep_orientation = false))]
pub fn union_all<'py>(
    py: Python<'py>,
    meshes: &Bound<'py, PyAny>,
    triangulate: bool,
    keep_orientation: bool,
) -> PyResult<WithTurned<'py>> {
    let mut turned = Vec::new();
    let items = meshes_of(meshes, "meshes", keep_orientation, &mut turned)?;
    let variant = variant(triangulate);
    let out = run(py, || {
        union_all_solids(&items, variant)
            .map(|out| out.mesh)
            .map_err(|e| solids_error(e, |i| format!("meshes[{i}]")))
    })?;
    Ok((Mesh::wrap(py, out)?, turned))
}

/// ``a`` minus every mesh of ``others`` in one call
/// (`umbra::difference_all_solids`): ``a`` minus the balanced union of the
/// others, whose independent branches run in parallel, the same result
/// whatever the thread count; ``a`` itself when ``others`` is empty.
/// Meshes whose facets face inward are turned outward unless
/// ``keep_orientation``. Returns the result and the signed volumes of the
/// meshes that were turned, by name.
#[pyfunction]
#[pyo3(signature = (a, others, *, triangulate = false, keep_orientation = false))]
pub fn difference_all<'py>(
    py: Python<'py>,
    a: &Bound<'py, Mesh>,
    others: &Bound<'py, PyAny>,
    triangulate: bool,
    keep_orientation: bool,
) -> PyResult<WithTurned<'py>> {
    let mut turned = Vec::new();
    let first = &a.get().mesh;
    let first = if keep_orientation {
        Cow::Borrowed(first)
    } else {
        outward(first, "a", &mut turned)
    };
    let items = meshes_of(others, "others", keep_orientation, &mut turned)?;
    let (first, variant) = (first.as_ref(), variant(triangulate));
    let out = run(py, || {
        difference_all_solids(first, &items, variant)
            .map(|out| out.mesh)
            .map_err(|e| {
                solids_error(e, |i| match i {
                    0 => "a".to_string(),
                    i => format!("others[{}]", i - 1),
                })
            })
    })?;
    Ok((Mesh::wrap(py, out)?, turned))
}

/// The mesh of a CSG tree given as a dict in the JSON form of ``umbra
/// csg`` (``{"op": "difference", "children": [{"box": {...}}, ...]}``;
/// ``umbra csg --help`` shows every node). ``file`` leaves are read
/// relative to the working directory. Independent branches run in
/// parallel; the result is the same whatever the thread count.
/// ``smooth=T`` smooths the result at tolerance ``T`` near where the
/// operands of the tree's Booleans met, as ``umbra csg --smooth T`` does;
/// ``None`` (the default) or 0 returns the Booleans' raw output.
#[pyfunction]
#[pyo3(signature = (tree, *, triangulate = false, smooth = None))]
pub fn csg<'py>(
    py: Python<'py>,
    tree: &Bound<'py, PyAny>,
    triangulate: bool,
    smooth: Option<f64>,
) -> PyResult<Bound<'py, Mesh>> {
    if !tree.is_instance_of::<PyDict>() {
        return Err(error(
            "tree: expected a dict (the JSON form of `umbra csg`)",
        ));
    }
    let kwargs = PyDict::new(py);
    kwargs.set_item("allow_nan", false)?;
    let text: String = py
        .import("json")?
        .call_method("dumps", (tree,), Some(&kwargs))
        .map_err(|e| error(format!("tree: not JSON data: {e}")))?
        .extract()?;
    let smooth = smooth.filter(|&t| t != 0.0);
    let out = run(py, || -> Result<MaybeSmoothed, String> {
        let smooth_error = |source| {
            UmbraError::Smooth {
                file: String::new(),
                source,
            }
            .to_string()
        };
        let opts = smooth.map(|t| SmoothOptions::new(t).guarded());
        if let Some(o) = &opts {
            o.validate().map_err(smooth_error)?;
        }
        let node = parse_csg(&text).map_err(|e| e.to_string())?;
        let options = CsgOptions {
            triangulate,
            contacts: smooth,
            raw_intermediates: false,
        };
        let result = evaluate_csg(&node, options).map_err(|e| e.to_string())?;
        let Some(opts) = opts else {
            return Ok((result.mesh, None));
        };
        // As the command line does: near the gathered contacts when they
        // reach the tolerance, else the whole mesh.
        smooth_csg_result(&result, variant(triangulate), &opts)
            .map(|(out, _)| (out.shape, Some(out.report)))
            .map_err(smooth_error)
    })?;
    warn_if_undone(py, out.1.as_ref())?;
    Mesh::wrap(py, out.0)
}

/// Panics inside an operation, for the test that no panic crosses into
/// Python (it must raise ``UmbraError("internal error ...")``).
#[pyfunction]
#[pyo3(name = "_panic_for_tests")]
pub fn panic_for_tests(py: Python<'_>) -> PyResult<()> {
    run(py, || -> Result<(), String> {
        panic!("deliberate panic of the test hook")
    })
}
