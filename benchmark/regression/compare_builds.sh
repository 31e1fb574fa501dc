#!/usr/bin/env bash
# Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
# SPDX-License-Identifier: GPL-3.0-or-later
# Runs two builds of ssmd_deform on the same inputs and reports the largest
# coordinate difference of their results, relative to the bounding-box
# diagonal: a refactoring that must not change results is checked with
#   compare_builds.sh OLD/ssmd_deform NEW/ssmd_deform [WORKDIR]
# Inputs: CGAL's armadillo (right arm rotated by 70 degrees, feet fixed) and
# the Botsch-Sorkine bar, cactus and plane when ../shared/data/botsch08 is
# present; algorithms spectral (both policies), linear and spatial.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
old="$1"
new="$2"
work="${3:-$(mktemp -d)}"
meshes="${SSMD_BUILD_DIR:-$root/build}/data/meshes"
botsch="$root/../shared/data/botsch08"
mkdir -p "$work"

/usr/bin/python3 "$root/scripts/make_selection.py" "$meshes/armadillo.off" "$work/armadillo" \
  --handle 50 40 -100 100 100 100 --fixed -100 -100 -100 100 -38 100 \
  --rotate 0 0 1 -70 22 52 -20 > /dev/null
cases=("$meshes/armadillo.off $work/armadillo.sel $work/armadillo.def")
for name in bar cactus plane; do
  if [ -f "$botsch/$name.off" ]; then
    cases+=("$botsch/$name.off $botsch/$name.sel $botsch/$name.def")
  fi
done

worst=0
for c in "${cases[@]}"; do
  read -r mesh sel def <<< "$c"
  stem="$(basename "$mesh" .off)"
  for variant in "spectral exact" "spectral soft" "linear exact" "spatial exact"; do
    read -r algorithm policy <<< "$variant"
    tag="${stem}_${algorithm}_${policy}"
    "$old" -q --no-cache --algorithm "$algorithm" --policy "$policy" -o "$work/old_$tag.off" "$mesh" "$sel" "$def"
    "$new" -q --no-cache --algorithm "$algorithm" --policy "$policy" -o "$work/new_$tag.off" "$mesh" "$sel" "$def"
    difference=$(/usr/bin/python3 - "$work/old_$tag.off" "$work/new_$tag.off" <<'PY'
import sys
import numpy as np
def read_off(path):
    tokens = []
    with open(path) as f:
        for line in f:
            line = line.split('#')[0].split()
            tokens.extend(line)
    assert tokens[0] == 'OFF'
    n = int(tokens[1])
    return np.array(tokens[4:4 + 3 * n], dtype=float).reshape(n, 3)
a, b = read_off(sys.argv[1]), read_off(sys.argv[2])
diagonal = np.linalg.norm(a.max(0) - a.min(0))
print(f"{np.abs(a - b).max() / diagonal:.3e}")
PY
)
    printf '%-28s max |old - new| / diagonal = %s\n' "$tag" "$difference"
  done
done
