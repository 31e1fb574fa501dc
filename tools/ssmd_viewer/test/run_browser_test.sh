#!/usr/bin/env bash
# Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
# SPDX-License-Identifier: GPL-3.0-or-later
# Runs check_page.mjs against a fresh ssmd_viewer: installs puppeteer-core and
# three.js into the build directory if needed (scripts/install_viewer_web.sh),
# starts the server on a free port, runs the test, stops the server.
#
#   run_browser_test.sh SSMD_VIEWER MESH BUILD_DIR [SERVER_OPTIONS...]
#
# Exits with 77 (skipped) when Chromium or Node.js is missing.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
viewer="$1" mesh="$2" build="$3"
shift 3

chromium="${CHROMIUM:-/usr/bin/chromium}"
if [ ! -x "$chromium" ] || ! command -v node >/dev/null 2>&1; then
  echo "skipped: the browser test needs Chromium ($chromium; Debian: apt-get install chromium) and Node.js"
  exit 77
fi
if ! bash "$here/../../../scripts/install_viewer_web.sh" "$build" --test; then
  echo "error: the npm packages of the browser test could not be installed (see above)" >&2
  exit 1
fi

log="$build/viewer_browser_test_server.log"
"$viewer" "$mesh" --port 0 --three-dir "$build/viewer_web/node_modules/three" "$@" > "$log" 2>&1 &
server=$!
trap 'kill $server 2>/dev/null || true' EXIT
url=""
for _ in $(seq 1 600); do
  url="$(grep -o 'http://127\.0\.0\.1:[0-9]*/' "$log" || true)"
  [ -n "$url" ] && break
  kill -0 $server 2>/dev/null || { cat "$log" >&2; exit 1; }
  sleep 0.1
done
[ -n "$url" ] || { echo "error: the server did not start" >&2; cat "$log" >&2; exit 1; }
echo "server: $url"
node "$here/check_page.mjs" "$url" "$build/viewer_web" "$build/viewer_screenshot.png"
