"""Round trips through every file format of the command-line tool, and the
tool's messages for files that cannot be read or written."""

import os

import numpy as np
import pytest

import umbra
from conftest import cube

MESH_EXACT = ["obj", "off", "ply"]  # every f64 bit and every polygon kept


@pytest.mark.parametrize("ext", MESH_EXACT)
@pytest.mark.parametrize("ascii", [False, True])
def test_polygon_formats_keep_the_mesh_exactly(tmp_path, ext, ascii):
    c = cube((0.1, -0.3, 1e-7), 0.3)  # coordinates with long binary expansions
    path = tmp_path / f"cube.{ext}"
    umbra.write(c, path, ascii=ascii)
    assert umbra.read(path) == c
    assert umbra.read(str(path)) == c


@pytest.mark.parametrize("name", ["out.stl", "out.STL"])
@pytest.mark.parametrize("ascii", [False, True])
def test_stl_welds_triangles(tmp_path, name, ascii):
    # Coordinates exact in float32, so binary STL keeps them.
    b = umbra.boolean(cube(), cube((0.5, 0.25, 0.5)), "union")
    path = tmp_path / name
    umbra.write(b, path, ascii=ascii)
    back = umbra.read(path)
    assert back.is_valid() and back.volume() == b.volume()
    assert back.faces.shape == b.triangles.shape
    assert len(back.vertices) == len(b.vertices)


@pytest.mark.parametrize("ext", MESH_EXACT + ["stl"])
def test_boolean_results_round_trip(tmp_path, ext):
    d = umbra.boolean(cube(), cube((0.5, 0.5, 0.5)), "difference")
    path = tmp_path / f"d.{ext}"
    umbra.write(d, path, ascii=True)
    back = umbra.read(path)
    assert back.is_valid() and back.volume() == d.volume()
    assert back.check()["two_manifold"]


@pytest.mark.parametrize("ext", MESH_EXACT + ["stl", "glb", "gltf"])
@pytest.mark.parametrize("ascii", [False, True])
def test_an_empty_result_round_trips(tmp_path, ext, ascii):
    # Disjoint cubes intersect in the empty solid, which every readable
    # format writes and reads back as the empty mesh.
    e = umbra.boolean(cube(), cube((5.0, 5.0, 5.0)), "intersection")
    assert len(e.vertices) == 0 and e.volume() == 0.0
    path = tmp_path / f"e.{ext}"
    umbra.write(e, path, ascii=ascii)
    back = umbra.read(path)
    assert back.is_valid() and back.volume() == 0.0 and len(back.faces) == 0


@pytest.mark.parametrize("ext", ["glb", "gltf"])
def test_gltf_round_trips_and_reads_trimesh_scenes(tmp_path, ext):
    # Umbra's own file: the cube's f32 coordinates come back exactly.
    path = tmp_path / f"cube.{ext}"
    umbra.write(cube(), path)
    back = umbra.read(path)
    assert back.is_valid() and back.volume() == cube().volume()
    # trimesh's exporter: a scene of two translated boxes and a mirrored
    # icosphere (determinant -1), vertices split per triangle.
    trimesh = pytest.importorskip("trimesh")
    import numpy as np

    scene = trimesh.Scene()
    box = trimesh.creation.box(extents=(1.0, 2.0, 3.0))
    sphere = trimesh.creation.icosphere(subdivisions=2, radius=0.75)
    sphere.unmerge_vertices()
    scene.add_geometry(box, node_name="a", transform=trimesh.transformations.translation_matrix([4.0, 0, 0]))
    scene.add_geometry(box, node_name="b", transform=trimesh.transformations.translation_matrix([-4.0, 0, 0]))
    mirror = trimesh.transformations.rotation_matrix(0.3, [1, 1, 0]) @ np.diag([1.0, -1.0, 1.0, 1.0])
    scene.add_geometry(sphere, node_name="s", transform=mirror)
    # .gltf: trimesh writes its buffers as files beside the document.
    path = tmp_path / f"scene.{ext}"
    if ext == "glb":
        scene.export(path)
    else:
        for name, data in scene.export(file_type="gltf").items():
            (tmp_path / (f"scene.{ext}" if name.endswith(".gltf") else name)).write_bytes(data)
    m = umbra.read(path)
    want = scene.to_geometry()
    assert m.is_valid() and len(m.faces) == len(want.faces)
    assert abs(m.volume() - want.volume) < 1e-5 * want.volume
    assert m.volume() > 2 * 6.0


def test_3mf_round_trips_and_reads_trimesh_scenes(tmp_path):
    path = tmp_path / "cube.3mf"
    umbra.write(cube(), path)
    back = umbra.read(path)
    assert back.is_valid() and back.volume() == cube().volume()
    # trimesh's exporter (its 3MF writer needs networkx and lxml): two
    # translated boxes and a mirrored icosphere.
    trimesh = pytest.importorskip("trimesh")
    pytest.importorskip("networkx")
    pytest.importorskip("lxml")
    import numpy as np

    scene = trimesh.Scene()
    box = trimesh.creation.box(extents=(1.0, 2.0, 3.0))
    sphere = trimesh.creation.icosphere(subdivisions=2, radius=0.75)
    scene.add_geometry(box, node_name="a", transform=trimesh.transformations.translation_matrix([4.0, 0, 0]))
    scene.add_geometry(box, node_name="b", transform=trimesh.transformations.translation_matrix([-4.0, 0, 0]))
    mirror = trimesh.transformations.rotation_matrix(0.3, [1, 1, 0]) @ np.diag([1.0, -1.0, 1.0, 1.0])
    scene.add_geometry(sphere, node_name="s", transform=mirror)
    path = tmp_path / "scene.3mf"
    scene.export(path)
    m = umbra.read(path)
    want = scene.to_geometry()
    assert m.is_valid() and len(m.faces) == len(want.faces)
    assert abs(m.volume() - want.volume) < 1e-9 * want.volume


def test_open_and_nan_mesh_files(tmp_path):
    path = tmp_path / "open.obj"
    c = cube()
    umbra.write(umbra.Mesh(c.vertices, c.faces[:5]), path)
    with pytest.raises(umbra.UmbraError, match=r"open\.obj: invalid shape"):
        umbra.read(path)
    m = umbra.read(path, check=False)
    assert not m.is_valid() and not m.check()["topologically_valid"]
    nan = tmp_path / "nan.off"
    nan.write_text("OFF\n3 1 0\n0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n")
    with pytest.raises(umbra.UmbraError, match=r"nan\.off"):
        umbra.read(nan)
    r = umbra.read(nan, check=False).check()
    assert not r["coordinates_valid"]


def test_file_errors(tmp_path):
    with pytest.raises(umbra.UmbraError, match=r"unknown extension '\.txt'"):
        umbra.read(tmp_path / "a.txt")
    with pytest.raises(umbra.UmbraError, match="cannot read the file"):
        umbra.read(tmp_path / "missing.obj")
    with pytest.raises(umbra.UmbraError, match=r"cube\.wkt: unsupported file type: expected a 3D"):
        umbra.write(cube(), tmp_path / "cube.wkt")
    square = [[np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0]])]]
    with pytest.raises(umbra.UmbraError, match=r"square\.obj: unsupported file type: expected a 2D"):
        umbra.write(square, tmp_path / "square.obj")
    bad = tmp_path / "bad.wkt"
    bad.write_text("POLYGON ((0 0, 1 0,")
    with pytest.raises(umbra.UmbraError, match=r"bad\.wkt: malformed WKT"):
        umbra.read(bad)
    with pytest.raises(umbra.UmbraError, match=r"cannot write the file"):
        umbra.write(cube(), tmp_path / "no" / "dir" / "cube.obj")


@pytest.mark.parametrize("ext", ["wkt", "geojson"])
def test_polygons_round_trip_plain(tmp_path, ext, monkeypatch):
    # Without shapely: the plain form in and out.
    monkeypatch.setattr(umbra, "_shapely", lambda: None)
    frame = [
        [
            np.array([[0.0, 0.0], [4.0, 0.0], [4.0, 4.0], [0.0, 4.0]]),
            np.array([[1.0, 1.0], [1.0, 3.0], [3.0, 3.0], [3.0, 1.0]]),
        ],
        [np.array([[10.0, 0.1], [11.0, 0.1], [10.5, 0.7]])],
    ]
    path = tmp_path / f"frame.{ext}"
    umbra.write(frame, path)
    back = umbra.read(path)
    assert isinstance(back, list) and len(back) == 2
    assert sorted(len(p) for p in back) == [1, 2]
    assert sorted(map(len, (r for p in back for r in p))) == [3, 4, 4]
    # Written again, the bytes are the same.
    again = tmp_path / f"again.{ext}"
    umbra.write(back, again)
    assert again.read_bytes() == path.read_bytes()


def test_svg_is_written(tmp_path):
    path = tmp_path / "square.svg"
    umbra.write([[np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0]])]], path)
    assert "<svg" in path.read_text()
    with pytest.raises(umbra.UmbraError, match="can be written but not read"):
        umbra.read(path)


@pytest.mark.parametrize("ext", ["wkt", "geojson"])
def test_polygons_round_trip_shapely(tmp_path, ext):
    shapely = pytest.importorskip("shapely")
    g = shapely.MultiPolygon(
        [
            shapely.box(0, 0, 4, 4).difference(shapely.box(1, 1, 3, 3)),
            shapely.Polygon([(10, 0.1), (11, 0.1), (10.5, 0.7)]),
        ]
    )
    path = tmp_path / f"g.{ext}"
    umbra.write(g, path)
    back = umbra.read(path)
    assert isinstance(back, shapely.MultiPolygon)
    assert back.normalize().equals_exact(g.normalize(), 0.0)


def test_holes_in_no_exterior_are_written_with_a_warning(tmp_path, monkeypatch):
    # A "hole" outside its polygon's exterior is an inside-out region of
    # the set: ring formats have no place for it, so it is written as an
    # exterior of its own (which readers fill) and the caller is told.
    monkeypatch.setattr(umbra, "_shapely", lambda: None)
    square = np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]])
    stray = np.array([[5.0, 5.0], [5.0, 6.0], [6.0, 6.0], [6.0, 5.0]])
    path = tmp_path / "stray.wkt"
    with pytest.warns(UserWarning, match=r"1 hole\(s\) lie in no exterior"):
        umbra.write([[square, stray]], path)
    back = umbra.read(path)
    assert sorted(len(p) for p in back) == [1, 1]
    # Kept as written, every ring is its own polygon as it runs: no warning.
    import warnings

    with warnings.catch_warnings():
        warnings.simplefilter("error")
        umbra.write([[square, stray]], tmp_path / "kept.wkt", keep_orientation=True)
        umbra.write([[square]], tmp_path / "plain.wkt")


def test_paths_may_be_bytes(tmp_path):
    path = os.fsencode(tmp_path / "cube.obj")
    umbra.write(cube(), path)
    assert umbra.read(path) == cube()


@pytest.mark.parametrize("ext", ["wkt", "geojson"])
def test_points_and_lines_beside_polygons_are_skipped_with_a_warning(tmp_path, ext, monkeypatch):
    # What GEOS and shapely overlays return: a collection of a polygon, a
    # line and a point. The polygon is read; the other two are skipped,
    # with the command line's warning.
    monkeypatch.setattr(umbra, "_shapely", lambda: None)
    path = tmp_path / f"mixed.{ext}"
    if ext == "wkt":
        path.write_text(
            "GEOMETRYCOLLECTION (POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0)), "
            "LINESTRING (0 0, 9 9), POINT (5 5))"
        )
    else:
        path.write_text(
            '{"type": "GeometryCollection", "geometries": ['
            '{"type": "Polygon", "coordinates": [[[0, 0], [4, 0], [4, 4], [0, 4], [0, 0]]]},'
            '{"type": "LineString", "coordinates": [[0, 0], [9, 9]]},'
            '{"type": "Point", "coordinates": [5, 5]}]}'
        )
    with pytest.warns(UserWarning, match="2 non-areal part"):
        back = umbra.read(path)
    assert len(back) == 1 and len(back[0]) == 1
    ring = np.asarray(back[0][0])
    x, y = ring[:, 0], ring[:, 1]
    assert abs(0.5 * abs(np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1))) - 16.0) < 1e-12
