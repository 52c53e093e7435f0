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


def mesh_object(model, v, t, name):
    """A lib3mf mesh object of vertices `v` and triangles `t`."""
    obj = model.AddMeshObject()
    obj.SetName(name)
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
    obj.SetGeometry(positions, triangles)
    return obj


def write_lib3mf_production(path):
    """Objects in other model parts (the production extension's p:path),
    laid out as Bambu Studio and Orca Slicer write them: the root model
    holds a components object, the meshes are in /3D/Objects/*.model."""
    wrapper = lib3mf.get_wrapper()
    model = wrapper.CreateModel()
    v, t = box_geometry()
    box = mesh_object(model, v, t, "box")
    box.SetPackagePart(model.FindOrCreatePackagePart("/3D/Objects/object_1.model"))
    tet = mesh_object(model, [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)],
                      [(0, 2, 1), (0, 1, 3), (1, 2, 3), (0, 3, 2)], "tetrahedron")
    tet.SetPackagePart(model.FindOrCreatePackagePart("/3D/Objects/object_2.model"))
    group = model.AddComponentsObject()
    # Translated by (5, 0, 0).
    group.AddComponent(box, transform([(1, 0, 0), (0, 1, 0), (0, 0, 1), (5, 0, 0)]))
    # Mirrored in x, then moved by (-1, 0, 0): x in [-3, -1].
    group.AddComponent(box, transform([(-1, 0, 0), (0, 1, 0), (0, 0, 1), (-1, 0, 0)]))
    # Scaled by 6 in z (volume 1), moved by (0, 5, 0).
    group.AddComponent(tet, transform([(1, 0, 0), (0, 1, 0), (0, 0, 6), (0, 5, 0)]))
    model.AddBuildItem(group, transform([(1, 0, 0), (0, 1, 0), (0, 0, 1), (0, 0, 10)]))
    # A build item of the tetrahedron itself (an <item> with a p:path),
    # moved by (20, 0, 0).
    model.AddBuildItem(tet, transform([(1, 0, 0), (0, 1, 0), (0, 0, 1), (20, 0, 0)]))
    model.QueryWriter("3mf").WriteToFile(path)
    print(path, "written by lib3mf", ".".join(map(str, wrapper.GetLibraryVersion())))


def matrix(tr):
    """A lib3mf transform as a 4 x 3 array (row-vector convention)."""
    return np.array([[tr.Fields[i][j] for j in range(3)] for i in range(4)])


def measure_lib3mf(path):
    """The figures of a file as lib3mf reads it back (it resolves the
    production paths itself): every build item expanded through its
    components, transforms composed; the volume by the divergence
    theorem, an instance whose transform has a negative determinant
    counted with its orientation reversed (core section 3.3)."""
    wrapper = lib3mf.get_wrapper()
    model = wrapper.CreateModel()
    model.QueryReader("3mf").ReadFromFile(path)
    found = {"triangles": 0, "volume": 0.0, "points": []}

    def walk(obj, m):
        if obj.IsMeshObject():
            mesh = model.GetMeshObjectByID(obj.GetUniqueResourceID())
            v = np.array([p.Coordinates[:] for p in mesh.GetVertices()])
            t = np.array([q.Indices[:] for q in mesh.GetTriangleIndices()])
            w = v @ m[:3] + m[3]
            six = np.einsum("ij,ij->i", w[t[:, 0]], np.cross(w[t[:, 1]], w[t[:, 2]]))
            sign = -1.0 if np.linalg.det(m[:3]) < 0 else 1.0
            found["triangles"] += len(t)
            found["volume"] += sign * float(six.sum()) / 6.0
            found["points"].append(w)
        else:
            group = model.GetComponentsObjectByID(obj.GetUniqueResourceID())
            for k in range(group.GetComponentCount()):
                c = group.GetComponent(k)
                inner = matrix(c.GetTransform())
                walk(c.GetObjectResource(),
                     np.vstack([inner[:3] @ m[:3], inner[3] @ m[:3] + m[3]]))

    items = model.GetBuildItems()
    while items.MoveNext():
        item = items.GetCurrent()
        walk(item.GetObjectResource(), matrix(item.GetObjectTransform()))
    points = np.vstack(found["points"])
    print(path, "(lib3mf's reading) triangles", found["triangles"], "volume",
          repr(found["volume"]), "bounds",
          [points.min(axis=0).tolist(), points.max(axis=0).tolist()])


def report(path):
    """The figures of a file as trimesh reads it back."""
    scene = trimesh.load(path, force="scene")
    mesh = scene.to_mesh() if hasattr(scene, "to_mesh") else scene.dump(concatenate=True)
    print(path, "triangles", len(mesh.faces), "volume", repr(float(mesh.volume)),
          "bounds", mesh.bounds.tolist())


def main():
    write_lib3mf("lib3mf_components.3mf")
    write_lib3mf_production("lib3mf_production.3mf")
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
    for path in ["lib3mf_components.3mf", "lib3mf_production.3mf",
                 "trimesh_icosphere.3mf", "trimesh_scene.3mf"]:
        report(path)
    # trimesh 5.2.0 reads a part that several components name once per
    # component, into one geometry each instance then places: its figures
    # for lib3mf_production.3mf count the box four times, not twice.
    for path in ["lib3mf_components.3mf", "lib3mf_production.3mf"]:
        measure_lib3mf(path)


main()
