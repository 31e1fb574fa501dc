#!/usr/bin/env bash
# Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
# SPDX-License-Identifier: GPL-3.0-or-later
# Renders doc/fig/rotation_patches.png, the figure of the manual's section on
# rotation patches: the armadillo's arm case at 104k vertices with the full
# iteration and with 1000 patches, coloured by the change of edge length.
# Runs quality_report twice (a few minutes: it runs CGAL ARAP beside them).
#
# Usage: benchmark/quality/render_rotation_patches_figure.sh
# Environment: SSMD_BUILD_DIR (default <repository>/build).
set -euo pipefail
repository="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
build_dir="${SSMD_BUILD_DIR:-${repository}/build}"
work="$(mktemp -d)"
trap 'rm -rf "${work}"' EXIT
python=/usr/bin/python3
for patches in 0 1000; do
  mkdir -p "${work}/k${patches}"
  "${build_dir}/benchmark/quality/quality_report" --output "${work}/k${patches}.md" \
    --meshes "${build_dir}/data/meshes" --cases "${repository}/benchmark/quality/cases" \
    --only armadillo_arm --case-levels armadillo_arm=1 --rotation-patches "${patches}" --basis exact \
    --smooth-energy dual-laplacian --stage-angle 0 \
    --mesh-output "${work}/k${patches}" > /dev/null
done
colour() { # NAME DIR CASE
  "${python}" "${repository}/scripts/edge_change_vtk.py" "$2/$3.input.off" "$2/$3.spectral_exact.off" \
    "${work}/$1.vtk"
}
colour arm_full "${work}/k0" armadillo_arm@1
colour arm_patches "${work}/k1000" armadillo_arm@1
"${python}" "${repository}/scripts/render_meshes.py" "${repository}/doc/fig/rotation_patches.png" --size 400 \
  --scalars edge_change --range 0,0.3 \
  "full iteration=${work}/arm_full.vtk" "1000 rotation patches=${work}/arm_patches.vtk"
