#!/usr/bin/env python3
# Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""The package against CGAL ARAP over region size, from the logs of the
reference harness's compare.sh (written by run_harness_comparison.sh, one
log per case): a markdown table (medians over the rounds, the values of each
round in brackets) on standard output, and a figure, log-log, of the first
result and of a drag against the number of region vertices, package and
CGAL ARAP (ORIGINAL_ARAP with CHOLMOD on its SPD block, and SparseLU).

Usage: plot_harness.py figure.png case.log [case.log ...]
"""
import json
import os
import re
import statistics
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

ROUND = re.compile(r"^round (\d+), (CGAL ARAP, [A-Za-z]+): drag ([0-9.e-]+) s vs ([0-9.e-]+) s = [0-9.]+x; "
                   r"first result ([0-9.e-]+) s vs ([0-9.e-]+) s = [0-9.]+x")
PACKAGE = re.compile(r"^round (\d+) package: (\{.*\})")


def read(log):
    """The case of one log: region vertices and, per program, the rounds'
    (first result, drag) in seconds."""
    case = {"name": os.path.splitext(os.path.basename(log))[0], "region": None,
            "package": {}, "CGAL ARAP, CHOLMOD": {}, "CGAL ARAP, SparseLU": {}}
    for line in open(log, encoding="utf-8"):
        package = PACKAGE.match(line)
        if package:
            data = json.loads(package.group(2))
            case["region"] = data["region_vertices"]
            case["package"][int(package.group(1))] = (data["first_s"], data["drag_median_s"])
            continue
        peer = ROUND.match(line)
        if peer and peer.group(2) in case:
            case[peer.group(2)][int(peer.group(1))] = (float(peer.group(6)), float(peer.group(4)))
    if case["region"] is None or not case["CGAL ARAP, CHOLMOD"]:
        raise ValueError(log + ": no round of compare.sh")
    return case


def median(case, program, which):
    return statistics.median(values[which] for values in case[program].values())


def cell(case, program, which):
    values = [case[program][r][which] for r in sorted(case[program])]
    text = lambda s: "%.3g s" % s if s >= 0.1 else "%.3g ms" % (1000 * s)
    rounds = ", ".join(text(v) for v in values)
    return "%s (%s)" % (text(median(case, program, which)), rounds) if len(values) > 1 else text(values[0])


def table(cases):
    rows = ["| case | region (vertices) | first result | CGAL ARAP (CHOLMOD) | ratio | drag | "
            "CGAL ARAP `deform(10)` (CHOLMOD) | ratio |",
            "|---|--:|--:|--:|--:|--:|--:|--:|"]
    for c in cases:
        first = median(c, "CGAL ARAP, CHOLMOD", 0) / median(c, "package", 0)
        drag = median(c, "CGAL ARAP, CHOLMOD", 1) / median(c, "package", 1)
        rows.append("| %s | %s | %s | %s | %.2f× | %s | %s | %.1f× |" % (
            c["name"], format(c["region"], ","), cell(c, "package", 0), cell(c, "CGAL ARAP, CHOLMOD", 0), first,
            cell(c, "package", 1), cell(c, "CGAL ARAP, CHOLMOD", 1), drag))
    return "\n".join(rows)


def plot(cases, filename):
    x = [c["region"] for c in cases]
    figure, axes = plt.subplots(1, 2, figsize=(10, 4))
    styles = (("package", "this package (defaults)", "o-", "C0"),
              ("CGAL ARAP, CHOLMOD", "CGAL ARAP, CHOLMOD", "s--", "C3"),
              ("CGAL ARAP, SparseLU", "CGAL ARAP, SparseLU", "^:", "C1"))
    for axis, which, title in ((axes[0], 0, "first result"), (axes[1], 1, "a drag (deform(10, 0))")):
        for program, label, style, color in styles:
            if all(c[program] for c in cases):
                axis.plot(x, [median(c, program, which) for c in cases], style, color=color, label=label)
        axis.set_xscale("log")
        axis.set_yscale("log")
        axis.set_xlabel("region of interest (vertices)")
        axis.set_ylabel("seconds")
        axis.set_title(title)
        axis.grid(True, which="both", alpha=0.3)
    axes[0].legend()
    figure.tight_layout()
    figure.savefig(filename, dpi=120)


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    # compare.sh's build logs (bench-build.*.log) sit beside the cases' logs.
    logs = [log for log in sys.argv[2:] if not os.path.basename(log).startswith("bench-build.")]
    cases = sorted((read(log) for log in logs), key=lambda c: c["region"])
    print(table(cases))
    plot(cases, sys.argv[1])


if __name__ == "__main__":
    main()
