#!/usr/bin/env python3
# Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""The cost of the Python binding against the C++ call, in the same run.

    benchmark_python_binding.py CPP_PROGRAM CASE_FILE LEVELS WORK_DIR [REPETITIONS [DRAGS]] [--output FILE]

Runs CPP_PROGRAM (benchmark_python_binding), which writes the case's arrays to
WORK_DIR and times the C++ call on them; then times the same steps through
ssmd.Deformation (the arrays in, the positions out), checks that the results
agree, and prints (and writes with --output) a Markdown table of medians.
"""

import argparse
import os
import platform
import shlex
import statistics
import subprocess
import time

import numpy as np

import ssmd


def drag_targets(V, handles, targets, k, drags):
    s = 0.5 + 0.5 * (k + 1) / drags
    rest = V[handles]
    return rest + s * (targets - rest)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("program")
    parser.add_argument("case_file")
    parser.add_argument("levels", type=int)
    parser.add_argument("work_dir")
    parser.add_argument("repetitions", type=int, nargs="?", default=3)
    parser.add_argument("drags", type=int, nargs="?", default=10)
    parser.add_argument("--output")
    args = parser.parse_args()
    os.makedirs(args.work_dir, exist_ok=True)

    def run_cpp():
        line = subprocess.run([args.program, args.case_file, str(args.levels), args.work_dir, "1",
                               str(args.drags)], check=True, capture_output=True, text=True).stdout
        words = shlex.split(line)
        return dict(zip(words[::2], words[1::2]))

    def load(name, dtype, columns=None):
        a = np.fromfile(os.path.join(args.work_dir, name), dtype=dtype)
        return a.reshape(-1, columns) if columns else a

    # Rounds alternate the two sides, so that a change of the machine's load
    # touches both alike.
    cpp_first, cpp_drag, first, drag, difference = [], [], [], [], 0.0
    for r in range(args.repetitions):
        cpp = run_cpp()
        cpp_first.append(float(cpp["first_result"]))
        cpp_drag.append(float(cpp["drag"]))
        V, F = load("V.f64", np.float64, 3), load("F.i64", np.int64, 3)
        roi, handles = load("roi.i64", np.int64), load("handles.i64", np.int64)
        targets = load("targets.f64", np.float64, 3)
        start = time.perf_counter()
        d = ssmd.Deformation(V, F, roi=roi, handles=handles, m=100)
        d.set_targets(drag_targets(V, handles, targets, args.drags - 1, args.drags))
        W = d.deform(iterations=10, tolerance=1e-4)
        first.append(time.perf_counter() - start)
        d.reset()
        drags = []
        for k in range(args.drags):
            start = time.perf_counter()
            d.set_targets(drag_targets(V, handles, targets, k, args.drags))
            W = d.deform(iterations=10, tolerance=1e-4)
            drags.append(time.perf_counter() - start)
        drag.append(statistics.median(drags))
        difference = max(difference, float(np.max(np.abs(W - load("cpp_result.f64", np.float64, 3)))))

    cpp_first, cpp_drag = statistics.median(cpp_first), statistics.median(cpp_drag)
    py_first, py_drag = statistics.median(first), statistics.median(drag)
    table = [
        "| step | C++ (s) | Python (s) | Python / C++ |",
        "|---|---|---|---|",
        "| first result: arrays in, preprocess, deform(10), positions out | %.3f | %.3f | %.3f |"
        % (cpp_first, py_first, py_first / cpp_first),
        "| drag: new targets, deform(10), positions out | %.4f | %.4f | %.3f |"
        % (cpp_drag, py_drag, py_drag / cpp_drag),
    ]
    text = "\n".join([
        "# The Python binding against the C++ call",
        "",
        "- Case: %s, %d Loop subdivision level(s): %d vertices, %d handles, region of %d vertices"
        % (os.path.basename(args.case_file), args.levels, len(V), len(handles), len(roi)),
        "- %d rounds, each a C++ run then a Python run: a first result and the median of %d drags "
        "per side; medians over the rounds. Largest difference between the two results: %.1e"
        % (args.repetitions, args.drags, difference),
        "- Machine: %s, %d cores; %s, flags %s; Python %s, NumPy %s"
        % (cpp["machine"], os.cpu_count(), cpp["compiler"], cpp["flags"], platform.python_version(),
           np.__version__),
        "",
    ] + table) + "\n"
    print(text)
    if args.output:
        with open(args.output, "w") as out:
            out.write(text)
    if difference > 1e-12:
        raise SystemExit("the Python and C++ results differ by %.3g" % difference)


if __name__ == "__main__":
    main()
