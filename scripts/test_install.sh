#!/usr/bin/env bash
# Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
# SPDX-License-Identifier: GPL-3.0-or-later
# The installed CMake package as another project uses it: installs the
# package to a temporary prefix, then configures, builds and runs the consumer
# of test/install_consumer once per component combination (none, CHOLMOD,
# OpenMP, OpenBLAS, all), one after the other, each with the compiled core of
# its components (which the consumer checks it uses). For every build it checks the
# compile line (-fopenmp only with OpenMP, the CHOLMOD and OpenBLAS macros
# only with their components) and the link line (each library only with its
# component). Then it
# configures the consumer against a CGAL that reports 6.0 (accepted) and one
# that reports 7.0 (rejected).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
script_start=$(date +%s)

bash "$root/scripts/install_dependencies.sh"

work="$(mktemp -d "${TMPDIR:-/tmp}/ssmd_install_test.XXXXXX")"
trap 'rm -rf "$work"' EXIT
prefix="$work/prefix"

step_start=$(date +%s)
cmake -S "$root" -B "$work/package" -DCMAKE_INSTALL_PREFIX="$prefix" \
  -DSSMD_BUILD_TESTS=OFF -DSSMD_BUILD_EXAMPLES=OFF -DSSMD_BUILD_BENCHMARKS=OFF \
  -DSSMD_BUILD_TOOLS=OFF -DSSMD_BUILD_FUZZERS=OFF -DSSMD_BUILD_DOC=OFF -DSSMD_BUILD_PYTHON=OFF \
  >"$work/package.log" 2>&1 || { cat "$work/package.log"; exit 1; }
cmake --install "$work/package" >>"$work/package.log" 2>&1 || { cat "$work/package.log"; exit 1; }
echo "install to $prefix: $(( $(date +%s) - step_start )) s"

fail() {
  echo "FAIL [$1]: $2" >&2
  exit 1
}

# check_present LABEL TEXT PATTERN WANTED WHAT: PATTERN must occur in TEXT
# when WANTED is 1 and must not occur otherwise.
check_present() {
  local label="$1" text="$2" pattern="$3" wanted="$4" what="$5"
  if grep -qE -- "$pattern" <<<"$text"; then
    [ "$wanted" = 1 ] || fail "$label" "$what although the component was not asked for"
  else
    [ "$wanted" = 0 ] || fail "$label" "no $what although the component was asked for"
  fi
}

# The consumer is built without a build type (no optimization): the compile
# time is that of the package's headers, the run is on a tiny mesh. The five
# combinations are configured one after the other, the two built ones
# compiled as many at a time as there are cores, then all checked one after
# the other.
all_components=("" "CHOLMOD" "OpenMP" "OpenBLAS" "CHOLMOD;OpenBLAS;OpenMP")
built_components=("" "CHOLMOD;OpenBLAS;OpenMP")
is_built() { [ "$1" = "" ] || [ "$1" = "CHOLMOD;OpenBLAS;OpenMP" ]; }
consumer_dir() { echo "$work/consumer_$(tr ';' '_' <<<"${1:-none}")"; }
builds_start=$(date +%s)
for components in "${all_components[@]}"; do
  build="$(consumer_dir "$components")"
  if ! cmake -S "$root/test/install_consumer" -B "$build" -DCMAKE_PREFIX_PATH="$prefix" \
       -DSSMD_COMPONENTS="$components" -DCMAKE_EXPORT_COMPILE_COMMANDS=ON \
       -DCGAL_DO_NOT_WARN_ABOUT_CMAKE_BUILD_TYPE=TRUE \
       >"$build.log" 2>&1; then
    cat "$build.log"
    fail "${components:-no component}" "configuration failed"
  fi
done
for components in "${built_components[@]}"; do consumer_dir "$components"; done |
  xargs -P "$(nproc)" -I{} sh -c 'cmake --build "{}" >>"{}.log" 2>&1 || touch "{}.failed"'
echo "consumer builds: $(( $(date +%s) - builds_start )) s"

for components in "${all_components[@]}"; do
  label="${components:-no component}"
  build="$(consumer_dir "$components")"
  if [ -e "$build.failed" ]; then
    cat "$build.log"
    fail "$label" "build failed"
  fi

  compile_line="$(grep '"command"' "$build/compile_commands.json")"
  link_line="$(cat "$build/CMakeFiles/consumer.dir/link.txt")"
  wants() { [[ ";$components;" == *";$1;"* ]] && echo 1 || echo 0; }
  check_present "$label" "$compile_line" '-fopenmp' "$(wants OpenMP)" "-fopenmp on the compile line"
  check_present "$label" "$compile_line" '-DCGAL_SSMD_USE_CHOLMOD' "$(wants CHOLMOD)" \
    "CGAL_SSMD_USE_CHOLMOD on the compile line"
  check_present "$label" "$compile_line" '-DCGAL_SSMD_USE_OPENBLAS' "$(wants OpenBLAS)" \
    "CGAL_SSMD_USE_OPENBLAS on the compile line"
  check_present "$label" "$link_line" 'gomp|-fopenmp' "$(wants OpenMP)" "OpenMP on the link line"
  check_present "$label" "$link_line" 'cholmod' "$(wants CHOLMOD)" "CHOLMOD on the link line"
  check_present "$label" "$link_line" 'openblas' "$(wants OpenBLAS)" "OpenBLAS on the link line"
  check_present "$label" "$link_line" 'SSMD_compiled_core' 1 "compiled core on the link line"

  if is_built "$components"; then
    output="$("$build/consumer")" || { echo "$output"; fail "$label" "the consumer failed"; }
    echo "consumer [$label]: $output"
  else
    echo "consumer [$label]: compile and link lines checked"
  fi
done

# CGAL's version file accepts only the major version asked for: the package
# must accept CGAL 6 and reject CGAL 7 by its own check. Two stand-ins load
# the installed CGAL but report another version.
step_start=$(date +%s)
cgal_dir="$(sed -n 's/^CGAL_DIR:PATH=//p' "$work/package/CMakeCache.txt")"
[ -f "$cgal_dir/CGALConfig.cmake" ] || fail "CGAL range" "no CGALConfig.cmake in '$cgal_dir'"
for version in 6.0.0 7.0.0; do
  fake="$work/cgal_$version"
  mkdir -p "$fake"
  echo "include(\"$cgal_dir/CGALConfig.cmake\")" >"$fake/CGALConfig.cmake"
  cat >"$fake/CGALConfigVersion.cmake" <<EOF
set(PACKAGE_VERSION $version)
set(PACKAGE_VERSION_COMPATIBLE TRUE)
if(PACKAGE_FIND_VERSION)
  if(PACKAGE_VERSION VERSION_LESS PACKAGE_FIND_VERSION
     OR NOT PACKAGE_FIND_VERSION_MAJOR STREQUAL "${version%%.*}")
    set(PACKAGE_VERSION_COMPATIBLE FALSE)
  endif()
endif()
EOF
  if cmake -S "$root/test/install_consumer" -B "$work/consumer_cgal_$version" \
       -DCMAKE_PREFIX_PATH="$prefix" -DCGAL_DIR="$fake" >"$work/cgal_$version.log" 2>&1; then
    [ "$version" = 6.0.0 ] || fail "CGAL $version" "accepted"
  else
    [ "$version" = 7.0.0 ] || { cat "$work/cgal_$version.log"; fail "CGAL $version" "rejected"; }
    grep -q "needs CGAL 5.5 to 6.x" "$work/cgal_$version.log" ||
      { cat "$work/cgal_$version.log"; fail "CGAL $version" "rejected without the reason"; }
  fi
done
echo "CGAL 6.0 accepted, CGAL 7.0 rejected: $(( $(date +%s) - step_start )) s"

# The CPU time beside the elapsed time: on a loaded machine the elapsed time
# says little about the cost of the test.
times >"$work/times"
read -r children_user children_system < <(tail -n 1 "$work/times")
echo "install test passed: $(( $(date +%s) - script_start )) s" \
  "(CPU time of the builds: user $children_user, system $children_system)"
