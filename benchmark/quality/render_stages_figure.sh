#!/usr/bin/env bash
# Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
# SPDX-License-Identifier: GPL-3.0-or-later
# Renders the figure of the manual's section "Large turns of the handles:
# stages" (doc/fig/cylinder_stages.png): the cylinder of the Botsch & Sorkine
# 2008 benchmark bent by 120°, by CGAL ARAP and by the spectral iteration with
# the sum of the two energies, its targets reached in one stage and in stages
# of 30°. Runs quality_report twice (about a minute).
#
# Usage: benchmark/quality/render_stages_figure.sh BOTSCH08_DIRECTORY
# Environment: SSMD_BUILD_DIR (default <repository>/build, quality_report built).
set -euo pipefail
repository="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
build_dir="${SSMD_BUILD_DIR:-${repository}/build}"
botsch08="${1:?usage: $0 BOTSCH08_DIRECTORY}"
figures="${repository}/doc/fig"
work="$(mktemp -d)"
trap 'rm -rf "${work}"' EXIT
python=/usr/bin/python3

for angle in 0 30; do
  "${build_dir}/benchmark/quality/quality_report" --output "${work}/${angle}.md" \
    --botsch08 "${botsch08}" --only cylinder \
    --smooth-energy dual-laplacian-and-arap --stage-angle "${angle}" --rotation-patches 0 --basis exact \
    --mesh-output "${work}/${angle}" > /dev/null
done
colour() { # NAME DIR ALGORITHM
  "${python}" "${repository}/scripts/edge_change_vtk.py" "$2/cylinder.input.off" "$2/cylinder.$3.off" "${work}/$1.vtk"
}
colour cgal "${work}/30" cgal_spokes_and_rims
colour cgal_converged "${work}/30" cgal_spokes_and_rims_long
colour single "${work}/0" spectral_exact
colour staged "${work}/30" spectral_exact
"${python}" "${repository}/scripts/render_meshes.py" "${figures}/cylinder_stages.png" --size 300 \
  --up +Z --azimuth 0 --elevation 0 --scalars edge_change --range 0,0.5 \
  "CGAL ARAP, 5 iterations=${work}/cgal.vtk" "CGAL ARAP, converged=${work}/cgal_converged.vtk" \
  "one stage=${work}/single.vtk" "stages of 30°=${work}/staged.vtk"
