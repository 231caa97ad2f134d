"""Visibility maps from Python against the genbsp program and against the
map's invariants."""

import json
import math
import pickle
from fractions import Fraction

import numpy as np
import pytest

import genbsp
from conftest import CUBE_OFF, run_cli


def directions_for(scene, eye, rng, n=400):
    """Random directions, and directions towards every vertex and edge
    midpoint of the scene (exact dyadic doubles where the scene allows):
    the degenerate ones, on the map's edges and vertices."""
    e = np.array([float(Fraction(c)) for c in eye])
    rand = rng.normal(size=(n, 3))
    verts = np.array([[float(c) for c in v] for v in scene.vertices()])
    towards = verts - e
    mids = []
    for f in scene.faces():
        for a, b in zip(f, f[1:] + f[:1]):
            mids.append((verts[a] + verts[b]) / 2 - e)
    d = np.concatenate([rand, towards, np.array(mids).reshape(-1, 3), np.eye(3), -np.eye(3)])
    return d[np.any(d != 0, axis=1)]


def exact_lines(d):
    return "".join(" ".join(str(Fraction(float(c))) for c in row) + "\n" for row in d)


@pytest.mark.parametrize("name", ["bricks", "platforms", "random", "room", "cube"])
@pytest.mark.parametrize("exact", [True, False])
def test_locate_equals_the_program(scenes, genbsp_cli, tmp_path, name, exact):
    path, eye = scenes[name]
    scene = genbsp.Scene.from_file(path)
    m = scene.visibility_map(eye, exact=exact)
    d = directions_for(scene, eye, np.random.default_rng(7))
    (tmp_path / "dirs").write_text(exact_lines(d))
    number = [] if exact else ["--number", "double"]
    cli = run_cli(genbsp_cli, "locate", path, "--eye", ",".join(eye), "--dirs", tmp_path / "dirs", *number).stdout.split()
    got = m.locate(d)
    assert got.dtype == np.int64 and got.shape == (len(d),)
    assert got.tolist() == [int(x) for x in cli]
    assert m.locate(d[0]) == got[0]


def test_locate_sees_the_cube_and_the_square():
    # The cube's near face straight ahead, the square beside it, nothing behind.
    scene = genbsp.Scene.from_arrays(
        np.array([[-0.5, -0.5, 2], [0.5, -0.5, 2], [0.5, 0.5, 2], [-0.5, 0.5, 2], [-4, -4, 5], [4, -4, 5], [4, 4, 5], [-4, 4, 5]], dtype=float),
        [[0, 3, 2, 1], [4, 7, 6, 5]],
    )
    m = scene.visibility_map([0, 0, 0])
    assert m.locate([[0, 0, 1], [0.1, 0.1, 1], [3, 3, 5], [0, 0, -1]]).tolist() == [0, 0, 1, -1]


def turning(u, a, b):
    """The turn at unit vertex u from great circle a (arriving) to b (leaving)."""
    tin, tout = np.cross(a, u), np.cross(b, u)
    return math.atan2(np.dot(u, np.cross(tin, tout)), np.dot(tin, tout))


@pytest.mark.parametrize("name", ["bricks", "platforms", "random", "room", "cube"])
def test_map_invariants(scenes, name):
    path, eye = scenes[name]
    m = genbsp.Scene.from_file(path).visibility_map(eye)
    h, v, faces = m.half_edges, m.vertices, m.faces
    origin, twin, nxt, prev, face = h.T
    idx = np.arange(len(h))
    # Twins pair up, next and prev are inverse, a face's cycle stays in the face.
    assert (twin[twin] == idx).all() and (twin != idx).all()
    assert (prev[nxt] == idx).all() and (nxt[prev] == idx).all()
    assert (face[nxt] == face).all()
    assert (origin[nxt] == origin[twin]).all()
    assert np.allclose(np.linalg.norm(v, axis=1), 1)
    assert set(face.tolist()) == set(range(len(faces)))
    # Euler: V - E + F = 1 + (components of the edge graph).
    parent = list(range(len(v)))

    def find(x):
        while parent[x] != x:
            parent[x] = parent[parent[x]]
            x = parent[x]
        return x

    for a, b in m.edges:
        parent[find(a)] = find(b)
    components = len({find(x) for x in range(len(v))})
    assert len(v) - len(m.edges) + len(faces) == 1 + components
    # Areas (Gauss-Bonnet on great-circle arcs) sum to 4 pi: a face bounded
    # by k cycles has area 2 pi (2 - k) minus its boundary's total turning.
    circle = np.cross(v[origin], v[origin[twin]])
    circle /= np.linalg.norm(circle, axis=1)[:, None]
    seen = np.zeros(len(h), bool)
    cycles = np.zeros(len(faces), int)
    turn = np.zeros(len(faces))
    for e in range(len(h)):
        if seen[e]:
            continue
        cycles[face[e]] += 1
        x = e
        while not seen[x]:
            seen[x] = True
            turn[face[x]] += turning(v[origin[nxt[x]]], circle[x], circle[nxt[x]])
            x = nxt[x]
    areas = 2 * math.pi * (2 - cycles) - turn
    assert (areas > -1e-9).all()
    assert abs(areas.sum() - 4 * math.pi) < 1e-6
    # faces_of and neighbours agree with the arrays.
    for f in range(min(len(faces), 40)):
        assert f in m.faces_of(int(faces[f]))
        assert m.neighbours(f) == sorted({int(face[twin[e]]) for e in idx[face == f]} - {f})
    assert m.visible_polygons() == sorted(set(faces.tolist()) - {-1})


def test_to_json_and_render_equal_the_program(scenes, genbsp_cli, tmp_path):
    path, eye = scenes["room"]
    m = genbsp.Scene.from_file(path).visibility_map(eye)
    run_cli(genbsp_cli, "map", path, "--eye", ",".join(eye), "-o", tmp_path / "map.json")
    mine, theirs = json.loads(m.to_json()), json.loads((tmp_path / "map.json").read_text())
    mine.pop("stats"), theirs.pop("stats")
    assert mine == theirs
    run_cli(genbsp_cli, "render", path, "--eye", ",".join(eye), "--size", "300x200", "--fov", "75", "-o", tmp_path / "r.svg")
    assert m.render(size=(300, 200), fov=75) == (tmp_path / "r.svg").read_text()
    summary = m.render(tmp_path / "lines.svg", style="lines", hidden="dashed")
    assert summary["views"][0]["output"] == str(tmp_path / "lines.svg")
    assert (tmp_path / "lines.svg").read_text().startswith("<?xml")
    assert m.render(format="png", size=(64, 48))[:8] == b"\x89PNG\r\n\x1a\n"
    assert m.render(format="pdf", size=(64, 48))[:5] == b"%PDF-"


def test_exact_numbers_in_and_out(tmp_path):
    # Vertices as exact strings, Fractions and ints; floats exactly as doubles.
    third = Fraction(1, 3)
    s = genbsp.Scene.from_arrays([[0, 0, 1], ["1", "0", "1"], [third, 1, 1]], [[0, 1, 2]])
    assert s.vertices()[2] == (third, 1, 1)
    d = genbsp.Scene.from_arrays(np.array([[0.1, 0, 1], [1, 0, 1], [0, 1, 1]]), [[0, 1, 2]])
    assert d.vertices()[0][0] == Fraction(0.1) != Fraction(1, 10)
    m = s.visibility_map([third, "0.25", Fraction(-1, 7)])
    assert m.eye == (third, Fraction(1, 4), Fraction(-1, 7))
    # Pickles (for Dask) with the exact vertices.
    t = pickle.loads(pickle.dumps(s))
    assert t.vertices() == s.vertices() and t.faces() == s.faces()


def test_bad_input_raises(tmp_path):
    with pytest.raises(FileNotFoundError, match="no such file"):
        genbsp.Scene.from_file(tmp_path / "missing.off")
    bad = tmp_path / "bad.off"
    bad.write_text("OFF\n3 1 0\n0 0 0\n1 zero 0\n0 1 0\n3 0 1 2\n")
    with pytest.raises(ValueError, match=r"bad.off:4:"):
        genbsp.Scene.from_file(bad)
    with pytest.raises(ValueError, match="out of range"):
        genbsp.Scene.from_arrays([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 1, 3]])
    with pytest.raises(ValueError, match="finite"):
        genbsp.Scene.from_arrays(np.array([[0, 0, np.nan], [1, 0, 0], [0, 1, 0]]), [[0, 1, 2]])
    s = genbsp.Scene.from_arrays([[0, 0, 1], [1, 0, 1], [0, 1, 1]], [[0, 1, 2]])
    with pytest.raises(ValueError, match="three numbers"):
        s.visibility_map([0, 0])
    with pytest.raises(ValueError, match="not a number"):
        s.visibility_map(["0", "x", "0"])
    m = s.visibility_map([0, 0, 0])
    with pytest.raises(ValueError, match=r"directions\[1\]: the zero vector"):
        m.locate([[0, 0, 1], [0, 0, 0]])
    with pytest.raises(ValueError, match="finite"):
        m.locate([[0, np.inf, 1]])
    with pytest.raises(ValueError, match="n x 3"):
        m.locate(np.zeros((2, 2)))
    with pytest.raises(ValueError, match="--fov"):
        m.render(fov=400)
    with pytest.raises(IndexError):
        m.neighbours(10**6)
    with pytest.raises(ValueError, match="give path"):
        m.render(projection="cube")


def test_file_errors_are_os_errors_and_bad_content_value_errors(tmp_path):
    """A file that cannot be opened or written is the OSError of its cause;
    a file that is there but is not a scene is a ValueError."""
    ply = tmp_path / "scene.ply"
    ply.write_text("ply\n")
    with pytest.raises(ValueError, match="unknown scene format"):
        genbsp.Scene.from_file(ply)
    (tmp_path / "folder.off").mkdir()
    with pytest.raises(IsADirectoryError, match="is a directory"):
        genbsp.Scene.from_file(tmp_path / "folder.off")
    s = genbsp.Scene.from_arrays([[0, 0, 1], [1, 0, 1], [0, 1, 1]], [[0, 1, 2]])
    m = s.visibility_map([0, 0, 0])
    for name in ("map.svg", "map.pdf"):
        with pytest.raises(FileNotFoundError, match="cannot write"):
            m.render(path=tmp_path / "no" / "such" / "folder" / name)
    with pytest.raises(FileNotFoundError, match="cannot write"):
        m.render(path=tmp_path / "no" / "map.svg", projection="cube")
    # A bad extension is bad input, not a file error.
    with pytest.raises(ValueError, match="unknown output format"):
        m.render(path=tmp_path / "map.xyz")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["folder.off", "scene.ply"]


def test_a_pickled_scene_keeps_its_colours_and_name(scenes):
    """What a Dask worker gets is the scene itself: the same exact vertices,
    faces, colours and name, so the same pictures."""
    path, eye = scenes["room"]
    s = genbsp.Scene.from_file(path)
    t = pickle.loads(pickle.dumps(s))
    assert t.name == s.name and t._s.face_colours() == s._s.face_colours()
    assert sum(c is not None for c in t._s.face_colours()) == t.num_faces
    a = s.visibility_map(eye).render(size=(160, 120))
    b = t.visibility_map(eye).render(size=(160, 120))
    assert a == b
    # The colours are in the picture: without them it is another one.
    bare = genbsp.Scene(genbsp._genbsp.Scene.from_text(s._s.exact_vertices(), s._s.face_indices()))
    assert bare.visibility_map(eye).render(size=(160, 120)) != a
