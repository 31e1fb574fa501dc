#!/usr/bin/env bash
# Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
# SPDX-License-Identifier: GPL-3.0-or-later
# Builds benchmark_basis in Release in the build directory, extracts the two
# CGAL sample meshes it needs, runs it and writes benchmark/results/basis.md.
#
# Usage: benchmark/run_basis_benchmark.sh [options of benchmark_basis]
#   e.g. --repetitions 5 --note "single runs on a shared machine"
# Environment: BUILD_DIR (default <repository>/build),
#              CGAL_DATA_TARBALL (default /usr/share/doc/libcgal-dev/data.tar.gz),
#              OUTPUT (default <repository>/benchmark/results/basis.md).
set -euo pipefail

repository="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build_dir="${BUILD_DIR:-${repository}/build}"
tarball="${CGAL_DATA_TARBALL:-/usr/share/doc/libcgal-dev/data.tar.gz}"
output="${OUTPUT:-${repository}/benchmark/results/basis.md}"
mesh_dir="${build_dir}/data/meshes"

cmake -S "${repository}" -B "${build_dir}" -DCMAKE_BUILD_TYPE=Release -DSSMD_BUILD_BENCHMARKS=ON
cmake --build "${build_dir}" --target benchmark_basis -j 2

for mesh in armadillo.off refined_elephant.off; do
  if [[ ! -f "${mesh_dir}/${mesh}" ]]; then
    if [[ ! -f "${tarball}" ]]; then
      echo "error: ${mesh_dir}/${mesh} is missing and there is no ${tarball}" >&2
      exit 1
    fi
    mkdir -p "${build_dir}"
    tar -xzf "${tarball}" -C "${build_dir}" "data/meshes/${mesh}"
  fi
done

mkdir -p "$(dirname "${output}")"
"${build_dir}/benchmark/benchmark_basis" "${mesh_dir}" --output "${output}" "$@" > /dev/null
echo "wrote ${output}"
