"""2D Booleans and simplification, on shapely geometries and on the plain
form (lists of rings), against analytic areas."""

import math

import numpy as np
import pytest

import umbra

SQUARE = [[np.array([[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]])]]
SHIFTED = [[np.array([[1.0, 1.0], [3.0, 1.0], [3.0, 3.0], [1.0, 3.0]])]]


def area(polygons):
    """The area of the plain form (shoelace, holes negative by role)."""
    total = 0.0
    for poly in polygons:
        for ring in poly:
            x, y = ring[:, 0], ring[:, 1]
            total += 0.5 * float(np.sum(x * np.roll(y, -1) - np.roll(x, -1) * y))
    return total


@pytest.mark.parametrize("via", ["basic", "simplify"])
@pytest.mark.parametrize(
    "op, expected", [("union", 7.0), ("intersection", 1.0), ("difference", 3.0), ("xor", 6.0)]
)
def test_plain_form_analytic(op, expected, via):
    out = umbra.boolean_2d(SQUARE, SHIFTED, op, via=via)
    assert isinstance(out, list)
    assert all(r.dtype == np.float64 and r.shape[1] == 2 for p in out for r in p)
    assert area(out) == expected


def test_plain_form_holes_and_orientation():
    # A clockwise exterior with a counter-clockwise hole: read by role.
    outer = np.array([[0.0, 0.0], [0.0, 4.0], [4.0, 4.0], [4.0, 0.0], [0.0, 0.0]])
    hole = np.array([[1.0, 1.0], [3.0, 1.0], [3.0, 3.0], [1.0, 3.0]])
    frame = [[outer, hole]]
    out = umbra.simplify(frame)
    assert area(out) == 12.0 and len(out) == 1 and len(out[0]) == 2
    # Kept as written, the same rings wind -1 around the frame: nothing is
    # positive, and the negative rule selects the frame.
    assert umbra.simplify(frame, keep_orientation=True) == []
    assert area(umbra.simplify(frame, "negative", keep_orientation=True)) == 12.0
    assert umbra.simplify([]) == []


def test_bad_2d_arguments():
    with pytest.raises(umbra.UmbraError, match="unknown operation 'plus'"):
        umbra.boolean_2d(SQUARE, SHIFTED, "plus")
    with pytest.raises(umbra.UmbraError, match="unknown algorithm 'fast'"):
        umbra.boolean_2d(SQUARE, SHIFTED, "union", via="fast")
    with pytest.raises(umbra.UmbraError, match="unknown fill rule 'odd'"):
        umbra.simplify(SQUARE, "odd")
    nan = [[np.array([[0.0, 0.0], [1.0, math.nan], [1.0, 1.0]])]]
    with pytest.raises(umbra.UmbraError, match=r"^b: polygon 1, ring 1, point 2: y"):
        umbra.boolean_2d(SQUARE, nan, "union")
    with pytest.raises(umbra.UmbraError, match=r"a\[0\]\[0\]: expected an \(n, 2\) array"):
        umbra.boolean_2d([[np.zeros((3, 3))]], SQUARE, "union")
    with pytest.raises(umbra.UmbraError, match="a: expected a list of polygons"):
        umbra.boolean_2d(7, SQUARE, "union")


@pytest.mark.parametrize("via", ["basic", "simplify"])
def test_invalid_operands_are_taken_as_sets(via):
    # A square given twice (overlapping parts) and a polygon with a hole
    # outside its shell: as sets (make_valid's areas) in both algorithms.
    # The basic Boolean on the rings as read gave an empty union of the
    # doubled square with itself, and filled the stray hole in the
    # intersection.
    sq = np.array([[0.0, 0.0], [10.0, 0.0], [10.0, 10.0], [0.0, 10.0]])
    stray = np.array([[20.0, 20.0], [20.0, 21.0], [21.0, 21.0], [21.0, 20.0]])
    twice = [[sq], [sq.copy()]]
    holed = [[sq, stray]]
    for shape in (twice, holed):
        for op in ("union", "intersection"):
            out = umbra.boolean_2d(shape, shape, op, via=via)
            if not isinstance(out, list):  # shapely installed
                out = out.area
            else:
                out = area(out)
            assert abs(out - 100.0) < 1e-9, (op, via, out)
