#!/usr/bin/env bash
# Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
# SPDX-License-Identifier: GPL-3.0-or-later
# Builds benchmark_refinement in Release and runs it on the armadillo's arm
# at 26k and 104k vertices (levels 0 and 1; LEVELS=0,1,2 adds 416k, about
# half an hour of CGAL ARAP) and on the twisted tube (33k vertices), with and
# without the volume kept; writes benchmark/results/refinement*.md and .tsv
# and the manual's figure doc/fig/refinement_energy.png.
#
# Usage: benchmark/run_refinement_benchmark.sh
# Environment: SSMD_BUILD_DIR (default <repository>/build), LEVELS.
set -euo pipefail

benchmark_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
repository="$(cd "${benchmark_dir}/.." && pwd)"
build_dir="${SSMD_BUILD_DIR:-${repository}/build}"
results="${benchmark_dir}/results"

cmake -S "${repository}" -B "${build_dir}" -DCMAKE_BUILD_TYPE=Release -DSSMD_BUILD_BENCHMARKS=ON >/dev/null
cmake --build "${build_dir}" --target benchmark_refinement -j 2
SSMD_BUILD_DIR="${build_dir}" "${repository}/scripts/fetch_sample_meshes.sh"
meshes="${build_dir}/data/meshes"
[ -f "${meshes}/tube.off" ] || /usr/bin/python3 "${benchmark_dir}/make_shape_meshes.py" "${meshes}"
mkdir -p "${results}"
program="${build_dir}/benchmark/benchmark_refinement"
"${program}" --levels "${LEVELS:-0,1}" --meshes "${meshes}" \
  --output "${results}/refinement_arm.md" --data "${results}/refinement_arm.tsv"
"${program}" --case "${benchmark_dir}/quality/cases/tube_twist.case" --levels 0 --meshes "${meshes}" \
  --output "${results}/refinement_tube.md" --data "${results}/refinement_tube.tsv"
"${program}" --case "${benchmark_dir}/quality/cases/tube_twist.case" --levels 0 --meshes "${meshes}" --keep-volume \
  --output "${results}/refinement_tube_volume.md" --data "${results}/refinement_tube_volume.tsv"
/usr/bin/python3 "${benchmark_dir}/plot_refinement.py" "${repository}/doc/fig/refinement_energy.png" \
  "${results}/refinement_arm.tsv" "${results}/refinement_tube.tsv"
