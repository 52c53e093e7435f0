//! `umbra.Mesh`: a polyhedral shape (the facade's `PolygonMesh`) built
//! from numpy arrays, immutable, with its checks, its volume, its exact
//! array form (pickling ships three numpy arrays) and trimesh interop.

use crate::arrays::{
    index_loop, index_matrix, index_vector, indices_of_array, is_integer, points, points_array,
    shape_text,
};
use crate::{error, run};
use numpy::{PyUntypedArray, PyUntypedArrayMethods};
use pyo3::prelude::*;
use pyo3::types::{PyList, PyTuple};
use umbra::{
    as_triangle_mesh, check_mesh, mesh_signed_volume, triangulate_mesh, Facet, HalfEdge,
    PolygonMesh, UmbraError,
};

/// A polyhedral mesh: vertices and facets (section 4.2 of the
/// dissertation). Immutable; every operation returns a new mesh.
///
/// ``Mesh(vertices, faces)``: ``vertices`` an (n, 3) float64 array-like;
/// ``faces`` an (m, k) integer array (k >= 3, one loop per row, usually
/// triangles) or a list whose entries are index sequences (one polygon
/// each) or lists of index sequences (a facet with holes: its outer loop
/// and hole loops, holes running the other way). Indices must name
/// existing vertices. Coordinates and closure are not checked here: see
/// ``is_valid()`` and ``check()``; the operations refuse invalid meshes.
#[pyclass(frozen, module = "umbra._umbra", name = "Mesh")]
pub struct Mesh {
    /// The shape.
    pub mesh: PolygonMesh,
}

/// The facets of `faces` for `n` vertices.
fn facets_of(faces: &Bound<'_, PyAny>, n: usize) -> PyResult<Vec<Facet>> {
    let expected = "an (m, 3) integer array or a list of index sequences";
    let np = faces.py().import("numpy")?;
    // Ragged lists make numpy raise: they take the general path below.
    if let Ok(arr) = np.call_method1("asarray", (faces,)) {
        if let Ok(arr) = arr.cast_into::<PyUntypedArray>() {
            let shape = arr.shape().to_vec();
            if shape == [0] {
                return Ok(Vec::new());
            }
            if shape.len() == 2 {
                let (rows, cols) = (shape[0], shape[1]);
                let Some(flat) = indices_of_array(&arr, n, "faces")? else {
                    let name: String = arr.getattr("dtype")?.getattr("name")?.extract()?;
                    return Err(error(format!(
                        "faces: expected {expected}, got dtype {name}"
                    )));
                };
                if cols < 3 && rows > 0 {
                    return Err(error(format!(
                        "faces: expected {expected}, got shape {}",
                        shape_text(&shape)
                    )));
                }
                return Ok(flat
                    .chunks_exact(cols.max(1))
                    .map(Facet::from_loop)
                    .collect());
            }
            if shape.len() == 1
                && arr.getattr("dtype")?.getattr("kind")?.extract::<String>()? != "O"
            {
                return Err(error(format!(
                    "faces: expected {expected}, got shape {}",
                    shape_text(&shape)
                )));
            }
        }
    }
    let mut facets = Vec::new();
    let items = faces
        .try_iter()
        .map_err(|_| error(format!("faces: expected {expected}")))?;
    for (i, entry) in items.enumerate() {
        let entry = entry?;
        let what = format!("faces[{i}]");
        if is_integer(&entry) {
            return Err(error(format!(
                "faces: expected {expected}, got an integer at {what}"
            )));
        }
        let first = entry
            .get_item(0)
            .map_err(|_| error(format!("{what}: expected a non-empty index sequence")))?;
        if is_integer(&first) {
            facets.push(Facet::from_loop(&index_loop(&entry, n, &what)?));
        } else {
            let mut f = Facet::default();
            for (j, l) in entry.try_iter()?.enumerate() {
                f.push_loop(&index_loop(&l?, n, &format!("{what}[{j}]"))?);
            }
            facets.push(f);
        }
    }
    Ok(facets)
}

/// An integer array as `u32` values below `limit`: 1-D, or of shape
/// `(n, columns)` (`what` names it in errors).
fn u32_array(
    obj: &Bound<'_, PyAny>,
    limit: usize,
    columns: Option<usize>,
    what: &str,
) -> PyResult<Vec<u32>> {
    let arr = obj
        .py()
        .import("numpy")?
        .call_method1("asarray", (obj,))
        .and_then(|a| Ok(a.cast_into::<PyUntypedArray>()?))
        .map_err(|e| error(format!("{what}: expected an integer array: {e}")))?;
    // The shape is part of the form: a flat (h * 2) or (h, 3) array is not
    // an (h, 2) one, though it holds an even number of indices.
    let shape = arr.shape();
    let (expected, fits) = match columns {
        None => ("a 1-D".to_string(), shape.len() == 1),
        Some(c) => (format!("an (n, {c})"), shape.len() == 2 && shape[1] == c),
    };
    if !fits {
        return Err(error(format!(
            "{what}: expected {expected} integer array, got shape {shape:?}"
        )));
    }
    indices_of_array(&arr, limit, what)?
        .ok_or_else(|| error(format!("{what}: expected an integer array")))
}

impl Mesh {
    /// The mesh of `mesh`, as a Python object.
    pub fn wrap(py: Python<'_>, mesh: PolygonMesh) -> PyResult<Bound<'_, Mesh>> {
        Bound::new(py, Mesh { mesh })
    }
}

#[pymethods]
impl Mesh {
    #[new]
    #[pyo3(signature = (vertices, faces))]
    fn new(vertices: &Bound<'_, PyAny>, faces: &Bound<'_, PyAny>) -> PyResult<Self> {
        let vertices = points::<3>(vertices, "vertices")?;
        if vertices.len() > u32::MAX as usize {
            return Err(error("vertices: more than 2^32 - 1 vertices"));
        }
        let facets = facets_of(faces, vertices.len())?;
        Ok(Mesh {
            mesh: PolygonMesh::new(vertices, facets),
        })
    }

    /// The vertex positions: an (n, 3) float64 array (a copy).
    #[getter]
    fn vertices<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        points_array(py, &self.mesh.vertices)
    }

    /// The facets: an (m, 3) int64 array when every facet is one triangle;
    /// otherwise a list with one entry per facet: a 1-D int64 array of the
    /// loop's vertex indices, or for a facet of several loops (holes, or
    /// several regions) a list of such arrays. ``Mesh(m.vertices,
    /// m.faces)`` rebuilds the same mesh.
    #[getter]
    fn faces<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        if let Some(t) = as_triangle_mesh(&self.mesh) {
            let flat: Vec<i64> = t
                .triangles
                .iter()
                .flatten()
                .map(|&i| i64::from(i))
                .collect();
            return index_matrix(py, flat, t.triangles.len(), 3);
        }
        let list = PyList::empty(py);
        for f in &self.mesh.facets {
            let loops = f.loops_in_plane(&self.mesh.vertices);
            if loops.len() == 1 {
                list.append(index_vector(py, &loops[0]))?;
            } else {
                let inner = PyList::empty(py);
                for l in &loops {
                    inner.append(index_vector(py, l))?;
                }
                list.append(inner)?;
            }
        }
        Ok(list.into_any())
    }

    /// The facets triangulated by internal edges (section 4.8): a (t, 3)
    /// int64 array over the same vertices (the form trimesh and renderers
    /// take). Facets with holes are triangulated around the holes.
    #[getter]
    fn triangles<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let m = &self.mesh;
        let tris = run(py, || {
            if let Err(e) = m.check_topology() {
                return Err(format!("mesh: invalid shape: {e}"));
            }
            Ok(match as_triangle_mesh(m) {
                Some(t) => t.triangles,
                None => triangulate_mesh(m).triangles,
            })
        })?;
        let flat: Vec<i64> = tris.iter().flatten().map(|&i| i64::from(i)).collect();
        index_matrix(py, flat, tris.len(), 3)
    }

    /// `true` when every facet and the whole shape are closed (section 4.2)
    /// and every coordinate is finite and at most ``f64::MAX / 4``: what
    /// the operations require.
    fn is_valid(&self, py: Python<'_>) -> PyResult<bool> {
        let m = &self.mesh;
        run(py, || {
            Ok::<_, String>(m.check_topology().is_ok() && m.validate_coordinates().is_ok())
        })
    }

    /// The mesh with every facet turned over: each loop walked backwards,
    /// so inside and outside swap (the volume changes sign).
    fn reversed(&self) -> Mesh {
        Mesh {
            mesh: self.mesh.reversed(),
        }
    }

    /// The signed volume (positive for outward-facing facets). Raises
    /// ``UmbraError`` for an invalid mesh (an open mesh encloses no
    /// volume).
    fn volume(&self, py: Python<'_>) -> PyResult<f64> {
        let m = &self.mesh;
        run(py, || {
            m.check_topology()
                .and_then(|()| m.validate_coordinates())
                .map_err(|source| UmbraError::InvalidShape {
                    file: "mesh".into(),
                    source,
                })?;
            Ok::<_, UmbraError>(mesh_signed_volume(m))
        })
    }

    /// The report of ``umbra check --json`` as a dict (without ``file``):
    /// counts, topological and coordinate validity with the first problem,
    /// 2-manifoldness, exact count of self-intersecting facet pairs,
    /// signed volume and bounding box. Never raises for a bad mesh: that is
    /// what it reports.
    fn check<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let m = &self.mesh;
        let json = run(py, || serde_json::to_string(&check_mesh(m)))?;
        py.import("json")?.call_method1("loads", (json,))
    }

    /// The exact array form ``(vertices, half_edges, facet_offsets)``:
    /// vertices (n, 3) float64, half-edges (h, 2) uint32 (start, end;
    /// umbra's indices are 32-bit), and int64 offsets (m + 1) such that
    /// facet i owns half-edges ``offsets[i]:offsets[i+1]``. This is what
    /// pickling ships: 24 bytes a vertex, 8 a half-edge, 8 a facet.
    fn to_arrays<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyTuple>> {
        let m = &self.mesh;
        let mut he = Vec::with_capacity(2 * m.half_edge_count());
        let mut offsets = Vec::with_capacity(m.facets.len() + 1);
        offsets.push(0i64);
        for f in &m.facets {
            for h in &f.half_edges {
                he.push(h.start);
                he.push(h.end);
            }
            offsets.push((he.len() / 2) as i64);
        }
        let rows = he.len() / 2;
        PyTuple::new(
            py,
            [
                points_array(py, &m.vertices)?,
                index_matrix(py, he, rows, 2)?,
                numpy::PyArray1::from_vec(py, offsets).into_any(),
            ],
        )
    }

    /// The mesh of an array form made by ``to_arrays()``.
    #[staticmethod]
    fn from_arrays(
        vertices: &Bound<'_, PyAny>,
        half_edges: &Bound<'_, PyAny>,
        facet_offsets: &Bound<'_, PyAny>,
    ) -> PyResult<Self> {
        let vertices = points::<3>(vertices, "vertices")?;
        let he = u32_array(half_edges, vertices.len(), Some(2), "half_edges")?;
        let count = he.len() / 2;
        let offsets = u32_array(facet_offsets, count + 1, None, "facet_offsets")?;
        if offsets.first() != Some(&0)
            || offsets.last() != Some(&(count as u32))
            || offsets.windows(2).any(|w| w[0] > w[1])
        {
            return Err(error(
                "facet_offsets: expected non-decreasing offsets from 0 to the half-edge count",
            ));
        }
        let facets = offsets
            .windows(2)
            .map(|w| Facet {
                half_edges: he[2 * w[0] as usize..2 * w[1] as usize]
                    .chunks_exact(2)
                    .map(|p| HalfEdge {
                        start: p[0],
                        end: p[1],
                    })
                    .collect(),
            })
            .collect();
        Ok(Mesh {
            mesh: PolygonMesh::new(vertices, facets),
        })
    }

    /// The mesh of a ``trimesh.Trimesh`` (its vertices and faces, exactly).
    /// Anything without both (a ``trimesh.Scene``, which ``trimesh.load``
    /// returns for many files, or a ``PointCloud``) is an ``UmbraError``
    /// saying what to pass instead.
    #[staticmethod]
    fn from_trimesh(m: &Bound<'_, PyAny>) -> PyResult<Self> {
        match (m.getattr("vertices"), m.getattr("faces")) {
            (Ok(v), Ok(f)) => Mesh::new(&v, &f),
            _ => {
                let kind = m
                    .get_type()
                    .name()
                    .map_or_else(|_| "object".to_string(), |n| n.to_string());
                Err(error(format!(
                    "from_trimesh: expected a trimesh.Trimesh (vertices and faces), got a {kind}; \
                     for a trimesh.Scene pass scene.to_mesh() (its meshes through their transforms)"
                )))
            }
        }
    }

    /// A ``trimesh.Trimesh`` of this mesh (``triangles`` as faces; no
    /// processing, so vertices stay as they are). Needs trimesh.
    fn to_trimesh<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let trimesh = py.import("trimesh")?;
        let kwargs = pyo3::types::PyDict::new(py);
        kwargs.set_item("vertices", self.vertices(py)?)?;
        kwargs.set_item("faces", self.triangles(py)?)?;
        kwargs.set_item("process", false)?;
        trimesh.getattr("Trimesh")?.call((), Some(&kwargs))
    }

    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<Bound<'py, PyTuple>> {
        let py = slf.py();
        let ctor = py.get_type::<Mesh>().getattr("from_arrays")?;
        PyTuple::new(py, [ctor, slf.get().to_arrays(py)?.into_any()])
    }

    /// Meshes are equal when their vertices (bit for bit, so never with a
    /// NaN) and facets (half-edges in order) are.
    fn __eq__(&self, other: &Bound<'_, PyAny>) -> bool {
        other
            .cast::<Mesh>()
            .is_ok_and(|o| o.get().mesh == self.mesh)
    }

    fn __repr__(&self) -> String {
        format!(
            "umbra.Mesh({} vertices, {} faces, {} half-edges)",
            self.mesh.vertices.len(),
            self.mesh.facets.len(),
            self.mesh.half_edge_count()
        )
    }
}
