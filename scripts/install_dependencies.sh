#!/usr/bin/env bash
# Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
# SPDX-License-Identifier: GPL-3.0-or-later
# Installs the Debian 12 packages the package, its tests, examples, benchmarks
# and documentation need, when they are missing. Uses apt-get as root, or
# through sudo when available. Extra packages given as arguments (e.g. the
# fuzzing toolchain of scripts/fuzz.sh) are installed the same way.
set -euo pipefail

packages=(
  build-essential cmake time
  libcgal-dev libeigen3-dev libboost-dev libspectra-dev libsuitesparse-dev libopenblas-dev catch2
  libcgal-demo doxygen libjs-mathjax fonts-mathjax chromium
  f3d xvfb xauth python3-pil python3-matplotlib fonts-dejavu-core
  libopenmesh-dev libcli11-dev nlohmann-json3-dev
  pybind11-dev python3-dev python3-numpy python3-pytest
  python3-venv python3-pip python3-setuptools python3-wheel python3-meshio python3-tqdm python3-mypy
  "$@"
)

missing=()
for package in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$package")
  fi
done
if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi

echo "Installing missing Debian packages: ${missing[*]}"
if [ "$(id -u)" -eq 0 ]; then
  as_root=()
elif command -v sudo >/dev/null 2>&1; then
  as_root=(sudo)
else
  echo "error: these packages are missing and this script is neither root nor able to use sudo:" >&2
  echo "  apt-get install ${missing[*]}" >&2
  exit 1
fi
export DEBIAN_FRONTEND=noninteractive
"${as_root[@]}" apt-get update -qq
"${as_root[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
