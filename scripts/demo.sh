#!/usr/bin/env bash
# Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
# SPDX-License-Identifier: GPL-3.0-or-later
# The main job: installs what is missing, builds in Release, fetches CGAL's
# sample meshes, then
#  1. deforms the armadillo (its right arm swung down by 70 degrees about the
#     shoulder, feet fixed) and writes the result and a before/after picture;
#  2. computes the manifold harmonics basis of the armadillo and writes
#     low-pass reconstructions (the paper's Figure 2) and their picture;
#  3. installs the Python package ssmd for the user and runs its example.
# Everything is written into build/demo.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${SSMD_BUILD_DIR:-$root/build}"

bash "$root/scripts/install_dependencies.sh"
bash "$root/scripts/build.sh" -DSSMD_BUILD_TESTS=OFF -DSSMD_BUILD_BENCHMARKS=OFF
bash "$root/scripts/fetch_sample_meshes.sh"
bash "$root/scripts/install_python_package.sh"

mesh="$build/data/meshes/armadillo.off"
out="$build/demo"
mkdir -p "$out"

echo "== Deformation of the armadillo"
/usr/bin/python3 "$root/scripts/make_selection.py" "$mesh" "$out/armadillo_arm" \
  --handle 50 40 -100 100 100 100 --fixed -100 -100 -100 100 -38 100 \
  --rotate 0 0 1 -70 22 52 -20
"$build/examples/deform_botsch08_format" "$mesh" "$out/armadillo_arm.sel" "$out/armadillo_arm.def" \
  "$out/armadillo_arm"
/usr/bin/python3 "$root/scripts/render_meshes.py" "$out/armadillo_arm.png" --azimuth 180 \
  "before=$mesh" "smooth (m = 100)=$out/armadillo_arm/smooth_rest.off" \
  "smooth, deformed=$out/armadillo_arm/smooth_deformed.off" "after=$out/armadillo_arm/deformed.off"

echo "== Low-pass reconstructions of the armadillo"
"$build/examples/manifold_harmonics_low_pass" "$mesh" "$out/low_pass" 10 30 100 300
/usr/bin/python3 "$root/scripts/render_meshes.py" "$out/low_pass_armadillo.png" --azimuth 180 \
  "original=$mesh" "m = 10=$out/low_pass/low_pass_10.off" "m = 30=$out/low_pass/low_pass_30.off" \
  "m = 100=$out/low_pass/low_pass_100.off" "m = 300=$out/low_pass/low_pass_300.off"
echo "== The same deformation from Python (package ssmd)"
/usr/bin/python3 "$root/examples/python/deform_armadillo.py" "$mesh" "$out/armadillo_arm_python.off"

echo "demo results in $out: armadillo_arm/deformed.off, armadillo_arm.png, low_pass_armadillo.png"
