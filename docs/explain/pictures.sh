#!/usr/bin/env bash
# The pictures of docs/learning.md, made by `genbsp explain` from the inputs in
# this folder.  With --check, makes them in a temporary folder and fails when
# one differs from the committed docs/images/explain/ (a stale picture).
#
#   docs/explain/pictures.sh [--check] GENBSP
set -euo pipefail
check=0
if [[ ${1:-} == --check ]]; then check=1; shift; fi
genbsp=${1:?usage: pictures.sh [--check] GENBSP}
here=$(cd "$(dirname "$0")" && pwd)
images=$here/../images/explain
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

run() { "$genbsp" explain "$@" >/dev/null; }
run build "$here/square-with-hole.wkt" -o "$work/e2-build"
run merge "$here/square-with-hole.wkt" "$here/triangle.wkt" --op difference -o "$work/e2-merge"
run merge "$here/intervals-a.e1" "$here/intervals-b.e1" --op xor -o "$work/e1-merge"
run merge "$here/arcs-a.s1" "$here/arcs-b.s1" --op union -o "$work/s1-merge"
run depth-order "$here/walls.wkt" --eye 0,0 -o "$work/depth"
run merge "$here/region.geojson" "$here/triangle.geojson" --op intersection -o "$work/s2-merge"
run visibility2d "$here/room.wkt" --eye 1,4 -o "$work/seen"
run build "$here/cube.off" -o "$work/e3-build"
run merge "$here/cube.off" "$here/tetrahedron.off" --op difference -o "$work/e3-merge"
run visibility "$here/blocks.off" --eye 6,-7,5 -o "$work/svm"
run visibility "$here/blocks.off" --view-dir -1,1,-1 -o "$work/parallel"
run visibility "$here/blocks.off" --eye -3,-5,9 -o "$work/light"

# picture NAME RUN STEP: step STEP of RUN (a negative STEP counts from the end).
out=$work/pictures
mkdir -p "$out"
picture() {
  local files=("$work/$2"/step-*.svg) k=$3
  ((k < 0)) && k=$((${#files[@]} + k))
  cp "${files[$k]}" "$out/$1.svg"
}
picture e2-build-0 e2-build 0
picture e2-build-1 e2-build 1
picture e2-build-5 e2-build 5
picture e2-build-last e2-build -1
picture e2-merge-a e2-merge 0
picture e2-merge-b e2-merge 1
picture e2-merge-step e2-merge 12
picture e2-merge-result e2-merge -1
picture e1-merge-a e1-merge 0
picture e1-merge-b e1-merge 1
picture e1-merge-result e1-merge -1
picture s1-merge-a s1-merge 0
picture s1-merge-b s1-merge 1
picture s1-merge-result s1-merge -1
picture depth-build depth 8
picture depth-order-3 depth 11
picture depth-order-last depth -1
picture s2-merge-a s2-merge 0
picture s2-merge-step s2-merge 12
picture s2-merge-result s2-merge -1
picture e3-build-3 e3-build 3
picture e3-merge-step e3-merge 12
picture e3-merge-result e3-merge -1
picture seen-0 seen 0
picture seen-3 seen 3
picture seen-last seen -1
picture svm-3 svm 3
picture svm-5 svm 5
picture svm-last svm -1
picture svm-parallel parallel -1
picture shadow-light light -1
"$genbsp" render "$here/blocks.off" --eye 6,-7,5 --look 0,0.5,1 --fov 80 --light -3,-5,9 --shadows --size 480x360 -o "$out/shadow-eye.svg" >/dev/null

if ((check)); then
  status=0
  for f in "$out"/*.svg; do
    name=$(basename "$f")
    if ! cmp -s "$f" "$images/$name"; then
      echo "docs/images/explain/$name: stale (run docs/explain/pictures.sh $genbsp)" >&2
      status=1
    fi
  done
  for f in "$images"/*.svg; do
    [[ -e $out/$(basename "$f") ]] || { echo "docs/images/explain/$(basename "$f"): no longer made" >&2; status=1; }
  done
  exit $status
fi
mkdir -p "$images"
rm -f "$images"/*.svg
cp "$out"/*.svg "$images/"
echo "wrote $(ls "$out" | wc -l) pictures to docs/images/explain"
