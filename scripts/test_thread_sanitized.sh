#!/usr/bin/env bash
# Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
# SPDX-License-Identifier: GPL-3.0-or-later
# The concurrency test built with ThreadSanitizer (SSMD_SANITIZE_THREAD=ON,
# without OpenMP, whose runtime is not instrumented), in build-tsan/ (or
# $SSMD_TSAN_BUILD_DIR): deformation objects in parallel threads next to a
# thread that uses the sparse solver directly. Any data race fails it.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${SSMD_TSAN_BUILD_DIR:-$root/build-tsan}"
jobs="${SSMD_JOBS:-$(nproc)}"

bash "$root/scripts/install_dependencies.sh"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-Og -g1 -DNDEBUG" -DSSMD_CORE_COMPILE_OPTIONS=-O1 -DSSMD_SANITIZE_THREAD=ON \
  -DSSMD_USE_OPENMP=OFF -DSSMD_BUILD_TESTS=ON -DSSMD_BUILD_EXAMPLES=OFF -DSSMD_BUILD_BENCHMARKS=OFF \
  -DSSMD_BUILD_DOC=OFF -DSSMD_BUILD_TOOLS=OFF -DSSMD_BUILD_FUZZERS=OFF -DSSMD_BUILD_PYTHON=OFF >/dev/null
cmake --build "$build" --parallel "$jobs" --target test_concurrency
export TSAN_OPTIONS="${TSAN_OPTIONS:-halt_on_error=1:second_deadlock_stack=1:suppressions=$root/test/thread_sanitizer.supp}"
"$build/test/test_concurrency"
