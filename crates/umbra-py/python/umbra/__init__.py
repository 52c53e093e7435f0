"""Umbra: topologically robust Boolean operations on polygons and polyhedra
in plain float64 arithmetic, after the dissertation "Towards robust inexact
geometric computation".

Any input that satisfies the closure constraints (section 4.2) yields output
that satisfies them too, whatever floating-point rounding does.

3D: ``Mesh`` (numpy arrays in and out), ``boolean``, ``union_all``, ``difference_all``,
``csg`` (the JSON tree form of ``umbra csg`` as a dict), ``Mesh.from_trimesh``
and ``Mesh.to_trimesh``.

2D: ``boolean_2d``, ``boolean_2d_all`` (any number of operands) and
``simplify`` on shapely geometries (Polygon, MultiPolygon, or a
GeometryCollection of those), returned as shapely
geometries; without shapely, on the plain form: a list of polygons, each a
list of rings (exterior first, then holes), each ring an (k, 2) float64
array.

Files: ``read`` and ``write`` for every format of the command-line tool
(.obj .off .stl .ply .3mf .glb .gltf meshes; .wkt .geojson polygons; .svg
polygons written only).

Every error is an ``UmbraError`` (a ``ValueError``) with the command-line
tool's one-line message. The GIL is released while umbra computes, so
threads run operations in parallel.
"""

from __future__ import annotations

import os
import warnings
from typing import Any, Iterable, List, Optional, Union

import numpy as np

from . import _umbra
from ._umbra import Mesh, UmbraError, __version__

__all__ = [
    "Mesh",
    "UmbraError",
    "boolean",
    "boolean_2d",
    "csg",
    "read",
    "simplify",
    "smooth",
    "union_all",
    "difference_all",
    "boolean_2d_all",
    "write",
    "__version__",
]

PathLike = Union[str, bytes, "os.PathLike[str]", "os.PathLike[bytes]"]


def _shapely() -> Any:
    """The shapely module, or None when it is not installed."""
    try:
        import shapely  # type: ignore[import-untyped, unused-ignore]
    except ImportError:
        return None
    return shapely


def _is_shapely(geom: Any) -> bool:
    shapely = _shapely()
    return shapely is not None and isinstance(geom, shapely.Geometry)


def _ring(coords: Any, what: str) -> np.ndarray:
    arr = np.asarray(coords, dtype=np.float64)
    if arr.ndim != 2 or arr.shape[1] != 2:
        raise UmbraError(
            f"{what}: unsupported geometry: coordinates with Z or M values "
            "(expected 2D polygons)"
        )
    return arr


def _from_shapely(geom: Any, what: str) -> List[List[np.ndarray]]:
    """A shapely geometry in the plain form."""
    shapely = _shapely()
    if geom.is_empty:
        return []
    if geom.has_z:
        raise UmbraError(
            f"{what}: unsupported geometry: {geom.geom_type} with Z coordinates "
            "(expected 2D polygons)"
        )
    if isinstance(geom, shapely.Polygon):
        return [
            [_ring(geom.exterior.coords, what)]
            + [_ring(r.coords, what) for r in geom.interiors]
        ]
    if isinstance(geom, (shapely.MultiPolygon, shapely.GeometryCollection)):
        out: List[List[np.ndarray]] = []
        for g in geom.geoms:
            out.extend(_from_shapely(g, what))
        return out
    raise UmbraError(
        f"{what}: unsupported geometry: {geom.geom_type} "
        "(expected Polygon, MultiPolygon or a GeometryCollection of them)"
    )


def _to_shapely(polygons: List[List[np.ndarray]]) -> Any:
    """The plain form as a shapely Polygon (none or one) or MultiPolygon."""
    shapely = _shapely()
    parts = [shapely.Polygon(p[0], p[1:]) for p in polygons if p]
    if not parts:
        return shapely.Polygon()
    if len(parts) == 1:
        return parts[0]
    return shapely.MultiPolygon(parts)


def _polygons_in(geom: Any, what: str) -> Any:
    return _from_shapely(geom, what) if _is_shapely(geom) else geom


def read(path: PathLike, *, check: bool = True, keep_orientation: bool = False) -> Any:
    """Read a file by its extension.

    Meshes (.obj .off .stl .ply .3mf .glb .gltf) return a ``Mesh``; STL
    and glTF triangles are welded by exact position. With ``check=False`` an open or otherwise invalid
    mesh (or one with NaN coordinates) is read anyway, for
    ``Mesh.check()`` to report, like ``umbra check``.

    Polygons (.wkt .geojson) return a shapely geometry when shapely is
    installed, else the plain form (a list of polygons, each a list of
    (k, 2) rings). Rings are read by role (exteriors counter-clockwise,
    holes clockwise) unless ``keep_orientation``. Points and lines in a
    collection (as GEOS and shapely overlays return beside polygons) are
    skipped with a ``UserWarning``; a file of no polygon at all raises.
    A mesh file with vertices but no faces raises; one of neither is the
    empty solid.
    """
    kind, value = _umbra.read(os.fsdecode(path), check=check, keep_orientation=keep_orientation)
    if kind == "polygons" and _shapely() is not None:
        return _to_shapely(value)  # type: ignore[arg-type]
    return value


def write(
    shape: Any,
    path: PathLike,
    *,
    ascii: bool = False,
    keep_orientation: bool = False,
) -> None:
    """Write a mesh or polygons to a file of the format of its extension.

    A ``Mesh`` (or a ``trimesh.Trimesh``) goes to .obj .off .stl .ply .3mf
    .glb .gltf (STL and PLY binary unless ``ascii``; binary STL and glTF
    store float32; a .gltf carries its buffer in a data URI). Polygons
    (shapely or the plain form) go to .wkt .geojson .svg.

    Polygon formats store exteriors counter-clockwise and holes clockwise.
    A clockwise ring that lies in no exterior (an inside-out region of the
    set) has no place there: it is written as an exterior of its own, which
    readers fill, and a ``UserWarning`` says how many; pass
    ``keep_orientation=True`` to write every ring as it runs.
    """
    path = os.fsdecode(path)
    if type(shape).__name__ == "Trimesh" and hasattr(shape, "faces"):
        shape = Mesh.from_trimesh(shape)
    if isinstance(shape, Mesh):
        _umbra.write_mesh(shape, path, ascii=ascii)
    else:
        orphans = _umbra.write_polygons(
            _polygons_in(shape, "geom"), path, keep_orientation=keep_orientation
        )
        if orphans:
            warnings.warn(
                f"{path}: {orphans} hole(s) lie in no exterior (the set is "
                "inside-out there); each was written as an exterior of its own, "
                "which readers fill. Write with keep_orientation=True to keep "
                "the rings as they run.",
                UserWarning,
                stacklevel=2,
            )


def _warn_turned(turned: List[Any]) -> None:
    """Warns about operands whose facets faced inward and were turned."""
    for name, volume in turned:
        warnings.warn(
            f"{name}: the facets face inward (signed volume {volume}): turned "
            "outward; pass keep_orientation=True to use it as an inside-out solid",
            UserWarning,
            stacklevel=3,
        )


def boolean(
    a: Mesh,
    b: Mesh,
    op: str,
    *,
    triangulate: bool = False,
    smooth: Optional[float] = None,
    keep_orientation: bool = False,
) -> Mesh:
    """The 3D Boolean ``op`` ("union", "intersection" or "difference").

    The result is always topologically valid. ``triangulate=True`` runs the
    triangle-mesh variant (section 4.8): operands are triangulated by
    internal edges first, and the result is triangles. ``smooth=T`` smooths
    the result at tolerance ``T`` (Appendix A: vertices closer than ``T``
    merge, slivers, gaps and coincident opposing facets go); ``None`` or 0
    returns the basic Boolean's raw output. Both operands must be valid
    (``Mesh.is_valid()``); otherwise ``UmbraError`` names the operand and
    the violated constraint.

    An operand whose facets face inward (negative ``volume()``, as some
    exporters write solids) is turned outward with a ``UserWarning``, as
    ``umbra boolean`` does; ``keep_orientation=True`` uses it as written,
    an inside-out solid (section 4.7).
    """
    out, turned = _umbra.boolean(
        a, b, op, triangulate=triangulate, smooth=smooth, keep_orientation=keep_orientation
    )
    _warn_turned(turned)
    return out


def smooth(mesh: Mesh, tolerance: Optional[float] = None) -> Mesh:
    """The mesh smoothed (Appendix A) at ``tolerance``.

    By default ``tolerance`` is 1e-9 times the largest extent of the mesh's
    bounding box, the rule of ``umbra smooth``. A triangle mesh stays a
    triangle mesh; every vertex moves by at most a small multiple of the
    tolerance.
    """
    return _umbra.smooth(mesh, tolerance)


def union_all(
    meshes: Iterable[Mesh], *, triangulate: bool = False, keep_orientation: bool = False
) -> Mesh:
    """The union of every mesh, as a balanced tree of binary Booleans.

    Meshes whose facets face inward are turned outward with a
    ``UserWarning`` unless ``keep_orientation`` (see ``boolean``).
    """
    out, turned = _umbra.union_all(
        list(meshes), triangulate=triangulate, keep_orientation=keep_orientation
    )
    _warn_turned(turned)
    return out


def difference_all(
    a: Mesh,
    others: Iterable[Mesh],
    *,
    triangulate: bool = False,
    keep_orientation: bool = False,
) -> Mesh:
    """``a`` minus every mesh of ``others`` in one call.

    ``a`` minus the balanced union of the others (independent branches run
    in parallel; the result is the same whatever the thread count); ``a``
    itself when ``others`` is empty. Meshes whose facets face inward are
    turned outward with a ``UserWarning`` unless ``keep_orientation`` (see
    ``boolean``).
    """
    out, turned = _umbra.difference_all(
        a, list(others), triangulate=triangulate, keep_orientation=keep_orientation
    )
    _warn_turned(turned)
    return out


def csg(tree: dict, *, triangulate: bool = False, smooth: float | None = None) -> Mesh:
    """The mesh of a CSG tree in the JSON form of ``umbra csg``, as a dict.

    Example: ``{"op": "difference", "children": [{"box": {"size": [2, 2, 2],
    "center": True}}, {"cylinder": {"radius": 0.5, "height": 3, "center":
    True}}]}``. Leaves: box, sphere, cylinder, torus, file (relative to the
    working directory); any node may carry translate, rotate (degrees) and
    scale. Independent branches run in parallel. ``smooth=T`` smooths the
    result at tolerance ``T`` near where the Booleans' operands met (as
    ``umbra csg --smooth T``); by default the raw result is returned.
    """
    return _umbra.csg(tree, triangulate=triangulate, smooth=smooth)


def boolean_2d(
    a: Any,
    b: Any,
    op: str,
    *,
    via: str = "basic",
    keep_orientation: bool = False,
    smooth: Optional[float] = None,
) -> Any:
    """The 2D Boolean ``op`` ("union", "intersection", "difference", "xor").

    ``via="basic"`` is the basic Boolean of chapter 4 (tolerant of
    self-intersecting and inside-out operands); ``via="simplify"`` assembles
    both boundaries and simplifies them (chapter 6), which resolves
    self-intersections. Operands are shapely geometries or the plain form;
    the result is a shapely Polygon or MultiPolygon when ``a`` or ``b`` is a
    shapely geometry, else the plain form. Rings are read by role unless
    ``keep_orientation`` (then every ring is a directed loop as written and
    every output loop is its own polygon in the plain form; shapely results
    are always laid out by role, as shapely has no ring direction).

    Operands read by role are taken as sets in both algorithms: an invalid
    geometry's overlapping parts, overlapping holes or holes outside their
    shell mean what ``shapely.make_valid`` makes of them (``via="basic"``
    first simplifies each operand by the positive rule; a valid operand
    comes through unchanged). A self-intersecting ring is read as drawn
    and oriented by its signed area, so only its larger lobe is inside
    (as GEOS's ``buffer(0)`` keeps it); use ``simplify(geom, "nonzero",
    keep_orientation=True)`` to keep every lobe.

    The result is smoothed (Appendix A) at ``smooth``, by default (None) at
    1e-9 times the operands' largest extent, as ``umbra boolean`` does:
    where operands share boundary the raw output can hold zero-width
    features (an edge running back over another) that make rings GEOS,
    and so shapely, calls invalid. ``smooth=0`` returns the raw output,
    and so does ``keep_orientation=True`` unless ``smooth`` is given (its
    winding numbers are the result, which smoothing does not keep).
    """
    # shapely has no ring direction: its results are laid out by role (a
    # hole as a polygon of its own would be filled).
    to_shapely = _is_shapely(a) or _is_shapely(b)
    out = _umbra.boolean_2d(
        _polygons_in(a, "a"),
        _polygons_in(b, "b"),
        op,
        via=via,
        keep_orientation=keep_orientation,
        smooth=smooth,
        layout_by_role=to_shapely,
    )
    return _to_shapely(out) if to_shapely else out


def boolean_2d_all(
    geoms: Iterable[Any],
    op: str = "union",
    *,
    keep_orientation: bool = False,
    smooth: Optional[float] = None,
) -> Any:
    """The 2D Boolean ``op`` of any number of geometries, in one sweep.

    Union and intersection take every geometry, "difference" is the first
    minus all the others and "xor" keeps what an odd number of them cover;
    a point is inside a geometry where its winding number is positive
    (section 6.1, through simplification: self-intersecting operands are
    resolved as ``boolean_2d(..., via="simplify")`` resolves them, and for
    two geometries the selection is the same). Operands are shapely
    geometries or the plain form; the result is shapely when any operand
    is. Rings are read by role unless ``keep_orientation``; the result is
    smoothed as ``boolean_2d`` smooths it (``smooth=0`` for the raw
    output). No geometries give the empty result.
    """
    geoms = list(geoms)
    to_shapely = any(_is_shapely(g) for g in geoms)
    out = _umbra.boolean_2d_all(
        [_polygons_in(g, f"geoms[{i}]") for i, g in enumerate(geoms)],
        op,
        keep_orientation=keep_orientation,
        smooth=smooth,
        layout_by_role=to_shapely,
    )
    return _to_shapely(out) if to_shapely else out


def simplify(geom: Any, rule: str = "positive", *, keep_orientation: bool = False) -> Any:
    """Simplify a polygon set by a winding-number fill rule (chapters 6-7).

    ``rule`` is "positive" (winding number > 0), "nonzero", "evenodd",
    "negative" or "at-least-2". The result has no crossing edges (up to the
    epsilon of section 8.4) and is returned in the input's kind (shapely or
    the plain form). Winding rules other than "positive" mostly make sense
    with ``keep_orientation=True``, where rings keep their direction.
    """
    to_shapely = _is_shapely(geom)
    out = _umbra.simplify(
        _polygons_in(geom, "geom"),
        rule,
        keep_orientation=keep_orientation,
        layout_by_role=to_shapely,
    )
    return _to_shapely(out) if to_shapely else out
