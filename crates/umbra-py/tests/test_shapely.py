"""2D Booleans and simplification on shapely geometries, in and out,
against shapely's own results and analytic areas (skipped without
shapely)."""

import math

import pytest

import umbra

shapely = pytest.importorskip("shapely")


def test_shapely_in_and_out():
    a = shapely.box(0, 0, 4, 4).difference(shapely.box(1, 1, 3, 3))  # with a hole
    b = shapely.box(2, -1, 5, 5)
    u = umbra.boolean_2d(a, b, "union")
    assert isinstance(u, shapely.Polygon) and u.area == 12.0 + 18.0 - 6.0
    assert u.is_valid and u.equals(a.union(b))
    i = umbra.boolean_2d(a, b, "intersection", via="simplify")
    assert i.equals(a.intersection(b))
    x = umbra.boolean_2d(a, b, "xor")
    assert isinstance(x, shapely.MultiPolygon) and x.equals(a.symmetric_difference(b))
    empty = umbra.boolean_2d(shapely.box(0, 0, 1, 1), shapely.box(5, 5, 6, 6), "intersection")
    assert isinstance(empty, shapely.Polygon) and empty.is_empty
    multi = shapely.MultiPolygon([shapely.box(0, 0, 1, 1), shapely.box(2, 0, 3, 1)])
    coll = shapely.GeometryCollection([multi, shapely.box(0, 2, 1, 3)])
    assert umbra.boolean_2d(coll, shapely.box(0, 0, 3, 3), "intersection").area == 3.0


def test_shapely_simplify_figure_eight():
    bowtie = shapely.Polygon([(0, 0), (2, 2), (2, 0), (0, 2)])
    assert not bowtie.is_valid
    s = umbra.simplify(bowtie)
    assert s.is_valid and isinstance(s, shapely.Polygon) and s.area == 1.0
    both = umbra.simplify(bowtie, "nonzero", keep_orientation=True)
    assert both.area == 2.0 and len(both.geoms) == 2


def test_shapely_bad_geometries():
    with pytest.raises(umbra.UmbraError, match="unsupported geometry: Point"):
        umbra.simplify(shapely.Point(0, 0))
    with pytest.raises(umbra.UmbraError, match="Z coordinates"):
        umbra.simplify(shapely.Polygon([(0, 0, 1), (1, 0, 1), (1, 1, 1)]))
    with pytest.raises(umbra.UmbraError, match=r"^a: polygon 1, ring 1, point 2: x"):
        umbra.boolean_2d(shapely.Polygon([(0, 0), (math.inf, 0), (1, 1)]), shapely.box(0, 0, 1, 1), "union")
