#!/usr/bin/env python3
"""Times the C++ Manifold (the registry's Python package `manifold3d`) on
the 3D bench inputs that `write-inputs-3d` writes, in-process, and prints
a CSV row per operation.

Optional and outside CI. Usage (from the repository root):

    pip install manifold3d numpy
    cargo run --release -p umbra-benches --bin write-inputs-3d
    python3 benches/manifold3d/run.py [--dir target/bench-inputs] [--cpus 1]
        [--sizes 2000,20000,200000,1000000] [--csv docs/images/manifold3d.csv]
        [--skip-batch] [--skip-chain]

Each operand is read from binary PLY (double coordinates, the same f64
bits the Rust benches use) and turned into a `Manifold` through `Mesh64`
before any timing. Timed: `a - b` (the sphere difference of
`perf-table-3d`), the same difference mesh in, mesh out
(`sphere-difference-mesh-to-mesh`: both `Manifold`s built from their
`Mesh64` arrays, the difference, and its `to_mesh64()`, which is what
Umbra's `boolean_triangles` does between `TriangleMesh`es), `Manifold.batch_boolean(spheres, Add)` (the union of the
1,000 spheres of `perf-table-nary`) and `Manifold.batch_boolean([slab] +
boxes, Subtract)` (the slab minus 1,000 boxes), and the iterated-CSG chain
of `csg-chain` (`chain-slab.ply` minus the boxes of `chain-boxes-1000.ply`
one difference at a time, in file order, each result feeding the next:
the summed time of the 1,000 differences). Manifold evaluates lazily, so
each timing ends with `num_tri()`, which forces the Boolean; in the chain
every step is forced, as a user who looks at each result would (left
lazy, Manifold folds the whole chain into one batch difference, which is
the n-ary row). Time is
the best of 3 runs (1 run at >= 1M triangles per operand).

Threads: the package runs its Booleans on TBB, which uses the CPUs the
process may run on. `--cpus K` restricts the process to the first K CPUs
(`os.sched_setaffinity`) before `manifold3d` is imported; the package has
no thread-count setting of its own.
"""

import argparse
import csv
import os
import sys
import time


def read_ply(path):
    """Vertices (n x 3 float64) and triangles (m x 3 uint64) of a binary
    little-endian PLY as `umbra::write_mesh` writes it (double x y z; a
    face list of uchar or uint counts with uint indices)."""
    import numpy as np

    with open(path, "rb") as f:
        data = f.read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    header = data[:end].decode("ascii").splitlines()
    if header[1] != "format binary_little_endian 1.0":
        raise ValueError(f"{path}: not binary little-endian PLY")
    nv = nf = 0
    count_type = "u1"
    for line in header:
        parts = line.split()
        if parts[:2] == ["element", "vertex"]:
            nv = int(parts[2])
        elif parts[:2] == ["element", "face"]:
            nf = int(parts[2])
        elif parts[:2] == ["property", "list"]:
            count_type = {"uchar": "u1", "uint": "<u4"}[parts[2]]
            if parts[3] != "uint":
                raise ValueError(f"{path}: face indices must be uint")
        elif parts[:1] == ["property"] and parts[1] != "double":
            raise ValueError(f"{path}: vertex properties must be double")
    verts = np.frombuffer(data, dtype="<f8", count=3 * nv, offset=end).reshape(nv, 3)
    face_dtype = np.dtype([("n", count_type), ("i", "<u4", (3,))])
    faces = np.frombuffer(data, dtype=face_dtype, count=nf, offset=end + 24 * nv)
    if nf and not (faces["n"] == 3).all():
        raise ValueError(f"{path}: every face must be a triangle")
    # Writable native-order copies (nanobind refuses read-only buffers).
    return np.array(verts, dtype=np.float64), np.array(faces["i"], dtype=np.uint64)


def manifold_of(m3d, path):
    verts, tris = read_ply(path)
    solid = m3d.Manifold(m3d.Mesh64(vert_properties=verts, tri_verts=tris))
    if str(solid.status()) not in ("Error.NoError", "NoError"):
        raise ValueError(f"{path}: manifold3d refused the mesh: {solid.status()}")
    return solid


def components_in_order(m3d, path):
    """The connected components of a PLY file's mesh as `Manifold`s, in the
    order of their first triangle (how `write-inputs-3d` concatenates the
    chain's boxes). `Manifold.decompose` does not promise an order, and the
    chain needs it."""
    import numpy as np

    verts, tris = read_ply(path)
    parent = list(range(len(verts)))

    def find(v):
        while parent[v] != v:
            parent[v] = parent[parent[v]]
            v = parent[v]
        return v

    for a, b, c in tris.tolist():
        ra, rb, rc = find(a), find(b), find(c)
        parent[rb] = ra
        parent[find(rc)] = ra
    groups = {}
    for t, tri in enumerate(tris.tolist()):
        groups.setdefault(find(tri[0]), []).append(t)
    parts = []
    for k, members in enumerate(groups.values()):  # insertion order = first triangle
        sub = tris[members]
        used, local = np.unique(sub, return_inverse=True)
        mesh = m3d.Mesh64(
            vert_properties=np.array(verts[used]),
            tri_verts=np.array(local.reshape(-1, 3), dtype=np.uint64),
        )
        solid = m3d.Manifold(mesh)
        if str(solid.status()) not in ("Error.NoError", "NoError"):
            raise ValueError(f"{path}: component {k}: {solid.status()}")
        parts.append(solid)
    return parts


def chain_of(slab, boxes):
    """The chain: `slab - box` for every box in order, each step forced;
    returns the summed time (ms) and the final result."""
    total, shape = 0.0, slab
    for b in boxes:
        t = time.perf_counter()
        shape = shape - b
        shape.num_tri()
        total += (time.perf_counter() - t) * 1e3
    return total, shape


def status_kib(field):
    """A `/proc/self/status` field in KiB (0 where there is none)."""
    try:
        with open("/proc/self/status") as f:
            for line in f:
                if line.startswith(field):
                    return int(line.split()[1])
    except OSError:
        pass
    return 0


class RssGrowth:
    """The resident set's growth during a block, as `perf-table-3d`
    measures Umbra's: `VmRSS` before, the kernel's peak RSS reset
    (`/proc/self/clear_refs`, value 5), `VmHWM` after. It sees every
    allocation of the C++ library (allocator retention included)."""

    def __enter__(self):
        self.base = status_kib("VmRSS:")
        try:
            with open("/proc/self/clear_refs", "w") as f:
                f.write("5")
        except OSError:
            pass
        return self

    def __exit__(self, *exc):
        self.mib = max(0, status_kib("VmHWM:") - self.base) / 1024.0
        return False


def best_of(runs, op):
    """Best time (ms) of `runs` runs, the last output, and the RSS growth
    (MiB) over all runs."""
    best, out = float("inf"), None
    with RssGrowth() as rss:
        for _ in range(runs):
            out = None  # the previous output is freed before the next run
            t = time.perf_counter()
            out = op()
            out.num_tri()
            best = min(best, (time.perf_counter() - t) * 1e3)
    return best, out, rss.mib


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--dir", default="target/bench-inputs")
    ap.add_argument("--sizes", default="2000,20000,200000,1000000")
    ap.add_argument("--cpus", type=int, default=0, help="run on the first K CPUs only")
    ap.add_argument("--csv", default="", help="append the rows to this CSV file too")
    ap.add_argument("--skip-batch", action="store_true", help="only the sphere differences")
    ap.add_argument("--skip-chain", action="store_true", help="no iterated-CSG chain")
    args = ap.parse_args()
    if args.cpus > 0:
        cpus = sorted(os.sched_getaffinity(0))[: args.cpus]
        os.sched_setaffinity(0, cpus)
    import manifold3d as m3d  # after the affinity is set: TBB sizes its pool then

    cpus = len(os.sched_getaffinity(0))
    version = getattr(m3d, "__version__", "")
    rows = []

    def record(op, size, ms, out, inputs, rss_mib):
        rows.append(
            {
                "library": "manifold3d" + (f" {version}" if version else ""),
                "op": op,
                "size": size,
                "cpus": cpus,
                "ms": f"{ms:.3f}",
                "triangles": out.num_tri(),
                "volume": repr(out.volume()),
                "input_triangles": inputs,
                "rss_growth_mib": f"{rss_mib:.1f}",
            }
        )
        print(
            f"{op} {size}: {ms:.1f} ms, {out.num_tri()} triangles, volume {out.volume():.9f}, "
            f"RSS growth {rss_mib:.1f} MiB",
            file=sys.stderr,
        )

    for size in [int(s) for s in args.sizes.split(",") if s.strip()]:
        a = manifold_of(m3d, os.path.join(args.dir, f"sphere-a-{size}.ply"))
        b = manifold_of(m3d, os.path.join(args.dir, f"sphere-b-{size}.ply"))
        runs = 1 if size >= 1_000_000 else 3
        ms, out, rss = best_of(runs, lambda: a - b)
        record("sphere-difference", size, ms, out, a.num_tri() + b.num_tri(), rss)
        # Mesh in, mesh out, as Umbra's `boolean_triangles` runs: from the
        # indexed arrays (read before the timing) to the result's arrays.
        # `a - b` above starts from `Manifold`s whose construction (edge
        # pairing, sorting, bounding boxes) was done before the timing.
        arrays = [read_ply(os.path.join(args.dir, f"sphere-{s}-{size}.ply")) for s in "ab"]

        def mesh_to_mesh():
            ma, mb = (m3d.Manifold(m3d.Mesh64(vert_properties=v, tri_verts=t)) for v, t in arrays)
            out = ma - mb
            out.to_mesh64()
            return out

        ms, out, rss = best_of(runs, mesh_to_mesh)
        record("sphere-difference-mesh-to-mesh", size, ms, out, a.num_tri() + b.num_tri(), rss)

    if not args.skip_batch:
        spheres = manifold_of(m3d, os.path.join(args.dir, "spheres-1000.ply")).decompose()
        ms, out, rss = best_of(1, lambda: m3d.Manifold.batch_boolean(spheres, m3d.OpType.Add))
        record("union-1000-spheres", len(spheres), ms, out, sum(s.num_tri() for s in spheres), rss)
        slab = manifold_of(m3d, os.path.join(args.dir, "slab.ply"))
        boxes = manifold_of(m3d, os.path.join(args.dir, "boxes-1000.ply")).decompose()
        ms, out, rss = best_of(
            1, lambda: m3d.Manifold.batch_boolean([slab] + boxes, m3d.OpType.Subtract)
        )
        record("slab-minus-1000-boxes", len(boxes), ms, out, slab.num_tri() + sum(x.num_tri() for x in boxes), rss)

    if not args.skip_chain:
        slab = manifold_of(m3d, os.path.join(args.dir, "chain-slab.ply"))
        boxes = components_in_order(m3d, os.path.join(args.dir, "chain-boxes-1000.ply"))
        with RssGrowth() as rss:
            ms, out = chain_of(slab, boxes)
        record("chain-1000-boxes", len(boxes), ms, out, slab.num_tri() + sum(x.num_tri() for x in boxes), rss.mib)

    fields = ["library", "op", "size", "cpus", "ms", "triangles", "volume", "input_triangles", "rss_growth_mib"]
    writer = csv.DictWriter(sys.stdout, fieldnames=fields)
    writer.writeheader()
    writer.writerows(rows)
    if args.csv:
        # Rows already in the file are kept; a file written before a column
        # existed is rewritten with that column empty in its old rows.
        old = []
        if os.path.exists(args.csv):
            with open(args.csv, newline="") as f:
                old = list(csv.DictReader(f))
        with open(args.csv, "w", newline="") as f:
            w = csv.DictWriter(f, fieldnames=fields, restval="", extrasaction="ignore")
            w.writeheader()
            w.writerows(old)
            w.writerows(rows)

if __name__ == "__main__":
    main()
