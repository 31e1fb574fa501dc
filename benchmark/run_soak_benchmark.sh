#!/usr/bin/env bash
# Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
# SPDX-License-Identifier: GPL-3.0-or-later
# The soak run: 10,000 drags with random targets on the armadillo's arm case
# Loop-subdivided once (104k vertices), then the plot of its memory. Writes
# benchmark/results/soak.md, soak_memory.tsv and soak_memory.png. Takes
# tens of minutes on 2 cores.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${SSMD_BUILD_DIR:-$root/build}"
results="$root/benchmark/results"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DSSMD_BUILD_BENCHMARKS=ON >/dev/null
cmake --build "$build" --parallel "${SSMD_JOBS:-$(nproc)}" --target benchmark_soak
bash "$root/scripts/fetch_sample_meshes.sh"
"$build/benchmark/benchmark_soak" --level 1 --drags "${SSMD_SOAK_DRAGS:-10000}" \
  --meshes "$build/data/meshes" --output "$results/soak.md" --memory-table "$results/soak_memory.tsv"
/usr/bin/python3 "$root/benchmark/plot_soak_memory.py" "$results/soak_memory.tsv" "$results/soak_memory.png"
