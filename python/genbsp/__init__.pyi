# Type stubs of the package genbsp (the docstrings are in __init__.py).
import os
from fractions import Fraction
from typing import Any, Iterable, Mapping, NamedTuple, Sequence

import numpy as np
import numpy.typing as npt

__version__: str

Number = int | float | Fraction | str | Any
Path = str | os.PathLike[str]

class Scene:
    @classmethod
    def from_file(cls, path: Path) -> Scene: ...
    @classmethod
    def from_arrays(cls, vertices: npt.ArrayLike | Sequence[Sequence[Number]], faces: Iterable[Sequence[int]] | npt.NDArray[np.integer[Any]]) -> Scene: ...
    @property
    def name(self) -> str: ...
    @property
    def num_faces(self) -> int: ...
    @property
    def num_polygons(self) -> int: ...
    def vertices(self) -> list[tuple[Fraction, Fraction, Fraction]]: ...
    def faces(self) -> list[list[int]]: ...
    def shadows(self, light: Sequence[Sequence[Number]] = ..., sun: Sequence[Sequence[Number]] = ..., exact: bool = ...) -> dict[str, Any]: ...
    def visibility_map(self, eye: Sequence[Number], exact: bool = ..., cull_backfaces: bool = ..., simplify: bool = ...) -> VisibilityMap: ...

class VisibilityMap:
    scene: Scene
    @property
    def eye(self) -> tuple[Fraction, Fraction, Fraction]: ...
    @property
    def exact(self) -> bool: ...
    @property
    def vertices(self) -> npt.NDArray[np.float64]: ...
    @property
    def half_edges(self) -> npt.NDArray[np.int64]: ...
    @property
    def edges(self) -> npt.NDArray[np.int64]: ...
    @property
    def faces(self) -> npt.NDArray[np.int64]: ...
    @property
    def stats(self) -> dict[str, Any]: ...
    def locate(self, directions: npt.ArrayLike) -> npt.NDArray[np.int64] | int: ...
    def faces_of(self, polygon: int) -> list[int]: ...
    def neighbours(self, face: int) -> list[int]: ...
    def visible_polygons(self) -> list[int]: ...
    def to_json(self) -> str: ...
    def render(self, path: Path | None = ..., format: str = ..., **options: Any) -> Any: ...

class Boolean2D:
    wkt: str
    geojson: str
    area: Fraction
    polygons: list[list[npt.NDArray[np.float64]]]

class BooleanS2:
    wkt: str
    geojson: str
    area: float
    area_km2: float

class Visibility2D:
    wkt: str
    geojson: str
    area: Fraction
    bounded: bool

def visibility2d(walls: Any, eye: Sequence[Number], box: Sequence[Number] | None = ...) -> Visibility2D: ...

class CsgResult:
    vertices: npt.NDArray[np.float64]
    faces: list[list[int]]
    volume: Fraction
    closed: bool
    exact_vertices: list[tuple[Fraction, Fraction, Fraction]]

class BatchResult(NamedTuple):
    jobs: list[dict[str, Any]]
    summary: dict[str, Any]

def boolean2d(a: Any, b: Any, op: str, fill_rule: str | None = ...) -> Boolean2D: ...
def boolean_s2(a: Any, b: Any, op: str) -> BooleanS2: ...
def csg(a: Scene | Path | tuple[Any, Any], b: Scene | Path | tuple[Any, Any], op: str) -> CsgResult: ...
def batch(
    scene: Scene | Path,
    jobs: Sequence[Mapping[str, Any]],
    workers: int | None = ...,
    shard: tuple[int, int] | None = ...,
    progress: bool = ...,
) -> BatchResult: ...
