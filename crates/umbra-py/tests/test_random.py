"""Random and garbage input, seeded: closed operands with random
coordinates always give topologically valid results (the contract of
section 4.2), and garbage always gives an UmbraError, never another
exception or a crash."""

import numpy as np
import pytest

import umbra

OCTA_FACES = np.array(
    [[0, 2, 4], [2, 1, 4], [1, 3, 4], [3, 0, 4], [2, 0, 5], [1, 2, 5], [3, 1, 5], [0, 3, 5]]
)


def random_octahedron(rng, scale):
    """Six random points joined as an octahedron: closed whatever the
    coordinates (often inside-out or self-intersecting)."""
    return umbra.Mesh(rng.normal(size=(6, 3)) * scale, OCTA_FACES)


@pytest.mark.parametrize("seed", range(8))
@pytest.mark.filterwarnings("ignore:.*the facets face inward:UserWarning")
def test_random_closed_operands_give_valid_results(seed):
    rng = np.random.default_rng(seed)
    for case in range(25):
        scale = 10.0 ** rng.integers(-3, 4)
        a, b = random_octahedron(rng, scale), random_octahedron(rng, scale)
        if case % 5 == 0:  # shared vertices: degenerate on purpose
            b = umbra.Mesh(np.vstack([a.vertices[:3], b.vertices[3:]]), OCTA_FACES)
        op = ("union", "intersection", "difference")[case % 3]
        # Inside-out operands as written half the time, turned outward
        # (with a warning) the other half.
        keep = case % 4 < 2
        out = umbra.boolean(a, b, op, triangulate=bool(case % 2), keep_orientation=keep)
        r = out.check()
        assert r["topologically_valid"], (seed, case, r["topology_error"])
        assert r["coordinates_valid"]


@pytest.mark.parametrize("seed", range(4))
def test_random_polygons_give_valid_results(seed):
    rng = np.random.default_rng(100 + seed)
    for case in range(25):
        a = [[rng.normal(size=(rng.integers(3, 9), 2))] for _ in range(rng.integers(1, 4))]
        b = [[rng.normal(size=(rng.integers(3, 9), 2))] for _ in range(rng.integers(1, 4))]
        op = ("union", "intersection", "difference", "xor")[case % 4]
        via = ("basic", "simplify")[case % 2]
        out = umbra.boolean_2d(a, b, op, via=via)
        # The output is laid out from a valid set: it reads back, and its
        # simplification by the positive rule is valid input again.
        assert all(r.shape[1] == 2 and np.isfinite(r).all() for p in out for r in p)
        umbra.simplify(out)


GARBAGE: list = [
    None, 3, 2.5, "abc", b"\x00\x01", [], [[]], [[[]]], [None], [[1, 2]], [[1, 2, "x"]],
    np.zeros((2, 2, 2)), np.array([[np.nan, 0, 0]]), np.full((3, 3), 1e308),
    [[0, 0, 0], [1, 1]], {"a": 1}, np.array([[1 + 2j, 0, 0]]),
]


@pytest.mark.parametrize("vertices", GARBAGE + [np.zeros((3, 3))])
@pytest.mark.parametrize("faces", GARBAGE + [[[0, 1, 2]]])
def test_garbage_never_escapes_as_another_error(vertices, faces):
    try:
        m = umbra.Mesh(vertices, faces)
    except umbra.UmbraError:
        return
    # Built: every query answers or raises UmbraError.
    for call in (m.check, m.is_valid, m.to_arrays, lambda: m.faces, lambda: m.vertices):
        call()
    for call in (m.volume, lambda: m.triangles, lambda: umbra.boolean(m, m, "union")):
        try:
            call()
        except umbra.UmbraError:
            pass


@pytest.mark.parametrize("geom", GARBAGE + [[[np.zeros((2, 3))]], [[[[0, 0], [1, 1]]]]])
def test_2d_garbage_never_escapes_as_another_error(geom):
    try:
        umbra.boolean_2d(geom, [[np.eye(2)]], "union")
    except umbra.UmbraError:
        pass
    try:
        umbra.simplify(geom)
    except umbra.UmbraError:
        pass
