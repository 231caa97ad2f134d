"""genbsp: binary space partitioning for exact geometric computing.

Exact visibility maps of polygon scenes, drawings with hidden parts removed,
and Boolean operations on polygons in the plane, on the sphere and on
polyhedra.  Every number that goes in is read exactly: a Python ``float`` as
the double it is, an ``int``, a ``fractions.Fraction``, a ``decimal.Decimal``
or a string such as ``"0.1"`` or ``"1/3"`` as the number it writes.  Exact
results (areas, volumes) come back as ``Fraction``.

Bad input raises ``ValueError`` with the library's one-line message; a file
that cannot be opened raises ``OSError`` (``FileNotFoundError`` when it does
not exist).  Long computations release the GIL.

See docs/python.md for a tour.
"""

from __future__ import annotations

import decimal
import json
import numbers
import os
import tempfile
from dataclasses import dataclass, field
from fractions import Fraction
from typing import Any, Iterable, Mapping, NamedTuple, Sequence

import numpy as np

from . import _genbsp

__all__ = [
    "Scene",
    "VisibilityMap",
    "Boolean2D",
    "BooleanS2",
    "CsgResult",
    "Visibility2D",
    "visibility2d",
    "BatchResult",
    "boolean2d",
    "boolean_s2",
    "csg",
    "batch",
    "__version__",
]

#: The library's version and source revision, as ``genbsp --version`` prints it.
__version__: str = _genbsp.version


def _exact_text(x: Any, what: str) -> str:
    """A number as text that the library reads exactly."""
    if isinstance(x, bool):
        raise ValueError(f"{what}: expected a number, got a bool")
    if isinstance(x, str):
        return x.strip()
    if isinstance(x, numbers.Integral):
        return str(int(x))
    if isinstance(x, Fraction):
        return f"{x.numerator}/{x.denominator}"
    if isinstance(x, decimal.Decimal):
        if not x.is_finite():
            raise ValueError(f"{what}: numbers must be finite")
        return str(x)
    if isinstance(x, numbers.Real):
        f = float(x)
        if f != f or f in (float("inf"), float("-inf")):
            raise ValueError(f"{what}: numbers must be finite")
        q = Fraction(f)
        return f"{q.numerator}/{q.denominator}"
    raise ValueError(f"{what}: expected a number, got {type(x).__name__}")


def _fraction(text: str) -> Fraction:
    return Fraction(text)


def _triple(v: Any, what: str) -> list[str]:
    items = list(v)
    if len(items) != 3:
        raise ValueError(f"{what}: expected three numbers, got {len(items)}")
    return [_exact_text(c, what) for c in items]


#: Options whose numbers the library reads exactly (points and directions):
#: a float among them is passed as the exact double it is.  Other numbers
#: (``fov``, ``crease`` …) are passed as their shortest decimal.
_EXACT_KEYS = frozenset({"eye", "view_dir", "up", "look", "dir", "light", "sun", "shift", "extent"})


def _plain_text(x: Any, key: str) -> str:
    if isinstance(x, bool) or not isinstance(x, (numbers.Real, str, decimal.Decimal)):
        raise ValueError(f"{key}: expected a number, got {x!r}")
    if isinstance(x, numbers.Integral):
        return str(int(x))
    return str(x) if isinstance(x, (str, decimal.Decimal)) else repr(float(x))


def _option_args(options: Mapping[str, Any]) -> list[str]:
    """Keyword options as the command line's options (``line_width=2`` → ``--line-width 2``)."""
    args: list[str] = []
    for key, value in options.items():
        flag = "--" + key.replace("_", "-")
        text = (lambda x: _exact_text(x, key)) if key in _EXACT_KEYS else (lambda x: _plain_text(x, key))
        if value is None or value is False:
            continue
        if value is True:
            args.append(flag)
        elif key in ("light", "sun"):
            points = value if len(value) and not isinstance(value[0], (numbers.Number, str)) else [value]
            for p in points:
                args += [flag, ",".join(_triple(p, key))]
        elif key == "size" and not isinstance(value, str):
            w, h = value
            args += [flag, f"{int(w)}x{int(h)}"]
        elif isinstance(value, (list, tuple, np.ndarray)):
            args += [flag, ",".join(text(c) for c in value)]
        elif isinstance(value, str):
            args += [flag, value]
        else:
            args += [flag, text(value)]
    return args


class Scene:
    """A polygon scene: faces (planar polygons) with exact vertices.

    Make one with :meth:`from_file` or :meth:`from_arrays`.  A face's index
    is its position in the file or the list; maps and queries answer with it.
    A scene is immutable, may be shared by threads, and pickles (its exact
    vertices and faces), so that it can be sent to Dask workers once.
    """

    __slots__ = ("_s",)

    def __init__(self, core: Any) -> None:
        self._s = core

    @classmethod
    def from_file(cls, path: str | os.PathLike[str]) -> "Scene":
        """Reads an OFF, OBJ or STL file (coordinates read exactly as written)."""
        return cls(_genbsp.Scene.from_file(os.fspath(path)))

    @classmethod
    def from_arrays(cls, vertices: Any, faces: Iterable[Sequence[int]]) -> "Scene":
        """A scene from vertices and faces.

        ``vertices`` is an n × 3 array of float64 (each read exactly as the
        double it is) or a sequence of triples of exact numbers (``int``,
        ``Fraction``, ``Decimal`` or strings such as ``"0.1"``).  ``faces``
        is a sequence of vertex-index sequences (or an m × k integer array),
        each a planar polygon.
        """
        face_list = [[int(i) for i in f] for f in (faces.tolist() if isinstance(faces, np.ndarray) else faces)]
        if isinstance(vertices, np.ndarray) and vertices.dtype.kind == "f":
            return cls(_genbsp.Scene.from_doubles(np.ascontiguousarray(vertices, dtype=np.float64), face_list))
        if isinstance(vertices, np.ndarray) and vertices.dtype.kind in "iu":
            vertices = vertices.tolist()
        text = [_triple(v, f"vertex {i}") for i, v in enumerate(vertices)]
        return cls(_genbsp.Scene.from_text(text, face_list))

    @property
    def name(self) -> str:
        """The file's path, or ``<scene N>`` for a scene made from arrays."""
        return self._s.name

    @property
    def num_faces(self) -> int:
        """Faces as given (including degenerate ones, which are skipped)."""
        return self._s.faces

    @property
    def num_polygons(self) -> int:
        """Convex polygons the faces became (non-convex faces are cut into triangles)."""
        return self._s.polygons

    def vertices(self) -> list[tuple[Fraction, Fraction, Fraction]]:
        """The exact vertices."""
        return [tuple(_fraction(c) for c in v) for v in self._s.exact_vertices()]  # type: ignore[misc]

    def faces(self) -> list[list[int]]:
        """The faces as vertex-index lists."""
        return self._s.face_indices()

    def visibility_map(
        self, eye: Sequence[Any], exact: bool = True, cull_backfaces: bool = False, simplify: bool = True
    ) -> "VisibilityMap":
        """The spherical visibility map of the scene seen from ``eye``.

        ``exact=False`` rounds the scene to doubles (signs are still exact
        for the rounded scene).  ``cull_backfaces`` drops faces turned away
        from the eye (closed, outward-oriented solids only); ``simplify``
        merges the faces of the map where one polygon is visible.
        """
        eye_text = _triple(eye, "eye")
        return VisibilityMap(self, self._s.visibility_map(eye_text, bool(exact), bool(cull_backfaces), bool(simplify)))

    def shadows(self, light: Sequence[Sequence[Any]] = (), sun: Sequence[Sequence[Any]] = (), exact: bool = True) -> dict[str, Any]:
        """Every face's lit and shadowed area from point lights (``light``,
        points) and lights at infinity (``sun``, directions towards them),
        computed exactly and reported in doubles, as ``genbsp shadow`` writes
        them: ``{"lights": [...], "faces": [{"face", "area", "lit_area"
        (one per light), "shadowed_area"}, ...], "stats": {...}}``."""
        args = ["shadow", self.name]
        for p in light:
            args += ["--light", ",".join(_triple(p, "light"))]
        for d in sun:
            args += ["--sun", ",".join(_triple(d, "sun"))]
        if not exact:
            args += ["--number", "double"]
        with tempfile.TemporaryDirectory(prefix="genbsp-") as tmp:
            out = os.path.join(tmp, "shadows.json")
            _genbsp.run(args + ["-o", out], self._s)
            with open(out) as f:
                return json.load(f)

    def __reduce__(self) -> Any:
        return (_scene_from_state, (self._s.exact_vertices(), self._s.face_indices(), self.name, self._s.face_colours()))

    def __repr__(self) -> str:
        return f"<genbsp.Scene {self.name!r}: {self.num_faces} faces>"


def _scene_from_state(
    vertices: list[list[str]], faces: list[list[int]], name: str, colours: list[Any] | None = None
) -> Scene:
    """A pickled scene as it was: its exact vertices, faces, colours and name."""
    return Scene(_genbsp.Scene.from_text([list(v) for v in vertices], faces, colours or [], name))


class VisibilityMap:
    """The exact map of what the eye sees in every direction, as a
    doubly-connected edge list on the sphere of directions.

    ``faces[f]`` is the input face visible in face ``f`` of the map, or -1
    where nothing is.  ``half_edges`` has one row per half-edge: origin
    vertex, twin, next, prev and the face on its left; the boundary of a
    face turns counter-clockwise seen from outside the sphere.
    """

    __slots__ = ("scene", "_m", "_arrays")

    def __init__(self, scene: Scene, core: Any) -> None:
        self.scene = scene
        self._m = core
        self._arrays: dict[str, np.ndarray] | None = None

    def _array(self, name: str) -> np.ndarray:
        if self._arrays is None:
            self._arrays = self._m.arrays()
            for a in self._arrays.values():
                a.setflags(write=False)
        return self._arrays[name]

    @property
    def eye(self) -> tuple[Fraction, Fraction, Fraction]:
        """The eye, exactly."""
        return tuple(_fraction(c) for c in self._m.eye)  # type: ignore[return-value]

    @property
    def exact(self) -> bool:
        return self._m.exact

    @property
    def vertices(self) -> np.ndarray:
        """The map's vertices as unit vectors (V × 3, float64, rounded for output)."""
        return self._array("vertices")

    @property
    def half_edges(self) -> np.ndarray:
        """H × 5 int64: origin, twin, next, prev, face."""
        return self._array("half_edges")

    @property
    def edges(self) -> np.ndarray:
        """E × 2 int64: the two end vertices of each edge (one row per pair of twins)."""
        h = self.half_edges
        return np.stack([h[0::2, 0], h[1::2, 0]], axis=1)

    @property
    def faces(self) -> np.ndarray:
        """F int64: the input face visible in each face of the map, or -1."""
        return self._array("faces")

    def locate(self, directions: Any) -> Any:
        """The input face visible in each direction, or -1.

        ``directions`` is an n × 3 array (each row read exactly as its
        doubles); the answer is an int64 array of n.  A single direction
        (three numbers) gives an ``int``.
        """
        d = np.asarray(directions, dtype=np.float64)
        if d.shape == (3,):
            return int(self._m.locate(d.reshape(1, 3))[0])
        return self._m.locate(np.ascontiguousarray(d))

    def faces_of(self, polygon: int) -> list[int]:
        """The faces of the map where input face ``polygon`` is visible."""
        return self._m.faces_of(int(polygon))

    def neighbours(self, face: int) -> list[int]:
        """The faces of the map that share an edge with ``face``."""
        return self._m.neighbours(int(face))

    def visible_polygons(self) -> list[int]:
        """The input faces visible somewhere, in increasing order."""
        return self._m.visible_polygons()

    @property
    def stats(self) -> dict[str, Any]:
        """Sizes and times of the build."""
        return self._m.stats()

    def to_json(self) -> str:
        """MAP.json, as ``genbsp map`` writes it (docs/map-format.md)."""
        return self._m.to_json()

    def _view_args(self) -> list[str]:
        args = ["--eye", ",".join(self._m.eye)]
        if not self._m.exact:
            args += ["--number", "double"]
        if self._m.cull_backfaces:
            args.append("--cull-backfaces")
        if not self._m.simplify:
            args.append("--no-simplify")
        return args

    def render(self, path: str | os.PathLike[str] | None = None, format: str = "svg", **options: Any) -> Any:
        """Draws the scene from the eye, hidden parts removed exactly.

        The options are those of ``genbsp render`` in Python spelling:
        ``look``, ``dir``, ``up``, ``fov``, ``size=(w, h)``, ``projection``,
        ``style`` (``shaded``, ``flat``, ``lines``, ``id``), ``hidden``,
        ``light=[...]``, ``sun=[...]``, ``shadows=True``, ``crease`` …
        With ``path`` the drawing is written there (format from its
        extension) and the summary of a line drawing is returned (else
        ``None``); without, the drawing is returned: ``str`` for SVG,
        ``bytes`` for ``"pdf"``, ``"eps"`` and ``"png"``.  The map drawn is
        built for the camera's window.
        """
        for k in ("eye", "number", "cull_backfaces", "no_simplify", "output", "o"):
            if k in options:
                raise ValueError(f"render: {k} is set by the map (or by path)")
        args = ["render", self.scene.name, *self._view_args(), *_option_args(options)]
        if path is not None:
            status, text = _genbsp.run(args + ["-o", os.fspath(path)], self.scene._s)
            return json.loads(text) if text.strip() else None
        if options.get("projection") == "cube" or options.get("split_layers"):
            raise ValueError("render: a cube map or split layers write several files; give path")
        if format not in ("svg", "pdf", "eps", "png"):
            raise ValueError(f"render: format is svg, pdf, eps or png, not {format!r}")
        with tempfile.TemporaryDirectory(prefix="genbsp-") as tmp:
            out = os.path.join(tmp, "drawing." + format)
            _genbsp.run(args + ["-o", out], self.scene._s)
            with open(out, "rb") as f:
                data = f.read()
        return data.decode("utf-8") if format == "svg" else data

    def __repr__(self) -> str:
        return f"<genbsp.VisibilityMap from {self._m.eye}: {len(self.faces)} faces>"


def _operand(x: Any, what: str) -> str:
    """WKT or GeoJSON text, or polygons as arrays of rings, as text."""
    if isinstance(x, str):
        return x
    if isinstance(x, np.ndarray) and x.ndim == 2:
        polygons = [[x]]
    else:
        polygons = list(x)
        # One polygon given as a list of rings of points: [[(x, y), ...], ...]
        if polygons and _depth(polygons) == 3:
            polygons = [polygons]
    parts = []
    for p in polygons:
        rings = []
        for r in p:
            pts = [f"{_exact_text(q[0], what)} {_exact_text(q[1], what)}" for q in r]
            if pts and pts[0] != pts[-1]:
                pts.append(pts[0])
            rings.append("(" + ", ".join(pts) + ")")
        parts.append("(" + ", ".join(rings) + ")")
    return "MULTIPOLYGON(" + ", ".join(parts) + ")" if parts else "MULTIPOLYGON EMPTY"


def _depth(x: Any) -> int:
    d = 0
    while isinstance(x, (list, tuple, np.ndarray)) and len(x):
        x = x[0]
        d += 1
    return d


@dataclass(frozen=True)
class Boolean2D:
    """A planar Boolean result: WKT, GeoJSON, the exact area, and each
    polygon's rings (outer first) as k × 2 float64 arrays."""

    wkt: str
    geojson: str
    area: Fraction
    polygons: list[list[np.ndarray]] = field(repr=False)


def boolean2d(a: Any, b: Any, op: str, fill_rule: str | None = None) -> Boolean2D:
    """A Boolean operation on two sets of polygons in the plane.

    ``a`` and ``b`` are WKT or GeoJSON text, or polygons as rings: a k × 2
    array (one ring), a list of rings (one polygon, outer ring first, then
    holes) or a list of such polygons; coordinates are read exactly.
    ``op`` is ``union``, ``intersection``, ``difference`` (a minus b) or
    ``xor``.  ``fill_rule`` (``evenodd``, ``nonzero``, ``positive``,
    ``negative``) reads every ring as a closed path that may cross itself.
    """
    r = _genbsp.boolean2d(_operand(a, "a"), _operand(b, "b"), op, fill_rule)
    polys = [[np.asarray(ring, dtype=np.float64).reshape(-1, 2) for ring in p] for p in r["polygons"]]
    return Boolean2D(r["wkt"], r["geojson"], _fraction(r["area"]), polys)


@dataclass(frozen=True)
class BooleanS2:
    """A Boolean result on the sphere: WKT and GeoJSON in longitude and
    latitude (degrees), its area in steradians and in km² on a sphere of the
    Earth's mean radius."""

    wkt: str
    geojson: str
    area: float
    area_km2: float


def boolean_s2(a: Any, b: Any, op: str) -> BooleanS2:
    """A Boolean operation on two sets of spherical polygons: longitude,
    latitude positions in degrees, great-circle edges, each ring's region
    on its left (RFC 7946).  ``a`` and ``b`` are WKT or GeoJSON text, or
    rings as for :func:`boolean2d`."""
    r = _genbsp.boolean_s2(_operand(a, "a"), _operand(b, "b"), op)
    return BooleanS2(r["wkt"], r["geojson"], r["area"], r["area_km2"])


@dataclass(frozen=True)
class Visibility2D:
    """A 2D visibility polygon: WKT, GeoJSON (each boundary piece naming its
    wall), the exact area and whether the view was bounded by walls."""

    wkt: str
    geojson: str
    area: Fraction
    bounded: bool


def visibility2d(walls: Any, eye: Sequence[Any], box: Sequence[Any] | None = None) -> Visibility2D:
    """The part of the plane the point ``eye`` sees among opaque walls,
    exactly.  ``walls`` is WKT or GeoJSON text (polygons with holes and line
    strings; every edge is a wall) or polygons as rings, as for
    :func:`boolean2d`.  ``box`` (x0, y0, x1, y1) bounds an unbounded view."""
    text = _operand(walls, "walls")
    e = [_exact_text(c, "eye") for c in eye]
    if len(e) != 2:
        raise ValueError(f"eye: expected two numbers, got {len(e)}")
    args = ["--eye", ",".join(e)]
    if box is not None:
        args += ["--box", ",".join(_exact_text(c, "box") for c in box)]
    ext = ".geojson" if text.lstrip().startswith("{") else ".wkt"
    with tempfile.TemporaryDirectory(prefix="genbsp-") as tmp:
        src, wkt, gj = (os.path.join(tmp, n) for n in ("walls" + ext, "seen.wkt", "seen.geojson"))
        with open(src, "w") as f:
            f.write(text)
        _, summary = _genbsp.run(["visibility2d", src, *args, "-o", wkt])
        _genbsp.run(["visibility2d", src, *args, "-o", gj])
        with open(wkt) as f, open(gj) as g:
            w, j = f.read(), g.read()
    s = json.loads(summary)
    return Visibility2D(w, j, _fraction(s["area_exact"]), bool(s.get("bounded", True)))


@dataclass(frozen=True)
class CsgResult:
    """A CSG result: vertices (float64, rounded for output), faces, the exact
    volume, whether the mesh is closed, and the exact vertices."""

    vertices: np.ndarray = field(repr=False)
    faces: list[list[int]] = field(repr=False)
    volume: Fraction
    closed: bool
    exact_vertices: list[tuple[Fraction, Fraction, Fraction]] = field(repr=False)


def _solid(x: Any) -> Any:
    if isinstance(x, Scene):
        return x._s
    if isinstance(x, (str, os.PathLike)):
        return _genbsp.Scene.from_file(os.fspath(x))
    if isinstance(x, tuple) and len(x) == 2:
        return Scene.from_arrays(*x)._s
    raise ValueError("csg: a solid is a Scene, a mesh file's path or a (vertices, faces) pair")


def csg(a: Any, b: Any, op: str) -> CsgResult:
    """A Boolean operation on two closed polyhedra (``union``,
    ``intersection`` or ``difference``): each a :class:`Scene`, a mesh
    file's path or a ``(vertices, faces)`` pair, closed and consistently
    oriented."""
    r = _genbsp.csg(_solid(a), _solid(b), op)
    exact = [tuple(_fraction(c) for c in v) for v in r["exact_vertices"]]
    return CsgResult(r["vertices"], r["faces"], _fraction(r["volume"]), r["closed"], exact)  # type: ignore[arg-type]


class BatchResult(NamedTuple):
    """What :func:`batch` returns: one result per job (in job order) and the summary."""

    jobs: list[dict[str, Any]]
    summary: dict[str, Any]


def batch(
    scene: Scene | str | os.PathLike[str],
    jobs: Sequence[Mapping[str, Any]],
    workers: int | None = None,
    shard: tuple[int, int] | None = None,
    progress: bool = False,
) -> BatchResult:
    """Runs many jobs on one scene, on ``workers`` threads (default: one per core).

    Each job is a dict as in a ``genbsp batch`` manifest: ``eye`` (or
    ``view_dir``), and any of ``stats: True``, ``map: PATH`` and
    ``render: {...}`` (the options of ``genbsp render`` with ``output``),
    with ``id``, ``number``, ``cull_backfaces`` and ``simplify``.  Points
    and directions are read exactly, as everywhere in this package (a float
    as the double it is).  Relative paths are from the current directory.  ``shard=(i,
    n)`` runs only the jobs whose index is i modulo n.  A failed job has
    ``ok: False`` and its error; it does not stop the others.
    """
    s = scene if isinstance(scene, Scene) else Scene.from_file(scene)
    i, n = shard if shard is not None else (0, 1)
    if not (0 <= i < n):
        raise ValueError(f"shard: expected 0 <= i < n, got {i}/{n}")
    text = json.dumps([_json_job(j) for j in jobs])
    lines, summary = _genbsp.batch(s._s, text, os.getcwd(), int(workers or 0), i, n, bool(progress))
    return BatchResult([json.loads(l) for l in lines], json.loads(summary))


def _json_job(job: Mapping[str, Any]) -> dict[str, Any]:
    """A job as JSON: numbers of points and directions (``_EXACT_KEYS``)
    exactly as given (a float as its double, a Fraction as p/q), the rest
    as JSON values."""

    def convert(v: Any, exact: bool) -> Any:
        if isinstance(v, Mapping):
            return {k: convert(x, k in _EXACT_KEYS) for k, x in v.items()}
        if isinstance(v, (list, tuple, np.ndarray)):
            return [convert(x, exact) for x in v]
        if isinstance(v, os.PathLike):
            return os.fspath(v)
        if isinstance(v, bool) or isinstance(v, str) or v is None:
            return v
        if isinstance(v, numbers.Integral):
            return int(v)
        if exact and isinstance(v, (numbers.Real, decimal.Decimal)):
            return _exact_text(v, "job")
        if isinstance(v, (Fraction, decimal.Decimal)):
            return _exact_text(v, "job")
        if isinstance(v, numbers.Real):
            return float(v)
        return v

    return convert(job, False)
