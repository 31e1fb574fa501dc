#!/usr/bin/env bash
# Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
# SPDX-License-Identifier: GPL-3.0-or-later
# Measures the preparation and the updates a second of the viewer's page
# (doc/viewer.md) in headless Chromium, the armadillo's right arm dragged at
# 26k and 104k vertices, each with a fresh server PREPARATIONS times, and
# writes benchmark/results/viewer.md.
#
# Usage: benchmark/run_viewer_benchmark.sh [ROUNDS [SECONDS [PREPARATIONS]]]
#        (default 5 rounds of 4 s, 3 preparations)
# Environment: SSMD_BUILD_DIR (default <repository>/build).
set -euo pipefail

benchmark_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
repository="$(cd "${benchmark_dir}/.." && pwd)"
build_dir="${SSMD_BUILD_DIR:-${repository}/build}"
rounds="${1:-5}" seconds="${2:-4}" preparations="${3:-3}"
results="${benchmark_dir}/results/viewer.md"

cmake -S "${repository}" -B "${build_dir}" -DCMAKE_BUILD_TYPE=Release -DSSMD_BUILD_TOOLS=ON >/dev/null
cmake --build "${build_dir}" --target ssmd_viewer -j 2
SSMD_BUILD_DIR="${build_dir}" "${repository}/scripts/fetch_sample_meshes.sh" >/dev/null
bash "${repository}/scripts/install_viewer_web.sh" "${build_dir}" --test
# As scripts/viewer.sh: OpenMP threads that spin while waiting take the cores the browser renders on.
export OMP_WAIT_POLICY=passive

run_level() {
  local level="$1" log="${build_dir}/viewer_benchmark_server.log" url=""
  "${build_dir}/tools/ssmd_viewer/ssmd_viewer" "${build_dir}/data/meshes/armadillo.off" --subdivide "${level}" --port 0 \
    --three-dir "${build_dir}/viewer_web/node_modules/three" > "${log}" 2>&1 &
  local server=$!
  for _ in $(seq 1 1200); do
    url="$(grep -o 'http://127\.0\.0\.1:[0-9]*/' "${log}" || true)"
    [ -n "${url}" ] && break
    sleep 0.1
  done
  [ -n "${url}" ] || { cat "${log}" >&2; kill "${server}"; exit 1; }
  node "${benchmark_dir}/viewer_page_rate.mjs" "${url}" "${build_dir}/viewer_web" "${rounds}" "${seconds}"
  kill "${server}"
  wait "${server}" 2>/dev/null || true
}

started="$(date -u '+%Y-%m-%d %H:%M UTC')"
measurements="${build_dir}/viewer_benchmark.jsonl"
: > "${measurements}"
for level in 0 1; do
  for _ in $(seq 1 "${preparations}"); do
    run_level "${level}" >> "${measurements}"
  done
done
cpu="$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//')"
/usr/bin/python3 - "${measurements}" "${started}" "${cpu}" "$(nproc)" "$(git -C "${repository}" rev-parse --short HEAD)" "${seconds}" > "${results}" <<'PY'
import json, statistics, sys
measurements, started, cpu, cores, revision, seconds = sys.argv[1:7]
with open(measurements) as lines:
    runs = [json.loads(line) for line in lines if line.strip()]
print("# The viewer's page: updates a second while the handle is dragged\n")
print(f"- Date: {started}, revision {revision}")
print(f"- Machine: {cpu}, {cores} logical CPUs, no GPU; the server, Chromium and its software renderer share them")
print(f"- Browser: {runs[0]['browser']} headless, WebGL by SwiftShader, 1200 × 800, multisampling "
      f"{'on' if runs[0]['antialias'] else 'off (software renderer)'}")
print("- Server: `ssmd_viewer` (Release), its defaults (2 solves per drag, 1000 rotation patches), `OMP_WAIT_POLICY=passive`")
print(f"- Drag: the armadillo's right arm (the browser test's boxes), the handle moved along a circle as a pointer would "
      f"(120 moves a second, one drag in flight), {len(runs[0]['rounds'])} rounds of {seconds} s in a row; "
      "*updates* are the deformed meshes the page applied, *frames* the frames it drew\n")
print("| vertices | region | preparation in the page | the server's `preprocess()` |")
print("|--:|--:|--:|--:|")
for run in runs:
    print(f"| {run['vertices']:,} | {run['region']:,} | {run['preparationPageSeconds']:.3f} s | {run['preprocessSeconds']:.3f} s |")
print()
print("| vertices | region | round | updates a second | frames a second | last `deform()` | last round trip |")
print("|--:|--:|--:|--:|--:|--:|--:|")
for run in runs:
    for i, r in enumerate(run["rounds"], 1):
        print(f"| {run['vertices']:,} | {run['region']:,} | {i} | {r['updatesPerSecond']:.1f} | {r['framesPerSecond']:.1f} | "
              f"{r['lastDeformMs']:.1f} ms | {r['lastRoundTripMs']:.1f} ms |")
print("\n| vertices | preparation in the page: median | lowest | highest | updates a second: median | lowest | highest | frames a second: median |")
print("|--:|--:|--:|--:|--:|--:|--:|--:|")
for vertices in sorted({run["vertices"] for run in runs}):
    level = [run for run in runs if run["vertices"] == vertices]
    p = [run["preparationPageSeconds"] for run in level]
    u = [r["updatesPerSecond"] for run in level for r in run["rounds"]]
    f = [r["framesPerSecond"] for run in level for r in run["rounds"]]
    print(f"| {vertices:,} | {statistics.median(p):.3f} s | {min(p):.3f} s | {max(p):.3f} s | "
          f"{statistics.median(u):.1f} | {min(u):.1f} | {max(u):.1f} | {statistics.median(f):.1f} |")
PY
cat "${results}"
