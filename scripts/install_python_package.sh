#!/usr/bin/env bash
# Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
# SPDX-License-Identifier: GPL-3.0-or-later
# Installs the Python package ssmd with pip into the project's virtual
# environment build/venv (or $SSMD_BUILD_DIR/venv), made anew from Debian's
# /usr/bin/python3 with --system-site-packages, so that NumPy, meshio, tqdm,
# pytest and mypy come from Debian's packages; the Python tests of ctest run
# from it. Then copies the installed package into the user's site of
# /usr/bin/python3 (~/.local/lib/python3.X/site-packages), so that
# `python3 -c "import ssmd"` and the demo work with the system's Python too.
#
#   install_python_package.sh         pip install . (pyproject.toml); with a
#                                     configured build/, its module is used:
#                                     nothing compiles after build.sh
#   install_python_package.sh WHEEL   installs that wheel instead
#                                     (scripts/test_python_package.sh)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${SSMD_BUILD_DIR:-$root/build}"
environment="$build/venv"
wheel="${1:-}"

/usr/bin/python3 -m venv --clear --system-site-packages "$environment"
if [ -n "$wheel" ]; then
  "$environment/bin/pip" install --no-index --quiet "$wheel"
else
  if [ -d "$build/python/CMakeFiles/ssmd_python_module.dir" ]; then
    export SSMD_CMAKE_BUILD_DIR="$build"
  fi
  (cd "$root" && "$environment/bin/pip" install --no-build-isolation --quiet .)
fi
installed="$(cd / && PYTHONNOUSERSITE=1 "$environment/bin/python" -c "import os, ssmd; print(os.path.dirname(ssmd.__file__))")"
echo "Python package ssmd installed in $installed (run $environment/bin/python)"

# The copy for /usr/bin/python3 (Debian forbids pip in its own environment).
site="$(env -u PYTHONNOUSERSITE /usr/bin/python3 -c "import site; print(site.getusersitepackages())")"
mkdir -p "$site"
rm -rf "$site/ssmd"
cp -r "$installed" "$site/ssmd"
rm -rf "$site/ssmd/__pycache__"
cd /
env -u PYTHONNOUSERSITE /usr/bin/python3 -c "import ssmd; print('and for /usr/bin/python3 in', ssmd.__path__[0])"
