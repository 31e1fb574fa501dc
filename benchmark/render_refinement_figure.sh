#!/usr/bin/env bash
# Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
# SPDX-License-Identifier: GPL-3.0-or-later
# Renders the figure of the manual's section "Refining to the ARAP optimum"
# (doc/fig/refinement_tube.png): the tube of benchmark/quality twisted by
# 120° (tube_twist.case), the package's result (deform()), refined to
# convergence without and with the volume kept (ssmd_deform --refine), and
# CGAL ARAP after 2000 iterations (the last shape of benchmark_refinement
# --mesh-output DIR on the case). Colour: edge change, 0 to 30 %.
#
# Usage: benchmark/render_refinement_figure.sh CGAL_MESH.off
# Environment: SSMD_BUILD_DIR (default <repository>/build, ssmd_deform built,
# tube.off in its data/meshes).
set -euo pipefail
repository="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build_dir="${SSMD_BUILD_DIR:-${repository}/build}"
cgal_mesh="${1:?usage: $0 CGAL_MESH.off}"
tube="${build_dir}/data/meshes/tube.off"
work="$(mktemp -d)"
trap 'rm -rf "${work}"' EXIT
python=/usr/bin/python3

cat > "${work}/tube.json" <<JSON
{"mesh": "${tube}",
 "handle": {"box": {"min": [-1, -1, 0.95], "max": [1, 1, 2]}},
 "fixed": {"box": {"min": [-1, -1, -1], "max": [1, 1, 0.05]}},
 "transform": {"rotation": {"axis": [0, 0, 1], "center": [0, 0, 1], "angle_deg": 120}}}
JSON
"${python}" "${repository}/../shared/bench/make_case.py" "${work}/tube.json" --out-prefix "${work}/tube" > /dev/null
tool="${build_dir}/tools/ssmd_deform"
"${tool}" -q --no-cache "${tube}" "${work}/tube.sel" "${work}/tube.def" -o "${work}/default.off"
"${tool}" -q --no-cache "${tube}" "${work}/tube.sel" "${work}/tube.def" --refine 1e-7 --refine-iterations 3000 \
  -o "${work}/refined.off"
"${tool}" -q --no-cache "${tube}" "${work}/tube.sel" "${work}/tube.def" --refine 1e-7 --refine-iterations 3000 \
  --volume-preservation -o "${work}/refined_volume.off"
for shape in default refined refined_volume; do
  "${python}" "${repository}/scripts/edge_change_vtk.py" "${tube}" "${work}/${shape}.off" "${work}/${shape}.vtk"
done
"${python}" "${repository}/scripts/edge_change_vtk.py" "${tube}" "${cgal_mesh}" "${work}/cgal.vtk"
"${python}" "${repository}/scripts/render_meshes.py" "${repository}/doc/fig/refinement_tube.png" --size 300 \
  --up +Z --azimuth 0 --elevation 10 --scalars edge_change --range 0,0.3 \
  "deform()=${work}/default.vtk" "refined=${work}/refined.vtk" \
  "refined, volume kept=${work}/refined_volume.vtk" "CGAL ARAP, 2000 iterations=${work}/cgal.vtk"
