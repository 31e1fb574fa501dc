#!/usr/bin/env python3
# Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Lowers the armadillo's right arm by 70 degrees about the shoulder, feet
fixed, through the Python package ssmd, and writes the result as OFF.

    python3 deform_armadillo.py [INPUT.off [OUTPUT.off]]

INPUT defaults to CGAL's sample armadillo (Debian package libcgal-demo, as
extracted by scripts/fetch_sample_meshes.sh into build/data/meshes).
"""

import os
import sys
import time

import numpy as np

import ssmd


def read_off(path):
    """A minimal OFF reader: triangles only, no colours, comments skipped."""
    with open(path) as f:
        tokens = [t for line in f for t in line.split("#", 1)[0].split()]
    if not tokens or tokens[0] != "OFF":
        raise ValueError(path + " is not an OFF file")
    n, f = int(tokens[1]), int(tokens[2])
    V = np.array(tokens[4:4 + 3 * n], dtype=float).reshape(n, 3)
    rows = np.array(tokens[4 + 3 * n:4 + 3 * n + 4 * f], dtype=np.int64).reshape(f, 4)
    if np.any(rows[:, 0] != 3):
        raise ValueError(path + " has faces that are not triangles")
    return V, rows[:, 1:]


def write_off(path, V, F):
    with open(path, "w") as out:
        out.write("OFF\n%d %d 0\n" % (len(V), len(F)))
        np.savetxt(out, V, fmt="%.17g")
        np.savetxt(out, np.hstack([np.full((len(F), 1), 3), F]), fmt="%d")


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    default = os.path.join(os.environ.get("SSMD_SAMPLE_MESH_DIR", os.path.join(here, "../../build/data/meshes")),
                           "armadillo.off")
    source = sys.argv[1] if len(sys.argv) > 1 else default
    target = sys.argv[2] if len(sys.argv) > 2 else "armadillo_arm.off"

    V, F = read_off(source)
    hand = np.flatnonzero(np.linalg.norm(V - [54, 80, -30], axis=1) < 13)   # the right hand
    feet = np.flatnonzero(V[:, 1] < -45)                                     # both feet

    start = time.perf_counter()
    deformation = ssmd.Deformation(V, F, handles=hand, fixed=feet, m=100)
    basis_seconds = deformation.preprocess_report["basis_seconds"]   # before deform() renews the report
    a = np.radians(-70)
    deformation.rotate([np.cos(a / 2), 0, 0, np.sin(a / 2)], center=[24, 56, 0])   # about z, at the shoulder
    W = deformation.deform(iterations=10)
    seconds = time.perf_counter() - start

    write_off(target, W, F)
    report = deformation.deform_report
    print("%d vertices, %d handle and %d fixed vertices: deformed in %.2f s "
          "(basis %.2f s, %d iterations); hand moved by %.1f, feet by %g; wrote %s"
          % (len(V), len(hand), len(feet), seconds, basis_seconds,
             report["iterations"], np.linalg.norm(W[hand] - V[hand], axis=1).max(),
             np.abs(W[feet] - V[feet]).max(), target))


if __name__ == "__main__":
    main()
