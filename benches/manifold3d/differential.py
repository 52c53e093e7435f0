#!/usr/bin/env python3
"""Checks the 3D `umbra boolean` and `umbra csg` against the C++ Manifold
(the registry's Python package `manifold3d`) on real meshes: the same
operands, bit for bit, through both, and the results compared.

Optional and outside CI. Usage (from the repository root):

    pip install manifold3d numpy trimesh
    cargo build --release -p umbra-cli
    python3 benches/manifold3d/differential.py [--umbra target/release/umbra]
        [--meshes DIR ...] [--pairs 200] [--chains 6] [--chain-length 40]
        [--seed 1] [--keep DIR]

Meshes: the closed meshes of `crates/test-support/data/pyvista` and of
every `--meshes DIR` (`.obj .ply .off .stl`; open or non-manifold ones and
ones Manifold refuses are skipped with a note). The sample meshes that
the PyPI wheel of `pymeshlab` ships (`pip download --no-deps pymeshlab`,
unzip the wheel, `pymeshlab/tests/sample_meshes`: the Stanford bunny, a
bone, an airplane, a cow, a cube) are what the figures in
`docs/performance.md` were measured on.

Pairs: a mesh against a second copy of itself or of another mesh, moved
in one of several ways: a random rotation and shift (`rand`), the same
mesh unmoved (`same`: every facet coincides), shifted by 0, 1e-12, 1e-9 or
a tenth of its size along each axis (`shift`), turned by 1e-6 to 1e-12
radians (`tiny`), its axes permuted cyclically and shifted by dyadic
fractions of its size (`perm`: exact coordinates, many coplanar and
coincident facets), and another mesh scaled to its size and shifted along
the axes only (`axis`). Each pair goes through `umbra boolean` (union,
intersection or difference, the polygon-mesh or the triangle-mesh
variant, default smoothing) and through Manifold's `batch_boolean`.

Chains: a mesh minus (or plus) `--chain-length` small icospheres placed
on its vertices, one operation at a time, each result feeding the next:
`umbra csg` on a nested script (triangle variant; default smoothing, then
again with `--smooth 0` for the timing of the Booleans alone) and
Manifold's `a - b` forced by `num_tri()` after every step.

Each case runs Umbra twice: the Booleans' own output (`--smooth 0`) must
be topologically valid (section 4.2) with the volume of Manifold's result
to a relative 1e-9 (or 1e-12 of the operand's size cubed, for results of
almost no volume); the default output (smoothed near the contacts, with
the guard) must also be a 2-manifold, with no more self-intersecting
facet pairs than the raw output (`umbra check --json`) and a volume
within the reported distortion bound times the surface area of the raw
one. Prints one line per case (with both outputs' self-intersecting
pairs, and for chains the triangle counts and times) and a summary; the
exit status is 1 when any case failed. With `--keep`, the operands and
script of every failed case are copied there.
"""

import argparse
import json
import math
import os
import random
import shutil
import subprocess
import sys
import tempfile
import time

OPS = ("union", "intersection", "difference")
SUFFIXES = (".obj", ".ply", ".off", ".stl")


def write_obj(path, verts, faces):
    """Writes an OBJ whose coordinates read back as the same f64 bits
    (Python's `repr` of a float is the shortest exact form)."""
    with open(path, "w") as out:
        for p in verts:
            out.write("v %r %r %r\n" % (float(p[0]), float(p[1]), float(p[2])))
        for t in faces:
            out.write("f %d %d %d\n" % (t[0] + 1, t[1] + 1, t[2] + 1))


def rotation(axis, angle):
    import numpy as np

    axis = np.asarray(axis, float)
    axis = axis / np.linalg.norm(axis)
    k = np.array(
        [[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]]
    )
    return np.eye(3) + math.sin(angle) * k + (1 - math.cos(angle)) * k @ k


class Checker:
    def __init__(self, umbra, m3d, keep):
        self.umbra = umbra
        self.m3d = m3d
        self.keep = keep
        self.failed = 0
        self.cases = 0

    def manifold(self, verts, faces):
        import numpy as np

        mesh = self.m3d.Mesh64(
            vert_properties=np.ascontiguousarray(verts, dtype=np.float64),
            tri_verts=np.ascontiguousarray(faces, dtype=np.uint64),
        )
        return self.m3d.Manifold(mesh)

    def check(self, path):
        out = subprocess.run(
            [self.umbra, "check", path, "--json"], capture_output=True, text=True
        )
        return json.loads(out.stdout)

    def verdict(self, label, raw, smoothed, volume, size, workdir):
        """Compares an Umbra result with Manifold's volume: `raw` is the
        `umbra check` report of the Booleans' own output (`--smooth 0`),
        `smoothed` that of the default output with the command's report
        (`smoothing.distortion_bound`) and the output's surface area
        (`area`) beside it, or `None`. Prints the case and records a
        failure."""
        self.cases += 1
        problems = []
        for name, report in (("raw", raw), ("smoothed", smoothed)):
            if report is None:
                continue
            if not report.get("topologically_valid"):
                problems.append("%s: not topologically valid" % name)
            # Coincident facets (a mesh against itself) leave the raw
            # output non-manifold where they cancel; smoothing removes that.
            if name == "smoothed" and report.get("two_manifold") is False:
                problems.append("%s: not 2-manifold" % name)
        mine = raw.get("signed_volume")
        if mine is None:
            problems.append("raw: no volume")
        elif abs(mine - volume) > 1e-9 * max(abs(volume), size**3 * 1e-3):
            problems.append("raw volume %r against %r" % (mine, volume))
        notes = ["self-intersecting pairs: raw %d" % raw.get("self_intersecting_facet_pairs", -1)]
        if smoothed is not None:
            pairs = smoothed.get("self_intersecting_facet_pairs", -1)
            notes.append("smoothed %d" % pairs)
            if pairs > raw.get("self_intersecting_facet_pairs", 0):
                problems.append("smoothing added self-intersecting facet pairs")
            # Every point moves by at most the distortion bound, so the
            # volume by at most the bound times the larger surface.
            moved = abs(smoothed.get("signed_volume", 0.0) - (mine or 0.0))
            allowed = smoothed["distortion_bound"] * max(smoothed["area"], raw["area"]) * 1.01 + 1e-9 * abs(volume)
            if moved > allowed:
                problems.append("smoothing changed the volume by %r (at most %r)" % (moved, allowed))
        status = "ok" if not problems else "FAILED: " + "; ".join(problems)
        print(
            "%s: umbra %r, manifold %r (%s): %s" % (label, mine, volume, ", ".join(notes), status),
            flush=True,
        )
        if problems:
            self.failed += 1
            if self.keep:
                dest = os.path.join(self.keep, "case%d" % self.cases)
                shutil.copytree(workdir, dest, dirs_exist_ok=True)

    def run(self, args, out, report=None):
        """Runs an Umbra command writing `out`; returns the check report
        of `out` with its surface area (and the command's smoothing
        report when `report` names one), or the error text."""
        import trimesh

        run = subprocess.run(args + (["--report", report] if report else []), capture_output=True, text=True)
        if run.returncode != 0:
            return run.stderr.strip()
        checked = self.check(out)
        checked["area"] = float(trimesh.load(out, process=False, force="mesh").area) if checked.get("facets") else 0.0
        if report:
            with open(report) as f:
                full = json.load(f)
            checked["distortion_bound"] = (full.get("smoothing") or {}).get("distortion_bound") or 0.0
            checked["total_ms"] = full["timings_ms"]["total"]
        return checked


def load_meshes(dirs, umbra):
    import numpy as np
    import trimesh

    meshes = {}
    for d in dirs:
        for name in sorted(os.listdir(d)):
            path = os.path.join(d, name)
            if not name.lower().endswith(SUFFIXES):
                continue
            report = json.loads(
                subprocess.run(
                    [umbra, "check", path, "--json"], capture_output=True, text=True
                ).stdout
                or "{}"
            )
            if not (
                report.get("topologically_valid")
                and report.get("two_manifold")
                and report.get("self_intersecting_facet_pairs") == 0
            ):
                print("skipped %s: not a closed 2-manifold without self-intersections" % name)
                continue
            mesh = trimesh.load(path, process=False, force="mesh")
            verts = np.asarray(mesh.vertices, dtype=np.float64)
            faces = np.asarray(mesh.faces, dtype=np.int64)
            if len(faces) == 0:
                continue
            key = name if name not in meshes else "%s/%s" % (os.path.basename(d), name)
            meshes[key] = (verts, faces)
    return meshes


def moved_copy(rng, a, b, same_mesh):
    """The second operand and the name of the way it was moved."""
    import numpy as np

    va, _ = a
    vb, _ = b
    lo, hi = va.min(0), va.max(0)
    size = float((hi - lo).max())
    kinds = ["rand", "axis"] + (["same", "shift", "tiny", "perm", "perm"] if same_mesh else [])
    kind = rng.choice(kinds)
    if kind == "same":
        return vb.copy(), kind
    if kind == "shift":
        return vb + np.array([rng.choice([0.0, 1e-12, 1e-9, 0.1]) * size for _ in range(3)]), kind
    if kind == "tiny":
        centre = va.mean(0)
        turn = rotation([rng.random() + 0.01 for _ in range(3)], rng.choice([1e-6, 1e-9, 1e-12]))
        return (vb - centre) @ turn.T + centre, kind
    if kind == "perm":
        order = rng.choice([[1, 2, 0], [2, 0, 1]])
        step = 2.0 ** math.floor(math.log2(size))
        return vb[:, order] + np.array([rng.choice([0.0, 0.25, 0.5, -0.125]) * step for _ in range(3)]), kind
    sb = float((vb.max(0) - vb.min(0)).max())
    centre_b = (vb.max(0) + vb.min(0)) / 2
    turn = rotation([rng.random() - 0.5 for _ in range(3)], rng.random() * 2 * math.pi) if kind == "rand" else np.eye(3)
    scale = size / sb * rng.uniform(0.5, 1.0)
    shift = (hi + lo) / 2 + np.array([rng.uniform(-0.3, 0.3) * size for _ in range(3)])
    return (vb - centre_b) @ turn.T * scale + shift, kind


def read_back(path):
    import numpy as np

    with open(path) as f:
        return np.array([[float(x) for x in line.split()[1:4]] for line in f if line.startswith("v ")])


def run_pairs(checker, meshes, rng, count, work):
    ops = {
        "union": checker.m3d.OpType.Add,
        "intersection": checker.m3d.OpType.Intersect,
        "difference": checker.m3d.OpType.Subtract,
    }
    names = sorted(meshes)
    for i in range(count):
        na = rng.choice(names)
        nb = na if rng.random() < 0.6 else rng.choice(names)
        a, b = meshes[na], meshes[nb]
        vb, kind = moved_copy(rng, a, b, na == nb)
        op = rng.choice(OPS)
        triangles = rng.random() < 0.5
        pa, pb, out = (os.path.join(work, f) for f in ("a.obj", "b.obj", "out.obj"))
        write_obj(pa, a[0], a[1])
        write_obj(pb, vb, b[1])
        va2, vb2 = read_back(pa), read_back(pb)
        want = checker.m3d.Manifold.batch_boolean(
            [checker.manifold(va2, a[1]), checker.manifold(vb2, b[1])], ops[op]
        ).volume()
        args = [checker.umbra, "boolean", op, pa, pb, "-o", out]
        if triangles:
            args.append("--triangulate")
        label = "pair %d: %s %s %s (%s, %s)" % (
            i, na, op, nb, kind, "triangles" if triangles else "polygons")
        size = float((a[0].max(0) - a[0].min(0)).max())
        raw = checker.run(args + ["--smooth", "0"], out)
        smoothed = checker.run(args, out, os.path.join(work, "report.json"))
        if isinstance(raw, str) or isinstance(smoothed, str):
            checker.cases += 1
            checker.failed += 1
            print("%s: FAILED: %s" % (label, raw if isinstance(raw, str) else smoothed), flush=True)
            continue
        checker.verdict(label, raw, smoothed, want, size, work)


def run_chains(checker, meshes, rng, count, length, work):
    import numpy as np
    import trimesh

    ico = trimesh.creation.icosphere(subdivisions=2)
    names = sorted(meshes)
    for i in range(count):
        name = rng.choice(names)
        op = rng.choice(["difference", "difference", "union"])
        verts, faces = meshes[name]
        write_obj(os.path.join(work, "base.obj"), verts, faces)
        verts = read_back(os.path.join(work, "base.obj"))
        size = float((verts.max(0) - verts.min(0)).max())
        node = {"file": "base.obj"}
        solid = checker.manifold(verts, faces)
        manifold_s = 0.0
        for k in range(length):
            radius = size * rng.uniform(0.03, 0.12)
            tool = os.path.join(work, "t%d.obj" % k)
            write_obj(tool, np.asarray(ico.vertices) * radius, ico.faces)
            at = verts[rng.randrange(len(verts))]
            node = {"op": op, "children": [node, {"file": "t%d.obj" % k, "translate": [float(c) for c in at]}]}
            other = checker.manifold(read_back(tool) + at, ico.faces)
            start = time.perf_counter()
            solid = solid - other if op == "difference" else solid + other
            solid.num_tri()
            manifold_s += time.perf_counter() - start
        script = os.path.join(work, "chain.json")
        with open(script, "w") as f:
            json.dump(node, f)
        label = "chain %d: %s %s %d icospheres" % (i, name, op, length)
        out = os.path.join(work, "chain.obj")
        args = [checker.umbra, "csg", script, "-o", out, "--triangulate", "--quiet"]
        report = os.path.join(work, "report.json")
        raw = checker.run(args + ["--smooth", "0"], out, report)
        smoothed = checker.run(args, out, report)
        if isinstance(raw, str) or isinstance(smoothed, str):
            checker.cases += 1
            checker.failed += 1
            print("%s: FAILED: %s" % (label, raw if isinstance(raw, str) else smoothed), flush=True)
            continue
        checker.verdict(label, raw, smoothed, solid.volume(), size, work)
        print(
            "  triangles: umbra %d, manifold %d; time: umbra %.1f ms (with smoothing %.1f ms), manifold %.1f ms"
            % (raw["facets"], solid.num_tri(), raw["total_ms"], smoothed["total_ms"], manifold_s * 1e3),
            flush=True,
        )


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    root = os.path.dirname(os.path.dirname(here))
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--umbra", default=os.path.join(root, "target", "release", "umbra"))
    parser.add_argument("--meshes", action="append", default=[])
    parser.add_argument("--pairs", type=int, default=200)
    parser.add_argument("--chains", type=int, default=6)
    parser.add_argument("--chain-length", type=int, default=40)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--keep")
    args = parser.parse_args()
    if args.chain_length > 55:
        parser.error("--chain-length: a CSG script nests at most about 60 operations")
    import manifold3d

    dirs = [os.path.join(root, "crates", "test-support", "data", "pyvista")] + args.meshes
    meshes = load_meshes(dirs, args.umbra)
    if not meshes:
        sys.exit("no closed meshes found")
    checker = Checker(args.umbra, manifold3d, args.keep)
    rng = random.Random(args.seed)
    with tempfile.TemporaryDirectory() as work:
        run_pairs(checker, meshes, rng, args.pairs, work)
        run_chains(checker, meshes, rng, args.chains, args.chain_length, work)
    print("%d cases, %d failed" % (checker.cases, checker.failed))
    sys.exit(1 if checker.failed else 0)


if __name__ == "__main__":
    main()
