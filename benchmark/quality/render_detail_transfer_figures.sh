#!/usr/bin/env bash
# Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
# SPDX-License-Identifier: GPL-3.0-or-later
# Renders the figures of the manual's section "Thin features, open sheets and
# tubes" (doc/fig/thin_feature_armadillo.png, strip_bend.png, tube_twist.png)
# from two --mesh-output directories of quality_report, one made by a build of
# an earlier revision (the deformation-gradient transfer, e.g. f1e88bf) and
# one by the current revision, each run with
#   --only armadillo_hand_raise,strip_bend,tube_twist --levels 0
#   --case-levels armadillo_hand_raise=2 --mesh-output DIR
# and, for the current revision, --smooth-energy dual-laplacian --stage-angle 0
# --rotation-patches 0 (the iteration the figures show)
#
# Usage: benchmark/quality/render_detail_transfer_figures.sh BEFORE_DIR AFTER_DIR
set -euo pipefail
repository="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
before="$1"
after="$2"
figures="${repository}/doc/fig"
work="$(mktemp -d)"
trap 'rm -rf "${work}"' EXIT
python=/usr/bin/python3
colour() { # NAME DIR CASE ALGORITHM
  "${python}" "${repository}/scripts/edge_change_vtk.py" "$2/$3.input.off" "$2/$3.$4.off" "${work}/$1.vtk"
}

colour hand_before "${before}" armadillo_hand_raise@2 spectral_exact
colour hand_after "${after}" armadillo_hand_raise@2 spectral_exact
# The back of the armadillo (it faces -z), where the spikes are.
"${python}" "${repository}/scripts/render_meshes.py" "${figures}/thin_feature_armadillo.png" --size 420 \
  --position "${HAND_CAMERA:-10,60,150}" --focus "${HAND_FOCUS:-0,35,45}" \
  --scalars edge_change --range 0,0.3 \
  "deformation gradients=${work}/hand_before.vtk" "rotations=${work}/hand_after.vtk"

colour strip_before "${before}" strip_bend spectral_exact
colour strip_after "${after}" strip_bend spectral_exact
"${python}" "${repository}/scripts/render_meshes.py" "${figures}/strip_bend.png" --size 400 \
  --up +Z --azimuth 30 --elevation 20 --scalars edge_change --range 0,0.1 \
  "deformation gradients=${work}/strip_before.vtk" "rotations=${work}/strip_after.vtk"

colour tube_cgal "${after}" tube_twist cgal_spokes_and_rims
colour tube_before "${before}" tube_twist spectral_exact
colour tube_after "${after}" tube_twist spectral_exact
"${python}" "${repository}/scripts/render_meshes.py" "${figures}/tube_twist.png" --size 320 \
  --up +Z --elevation 10 --scalars edge_change --range 0,0.5 \
  "CGAL ARAP=${work}/tube_cgal.vtk" "deformation gradients=${work}/tube_before.vtk" \
  "rotations=${work}/tube_after.vtk"
