#!/usr/bin/env bash
# Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
# SPDX-License-Identifier: GPL-3.0-or-later
# The Python binding against the C++ call on the armadillo arm case, 104k
# vertices (one Loop subdivision): builds the benchmark program and the Python
# package in the Release build, writes benchmark/results/python_binding.md.
#   LEVELS=0 bash benchmark/run_python_binding_benchmark.sh   # the 26k mesh
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${SSMD_BUILD_DIR:-$root/build}"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DSSMD_BUILD_BENCHMARKS=ON -DSSMD_BUILD_PYTHON=ON >/dev/null
bash "$root/scripts/fetch_sample_meshes.sh" >/dev/null
cmake --build "$build" --target benchmark_python_binding ssmd_python_module -j "$(nproc)" >/dev/null
PYTHONPATH="$build/python" /usr/bin/python3 "$root/benchmark/benchmark_python_binding.py" \
  "$build/benchmark/benchmark_python_binding" "$root/benchmark/quality/cases/armadillo_arm.case" \
  "${LEVELS:-1}" "$build/benchmark/python_binding" "${ROUNDS:-5}" "${DRAGS:-10}" \
  --output "$root/benchmark/results/python_binding.md"
