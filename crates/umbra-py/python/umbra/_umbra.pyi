"""Type stubs of the native module of umbra (PyO3). Use the functions of
the ``umbra`` package; these are its building blocks."""

import os
from typing import Any, Iterable, List, Literal, Sequence, Tuple, Union, final

import numpy as np
import numpy.typing as npt

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
    "write_mesh",
    "write_polygons",
    "_panic_for_tests",
    "__version__",
]

__version__: str

_PathLike = Union[str, "os.PathLike[str]"]
# The plain form of 2D polygons: polygons, each a list of (k, 2) rings
# (exterior first, then holes).
_Polygons = List[List[npt.NDArray[np.float64]]]
# What Mesh.faces returns: an (m, 3) array for triangles, else one entry per
# facet (a loop, or a list of loops for a facet with holes).
_Faces = Union[npt.NDArray[np.int64], List[Union[npt.NDArray[np.int64], List[npt.NDArray[np.int64]]]]]

class UmbraError(ValueError):
    """An error of umbra, with the command-line tool's one-line message."""

@final
class Mesh:
    """A polyhedral mesh: vertices and facets, immutable."""

    def __new__(cls, vertices: npt.ArrayLike, faces: Any) -> "Mesh": ...
    @property
    def vertices(self) -> npt.NDArray[np.float64]:
        """The (n, 3) vertex positions (a copy)."""
    @property
    def faces(self) -> _Faces:
        """(m, 3) int64 for triangles, else a list of loops per facet."""
    @property
    def triangles(self) -> npt.NDArray[np.int64]:
        """The facets triangulated by internal edges: (t, 3) int64."""
    def is_valid(self) -> bool:
        """Closed facets and shape, valid coordinates."""
    def volume(self) -> float:
        """The signed volume; UmbraError for an invalid mesh."""
    def reversed(self) -> Mesh:
        """The mesh with every facet turned over (inside and outside swap)."""
    def check(self) -> dict[str, Any]:
        """The report of ``umbra check --json`` (without ``file``)."""
    def to_arrays(
        self,
    ) -> Tuple[npt.NDArray[np.float64], npt.NDArray[np.uint32], npt.NDArray[np.int64]]:
        """(vertices, half_edges (h, 2), facet_offsets (m + 1))."""
    @staticmethod
    def from_arrays(
        vertices: npt.ArrayLike, half_edges: npt.ArrayLike, facet_offsets: npt.ArrayLike
    ) -> "Mesh":
        """The mesh of ``to_arrays()``."""
    @staticmethod
    def from_trimesh(m: Any) -> "Mesh":
        """The mesh of a ``trimesh.Trimesh``."""
    def to_trimesh(self) -> Any:
        """A ``trimesh.Trimesh`` of ``vertices`` and ``triangles``."""
    def __reduce__(self) -> Tuple[Any, ...]: ...
    def __eq__(self, other: object, /) -> bool: ...

def boolean(
    a: Mesh,
    b: Mesh,
    op: Literal["union", "intersection", "difference"] | str,
    *,
    triangulate: bool = False,
    smooth: float | None = None,
    keep_orientation: bool = False,
) -> Tuple[Mesh, List[Tuple[str, float]]]: ...
def smooth(mesh: Mesh, tolerance: float | None = None) -> Mesh: ...
def union_all(
    meshes: Iterable[Mesh], *, triangulate: bool = False, keep_orientation: bool = False
) -> Tuple[Mesh, List[Tuple[str, float]]]: ...
def difference_all(
    a: Mesh,
    others: Iterable[Mesh],
    *,
    triangulate: bool = False,
    keep_orientation: bool = False,
) -> Tuple[Mesh, List[Tuple[str, float]]]: ...
def csg(
    tree: dict[str, Any], *, triangulate: bool = False, smooth: float | None = None
) -> Mesh: ...
def boolean_2d(
    a: Sequence[Sequence[npt.ArrayLike]],
    b: Sequence[Sequence[npt.ArrayLike]],
    op: str,
    *,
    via: Literal["basic", "simplify"] | str = "basic",
    keep_orientation: bool = False,
    smooth: float | None = None,
    layout_by_role: bool = False,
) -> _Polygons: ...
def boolean_2d_all(
    geoms: Iterable[Sequence[Sequence[npt.ArrayLike]]],
    op: str,
    *,
    keep_orientation: bool = False,
    smooth: float | None = None,
    layout_by_role: bool = False,
) -> _Polygons: ...
def simplify(
    geom: Sequence[Sequence[npt.ArrayLike]],
    rule: str = "positive",
    *,
    keep_orientation: bool = False,
    layout_by_role: bool = False,
) -> _Polygons: ...
def read(
    path: _PathLike, *, check: bool = True, keep_orientation: bool = False
) -> Union[Tuple[Literal["mesh"], Mesh], Tuple[Literal["polygons"], _Polygons]]: ...
def write_mesh(mesh: Mesh, path: _PathLike, *, ascii: bool = False) -> None: ...
def write_polygons(
    polygons: Sequence[Sequence[npt.ArrayLike]], path: _PathLike, *, keep_orientation: bool = False
) -> int: ...
def _panic_for_tests() -> None: ...
