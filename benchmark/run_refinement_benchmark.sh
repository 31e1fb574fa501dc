#!/usr/bin/env bash
# Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
# SPDX-License-Identifier: GPL-3.0-or-later
# Builds benchmark_refinement (and ssmd_deform, for the tube's figure) in
# Release and runs it on the armadillo's arm at 26k and 104k vertices
# (LEVELS="0 1"; "0 1 2" adds 416k, an hour and a half of CGAL ARAP) and on the twisted
# tube (35k vertices), with and without the volume kept; writes
# benchmark/results/refinement_*.md and .tsv and the manual's figures
# doc/fig/refinement_energy.png and refinement_tube.png. About 20 minutes
# with the default levels on 2 cores.
#
# With REUSE_CGAL=1 the arm's levels whose results/refinement_arm_*.tsv exist
# take CGAL ARAP's curves from there (benchmark_refinement --cgal-data)
# instead of running it again: at 416k it ran for 91 minutes, to convergence.
#
# Usage: benchmark/run_refinement_benchmark.sh
# Environment: SSMD_BUILD_DIR (default <repository>/build), LEVELS, REUSE_CGAL.
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
# At 416k CGAL ARAP needed 8000 iterations (91 minutes) to stop lowering its
# energy (by 0.04 % over the last 1754).
cgal_iterations=(4000 4000 8000 8000)
package_iterations=(2000 2000 1200 1200)
work="$(mktemp -d)"
trap 'rm -rf "${work}"' EXIT
for level in ${LEVELS:-0 1}; do
  data="${results}/refinement_arm_${sizes[level]}.tsv"
  reuse=()
  if [ "${REUSE_CGAL:-0}" = 1 ] && [ -f "${data}" ]; then
    # A copy: the run writes its --data over the file it would read.
    earlier="${work}/$(basename "${data}")"
    cp "${data}" "${earlier}"
    reuse=(--cgal-data "${earlier}")
  fi
  "${program}" --levels "${level}" --cgal-iterations "${cgal_iterations[level]}" \
    --package-iterations "${package_iterations[level]}" --meshes "${meshes}" "${reuse[@]}" \
    --output "${results}/refinement_arm_${sizes[level]}.md" --data "${data}"
done
"${program}" --case "${benchmark_dir}/quality/cases/tube_twist.case" --levels 0 --meshes "${meshes}" \
  --cgal-iterations 2000 --package-iterations 1000 --mesh-output "${work}" \
  --output "${results}/refinement_tube.md" --data "${results}/refinement_tube.tsv"
"${program}" --case "${benchmark_dir}/quality/cases/tube_twist.case" --levels 0 --meshes "${meshes}" --keep-volume \
  --cgal-iterations 12 --package-iterations 1000 \
  --output "${results}/refinement_tube_volume.md" --data "${results}/refinement_tube_volume.tsv"
/usr/bin/python3 "${benchmark_dir}/plot_refinement.py" "${repository}/doc/fig/refinement_energy.png" \
  "${results}"/refinement_arm_*.tsv "${results}/refinement_tube.tsv"
SSMD_BUILD_DIR="${build_dir}" bash "${benchmark_dir}/render_refinement_figure.sh" "${work}/tube_twist_0_cgal.off"
