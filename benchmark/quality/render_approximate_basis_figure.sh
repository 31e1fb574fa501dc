#!/usr/bin/env bash
# Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
# SPDX-License-Identifier: GPL-3.0-or-later
# Renders the figures of the manual's section "An approximate basis for large
# meshes" (doc/fig/approximate_basis_tube.png, doc/fig/approximate_basis_plane.png):
# the twisted tube and the bumpy plane of Botsch and Sorkine deformed by CGAL
# ARAP and by the default iteration with the exact and with the approximate
# basis. Runs quality_report twice (about three minutes).
#
# Usage: benchmark/quality/render_approximate_basis_figure.sh [BOTSCH08_DIR]
#   BOTSCH08_DIR: the Botsch & Sorkine 2008 cases (default ../shared/data/botsch08
#   next to the repository); without them only the tube is drawn.
# Environment: SSMD_BUILD_DIR (default <repository>/build, quality_report built).
set -euo pipefail
repository="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
build_dir="${SSMD_BUILD_DIR:-${repository}/build}"
botsch08="${1:-${repository}/../shared/data/botsch08}"
figures="${repository}/doc/fig"
work="$(mktemp -d)"
trap 'rm -rf "${work}"' EXIT
python=/usr/bin/python3

for basis in exact partition-of-unity; do
  "${build_dir}/benchmark/quality/quality_report" --output "${work}/${basis}.md" \
    --meshes "${build_dir}/data/meshes" --cases "${repository}/benchmark/quality/cases" \
    --botsch08 "${botsch08}" --only tube_twist,plane --basis "${basis}" \
    --smooth-energy dual-laplacian --stage-angle 0 --rotation-patches 0 \
    --mesh-output "${work}/${basis}" > /dev/null
done
colour() { # NAME DIR CASE ALGORITHM
  "${python}" "${repository}/scripts/edge_change_vtk.py" "$2/$3.input.off" "$2/$3.$4.off" "${work}/$1.vtk"
}
colour tube_cgal "${work}/exact" tube_twist cgal_spokes_and_rims
colour tube_exact "${work}/exact" tube_twist spectral_exact
colour tube_approximate "${work}/partition-of-unity" tube_twist spectral_exact
"${python}" "${repository}/scripts/render_meshes.py" "${figures}/approximate_basis_tube.png" --size 300 \
  --up +Z --elevation 10 --scalars edge_change --range 0,0.5 \
  "CGAL ARAP=${work}/tube_cgal.vtk" "exact basis (default)=${work}/tube_exact.vtk" \
  "approximate basis=${work}/tube_approximate.vtk"
if [[ -f "${work}/exact/plane.input.off" ]]; then
  colour plane_cgal "${work}/exact" plane cgal_spokes_and_rims
  colour plane_exact "${work}/exact" plane spectral_exact
  colour plane_approximate "${work}/partition-of-unity" plane spectral_exact
  "${python}" "${repository}/scripts/render_meshes.py" "${figures}/approximate_basis_plane.png" --size 300 \
    --up +Z --elevation 25 --scalars edge_change --range 0,0.5 \
    "CGAL ARAP=${work}/plane_cgal.vtk" "exact basis (default)=${work}/plane_exact.vtk" \
    "approximate basis=${work}/plane_approximate.vtk"
fi
