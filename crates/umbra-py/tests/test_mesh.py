"""Mesh construction, arrays in and out, validity, volume, check reports
and every kind of bad input."""

import math
import pickle

import numpy as np
import pytest

import umbra
from conftest import cube, tetra


def test_arrays_round_trip_and_analytic_volumes():
    c = cube((1.0, -2.0, 0.5), 2.0)
    assert c.vertices.dtype == np.float64 and c.vertices.shape == (8, 3)
    assert c.volume() == 8.0
    assert c.is_valid()
    # Quads: one 1-D array per facet, and the same mesh again from them.
    assert isinstance(c.faces, list) and [len(f) for f in c.faces] == [4] * 6
    assert umbra.Mesh(c.vertices, c.faces) == c
    t = tetra()
    assert t.faces.dtype == np.int64 and t.faces.shape == (4, 3)
    assert abs(t.volume() - 1.0 / 6.0) < 1e-15
    assert umbra.Mesh(t.vertices, t.faces) == t
    # The triangulation of the quads covers the same volume.
    tri = umbra.Mesh(c.vertices, c.triangles)
    assert tri.faces.shape == (12, 3) and tri.volume() == 8.0


def test_inputs_in_any_array_form():
    t = tetra()
    as_lists = umbra.Mesh(t.vertices.tolist(), t.faces.tolist())
    as_int_vertices = umbra.Mesh(t.vertices.astype(np.int32), t.faces.astype(np.uint16))
    as_tuples = umbra.Mesh(tuple(map(tuple, t.vertices)), [tuple(f) for f in t.faces])
    assert as_lists == t and as_int_vertices == t and as_tuples == t
    # Mixed polygon sizes (a ragged list) and numpy integer scalars.
    v = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0.5, 0.5, 1]], dtype=float)
    pyramid = umbra.Mesh(v, [[0, 3, 2, 1], [0, 1, 4], [1, 2, 4], [2, 3, 4], [3, 0, 4]])
    assert pyramid.is_valid()
    assert abs(pyramid.volume() - 1.0 / 3.0) < 1e-15
    assert [len(f) for f in pyramid.faces] == [4, 3, 3, 3, 3]
    empty = umbra.Mesh(np.zeros((0, 3)), [])
    assert empty.vertices.shape == (0, 3) and empty.faces.shape == (0, 3)
    assert empty.volume() == 0.0


def test_facets_with_holes_round_trip():
    # A square slab with a square hole through it: the top and bottom
    # facets have two loops each.
    outer = [(0, 0), (3, 0), (3, 3), (0, 3)]
    inner = [(1, 1), (2, 1), (2, 2), (1, 2)]
    pts = [(x, y, z) for z in (0.0, 1.0) for (x, y) in outer + inner]
    v = np.array(pts, dtype=float)  # 0-7 at z=0, 8-15 at z=1
    bottom = [[0, 3, 2, 1], [4, 5, 6, 7]]
    top = [[8, 9, 10, 11], [12, 15, 14, 13]]
    sides = []
    for i in range(4):
        j = (i + 1) % 4
        sides.append([i, j, j + 8, i + 8])
        sides.append([4 + j, 4 + i, 12 + i, 12 + j])
    m = umbra.Mesh(v, [bottom, top] + sides)
    assert m.is_valid() and m.volume() == 8.0
    faces = m.faces
    assert isinstance(faces[0], list) and len(faces[0]) == 2
    assert umbra.Mesh(m.vertices, faces).volume() == 8.0
    assert umbra.Mesh(m.vertices, m.triangles).volume() == 8.0


def test_exact_array_form_and_pickle():
    c = cube((0.1, 0.2, 0.3), 0.7)
    v, he, off = c.to_arrays()
    assert he.shape == (24, 2) and off.tolist() == [0, 4, 8, 12, 16, 20, 24]
    assert umbra.Mesh.from_arrays(v, he, off) == c
    back = pickle.loads(pickle.dumps(c))
    assert back == c and back is not c
    with pytest.raises(umbra.UmbraError, match="facet_offsets"):
        umbra.Mesh.from_arrays(v, he, [0, 5, 4, 24])
    with pytest.raises(umbra.UmbraError, match="out of range"):
        umbra.Mesh.from_arrays(v, he + 8, off)
    # The array shapes are part of the form: a flat or (h, 3) array of the
    # same indices is not an (h, 2) one.
    with pytest.raises(umbra.UmbraError, match=r"half_edges: expected an \(n, 2\)"):
        umbra.Mesh.from_arrays(v, he.reshape(-1), off)
    with pytest.raises(umbra.UmbraError, match=r"half_edges: expected an \(n, 2\)"):
        umbra.Mesh.from_arrays(v, he.reshape(-1, 3), off)
    with pytest.raises(umbra.UmbraError, match=r"facet_offsets: expected a 1-D"):
        umbra.Mesh.from_arrays(v, he, off.reshape(-1, 1))


def test_check_reports_like_the_cli():
    r = cube().check()
    assert r["topologically_valid"] and r["coordinates_valid"]
    assert r["two_manifold"] and r["self_intersecting_facet_pairs"] == 0
    assert r["signed_volume"] == 1.0
    assert r["bounding_box"] == [[0.0, 0.0, 0.0], [1.0, 1.0, 1.0]]
    assert (r["vertices"], r["facets"], r["half_edges"], r["edges"]) == (8, 6, 24, 12)


def test_open_mesh_is_reported_and_refused():
    c = cube()
    open_box = umbra.Mesh(c.vertices, c.faces[1:])
    assert not open_box.is_valid()
    r = open_box.check()
    assert not r["topologically_valid"] and r["topology_error"]
    with pytest.raises(umbra.UmbraError, match="invalid shape"):
        open_box.volume()
    with pytest.raises(umbra.UmbraError, match="operand A"):
        umbra.boolean(open_box, c, "union")
    with pytest.raises(umbra.UmbraError, match="operand B"):
        umbra.boolean(c, open_box, "union")


@pytest.mark.parametrize("bad", [math.nan, math.inf, -math.inf, 1e308])
def test_bad_coordinates_are_reported_and_refused(bad):
    v = cube().vertices
    v[5, 1] = bad
    m = umbra.Mesh(v, cube().faces)
    assert not m.is_valid()
    r = m.check()
    assert r["topologically_valid"] and not r["coordinates_valid"]
    assert r["coordinate_error"]
    with pytest.raises(umbra.UmbraError):
        m.volume()
    with pytest.raises(umbra.UmbraError, match="operand B"):
        umbra.boolean(cube(), m, "difference")
    # The caller's arrays are untouched.
    assert v[5, 1] == bad or (math.isnan(bad) and math.isnan(v[5, 1]))


@pytest.mark.parametrize(
    "vertices, faces, match",
    [
        (np.zeros((4, 2)), [[0, 1, 2]], r"vertices: expected an \(n, 3\) array.*shape \(4, 2\)"),
        (np.zeros((4, 3, 1)), [[0, 1, 2]], "shape"),
        (np.array([["a", "b", "c"]]), [[0, 0, 0]], "dtype"),
        (np.zeros((4, 3), dtype=bool), [[0, 1, 2]], "dtype bool"),
        ([[0, 0, 0], [1, 0]], [[0, 1, 1]], "vertices"),
        (np.zeros((4, 3)), np.array([[0.0, 1.0, 2.0]]), "dtype float64"),
        (np.zeros((4, 3)), np.array([[0, 1]]), r"shape \(1, 2\)"),
        (np.zeros((4, 3)), np.array([0, 1, 2]), r"shape \(3,\)"),
        (np.zeros((4, 3)), [[0, 1, 4]], "vertex index 4 out of range"),
        (np.zeros((4, 3)), np.array([[0, 1, 7]], dtype=np.uint8), "vertex index 7 out of range"),
        (np.zeros((4, 3)), [[0, -1, 2]], "negative vertex index -1"),
        (np.zeros((4, 3)), [[0, 1, 2], []], "faces"),
        (np.zeros((4, 3)), [[0, 1, 2], [0, 1.5, 2]], "faces"),
        (np.zeros((4, 3)), [[0, 1, 2], "abc"], "faces"),
        (np.zeros((4, 3)), 5, "faces"),
    ],
)
def test_bad_arrays_raise_umbra_errors(vertices, faces, match):
    with pytest.raises(umbra.UmbraError, match=match):
        umbra.Mesh(vertices, faces)


def test_umbra_error_is_a_value_error_and_panics_never_cross():
    assert issubclass(umbra.UmbraError, ValueError)
    with pytest.raises(umbra.UmbraError, match=r"^internal error \(this is a bug, please report it\)"):
        umbra._umbra._panic_for_tests()
    # The interpreter is fine afterwards.
    assert cube().volume() == 1.0


def test_umbra_error_pickles_for_worker_processes():
    # Errors raised in a worker process travel back by pickle.
    e = pickle.loads(pickle.dumps(umbra.UmbraError("bad input")))
    assert type(e) is umbra.UmbraError and str(e) == "bad input"
    assert umbra.UmbraError.__module__ == "umbra"
