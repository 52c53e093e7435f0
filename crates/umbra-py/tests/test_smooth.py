"""Smoothing from Python (Appendix A): the stacked cubes of figures
5.1-5.2 become one closed box, the raw Boolean is kept when asked, a
triangle mesh stays triangles, bad tolerances raise UmbraError, and
operands are left untouched; smoothing that would leave intersecting
facet pairs the raw Boolean does not have is undone, with a warning."""

import pickle

import numpy as np
import pytest

import umbra
from conftest import cube


@pytest.mark.parametrize("triangulate", [False, True])
@pytest.mark.parametrize("gap", [0.0, 1e-9, -1e-9, 1e-7])
@pytest.mark.parametrize("order", [0, 1])
def test_stacked_cubes_become_one_box(triangulate, gap, order):
    lower, upper = cube(), cube((0.0, 0.0, 1.0 + gap))
    a, b = (lower, upper) if order == 0 else (upper, lower)
    before = pickle.dumps(a), pickle.dumps(b)
    m = umbra.boolean(a, b, "union", triangulate=triangulate, smooth=1e-5)
    assert (pickle.dumps(a), pickle.dumps(b)) == before
    report = m.check()
    assert report["topologically_valid"]
    assert report["two_manifold"]
    assert report["self_intersecting_facet_pairs"] == 0
    assert abs(m.volume() - 2.0) <= 1e-9 + abs(gap)
    if triangulate:
        assert isinstance(m.faces, np.ndarray) and m.faces.shape[1] == 3
    else:
        # The two touching faces cancelled: 10 facets remain.
        assert len(m.faces) == 10


def test_smooth_none_and_zero_keep_the_raw_result():
    a, b = cube(), cube((0.0, 0.0, 1.0))
    raw = umbra.boolean(a, b, "union")
    assert umbra.boolean(a, b, "union", smooth=None) == raw
    assert umbra.boolean(a, b, "union", smooth=0.0) == raw
    assert umbra.boolean(a, b, "union", smooth=1e-6) != raw


@pytest.mark.parametrize("bad", [-1.0, float("nan"), float("inf")])
def test_bad_tolerances_raise(bad):
    with pytest.raises(umbra.UmbraError, match="tolerance"):
        umbra.boolean(cube(), cube((0.5, 0.5, 0.5)), "union", smooth=bad)
    with pytest.raises(umbra.UmbraError, match="tolerance"):
        umbra.smooth(cube(), bad)


def test_smooth_function_merges_a_gap_and_keeps_triangles():
    # Two boxes 1e-8 apart as one mesh: smoothing closes the gap.
    a, b = cube(), cube((1.0 + 1e-8, 0.0, 0.0))
    two = umbra.Mesh(
        np.vstack([a.vertices, b.vertices]),
        [list(f) for f in a.faces] + [[i + len(a.vertices) for i in f] for f in b.faces],
    )
    one = umbra.smooth(two, 1e-6)
    assert one.check()["two_manifold"]
    assert abs(one.volume() - 2.0) < 1e-6
    assert len(one.vertices) == 12
    tri = umbra.boolean(a, cube((0.5, 0.5, 0.5)), "union", triangulate=True)
    smoothed = umbra.smooth(tri)
    assert isinstance(smoothed.faces, np.ndarray) and smoothed.faces.shape[1] == 3
    assert abs(smoothed.volume() - tri.volume()) < 1e-12


@pytest.mark.parametrize(
    "turn, triangulate",
    [({"rotate": [0, 0, 7.5]}, False), ({"rotate": [90, 0, 0], "translate": [5e-8, 0, 0]}, True)],
)
def test_smoothing_that_would_leave_intersections_is_undone_with_a_warning(turn, triangulate):
    # A 24-segment sphere minus its copy turned (and moved by 5e-8):
    # smoothing at 2e-8 would leave more intersecting facet pairs or
    # pinches than the raw result has where it changed it, so it is
    # undone there, with a warning: everywhere (the raw result comes
    # back) or only at the places that are worse (kept elsewhere), never
    # leaving more defects than the raw result by the whole-mesh check.
    copy = {"sphere": {"radius": 10, "segments": 24}}
    copy.update(turn)
    tree = {"op": "difference", "children": [{"sphere": {"radius": 10, "segments": 24}}, copy]}
    raw = umbra.csg(tree, triangulate=triangulate)
    with pytest.warns(UserWarning, match="smoothing undone") as warned:
        out = umbra.csg(tree, triangulate=triangulate, smooth=2e-8)
    message = str(warned[0].message)
    if "kept elsewhere" in message:
        assert out != raw
    else:
        assert out == raw
    report, before = out.check(), raw.check()
    assert report["topologically_valid"]

    def defects(r):
        manifold = r["non_manifold_edges"] + r["open_edges"] + r["non_manifold_vertices"]
        return (r["self_intersecting_facet_pairs"], manifold)

    assert defects(report) <= defects(before)
