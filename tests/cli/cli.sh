#!/usr/bin/env bash
# End-to-end tests of the genbsp program: outputs against the library's own
# tests' facts, errors as one line with file:line and exit status 2, files
# written whole or not at all.
set -uo pipefail
genbsp=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0 passed=0
check() { # check NAME CONDITION...
  local name=$1
  shift
  if "$@"; then passed=$((passed + 1)); else
    echo "FAILED: $name" >&2
    failures=$((failures + 1))
  fi
}
quiet() { "$@" >/dev/null; }
expect_error() { # expect_error NAME PATTERN COMMAND...: exit 2, one stderr line matching PATTERN
  local name=$1 pattern=$2
  shift 2
  "$@" >"$work/out" 2>"$work/err"
  local status=$?
  check "$name: exit status 2 (got $status)" test "$status" -eq 2
  check "$name: one line on stderr" test "$(wc -l <"$work/err")" -eq 1
  check "$name: message matches '$pattern' (got '$(cat "$work/err")')" grep -qE -e "$pattern" "$work/err"
}

# A cube (outward faces) in front of a larger square, in OFF with exact decimals.
cat >"$work/scene.off" <<'SCENE'
OFF
# a unit cube at z in [2, 3] and a square behind it at z = 5
12 7 0
-0.5 -0.5 2
0.5 -0.5 2
0.5 0.5 2
-0.5 0.5 2
-0.5 -0.5 3
0.5 -0.5 3
0.5 0.5 3
-0.5 0.5 3
-4 -4 5
4 -4 5
4 4 5
-4 4 5
4 0 3 2 1
4 4 5 6 7
4 0 1 5 4
4 2 3 7 6
4 0 4 7 3
4 1 2 6 5
4 8 11 10 9
SCENE

# locate: straight ahead the cube's near face (0); beside it the square (6); behind, nothing.
printf '0 0 1\n0.1 0.1 1\n3 3 5\n0 0 -1\n# a comment line\n\n1 1 -1/3\n' >"$work/dirs"
"$genbsp" locate "$work/scene.off" --eye 0,0,0 --dirs "$work/dirs" >"$work/located"
check "locate answers" test "$(tr '\n' ' ' <"$work/located")" = "0 0 6 -1 -1 "
"$genbsp" locate "$work/scene.off" --eye 0,0,0 --cull-backfaces --dirs - <"$work/dirs" >"$work/located2"
check "locate from standard input, culling back faces" cmp -s "$work/located" "$work/located2"

# The cube is a closed convex solid seen from outside: its five back faces are
# proven hidden and left out by default; the map is the same without that.
"$genbsp" map "$work/scene.off" --eye 0,0,0 -o "$work/solid.json"
"$genbsp" map "$work/scene.off" --eye 0,0,0 --no-solid-culling -o "$work/solid2.json"
check "closed convex solids: back faces culled, the same map" python3 - "$work/solid.json" "$work/solid2.json" <<'PY'
import json, sys
a, b = (json.load(open(f)) for f in sys.argv[1:])
assert a["stats"]["convex_solids"] == 1 and a["stats"]["discarded_backfacing"] == 5, a["stats"]
assert b["stats"]["convex_solids"] == 0 and b["stats"]["discarded_backfacing"] == 0, b["stats"]
a.pop("stats"); b.pop("stats")
assert a == b
PY

# stats: one JSON object with the required keys.
"$genbsp" stats "$work/scene.off" --eye 0,0,0 >"$work/stats.json"
for key in input_faces discarded_faces fragments v_nodes map map_unsimplified filter_fallbacks seconds peak_bytes \
  depth_order_seconds visible_seconds map_seconds simplify_seconds visible_pieces map_pieces; do
  check "stats has $key" grep -q "\"$key\"" "$work/stats.json"
done
check "stats counts 7 input faces" grep -q '"input_faces":7' "$work/stats.json"
# Seen from the origin: the near face of the cube, the square around it, the background.
check "stats: 3 faces after simplifying" grep -q '"map":{"vertices":8,"edges":8,"faces":3}' "$work/stats.json"

# --progress: lines on standard error, ending at 100 %; standard output unchanged.
"$genbsp" stats "$work/scene.off" --eye 0,0,0 --progress >"$work/stats2.json" 2>"$work/progress"
check "progress reaches 100 %" grep -q 'mapping 100%' "$work/progress"
check "progress starts at 0 %" grep -q 'mapping 0%' "$work/progress"
check "progress leaves standard output alone" test "$(head -c 40 "$work/stats2.json")" = "$(head -c 40 "$work/stats.json")"

# map: the JSON schema, with a Python check of cycles and labels.
"$genbsp" map "$work/scene.off" --eye 0,0,0 -o "$work/map.json"
check "map schema" python3 - "$work/map.json" <<'PY'
import json, math, sys
m = json.load(open(sys.argv[1]))
assert m["eye"] == [0, 0, 0]
assert all(abs(math.hypot(*v) - 1) < 1e-12 for v in m["vertices"])
labels = sorted(f["polygon"] for f in m["faces"])
assert labels == [-1, 0, 6], labels
square = next(f for f in m["faces"] if f["polygon"] == 6)
assert len(square["cycles"]) == 2  # the square with the cube's face as a hole
for f in m["faces"]:
    for c in f["cycles"]:
        assert all(0 <= v < len(m["vertices"]) for v in c)
assert "stats" in m
PY

# scene: a family written as OFF, read back, with the suggested eye.
eye=$("$genbsp" scene platforms --n 5 -o "$work/platforms.off")
check "scene prints the eye" grep -qE '^[-0-9./]+,[-0-9./]+,[-0-9./]+$' <<<"$eye"
"$genbsp" stats "$work/platforms.off" --eye "$eye" >"$work/p.json"
check "platforms of 5 slabs: 6 faces" grep -q '"faces":6}' "$work/p.json"

# The furnished room: 1,161 faces with OFF colours, and colours reach the drawing.
room_eye=$("$genbsp" scene room -o "$work/room.off")
check "room: 1161 faces" test "$(sed -n 3p "$work/room.off" | cut -d' ' -f2)" = 1161
check "room: every face has a colour" test "$(awk 'NR > 3 && NF == 8' "$work/room.off" | wc -l)" -eq 1161
"$genbsp" render "$work/room.off" --eye "$room_eye" --look 330,250,80 --style flat --size 160x120 -o "$work/room.svg"
check "room: the rug's colour is drawn flat" grep -q 'fill="#a0343a"' "$work/room.svg"

# Errors: one line naming file and line, exit status 2, no output file left behind.
printf 'OFF\n3 1 0\n0 0 0\n1 0 zero\n0 1 0\n3 0 1 2\n' >"$work/bad.off"
expect_error "bad number" "bad.off:4:" "$genbsp" stats "$work/bad.off" --eye 0,0,1
printf 'OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n' >"$work/bad2.off"
expect_error "index out of range" "bad2.off:6:" "$genbsp" map "$work/bad2.off" --eye 0,0,1 -o "$work/never.json"
check "no output file after an error" test ! -e "$work/never.json"
expect_error "missing file" "nothere.off" "$genbsp" stats "$work/nothere.off" --eye 0,0,0
expect_error "bad eye" "--eye" "$genbsp" stats "$work/scene.off" --eye 1,2
printf '0 0 1\n1 x 1\n' >"$work/bad.dirs"
expect_error "bad direction line" "bad.dirs:2:" "$genbsp" locate "$work/scene.off" --eye 0,0,0 --dirs "$work/bad.dirs"
expect_error "unknown option" "try --help" "$genbsp" stats "$work/scene.off" --eye 0,0,0 --frobnicate
expect_error "unknown family" "try --help" "$genbsp" scene cubes -o "$work/x.off"
# render: every format and projection; the id SVG shows faces 0 (the cube's
# near face) and 6 (the square) in perspective; nothing else is visible.
"$genbsp" render "$work/scene.off" --eye 0,0,0 --dir 0,0,1 --up 0,1,0 --style id --size 200x150 -o "$work/id.svg"
check "render id: faces 0 and 6 only" test "$(grep -o 'data-face="[0-9]*"' "$work/id.svg" | sort -u | tr '\n' ' ')" = 'data-face="0" data-face="6" '
check "render id: fill is index + 1" grep -q 'data-face="6" fill="#000007"' "$work/id.svg"
for projection in perspective stereographic fisheye fisheye-equisolid equirectangular; do
  for ext in svg pdf eps png; do
    "$genbsp" render "$work/scene.off" --eye 0,0,0 --dir 0,0,1 --projection $projection --fov 150 --size 120x90 -o "$work/r-$projection.$ext"
    check "render $projection $ext: written" test -s "$work/r-$projection.$ext"
  done
  check "render $projection: SVG parses" python3 -c 'import sys, xml.dom.minidom as m; m.parse(sys.argv[1])' "$work/r-$projection.svg"
  check "render $projection: PDF header" grep -q '^%PDF-' "$work/r-$projection.pdf"
  check "render $projection: PNG signature" test "$(head -c 8 "$work/r-$projection.png" | od -An -tx1 | tr -d ' \n')" = 89504e470d0a1a0a
done
"$genbsp" render "$work/scene.off" --eye 0,0,0 --dir 0,0,1 --projection cube --style lines -o "$work/cube.svg"
for side in front right back left up down; do check "render cube: $side face" test -s "$work/cube-$side.svg"; done
check "render cube: nothing behind the eye" test "$(grep -c '<path' "$work/cube-back.svg")" -eq 0
check "render cube: the cube's outline ahead" test "$(grep -c '<path' "$work/cube-front.svg")" -ge 1
expect_error "render: unknown format" "\.gif" "$genbsp" render "$work/scene.off" --eye 0,0,0 -o "$work/x.gif"
expect_error "render: bad size" "--size" "$genbsp" render "$work/scene.off" --eye 0,0,0 --size 100by20 -o "$work/x.svg"
expect_error "render: up along the view" "up vector" "$genbsp" render "$work/scene.off" --eye 0,0,0 --dir 0,0,1 --up 0,0,2 -o "$work/x.svg"
expect_error "render: bad projection" "try --help" "$genbsp" render "$work/scene.off" --eye 0,0,0 --projection mercator -o "$work/x.svg"
check "render: no file after an error" test ! -e "$work/x.svg"

# locate --view-dir: lines parallel to z through the cube (its face 0 at z =
# 2), beside it (the square, 6) and beyond the square (nothing).
printf '0 0 0\n3 3 -100\n10 10 1\n0.1 0.2 50\n' >"$work/points"
"$genbsp" locate "$work/scene.off" --view-dir 0,0,1 --dirs "$work/points" >"$work/located-parallel"
check "locate --view-dir: faces along parallel lines" test "$(tr '\n' ' ' <"$work/located-parallel")" = "0 6 -1 0 "
"$genbsp" map "$work/scene.off" --view-dir 0,0,1 -o "$work/map-parallel.json"
check "map --view-dir: the cube's face of area 1 and the square's 63 around it, in the view plane" python3 -c '
import json, sys
d = json.load(open(sys.argv[1]))
assert d["view"]["direction"] == [0, 0, 1] and d["view"]["up"] == [0, 1, 0] and d["view"]["right"] == [-1, 0, 0], d["view"]
xy = d["vertices"]
def area(c):
    return sum(xy[a][0] * xy[b][1] - xy[b][0] * xy[a][1] for a, b in zip(c, c[1:] + c[:1])) / 2
faces = {}
for f in d["faces"]:
    faces[f["polygon"]] = faces.get(f["polygon"], 0) + sum(area(c) for c in f["cycles"])
    assert area(f["cycles"][0]) > 0 or f["polygon"] == -1   # the outer cycle first, counter-clockwise
assert abs(faces[0] - 1) < 1e-9 and abs(faces[6] - 63) < 1e-9, faces
assert all(abs(x) <= 4 + 1e-9 and abs(y) <= 4 + 1e-9 for x, y in xy)
' "$work/map-parallel.json"
expect_error "map: --up without --view-dir" "--up is for --view-dir" "$genbsp" map "$work/scene.off" --eye 0,0,0 --up 0,0,1 -o "$work/x.json"
expect_error "map: neither --eye nor --view-dir" "--view-dir" "$genbsp" map "$work/scene.off" -o "$work/x.json"
"$genbsp" stats "$work/scene.off" --view-dir 1,1,3 >"$work/stats-parallel.json"
check "stats --view-dir: a map" python3 -c 'import json, sys; d = json.load(open(sys.argv[1])); sys.exit(not (d["polygons"] == 7 and d["map"]["faces"] >= 5))' "$work/stats-parallel.json"
expect_error "locate: --eye and --view-dir" "--view-dir" "$genbsp" locate "$work/scene.off" --eye 0,0,0 --view-dir 0,0,1 --dirs "$work/points"
expect_error "stats: neither --eye nor --view-dir" "--view-dir" "$genbsp" stats "$work/scene.off"

# render orthographic: looking along (1,1,3) from the point at infinity, the
# cube's faces facing -x, -y and -z (2, 4, 0) and the square (6).
"$genbsp" render "$work/scene.off" --projection orthographic --dir 1,1,3 --style id --size 200x150 -o "$work/ortho.svg"
check "render orthographic: faces 0, 2, 4 and 6" test "$(grep -o 'data-face="[0-9]*"' "$work/ortho.svg" | sort -u | tr '\n' ' ')" = 'data-face="0" data-face="2" data-face="4" data-face="6" '
"$genbsp" render "$work/scene.off" --projection orthographic --dir 0,0,1 --extent 2 --light 0,0,0 --shadows -o "$work/ortho.pdf"
check "render orthographic with shadows: PDF" grep -q '^%PDF-' "$work/ortho.pdf"
"$genbsp" render "$work/scene.off" --view bottom --style id --size 200x150 -o "$work/bottom.svg"
check "render --view bottom: the cube's bottom (0) and the square around it (6)" test "$(grep -o 'data-face="[0-9]*"' "$work/bottom.svg" | sort -u | tr '\n' ' ')" = 'data-face="0" data-face="6" '
expect_error "render --view with --dir" "--view" "$genbsp" render "$work/scene.off" --view front --dir 1,0,0 -o "$work/x.svg"
expect_error "render orthographic: no direction" "--dir" "$genbsp" render "$work/scene.off" --projection orthographic -o "$work/x.svg"
expect_error "render: --eye is needed in perspective" "--eye" "$genbsp" render "$work/scene.off" -o "$work/x.svg"
expect_error "render: --extent is orthographic" "--extent" "$genbsp" render "$work/scene.off" --eye 0,0,0 --extent 3 -o "$work/x.svg"

# view: one self-contained page with the map in place of the placeholder.
"$genbsp" view "$work/scene.off" --eye 0,0,0 -o "$work/view.html"
check "view: a page" grep -q '<html' "$work/view.html"
check "view: the map embedded" grep -q '"polygon":6' "$work/view.html"
check "view: no placeholder left" test "$(grep -c 'GENBSP_MAP\*/null' "$work/view.html")" -eq 0
check "view: nothing fetched from the network" test "$(grep -cE '(src|href)="https?:' "$work/view.html")" -eq 0
expect_error "view: not html" "\.html" "$genbsp" view "$work/scene.off" --eye 0,0,0 -o "$work/view.txt"

# bool: the plane from WKT and GeoJSON (exact decimals), the sphere from GeoJSON.
printf 'MULTIPOLYGON (((0 0, 2 0, 2 2, 0 2, 0 0), (0.5 0.5, 0.5 1.5, 1.5 1.5, 1.5 0.5, 0.5 0.5)))\n' >"$work/a.wkt"
cat >"$work/b.geojson" <<'GEO'
{"type": "FeatureCollection", "features": [
  {"type": "Feature", "properties": {"name": "shifted"},
   "geometry": {"type": "Polygon", "coordinates": [[[1, 0.1], [3, 0.1], [3, 2.1], [1, 2.1], [1, 0.1]]]}}]}
GEO
summary_field() { python3 -c 'import json, sys; print(json.loads(sys.stdin.read())[sys.argv[1]])' "$1"; }
# A: 4 - 1 = 3; B: 4; A ∩ B = [1,2]x[0.1,2] minus [1,1.5]x[0.5,1.5] = 1.9 - 0.5 = 1.4.
for op_area in union:5.6 intersection:1.4 difference:1.6 xor:4.2; do
  op=${op_area%%:*} area=${op_area#*:}
  "$genbsp" bool "$work/a.wkt" "$work/b.geojson" --op "$op" -o "$work/r-$op.wkt" >"$work/summary"
  check "bool $op: exact area $area" test "$(summary_field area_exact <"$work/summary")" = "$area"
  check "bool $op: WKT written" grep -q '^MULTIPOLYGON' "$work/r-$op.wkt"
done
"$genbsp" bool "$work/a.wkt" "$work/b.geojson" --op union -o "$work/u.geojson" >"$work/summary"
check "bool union: 1 polygon, 2 rings" test "$(summary_field polygons <"$work/summary") $(summary_field rings <"$work/summary")" = "1 2"
check "bool union: GeoJSON parses as a MultiPolygon" python3 -c 'import json, sys; d = json.load(open(sys.argv[1])); assert d["type"] == "MultiPolygon" and len(d["coordinates"][0]) == 2' "$work/u.geojson"
"$genbsp" bool "$work/r-union.wkt" "$work/u.geojson" --op xor -o "$work/none.wkt" >"$work/summary"
check "bool: written WKT and GeoJSON read back as the same set" test "$(summary_field area_exact <"$work/summary")" = 0
check "bool: the empty result" grep -q 'MULTIPOLYGON EMPTY' "$work/none.wkt"
"$genbsp" bool "$work/a.wkt" "$work/b.geojson" --op union -o "$work/u.svg" >/dev/null
check "bool: SVG parses, one path per polygon" python3 -c 'import sys, xml.dom.minidom as m; assert len(m.parse(sys.argv[1]).getElementsByTagName("path")) == 1' "$work/u.svg"
printf 'POLYGON ((0 0, 4 4, 4 0, 0 4, 0 0))\n' >"$work/bow.wkt"
expect_error "bool: a self-crossing ring" "bow.wkt: .*crosses itself" "$genbsp" bool "$work/bow.wkt" "$work/a.wkt" --op union -o "$work/x.wkt"
"$genbsp" bool "$work/bow.wkt" "$work/bow.wkt" --op union --fill-rule evenodd -o "$work/bow-out.wkt" >"$work/summary"
check "bool --fill-rule evenodd: the bow tie's two lobes" test "$(summary_field area_exact <"$work/summary") $(summary_field polygons <"$work/summary")" = "8 2"
"$genbsp" bool "$work/bow.wkt" "$work/bow.wkt" --op union --fill-rule positive -o "$work/bow-out.wkt" >"$work/summary"
check "bool --fill-rule positive: one lobe" test "$(summary_field area_exact <"$work/summary")" = 4
# A hole sharing part of an edge with its outer ring: refused (the region lies
# on neither side of the shared part, which the build cannot tell from two
# polygons meeting there), and read right as paths with a fill rule:
# 16 - 4 = 12 for the square with the notch, 18 for the strip, 6 in common.
printf 'POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0), (1 0, 1 2, 3 2, 3 0, 1 0))\n' >"$work/notch.wkt"
printf 'POLYGON ((2 -1, 5 -1, 5 5, 2 5, 2 -1))\n' >"$work/strip.wkt"
expect_error "bool: a hole sharing an edge with its outer ring is refused" "notch.wkt: .*shares part of an edge" "$genbsp" bool "$work/notch.wkt" "$work/strip.wkt" --op union -o "$work/notch-x.wkt"
check "bool: nothing written for the refused notch" test ! -e "$work/notch-x.wkt"
"$genbsp" bool "$work/notch.wkt" "$work/strip.wkt" --op union --fill-rule nonzero -o "$work/notch-u.wkt" >"$work/summary"
check "bool --fill-rule nonzero: the notched square's union, exact area 24" test "$(summary_field area_exact <"$work/summary")" = 24
printf 'POLYGON ((0 0, 2 0,\n 2 2, 0 x, 0 0))\n' >"$work/bad.wkt"
expect_error "bool: a bad WKT number" "bad.wkt:2: not a number 'x'" "$genbsp" bool "$work/bad.wkt" "$work/a.wkt" --op union -o "$work/x.wkt"
printf '{"type": "Polygon",\n "coordinates": [[[0, 0], [1, 0], [0, 0]]]}\n' >"$work/bad.geojson"
expect_error "bool: a short GeoJSON ring" "bad.geojson:2: a ring needs" "$genbsp" bool "$work/bad.geojson" "$work/a.wkt" --op union -o "$work/x.wkt"
printf 'POLYGON ((0 0, 1 0, 1 1, 0 0)) extra\n' >"$work/trail.wkt"
expect_error "bool: text after the geometry" "trail.wkt:1: unexpected" "$genbsp" bool "$work/trail.wkt" "$work/a.wkt" --op union -o "$work/x.wkt"
expect_error "bool: unknown output format" "\.dxf" "$genbsp" bool "$work/a.wkt" "$work/a.wkt" --op union -o "$work/x.dxf"
expect_error "bool: bad operation" "try --help" "$genbsp" bool "$work/a.wkt" "$work/a.wkt" --op minus -o "$work/x.wkt"
check "bool: no file after an error" test ! -e "$work/x.wkt"
# The sphere: the northern hemisphere (counter-clockwise along the equator) and an octant.
printf '{"type":"Polygon","coordinates":[[[0,0],[90,0],[180,0],[-90,0],[0,0]]]}\n' >"$work/north.geojson"
printf '{"type":"Polygon","coordinates":[[[0,0],[90,0],[0,90],[0,0]]]}\n' >"$work/octant.geojson"
printf '{"type":"Polygon","coordinates":[[[170,-10],[-170,-10],[-170,10],[170,10],[170,-10]]]}\n' >"$work/dateline.geojson"
sphere_area() { "$genbsp" bool "$@" --geometry s2 -o "$work/s.geojson" | summary_field area; }
close_to() { python3 -c 'import math, sys; a, b = float(sys.argv[1]), eval(sys.argv[2], {"pi": math.pi}); sys.exit(abs(a - b) > 1e-9 * max(1, abs(b)))' "$1" "$2"; }
check "bool s2: hemisphere minus octant = 3 pi / 2" close_to "$(sphere_area "$work/north.geojson" "$work/octant.geojson" --op difference)" "1.5 * pi"
check "bool s2: octant from the south hemisphere's view: nothing shared" close_to "$(sphere_area "$work/octant.geojson" "$work/north.geojson" --op difference)" "0"
# Independent truth: the square's area as two spherical triangles (Van Oosterom and Strackee).
square_area=$(python3 -c '
import math
def v(lon, lat):
    lon, lat = math.radians(lon), math.radians(lat)
    return (math.cos(lat) * math.cos(lon), math.cos(lat) * math.sin(lon), math.sin(lat))
def tri(a, b, c):
    dot = lambda p, q: sum(x * y for x, y in zip(p, q))
    cross = lambda p, q: (p[1] * q[2] - p[2] * q[1], p[2] * q[0] - p[0] * q[2], p[0] * q[1] - p[1] * q[0])
    return 2 * math.atan2(dot(a, cross(b, c)), 1 + dot(a, b) + dot(b, c) + dot(c, a))
p = [v(170, -10), v(-170, -10), v(-170, 10), v(170, 10)]
print(repr(tri(p[0], p[1], p[2]) + tri(p[0], p[2], p[3])))')
check "bool s2: a square across the antimeridian" close_to "$(sphere_area "$work/dateline.geojson" "$work/dateline.geojson" --op union)" "$square_area"
"$genbsp" bool "$work/north.geojson" "$work/dateline.geojson" --geometry s2 --op union -o "$work/s.geojson" >"$work/summary"
check "bool s2: km² on the mean Earth radius" python3 -c 'import json, sys, math; d = json.loads(open(sys.argv[1]).read()); assert abs(d["area_km2"] - d["area"] * 6371.0088 ** 2) < 1e-6 * d["area_km2"]' "$work/summary"
expect_error "bool s2: no SVG" "SVG output is for --geometry e2" "$genbsp" bool "$work/north.geojson" "$work/octant.geojson" --geometry s2 --op union -o "$work/x.svg"

# csg: boxes in OFF with exact decimals; outputs read back by genbsp itself.
box() { # box X0 Y0 Z0 X1 Y1 Z1: a box with outward faces, in OFF
  printf 'OFF\n8 6 0\n%s %s %s\n%s %s %s\n%s %s %s\n%s %s %s\n%s %s %s\n%s %s %s\n%s %s %s\n%s %s %s\n' \
    "$1" "$2" "$3" "$4" "$2" "$3" "$4" "$5" "$3" "$1" "$5" "$3" "$1" "$2" "$6" "$4" "$2" "$6" "$4" "$5" "$6" "$1" "$5" "$6"
  printf '4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 2 3 7 6\n4 0 4 7 3\n4 1 2 6 5\n'
}
box 0 0 0 1 1 1 >"$work/b1.off"
box 1 0 0 2 1 1 >"$work/b2.off"
box 0.5 0.5 0.5 1.5 1.5 1.5 >"$work/b3.off"
box 1 1 0 2 2 1 >"$work/b4.off"
"$genbsp" csg "$work/b1.off" "$work/b2.off" --op union -o "$work/u.off" >"$work/summary"
check "csg: boxes sharing a face unite into one box of 6 faces, 8 vertices" test "$(summary_field volume_exact <"$work/summary") $(summary_field faces <"$work/summary") $(summary_field vertices <"$work/summary") $(summary_field closed <"$work/summary")" = "2 6 8 True"
"$genbsp" csg "$work/b1.off" "$work/b3.off" --op difference -o "$work/d.obj" >"$work/summary"
check "csg difference: exact volume 7/8, closed" test "$(summary_field volume_exact <"$work/summary") $(summary_field closed <"$work/summary")" = "0.875 True"
"$genbsp" csg "$work/d.obj" "$work/b3.off" --op union -o "$work/back.stl" >"$work/summary"
check "csg: the OBJ written reads back (difference + cube = 15/8)" test "$(summary_field volume_exact <"$work/summary")" = 1.875
"$genbsp" csg "$work/back.stl" "$work/back.stl" --op intersection -o "$work/back2.off" >"$work/summary"
check "csg: the STL written reads back" test "$(summary_field volume_exact <"$work/summary") $(summary_field closed <"$work/summary")" = "1.875 True"
"$genbsp" csg "$work/b1.off" "$work/b4.off" --op union -o "$work/edge.off" >"$work/summary"
check "csg: boxes sharing an edge are reported non-manifold" test "$(summary_field closed <"$work/summary") $(summary_field non_manifold_edges <"$work/summary")" = "False 1"
head -n 15 "$work/b1.off" | sed 's/^8 6 0$/8 5 0/' >"$work/open.off"
expect_error "csg: an open mesh" "open.off: open mesh" "$genbsp" csg "$work/open.off" "$work/b1.off" --op union -o "$work/x.off"
{ head -n 10 "$work/b1.off"; printf '4 0 1 2 3\n4 7 6 5 4\n4 4 5 1 0\n4 6 7 3 2\n4 3 7 4 0\n4 5 6 2 1\n'; } >"$work/inverted.off"
"$genbsp" csg "$work/inverted.off" "$work/b2.off" --op union -o "$work/inv.off" >"$work/summary" 2>"$work/err"
check "csg: an inside-out mesh is turned and said so" grep -q "inverted.off: the faces turn clockwise" "$work/err"
check "csg: ... and used the right way out" test "$(summary_field volume_exact <"$work/summary")" = 2
"$genbsp" csg "$work/b1.off" "$work/b3.off" --op union --progress -o "$work/p.off" >/dev/null 2>"$work/err"
check "csg --progress: the stages on standard error" test "$(grep -c '^genbsp: ' "$work/err")" -eq 4
expect_error "csg: unknown output format" "\.ply" "$genbsp" csg "$work/b1.off" "$work/b2.off" --op union -o "$work/x.ply"
expect_error "csg: no xor" "try --help" "$genbsp" csg "$work/b1.off" "$work/b2.off" --op xor -o "$work/x.off"
check "csg: no file after an error" test ! -e "$work/x.off"
# A cavity sharing part of a face with the outer shell: refused, as the hole
# sharing an edge is in the plane (see docs/robustness.md).
cat >"$work/cavity.off" <<'CAVITY'
OFF
16 12 0
0 0 0
4 0 0
4 4 0
0 4 0
0 0 4
4 0 4
4 4 4
0 4 4
1 1 0
3 1 0
3 3 0
1 3 0
1 1 2
3 1 2
3 3 2
1 3 2
4 0 3 2 1
4 4 5 6 7
4 0 1 5 4
4 2 3 7 6
4 1 2 6 5
4 0 4 7 3
4 9 10 11 8
4 15 14 13 12
4 12 13 9 8
4 14 15 11 10
4 13 14 10 9
4 11 15 12 8
CAVITY
expect_error "csg: a cavity sharing part of a face with the outer shell is refused" "cavity.off: .*a cavity shares part of a face with the outer shell" "$genbsp" csg "$work/cavity.off" "$work/b1.off" --op union -o "$work/cavity-x.off"
check "csg: nothing written for the refused cavity" test ! -e "$work/cavity-x.off"

# shadow: a light at the eye casts the cube's near face (z = 2, side 1) on
# the square at z = 5, scaled by 5/2: 6.25 of its 64 are in shadow.
"$genbsp" shadow "$work/scene.off" --light 0,0,0 -o "$work/shadow.json"
face_field() { python3 -c 'import json, sys; f = [x for x in json.load(open(sys.argv[1]))["faces"] if x["face"] == int(sys.argv[2])][0]; v = eval(sys.argv[3], {}, f); print(v)' "$@"; }
check "shadow json: the square's shadowed area" close_to "$(face_field "$work/shadow.json" 6 shadowed_area)" 6.25
check "shadow json: the square's lit area" close_to "$(face_field "$work/shadow.json" 6 'lit_area[0]')" 57.75
check "shadow json: the near face is lit whole" close_to "$(face_field "$work/shadow.json" 0 'lit_area[0]')" 1
check "shadow json: the far face turns its back" close_to "$(face_field "$work/shadow.json" 1 shadowed_area)" 1
"$genbsp" shadow "$work/scene.off" --light 0,0,0 --light 1,1,0 -o "$work/shadow.off"
check "shadow off: pieces written, and read back" quiet "$genbsp" stats "$work/shadow.off" --eye 0,0,1/3
"$genbsp" shadow "$work/scene.off" --light 0,0,0 -o "$work/shadow.obj"
check "shadow obj: coloured vertices" test "$(grep -c '^v [^ ]* [^ ]* [^ ]* [^ ]* [^ ]* [^ ]*$' "$work/shadow.obj")" -ge 12
expect_error "shadow: unknown format" "\.ply" "$genbsp" shadow "$work/scene.off" --light 0,0,0 -o "$work/x.ply"
expect_error "shadow: a light is needed" "--light" "$genbsp" shadow "$work/scene.off" -o "$work/x.json"
expect_error "shadow: bad light" "--light" "$genbsp" shadow "$work/scene.off" --light 0,0 -o "$work/x.json"
check "shadow: no file after an error" test ! -e "$work/x.json"
# render --shadows: from the eye, a light beside it shows part of the cube's shadow on the square.
"$genbsp" render "$work/scene.off" --eye 0,0,0 --dir 0,0,1 --up 0,1,0 --style id --light 1,1,0 --shadows --size 200x150 -o "$work/shadow-id.svg"
check "render --shadows id: the square lit (#000007)" grep -q 'data-face="6" fill="#000007"' "$work/shadow-id.svg"
check "render --shadows id: and in shadow (#800007)" grep -q 'data-face="6" fill="#800007"' "$work/shadow-id.svg"
check "render --shadows id: the near face lit (#000001)" grep -q 'data-face="0" fill="#000001"' "$work/shadow-id.svg"
"$genbsp" render "$work/scene.off" --eye 0,0,0 --dir 0,0,1 --up 0,1,0 --style lines --light 1,1,0 --shadows -o "$work/shadow-lines.svg"
check "render --shadows lines: shadow boundaries on their own layer" grep -q 'id="visible-shadow"' "$work/shadow-lines.svg"
"$genbsp" render "$work/scene.off" --eye 0,0,0 --dir 0,0,1 --light 1,1,0 --light -1,0,0 --shadows -o "$work/shadow.pdf"
check "render --shadows: PDF" grep -q '^%PDF-' "$work/shadow.pdf"
expect_error "render: --shadows needs a light" "--light" "$genbsp" render "$work/scene.off" --eye 0,0,0 --shadows -o "$work/x.svg"
expect_error "render: a zero sun" "--sun" "$genbsp" render "$work/scene.off" --eye 0,0,0 --sun 0,0,0 --shadows -o "$work/x.svg"
# A sun far along -z: parallel rays cast the cube's 1 x 1 section on the square.
"$genbsp" shadow "$work/scene.off" --sun 0,0,-1 -o "$work/sun.json"
check "shadow --sun: the square's shadowed area" close_to "$(face_field "$work/sun.json" 6 shadowed_area)" 1
check "shadow --sun: the square's lit area" close_to "$(face_field "$work/sun.json" 6 'lit_area[0]')" 63
"$genbsp" render "$work/scene.off" --eye 0,0,0 --dir 0,0,1 --up 0,1,0 --style id --sun 1,2,-4 --light 1,1,0 --shadows --size 200x150 -o "$work/sun-id.svg"
check "render --sun --light --shadows id: the square in shadow somewhere" grep -q 'data-face="6" fill="#800007"' "$work/sun-id.svg"
"$genbsp" view "$work/scene.off" --eye 0,0,0 --light 1,1,0 -o "$work/view-lit.html"
check "view --light: faces list the lights that reach them" grep -q '"polygon":6,"lights":\[0\]' "$work/view-lit.html"
check "view --light: and the shadowed ones none" grep -q '"polygon":6,"lights":\[\]' "$work/view-lit.html"

# visibility2d: a 10 x 10 room with a 2 x 2 hole, seen from (1, 5).
printf 'POLYGON ((0 0, 10 0, 10 10, 0 10, 0 0), (4 4, 4 6, 6 6, 6 4, 4 4))\n' >"$work/room.wkt"
"$genbsp" visibility2d "$work/room.wkt" --eye 1,5 -o "$work/vis.wkt" >"$work/summary"
# Behind the hole's near side, between the rays from (1,5) through (4,4) and
# (4,6): the quadrilateral (4,4) (4,6) (10,8) (10,2), the hole inside it, of
# area (2 + 6)/2 · 6 = 24: 100 − 24 = 76.
check "visibility2d: exact area 76" test "$(summary_field area_exact <"$work/summary")" = "76"
check "visibility2d: bounded" test "$(summary_field bounded <"$work/summary")" = "True"
# (0,0) (10,0) (10,2) (4,4) (4,6) (10,8) (10,10) (0,10)
check "visibility2d: 8 vertices" test "$(summary_field vertices <"$work/summary")" = "8"
check "visibility2d: WKT polygon" grep -q '^POLYGON ((' "$work/vis.wkt"
"$genbsp" visibility2d "$work/room.wkt" --eye 1,5 -o "$work/vis.geojson" >/dev/null
check "visibility2d: GeoJSON names each piece's wall" python3 -c '
import json, sys
d = json.load(open(sys.argv[1]))
assert d["geometry"]["type"] == "Polygon" and d["properties"]["area"] == 76
walls = [p["wall"] for p in d["properties"]["pieces"]]
assert {"polygon": 0, "ring": 1, "edge": 0} in walls, walls   # the hole edge (4,4)-(4,6) faces the eye
assert {"polygon": 0, "ring": 0, "edge": 1} in walls, walls   # the far wall x = 10
' "$work/vis.geojson"
"$genbsp" visibility2d "$work/room.wkt" --eye 0,5 -o "$work/vis-edge.svg" >"$work/summary"
check "visibility2d: an eye on the room's wall looks in" python3 -c 'import json,sys; d=json.load(open(sys.argv[1])); assert 0 < d["area"] < 96' "$work/summary"
check "visibility2d: SVG with the region and the walls" grep -q 'id="visible"' "$work/vis-edge.svg"
# --eyes: the walls' tree once, a polygon per eye, the same answers as one eye at a time.
printf '# eyes\n1 5\n0,5\n' >"$work/eyes.txt"
"$genbsp" visibility2d "$work/room.wkt" --eyes "$work/eyes.txt" -o "$work/many.wkt" >"$work/summary"
"$genbsp" visibility2d "$work/room.wkt" --eye 0,5 -o "$work/one.wkt" >"$work/summary-one"
check "visibility2d --eyes: two views, the first of area 76" python3 -c '
import json, sys
d = json.load(open(sys.argv[1])); one = json.load(open(sys.argv[2]))
assert d["eyes"] == 2 and d["views"][0]["area_exact"] == "76" and d["views"][1]["area_exact"] == one["area_exact"], (d, one)
' "$work/summary" "$work/summary-one"
check "visibility2d --eyes: a GEOMETRYCOLLECTION holding the single view's polygon" grep -qF "$(cat "$work/one.wkt")" "$work/many.wkt"
"$genbsp" visibility2d "$work/room.wkt" --eyes - -o "$work/many.geojson" <"$work/eyes.txt" >/dev/null
check "visibility2d --eyes -: a FeatureCollection from standard input" python3 -c 'import json, sys; d = json.load(open(sys.argv[1])); assert d["type"] == "FeatureCollection" and len(d["features"]) == 2' "$work/many.geojson"
printf '1 5\n0 x\n' >"$work/bad-eyes.txt"
expect_error "visibility2d --eyes: a bad line" "bad-eyes.txt:2: " "$genbsp" visibility2d "$work/room.wkt" --eyes "$work/bad-eyes.txt" -o "$work/x.wkt"
expect_error "visibility2d: neither --eye nor --eyes" "--eyes" "$genbsp" visibility2d "$work/room.wkt" -o "$work/x.wkt"
printf 'MULTIPOLYGON (((0 0, 1 0, 1 1, 0 1, 0 0)), ((1 0, 2 0, 2 1, 1 1, 1 0)))\n' >"$work/two-rooms.wkt"
"$genbsp" visibility2d "$work/two-rooms.wkt" --eye 1,0.5 -o "$work/two.wkt" >"$work/summary"
check "visibility2d: an eye on the wall between two rooms looks into both" test "$(summary_field area_exact <"$work/summary")" = "2"
printf 'POLYGON ((0 0, 4 0, 4 4, 2 4, 2 6, 2 4, 0 4, 0 0))\n' >"$work/spike.wkt"
"$genbsp" visibility2d "$work/spike.wkt" --eye 2,6 -o "$work/spike-out.wkt" >"$work/summary"
check "visibility2d: at a spike's tip nothing is seen: an empty polygon" test "$(cat "$work/spike-out.wkt")" = "POLYGON EMPTY"
printf 'MULTILINESTRING ((2 -1, 2 1), (4 -3, 4 3))\n' >"$work/walls.wkt"
"$genbsp" visibility2d "$work/walls.wkt" --eye 0,0 -o "$work/open.wkt" >"$work/summary" 2>"$work/err"
check "visibility2d: unbounded view reported" test "$(summary_field bounded <"$work/summary")" = "False"
check "visibility2d: and clipped to a box, said on stderr" grep -q 'unbounded' "$work/err"
"$genbsp" visibility2d "$work/walls.wkt" --eye 0,0 --box -10,-10,10,10 -o "$work/boxed.wkt" >"$work/summary"
check "visibility2d --box: bounded by the box" test "$(summary_field bounded <"$work/summary")" = "True"
expect_error "visibility2d: eye outside the box" "outside --box" "$genbsp" visibility2d "$work/walls.wkt" --eye 20,0 --box -10,-10,10,10 -o "$work/x.wkt"
expect_error "visibility2d: a bad eye" "--eye" "$genbsp" visibility2d "$work/room.wkt" --eye 1,2,3 -o "$work/x.wkt"
printf 'MULTILINESTRING ((2 -1, 2 1), (4 -3))\n' >"$work/bad-walls.wkt"
expect_error "visibility2d: a one-point line string" "bad-walls.wkt:1: .*at least 2 positions" "$genbsp" visibility2d "$work/bad-walls.wkt" --eye 0,0 -o "$work/x.wkt"
expect_error "visibility2d: unknown output format" "unknown output format" "$genbsp" visibility2d "$work/room.wkt" --eye 1,5 -o "$work/x.png"
check "visibility2d: no file after an error" test ! -e "$work/x.wkt"

# Hidden lines: a cube seen from near a corner shows 6 silhouette and 3
# crease edges; its 3 far edges are hidden creases.
box -1 -1 -1 1 1 1 >"$work/cube.off"
line_count() { # line_count SUMMARY visible|hidden CLASS: edges of that class in the first view
  python3 -c 'import json, sys; v = json.load(open(sys.argv[1]))["views"][0][sys.argv[2]]; print(v.get(sys.argv[3], {}).get("edges", 0))' "$@"
}
"$genbsp" render "$work/cube.off" --eye 3,4,5 --style lines --hidden dashed -o "$work/lines.svg" >"$work/lines.json"
check "render --hidden dashed: 6 silhouette, 3 crease edges visible" test "$(line_count "$work/lines.json" visible silhouette) $(line_count "$work/lines.json" visible crease)" = "6 3"
check "render --hidden dashed: 3 crease edges hidden" test "$(line_count "$work/lines.json" hidden crease)" = 3
check "render --hidden dashed: dashes" grep -q 'stroke-dasharray' "$work/lines.svg"
check "render --hidden dashed: layers" test "$(grep -c 'inkscape:groupmode="layer"' "$work/lines.svg")" -eq 3
check "render lines: pen travel shortened" python3 -c 'import json, sys; t = json.load(open(sys.argv[1]))["views"][0]["pen_travel_px"]; assert t["after"] < t["before"]' "$work/lines.json"
"$genbsp" render "$work/cube.off" --eye 3,4,5 --style lines -o "$work/lines-none.svg" >"$work/summary"
check "render lines: hidden lines left out by default" test "$(grep -c 'id="hidden-' "$work/lines-none.svg")" -eq 0
"$genbsp" render "$work/cube.off" --eye 3,4,5 --style lines --hidden layer -o "$work/lines-layer.svg" >"$work/summary"
check "render --hidden layer: the hidden layer is in the file, not shown" grep -q 'id="hidden-crease"[^>]*display:none' "$work/lines-layer.svg"
"$genbsp" render "$work/cube.off" --eye 3,4,5 --style lines --hidden thin --split-layers --line-width 2 -o "$work/pens.svg" >"$work/pens.json"
for layer in visible-silhouette visible-crease hidden-crease; do
  check "render --split-layers: $layer in a file of its own" test "$(grep -c 'inkscape:groupmode="layer"' "$work/pens-$layer.svg" 2>/dev/null)" = 1
done
check "render --split-layers: the files listed" python3 -c 'import json, sys; assert len(json.load(open(sys.argv[1]))["layer_files"]) == 3' "$work/pens.json"
check "render --line-width: outlines 2 px wide" grep -q 'id="visible-silhouette"[^>]*stroke-width="2"' "$work/pens.svg"
"$genbsp" render "$work/cube.off" --eye 3,4,5 --style lines --hidden dashed --number double -o "$work/lines-double.svg" >"$work/double.json"
check "render lines --number double: the same lines" test "$(line_count "$work/double.json" visible silhouette) $(line_count "$work/double.json" hidden crease)" = "6 3"
"$genbsp" render "$work/cube.off" --view iso --style lines --hidden dashed -o "$work/iso.svg" >"$work/iso.json"
check "render lines, orthographic iso: 6 silhouette, 3 crease visible, 3 hidden" test "$(line_count "$work/iso.json" visible silhouette) $(line_count "$work/iso.json" visible crease) $(line_count "$work/iso.json" hidden crease)" = "6 3 3"
"$genbsp" render "$work/cube.off" --eye 3,4,5 --style lines --hidden dashed -o "$work/lines.pdf" >"$work/summary"
check "render lines: PDF" grep -q '^%PDF-' "$work/lines.pdf"
expect_error "render: --hidden without --style lines" "--hidden is for --style lines" "$genbsp" render "$work/cube.off" --eye 3,4,5 --hidden dashed -o "$work/x.svg"
expect_error "render: --split-layers without --style lines" "--split-layers is for --style lines" "$genbsp" render "$work/cube.off" --eye 3,4,5 --split-layers -o "$work/x.svg"
expect_error "render: --line-width without --style lines" "--line-width is for --style lines" "$genbsp" render "$work/cube.off" --eye 3,4,5 --line-width 2 -o "$work/x.svg"
expect_error "render: an unknown --hidden" "--hidden" "$genbsp" render "$work/cube.off" --eye 3,4,5 --style lines --hidden dotted -o "$work/x.svg"
check "render: no file after an error" test ! -e "$work/x.svg"

# --version: the version and the source revision; the same string in JSON summaries.
"$genbsp" --version >"$work/version"
check "--version exits 0 and names genbsp" grep -qE '^genbsp [0-9]+\.[0-9]+\.[0-9]+ \(.+\)$' "$work/version"
"$genbsp" stats "$work/scene.off" --eye 0,0,0 >"$work/summary"
check "stats: the version in the summary" test "genbsp $(summary_field genbsp <"$work/summary")" = "$(cat "$work/version")"

# Determinism: the same input gives byte-identical files, run after run (a
# PDF's creation date from SOURCE_DATE_EPOCH, else the time of writing).
export SOURCE_DATE_EPOCH=1764720000
for k in 1 2; do
  "$genbsp" map "$work/scene.off" --eye 0,0,1/3 -o "$work/det-$k.json" >/dev/null
  "$genbsp" render "$work/cube.off" --eye 3,4,5 --style lines --hidden dashed -o "$work/det-$k.svg" >/dev/null
  "$genbsp" render "$work/scene.off" --eye 0,0,0 --dir 0,0,1 --light 1,1,0 --shadows -o "$work/det-$k.pdf" >/dev/null
  "$genbsp" bool "$work/north.geojson" "$work/dateline.geojson" --geometry s2 --op union -o "$work/det-$k.geojson" >/dev/null
  "$genbsp" csg "$work/b1.off" "$work/b3.off" --op difference -o "$work/det-$k.off" >/dev/null
done
for ext in svg pdf geojson off; do
  check "determinism: $ext output identical in two runs" cmp -s "$work/det-1.$ext" "$work/det-2.$ext"
done
# A map file's statistics hold timings; all else is identical.
unset SOURCE_DATE_EPOCH
check "determinism: the PDF's creation date from SOURCE_DATE_EPOCH" grep -qa 'CreationDate (20251203000000Z)' "$work/det-1.pdf"
check "determinism: map files identical but for their timings" python3 -c 'import json, sys
a, b = (json.load(open(f)) for f in sys.argv[1:])
a.pop("stats"), b.pop("stats")
assert a == b' "$work/det-1.json" "$work/det-2.json"


# batch: one scene, many jobs; each job's files and numbers as the single commands give them.
mkdir -p "$work/batch"
cat >"$work/batch/jobs.json" <<'JSON'
{"scene": "../scene.off",
 "jobs": [
  {"id": "centre", "eye": [0, 0, 0], "stats": true, "map": "m0.json"},
  {"eye": ["1/3", 0.1, "-0.5"], "render": [{"output": "r1.svg", "size": [200, 150], "fov": 70}, {"output": "r1-lines.svg", "style": "lines", "hidden": "dashed"}]},
  {"id": 7, "eye": [0.2, -0.3, 0.5], "stats": true, "cull_backfaces": true},
  {"view_dir": [0, 0, 1], "map": "parallel.json"}
 ]}
JSON
"$genbsp" batch "$work/batch/jobs.json" --jobs 2 >"$work/batch/out1" 2>"$work/batch/err1"
check "batch: exit status 0" test $? -eq 0
check "batch: a line per job and a summary" test "$(wc -l <"$work/batch/out1")" -eq 5
"$genbsp" map "$work/scene.off" --eye 0,0,0 -o "$work/batch/m0-single.json"
"$genbsp" stats "$work/scene.off" --eye 0.2,-0.3,0.5 --cull-backfaces >"$work/batch/s2-single.json"
"$genbsp" render "$work/scene.off" --eye 1/3,0.1,-0.5 --size 200x150 --fov 70 -o "$work/batch/r1-single.svg"
"$genbsp" render "$work/scene.off" --eye 1/3,0.1,-0.5 --style lines --hidden dashed -o "$work/batch/r1-lines-single.svg" >/dev/null
"$genbsp" map "$work/scene.off" --view-dir 0,0,1 -o "$work/batch/parallel-single.json"
check "batch: the image is the single command's" cmp -s "$work/batch/r1.svg" "$work/batch/r1-single.svg"
check "batch: the line drawing is the single command's" cmp -s "$work/batch/r1-lines.svg" "$work/batch/r1-lines-single.svg"
check "batch: maps and stats are the single commands'" python3 - "$work/batch" <<'PY'
import json, sys, os
d = sys.argv[1]
lines = [json.loads(l) for l in open(os.path.join(d, "out1"))]
jobs = {l["job"]: l for l in lines if "job" in l}
summary = lines[-1]["summary"]
assert summary["jobs"] == 4 and summary["ok"] == 4 and summary["failed"] == 0 and summary["workers"] == 2, summary
assert all(j["ok"] for j in jobs.values())
assert jobs[0]["id"] == "centre" and jobs[2]["id"] == 7 and "id" not in jobs[1]
def strip(m):
    m = dict(m); m.pop("stats"); return m
for a, b in (("m0.json", "m0-single.json"), ("parallel.json", "parallel-single.json")):
    assert strip(json.load(open(os.path.join(d, a)))) == strip(json.load(open(os.path.join(d, b)))), a
single = json.load(open(os.path.join(d, "s2-single.json")))
for key in ("map", "map_unsimplified", "discarded_backfacing", "fragments", "visible_pieces"):
    assert jobs[2]["stats"][key] == single[key], key
assert jobs[0]["stats"]["map"] == json.load(open(os.path.join(d, "m0-single.json")))["stats"]["map"]
assert jobs[0]["outputs"] == [os.path.join(d, "m0.json")]
assert jobs[1]["render"][0]["views"][0]["output"] == os.path.join(d, "r1-lines.svg") and jobs[1]["render"][0]["views"][0]["visible"]["silhouette"]["edges"] > 0
PY
"$genbsp" batch "$work/batch/jobs.json" --jobs 1 >"$work/batch/out2"
check "batch: one thread gives the same results as two" python3 - "$work/batch/out1" "$work/batch/out2" <<'PY'
import json, sys
def results(f):
    out = {}
    for l in open(f):
        j = json.loads(l)
        if "job" in j:
            j.pop("seconds")
            if "stats" in j:
                j["stats"] = {k: v for k, v in j["stats"].items() if "seconds" not in k and k != "peak_bytes"}
            for r in j.get("render", []):
                for v in r.get("views", []): v.pop("seconds")
            out[j["job"]] = j
    return out
assert results(sys.argv[1]) == results(sys.argv[2])
PY
"$genbsp" batch "$work/batch/jobs.json" --shard 0/3 >"$work/batch/shard0"
"$genbsp" batch "$work/batch/jobs.json" --shard 1/3 >"$work/batch/shard1"
"$genbsp" batch "$work/batch/jobs.json" --shard 2/3 >"$work/batch/shard2"
check "batch: three shards run every job once" test "$(cat "$work"/batch/shard? | grep -o '"job":[0-9]*' | sort | tr '\n' ' ')" = '"job":0 "job":1 "job":2 "job":3 '
"$genbsp" batch "$work/batch/jobs.json" --progress >/dev/null 2>"$work/batch/progress"
check "batch: --progress counts the jobs on standard error" grep -q 'genbsp: batch 4/4 jobs, 0 failed' "$work/batch/progress"
check "batch: a shard's summary names it" grep -q '"shard":"1/3"' "$work/batch/shard1"
# A job that fails while running: its status 2, its files gone, the other jobs done.
cat >"$work/batch/fails.json" <<JSON
{"scene": "$work/scene.off", "jobs": [
  {"eye": [0, 0, 0], "map": "kept.json"},
  {"eye": [0, 0, 0], "map": "dropped.json", "render": {"output": "no/such/folder/dropped.svg"}}]}
JSON
"$genbsp" batch "$work/batch/fails.json" >"$work/batch/out3" 2>/dev/null
check "batch: a failed job makes exit status 2" test $? -eq 2
check "batch: the failed job says why" grep -q '"job":1,"ok":false,"error":"[^"]*dropped.svg: cannot write' "$work/batch/out3"
check "batch: the other job's file is written" test -s "$work/batch/kept.json"
check "batch: the failed job's files are removed" test ! -e "$work/batch/dropped.json"
# Every file a render writes is its job's: a cube map's faces and split layers too.
cat >"$work/batch/many.json" <<JSON
{"scene": "$work/scene.off", "jobs": [
  {"eye": [0, 0, 0], "render": [{"output": "cube.svg", "projection": "cube", "size": [64, 64]},
                                {"output": "layers.svg", "style": "lines", "split_layers": true},
                                {"output": "nowhere/last.svg"}]}]}
JSON
"$genbsp" batch "$work/batch/many.json" >"$work/batch/out4" 2>/dev/null
check "batch: a job failing after a cube map and split layers" grep -q '"job":0,"ok":false' "$work/batch/out4"
check "batch: the cube map's faces and the layers are removed" test -z "$(ls "$work/batch" | grep -E '^(cube|layers)')"
sed 's|"output": "nowhere/last.svg"|"output": "last.svg"|' "$work/batch/many.json" >"$work/batch/many-ok.json"
"$genbsp" batch "$work/batch/many-ok.json" >"$work/batch/out5"
check "batch: a cube map writes six faces" test "$(ls "$work/batch" | grep -cE '^cube-(front|right|back|left|up|down)\.svg$')" -eq 6
check "batch: split layers are written and reported" python3 - "$work/batch" <<'PY'
import json, os, sys
d = sys.argv[1]
job = json.loads(open(os.path.join(d, "out5")).readline())
layers = sorted(f for f in os.listdir(d) if f.startswith("layers-"))
reported = sorted(os.path.basename(f) for f in job["outputs"] if os.path.basename(f).startswith("layers-"))
assert layers and reported == layers, (layers, reported)
assert sorted(os.path.basename(f) for r in job["render"] for f in r.get("layer_files", [])) == layers
PY
echo '{"scene": "../scene.off", "jobs": [{"eye": [0, 0, 0], "render": {"output": "c.svg", "projection": "cube"}}, {"eye": [1, 0, 0], "render": {"output": "c-back.svg"}}]}' >"$work/batch/face.json"
expect_error "batch: a file that is a cube map's face" 'job 1: image .*c-back.svg is written by job 0 too' "$genbsp" batch "$work/batch/face.json"
echo '{"scene": "../scene.off", "jobs": [{"eye": [0, 0, 0], "render": {"output": "l.svg", "style": "lines", "split-layers": true}}, {"eye": [1, 0, 0], "map": "l-hidden-crease.svg"}]}' >"$work/batch/layer.json"
expect_error "batch: a file that is a split layer" 'job 1: map .*l-hidden-crease.svg is written by job 0 too' "$genbsp" batch "$work/batch/layer.json"
echo '{"scene": "../scene.off", "jobs": [{"eye": [0, 0, 0], "rendr": {}}]}' >"$work/batch/typo.json"
expect_error "batch: unknown key" 'typo.json: job 0: unknown key "rendr"' "$genbsp" batch "$work/batch/typo.json"
echo '{"scene": "../scene.off", "jobs": [{"eye": [0, 0, 0], "stats": true}, {"eye": [1, 0, 0], "render": {"output": "x.svg", "fov": 400}}]}' >"$work/batch/range.json"
expect_error "batch: a bad option fails before any job runs" 'range.json: job 1.render: --fov' "$genbsp" batch "$work/batch/range.json"
# What a command checks before it reads its scene is checked before any job runs, with its place.
echo '{"scene": "../scene.off", "jobs": [{"eye": [0, 0, 0], "stats": true}, {"eye": [1, 0, 0], "render": [{"output": "a.svg"}, {"output": "b.txt"}]}]}' >"$work/batch/ext.json"
expect_error "batch: a bad image extension, before any job runs" "ext.json: job 1.render\\[1\\]: .*b.txt: unknown output format" "$genbsp" batch "$work/batch/ext.json"
echo '{"scene": "../scene.off", "jobs": [{"eye": [0, 0, 0], "map": "m.json", "up": [0, 0, 1]}]}' >"$work/batch/up.json"
expect_error "batch: up without view_dir, before any job runs" 'up.json: job 0: --up is for --view-dir' "$genbsp" batch "$work/batch/up.json"
echo '{"scene": "../scene.off", "jobs": [{"eye": [0, 0, 0], "render": {"output": "h.svg", "help": true}}]}' >"$work/batch/help.json"
expect_error "batch: help is no render option" 'help.json: job 0.render.help: not a render option' "$genbsp" batch "$work/batch/help.json"
echo '{"scene": "../scene.off", "jobs": [{"eye": [0, 0, 0], "stats": true}, {"eye": ["1", "2/0", 0], "stats": true}]}' >"$work/batch/badeye.json"
expect_error "batch: an eye that is no number, before any job runs" 'badeye.json: job 1' "$genbsp" batch "$work/batch/badeye.json"
check "batch: no file from a manifest refused" test ! -e "$work/batch/a.svg" -a ! -e "$work/batch/m.json"
check "batch: nothing printed when the manifest is bad" test ! -s "$work/out"
echo '{"scene": "../scene.off", "jobs": [{"eye": [0, 0, 0], "map": "same.json"}, {"eye": [1, 0, 0], "map": "./same.json"}]}' >"$work/batch/twice.json"
expect_error "batch: two jobs writing one file" 'job 1: map .*same.json is written by job 0 too' "$genbsp" batch "$work/batch/twice.json"
printf '{"scene": "../scene.off",\n "jobs": [\n  {"eye": [0, 0, 0],}]}\n' >"$work/batch/broken.json"
expect_error "batch: not JSON, with its line" 'broken.json:3: not JSON' "$genbsp" batch "$work/batch/broken.json"
echo '{"scene": "../scene.off", "jobs": [{"eye": [0, 0], "stats": true}]}' >"$work/batch/eye.json"
expect_error "batch: an eye of two numbers" 'job 0.eye: expected an array of 3 numbers' "$genbsp" batch "$work/batch/eye.json"
expect_error "batch: a bad shard" '--shard: expected 0 <= I < N' "$genbsp" batch "$work/batch/jobs.json" --shard 3/3
echo '{"scene": "nothere.off", "jobs": [{"eye": [0, 0, 0], "stats": true}]}' >"$work/batch/missing.json"
expect_error "batch: a missing scene" 'nothere.off' "$genbsp" batch "$work/batch/missing.json"

# explain: the steps of building and merging, each a picture and a trace entry; the
# last picture's cells are the library's direct result.
mkdir -p "$work/explain"
cat >"$work/explain/a.wkt" <<'WKT'
POLYGON((0 0, 4 0, 4 3, 0 3, 0 0), (1 1, 1 2, 2 2, 2 1, 1 1))
WKT
echo 'POLYGON((2 -1, 6 1, 3 5, 2 -1))' >"$work/explain/b.wkt"
printf '0 1\n2 3.5  # a comment\n5 6\n' >"$work/explain/a.e1"
printf '0.5 2.5\n' >"$work/explain/b.e1"
printf '1,0 0,1\n-1,0 0,-1\n' >"$work/explain/a.s1"
printf '1,1 -1,1\n' >"$work/explain/b.s1"
ex="$work/explain"
quiet "$genbsp" explain build "$ex/a.wkt" -o "$ex/build-e2"
check "explain build e2: exit status 0" test $? -eq 0
quiet "$genbsp" explain merge "$ex/a.wkt" "$ex/b.wkt" --op difference -o "$ex/merge-e2"
"$genbsp" bool "$ex/a.wkt" "$ex/b.wkt" --op difference -o "$ex/difference.wkt" >"$ex/difference.json"
"$genbsp" bool "$ex/a.wkt" "$ex/a.wkt" --op union -o "$ex/same.wkt" >"$ex/same.json"
cat >"$ex/a.geojson" <<'JSON'
{"type": "Polygon", "coordinates": [[[0, 0], [40, 0], [40, 30], [0, 30], [0, 0]], [[10, 10], [10, 20], [20, 20], [20, 10], [10, 10]]]}
JSON
echo '{"type": "Polygon", "coordinates": [[[20, -10], [60, 10], [30, 50], [20, -10]]]}' >"$ex/b.geojson"
quiet "$genbsp" explain build "$ex/a.geojson" -o "$ex/build-s2"
quiet "$genbsp" explain merge "$ex/a.geojson" "$ex/b.geojson" --op intersection -o "$ex/merge-s2"
"$genbsp" bool "$ex/a.geojson" "$ex/a.geojson" --geometry s2 --op union -o "$ex/same-s2.geojson" >"$ex/same-s2.json"
"$genbsp" bool "$ex/a.geojson" "$ex/b.geojson" --geometry s2 --op intersection -o "$ex/and-s2.geojson" >"$ex/and-s2.json"
quiet "$genbsp" explain build "$ex/a.e1" -o "$ex/build-e1"
quiet "$genbsp" explain merge "$ex/a.e1" "$ex/b.e1" --op xor -o "$ex/merge-e1"
quiet "$genbsp" explain build "$ex/a.s1" -o "$ex/build-s1"
quiet "$genbsp" explain merge "$ex/a.s1" "$ex/b.s1" -o "$ex/merge-s1"
check "explain: steps, pictures and trace agree; the last step is the library's result" python3 - "$ex" <<'PY'
import json, math, os, sys
import xml.etree.ElementTree as ET
from fractions import Fraction
d = sys.argv[1]
def inside(step, key):
    return sum(Fraction(c[key]) if isinstance(c[key], str) else c[key] for c in step["cells"] if c["label"] is True)
for run in ("build-e2", "merge-e2", "build-e1", "merge-e1", "build-s1", "merge-s1", "build-s2", "merge-s2"):
    folder = os.path.join(d, run)
    trace = json.load(open(os.path.join(folder, "trace.json")))
    pictures = sorted(f for f in os.listdir(folder) if f.startswith("step-"))
    steps = trace["steps"]
    assert len(pictures) == len(steps) and [s["picture"] for s in steps] == pictures, run
    assert [s["step"] for s in steps] == list(range(len(steps))), run
    html = open(os.path.join(folder, "index.html")).read()
    assert all(p in html for p in pictures), run
    for s in steps:
        svg = ET.parse(os.path.join(folder, s["picture"])).getroot()   # well-formed, or this raises
        drawn = sorted((e.get("data-cell"), e.get("data-label")) for e in svg.iter() if e.get("data-cell"))
        listed = sorted((c["node"], "pending" if c["pending"] else ("in" if c["label"] else "out")) for c in s["cells"])
        assert drawn == listed, (run, s["step"])
    last = steps[-1]
    assert not any(c["pending"] for c in last["cells"]), run
    assert len(last["cells"]) == trace["result"]["cells"], run
    if run.startswith("build"):
        assert steps[0]["operation"] == "start" and len(steps[0]["cells"]) == 1 and steps[0]["cells"][0]["pending"], run
        assert len(steps) == trace["result"]["interior_nodes"] + 1, run
        for k, s in enumerate(steps[1:]):
            assert s["operation"] == "split" and s["node"] == f"node {k}", run
    else:
        assert [s["phase"] for s in steps[:2]] == ["a", "b"] and steps[-1]["phase"] == "reduce", run
def area(summary):
    return Fraction(json.load(open(os.path.join(d, summary)))["area_exact"])
t = lambda run: json.load(open(os.path.join(d, run, "trace.json")))["steps"][-1]
assert inside(t("build-e2"), "area") == area("same.json") == 11
assert inside(t("merge-e2"), "area") == area("difference.json") == Fraction(25, 4)
assert inside(t("build-e1"), "length") == Fraction(7, 2)
assert inside(t("merge-e1"), "length") == Fraction(7, 2)   # [0,.5] [1,2] [2.5,3.5] [5,6]
assert abs(inside(t("build-s1"), "length") - math.pi) < 1e-12
assert abs(inside(t("merge-s1"), "length") - 5 * math.pi / 4) < 1e-12
sr = lambda summary: json.load(open(os.path.join(d, summary)))["area"]
assert abs(inside(t("build-s2"), "area") - sr("same-s2.json")) < 1e-12
assert abs(inside(t("merge-s2"), "area") - sr("and-s2.json")) < 1e-12 and sr("and-s2.json") > 0.01
PY
# Depth order: the segments front to back from the eye, checked against rays cast
# exactly between every pair, and every segment listed.
cat >"$ex/walls.wkt" <<'WKT'
GEOMETRYCOLLECTION(LINESTRING(1 1, 4 2), LINESTRING(2 3, 5 0), LINESTRING(0 4, 3 5),
  POLYGON((5 3, 6 3, 6 4, 5 4, 5 3)), LINESTRING(-1 2, 0 2, 1 2))
WKT
quiet "$genbsp" explain depth-order "$ex/walls.wkt" --eye 0,0 -o "$ex/depth"
check "explain depth-order: exit status 0" test $? -eq 0
check "explain depth-order: front to back along every ray" python3 - "$ex/depth" <<'PY'
import json, os, sys
import xml.etree.ElementTree as ET
from fractions import Fraction as F
d = sys.argv[1]
trace = json.load(open(os.path.join(d, "trace.json")))
order = trace["result"]["order"]
eye = [F(x) for x in trace["eye"]]
steps = trace["steps"]
assert len(steps) == len([f for f in os.listdir(d) if f.startswith("step-")])
assert len(steps) == trace["result"]["interior_nodes"] + 1 + len(order)
assert [s["segment"] for s in steps if s["operation"] == "emit"] == [o["segment"] for o in order]
assert {o["segment"] for o in order} == set(range(9))     # 4 polygon edges, 5 line segments
for s in steps:
    ET.parse(os.path.join(d, s["picture"]))
last = ET.parse(os.path.join(d, steps[-1]["picture"])).getroot()
assert sorted(int(e.get("data-rank")) for e in last.iter() if e.get("data-rank")) == list(range(len(order)))
def vec(p): return (F(p[0]) - eye[0], F(p[1]) - eye[1])
def cross(a, b): return a[0] * b[1] - a[1] * b[0]
def wedge(piece):
    p, q = vec(piece[0]), vec(piece[1])
    c = cross(p, q)
    return None if c == 0 else ((p, q) if c > 0 else (q, p))
def inside(v, w): return cross(w[0], v) > 0 and cross(v, w[1]) > 0
def hit(v, piece):   # t with eye + t v on the segment
    a, b = vec(piece[0]), vec(piece[1])
    e = (b[0] - a[0], b[1] - a[1])
    return cross(a, e) / cross(v, e)
pieces = [o["piece"] for o in order]
checked = 0
for i in range(len(pieces)):
    for j in range(i + 1, len(pieces)):
        wi, wj = wedge(pieces[i]), wedge(pieces[j])
        if not wi or not wj:
            continue
        ends = [vec(p) for p in pieces[i] + pieces[j]]
        for a in range(4):
            for b in range(a + 1, 4):
                v = (ends[a][0] + ends[b][0], ends[a][1] + ends[b][1])
                if inside(v, wi) and inside(v, wj):
                    checked += 1
                    assert hit(v, pieces[i]) <= hit(v, pieces[j]), (i, j)
assert checked > 10, checked
PY
expect_error "explain depth-order: an eye of one number" '--eye' "$genbsp" explain depth-order "$ex/walls.wkt" --eye 1 -o "$ex/o"
# 2D visibility: what is seen only grows as pieces arrive front to back, and
# the last step is genbsp visibility2d's region.
cat >"$ex/room.wkt" <<'WKT'
GEOMETRYCOLLECTION(POLYGON((0 0, 10 0, 10 8, 0 8, 0 0)), LINESTRING(3 2, 3 6), LINESTRING(5 5, 8 5), LINESTRING(6 1, 7 3))
WKT
quiet "$genbsp" explain visibility2d "$ex/room.wkt" --eye 1,4 -o "$ex/seen"
check "explain visibility2d: exit status 0" test $? -eq 0
"$genbsp" visibility2d "$ex/room.wkt" --eye 1,4 -o "$ex/seen.wkt" >"$ex/seen.json"
check "explain visibility2d: growing front to back, ending as genbsp visibility2d" python3 - "$ex/seen" "$ex/seen.json" <<'PY'
import json, math, os, sys
import xml.etree.ElementTree as ET
from fractions import Fraction as F
d = sys.argv[1]
trace = json.load(open(os.path.join(d, "trace.json")))
steps = trace["steps"]
assert len(steps) == trace["result"]["fragments"] + 1 == len([f for f in os.listdir(d) if f.startswith("step-")])
for s in steps:
    ET.parse(os.path.join(d, s["picture"]))
assert F(trace["result"]["area"]) == F(json.load(open(sys.argv[2]))["area_exact"])
assert trace["result"]["bounded"] and steps[0]["arcs"] == [{"from": None, "to": None, "segment": None, "rank": None}]
def angle(p): return math.atan2(float(F(p[1])), float(F(p[0])))
def seen(arcs, t):   # the segment seen in direction t (radians), None for nothing
    for a in arcs:
        if a["from"] is None:
            return a["segment"]
        t0, t1 = angle(a["from"]), angle(a["to"])
        if (t - t0) % (2 * math.pi) < (t1 - t0) % (2 * math.pi) or (t1 - t0) % (2 * math.pi) == 0:
            return a["segment"]
    raise AssertionError("the arcs do not cover the circle")
probes = [2 * math.pi * (k + 0.37) / 720 for k in range(720)]
before = [None] * len(probes)
for s in steps[1:]:
    now = [seen(s["arcs"], t) for t in probes]
    assert all(b is None or b == n for b, n in zip(before, now)), s["step"]   # what was seen stays seen
    before = now
assert None not in before
PY
expect_error "explain visibility2d: an eye on a wall" '--eye: on segment 4' "$genbsp" explain visibility2d "$ex/room.wkt" --eye 3,3 -o "$ex/o"
# The spherical visibility map growing: each fragment's area fixed once it
# arrives, 4 pi in all at every step, and the last map that of genbsp map,
# polygon by polygon, by areas computed here from each map's cycles.
python3 - "$ex/blocks.off" <<'PY'
import sys
v = [(-4,-4,0),(4,-4,0),(4,4,0),(-4,4,0),(-1,-1,0),(1,-1,0),(1,1,0),(-1,1,0),(-1,-1,2),(1,-1,2),(1,1,2),(-1,1,2),
     (1,2,0),(3,2,0),(3,3,0),(1,3,0),(1,2,4),(3,2,4),(3,3,4),(1,3,4)]
f = [(0,1,2,3),(4,5,9,8),(5,6,10,9),(7,4,8,11),(8,9,10,11),(6,7,11,10),(12,13,17,16),(13,14,18,17),(15,12,16,19),(16,17,18,19),(14,15,19,18)]
with open(sys.argv[1], "w") as o:
    o.write("OFF\n%d %d 0\n" % (len(v), len(f)))
    o.writelines("%d %d %d\n" % p for p in v)
    o.writelines("4 %d %d %d %d\n" % q for q in f)
PY
quiet "$genbsp" explain visibility "$ex/blocks.off" --eye 6,-7,5 --projection equirectangular -o "$ex/svm"
check "explain visibility: exit status 0" test $? -eq 0
"$genbsp" map "$ex/blocks.off" --eye 6,-7,5 -o "$ex/blocks-map.json" >/dev/null
check "explain visibility: growing front to back, ending as genbsp map" python3 - "$ex/svm" "$ex/blocks-map.json" <<'PY'
import json, math, os, sys
import xml.etree.ElementTree as ET
d = sys.argv[1]
trace = json.load(open(os.path.join(d, "trace.json")))
steps = trace["steps"]
assert trace["projection"] == "equirectangular"
assert len(steps) == trace["result"]["fragments"] + 1 == len([f for f in os.listdir(d) if f.startswith("step-")])
assert trace["result"]["fragments"] >= trace["result"]["polygons"] == 11
for s in steps:
    ET.parse(os.path.join(d, s["picture"]))
    total = sum(x["area"] for x in s["seen"]) + s["free_area"] + s["clipped_area"]
    assert abs(total - 4 * math.pi) < 1e-9, (s["step"], total)
    assert s["clipped_area"] == 0
assert steps[0]["seen"] == [] and abs(steps[0]["free_area"] - 4 * math.pi) < 1e-12
fixed = {}
for s in steps[1:]:
    now = {x["rank"]: x["area"] for x in s["seen"]}
    assert all(r < s["step"] for r in now)
    for r, a in fixed.items():   # what was seen stays seen, and no more of it
        assert abs(now.get(r, 0) - a) < 1e-12, (s["step"], r)
    assert s["visible"] == (s["rank"] in now)
    fixed = now
def areas(path):   # per polygon, by Gauss-Bonnet on each face's cycles of minor arcs
    m = json.load(open(path))
    V = m["vertices"]
    def sub(a, b): return [a[i] - b[i] for i in range(3)]
    def dot(a, b): return sum(a[i] * b[i] for i in range(3))
    def cross(a, b): return [a[1]*b[2]-a[2]*b[1], a[2]*b[0]-a[0]*b[2], a[0]*b[1]-a[1]*b[0]]
    def toward(p, q): return sub(q, [dot(p, q) * x for x in p])
    out = {}
    for face in m["faces"]:
        turning = 0
        for c in face["cycles"]:
            for i in range(len(c)):
                a, p, b = V[c[i - 1]], V[c[i]], V[c[(i + 1) % len(c)]]
                tin, tout = [-x for x in toward(p, a)], toward(p, b)
                turning += math.atan2(dot(cross(tin, tout), p), dot(tin, tout))
        area = 4 * math.pi if not face["cycles"] else 2 * math.pi * (2 - len(face["cycles"])) - turning
        out[face["polygon"]] = out.get(face["polygon"], 0) + area
    return out, len(m["faces"])
mine, mine_faces = areas(os.path.join(d, trace["result"]["map"]))
theirs, their_faces = areas(sys.argv[2])
assert mine_faces == their_faces == trace["result"]["faces"], (mine_faces, their_faces)
assert mine.keys() == theirs.keys() and all(abs(mine[p] - theirs[p]) < 1e-9 for p in mine), (mine, theirs)
last = {}
for x in steps[-1]["seen"]:
    last[x["polygon"]] = last.get(x["polygon"], 0) + x["area"]
last[-1] = steps[-1]["free_area"]
assert all(abs(last.get(p, 0) - theirs[p]) < 1e-9 for p in theirs) and len([p for p in theirs if p >= 0]) >= 6
PY
quiet "$genbsp" explain visibility "$ex/blocks.off" --eye 6,-7,5 -o "$ex/svm-auto"
check "explain visibility: a perspective towards the scene by default, clipped to it" python3 -c '
import json, sys; t = json.load(open(sys.argv[1]))
assert t["projection"] == "perspective" and t["steps"][-1]["clipped_area"] > 0' "$ex/svm-auto/trace.json"
quiet "$genbsp" explain visibility "$ex/blocks.off" --view-dir -1,1,-1 -o "$ex/svm-parallel"
check "explain visibility --view-dir: exit status 0" test $? -eq 0
"$genbsp" map "$ex/blocks.off" --view-dir -1,1,-1 -o "$ex/blocks-parallel.json" >/dev/null
check "explain visibility --view-dir: the last map is genbsp map --view-dir's, area by area in the view plane" python3 - "$ex/svm-parallel" "$ex/blocks-parallel.json" <<'PY'
import json, os, sys
d = sys.argv[1]
trace = json.load(open(os.path.join(d, "trace.json")))
assert trace["projection"] == "orthographic" and trace["view_dir"] == ["-1", "1", "-1"]
def areas(path):   # per polygon: the signed areas of its faces' cycles (holes turn the other way)
    m = json.load(open(path))
    V, out = m["vertices"], {}
    for face in m["faces"]:
        for c in face["cycles"]:
            a = sum(V[c[i - 1]][0] * V[c[i]][1] - V[c[i]][0] * V[c[i - 1]][1] for i in range(len(c))) / 2
            out[face["polygon"]] = out.get(face["polygon"], 0) + a
    return out, len(m["faces"]), len(m["vertices"])
mine, theirs = areas(os.path.join(d, "map.json")), areas(sys.argv[2])
assert mine[1:] == theirs[1:], (mine[1:], theirs[1:])
assert mine[0].keys() == theirs[0].keys() and all(abs(mine[0][p] - theirs[0][p]) < 1e-9 for p in mine[0] if p >= 0)
assert sum(1 for p in theirs[0] if p >= 0 and theirs[0][p] > 0.1) >= 6
PY
expect_error "explain visibility: --eye and --view-dir" 'give --eye X,Y,Z or --view-dir' "$genbsp" explain visibility "$ex/blocks.off" --eye 1,2,3 --view-dir 1,0,0 -o "$ex/o"
"$genbsp" scene sphere --n 9 -o "$ex/sphere.off" >/dev/null
expect_error "explain visibility: too many polygons" 'sphere.off: 288 convex polygons; explain draws at most 200' "$genbsp" explain visibility "$ex/sphere.off" --eye 0,0,5 -o "$ex/o"
expect_error "explain visibility: an eye of two numbers" '--eye' "$genbsp" explain visibility "$ex/blocks.off" --eye 1,2 -o "$ex/o"
# Solids (E3): the cube's tree ends with its volume inside, and the merge
# with the volume genbsp csg gives; both checked exactly.
printf 'OFF\n8 6 0\n0 0 0\n2 0 0\n2 2 0\n0 2 0\n0 0 2\n2 0 2\n2 2 2\n0 2 2\n4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n' >"$ex/cube.off"
printf 'OFF\n4 4 0\n1 1 1\n3 1 1\n1 3 1\n1 1 3\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n' >"$ex/tet.off"
quiet "$genbsp" explain build "$ex/cube.off" -o "$ex/build-e3"
check "explain build (e3): exit status 0" test $? -eq 0
quiet "$genbsp" explain merge "$ex/cube.off" "$ex/tet.off" --op difference -o "$ex/merge-e3"
check "explain merge (e3): exit status 0" test $? -eq 0
"$genbsp" csg "$ex/cube.off" "$ex/tet.off" --op difference -o "$ex/cube-tet.off" >"$ex/csg.json"
# Boxes whose corners compare differently coordinate by coordinate and as words.
printf 'OFF\n8 6 0\n0 5 0\n1 5 0\n1 6 0\n0 6 0\n0 5 1\n1 5 1\n1 6 1\n0 6 1\n4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n' >"$ex/box-a.off"
printf 'OFF\n8 6 0\n1 0 0\n2 0 0\n2 1 0\n1 1 0\n1 0 1\n2 0 1\n2 1 1\n1 1 1\n4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n' >"$ex/box-b.off"
quiet "$genbsp" explain merge "$ex/box-a.off" "$ex/box-b.off" --op union -o "$ex/merge-boxes"
check "explain merge (e3): two boxes apart, in one frame" python3 -c '
import json, sys; from fractions import Fraction as F
t = json.load(open(sys.argv[1])); last = t["steps"][-1]
assert sum(F(c["volume"]) for c in last["cells"] if c["label"] is True) == 2' "$ex/merge-boxes/trace.json"
check "explain (e3): cells inside add up to the solids' volumes, exactly" python3 - "$ex" <<'PY'
import json, os, sys
import xml.etree.ElementTree as ET
from fractions import Fraction as F
ex = sys.argv[1]
def trace(name):
    t = json.load(open(os.path.join(ex, name, "trace.json")))
    assert t["geometry"] == "e3"
    for s in t["steps"]:
        ET.parse(os.path.join(ex, name, s["picture"]))
    assert len(t["steps"]) == len([f for f in os.listdir(os.path.join(ex, name)) if f.startswith("step-")])
    return t
def inside(step):
    return sum(F(c["volume"]) for c in step["cells"] if c["label"] is True)
b = trace("build-e3")
assert len(b["steps"]) == b["result"]["interior_nodes"] + 1 and b["result"]["cells"] == len(b["steps"][-1]["cells"])
assert inside(b["steps"][-1]) == 8
assert all(c["volume"] is None for c in b["steps"][-1]["cells"] if c["label"] is False)   # outside cells are unbounded
m = trace("merge-e3")
csg = F(json.load(open(os.path.join(ex, "csg.json")))["volume_exact"])
assert inside(m["steps"][-1]) == csg == F(43, 6), (inside(m["steps"][-1]), csg)
assert inside(m["steps"][0]) == 8 and inside(m["steps"][1]) == F(4, 3)   # the operands
root = ET.parse(os.path.join(ex, "build-e3", b["steps"][-1]["picture"])).getroot()
assert any(e.tag.endswith("path") and e.get("fill") not in (None, "none") for e in root.iter()), "no solid drawn"
first = ET.parse(os.path.join(ex, "build-e3", b["steps"][0]["picture"])).getroot()
assert not any(e.tag.endswith("path") and e.get("fill") not in (None, "none") for e in first.iter()), "a solid before any cell is inside"
PY
quiet "$genbsp" explain build "$ex/a.e1" -o "$ex/build-e2"
check "explain: a second run replaces the earlier pictures" test "$(ls "$ex/build-e2" | grep -c '^step-')" -eq 7
python3 -c "
import math
n = 201
print('POLYGON((' + ', '.join(f'{math.cos(2*math.pi*k/n):.6f} {math.sin(2*math.pi*k/n):.6f}' for k in list(range(n)) + [0]) + '))')" >"$ex/big.wkt"
expect_error "explain: too many hyperplanes" 'big.wkt: 201 boundary pieces; explain draws at most 200' "$genbsp" explain build "$ex/big.wkt" -o "$ex/big"
check "explain: nothing written for a refused input" test ! -e "$ex/big"
printf '0 1\n0.5 2\n' >"$ex/overlap.e1"
expect_error "explain: overlapping intervals" 'overlap.e1: the intervals overlap' "$genbsp" explain build "$ex/overlap.e1" -o "$ex/o"
printf '0 1\n2 x\n' >"$ex/bad.e1"
expect_error "explain: a bad number, with its line" 'bad.e1:2: not a number' "$genbsp" explain build "$ex/bad.e1" -o "$ex/o"
printf '1,0 2,0\n' >"$ex/same.s1"
expect_error "explain: an arc between one direction" 'same.s1:1: the two directions are the same' "$genbsp" explain build "$ex/same.s1" -o "$ex/o"
cp "$ex/a.e1" "$ex/a.txt"
expect_error "explain: an unknown extension" "cannot tell the geometry from '.txt'" "$genbsp" explain build "$ex/a.txt" -o "$ex/o"
expect_error "explain: operands of two geometries" 'different geometries' "$genbsp" explain merge "$ex/a.e1" "$ex/a.wkt" -o "$ex/o"
expect_error "explain: a missing subcommand" 'subcommand' "$genbsp" explain "$ex/a.e1" -o "$ex/o"

# Memory: --max-memory (or GENBSP_MAX_MEMORY) ends a run that needs more with
# one line and status 2, nothing written.  (Not under the address
# sanitizer, whose shadow memory is address space too: the sanitizer build
# sets GENBSP_SANITIZED, and ldd's list is read whole, never through a pipe
# that grep -q may close early, which pipefail would take for a failure.)
libraries=$(ldd "$genbsp" 2>/dev/null || true)
if [[ -n ${GENBSP_SANITIZED:-} || $libraries == *libasan* || $libraries == *libtsan* ]]; then
  echo "skip: --max-memory under a sanitizer"
else
  "$genbsp" scene sphere --n 60 -o "$work/sphere60.off" >/dev/null
  expect_error "--max-memory: a map past the limit" '^genbsp: out of memory \(--max-memory 64M\); nothing was written$' \
    "$genbsp" --max-memory 64M map "$work/sphere60.off" --eye 0.1,0.2,0.3 -o "$work/oom.json"
  check "--max-memory: no output file" test ! -e "$work/oom.json"
  expect_error "--max-memory after the subcommand" 'out of memory \(--max-memory 64M\)' \
    "$genbsp" render "$work/sphere60.off" --eye 0.1,0.2,0.3 -o "$work/oom.svg" --max-memory 64M
  check "--max-memory: no picture" test ! -e "$work/oom.svg"
  expect_error "GENBSP_MAX_MEMORY" 'out of memory \(--max-memory 64M\)' env GENBSP_MAX_MEMORY=64M "$genbsp" csg "$work/sphere60.off" "$work/sphere60.off" --op union -o "$work/oom.off"
  check "GENBSP_MAX_MEMORY: no mesh" test ! -e "$work/oom.off"
  # In a batch the job that runs out fails alone, its files gone, and the next one runs (on one
  # thread when the limit leaves no room for more).
  cat >"$work/oom-jobs.json" <<'JSON'
{"scene": "sphere60.off",
 "jobs": [{"eye": [0.1, 0.2, 0.3], "map": "oom-b0.json"},
          {"eye": [0, 0, 300000], "render": {"output": "oom-b1.svg", "size": [16, 16], "fov": 1, "dir": [0, 0, 1]}}]}
JSON
  "$genbsp" --max-memory 64M batch "$work/oom-jobs.json" >"$work/oom-batch.out" 2>"$work/oom-batch.err"
  check "--max-memory batch: status 2 (a job ran out)" test $? -eq 2
  check "--max-memory batch: the job that ran out says so, the other one is written" python3 - "$work/oom-batch.out" <<'PY'
import json, sys
lines = [json.loads(l) for l in open(sys.argv[1])]
assert lines[0] == {**lines[0], "job": 0, "ok": False, "error": "out of memory (--max-memory 64M)", "status": 2}, lines[0]
assert lines[1]["job"] == 1 and lines[1]["ok"], lines[1]
assert lines[2]["summary"]["failed"] == 1, lines[2]
PY
  check "--max-memory batch: no map from the job that ran out" test ! -e "$work/oom-b0.json"
  check "--max-memory batch: the other job's picture" test -s "$work/oom-b1.svg"
  "$genbsp" --max-memory 1G map "$work/sphere60.off" --eye 0.1,0.2,0.3 -o "$work/fits.json" >/dev/null
  check "--max-memory: a run within the limit writes its map" test -s "$work/fits.json"
fi
expect_error "--max-memory: not a size" "--max-memory: expected a size such as 512M or 2G, got '12Q'" "$genbsp" --max-memory 12Q scene random --n 2 -o "$work/x.off"
expect_error "--max-memory: too small" '--max-memory: at least 64M' "$genbsp" --max-memory 1M scene random --n 2 -o "$work/x.off"
for sub in map locate stats scene render view shadow bool csg visibility2d batch explain "explain build" "explain merge" "explain depth-order" "explain visibility2d" "explain visibility"; do
  "$genbsp" $sub --help >"$work/help" 2>&1
  check "$sub --help exits 0" test $? -eq 0
  check "$sub --help says what it does" grep -q "Usage" "$work/help"
done

echo "$passed passed, $failures failed"
test "$failures" -eq 0
