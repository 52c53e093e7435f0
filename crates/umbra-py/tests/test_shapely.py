"""2D Booleans and simplification on shapely geometries, in and out,
against shapely's own results and analytic areas (skipped without
shapely)."""

import math

import numpy as np
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


def test_shapely_results_keep_their_holes_when_orientation_is_kept():
    # shapely has no ring direction: a hole returned as a polygon of its
    # own was filled (area 116 for this donut, and invalid).
    # Exterior counter-clockwise, hole clockwise (as written, so that the
    # winding numbers are those of the set).
    donut = shapely.geometry.polygon.orient(
        shapely.box(0, 0, 10, 10).difference(shapely.box(2, 2, 6, 6)), 1.0
    )
    for rule in ("positive", "nonzero"):
        s = umbra.simplify(donut, rule, keep_orientation=True)
        assert s.is_valid and s.area == 84.0, (rule, s.wkt)
    u = umbra.boolean_2d(donut, shapely.box(20, 0, 21, 1), "union", keep_orientation=True)
    assert u.is_valid and u.area == 85.0, u.wkt
    # The plain form keeps every loop as it runs.
    plain = umbra.simplify(
        [[np.asarray(donut.exterior.coords), np.asarray(donut.interiors[0].coords)]],
        keep_orientation=True,
    )
    assert len(plain) == 2


def test_shapely_bad_geometries():
    with pytest.raises(umbra.UmbraError, match="unsupported geometry: Point"):
        umbra.simplify(shapely.Point(0, 0))
    with pytest.raises(umbra.UmbraError, match="Z coordinates"):
        umbra.simplify(shapely.Polygon([(0, 0, 1), (1, 0, 1), (1, 1, 1)]))
    with pytest.raises(umbra.UmbraError, match=r"^a: polygon 1, ring 1, point 2: x"):
        umbra.boolean_2d(shapely.Polygon([(0, 0), (math.inf, 0), (1, 1)]), shapely.box(0, 0, 1, 1), "union")


def shapely_results(a, b):
    """Each operation's name and shapely's own result for it."""
    return (
        ("union", a.union(b)),
        ("intersection", a.intersection(b)),
        ("difference", a.difference(b)),
        ("xor", a.symmetric_difference(b)),
    )


def test_results_are_valid_for_geos_where_rings_touch():
    # A hole touching its outer ring at a corner, valid in shapely: the
    # result is one outer ring and one hole, not one ring through (0, 0)
    # twice (which GEOS calls a ring self-intersection).
    a = shapely.Polygon(
        [(0, 0), (10, 0), (10, 10), (0, 10)], [[(0, 0), (5, 2), (2, 5)]]
    )
    assert a.is_valid
    for out in (
        umbra.simplify(a),
        umbra.boolean_2d(a, shapely.box(0, 0, 10, 10), "intersection"),
        umbra.boolean_2d(a, shapely.box(0, 0, 10, 10), "intersection", via="simplify"),
    ):
        assert out.is_valid, shapely.is_valid_reason(out)
        assert isinstance(out, shapely.Polygon) and len(out.interiors) == 1
        assert out.area == a.area


def test_shared_boundaries_give_valid_results_by_default():
    # Operands with collinear, differently subdivided edges along x = 7
    # (found by a random search): the basic Boolean's raw xor keeps an
    # edge running back over two others there, so GEOS calls it invalid
    # and make_valid grows its area by 14%; smoothed at the default
    # tolerance it is valid, with shapely's area.
    a = shapely.from_wkt(
        "MULTIPOLYGON (((3.75 2.25, 3 2, 0 3, 3.75 2.25)), ((7 1, 5 2, 3.75 2.25, "
        "6 3, 5 3, 5.588235294117648 5.352941176470588, "
        "5.421052631578947 5.631578947368422, 2 7, 4.84375 6.59375, 4 8, 7 9, "
        "7 6.666666666666667, 9 6, 7 6.285714285714286, 7 5, 9 2, 7 1)))"
    )
    b = shapely.from_wkt(
        "MULTIPOLYGON (((4.108129228452552 -0.8560933097432738, "
        "3.7564035372693443 -2.462358276728184, "
        "3.689519287022729 -1.2665638144884535, "
        "4.108129228452552 -0.8560933097432738)), "
        "((1.2222222222222223 4.185185185185185, "
        "2.263157894736842 5.052631578947369, 2.333333333333333 5.333333333333333, "
        "1.2 4.2, 0 5, 1 7, 2.8666666666666667 7.466666666666667, 3 8, "
        "2.935483870967742 7.483870967741935, 5 8, "
        "4.2727272727272725 6.7272727272727275, 7 9, 7 8, 7 7, 9 6, 7 5, "
        "6.3076923076923075 4.538461538461538, 6 3, "
        "4.823716329416474 2.411858164708237, 4.773851768973037 2.184136111579416, "
        "6.305021926271529 1.298083085266991, 6.0010279938882505 1, 7 1, "
        "5.796460468311093 0.7994100780518488, "
        "4.108129228452552 -0.8560933097432738, "
        "4.4204177708118095 0.5700696284686348, "
        "3.5944904730803153 0.4324150788467192, "
        "3.689519287022729 -1.2665638144884535, "
        "1.8869653758479472 -3.034068932076178, "
        "-4.003996413740553 -3.103030771376465, "
        "-2.1649416186618833 2.3734241744549385, "
        "0.746596194347352 1.5757983793626686, 0.7771996397733553 1.584045085521631, "
        "1.533332529313466 2.1333301172538643, "
        "1.9285714285714286 3.7142857142857144, "
        "1.2222222222222223 4.185185185185185), "
        "(3.3076923076923075 5.923076923076923, 3.75 5.8125, "
        "4.2727272727272725 6.7272727272727275, "
        "3.3076923076923075 5.923076923076923), (3 6, "
        "2.7142857142857144 5.714285714285714, 2.674418604651163 5.395348837209303, "
        "3.3076923076923075 5.923076923076923, 3 6), (2.44 3.52, "
        "2.423076923076923 3.3846153846153846, 2.857314743861321 3.0951235040924527, "
        "3.009077855478106 3.205370269883727, 3.1952608678573613 3.0976304339286806, "
        "4.2727272727272725 3.6363636363636362, 5.378378378378378 5.405405405405405, "
        "3.75 5.8125, 2.44 3.52), (6.428571428571429 5.142857142857143, "
        "6.333333333333334 4.666666666666667, 7 5, "
        "6.428571428571429 5.142857142857143), "
        "(4.585853170764443 2.2929265853822214, "
        "3.520228412587045 1.7601142062935224, 3.5627438033127388 1, "
        "4.5145601197988325 1, 4.773851768973037 2.184136111579416, "
        "4.585853170764443 2.2929265853822214), "
        "(-0.8779115246628202 0.3817064476260609, "
        "1.0860442492814686 0.3441769971258742, 1.3 1.2, 1 1, "
        "1.4350354309548725 1.761312004171027, 0.7771996397733553 1.584045085521631, "
        "-0.8779115246628202 0.3817064476260609), "
        "(3.704456185841943 2.8029707905612957, "
        "3.7392667114728986 2.782826738356638, 3.7857142857142856 2.857142857142857, "
        "3.704456185841943 2.8029707905612957), "
        "(2.1333333333333333 1.0666666666666667, "
        "2.909090909090909 1.4545454545454546, "
        "3.4381883358095937 2.3011013372953504, "
        "2.621571616036583 2.0810477440243886, 2.227272727272727 1.8181818181818181, "
        "2.1333333333333333 1.0666666666666667), (2 1, 2.125 1, "
        "2.1333333333333333 1.0666666666666667, 2 1), "
        "(2.082185690525204 0.6574855242016329, 2.4489733624245367 1, 2.125 1, "
        "2.082185690525204 0.6574855242016329), "
        "(2.871747321554525 1.3947957144872396, "
        "2.966435756068423 1.4832178780342116, 2.909090909090909 1.4545454545454546, "
        "2.871747321554525 1.3947957144872396)), ((1 4, 1.2 4.2, "
        "1.2222222222222223 4.185185185185185, 1 4)))"
    )
    assert a.is_valid and b.is_valid
    for op, want in shapely_results(a, b):
        raw = umbra.boolean_2d(a, b, op, smooth=0)
        assert abs(raw.area - want.area) <= 1e-12 * want.area
        for via in ("basic", "simplify"):
            out = umbra.boolean_2d(a, b, op, via=via)
            assert out.is_valid, (op, via, shapely.is_valid_reason(out))
            assert abs(out.area - want.area) <= 1e-12 * want.area, (op, via)
            assert out.symmetric_difference(want).area <= 1e-9 * want.area, (op, via)


def test_the_command_line_writes_valid_rings(cli, tmp_path):
    # The same operands through `umbra boolean` (WKT and GeoJSON out,
    # smoothed by default): every file shapely reads is valid, with
    # shapely's area; `--smooth 0` writes the raw output.
    import json
    import subprocess

    a = shapely.Polygon(
        [(0, 0), (10, 0), (10, 10), (0, 10)], [[(0, 0), (5, 2), (2, 5)]]
    )
    b = shapely.box(1, -1, 11, 3)
    (tmp_path / "a.wkt").write_text(a.wkt)
    (tmp_path / "b.wkt").write_text(b.wkt)
    for op, want in shapely_results(a, b):
        for via in ("basic", "simplify"):
            for ext in ("wkt", "geojson"):
                out = tmp_path / f"o.{ext}"
                r = subprocess.run(
                    [cli, "boolean", op, str(tmp_path / "a.wkt"), str(tmp_path / "b.wkt"),
                     "-o", str(out), "--via", via],
                    capture_output=True, text=True, timeout=120,
                )
                assert r.returncode == 0, r.stderr
                if ext == "wkt":
                    g = shapely.from_wkt(out.read_text())
                else:
                    doc = json.loads(out.read_text())
                    g = shapely.geometry.shape(doc.get("geometry", doc))
                assert g.is_valid, (op, via, ext, shapely.is_valid_reason(g))
                assert abs(g.area - want.area) <= 1e-12 * want.area, (op, via, ext)


def test_random_valid_operands_give_valid_results():
    # Unions of random triangles and polygons on a small integer grid
    # (shared vertices, collinear edges and touching rings everywhere),
    # made valid by shapely: every Boolean, by either algorithm, is valid
    # for GEOS and matches shapely's own result.
    import random

    rng = random.Random(20261125)

    def operand():
        parts = []
        for _ in range(rng.randint(1, 3)):
            pts = [(rng.randint(0, 9), rng.randint(0, 9)) for _ in range(rng.randint(3, 9))]
            parts.append(shapely.make_valid(shapely.Polygon(pts)))
        g = shapely.union_all(parts)
        return shapely.union_all(
            [p for p in shapely.get_parts(g) if p.geom_type in ("Polygon", "MultiPolygon")]
        )

    checked = 0
    for _ in range(40):
        a, b = operand(), operand()
        if a.is_empty or b.is_empty:
            continue
        for op, want in shapely_results(a, b):
            for via in ("basic", "simplify"):
                out = umbra.boolean_2d(a, b, op, via=via)
                assert out.is_valid, (a.wkt, b.wkt, op, via, shapely.is_valid_reason(out))
                scale = a.area + b.area
                assert abs(out.area - want.area) <= 1e-9 * scale, (a.wkt, b.wkt, op, via)
                assert out.symmetric_difference(want).area <= 1e-9 * scale, (a.wkt, b.wkt, op)
                checked += 1
    assert checked > 200


def test_boolean_2d_all_matches_shapely_over_many_operands():
    # Three to six random valid operands on a small integer grid (shared
    # vertices, collinear edges, touching rings), every operation in one
    # sweep against GEOS folding the binary operations: union_all,
    # intersection_all, the first minus the union of the others, and the
    # symmetric difference folded left (what an odd number cover).
    import functools
    import random

    rng = random.Random(20261129)

    def operand():
        pts = [(rng.randint(0, 9), rng.randint(0, 9)) for _ in range(rng.randint(3, 8))]
        g = shapely.make_valid(shapely.Polygon(pts))
        return shapely.union_all(
            [p for p in shapely.get_parts(g) if p.geom_type in ("Polygon", "MultiPolygon")]
        )

    checked = 0
    for _ in range(25):
        geoms = [g for g in (operand() for _ in range(rng.randint(3, 6))) if not g.is_empty]
        if len(geoms) < 3:
            continue
        wants = {
            "union": shapely.union_all(geoms),
            "intersection": shapely.intersection_all(geoms),
            "difference": geoms[0].difference(shapely.union_all(geoms[1:])),
            "xor": functools.reduce(lambda x, y: x.symmetric_difference(y), geoms),
        }
        scale = sum(g.area for g in geoms)
        for op, want in wants.items():
            out = umbra.boolean_2d_all(geoms, op)
            assert out.is_valid, ([g.wkt for g in geoms], op, shapely.is_valid_reason(out))
            assert abs(out.area - want.area) <= 1e-9 * scale, ([g.wkt for g in geoms], op)
            assert out.symmetric_difference(want).area <= 1e-9 * scale, op
            checked += 1
        # Two operands select what the binary Boolean through simplification does.
        for op in wants:
            two = umbra.boolean_2d_all(geoms[:2], op)
            assert two.symmetric_difference(
                umbra.boolean_2d(geoms[0], geoms[1], op, via="simplify")
            ).area <= 1e-12 * scale, op
    assert checked > 60
    # An iterator, the plain form in and out, and no operands at all.
    square = [[np.array([[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]])]]
    shifted = [[r + 1.0 for r in square[0]]]
    plain = umbra.boolean_2d_all(iter([square, shifted, square]), "xor")
    assert isinstance(plain, list)
    assert math.isclose(sum(abs(_ring_area(r[0])) for r in plain), 4.0)  # the shifted square
    assert umbra.boolean_2d_all([], "union") == []
    with pytest.raises(umbra.UmbraError, match=r"unknown operation"):
        umbra.boolean_2d_all([square, square], "unoin")
    with pytest.raises(umbra.UmbraError, match=r"geoms\[1\]"):
        umbra.boolean_2d_all([square, [[np.array([[0.0, 0.0], [np.nan, 1.0], [1.0, 1.0]])]]])


def _ring_area(r):
    x, y = np.asarray(r)[:, 0], np.asarray(r)[:, 1]
    return 0.5 * float(np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1)))
