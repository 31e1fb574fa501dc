#!/usr/bin/env python3
# Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Cost of a drag against the number of vertices, log-log, from the table of
benchmark_drag --data: per variant the median of each part (iteration, detail
transfer, output) and CGAL ARAP's whole deform(), with the slope of each line.

Usage: plot_drag.py drag.tsv drag_scaling.png
"""
import csv
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def main(table, figure):
    parts = defaultdict(lambda: defaultdict(list))
    with open(table, newline="") as f:
        for row in csv.DictReader(f, delimiter="\t"):
            n = int(row["vertices"])
            if int(row["patches"]) < 0:
                parts[("CGAL ARAP", "deform(10)")][n].append(float(row["total"]))
                continue
            for part in ("iteration", "detail_transfer", "output"):
                parts[(row["variant"], part.replace("_", " "))][n].append(float(row[part]))
    fig, ax = plt.subplots(figsize=(7.5, 5))
    styles = {"iteration": "-o", "detail transfer": "--s", "output": ":^", "deform(10)": "-D"}
    for (variant, part), by_n in sorted(parts.items()):
        ns = np.array(sorted(by_n))
        medians = np.array([np.median(by_n[n]) for n in ns]) * 1000
        slope = np.polyfit(np.log(ns), np.log(medians), 1)[0] if len(ns) > 1 else float("nan")
        ax.loglog(ns, medians, styles[part], label=f"{variant}: {part} (slope {slope:.2f})")
    ax.set_xlabel("vertices")
    ax.set_ylabel("median per drag (ms)")
    ax.set_title("Cost of a drag against the size of the mesh")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(figure, dpi=110)


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
