#!/usr/bin/env bash
# Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
# SPDX-License-Identifier: GPL-3.0-or-later
# Builds benchmark_drag in Release, runs it on the armadillo's arm at 26k,
# 104k, 416k and 1.6M vertices (levels 0-3) and writes
# benchmark/results/drag.md, drag.tsv and the manual's figure doc/fig/drag_scaling.png.
#
# Usage: benchmark/run_drag_benchmark.sh [options of benchmark_drag]
#   e.g. --levels 0,1,2      leave out 1.6M (about 20 minutes of the run)
# Environment: SSMD_BUILD_DIR (default <repository>/build).
set -euo pipefail

benchmark_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
repository="$(cd "${benchmark_dir}/.." && pwd)"
build_dir="${SSMD_BUILD_DIR:-${repository}/build}"
results="${benchmark_dir}/results"

cmake -S "${repository}" -B "${build_dir}" -DCMAKE_BUILD_TYPE=Release -DSSMD_BUILD_BENCHMARKS=ON
cmake --build "${build_dir}" --target benchmark_drag -j 2
SSMD_BUILD_DIR="${build_dir}" "${repository}/scripts/fetch_sample_meshes.sh"
mkdir -p "${results}"
"${build_dir}/benchmark/benchmark_drag" --levels 0,1,2,3 --patches 300,1000 --cgal-drags 10 --cgal-drags-large 3 --meshes "${build_dir}/data/meshes" \
  --output "${results}/drag.md" --data "${results}/drag.tsv" "$@"
/usr/bin/python3 "${benchmark_dir}/plot_drag.py" "${results}/drag.tsv" "${repository}/doc/fig/drag_scaling.png"
