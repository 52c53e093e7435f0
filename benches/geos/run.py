#!/usr/bin/env python3
"""Times the default 2D `umbra boolean` (the basic Boolean, then smoothing
at the default tolerance) against GEOS (through the registry's `shapely`)
on real maps, and checks that both give the same region.

Optional and outside CI. Usage (from the repository root):

    pip install shapely pyshp
    cargo build --release -p umbra-cli
    python3 benches/geos/run.py [--umbra target/release/umbra]
        [--nybb path/to/nybb.shp] [--runs 3] [--csv out.csv]

Maps: Natural Earth's countries (`crates/test-support/data/naturalearth`,
10,355 vertices) and, with `--nybb`, the New York City borough boundaries
(76,063 vertices) that the PyPI wheel `geopandas-0.14.4` ships as
`geopandas/datasets/nybb_16a.zip` (`pip download --no-deps
geopandas==0.14.4`, unzip the wheel, then the archive). Each map is
united into one region `A` by shapely, and `B` is one of four copies:
rotated by 0.37 degrees about its centroid and shifted by about 1% of its
width (`rt`), scaled by `1 + 1e-7` about the origin (`sc`: thousands of
crossings and slivers), shifted by 1e-9 of its width (`sh`) and rotated
by 1e-6 degrees about its centroid (`rot`). For each of union,
intersection, difference and symmetric difference the script prints the
least of `--runs` times of the Umbra command's reported `total` (the
Boolean with its operands' regularisation, and smoothing; reading and
writing files excluded) and of its `smooth` part, the least of as many
in-process shapely calls on the same two geometries, and the area of the
symmetric difference of the two results over GEOS's result area.
"""

import argparse
import csv
import json
import os
import subprocess
import sys
import tempfile
import time

OPS = {
    "union": "union",
    "intersection": "intersection",
    "difference": "difference",
    "xor": "symmetric_difference",
}


def read_map(path):
    from shapely import unary_union
    from shapely.geometry import shape

    if path.endswith(".shp"):
        import shapefile

        geoms = [shape(s.__geo_interface__) for s in shapefile.Reader(path).shapes()]
    else:
        with open(path) as f:
            doc = json.load(f)
        geoms = [shape(feature["geometry"]) for feature in doc["features"]]
    return unary_union(geoms)


def copies(a):
    from shapely import affinity

    minx, _, maxx, _ = a.bounds
    w = maxx - minx
    return {
        "rt": affinity.rotate(affinity.translate(a, w * 0.0123, -w * 0.0071), 0.37, origin="centroid"),
        "sc": affinity.scale(a, 1.0000001, 1.0000001, origin=(0, 0)),
        "sh": affinity.translate(a, w * 1e-9, w * 3e-10),
        "rot": affinity.rotate(a, 1e-6, origin="centroid"),
    }


def write(geom, path):
    from shapely.geometry import mapping

    with open(path, "w") as f:
        json.dump({"type": "Feature", "properties": {}, "geometry": mapping(geom)}, f)


def read_result(path):
    from shapely import unary_union
    from shapely.geometry import shape

    with open(path) as f:
        doc = json.load(f)
    if doc.get("type") == "FeatureCollection":
        return unary_union([shape(x["geometry"]) for x in doc["features"]])
    if doc.get("type") == "Feature":
        return shape(doc["geometry"])
    return shape(doc)


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--umbra", default="target/release/umbra")
    p.add_argument("--nybb", help="nybb.shp from the geopandas-0.14.4 wheel")
    p.add_argument("--runs", type=int, default=3)
    p.add_argument("--csv")
    args = p.parse_args()
    maps = {"countries": "crates/test-support/data/naturalearth/countries.geojson"}
    if args.nybb:
        maps["nybb"] = args.nybb
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for name, path in maps.items():
            a = read_map(path)
            a_file = os.path.join(tmp, f"{name}_A.geojson")
            write(a, a_file)
            for copy, b in copies(a).items():
                b_file = os.path.join(tmp, f"{name}_{copy}.geojson")
                write(b, b_file)
                for op, method in OPS.items():
                    geos = min(timed(lambda: getattr(a, method)(b)) for _ in range(args.runs))
                    reference = getattr(a, method)(b)
                    out = os.path.join(tmp, "out.geojson")
                    report = os.path.join(tmp, "report.json")
                    total = smooth = float("inf")
                    for _ in range(args.runs):
                        subprocess.run(
                            [args.umbra, "boolean", op, a_file, b_file, "-o", out, "--report", report],
                            check=True,
                            capture_output=True,
                        )
                        with open(report) as f:
                            t = json.load(f)["timings_ms"]
                        total = min(total, t["total"])
                        smooth = min(smooth, t.get("smooth") or 0.0)
                    result = read_result(out)
                    differ = result.symmetric_difference(reference).area / max(reference.area, 1e-300)
                    row = {
                        "map": name,
                        "copy": copy,
                        "op": op,
                        "umbra_ms": round(total, 1),
                        "umbra_smooth_ms": round(smooth, 1),
                        "geos_ms": round(geos * 1e3, 1),
                        "umbra_over_geos": round(total / (geos * 1e3), 2),
                        "symdiff_over_area": f"{differ:.1e}",
                        "valid": result.is_valid,
                    }
                    rows.append(row)
                    print(",".join(str(v) for v in row.values()), flush=True)
    if args.csv:
        with open(args.csv, "w", newline="") as f:
            w = csv.DictWriter(f, fieldnames=list(rows[0]))
            w.writeheader()
            w.writerows(rows)


def timed(f):
    start = time.perf_counter()
    f()
    return time.perf_counter() - start


if __name__ == "__main__":
    sys.exit(main())
