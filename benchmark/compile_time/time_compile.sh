#!/usr/bin/env bash
# Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
# SPDX-License-Identifier: GPL-3.0-or-later
# Compile time of main_header_default_tag.cpp with the flags a consumer of the
# installed package gets (no tests, no OpenMP unless EXTRA_FLAGS adds it), the
# median of REPEATS runs, and the shared libraries the program links.
#   time_compile.sh [REPEATS] [EXTRA_FLAGS...]
# SSMD_INCLUDE_DIR selects the headers (default: this tree's include/), so
# that two versions can be timed in the same run.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
include_dir="${SSMD_INCLUDE_DIR:-$here/../../include}"
repeats="${1:-3}"
shift || true
out="$(mktemp -d)"
times=()
for ((r = 0; r < repeats; ++r)); do
  start=$(date +%s.%N)
  c++ -std=c++17 -O3 -DNDEBUG -frounding-math -DCGAL_SSMD_USE_CHOLMOD -DCGAL_SSMD_USE_BLAS \
    -DCGAL_SSMD_USE_OPENBLAS -I"$include_dir" -isystem /usr/include/eigen3 \
    -isystem /usr/include/suitesparse "$@" -c "$here/main_header_default_tag.cpp" -o "$out/probe.o"
  end=$(date +%s.%N)
  times+=("$(awk -v a="$start" -v b="$end" 'BEGIN {printf "%.3f", b - a}')")
done
printf '%s\n' "${times[@]}" | sort -n | awk '{a[NR]=$1} END {printf "compile seconds: median %.2f (runs:", a[int((NR+1)/2)]; for(i=1;i<=NR;++i) printf " %.2f", a[i]; print ")"}'
c++ "$out/probe.o" -o "$out/probe" "$@" -lcholmod -lsuitesparseconfig -lopenblas -lgmp -lmpfr -lpthread
# Direct dependencies (ldd would add libgomp through Debian's CHOLMOD, which
# uses OpenMP internally whatever the program does).
echo "needs: $(readelf -d "$out/probe" | awk '/NEEDED/ {print $5}' | tr -d '[]' | grep -E 'gomp|cholmod|openblas' | tr '\n' ' ')"
rm -rf "$out"
