#!/usr/bin/env bash
# The main job: installs what is missing, builds in Release, fetches the sample
# meshes, computes the manifold harmonics basis of the armadillo and writes
# low-pass reconstructions (meshes and one picture) into build/demo.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${SSMD_BUILD_DIR:-$root/build}"

bash "$root/scripts/install_dependencies.sh"
bash "$root/scripts/build.sh" -DSSMD_BUILD_TESTS=OFF -DSSMD_BUILD_BENCHMARKS=OFF
bash "$root/scripts/fetch_sample_meshes.sh"

mesh="$build/data/meshes/armadillo.off"
out="$build/demo"
"$build/examples/manifold_harmonics_low_pass" "$mesh" "$out" 10 30 100 300
/usr/bin/python3 "$root/scripts/render_meshes.py" "$out/low_pass_armadillo.png" --azimuth 180 \
  "original=$mesh" "m = 10=$out/low_pass_10.off" "m = 30=$out/low_pass_30.off" \
  "m = 100=$out/low_pass_100.off" "m = 300=$out/low_pass_300.off"
echo "demo results in $out"
