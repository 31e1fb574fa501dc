#!/usr/bin/env bash
# Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
# SPDX-License-Identifier: GPL-3.0-or-later
# Builds benchmark_eigensolvers in Release in the build directory, extracts
# the CGAL sample mesh of the armadillo case, runs it (armadillo Loop-subdivided
# once and twice, about 104k and 416k vertices, m = 100 and 200, with the
# deformation comparison) and writes benchmark/results/eigensolvers.md.
# About 25 minutes on a 2-core machine.
#
# Usage: benchmark/run_eigensolver_benchmark.sh [options of benchmark_eigensolvers]
#   e.g. --levels 1 --frequencies 100 --repetitions 5
# Environment: BUILD_DIR (default <repository>/build),
#              CGAL_DATA_TARBALL (default /usr/share/doc/libcgal-dev/data.tar.gz),
#              OUTPUT (default <repository>/benchmark/results/eigensolvers.md).
set -euo pipefail

repository="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build_dir="${BUILD_DIR:-${repository}/build}"
tarball="${CGAL_DATA_TARBALL:-/usr/share/doc/libcgal-dev/data.tar.gz}"
output="${OUTPUT:-${repository}/benchmark/results/eigensolvers.md}"
mesh_dir="${build_dir}/data/meshes"

bash "${repository}/scripts/install_dependencies.sh"
cmake -S "${repository}" -B "${build_dir}" -DCMAKE_BUILD_TYPE=Release -DSSMD_BUILD_BENCHMARKS=ON
cmake --build "${build_dir}" --target benchmark_eigensolvers -j 2

if [[ ! -f "${mesh_dir}/armadillo.off" ]]; then
  if [[ ! -f "${tarball}" ]]; then
    echo "error: ${mesh_dir}/armadillo.off is missing and there is no ${tarball}" >&2
    exit 1
  fi
  mkdir -p "${build_dir}"
  tar -xzf "${tarball}" -C "${build_dir}" "data/meshes/armadillo.off"
fi

mkdir -p "$(dirname "${output}")"
"${build_dir}/benchmark/benchmark_eigensolvers" --mesh-directory "${mesh_dir}" \
  --output "${output}" "$@" > /dev/null
echo "wrote ${output}"
