"""Equality with the command-line tool: the same inputs through `umbra`
and through the package give the same bytes (the same writers, so any
difference is a difference of the results) and the same check report."""

import json
import subprocess

import pytest

import umbra
from conftest import REPO, cube

EXAMPLES = REPO / "examples"


def run(cli, *args):
    return subprocess.run([cli, *args], capture_output=True, text=True, timeout=120)


@pytest.mark.parametrize("op", ["union", "intersection", "difference"])
@pytest.mark.parametrize("triangulate", [False, True])
@pytest.mark.parametrize("smooth", [None, 1e-6])
def test_3d_boolean_equals_the_cli(cli, tmp_path, op, triangulate, smooth):
    # The CLI smooths 3D results by default; the library only when asked:
    # `--smooth 0` is the raw result, `--smooth T` is `smooth=T`.
    a, b = EXAMPLES / "cube.obj", EXAMPLES / "cube_shifted.off"
    out = tmp_path / "cli.obj"
    flags = ["--triangulate"] if triangulate else []
    flags += ["--smooth", str(smooth or 0)]
    r = run(cli, "boolean", op, str(a), str(b), "-o", str(out), *flags)
    assert r.returncode == 0, r.stderr
    mine = tmp_path / "py.obj"
    result = umbra.boolean(
        umbra.read(a), umbra.read(b), op, triangulate=triangulate, smooth=smooth
    )
    umbra.write(result, mine)
    assert mine.read_bytes() == out.read_bytes()


@pytest.mark.parametrize("op", ["union", "xor"])
@pytest.mark.parametrize("via", ["basic", "simplify"])
def test_2d_boolean_equals_the_cli(cli, tmp_path, monkeypatch, op, via):
    monkeypatch.setattr(umbra, "_shapely", lambda: None)
    a, b = EXAMPLES / "a.wkt", EXAMPLES / "b.wkt"
    out = tmp_path / "cli.wkt"
    r = run(cli, "boolean", op, str(a), str(b), "-o", str(out), "--via", via)
    assert r.returncode == 0, r.stderr
    mine = tmp_path / "py.wkt"
    umbra.write(umbra.boolean_2d(umbra.read(a), umbra.read(b), op, via=via), mine)
    assert mine.read_bytes() == out.read_bytes()


def test_simplify_equals_the_cli(cli, tmp_path, monkeypatch):
    monkeypatch.setattr(umbra, "_shapely", lambda: None)
    src = EXAMPLES / "figure_eight.wkt"
    out = tmp_path / "cli.wkt"
    r = run(cli, "simplify", str(src), "-o", str(out), "--rule", "nonzero", "--keep-orientation")
    assert r.returncode == 0, r.stderr
    mine = tmp_path / "py.wkt"
    simple = umbra.simplify(umbra.read(src, keep_orientation=True), "nonzero", keep_orientation=True)
    umbra.write(simple, mine, keep_orientation=True)
    assert mine.read_bytes() == out.read_bytes()


def test_csg_equals_the_cli(cli, tmp_path):
    script = EXAMPLES / "bracket.json"
    out = tmp_path / "cli.obj"
    r = run(cli, "csg", str(script), "-o", str(out), "--quiet")
    assert r.returncode == 0, r.stderr
    mine = tmp_path / "py.obj"
    umbra.write(umbra.csg(json.loads(script.read_text())), mine)
    assert mine.read_bytes() == out.read_bytes()


@pytest.mark.parametrize("triangulate", [False, True])
@pytest.mark.parametrize("smooth", [2e-9, 5e-2])
def test_csg_smooth_equals_the_cli(cli, tmp_path, triangulate, smooth):
    # `smooth=T` smooths near the tree's contacts as `umbra csg --smooth T`
    # does (at 5e-2 the pipe tee's vertices do merge).
    script = EXAMPLES / "pipe_tee.json"
    out = tmp_path / "cli.obj"
    flags = ["--triangulate"] if triangulate else []
    r = run(cli, "csg", str(script), "-o", str(out), "--quiet", "--smooth", str(smooth), *flags)
    assert r.returncode == 0, r.stderr
    mine = tmp_path / "py.obj"
    tree = json.loads(script.read_text())
    umbra.write(umbra.csg(tree, triangulate=triangulate, smooth=smooth), mine)
    assert mine.read_bytes() == out.read_bytes()
    with pytest.raises(umbra.UmbraError, match="tolerance"):
        umbra.csg(tree, smooth=-1.0)


@pytest.mark.parametrize("valid", [True, False])
def test_check_equals_the_cli(cli, tmp_path, valid):
    c = cube((0.25, 0.5, 0.125), 2.0)
    m = c if valid else umbra.Mesh(c.vertices, c.faces[:-1])
    path = tmp_path / "m.obj"
    umbra.write(m, path)
    r = run(cli, "check", str(path), "--json")
    assert r.returncode == (0 if valid else 1), r.stderr
    report = json.loads(r.stdout)
    assert report.pop("file") == str(path)
    mine = m.check()
    if not valid:
        # The same first problem, on one line; the command line names it
        # in the file's terms (OBJ's 1-based vertices and their lines),
        # the package in the mesh's (0-based, as its arrays).
        assert report["topology_error"] in r.stderr
        assert "(line " in report["topology_error"]
        assert "closure" in report["topology_error"] and "closure" in mine["topology_error"]
        report.pop("topology_error")
        mine.pop("topology_error")
    assert report == mine
