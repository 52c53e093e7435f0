"""A batch of independent 3D Booleans fanned out with dask.distributed.

A plate is carved by many tool paths (slots milled along x and y, and
drilled holes), cut into tiles: each tile is one task, "the tile minus the
union of the tools that reach it", run by umbra on a worker. The meshes
travel between the client and the workers as numpy arrays (an umbra.Mesh
pickles as its vertices, half-edges and facet offsets). Results are
gathered, validated (topologically valid, 2-manifold, no self-intersecting
facets, and the volume of every tile, to 1e-12 of the tile's, against an
exact oracle: the union of axis-aligned slot boxes by coordinate
compression, plus the prism volume of each hole) and summarised.

    pip install ./crates/umbra-py "dask[distributed]"
    python crates/umbra-py/examples/dask_batch.py                 # a LocalCluster of 2 workers
    python crates/umbra-py/examples/dask_batch.py --workers 1 --tiles 8
    python crates/umbra-py/examples/dask_batch.py --scheduler tcp://HOST:8786

Exit status 0 when every tile is valid and its volume matches, 1 otherwise.
"""

from __future__ import annotations

import argparse
import itertools
import math
import os
import sys
import time

import numpy as np

# One rayon thread per Boolean: dask already runs one task per core. Set
# before the workers start (they inherit the environment).
os.environ.setdefault("RAYON_NUM_THREADS", "1")

import umbra  # noqa: E402
from dask.distributed import Client, LocalCluster  # noqa: E402

PLATE = 100.0  # the plate is PLATE x PLATE x THICK, corner at the origin
THICK = 10.0


def box(lo, hi):
    """An axis-aligned box as an umbra mesh (a CSG leaf, moved)."""
    size = [h - l for l, h in zip(lo, hi)]
    return umbra.csg({"box": {"size": size}, "translate": list(lo)})


def hole(x, y, radius, segments):
    """A drilled hole: a vertical prism through the plate and beyond."""
    return umbra.csg(
        {
            "cylinder": {"radius": radius, "height": THICK + 2.0, "segments": segments},
            "translate": [x, y, -1.0],
        }
    )


def prism_volume(radius, segments, height):
    """The volume of a regular prism inscribed in a cylinder."""
    return 0.5 * segments * radius * radius * math.sin(2.0 * math.pi / segments) * height


def box_union_volume(boxes, clip):
    """The exact volume of the union of axis-aligned boxes within `clip`
    (coordinate compression: every cell of the grid of box bounds is in
    or out as a whole)."""
    lo_c, hi_c = np.array(clip[0]), np.array(clip[1])
    parts = []
    for lo, hi in boxes:
        lo = np.maximum(lo, lo_c)
        hi = np.minimum(hi, hi_c)
        if np.all(hi > lo):
            parts.append((lo, hi))
    if not parts:
        return 0.0
    lo = np.array([p[0] for p in parts])
    hi = np.array([p[1] for p in parts])
    axes = [np.unique(np.concatenate([lo[:, k], hi[:, k]])) for k in range(3)]
    mids = [(a[:-1] + a[1:]) / 2.0 for a in axes]
    widths = [np.diff(a) for a in axes]
    cx, cy, cz = np.meshgrid(*mids, indexing="ij")
    inside = np.zeros(cx.shape, dtype=bool)
    for (l0, l1, l2), (h0, h1, h2) in zip(lo, hi):
        inside |= (cx > l0) & (cx < h0) & (cy > l1) & (cy < h1) & (cz > l2) & (cz < h2)
    cell = widths[0][:, None, None] * widths[1][None, :, None] * widths[2][None, None, :]
    return float(np.sum(cell[inside]))


def plan(tiles, slots, holes_per_tile, segments):
    """The jobs: for each tile, its box, the tools that reach it, and the
    volume it must have."""
    step = PLATE / tiles
    # Slots: 2 wide, 3 deep (from z = 7 up through the top), across the
    # whole plate, evenly spread along x and along y.
    slot_boxes = []
    for k in range(slots):
        c = PLATE * (k + 0.5) / slots + 0.37  # off the tile borders
        slot_boxes.append(((-1.0, c - 1.0, 7.0), (PLATE + 1.0, c + 1.0, THICK + 1.0)))
        slot_boxes.append(((c - 1.0, -1.0, 7.0), (c + 1.0, PLATE + 1.0, THICK + 1.0)))
    # Holes: a square grid inside every tile, between the slots.
    n = max(1, int(round(math.sqrt(holes_per_tile))))
    radius = min(step / n / 4.0, 0.45 * PLATE / slots - 1.0)
    jobs = []
    for i, j in itertools.product(range(tiles), range(tiles)):
        lo = (i * step, j * step, 0.0)
        hi = ((i + 1) * step, (j + 1) * step, THICK)
        tools = [(b_lo, b_hi) for b_lo, b_hi in slot_boxes
                 if all(b_lo[k] <= hi[k] and lo[k] <= b_hi[k] for k in range(3))]
        centres = []
        for a, b in itertools.product(range(n), range(n)):
            x = lo[0] + step * (a + 0.5) / n
            y = lo[1] + step * (b + 0.5) / n
            # Only where no slot passes (so the oracle's parts are disjoint).
            if all(not (s_lo[0] - radius <= x <= s_hi[0] + radius
                        and s_lo[1] - radius <= y <= s_hi[1] + radius) for s_lo, s_hi in slot_boxes):
                centres.append((x, y))
        if radius <= 0.0:
            centres = []
        expected = (
            step * step * THICK
            - box_union_volume(tools, (lo, hi))
            - len(centres) * prism_volume(radius, segments, THICK)
        )
        meshes = [box(t_lo, t_hi) for t_lo, t_hi in tools]
        meshes += [hole(x, y, radius, segments) for x, y in centres]
        jobs.append({"tile": (i, j), "box": box(lo, hi), "tools": meshes, "expected": expected,
                     "tolerance": 1e-12 * step * step * THICK})
    return jobs


def carve(tile, tools):
    """One task, run on a worker: the tile minus the union of its tools,
    with its check report. Returns plain data and the mesh (numpy arrays
    on the wire)."""
    start, cpu = time.perf_counter(), time.process_time()
    cut = umbra.boolean(tile, umbra.union_all(tools), "difference") if tools else tile
    report = cut.check()
    return {
        "mesh": cut,
        "volume": report["signed_volume"],
        "valid": report["topologically_valid"] and report["coordinates_valid"],
        "two_manifold": report["two_manifold"],
        "self_intersections": report["self_intersecting_facet_pairs"],
        "booleans": len(tools),  # len - 1 unions and one difference
        "seconds": time.perf_counter() - start,
        "cpu_seconds": time.process_time() - cpu,
        "worker_pid": os.getpid(),
    }


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--scheduler", metavar="ADDRESS", help="a running dask scheduler (default: a LocalCluster)")
    p.add_argument("--workers", type=int, default=2, help="LocalCluster worker processes (default 2)")
    p.add_argument("--tiles", type=int, default=4, help="tiles per side (default 4: 16 tasks)")
    p.add_argument("--slots", type=int, default=8, help="slots along each axis (default 8)")
    p.add_argument("--holes", type=int, default=16, help="holes per tile (default 16)")
    p.add_argument("--segments", type=int, default=48, help="segments of a hole (default 48)")
    p.add_argument("--output", metavar="FILE", help="also write the union of the tiles (e.g. plate.obj)")
    args = p.parse_args(argv)

    t0 = time.perf_counter()
    jobs = plan(args.tiles, args.slots, args.holes, args.segments)
    t_plan = time.perf_counter() - t0

    if args.scheduler:
        client = Client(args.scheduler)
        cluster = None
    else:
        cluster = LocalCluster(
            n_workers=args.workers, threads_per_worker=1, processes=True, dashboard_address=None
        )
        client = Client(cluster)
    try:
        workers = len(client.scheduler_info().get("workers", {}))
        # Warm every worker (import umbra there) before timing.
        client.run(lambda: __import__("umbra").__version__)
        t1 = time.perf_counter()
        futures = [client.submit(carve, j["box"], j["tools"], pure=False) for j in jobs]
        results = client.gather(futures)
        t_run = time.perf_counter() - t1
    finally:
        client.close()
        if cluster is not None:
            cluster.close()

    bad = []
    total, expected_total = 0.0, 0.0
    for job, r in zip(jobs, results):
        total += r["volume"]
        expected_total += job["expected"]
        tol = job["tolerance"]
        ok = (
            r["valid"]
            and r["two_manifold"]
            and r["self_intersections"] == 0
            and abs(r["volume"] - job["expected"]) <= tol
        )
        if not ok:
            bad.append((job["tile"], r["volume"], job["expected"], r["valid"], r["two_manifold"], r["self_intersections"]))

    booleans = sum(r["booleans"] for r in results)
    busy = sum(r["seconds"] for r in results)
    cpu = sum(r["cpu_seconds"] for r in results)
    facets = sum(len(r["mesh"].to_arrays()[2]) - 1 for r in results)
    print(f"umbra {umbra.__version__}: {len(jobs)} tiles, {booleans} Booleans, {workers} worker(s), "
          f"{len({r['worker_pid'] for r in results})} process(es) used")
    print(f"  plan {t_plan:.2f} s; run {t_run:.2f} s wall, {busy:.2f} s in tasks ({cpu:.2f} s CPU); "
          f"{len(jobs) / t_run:.1f} tiles/s, {booleans / t_run:.0f} Booleans/s")
    print(f"  volume {total:.9f}, expected {expected_total:.9f} (difference {total - expected_total:.3e}); "
          f"{facets} facets in all")
    if args.output:
        plate = umbra.union_all([r["mesh"] for r in results])
        umbra.write(plate, args.output)
        print(f"  the carved plate: {plate} -> {args.output}")
    if bad:
        print(f"  {len(bad)} tile(s) FAILED validation:")
        for b in bad[:10]:
            print(f"    tile {b[0]}: volume {b[1]} expected {b[2]} valid {b[3]} 2-manifold {b[4]} "
                  f"self-intersecting pairs {b[5]}")
        return 1
    print("  every tile topologically valid, 2-manifold, without self-intersections, volume exact to 1e-12 of the tile")
    return 0


if __name__ == "__main__":
    sys.exit(main())
