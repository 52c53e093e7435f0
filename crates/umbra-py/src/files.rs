//! Files: every format of the command-line tool, decided by the extension
//! (`.obj .off .stl .ply .3mf .glb .gltf` meshes read and written; `.wkt
//! .geojson` polygons read and written, `.svg` written),
//! through the facade's readers and writers, so messages are the tool's.

use crate::mesh::Mesh;
use crate::planar::{orientation, polygons_to_py};
use crate::run;
use pyo3::prelude::*;
use pyo3::types::PyTuple;
use std::path::PathBuf;
use umbra::{
    layout_polygons, read_mesh, read_polygon_set_counted, write_mesh_with, write_polygon_set,
    FileKind, MeshReadOptions, MeshWriteOptions, ReadOptions,
};

/// What a file held.
enum Content {
    Mesh(umbra::PolygonMesh),
    /// The polygons and the warning about parts skipped, if any.
    Polygons(umbra::Polygons, Option<String>),
}

/// Reads a file: `("mesh", Mesh)` or `("polygons", list)`.
#[pyfunction]
#[pyo3(signature = (path, *, check = true, keep_orientation = false))]
pub fn read<'py>(
    py: Python<'py>,
    path: PathBuf,
    check: bool,
    keep_orientation: bool,
) -> PyResult<Bound<'py, PyTuple>> {
    let content = run(py, || {
        if FileKind::from_path(&path)?.is_mesh() {
            let options = MeshReadOptions {
                validate_coordinates: check,
            };
            read_mesh(&path, options, check).map(Content::Mesh)
        } else {
            let options = ReadOptions {
                orientation: orientation(keep_orientation),
                validate_coordinates: true,
            };
            let read = read_polygon_set_counted(&path, options)?;
            let file = path.display().to_string();
            let warning = read.warning(&file);
            layout_polygons(&read.set, orientation(keep_orientation), &file)
                .map(|l| Content::Polygons(l.polygons, warning))
        }
    })?;
    match content {
        Content::Mesh(m) => PyTuple::new(
            py,
            [
                "mesh".into_pyobject(py)?.into_any(),
                Mesh::wrap(py, m)?.into_any(),
            ],
        ),
        Content::Polygons(p, warning) => {
            if let Some(w) = warning {
                crate::warn_user(py, &w)?;
            }
            PyTuple::new(
                py,
                [
                    "polygons".into_pyobject(py)?.into_any(),
                    polygons_to_py(py, &p)?,
                ],
            )
        }
    }
}

/// Writes a mesh; STL and PLY binary unless `ascii`.
#[pyfunction]
#[pyo3(signature = (mesh, path, *, ascii = false))]
pub fn write_mesh(
    py: Python<'_>,
    mesh: &Bound<'_, Mesh>,
    path: PathBuf,
    ascii: bool,
) -> PyResult<()> {
    let m = &mesh.get().mesh;
    run(py, || {
        write_mesh_with(&path, m, MeshWriteOptions { text: ascii })
    })
}

/// Writes polygons (the plain Python form); returns the number of holes
/// that lie in no outer ring (an inside-out shape, written as exteriors).
#[pyfunction]
#[pyo3(signature = (polygons, path, *, keep_orientation = false))]
pub fn write_polygons(
    py: Python<'_>,
    polygons: &Bound<'_, PyAny>,
    path: PathBuf,
    keep_orientation: bool,
) -> PyResult<usize> {
    let set = crate::planar::input_set(py, polygons, keep_orientation, "geom")?;
    run(py, || {
        write_polygon_set(&path, &set, orientation(keep_orientation))
    })
}
