#!/usr/bin/env python3
# Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
# SPDX-License-Identifier: GPL-3.0-or-later
#
# Draws the figures of the deformation benchmark from the data file written by
# benchmark_deformation (--data):
#   - deformation_time_vs_m.png: the paper's Figure 5, the phases of the
#     spectral solver against the number of frequencies m on one case, with
#     the spatial solver and CGAL ARAP on the same case for reference;
#   - deformation_time_vs_n.png: every phase of every algorithm against the
#     number of vertices of the region, log-log, on the Loop-subdivided meshes.
#
# Usage: plot_deformation.py DATA.tsv OUTPUT_DIRECTORY [--figure5-case NAME@LEVEL]
#                            [--scaling-case NAME]

import argparse
import csv
import math
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

PEERS = [
    ("cgal_original", "CGAL ARAP, original", "tab:red", "o", "-"),
    ("cgal_sre", "CGAL ARAP, SRE", "tab:orange", "s", "-"),
    ("spatial", "spatial dual Laplacian", "tab:purple", "^", "-"),
    ("spectral_exact_100", "spectral, exact, m = 100", "tab:blue", "D", "-"),
    ("spectral_soft_100", "spectral, soft, m = 100", "tab:cyan", "v", "--"),
    ("spectral_exact_200", "spectral, exact, m = 200", "tab:green", "P", "-"),
    ("spectral_soft_200", "spectral, soft, m = 200", "tab:olive", "X", "--"),
]

PHASES = [
    ("per_mesh", "per mesh (spectral: eigensolve included)"),
    ("constraint", "per constraint set: preprocess()"),
    ("deform10", "target change: deform(10, 0)"),
    ("iteration", "per iteration"),
    ("converge", "to convergence: deform(cap, 1e-4) (CGAL capped)"),
    ("peak_bytes", "peak resident memory"),
]


def read(path):
    rows = []
    with open(path) as f:
        for line in f:
            if line.startswith("#") or not line.strip():
                continue
            case, level, vertices, region, algorithm, phase, median, low, high, runs = line.rstrip("\n").split("\t")
            rows.append(
                dict(case=case, level=int(level), vertices=int(vertices), region=float(region),
                     algorithm=algorithm, phase=phase, median=float(median), min=float(low),
                     max=float(high), runs=int(runs)))
    return rows


def value(rows, **keys):
    for r in rows:
        if all(r[k] == v for k, v in keys.items()):
            return r
    return None


def figure5(rows, case, output):
    name, level = case.split("@")
    level = int(level)
    fig_rows = [r for r in rows if r["case"] == "figure5"]
    if not fig_rows:
        print("no Figure 5 data")
        return
    ms = sorted({int(r["region"]) for r in fig_rows if r["algorithm"].startswith("figure5_soft_")})
    eig = sorted({int(r["region"]) for r in fig_rows if r["algorithm"].startswith("figure5_eigensolve_")})

    def series(prefix, phase, m_values):
        xs, ys, lo, hi = [], [], [], []
        for m in m_values:
            r = value(fig_rows, algorithm="%s%d" % (prefix, m), phase=phase)
            if r is not None and r["median"] > 0:
                xs.append(m)
                ys.append(r["median"])
                lo.append(r["median"] - r["min"])
                hi.append(r["max"] - r["median"])
        return xs, ys, [lo, hi]

    def reference(ax, algorithm, phase, label, color, style):
        r = value(rows, case=name, level=level, algorithm=algorithm, phase=phase)
        if r is not None and r["median"] > 0:
            ax.axhline(r["median"], color=color, linestyle=style, linewidth=1.2, label=label)

    fig, axes = plt.subplots(1, 3, figsize=(17, 5.2))
    ax = axes[0]
    for prefix, phase, label, color, marker in [
        ("figure5_soft_", "factorization", "spectral factorization (soft): Ã and its Cholesky", "tab:cyan", "v"),
        ("figure5_soft_", "constraint", "spectral, soft: preprocess()", "tab:blue", "o"),
        ("figure5_exact_", "constraint", "spectral, exact: preprocess()", "tab:green", "s"),
    ]:
        xs, ys, err = series(prefix, phase, ms)
        ax.errorbar(xs, ys, yerr=err, marker=marker, color=color, label=label, capsize=2)
    reference(ax, "spatial", "factorization", "spatial dual Laplacian: factorization", "tab:purple", "--")
    reference(ax, "cgal_original", "constraint", "CGAL ARAP, original: preprocess()", "tab:red", ":")
    ax.set_title("per constraint set (Table 1: factorization)")
    ax.set_yscale("log")

    ax = axes[1]
    for prefix, phase, label, color, marker in [
        ("figure5_exact_", "iteration", "spectral, exact: one iteration", "tab:blue", "o"),
        ("figure5_exact_", "deform10", "spectral, exact: deform(10, 0)", "tab:green", "s"),
        ("figure5_exact_", "transfer10", "spectral, exact: detail transfer", "tab:olive", "^"),
        ("figure5_soft_", "deform10", "spectral, soft: deform(10, 0)", "tab:cyan", "v"),
    ]:
        xs, ys, err = series(prefix, phase, ms)
        ax.errorbar(xs, ys, yerr=err, marker=marker, color=color, label=label, capsize=2)
    reference(ax, "spatial", "iteration", "spatial: one iteration", "tab:purple", "--")
    reference(ax, "cgal_original", "iteration", "CGAL ARAP, original: one iteration", "tab:red", ":")
    reference(ax, "cgal_original", "deform10", "CGAL ARAP, original: deform(10, 0)", "tab:red", "-.")
    ax.set_title("per target change (Table 1: back-substitution)")
    ax.set_yscale("log")

    ax = axes[2]
    xs, ys, err = series("figure5_eigensolve_", "eigensolve", eig)
    ax.errorbar(xs, ys, yerr=err, marker="o", color="tab:blue", label="eigensolve (basis)", capsize=2)
    xs, ys, err = series("figure5_soft_", "first_cached", ms)
    ax.errorbar(xs, ys, yerr=err, marker="s", color="tab:green",
                label="rest of the per-mesh work (basis cached)", capsize=2)
    reference(ax, "spatial", "per_mesh", "spatial dual Laplacian: per mesh", "tab:purple", "--")
    reference(ax, "cgal_original", "per_mesh", "CGAL ARAP, original: per mesh", "tab:red", ":")
    ax.set_title("per mesh")
    ax.set_yscale("log")
    for ax in axes:
        ax.set_xlabel("number of frequencies m")
        ax.set_ylabel("time (s)")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=7.5)
    fig.suptitle("Time against the number of frequencies (the paper's Figure 5), case %s" % case)
    fig.tight_layout()
    fig.savefig(output, dpi=110)
    plt.close(fig)
    print("wrote", output)


def scaling(rows, main_case, output):
    data = [r for r in rows if r["case"] != "figure5" and r["algorithm"] != "anatomy"]
    cases = sorted({r["case"] for r in data})
    others = [c for c in cases if c != main_case]
    markers_of_case = {c: m for c, m in zip(others, ["x", "+", "1", "2", "3", "4", "*", "h"])}
    fig, axes = plt.subplots(2, 3, figsize=(17, 10.5))
    for ax, (phase, title) in zip(axes.flat, PHASES):
        for key, label, color, marker, style in PEERS:
            points = sorted(
                (r["region"], r["median"], r["min"], r["max"])
                for r in data
                if r["case"] == main_case and r["algorithm"] == key and r["phase"] == phase and r["median"] > 0)
            if points:
                xs = [p[0] for p in points]
                ys = [p[1] for p in points]
                err = [[p[1] - p[2] for p in points], [p[3] - p[1] for p in points]]
                ax.errorbar(xs, ys, yerr=err, color=color, marker=marker, linestyle=style,
                            label=label, capsize=2, markersize=5)
            for c in others:
                pts = [(r["region"], r["median"]) for r in data
                       if r["case"] == c and r["algorithm"] == key and r["phase"] == phase and r["median"] > 0]
                if pts:
                    ax.scatter([p[0] for p in pts], [p[1] for p in pts], color=color,
                               marker=markers_of_case[c], s=30)
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_title(title)
        ax.set_xlabel("vertices of the region n")
        ax.set_ylabel("bytes" if phase == "peak_bytes" else "time (s)")
        ax.grid(True, which="both", alpha=0.3)
        # A slope-1 guide through the middle of the panel.
        lines = [l for l in ax.get_lines() if len(l.get_xdata()) > 0]
        if lines and phase != "peak_bytes":
            xs = sorted({x for l in lines for x in l.get_xdata()})
            ys = sorted({y for l in lines for y in l.get_ydata()})
            if len(xs) > 1 and ys:
                x0, x1 = xs[0], xs[-1]
                y0 = math.sqrt(ys[0] * ys[-1]) / math.sqrt(x1 / x0)
                ax.plot([x0, x1], [y0, y0 * x1 / x0], color="gray", linestyle=":", linewidth=1,
                        label="∝ n")
    handles, labels = axes.flat[0].get_legend_handles_labels()
    for c in others:
        handles.append(plt.Line2D([], [], color="black", marker=markers_of_case[c], linestyle=""))
        labels.append("case %s (markers)" % c)
    fig.legend(handles, labels, loc="lower center", ncol=5, fontsize=8.5)
    fig.suptitle("Time against the number of vertices (lines: %s on its Loop-subdivided meshes)" % main_case)
    fig.tight_layout(rect=(0, 0.07, 1, 0.97))
    fig.savefig(output, dpi=100)
    plt.close(fig)
    print("wrote", output)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("data")
    parser.add_argument("output_directory")
    parser.add_argument("--figure5-case", default="armadillo_arm@0")
    parser.add_argument("--scaling-case", default="armadillo_arm")
    args = parser.parse_args()
    rows = read(args.data)
    os.makedirs(args.output_directory, exist_ok=True)
    figure5(rows, args.figure5_case, os.path.join(args.output_directory, "deformation_time_vs_m.png"))
    scaling(rows, args.scaling_case, os.path.join(args.output_directory, "deformation_time_vs_n.png"))


if __name__ == "__main__":
    main()
