#!/usr/bin/env bash
# Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
# SPDX-License-Identifier: GPL-3.0-or-later
# Renders the figures of the manual's section "The energy of the iteration"
# (doc/fig/tube_twist_energy.png, doc/fig/bar_twist_energy.png): the twisted
# tube and the twisted bar deformed by CGAL ARAP and by the spectral iteration
# with each smooth energy. Runs quality_report three times (about five minutes).
#
# Usage: benchmark/quality/render_smooth_energy_figure.sh
# Environment: SSMD_BUILD_DIR (default <repository>/build, quality_report built).
set -euo pipefail
repository="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
build_dir="${SSMD_BUILD_DIR:-${repository}/build}"
figures="${repository}/doc/fig"
work="$(mktemp -d)"
trap 'rm -rf "${work}"' EXIT
python=/usr/bin/python3

for energy in dual-laplacian arap dual-laplacian-and-arap; do
  "${build_dir}/benchmark/quality/quality_report" --output "${work}/${energy}.md" \
    --meshes "${build_dir}/data/meshes" --cases "${repository}/benchmark/quality/cases" \
    --only tube_twist,bar_twist --smooth-energy "${energy}" --stage-angle 0 --rotation-patches 0 --basis exact --mesh-output "${work}/${energy}" > /dev/null
done
colour() { # NAME DIR CASE ALGORITHM
  "${python}" "${repository}/scripts/edge_change_vtk.py" "$2/$3.input.off" "$2/$3.$4.off" "${work}/$1.vtk"
}
for shape in tube bar; do
  colour "${shape}_cgal" "${work}/arap" "${shape}_twist" cgal_spokes_and_rims
  colour "${shape}_dual" "${work}/dual-laplacian" "${shape}_twist" spectral_exact
  colour "${shape}_arap" "${work}/arap" "${shape}_twist" spectral_exact
  colour "${shape}_sum" "${work}/dual-laplacian-and-arap" "${shape}_twist" spectral_exact
done
"${python}" "${repository}/scripts/render_meshes.py" "${figures}/tube_twist_energy.png" --size 300 \
  --up +Z --elevation 10 --scalars edge_change --range 0,0.5 \
  "CGAL ARAP=${work}/tube_cgal.vtk" "dual Laplacian (default)=${work}/tube_dual.vtk" \
  "ARAP energy=${work}/tube_arap.vtk" "sum of the two=${work}/tube_sum.vtk"
"${python}" "${repository}/scripts/render_meshes.py" "${figures}/bar_twist_energy.png" --size 300 \
  --up +Z --elevation 10 --scalars edge_change --range 0,0.5 \
  "CGAL ARAP=${work}/bar_cgal.vtk" "dual Laplacian (default)=${work}/bar_dual.vtk" \
  "ARAP energy=${work}/bar_arap.vtk" "sum of the two=${work}/bar_sum.vtk"
