#!/usr/bin/env bash
# Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
# SPDX-License-Identifier: GPL-3.0-or-later
# The package against CGAL ARAP as a user gets both, with the reference
# harness that sits beside the repository (../shared/bench, see its README):
# installs the package from build/ (or $SSMD_BUILD_DIR) into a prefix, makes
# the cases of benchmark/harness_cases/ (the mesh's own resolution, and the
# armadillo and dino Loop-subdivided at the levels listed in SUBDIVIDE, e.g.
# SUBDIVIDE="1 2"), and runs compare.sh on each, ROUNDS rounds (default 3).
# The harness builds its programs against the installed package with the
# library's defaults.
#
#   bash benchmark/run_harness_comparison.sh [ROUNDS] [CASE ...]
#
# Output: one log per case in $OUT (default build/harness; the subdivided
# cases as CASE_LEVEL.log), and the lines of compare.sh with the ratios on
# standard output. benchmark/plot_harness.py makes the table and the figure
# from the logs.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${SSMD_BUILD_DIR:-$root/build}"
bench="${SSMD_HARNESS_DIR:-$root/../shared/bench}"
rounds="${1:-3}"
shift || true
out="$(realpath -m "${OUT:-$build/harness}")"
if [ ! -x "$bench/compare.sh" ]; then
  echo "error: the reference harness is not at $bench (set SSMD_HARNESS_DIR)" >&2
  exit 1
fi
bash "$root/scripts/fetch_sample_meshes.sh" >/dev/null
mkdir -p "$out/cases"
cmake --install "$build" --prefix "$out/prefix" >/dev/null
export BENCH_BUILD="${BENCH_BUILD:-$out/bench-build}"
meshes="$build/data/meshes"

cases=("$@")
if [ ${#cases[@]} -eq 0 ]; then
  cases=(cactus_top elephant_top dino_neck bunny_ears armadillo_arm)
fi
for name in "${cases[@]}"; do
  spec="$root/benchmark/harness_cases/$name.json"
  prefix="$out/cases/$name"
  /usr/bin/python3 "$bench/make_case.py" "$spec" --data-dir "$meshes" --out-prefix "$prefix" >/dev/null
  mesh="$meshes/$(python3 -c 'import json, sys; print(json.load(open(sys.argv[1]))["mesh"])' "$spec")"
  echo "== $name ($mesh)"
  bash "$bench/compare.sh" "$out/prefix" "$mesh" "$prefix.sel" "$prefix.def" "$rounds" | tee "$out/$name.log" |
    grep -E "^round [0-9]+, "
  if [ "$name" = cactus_top ] || [ "$name" = elephant_top ] || [ "$name" = bunny_ears ]; then
    continue
  fi
  for level in ${SUBDIVIDE:-}; do
    fine="$out/cases/${name}_$level.off"
    [ -f "$fine" ] || "$BENCH_BUILD/arap/subdivide" "$mesh" "$fine" "$level" >/dev/null
    /usr/bin/python3 "$bench/make_case.py" "$spec" --mesh "$fine" --out-prefix "${prefix}_$level" >/dev/null
    echo "== ${name}, subdivided $level times"
    bash "$bench/compare.sh" "$out/prefix" "$fine" "${prefix}_$level.sel" "${prefix}_$level.def" "$rounds" |
      tee "$out/${name}_$level.log" | grep -E "^round [0-9]+, "
  done
done
