#!/usr/bin/env python3
# Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Time to the first deformed mesh against the number of vertices, log-log,
from the tables of one or more reports of benchmark_drag (the column *first
result*: constructor, preprocess and the first drag): this package with the
exact and with the approximate basis against CGAL ARAP.

Usage: plot_first_result.py figure.png drag.md [drag.md ...]
"""
import re
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def seconds(text):
    value, unit = text.split()
    return float(value) / 1000.0 if unit == "ms" else float(value)


def read(reports):
    """{variant: {n: seconds}} from the markdown tables of the reports."""
    series = defaultdict(dict)
    for report in reports:
        n = None
        first_column = None
        for line in open(report, encoding="utf-8"):
            header = re.match(r"### .* @\d+: (\d+) vertices", line)
            if header:
                n = int(header.group(1))
                continue
            cells = [c.strip() for c in line.strip().strip("|").split("|")]
            if n is None or len(cells) < 10:
                continue
            if cells[0] == "algorithm":
                first_column = cells.index("first result")
                continue
            if first_column is None or cells[0].startswith("---"):
                continue
            series[cells[0]][n] = seconds(cells[first_column])
    return series


def main(figure, reports):
    series = read(reports)
    plt.figure(figsize=(6.4, 4.2))
    styles = {"CGAL": ("black", "s"), "partition-of-unity": ("tab:green", "o"), "spectral": ("tab:blue", "^")}
    # The first result does not depend on the iteration: the variants of one
    # basis (full iteration, rotation patches) are one series, their fastest
    # run at each size.
    merged = defaultdict(dict)
    for name, points in series.items():
        key = "CGAL" if name.startswith("CGAL") else ("partition-of-unity" if "partition" in name else "spectral")
        for n, t in points.items():
            merged[key][n] = min(t, merged[key].get(n, t))
    labels = {"CGAL": "CGAL ARAP", "partition-of-unity": "this package, approximate basis",
              "spectral": "this package, exact basis"}
    for key in ("CGAL", "spectral", "partition-of-unity"):
        if key not in merged:
            continue
        points = merged[key]
        colour, marker = styles[key]
        ns = sorted(points)
        plt.loglog(ns, [points[n] for n in ns], marker=marker, color=colour, label=labels[key])
    plt.xlabel("vertices")
    plt.ylabel("constructor to first deformed mesh (s)")
    plt.title("First result: the armadillo's arm, exact constraints")
    plt.grid(True, which="both", alpha=0.3)
    plt.legend()
    plt.tight_layout()
    plt.savefig(figure, dpi=110)


if __name__ == "__main__":
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2:])
