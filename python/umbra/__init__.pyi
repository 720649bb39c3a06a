# Type stubs for the Python module umbra (PEP 484), installed beside it
# with py.typed (PEP 561): what editors and type checkers see of it.
# docs/python.md says what each function does.

import os
from typing import Any, Literal, Mapping, Sequence, Tuple, TypedDict, Union, overload

import numpy as np
import numpy.typing as npt

__version__: str
__all__: list[str]

PathLike = Union[str, bytes, os.PathLike[str], os.PathLike[bytes]]

class _HasVerticesAndFaces:
    vertices: npt.ArrayLike
    faces: npt.ArrayLike

# A mesh: a file's path, a (vertices, faces) pair of arrays, or any object
# with .vertices and .faces (trimesh, Open3D, umbra.Mesh).
MeshLike = Union[PathLike, Tuple[npt.ArrayLike, npt.ArrayLike], _HasVerticesAndFaces, "Mesh"]
Size = Tuple[int, int]
Pass = Literal["depth", "normal", "object", "shadow"]
RGBA = npt.NDArray[np.uint8]
Grey = npt.NDArray[np.uint8]
Depth = npt.NDArray[np.float32]

class InputError(ValueError): ...
class OptionError(ValueError): ...
class UmbraWarning(UserWarning): ...

class Mesh:
    vertices: npt.NDArray[np.float64]
    faces: npt.NDArray[np.uint32]
    polygon_of_face: npt.NDArray[np.uint32]
    polygons: int
    format: str
    vertex_colors: npt.NDArray[np.float32] | None
    materials: list[str]
    warnings: list[str]
    def __init__(self, fields: Mapping[str, Any]) -> None: ...

class Views(TypedDict, total=False):
    color: npt.NDArray[np.uint8]       # (N, h, w, 4), always there
    depth: npt.NDArray[np.float32]     # (N, h, w)
    normal: npt.NDArray[np.float32]    # (N, h, w, 3)
    object: npt.NDArray[np.uint8]      # (N, h, w)
    shadow: npt.NDArray[np.uint8]      # (N, h, w): light 1's
    shadows: npt.NDArray[np.uint8]     # (N, lights, h, w), where there are several lights
    cameras: dict[str, Any]            # transforms.json's content, always there

Cameras = Union[PathLike, Mapping[str, Any]]
Orbit = Literal["model", "light"]
Spread = Literal["ring", "sphere"]

class Renderer:
    def __init__(self, gl: Literal["auto", "egl", "osmesa"] = "auto") -> None: ...
    @overload
    def render(self, mesh: MeshLike, size: Size | None = None, *, mask: Literal[False] = False, depth: Literal[False] = False,
               views: None = None, views_on: Spread = "ring", cameras: None = None, passes: Sequence[Pass] = (),
               turntable: None = None, orbit: Orbit = "model", **options: Any) -> RGBA: ...
    @overload
    def render(self, mesh: MeshLike, size: Size | None = None, *, mask: Literal[True], depth: Literal[False] = False,
               views: None = None, views_on: Spread = "ring", cameras: None = None, passes: Sequence[Pass] = (),
               turntable: None = None, orbit: Orbit = "model", **options: Any) -> Tuple[RGBA, Grey]: ...
    @overload
    def render(self, mesh: MeshLike, size: Size | None = None, *, mask: Literal[False] = False, depth: Literal[True],
               views: None = None, views_on: Spread = "ring", cameras: None = None, passes: Sequence[Pass] = (),
               turntable: None = None, orbit: Orbit = "model", **options: Any) -> Tuple[RGBA, Depth]: ...
    @overload
    def render(self, mesh: MeshLike, size: Size | None = None, *, mask: Literal[True], depth: Literal[True],
               views: None = None, views_on: Spread = "ring", cameras: None = None, passes: Sequence[Pass] = (),
               turntable: None = None, orbit: Orbit = "model", **options: Any) -> Tuple[RGBA, Grey, Depth]: ...
    @overload
    def render(self, mesh: MeshLike, size: Size | None = None, *, mask: Literal[False] = False, depth: Literal[False] = False,
               views: int, views_on: Spread = "ring", cameras: None = None, passes: Sequence[Pass] | Pass = (),
               turntable: None = None, orbit: Orbit = "model", **options: Any) -> Views: ...
    @overload
    def render(self, mesh: MeshLike, size: Size | None = None, *, mask: Literal[False] = False, depth: Literal[False] = False,
               views: None = None, views_on: Spread = "ring", cameras: Cameras, passes: Sequence[Pass] | Pass = (),
               turntable: None = None, orbit: Orbit = "model", **options: Any) -> Views: ...
    @overload
    def render(self, mesh: MeshLike, size: Size | None = None, *, mask: Literal[False] = False, depth: Literal[False] = False,
               views: None = None, views_on: Spread = "ring", cameras: None = None, passes: Sequence[Pass] | Pass = (),
               turntable: int, orbit: Orbit = "model", **options: Any) -> Views: ...
    @property
    def platform(self) -> str: ...
    def close(self) -> None: ...
    def __enter__(self) -> "Renderer": ...
    def __exit__(self, *exc: object) -> None: ...

@overload
def render(mesh: MeshLike, size: Size | None = None, *, mask: Literal[False] = False, depth: Literal[False] = False,
           views: None = None, views_on: Spread = "ring", cameras: None = None, passes: Sequence[Pass] = (),
           turntable: None = None, orbit: Orbit = "model", **options: Any) -> RGBA: ...
@overload
def render(mesh: MeshLike, size: Size | None = None, *, mask: Literal[True], depth: Literal[False] = False,
           views: None = None, views_on: Spread = "ring", cameras: None = None, passes: Sequence[Pass] = (),
           turntable: None = None, orbit: Orbit = "model", **options: Any) -> Tuple[RGBA, Grey]: ...
@overload
def render(mesh: MeshLike, size: Size | None = None, *, mask: Literal[False] = False, depth: Literal[True],
           views: None = None, views_on: Spread = "ring", cameras: None = None, passes: Sequence[Pass] = (),
           turntable: None = None, orbit: Orbit = "model", **options: Any) -> Tuple[RGBA, Depth]: ...
@overload
def render(mesh: MeshLike, size: Size | None = None, *, mask: Literal[True], depth: Literal[True],
           views: None = None, views_on: Spread = "ring", cameras: None = None, passes: Sequence[Pass] = (),
           turntable: None = None, orbit: Orbit = "model", **options: Any) -> Tuple[RGBA, Grey, Depth]: ...
@overload
def render(mesh: MeshLike, size: Size | None = None, *, mask: Literal[False] = False, depth: Literal[False] = False,
           views: int, views_on: Spread = "ring", cameras: None = None, passes: Sequence[Pass] | Pass = (),
           turntable: None = None, orbit: Orbit = "model", **options: Any) -> Views: ...
@overload
def render(mesh: MeshLike, size: Size | None = None, *, mask: Literal[False] = False, depth: Literal[False] = False,
           views: None = None, views_on: Spread = "ring", cameras: Cameras, passes: Sequence[Pass] | Pass = (),
           turntable: None = None, orbit: Orbit = "model", **options: Any) -> Views: ...
@overload
def render(mesh: MeshLike, size: Size | None = None, *, mask: Literal[False] = False, depth: Literal[False] = False,
           views: None = None, views_on: Spread = "ring", cameras: None = None, passes: Sequence[Pass] | Pass = (),
           turntable: int, orbit: Orbit = "model", **options: Any) -> Views: ...

def check(mesh: MeshLike, *, time_limit: float = 60.0, picture: Size | None = None) -> dict[str, Any]: ...
def repair(mesh: MeshLike, *, max_hole_edges: int = ..., merge_tolerance: float = 0.0,
           time_limit: float = 60.0) -> Tuple[npt.NDArray[np.float64], npt.NDArray[np.uint32], dict[str, Any]]: ...
def load(path: PathLike) -> Mesh: ...
