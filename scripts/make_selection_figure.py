#!/usr/bin/python3
# Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""The manual's figure of what region of interest, handle and fixed vertices
mean: CGAL's armadillo with the three sets coloured, before and after the
handle is moved (deformed with the Python package ssmd).

    make_selection_figure.py ARMADILLO.off OUTPUT.png
"""

import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.collections import PolyCollection  # noqa: E402
from matplotlib.patches import Patch  # noqa: E402

sys.path.insert(0, __import__("os").path.join(__import__("os").path.dirname(__file__), "..", "examples", "python"))
from deform_armadillo import read_off  # noqa: E402

import ssmd  # noqa: E402

COLOURS = {"fixed": np.array([0.62, 0.62, 0.62]), "roi": np.array([0.36, 0.60, 0.86]),
           "handle": np.array([0.95, 0.55, 0.15])}


def draw(ax, V, F, part, title):
    """Flat-shaded orthographic view from the front (the armadillo looks down -z)."""
    x, y, depth = -V[:, 0], V[:, 1], V[:, 2]
    tri = V[F]
    normals = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
    normals /= np.linalg.norm(normals, axis=1, keepdims=True) + 1e-300
    light = np.array([0.3, 0.4, -1.0]); light /= np.linalg.norm(light)
    shade = 0.35 + 0.65 * np.clip(normals @ light, 0, 1)
    facing = normals[:, 2] < 0
    order = np.argsort(-depth[F].mean(axis=1))          # far to near
    order = order[facing[order]]
    labels = np.array(["fixed", "roi", "handle"])[part[F].max(axis=1)]
    colours = np.array([COLOURS[l] for l in labels]) * shade[:, None]
    polygons = np.stack([x[F], y[F]], axis=-1)[order]
    ax.add_collection(PolyCollection(polygons, facecolors=np.clip(colours[order], 0, 1), edgecolors="none",
                                  antialiaseds=False))
    ax.set_xlim(x.min() - 5, x.max() + 5); ax.set_ylim(y.min() - 5, y.max() + 5)
    ax.set_aspect("equal"); ax.axis("off"); ax.set_title(title, fontsize=11)


def main():
    V, F = read_off(sys.argv[1])
    handle = np.flatnonzero(np.linalg.norm(V - [54, 80, -30], axis=1) < 13)
    roi = np.flatnonzero(np.linalg.norm(V - [24, 56, 0], axis=1) < 62)
    roi = np.union1d(roi, handle)
    part = np.zeros(len(V), dtype=int)
    part[roi] = 1
    part[handle] = 2

    d = ssmd.Deformation(V, F, roi=roi, handles=handle, m=100)
    a = np.radians(-70)
    d.rotate([np.cos(a / 2), 0, 0, np.sin(a / 2)], center=[24, 56, 0])
    W = d.deform()
    print("%d ROI vertices (%d handle), %d fixed; hand moved by %.1f, fixed vertices by %g"
          % (len(roi), len(handle), len(V) - len(roi), np.linalg.norm(W[handle] - V[handle], axis=1).max(),
             np.abs(np.delete(W - V, roi, axis=0)).max()))

    fig, axes = plt.subplots(1, 2, figsize=(9, 5.2), dpi=110)
    draw(axes[0], V, F, part, "selection: roi, control vertices, the rest fixed")
    draw(axes[1], W, F, part, "after the handle's targets turn 70° about the shoulder")
    fig.legend(handles=[Patch(color=COLOURS["handle"], label="handle: control vertices, moved to their targets"),
                        Patch(color=COLOURS["roi"], label="region of interest: free, follows the handle"),
                        Patch(color=COLOURS["fixed"], label="outside the region: fixed, never moves")],
               loc="lower center", ncol=1, frameon=False, fontsize=10)
    fig.subplots_adjust(left=0.01, right=0.99, top=0.93, bottom=0.2, wspace=0.02)
    fig.savefig(sys.argv[2])


if __name__ == "__main__":
    main()
