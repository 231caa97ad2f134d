"""Boolean operations from Python: exact areas and volumes (Fractions)
against values computed by hand, inclusion-exclusion, and the program."""

import json
import random
from fractions import Fraction

import numpy as np
import pytest

import genbsp
from conftest import run_cli


def square(x0, y0, x1, y1):
    return [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]


def box_area(r):
    return (r[2] - r[0]) * (r[3] - r[1])


@pytest.mark.parametrize(
    "op, area", [("union", 7), ("intersection", 1), ("difference", 3), ("xor", 6)]
)
def test_two_squares(op, area):
    r = genbsp.boolean2d([square(0, 0, 2, 2)], "POLYGON((1 1, 3 1, 3 3, 1 3, 1 1))", op)
    assert r.area == area and isinstance(r.area, Fraction)
    assert r.wkt.startswith(("POLYGON", "MULTIPOLYGON"))
    assert json.loads(r.geojson)["type"] in ("Polygon", "MultiPolygon")
    # The rings as arrays: their shoelace areas (outer minus holes) add up.
    total = 0.0
    for p in r.polygons:
        for k, ring in enumerate(p):
            x, y = ring[:, 0], ring[:, 1]
            a = abs(np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1))) / 2
            total += a if k == 0 else -a
    assert abs(total - area) < 1e-12


def test_inclusion_exclusion_with_exact_fractions():
    rng = random.Random(3)
    for _ in range(40):
        # Rectangles with thirds and sevenths, often sharing edges (degenerate).
        ra = sorted(Fraction(rng.randint(0, 6), 3) for _ in range(2)) + sorted(Fraction(rng.randint(0, 6), 3) for _ in range(2))
        rb = sorted(Fraction(rng.randint(0, 14), 7) for _ in range(2)) + sorted(Fraction(rng.randint(0, 6), 3) for _ in range(2))
        a = (ra[0], ra[2], ra[1], ra[3])
        b = (rb[0], rb[2], rb[1], rb[3])
        if box_area(a) == 0 or box_area(b) == 0:
            continue
        A, B = [square(*a)], [square(*b)]
        u = genbsp.boolean2d(A, B, "union").area
        i = genbsp.boolean2d(A, B, "intersection").area
        d = genbsp.boolean2d(A, B, "difference").area
        assert u + i == box_area(a) + box_area(b)
        assert d == box_area(a) - i
        ix = max(Fraction(0), min(a[2], b[2]) - max(a[0], b[0])) * max(Fraction(0), min(a[3], b[3]) - max(a[1], b[1]))
        assert i == ix


def test_fill_rule_and_the_program(genbsp_cli, tmp_path):
    bowtie = "POLYGON((0 0, 2 2, 2 0, 0 2, 0 0))"
    sq = "POLYGON((0 0, 2 0, 2 1/2, 0 1/2, 0 0))"
    r = genbsp.boolean2d(bowtie, sq, "union", fill_rule="evenodd")
    (tmp_path / "a.wkt").write_text(bowtie)
    (tmp_path / "b.wkt").write_text(sq)
    out = run_cli(genbsp_cli, "bool", tmp_path / "a.wkt", tmp_path / "b.wkt", "--op", "union", "--fill-rule", "evenodd", "-o", tmp_path / "o.wkt")
    assert r.area == Fraction(json.loads(out.stdout)["area_exact"])
    assert r.wkt.strip() == (tmp_path / "o.wkt").read_text().strip()
    # The bow tie's two triangles (area 1 each) and the strip (area 1) overlap
    # where 0 <= y <= 1/2 under the diagonals: 2 x (integral of y dy from 0 to 1/2) = 1/4.
    assert r.area == 2 + 1 - Fraction(1, 4)


def test_spherical_octants():
    octant = "POLYGON((0 0, 90 0, 0 90, 0 0))"
    next_octant = "POLYGON((90 0, 180 0, 0 90, 90 0))"
    assert genbsp.boolean_s2(octant, octant, "intersection").area == pytest.approx(np.pi / 2, rel=1e-12)
    u = genbsp.boolean_s2(octant, next_octant, "union")
    assert u.area == pytest.approx(np.pi, rel=1e-12)
    assert u.area_km2 == pytest.approx(np.pi * 6371.0088**2, rel=1e-6)
    assert genbsp.boolean_s2(octant, next_octant, "intersection").area == pytest.approx(0, abs=1e-12)


def cube(x, y, z, s):
    v = [(x + s * (i & 1), y + s * (i >> 1 & 1), z + s * (i >> 2 & 1)) for i in range(8)]
    f = [[0, 2, 3, 1], [4, 5, 7, 6], [0, 1, 5, 4], [2, 6, 7, 3], [0, 4, 6, 2], [1, 3, 7, 5]]
    return v, f


@pytest.mark.parametrize("op, volume", [("union", Fraction(15, 8)), ("intersection", Fraction(1, 8)), ("difference", Fraction(7, 8))])
def test_csg_of_two_cubes(op, volume):
    h = Fraction(1, 2)
    r = genbsp.csg(cube(0, 0, 0, 1), genbsp.Scene.from_arrays(*cube(h, h, h, 1)), op)
    assert r.volume == volume and r.closed
    assert r.vertices.shape == (len(r.exact_vertices), 3)
    assert all(0 <= i < len(r.vertices) for f in r.faces for i in f)


def test_csg_of_files_equals_the_program(genbsp_cli, tmp_path):
    for name, (x, s) in (("a", (0, 2)), ("b", (1, 2))):
        v, f = cube(x, Fraction(1, 3), 0, s)
        text = f"OFF\n{len(v)} {len(f)} 0\n" + "".join(" ".join(map(str, p)) + "\n" for p in v)
        text += "".join(f"{len(q)} " + " ".join(map(str, q)) + "\n" for q in f)
        (tmp_path / f"{name}.off").write_text(text)
    r = genbsp.csg(tmp_path / "a.off", str(tmp_path / "b.off"), "union")
    out = json.loads(run_cli(genbsp_cli, "csg", tmp_path / "a.off", tmp_path / "b.off", "--op", "union", "-o", tmp_path / "u.off").stdout)
    assert r.volume == Fraction(out["volume_exact"]) == 12
    assert len(r.faces) == out["faces"]


def test_boolean_errors():
    with pytest.raises(ValueError, match="op"):
        genbsp.boolean2d("POLYGON((0 0, 1 0, 0 1, 0 0))", "POLYGON((0 0, 1 0, 0 1, 0 0))", "merge")
    with pytest.raises(ValueError, match="a:1:"):
        genbsp.boolean2d("POLYGON((0 0, 1 0", "POLYGON((0 0, 1 0, 0 1, 0 0))", "union")
    with pytest.raises(ValueError):
        genbsp.boolean2d("POLYGON((0 0, 1 0, 0 1, 0 0))", "POLYGON((0 0, 1 0, 0 1, 0 0))", "union", fill_rule="odd")
    v, f = cube(0, 0, 0, 1)
    with pytest.raises(ValueError, match="open mesh"):
        genbsp.csg((v, f[:-1]), (v, f), "union")
    with pytest.raises(FileNotFoundError):
        genbsp.csg("missing.off", (v, f), "union")


def test_visibility2d_around_a_pillar():
    # A 10 x 10 room with a pillar [4, 6] x [7, 8]; from (5, 5) the pillar
    # hides the trapezoid between y = 7 (width 2) and y = 10 (width 5): 10.5.
    room = "POLYGON((0 0, 10 0, 10 10, 0 10, 0 0), (4 7, 6 7, 6 8, 4 8, 4 7))"
    v = genbsp.visibility2d(room, [5, 5])
    assert v.area == Fraction(179, 2) and v.bounded
    assert json.loads(v.geojson)["type"] == "Feature"
    with pytest.raises(ValueError, match="two numbers"):
        genbsp.visibility2d(room, [5, 5, 5])


def test_shadow_of_a_square_on_the_floor():
    # A unit square at height 1 under a point light at height 10: its shadow
    # on the floor is the square scaled by 10/9 (floor face 1).
    v = [(-2, -2, 0), (2, -2, 0), (2, 2, 0), (-2, 2, 0), (Fraction(-1, 2), Fraction(-1, 2), 1), (Fraction(1, 2), Fraction(-1, 2), 1),
         (Fraction(1, 2), Fraction(1, 2), 1), (Fraction(-1, 2), Fraction(1, 2), 1)]
    scene = genbsp.Scene.from_arrays(v, [[0, 1, 2, 3], [4, 5, 6, 7]])
    s = scene.shadows(light=[(0, 0, 10)])
    floor = next(f for f in s["faces"] if f["face"] == 0)
    assert floor["area"] == pytest.approx(16)
    assert floor["shadowed_area"] == pytest.approx(100 / 81, rel=1e-12)
    assert floor["lit_area"][0] == pytest.approx(16 - 100 / 81, rel=1e-12)
