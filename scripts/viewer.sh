#!/usr/bin/env bash
# Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
# SPDX-License-Identifier: GPL-3.0-or-later
# Starts the browser viewer ssmd_viewer (doc/viewer.md) on a mesh, the
# armadillo by default: installs what is missing (Debian packages, three.js
# from npm into the build directory), builds the viewer into build/ (or
# $SSMD_BUILD_DIR) and prints the URL to open. Options after the mesh go to
# ssmd_viewer, e.g.
#
#   bash scripts/viewer.sh                                   # the armadillo, 26,002 vertices
#   bash scripts/viewer.sh --subdivide 1                     # the armadillo Loop-subdivided: 104,002 vertices
#   bash scripts/viewer.sh my_mesh.ply --port 9000
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${SSMD_BUILD_DIR:-$root/build}"
export SSMD_BUILD_DIR="$build"

mesh=""
if [ $# -gt 0 ] && [[ "$1" != -* ]]; then
  mesh="$1"
  shift
fi

bash "$root/scripts/install_dependencies.sh"
bash "$root/scripts/install_viewer_web.sh" "$build"
if [ -z "$mesh" ]; then
  bash "$root/scripts/fetch_sample_meshes.sh" >/dev/null
  mesh="$build/data/meshes/armadillo.off"
fi
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DSSMD_BUILD_TOOLS=ON >/dev/null
cmake --build "$build" --target ssmd_viewer --parallel "${SSMD_JOBS:-$(nproc)}"

# OpenMP threads that spin while waiting take the cores the browser renders on.
export OMP_WAIT_POLICY="${OMP_WAIT_POLICY:-passive}"
exec "$build/tools/ssmd_viewer/ssmd_viewer" "$mesh" "$@"
