#!/usr/bin/env bash
# Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
# SPDX-License-Identifier: GPL-3.0-or-later
# Makes `python3 -c "import ssmd"` work for the user who runs it: copies the
# Python package built in build/python/ssmd (or $SSMD_BUILD_DIR) into the
# user's site-packages of /usr/bin/python3 (~/.local/lib/python3.X/...), which
# needs no root and is also the user site of any other CPython 3.X. To install
# elsewhere: cmake --install build --component python --prefix PREFIX.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${SSMD_BUILD_DIR:-$root/build}"
package="$build/python/ssmd"
if ! ls "$package"/_ssmd*.so >/dev/null 2>&1; then
  echo "the Python package was not built (pybind11 missing?): skipping its installation" >&2
  exit 0
fi
site="$(/usr/bin/python3 -m site --user-site)"
mkdir -p "$site"
rm -rf "$site/ssmd"
mkdir "$site/ssmd"
cp "$package"/__init__.py "$package"/_ssmd*.so "$package"/_ssmd.pyi "$package"/py.typed "$site/ssmd/"
cd /
/usr/bin/python3 -c "import ssmd; print('Python package ssmd', ssmd.__version__, 'installed in', ssmd.__path__[0])"
