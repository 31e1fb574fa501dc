#!/usr/bin/env python3
# Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""ARAP energy against time, from the tables of benchmark_refinement --data:
one panel per mesh size, the package (deform() then refine()) and CGAL ARAP
from the rest pose, each point a checkpoint; the dotted line is 1 % above
CGAL ARAP's lowest energy.

Usage: plot_refinement.py FIGURE.png TABLE.tsv [TABLE.tsv ...]
"""
import csv
import os
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main(figure, tables):
    curves = defaultdict(lambda: defaultdict(list))  # (table, vertices) -> method -> points
    for table in tables:
        with open(table, newline="") as f:
            for row in csv.DictReader(f, delimiter="\t"):
                key = (table, int(row["vertices"]))
                curves[key][row["method"]].append((float(row["seconds"]), float(row["energy"])))
    keys = sorted(curves, key=lambda k: (tables.index(k[0]), k[1]))
    fig, axes = plt.subplots(1, len(keys), figsize=(5.2 * len(keys), 4.4), squeeze=False)
    for ax, key in zip(axes[0], keys):
        lowest = min(e for s, e in curves[key]["CGAL ARAP"])
        for method, points in sorted(curves[key].items()):
            seconds, energy = zip(*points)
            ax.loglog(seconds, energy, "-o" if method.startswith("package") else "-s", markersize=3, label=method)
        ax.axhline(1.01 * lowest, color="grey", linestyle=":", label="1 % above CGAL ARAP's lowest")
        ax.set_xlabel("seconds since the constructor")
        ax.set_ylabel("ARAP energy")
        case = os.path.splitext(os.path.basename(key[0]))[0].replace("refinement_", "").replace("_", " ")
        ax.set_title(f"{case}: {key[1]:,} vertices")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(figure, dpi=110)


if __name__ == "__main__":
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2:])
