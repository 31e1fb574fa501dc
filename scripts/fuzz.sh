#!/usr/bin/env bash
# Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
# SPDX-License-Identifier: GPL-3.0-or-later
# Builds the libFuzzer harnesses of fuzz/ with clang, AddressSanitizer and
# UndefinedBehaviorSanitizer, and runs each one in turn on its seed corpus.
#
#   bash scripts/fuzz.sh [SECONDS_PER_HARNESS] [HARNESS...]
#
# SECONDS_PER_HARNESS defaults to 600; the harnesses default to all of them
# (fuzz_selection_io, fuzz_basis_io, fuzz_deformation). Environment:
#   SSMD_FUZZ_BUILD_DIR  build directory (default: build-fuzz in the repository, ignored by git)
#   SSMD_FUZZ_OUT        where new corpus entries, crashes and logs go
#                        (default: ${TMPDIR:-/tmp}/ssmd-fuzz, outside the repository)
#   SSMD_JOBS            parallel build jobs (default: nproc)
# The exit status is non-zero when a harness reported a crash, a sanitizer
# error, a timeout or a violated property; the input is then in
# $SSMD_FUZZ_OUT/<harness>/artifacts/.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${SSMD_FUZZ_BUILD_DIR:-$root/build-fuzz}"
out="${SSMD_FUZZ_OUT:-${TMPDIR:-/tmp}/ssmd-fuzz}"
jobs="${SSMD_JOBS:-$(nproc)}"
seconds="${1:-600}"
shift || true
harnesses=("$@")
if [ ${#harnesses[@]} -eq 0 ]; then
  harnesses=(fuzz_selection_io fuzz_basis_io fuzz_deformation)
fi

# The package's dependencies, then clang and its libFuzzer runtime (Debian 12:
# libclang_rt.fuzzer comes with libclang-rt-14-dev).
bash "$root/scripts/install_dependencies.sh" clang libclang-rt-14-dev

cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_COMPILER=clang++ -DSSMD_BUILD_FUZZERS=ON \
  -DSSMD_BUILD_TESTS=OFF -DSSMD_BUILD_EXAMPLES=OFF -DSSMD_BUILD_BENCHMARKS=OFF \
  -DSSMD_BUILD_TOOLS=OFF -DSSMD_BUILD_DOC=OFF >/dev/null
cmake --build "$build" --parallel "$jobs" --target "${harnesses[@]}"

export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
status=0
for harness in "${harnesses[@]}"; do
  corpus="$out/$harness/corpus"
  artifacts="$out/$harness/artifacts"
  mkdir -p "$corpus" "$artifacts"
  log="$out/$harness/$(date -u +%Y%m%dT%H%M%SZ).log"
  echo "== $harness: ${seconds} s, new inputs in $corpus, log $log"
  # New inputs go to the first directory; the committed seeds are only read.
  if "$build/fuzz/$harness" "$corpus" "$root/fuzz/corpus/$harness" \
      -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=4096 \
      -artifact_prefix="$artifacts/" -print_final_stats=1 >"$log" 2>&1; then
    echo "   no finding"
  else
    echo "   FINDING: see $log and $artifacts" >&2
    status=1
  fi
  grep -E "^#[0-9]+ +(DONE|INITED)" "$log" | tail -n 2 || true
  grep -E "^stat::number_of_executed_units|^stat::peak_rss_mb" "$log" || true
done
exit $status
