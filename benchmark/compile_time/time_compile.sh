#!/usr/bin/env bash
# Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
# SPDX-License-Identifier: GPL-3.0-or-later
# Compile time and peak memory of a minimal consumer of the package
# (main_header_default_tag.cpp) against the same program written for CGAL's
# Surface_mesh_deformation (cgal_arap_default.cpp), same flags, same run,
# alternately, REPEATS times each (medians): the consumer as the CMake
# targets compile it (the compiled core linked: CGAL_SSMD_COMPILED_CORE set),
# the consumer with headers only (no compiled core), and CGAL's program; then
# the compiled core itself, which a build tree compiles once for all its
# programs. The flags are those of the package with the components CHOLMOD
# and OpenBLAS, -O3, one job.
#   time_compile.sh [REPEATS] [EXTRA_FLAGS...]
# SSMD_INCLUDE_DIR selects the headers (default: this tree's include/).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
include_dir="${SSMD_INCLUDE_DIR:-$here/../../include}"
core_source="$here/../../src/compiled_spectral_pipeline.cpp"
repeats="${1:-3}"
shift || true
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
flags=(-std=c++17 -O3 -DNDEBUG -frounding-math -DCGAL_SSMD_USE_CHOLMOD -DCGAL_SSMD_USE_BLAS
       -DCGAL_SSMD_USE_OPENBLAS -I"$include_dir" -isystem /usr/include/eigen3 -isystem /usr/include/suitesparse "$@")
# The configuration number of these flags (internal/compiled_core.h): CHOLMOD
# 1, BLAS 2, OpenBLAS 4, OpenMP 8.
configuration=7
for flag in "$@"; do [ "$flag" = "-fopenmp" ] && configuration=15; done

# compile NAME SOURCE [FLAGS...]: appends "seconds megabytes" to $out/NAME.
compile() {
  local name="$1" source="$2"
  shift 2
  /usr/bin/time -f "%e %M" -o "$out/$name.last" c++ "${flags[@]}" "$@" -c "$source" -o "$out/$name.o"
  awk '{printf "%s %.0f\n", $1, $2 / 1024}' "$out/$name.last" >>"$out/$name"
}
for ((r = 0; r < repeats; ++r)); do
  compile package "$here/main_header_default_tag.cpp" -DCGAL_SSMD_COMPILED_CORE=$configuration
  compile headers_only "$here/main_header_default_tag.cpp"
  compile cgal_arap "$here/cgal_arap_default.cpp"
done
compile core "$core_source" -DCGAL_SSMD_COMPILED_CORE=$configuration

median() { sort -n -k"$2" "$out/$1" | awk -v k="$2" '{a[NR]=$k} END {print a[int((NR+1)/2)]}'; }
cgal_seconds="$(median cgal_arap 1)"
report() {
  local seconds memory
  seconds="$(median "$1" 1)"
  memory="$(median "$1" 2)"
  printf '%-44s %8.1f s %6d MB   %5.2f x CGAL ARAP   (runs: %s)\n' "$2" "$seconds" "$memory" \
    "$(awk -v a="$seconds" -v b="$cgal_seconds" 'BEGIN {print a / b}')" "$(awk '{printf "%s ", $1}' "$out/$1")"
}
echo "compile time and peak memory, medians of $repeats runs (c++ $(c++ -dumpfullversion), ${flags[*]:0:4} ...):"
report package "package consumer, compiled core linked"
report headers_only "package consumer, headers only"
report cgal_arap "CGAL Surface_mesh_deformation consumer"
report core "compiled core (once per build tree)"

# The consumer links with the core, and needs no OpenMP runtime directly.
c++ "$out/package.o" "$out/core.o" -o "$out/probe" "$@" -lcholmod -lsuitesparseconfig -lopenblas -lgmp -lmpfr -lpthread
echo "needs: $(readelf -d "$out/probe" | awk '/NEEDED/ {print $5}' | tr -d '[]' | grep -E 'gomp|cholmod|openblas' | tr '\n' ' ')"
