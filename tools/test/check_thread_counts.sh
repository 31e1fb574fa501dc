#!/usr/bin/env bash
# Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
# SPDX-License-Identifier: GPL-3.0-or-later
# Runs a deformation command with OMP_NUM_THREADS=1, then 2, and checks that
# the two meshes written agree to TOLERANCE of the bounding-box diagonal (the
# thread counts change the order of some sums, not the result).
#
#   check_thread_counts.sh TOLERANCE OUTPUT.off -- COMMAND... (writing OUTPUT.off)
set -euo pipefail
tolerance="$1" output="$2"
shift 2
[ "$1" = "--" ] && shift
for threads in 1 2; do
  rm -f "$output"
  OMP_NUM_THREADS=$threads OPENBLAS_NUM_THREADS=$threads "$@" > /dev/null
  mv "$output" "$output.$threads"
done
python3 - "$output.1" "$output.2" "$tolerance" <<'PY'
import sys

def points(path):
    words = open(path).read().split()
    assert words[0] == "OFF", path
    n = int(words[1])
    return [tuple(map(float, words[4 + 3 * i:7 + 3 * i])) for i in range(n)]

a, b, tolerance = points(sys.argv[1]), points(sys.argv[2]), float(sys.argv[3])
assert len(a) == len(b), "different vertex counts"
low = [min(p[k] for p in a) for k in range(3)]
high = [max(p[k] for p in a) for k in range(3)]
diagonal = sum((h - l) ** 2 for h, l in zip(high, low)) ** 0.5
distance = max(sum((p[k] - q[k]) ** 2 for k in range(3)) ** 0.5 for p, q in zip(a, b)) / diagonal
print("largest distance between the results of 1 and 2 threads: %.3g of the diagonal" % distance)
if not distance <= tolerance:
    sys.exit("FAIL: above %g" % tolerance)
PY
