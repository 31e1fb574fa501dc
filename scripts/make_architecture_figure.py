#!/usr/bin/python3
# Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Draw the data flow of the package (doc/fig/architecture_data_flow.png):
the stages of a deformation from the mesh to the written positions, the
header or folder of each stage, when each stage runs, the spatial pipeline
that the algorithm tag selects instead of the spectral one, and the shared
numerical services. Used by doc/architecture.md.

usage: make_architecture_figure.py [OUTPUT.png]
       (default: doc/fig/architecture_data_flow.png next to this script)
"""
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.patches import FancyArrowPatch, FancyBboxPatch  # noqa: E402

WIDTH, HEIGHT, DPI = 980, 1150, 100

# Colours: when a stage runs.
INPUT = "#ececec"
PER_REGION = "#d6e6f5"
PER_CONSTRAINT_SET = "#fbe0c3"
PER_DRAG = "#d9efd2"
SERVICE = "#e8e2f1"
EDGE = "#4a4a4a"

TITLE_SIZE = 12
TEXT_SIZE = 9.5
LINE = 18  # pixels between two lines of text

matplotlib.rcParams["mathtext.fontset"] = "dejavusans"


def box(ax, x, y, w, h, colour, title, lines, dashed=False):
    """A rounded box with its top-left corner at (x, y) (pixels, y down), a
    bold title and lines of text; a line given as ('mono', text) is set in a
    monospaced font (header and folder names)."""
    ax.add_patch(FancyBboxPatch((x, y), w, h, boxstyle="round,pad=0,rounding_size=8",
                                facecolor=colour, edgecolor=EDGE,
                                linewidth=1.0, linestyle="--" if dashed else "-"))
    ax.text(x + 12, y + 24, title, fontsize=TITLE_SIZE, fontweight="bold", va="baseline",
            ha="left")
    # Baselines at a fixed pitch, whatever the height of the glyphs (hats,
    # superscripts) of a line.
    ty = y + 24 + 21
    for line in lines:
        family, text = ("monospace", line[1]) if isinstance(line, tuple) else ("sans-serif", line)
        ax.text(x + 12, ty, text, fontsize=TEXT_SIZE, family=family, va="baseline", ha="left",
                color="#202020")
        ty += LINE


def arrow(ax, start, end, label=None, dashed=False, connection="arc3", label_y=None):
    ax.add_patch(FancyArrowPatch(start, end, arrowstyle="-|>", mutation_scale=14,
                                 linewidth=1.3, color=EDGE, linestyle="--" if dashed else "-",
                                 connectionstyle=connection, shrinkA=0, shrinkB=0))
    if label:
        ax.text(start[0] + 10, label_y if label_y else (start[1] + end[1]) / 2, label,
                fontsize=TEXT_SIZE,
                style="italic", va="center", ha="left", color="#303030")


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    output = sys.argv[1] if len(sys.argv) > 1 else os.path.normpath(os.path.join(
        here, os.pardir, "doc", "fig", "architecture_data_flow.png"))

    fig = plt.figure(figsize=(WIDTH / DPI, HEIGHT / DPI), dpi=DPI)
    ax = fig.add_axes([0, 0, 1, 1])
    ax.set_xlim(0, WIDTH)
    ax.set_ylim(HEIGHT, 0)
    ax.axis("off")

    # The main column: the stages of the spectral pipeline.
    x, w = 40, 560
    cx = x + w / 2
    stages = [
        # y, height, colour, title, lines
        (20, 82, INPUT, "Mesh, region of interest, control vertices, targets",
         [("mono", "Spectral_surface_mesh_deformation.h"),
          "a FaceGraph model read through its vertex point and index maps"]),
        (142, 108, PER_REGION, "Region extraction",
         [("mono", "internal/Mesh/"),
          r"triangle arrays of the region, cotangent stiffness $Q$ and mass $M$,",
          r"dual mesh operator $\hat{L}F$; public operators:",
          ("mono", "cotangent_operators.h, Dual_mesh_laplacian.h")]),
        (302, 118, PER_REGION, "Manifold harmonics basis (cacheable)",
         [("mono", "Manifold_harmonics_basis.h, internal/Basis/"),
          r"the $m$ lowest eigenpairs of $Q\,h = \lambda\,M h$, shift-invert;",
          ("mono", "Block_lanczos_eigensolver_traits.h (default),"),
          ("mono", "Spectra_eigensolver_traits.h, internal/Eigensolvers/")]),
        (460, 82, PER_CONSTRAINT_SET, "Reduced system",
         [r"groups of constrained vertices, $\tilde{A} = G_0 + w^2 H_c^\top H_c$, its $m \times m$ Cholesky;",
          "exact policy: sparse factorization of the detail transfer"]),
        (582, 100, PER_DRAG, "Reduced dual Laplacian solve",
         [("mono", "internal/Deformation/Spectral_dual_laplacian_solver.h"),
          r"rigid-fit smooth targets; per iteration, $O(nm)$: $S = H\tilde{V}$, dual normals,",
          r"$H^\top (\hat{L}F)^\top \hat{l}$, two $m \times m$ triangular solves"]),
        (722, 118, PER_DRAG, "Detail transfer",
         [("mono", "internal/Deformation/Detail_transfer.h,"),
          ("mono", "internal/Deformation/Smooth_rotation_field.h"),
          r"rotations of the smooth one-rings, Poisson solve with $Q$;",
          "exact policy: all constrained vertices prescribed; soft: the fixed ones"]),
        (880, 62, INPUT, "Positions written through the vertex point map",
         ["the ROI vertices only; the mesh is unchanged when a step fails"]),
    ]
    for y, h, colour, title, lines in stages:
        box(ax, x, y, w, h, colour, title, lines)

    labels = ["ROI, targets", r"$Q$, $M$", r"basis $H$ ($n \times m$), $G_0$",
              r"factor of $\tilde{A}$", r"smooth deformed mesh $S$", r"detailed positions $Y$"]
    # The frame of the spectral pipeline (below) crosses the first and the
    # last of these arrows: their labels sit between the frame and a box.
    frame_top, frame_bottom = 268, 854
    label_ys = [None, (stages[1][0] + stages[1][1] + frame_top) / 2, None, None, None,
                (frame_bottom + stages[6][0]) / 2]
    for (y0, h0, *_), (y1, *_), label, label_y in zip(stages, stages[1:], labels, label_ys):
        arrow(ax, (cx, y0 + h0), (cx, y1), label, label_y=label_y)

    # The spectral pipeline: a frame around the stages it owns.
    ax.add_patch(FancyBboxPatch((24, frame_top), w + 32, frame_bottom - frame_top, boxstyle="round,pad=0,rounding_size=12",
                                facecolor="none", edgecolor="#7a7a7a", linewidth=1.0,
                                linestyle=(0, (5, 4))))
    ax.text(36, frame_top + 6, "spectral pipeline", fontsize=TEXT_SIZE, va="top", ha="left",
            color="#505050")

    # The right column: legend, tag, spatial pipeline.
    rx, rw = 650, 310
    ax.add_patch(FancyBboxPatch((rx, 20), rw, 112, boxstyle="round,pad=0,rounding_size=8",
                                facecolor="white", edgecolor=EDGE, linewidth=1.0))
    ax.text(rx + 12, 30, "When a stage runs", fontsize=TITLE_SIZE, fontweight="bold", va="top")
    for i, (colour, text) in enumerate([(PER_REGION, "per region (ROI, geometry, m)"),
                                        (PER_CONSTRAINT_SET, "per constraint set"),
                                        (PER_DRAG, "per drag: every deform()")]):
        yy = 60 + i * 26
        ax.add_patch(FancyBboxPatch((rx + 14, yy), 30, 16, boxstyle="round,pad=0,rounding_size=3",
                                    facecolor=colour, edgecolor=EDGE, linewidth=0.8))
        ax.text(rx + 54, yy + 8, text, fontsize=TEXT_SIZE, va="center")

    box(ax, rx, 268, rw - 50, 184, "white", "Algorithm tag",
        ["a template argument: it selects",
         "the pipeline at compile time",
         ("mono", "SPECTRAL_DUAL_LAPLACIAN"),
         "  spectral, iterated (default)",
         ("mono", "SPECTRAL_LINEAR"),
         "  spectral, one solve",
         ("mono", "SPATIAL_DUAL_LAPLACIAN"),
         "  spatial (below)"])

    box(ax, rx, 482, rw, 186, "white", "Spatial pipeline",
        [("mono", "internal/Deformation/"),
         ("mono", "Spatial_dual_laplacian_solver.h"),
         "dual Laplacian editing on the",
         "detailed region: a sparse n \u00d7 n",
         "system factored per constraint",
         "set, a sparse back-substitution",
         "per iteration; no basis and no",
         "detail transfer"], dashed=True)
    lane = rx + rw - 25  # the spatial path runs down the right edge
    arrow(ax, (x + w, 194), (lane, 482), connection="angle,angleA=0,angleB=90,rad=10",
          dashed=True)
    arrow(ax, (lane, 668), (x + w, 911), connection="angle,angleA=-90,angleB=0,rad=10",
          dashed=True)

    # The shared services.
    sy, sh = 1010, 124
    ax.text(24, sy - 24, "Shared numerical services, used by the stages above",
            fontsize=TITLE_SIZE, fontweight="bold", va="center")
    services = [
        (SERVICE, "Sparse SPD solvers",
         [("mono", "Sparse_spd_solver_traits.h"),
          "CHOLMOD (supernodal or",
          "simplicial) or Eigen: the basis,",
          "spatial solver, detail transfer"]),
        (SERVICE, "Dense kernels",
         [("mono", "internal/Linear_algebra/"),
          "basis panels, BLAS products,",
          "Dirichlet systems, subtree",
          "triangular solves"]),
        (SERVICE, "Memory",
         [("mono", "internal/Memory/"),
          "large arrays, huge pages for",
          "CHOLMOD: opt-in, process-wide",
          "tuning, off by default"]),
    ]
    sw, gap = 296, 22
    for i, (colour, title, lines) in enumerate(services):
        box(ax, 24 + i * (sw + gap), sy, sw, sh, colour, title, lines)

    fig.savefig(output, dpi=DPI, facecolor="white")
    print(output)


if __name__ == "__main__":
    main()
