#!/usr/bin/env bash
# Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
# SPDX-License-Identifier: GPL-3.0-or-later
# Builds quality_report in Release in the build directory, extracts the CGAL
# sample meshes the case files use, runs it and writes
# benchmark/results/quality.md.
#
# Usage: benchmark/quality/run_quality_report.sh [options of quality_report]
#   e.g. --botsch08 DIR       add the Botsch & Sorkine 2008 cases (bar, cactus,
#                             cylinder, plane) found in DIR (skipped otherwise)
#        --mesh-output DIR    also write the inputs, selections and results there
# Environment: SSMD_BUILD_DIR (default <repository>/build),
#              OUTPUT (default <repository>/benchmark/results/quality.md).
set -euo pipefail

quality_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
repository="$(cd "${quality_dir}/../.." && pwd)"
build_dir="${SSMD_BUILD_DIR:-${repository}/build}"
output="${OUTPUT:-${repository}/benchmark/results/quality.md}"

cmake -S "${repository}" -B "${build_dir}" -DCMAKE_BUILD_TYPE=Release -DSSMD_BUILD_BENCHMARKS=ON
cmake --build "${build_dir}" --target quality_report -j 2
SSMD_BUILD_DIR="${build_dir}" "${repository}/scripts/fetch_sample_meshes.sh"
# The meshes of cases/bar_twist.case, tube_twist.case and strip_bend.case are generated.
[[ -f "${build_dir}/data/meshes/twist_bar.off" ]] ||
  python3 "${repository}/benchmark/make_bar_mesh.py" "${build_dir}/data/meshes/twist_bar.off"
[[ -f "${build_dir}/data/meshes/tube.off" && -f "${build_dir}/data/meshes/strip.off" ]] ||
  python3 "${repository}/benchmark/make_shape_meshes.py" "${build_dir}/data/meshes"

notes=()
if revision="$(git -C "${repository}" rev-parse --short HEAD 2> /dev/null)"; then
  if [[ -n "$(git -C "${repository}" status --porcelain 2> /dev/null)" ]]; then
    revision="${revision} with uncommitted changes"
  fi
  notes=(--note "repository revision ${revision}")
fi

mkdir -p "$(dirname "${output}")"
"${build_dir}/benchmark/quality/quality_report" --output "${output}" \
  --meshes "${build_dir}/data/meshes" --cases "${quality_dir}/cases" "${notes[@]}" "$@"
echo "wrote ${output}"
