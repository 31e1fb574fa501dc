#!/usr/bin/env bash
# Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
# SPDX-License-Identifier: GPL-3.0-or-later
# Extracts CGAL's sample meshes (Debian package libcgal-demo) into
# build/data/meshes (or $SSMD_BUILD_DIR/data/meshes).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${SSMD_BUILD_DIR:-$root/build}"
archive=/usr/share/doc/libcgal-dev/data.tar.gz
meshes=(armadillo.off refined_elephant.off elephant.off dino.off cactus.off bunny00.off)

if [ ! -f "$archive" ]; then
  echo "error: $archive not found; install the Debian package libcgal-demo" >&2
  exit 1
fi
mkdir -p "$build/data"
todo=()
for mesh in "${meshes[@]}"; do
  [ -f "$build/data/meshes/$mesh" ] || todo+=("data/meshes/$mesh")
done
if [ ${#todo[@]} -gt 0 ]; then
  tar -xzf "$archive" -C "$build" "${todo[@]}"
fi
echo "sample meshes in $build/data/meshes"
