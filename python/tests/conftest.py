# Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Meshes built in code for the tests of the Python package."""

import numpy as np
import pytest


def tube(rings=24, segments=20, radius=0.5, height=3.0):
    """An open cylinder along z: `rings` rings of `segments` vertices."""
    angles = 2 * np.pi * np.arange(segments) / segments
    V = np.array([[radius * np.cos(a), radius * np.sin(a), height * r / (rings - 1)]
                  for r in range(rings) for a in angles])
    F = []
    for r in range(rings - 1):
        for s in range(segments):
            a, b = r * segments + s, r * segments + (s + 1) % segments
            c, d = a + segments, b + segments
            F += [[a, b, d], [a, d, c]]
    return V, np.array(F, dtype=np.int64)


def icosphere(subdivisions=3):
    """The unit sphere: an icosahedron subdivided `subdivisions` times."""
    t = (1 + 5 ** 0.5) / 2
    V = [[-1, t, 0], [1, t, 0], [-1, -t, 0], [1, -t, 0], [0, -1, t], [0, 1, t],
         [0, -1, -t], [0, 1, -t], [t, 0, -1], [t, 0, 1], [-t, 0, -1], [-t, 0, 1]]
    V = [list(np.array(v) / np.linalg.norm(v)) for v in V]
    F = [[0, 11, 5], [0, 5, 1], [0, 1, 7], [0, 7, 10], [0, 10, 11], [1, 5, 9], [5, 11, 4],
         [11, 10, 2], [10, 7, 6], [7, 1, 8], [3, 9, 4], [3, 4, 2], [3, 2, 6], [3, 6, 8],
         [3, 8, 9], [4, 9, 5], [2, 4, 11], [6, 2, 10], [8, 6, 7], [9, 8, 1]]
    for _ in range(subdivisions):
        midpoint = {}

        def middle(a, b):
            key = (min(a, b), max(a, b))
            if key not in midpoint:
                p = np.array(V[a]) + np.array(V[b])
                V.append(list(p / np.linalg.norm(p)))
                midpoint[key] = len(V) - 1
            return midpoint[key]

        F = [g for a, b, c in F for g in
             ([a, middle(a, b), middle(c, a)], [b, middle(b, c), middle(a, b)],
              [c, middle(c, a), middle(b, c)], [middle(a, b), middle(b, c), middle(c, a)])]
    return np.array(V), np.array(F, dtype=np.int64)


@pytest.fixture(scope="session")
def tube_mesh():
    V, F = tube()
    segments = 20
    fixed = np.arange(segments)                       # the bottom ring
    handles = np.arange(len(V) - segments, len(V))    # the top ring
    return V, F, fixed, handles
