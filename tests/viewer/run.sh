#!/usr/bin/env bash
# Browser test of the map viewer (web/viewer.html) in headless Chromium.
# Usage: tests/viewer/run.sh GENBSP_BINARY WORKDIR
#
# Needs node, Chromium at /usr/bin/chromium (Debian's package `chromium`;
# another binary with CHROMIUM=PATH) and the npm package playwright-core,
# found in WORKDIR/node_modules (npm install --prefix WORKDIR playwright-core)
# or anywhere node resolves it.  Installs nothing; exits 77 (skipped) when
# one of them is missing.  Prints one line per check and a last line
# "N passed, M failed"; exits 1 when a check failed.
#
# No check depends on the machine's speed: the frame times it measures are
# printed for information (the viewer benchmark, bench/viewer.mjs, has the
# target).  Environment: GENBSP_VIEWER_EMBED=1: make the pages with
# `genbsp map` and web/embed.mjs from web/viewer.html as it is on disk, not
# with `genbsp view` (which writes the copy compiled into it);
# GENBSP_VIEWER_SCREENSHOTS=DIR: also save the pictures of docs/viewer.md there.
set -uo pipefail

if (($# != 2)); then
  echo "usage: $0 GENBSP_BINARY WORKDIR" >&2
  exit 2
fi
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
genbsp=$1
work=$2
chromium=${CHROMIUM:-/usr/bin/chromium}

if ! command -v node >/dev/null 2>&1; then
  echo "SKIP: node is not installed (apt-get install nodejs)"
  exit 77
fi
if [[ ! -x $chromium ]]; then
  echo "SKIP: no Chromium at $chromium (apt-get install chromium)"
  exit 77
fi
mkdir -p "$work" || exit 2
if ! node -e 'require("module").createRequire(require("path").resolve(process.argv[1], "x.js")).resolve("playwright-core")' "$work" >/dev/null 2>&1; then
  echo "SKIP: the npm package playwright-core is not installed (npm install --prefix $work playwright-core)"
  exit 77
fi
if [[ ! -x $genbsp ]]; then
  echo "FAIL: $genbsp is not an executable"
  echo "0 passed, 1 failed"
  exit 1
fi

exec node "$here/run.mjs" --genbsp "$genbsp" --workdir "$work" --chromium "$chromium" --web "$here/../../web"
