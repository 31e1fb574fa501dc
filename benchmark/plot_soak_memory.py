#!/usr/bin/env python3
# Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Plots the resident memory of a soak run (benchmark_soak --memory-table)
against the number of drags: plot_soak_memory.py MEMORY.tsv OUTPUT.png"""
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    drags, rss = [], []
    with open(sys.argv[1]) as table:
        next(table)
        for line in table:
            fields = line.split("\t")
            drags.append(int(fields[0]))
            rss.append(float(fields[2]))
    figure, axes = plt.subplots(figsize=(8, 3.5), dpi=110)
    axes.plot(drags, rss, color="#1f77b4")
    axes.set_xlabel("drags")
    axes.set_ylabel("resident memory (MiB)")
    axes.set_ylim(0, max(rss) * 1.15)
    axes.grid(alpha=0.3)
    axes.set_title("Soak run: resident memory after each drag")
    figure.tight_layout()
    figure.savefig(sys.argv[2])


if __name__ == "__main__":
    main()
