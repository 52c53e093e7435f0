"""3D Booleans, n-ary unions and differences and CSG trees against analytic
volumes, with every operand left untouched and every bad argument refused."""

import math
import pickle
import warnings

import numpy as np
import pytest

import umbra
from conftest import cube


def close(x, y, tol=1e-12):
    return abs(x - y) <= tol * max(1.0, abs(y))


@pytest.mark.parametrize("triangulate", [False, True])
@pytest.mark.parametrize(
    "shift, union, inter",
    [
        ((0.5, 0.5, 0.5), 1.875, 0.125),  # general position
        ((0.5, 0.0, 0.0), 1.5, 0.5),  # coplanar facets (degenerate)
        ((1.0, 0.0, 0.0), 2.0, 0.0),  # touching along a facet
        ((3.0, 0.0, 0.0), 2.0, 0.0),  # disjoint
        ((0.0, 0.0, 0.0), 1.0, 1.0),  # identical
    ],
)
def test_two_cubes_analytic(shift, union, inter, triangulate):
    a, b = cube(), cube(shift)
    a_before, b_before = pickle.dumps(a), pickle.dumps(b)
    results = {
        op: umbra.boolean(a, b, op, triangulate=triangulate)
        for op in ("union", "intersection", "difference")
    }
    for op, m in results.items():
        assert m.is_valid(), op
        assert m.check()["topologically_valid"]
        if triangulate:
            assert isinstance(m.faces, np.ndarray) and m.faces.shape[1] == 3
    assert close(results["union"].volume(), union)
    assert close(results["intersection"].volume(), inter)
    assert close(results["difference"].volume(), 1.0 - inter)
    assert pickle.dumps(a) == a_before and pickle.dumps(b) == b_before


def test_bad_operations():
    a, b = cube(), cube((0.5, 0.5, 0.5))
    with pytest.raises(umbra.UmbraError, match=r"unknown operation 'unoin' \(expected union"):
        umbra.boolean(a, b, "unoin")
    with pytest.raises(umbra.UmbraError, match="supports union, intersection and difference, not xor"):
        umbra.boolean(a, b, "xor")
    with pytest.raises(TypeError):
        umbra.boolean(a, "cube.obj", "union")


def test_union_all_balanced_tree():
    row = [cube((0.5 * i, 0.0, 0.0)) for i in range(7)]  # overlapping chain
    u = umbra.union_all(row)
    assert u.is_valid() and close(u.volume(), 4.0)
    assert u.check()["two_manifold"]
    grid = [cube((2.0 * i, 2.0 * j, 0.0)) for i in range(3) for j in range(3)]
    assert close(umbra.union_all(iter(grid)).volume(), 9.0)
    tri = umbra.union_all(row, triangulate=True)
    assert tri.faces.shape[1] == 3 and close(tri.volume(), 4.0)
    one = cube()
    assert umbra.union_all([one]) == one
    assert umbra.union_all([]).volume() == 0.0
    open_box = umbra.Mesh(one.vertices, one.faces[1:])
    with pytest.raises(umbra.UmbraError, match=r"meshes\[2\]: invalid shape"):
        umbra.union_all([one, one, open_box])
    with pytest.raises(umbra.UmbraError, match=r"meshes\[1\]: expected an umbra.Mesh"):
        umbra.union_all([one, 3])


@pytest.mark.parametrize("triangulate", [False, True])
def test_difference_all_one_minus_many(triangulate):
    # A 6 x 1 x 1 bar minus cubes of side 1.5 through its top half
    # (y > 0.5, all z): each removes 0.5 per unit of x it spans, over
    # x in [0, 1.25], [2, 3.5] and [3, 4.5] (overlapping) and [5, 6].
    bar = cube((0.0, 0.0, 0.0), 1.0)
    bar = umbra.Mesh(bar.vertices * np.array([6.0, 1.0, 1.0]), bar.faces)
    assert bar.volume() == 6.0
    tools = [cube((x, 0.5, -0.25), 1.5) for x in (-0.25, 2.0, 3.0, 5.0)]
    before = [pickle.dumps(t) for t in tools]
    d = umbra.difference_all(bar, tools, triangulate=triangulate)
    assert d.is_valid() and d.check()["two_manifold"]
    assert close(d.volume(), 6.0 - 0.5 * (1.25 + 2.5 + 1.0)), d.volume()
    if triangulate:
        assert d.faces.shape[1] == 3
    # The same as one difference at a time, and the callers' meshes untouched.
    chained = bar
    for t in tools:
        chained = umbra.boolean(chained, t, "difference", triangulate=triangulate)
    assert close(chained.volume(), d.volume())
    assert [pickle.dumps(t) for t in tools] == before
    assert umbra.difference_all(bar, []) == bar
    assert umbra.difference_all(bar, iter(tools), triangulate=triangulate) == d


def test_difference_all_names_the_bad_operand():
    one = cube()
    open_box = umbra.Mesh(one.vertices, one.faces[1:])
    with pytest.raises(umbra.UmbraError, match=r"^a: invalid shape"):
        umbra.difference_all(open_box, [one])
    with pytest.raises(umbra.UmbraError, match=r"others\[1\]: invalid shape"):
        umbra.difference_all(one, [one, open_box])
    with pytest.raises(umbra.UmbraError, match=r"others\[0\]: expected an umbra.Mesh"):
        umbra.difference_all(one, [3])
    with pytest.raises(TypeError):
        umbra.difference_all("cube.obj", [one])
    with pytest.warns(UserWarning, match=r"others\[0\]: the facets face inward"):
        d = umbra.difference_all(one, [cube((0.5, 0.5, 0.5)).reversed()])
    assert close(d.volume(), 0.875)


def test_csg_tree_dict():
    tree = {
        "op": "difference",
        "children": [
            {"box": {"size": [2, 2, 2], "center": True}},
            {"cylinder": {"radius": 0.5, "height": 3, "segments": 8, "center": True}},
        ],
    }
    m = umbra.csg(tree)
    prism = 2.0 * 4.0 * 0.25 * math.sin(math.tau / 8.0)
    assert m.is_valid() and close(m.volume(), 8.0 - prism)
    t = umbra.csg(tree, triangulate=True)
    assert t.faces.shape[1] == 3 and close(t.volume(), 8.0 - prism)
    # Transforms: a unit cube scaled by 3 and moved keeps volume 27.
    moved = umbra.csg({"box": {"size": 1}, "scale": 3, "translate": [5, 0, 0], "rotate": [0, 0, 30]})
    assert close(moved.volume(), 27.0, 1e-9)
    # The same tree as nested Booleans in Python.
    box = umbra.csg(tree["children"][0])
    cyl = umbra.csg(tree["children"][1])
    assert umbra.boolean(box, cyl, "difference") == m


@pytest.mark.parametrize(
    "tree, match",
    [
        ({"sphere": {"radius": -1}}, "radius"),
        ({"op": "union", "children": []}, "at least one child"),
        ({"pyramid": {}}, "root"),
        ({"box": {"size": [1, 1, float("nan")]}}, "not JSON data"),
        ([{"box": {"size": 1}}], "expected a dict"),
        ({"file": "no/such/file.obj"}, "no/such/file.obj"),
    ],
)
def test_bad_csg_trees(tree, match):
    with pytest.raises(umbra.UmbraError, match=match):
        umbra.csg(tree)


def test_csg_file_leaves_are_read_from_the_working_directory(tmp_path, monkeypatch):
    umbra.write(cube((0.0, 0.0, 0.0), 2.0), tmp_path / "block.off")
    monkeypatch.chdir(tmp_path)
    tree = {
        "op": "difference",
        "children": [{"file": "block.off"}, {"box": {"size": 1}, "translate": [1.5, 1.5, 1.5]}],
    }
    m = umbra.csg(tree)
    assert m.is_valid() and close(m.volume(), 8.0 - 0.125)


@pytest.mark.parametrize("triangulate", [False, True])
def test_inward_facing_operands_are_turned_outward(triangulate):
    a, b = cube(), cube((0.5, 0.5, 0.5))
    inward = b.reversed()
    assert inward.volume() == -1.0 and inward.reversed() == b
    before = pickle.dumps(inward)
    for op, want in [("union", 1.875), ("intersection", 0.125), ("difference", 0.875)]:
        with pytest.warns(UserWarning, match=r"^b: the facets face inward"):
            m = umbra.boolean(a, inward, op, triangulate=triangulate)
        assert close(m.volume(), want), op
        # As written: the inside-out solid of everything but the cube.
        with warnings.catch_warnings():
            warnings.simplefilter("error")
            kept = umbra.boolean(a, inward, op, triangulate=triangulate, keep_orientation=True)
        assert kept.is_valid()
        assert not close(kept.volume(), want), op
    assert pickle.dumps(inward) == before  # the caller's mesh is untouched
    with pytest.warns(UserWarning, match=r"meshes\[1\]: the facets face inward"):
        u = umbra.union_all([a, inward], triangulate=triangulate)
    assert close(u.volume(), 1.875)
