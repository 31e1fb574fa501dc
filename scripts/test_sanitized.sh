#!/usr/bin/env bash
# Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
# SPDX-License-Identifier: GPL-3.0-or-later
# The Catch2 suite built with AddressSanitizer and UndefinedBehaviorSanitizer
# (SSMD_SANITIZE=ON), tests only, in build-asan/ (or $SSMD_ASAN_BUILD_DIR).
# -Og -g1 (line tables): GCC's level for debugging keeps the reports
# readable and compiles the tests a quarter faster than -O1 (which compiles
# faster than -O2 -g), this build being most of the CI's time; the compiled
# core, compiled once and where the tests spend their time, at -O1, which
# runs them twice as fast as -Og (benchmark/NOTES.md). Any sanitizer report
# fails the test that triggered it.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${SSMD_ASAN_BUILD_DIR:-$root/build-asan}"
jobs="${SSMD_JOBS:-$(nproc)}"

bash "$root/scripts/install_dependencies.sh"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-Og -g1 -DNDEBUG" -DSSMD_CORE_COMPILE_OPTIONS=-O1 -DSSMD_SANITIZE=ON \
  -DSSMD_BUILD_TESTS=ON -DSSMD_BUILD_EXAMPLES=OFF -DSSMD_BUILD_BENCHMARKS=OFF \
  -DSSMD_BUILD_DOC=OFF -DSSMD_BUILD_TOOLS=OFF -DSSMD_BUILD_FUZZERS=OFF -DSSMD_BUILD_PYTHON=OFF >/dev/null
cmake --build "$build" --parallel "$jobs"
cd "$build"
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1:detect_stack_use_after_return=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
ctest --output-on-failure --timeout 1800 -j "$jobs"
