"""trimesh interop (skipped without trimesh)."""

import numpy as np
import pytest

import umbra
from conftest import cube

trimesh = pytest.importorskip("trimesh")


def test_trimesh_round_trip_and_volumes():
    box = trimesh.creation.box(extents=(2.0, 3.0, 4.0))
    m = umbra.Mesh.from_trimesh(box)
    assert m.is_valid() and abs(m.volume() - 24.0) < 1e-12
    np.testing.assert_array_equal(m.vertices, box.vertices)
    np.testing.assert_array_equal(m.faces, box.faces)
    sphere = trimesh.creation.icosphere(subdivisions=3, radius=1.0)
    s = umbra.Mesh.from_trimesh(sphere)
    d = umbra.boolean(m, s, "difference")
    t = d.to_trimesh()
    assert isinstance(t, trimesh.Trimesh) and t.is_watertight
    assert abs(t.volume - d.volume()) < 1e-9
    assert abs(d.volume() - (24.0 - sphere.volume)) < 1e-9
    np.testing.assert_array_equal(t.vertices, d.vertices)


def test_quads_go_to_trimesh_as_triangles(tmp_path):
    t = cube().to_trimesh()
    assert t.faces.shape == (12, 3) and abs(t.volume - 1.0) < 1e-15
    # write() takes a Trimesh too.
    path = tmp_path / "box.ply"
    umbra.write(trimesh.creation.box(), path)
    assert abs(umbra.read(path).volume() - 1.0) < 1e-15


def test_scenes_and_point_clouds_are_refused_by_name():
    box = trimesh.creation.box(extents=(2.0, 3.0, 4.0))
    scene = trimesh.Scene([box])
    with pytest.raises(umbra.UmbraError, match=r"got a Scene; .*scene\.to_mesh\(\)"):
        umbra.Mesh.from_trimesh(scene)
    with pytest.raises(umbra.UmbraError, match="got a PointCloud"):
        umbra.Mesh.from_trimesh(trimesh.PointCloud(box.vertices))
    # The hint works: the scene's mesh through its transforms.
    assert abs(umbra.Mesh.from_trimesh(scene.to_mesh()).volume() - 24.0) < 1e-12
