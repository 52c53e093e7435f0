"""The GIL is released during operations: Python keeps running beside a
Boolean, and two threads run two Booleans on two cores in about the time
of one."""

import os
import subprocess
import sys
import threading
import time

import pytest

import umbra

SPHERES = """
import umbra
a = umbra.csg({"sphere": {"radius": 1, "segments": %(segments)d}})
b = umbra.csg({"sphere": {"radius": 1, "segments": %(segments)d}, "translate": [0.3, 0.2, 0.1]})
"""


def spheres(segments):
    scope = {}
    exec(SPHERES % {"segments": segments}, scope)
    return scope["a"], scope["b"]


def test_python_runs_beside_a_boolean():
    a, b = spheres(256)
    start = time.perf_counter()
    umbra.boolean(a, b, "difference")
    alone = time.perf_counter() - start
    worker = threading.Thread(target=umbra.boolean, args=(a, b, "difference"))
    gaps = []
    last = time.perf_counter()
    worker.start()
    while worker.is_alive():
        now = time.perf_counter()
        gaps.append(now - last)
        last = now
    worker.join()
    # Holding the GIL, the worker would stop this loop for the whole
    # Boolean; released, the loop only waits for the interpreter's switch
    # interval (5 ms) now and then.
    assert len(gaps) > 100
    assert max(gaps) < max(alone / 2, 0.05), (max(gaps), alone)


# Two Booleans one after the other, then on two threads at once, with one
# rayon thread per Boolean so each takes one core: the best ratio of
# several tries (the machine may be busy with other work).
TIMING = (
    SPHERES
    + """
import threading, time
def two_in_sequence():
    t = time.perf_counter()
    umbra.boolean(a, b, "difference"); umbra.boolean(b, a, "union")
    return time.perf_counter() - t
def two_in_threads():
    ts = [threading.Thread(target=umbra.boolean, args=(a, b, "difference")),
          threading.Thread(target=umbra.boolean, args=(b, a, "union"))]
    t = time.perf_counter()
    for x in ts: x.start()
    for x in ts: x.join()
    return time.perf_counter() - t
two_in_sequence()
best = min(two_in_threads() / two_in_sequence() for _ in range(5))
print(best)
"""
)


def test_two_booleans_run_at_the_same_time():
    # Whatever the load of the machine: with the GIL held, the second
    # thread could not even enter its call until the first one returned,
    # so the two calls would not overlap in time.
    a, b = spheres(256)
    spans = {}

    def timed(name, x, y, op):
        start = time.perf_counter()
        umbra.boolean(x, y, op)
        spans[name] = (start, time.perf_counter())

    ts = [
        threading.Thread(target=timed, args=("first", a, b, "difference")),
        threading.Thread(target=timed, args=("second", b, a, "union")),
    ]
    for t in ts:
        t.start()
    for t in ts:
        t.join()
    (s1, e1), (s2, e2) = spans["first"], spans["second"]
    overlap = min(e1, e2) - max(s1, s2)
    assert overlap > 0.5 * min(e1 - s1, e2 - s2), spans


@pytest.mark.skipif((os.cpu_count() or 1) < 2, reason="needs two cores")
def test_two_threads_take_about_the_time_of_one():
    env = dict(os.environ, RAYON_NUM_THREADS="1")
    out = subprocess.run(
        [sys.executable, "-c", TIMING % {"segments": 192}],
        env=env,
        capture_output=True,
        text=True,
        check=True,
        timeout=300,
    )
    ratio = float(out.stdout.strip().splitlines()[-1])
    # 0.5 on two idle cores, 1.0 if the Booleans ran one at a time. On a
    # machine busy with other work (load average at or above the number of
    # cores) the second core is not ours to measure: then only a clear
    # pass counts, and a miss is a skip, not a failure.
    if ratio >= 0.8 and os.getloadavg()[0] >= (os.cpu_count() or 1) - 0.5:
        pytest.skip(f"the machine is busy (load {os.getloadavg()[0]:.1f}): ratio {ratio:.2f}")
    assert ratio < 0.8, ratio


# A Boolean in the parent, then Booleans in children forked from it (as
# multiprocessing does on Linux): a child inherits the parent's pool
# without its worker threads, and an operation on it would wait forever.
FORKED = (
    SPHERES
    + """
import multiprocessing, sys
def volume(op):
    return umbra.boolean(a, b, op).volume()
want = [volume(op) for op in ("union", "difference")]
with multiprocessing.get_context("fork").Pool(2) as pool:
    got = pool.map(volume, ["union", "difference"])
assert got == want, (got, want)
print("ok")
"""
)


@pytest.mark.skipif(not hasattr(os, "fork"), reason="needs fork")
@pytest.mark.parametrize("threads", ["1", "2"])
def test_booleans_run_in_forked_children(threads):
    env = dict(os.environ, RAYON_NUM_THREADS=threads)
    out = subprocess.run(
        [sys.executable, "-c", FORKED % {"segments": 32}],
        env=env,
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert out.returncode == 0 and out.stdout.strip() == "ok", out.stderr
