#!/usr/bin/env bash
# Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
# SPDX-License-Identifier: GPL-3.0-or-later
# Builds benchmark_refinement (and ssmd_deform, for the tube's figure) in
# Release and runs it on the armadillo's arm at 26k and 104k vertices
# (LEVELS="0 1"; "0 1 2" adds 416k, an hour of CGAL ARAP) and on the twisted
# tube (35k vertices), with and without the volume kept; writes
# benchmark/results/refinement_*.md and .tsv and the manual's figures
# doc/fig/refinement_energy.png and refinement_tube.png. About 20 minutes
# with the default levels on 2 cores.
#
# Usage: benchmark/run_refinement_benchmark.sh
# Environment: SSMD_BUILD_DIR (default <repository>/build), LEVELS.
set -euo pipefail

benchmark_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
repository="$(cd "${benchmark_dir}/.." && pwd)"
build_dir="${SSMD_BUILD_DIR:-${repository}/build}"
results="${benchmark_dir}/results"

cmake -S "${repository}" -B "${build_dir}" -DCMAKE_BUILD_TYPE=Release -DSSMD_BUILD_BENCHMARKS=ON -DSSMD_BUILD_TOOLS=ON >/dev/null
cmake --build "${build_dir}" --target benchmark_refinement ssmd_deform -j 2
SSMD_BUILD_DIR="${build_dir}" "${repository}/scripts/fetch_sample_meshes.sh"
meshes="${build_dir}/data/meshes"
[ -f "${meshes}/tube.off" ] || /usr/bin/python3 "${benchmark_dir}/make_shape_meshes.py" "${meshes}"
mkdir -p "${results}"
program="${build_dir}/benchmark/benchmark_refinement"
sizes=(26k 104k 416k 1.66M)
# At 416k, 2400 iterations of CGAL ARAP take more than 45 minutes.
cgal_iterations=(4000 4000 2400 2400)
package_iterations=(2000 2000 1200 1200)
for level in ${LEVELS:-0 1}; do
  "${program}" --levels "${level}" --cgal-iterations "${cgal_iterations[level]}" \
    --package-iterations "${package_iterations[level]}" --meshes "${meshes}" \
    --output "${results}/refinement_arm_${sizes[level]}.md" --data "${results}/refinement_arm_${sizes[level]}.tsv"
done
work="$(mktemp -d)"
trap 'rm -rf "${work}"' EXIT
"${program}" --case "${benchmark_dir}/quality/cases/tube_twist.case" --levels 0 --meshes "${meshes}" \
  --cgal-iterations 2000 --package-iterations 1000 --mesh-output "${work}" \
  --output "${results}/refinement_tube.md" --data "${results}/refinement_tube.tsv"
"${program}" --case "${benchmark_dir}/quality/cases/tube_twist.case" --levels 0 --meshes "${meshes}" --keep-volume \
  --cgal-iterations 12 --package-iterations 1000 \
  --output "${results}/refinement_tube_volume.md" --data "${results}/refinement_tube_volume.tsv"
/usr/bin/python3 "${benchmark_dir}/plot_refinement.py" "${repository}/doc/fig/refinement_energy.png" \
  "${results}"/refinement_arm_*.tsv "${results}/refinement_tube.tsv"
SSMD_BUILD_DIR="${build_dir}" bash "${benchmark_dir}/render_refinement_figure.sh" "${work}/tube_twist_0_cgal.off"
