#!/usr/bin/env bash
# Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
# SPDX-License-Identifier: GPL-3.0-or-later
# The tests: installs what is missing, builds in Release and runs through
# ctest the examples, the command-line tool, the Python package, the
# benchmarks' smoke runs, the documentation check and the Catch2 tests of
# types, of the build and of allocation failures; then the Catch2 tests that
# run the algorithms, built once, with AddressSanitizer and
# UndefinedBehaviorSanitizer (scripts/test_sanitized.sh), so that no test
# program is compiled twice.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${SSMD_BUILD_DIR:-$root/build}"

bash "$root/scripts/install_dependencies.sh"
# The Python module is left out of this build: pip compiles it, once, in the
# test of the package (scripts/test_python_package.sh), which installs it
# into build/venv, where ctest runs the Python tests. That test runs while
# the build compiles the rest, as the module did within the build.
mkdir -p "$build"
python_log="$build/python_package_test.log"
(start=$(date +%s); bash "$root/scripts/test_python_package.sh"
 echo "Python package test (pip install, pip wheel, two environments): $(( $(date +%s) - start )) s") \
  >"$python_log" 2>&1 &
python_test=$!
bash "$root/scripts/build.sh" -DSSMD_BUILD_TESTS=ON -DSSMD_BUILD_SANITIZABLE_TESTS=OFF -DSSMD_BUILD_EXAMPLES=ON \
  -DSSMD_PYTHON_MODULE_IN_ALL=OFF
bash "$root/scripts/fetch_sample_meshes.sh"   # the examples run on a sample mesh
if ! wait "$python_test"; then
  cat "$python_log"
  echo "FAIL: the Python package test (log: $python_log)" >&2
  exit 1
fi
grep -E "^(== |Python package test)" "$python_log"
(cd "$build" && ctest --output-on-failure --timeout 900 -j "${SSMD_JOBS:-$(nproc)}")
bash "$root/scripts/test_sanitized.sh"
