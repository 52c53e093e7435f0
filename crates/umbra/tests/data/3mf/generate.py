"""Writes the 3MF fixtures of this directory with software Umbra does not
share code with: lib3mf (the 3MF Consortium's reference library) and
trimesh. Run in a virtual environment with `lib3mf` and `trimesh`
installed; prints the expected figures recorded in README.md."""

import sys

import lib3mf
import numpy as np
import trimesh


def box_geometry():
    """A 2 x 1 x 1 box [0,2]x[0,1]x[0,1], outward triangles."""
    v = [(x, y, z) for z in (0, 1) for y in (0, 1) for x in (0, 2)]
    quads = [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4),
             (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)]
    t = []
    for a, b, c, d in quads:
        t += [(a, b, c), (a, c, d)]
    return v, t


def transform(rows):
    """A lib3mf transform from 4 rows of 3 (row-vector convention)."""
    tr = lib3mf.Transform()
    for i in range(4):
        for j in range(3):
            tr.Fields[i][j] = rows[i][j]
    return tr


def write_lib3mf(path):
    wrapper = lib3mf.get_wrapper()
    model = wrapper.CreateModel()
    box = model.AddMeshObject()
    box.SetName("box")
    v, t = box_geometry()
    positions = []
    for p in v:
        q = lib3mf.Position()
        q.Coordinates[0], q.Coordinates[1], q.Coordinates[2] = p
        positions.append(q)
    triangles = []
    for tri in t:
        q = lib3mf.Triangle()
        q.Indices[0], q.Indices[1], q.Indices[2] = tri
        triangles.append(q)
    box.SetGeometry(positions, triangles)
    pair = model.AddComponentsObject()
    # Translated by (5, 0, 0).
    pair.AddComponent(box, transform([(1, 0, 0), (0, 1, 0), (0, 0, 1), (5, 0, 0)]))
    # Mirrored in x, then moved by (-1, 0, 0): x in [-3, -1].
    pair.AddComponent(box, transform([(-1, 0, 0), (0, 1, 0), (0, 0, 1), (-1, 0, 0)]))
    model.AddBuildItem(pair, transform([(1, 0, 0), (0, 1, 0), (0, 0, 1), (0, 0, 10)]))
    # Rotated 90 degrees about z (x' = -y, y' = x), moved by (0, 20, 0).
    model.AddBuildItem(box, transform([(0, 1, 0), (-1, 0, 0), (0, 0, 1), (0, 20, 0)]))
    model.QueryWriter("3mf").WriteToFile(path)
    print(path, "written by lib3mf", ".".join(map(str, wrapper.GetLibraryVersion())))


def report(path):
    """The figures of a file as trimesh reads it back."""
    scene = trimesh.load(path, force="scene")
    mesh = scene.to_mesh() if hasattr(scene, "to_mesh") else scene.dump(concatenate=True)
    print(path, "triangles", len(mesh.faces), "volume", repr(float(mesh.volume)),
          "bounds", mesh.bounds.tolist())


def main():
    write_lib3mf("lib3mf_components.3mf")
    sphere = trimesh.creation.icosphere(subdivisions=2, radius=1.5)
    print("icosphere volume", repr(float(sphere.volume)), "bounds", sphere.bounds.tolist())
    sphere.export("trimesh_icosphere.3mf")
    scene = trimesh.Scene()
    box = trimesh.creation.box(extents=[1, 2, 3])
    scene.add_geometry(box, transform=trimesh.transformations.translation_matrix([10, 0, 0]))
    cyl = trimesh.creation.cylinder(radius=1, height=2, sections=12)
    turn = trimesh.transformations.rotation_matrix(np.pi / 2, [1, 0, 0])
    scene.add_geometry(cyl, transform=trimesh.transformations.translation_matrix([0, 5, 0]) @ turn)
    scene.export("trimesh_scene.3mf")
    print("trimesh", trimesh.__version__, file=sys.stderr)
    for path in ["lib3mf_components.3mf", "trimesh_icosphere.3mf", "trimesh_scene.3mf"]:
        report(path)


main()
