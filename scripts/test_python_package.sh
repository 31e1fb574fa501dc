#!/usr/bin/env bash
# Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
# SPDX-License-Identifier: GPL-3.0-or-later
# The Python package as a user installs it, from a clean copy of the sources
# (the files git knows), with Debian's Python and packages only (no package
# index):
#  1. python3 -m venv --system-site-packages v
#     v/bin/pip install --no-build-isolation .      (compiles the module)
#  2. v/bin/python -c "import ssmd" from another folder;
#  3. pip wheel --no-build-isolation --no-deps .    (reuses the CMake build of
#     step 1: nothing compiles; --no-deps, or pip would want a wheel of NumPy);
#  4. the wheel installs into a second fresh environment, which imports it;
#  5. cmake --install --component python of the same build into a prefix,
#     imported from there;
#  6. the wheel goes into the project's environment build/venv
#     (scripts/install_python_package.sh WHEEL), from which ctest runs the
#     Python tests: the module is compiled once for all of it.
# The CMake build directory is kept in build/python_package/cmake, so that a
# second run compiles only what changed. Everything runs with
# PYTHONNOUSERSITE=1: the set-up commands copy the package into the user's
# site, which an environment with the system's packages would put before its
# own.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${SSMD_BUILD_DIR:-$root/build}"
work="$build/python_package"
python=/usr/bin/python3   # Debian's: python3-numpy is its NumPy
export PYTHONNOUSERSITE=1
export SSMD_CMAKE_BUILD_DIR="$work/cmake"

step() { echo "== $1: $(( $(date +%s) - step_start )) s"; step_start=$(date +%s); }
step_start=$(date +%s)

rm -rf "$work/source" "$work/v" "$work/v2" "$work/dist" "$work/elsewhere"
mkdir -p "$work/source" "$work/elsewhere"
# tar keeps the modification times, so that the kept CMake build sees
# unchanged files as unchanged.
if git -C "$root" rev-parse --is-inside-work-tree >/dev/null 2>&1; then
  (cd "$root" && git ls-files -z --cached --others --exclude-standard |
    xargs -0 sh -c 'for f; do [ -e "$f" ] && printf "%s\0" "$f"; done' sh |
    tar --null -T - -cf -) | tar -xf - -C "$work/source"
else
  (cd "$root" && tar --exclude=./build --exclude='./build-*' -cf - .) | tar -xf - -C "$work/source"
fi
step "clean copy of the sources"

(cd "$work/source" && "$python" -m venv --system-site-packages ../v && ../v/bin/pip install --no-build-isolation .)
step "pip install --no-build-isolation . into a new environment"

check_import() {   # ENVIRONMENT
  (cd "$work/elsewhere" && "$1/bin/python" -c "import ssmd") || {
    echo "FAIL: import ssmd in $1" >&2; exit 1; }
  (cd "$work/elsewhere" && "$1/bin/python" - "$1" <<'PYTHON'
import os, sys, ssmd
here = os.path.realpath(ssmd.__file__)
assert here.startswith(os.path.realpath(sys.argv[1]) + os.sep), "ssmd imported from " + here
print("imported ssmd", ssmd.__version__, "from", os.path.dirname(here))
PYTHON
  )
}
check_import "$work/v"
step "import ssmd from another folder"

(cd "$work/source" && ../v/bin/pip wheel --no-build-isolation --no-deps -w ../dist .)
wheel="$(ls "$work"/dist/ssmd-*.whl)"
step "pip wheel --no-build-isolation --no-deps ."

"$python" -m venv --system-site-packages "$work/v2"
"$work/v2/bin/pip" install --no-index "$wheel"
check_import "$work/v2"
step "the wheel in a second new environment"

# The CMake installation of the same build (cmake --install --component
# python), for those who install the package with the C++ one.
rm -rf "$work/prefix"
cmake --install "$work/cmake" --component python --prefix "$work/prefix" >/dev/null
site="$(ls -d "$work"/prefix/lib/python3*/*-packages)"
(cd "$work/elsewhere" && PYTHONPATH="$site" "$python" - "$site" <<'PYTHON'
import os, sys, ssmd
here = os.path.realpath(ssmd.__file__)
assert here.startswith(os.path.realpath(sys.argv[1]) + os.sep), "ssmd imported from " + here
PYTHON
)
step "cmake --install --component python, imported from the prefix"

bash "$root/scripts/install_python_package.sh" "$wheel"
step "the wheel in the project's environment $build/venv"
